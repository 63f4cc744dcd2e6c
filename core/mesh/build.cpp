#include "snaxels/mesh/build.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include <OpenMesh/Core/System/omstream.hh>
#include <glm/glm.hpp>

#include "snaxels/error.h"
#include "snaxels/util/memory.h"

namespace snaxels {
namespace {

struct PositionKey {
    std::uint64_t x, y, z;
    bool operator==(const PositionKey&) const = default;
};

struct PositionKeyHash {
    std::size_t operator()(const PositionKey& k) const noexcept {
        std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
        h ^= (k.y + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2));
        h ^= (k.z + 0x94D049BB133111EBull + (h << 6) + (h >> 2));
        return static_cast<std::size_t>(h ^ (h >> 31));
    }
};

// Adding +0.0 turns -0.0 into +0.0, so both weld together.
PositionKey key_of(const glm::dvec3& p) {
    return {std::bit_cast<std::uint64_t>(p.x + 0.0), std::bit_cast<std::uint64_t>(p.y + 0.0),
            std::bit_cast<std::uint64_t>(p.z + 0.0)};
}

bool is_degenerate(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e0 = b - a, e1 = c - a, e2 = c - b;
    const glm::dvec3 n{e0.y * e1.z - e0.z * e1.y, e0.z * e1.x - e0.x * e1.z,
                       e0.x * e1.y - e0.y * e1.x};
    const double twice_area = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    const double longest = std::max({glm::dot(e0, e0), glm::dot(e1, e1), glm::dot(e2, e2)});
    // Relative test: collinear corners in float input leave a rounding-size area.
    return !(twice_area > 1e-12 * longest);
}

struct UnionFind {
    std::vector<std::uint32_t> parent;
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
    std::uint32_t find(std::uint32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// Fans of faces that meet only at a vertex (a bow tie, or a cone tip shared
// by two surfaces) get a copy of the vertex each but the first: the faces
// around a vertex of a manifold mesh form one fan. Faces join a fan through
// an edge at the vertex they share. OpenMesh accepts some such faces and
// leaves a vertex with two gaps in its ring (found by fuzz_mesh). Appends
// the copies to @p positions and @p source; returns how many it made.
std::size_t split_fans(std::vector<std::array<std::uint32_t, 3>>& faces, std::vector<glm::dvec3>& positions,
                       std::vector<std::uint32_t>& source) {
    // Corners c = 3 f + k; corners of one vertex in one fan end up united.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> edges; // (edge key, corner of its first vertex)
    edges.reserve(faces.size() * 3);
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = faces[f][k], b = faces[f][(k + 1) % 3];
            edges.emplace_back(a < b ? (a << 32 | b) : (b << 32 | a), std::uint32_t(3 * f + std::size_t(k)));
        }
    std::sort(edges.begin(), edges.end());
    UnionFind fans(faces.size() * 3);
    auto corner_of = [&](std::uint32_t face, std::uint32_t vertex) {
        for (std::uint32_t k = 0; k < 3; ++k)
            if (faces[face][k] == vertex) return 3 * face + k;
        return 3 * face; // unreachable: the face has the vertex
    };
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].first == edges[i].first) ++j;
        for (std::size_t e = i + 1; e < j; ++e) {
            const std::uint32_t f1 = edges[i].second / 3, f2 = edges[e].second / 3;
            for (const auto v : {std::uint32_t(edges[i].first >> 32), std::uint32_t(edges[i].first & 0xffffffffu)})
                fans.unite(corner_of(f1, v), corner_of(f2, v));
        }
        i = j;
    }
    std::vector<std::int64_t> first_fan(positions.size(), -1);
    std::unordered_map<std::uint32_t, std::uint32_t> copy_of_fan;
    const std::size_t before = positions.size();
    for (std::size_t f = 0; f < faces.size(); ++f)
        for (std::uint32_t k = 0; k < 3; ++k) {
            const std::uint32_t v = faces[f][k];
            const std::uint32_t fan = fans.find(std::uint32_t(3 * f + k));
            if (first_fan[v] < 0) first_fan[v] = fan;
            if (first_fan[v] == fan) continue;
            auto [it, fresh] = copy_of_fan.try_emplace(fan, std::uint32_t(positions.size()));
            if (fresh) {
                const glm::dvec3 at = positions[v]; // a copy: push_back may move the array
                positions.push_back(at);
                source.push_back(source[v]);
            }
            faces[f][k] = it->second;
        }
    return positions.size() - before;
}

// Adds triangles, splitting (duplicating) as few vertices as it takes when a
// face cannot join the manifold halfedge structure as it is: a complex
// vertex or edge, or a fan with no free gap to link into.
class RepairingFaceAdder {
  public:
    /// @p source: per vertex, the input vertex it stands for (copies inherit it).
    RepairingFaceAdder(Mesh& mesh, OpenMesh::VPropHandleT<std::uint32_t> source)
        : mesh_(mesh), source_(source) {}

    /// The face added (invalid when no repair could add it).
    Mesh::FaceHandle add(const std::array<Mesh::VertexHandle, 3>& vh) {
        if (const auto fh = mesh_.add_face(vh[0], vh[1], vh[2]); fh.is_valid()) return fh;
        // Replace subsets of corners, smallest first: by the copy an earlier
        // repair made of the same vertex (so a second fan around a vertex
        // becomes one new vertex, not one per face), else by a fresh copy.
        static constexpr int kSubsets[] = {1, 2, 4, 3, 5, 6, 7};
        for (const int subset : kSubsets) {
            auto trial = vh;
            bool all_copied = true;
            for (int i = 0; i < 3; ++i)
                if (subset & (1 << i)) {
                    const auto it = latest_copy_.find(vh[i].idx());
                    if (it == latest_copy_.end()) all_copied = false;
                    else trial[i] = it->second;
                }
            if (!all_copied) continue;
            if (const auto fh = mesh_.add_face(trial[0], trial[1], trial[2]); fh.is_valid()) return fh;
        }
        for (const int subset : kSubsets) {
            auto trial = vh;
            std::size_t used = 0;
            for (int i = 0; i < 3; ++i)
                if (subset & (1 << i)) trial[i] = spare(used++, vh[i]);
            if (const auto fh = mesh_.add_face(trial[0], trial[1], trial[2]); fh.is_valid()) {
                for (int i = 0; i < 3; ++i)
                    if (subset & (1 << i)) latest_copy_[vh[i].idx()] = trial[i];
                spares_.erase(spares_.begin(), spares_.begin() + static_cast<long>(used));
                copies_ += used;
                return fh;
            }
        }
        return Mesh::FaceHandle();
    }

    /// Removes unused spare vertices; call once after the last face.
    std::size_t finish() {
        if (!spares_.empty()) {
            for (const auto v : spares_) mesh_.delete_vertex(v, false);
            mesh_.garbage_collection();
        }
        return copies_;
    }

  private:
    // An isolated vertex at the position of @p original, reused between attempts.
    Mesh::VertexHandle spare(std::size_t k, Mesh::VertexHandle original) {
        // A copy: add_vertex grows the point array, and a reference into it
        // would be read after it moved (found by AddressSanitizer).
        const Mesh::Point at = mesh_.point(original);
        while (spares_.size() <= k) spares_.push_back(mesh_.add_vertex(at));
        mesh_.set_point(spares_[k], at);
        mesh_.property(source_, spares_[k]) = mesh_.property(source_, original);
        return spares_[k];
    }

    Mesh& mesh_;
    OpenMesh::VPropHandleT<std::uint32_t> source_;
    std::vector<Mesh::VertexHandle> spares_;
    std::unordered_map<int, Mesh::VertexHandle> latest_copy_; ///< input vertex -> its newest copy
    std::size_t copies_ = 0;
};

} // namespace

void compute_vertex_normals(Mesh& mesh) {
    std::vector<OpenMesh::Vec3d> sum(mesh.n_vertices(), OpenMesh::Vec3d(0.0));
    for (const auto fh : mesh.faces()) {
        auto it = mesh.cfv_iter(fh);
        const auto a = *it, b = *++it, c = *++it;
        const auto& pa = mesh.point(a);
        // |cross| is twice the area, so summing cross products weights by area.
        const OpenMesh::Vec3d n = OpenMesh::cross(mesh.point(b) - pa, mesh.point(c) - pa);
        sum[a.idx()] += n;
        sum[b.idx()] += n;
        sum[c.idx()] += n;
    }
    for (const auto vh : mesh.vertices()) {
        OpenMesh::Vec3d n = sum[vh.idx()];
        const double len = n.norm();
        mesh.set_normal(vh, len > 0.0 ? n / len : OpenMesh::Vec3d(0.0, 0.0, 1.0));
    }
}

namespace {

// 1. Weld by exact position: per input vertex, its index among the unique
// positions.
std::vector<std::uint32_t> weld(const TriangleSoup& soup, std::vector<glm::dvec3>& unique) {
    std::vector<std::uint32_t> welded(soup.positions.size());
    unique.reserve(soup.positions.size());
    std::unordered_map<PositionKey, std::uint32_t, PositionKeyHash> index;
    index.reserve(soup.positions.size());
    for (std::size_t i = 0; i < soup.positions.size(); ++i) {
        const glm::dvec3& p = soup.positions[i];
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(p[k]))
                throw Error(std::string("a vertex has a non-finite coordinate (") + (std::isnan(p[k]) ? "NaN" : "infinity") +
                            ")");
        auto [it, inserted] = index.try_emplace(key_of(p), static_cast<std::uint32_t>(unique.size()));
        if (inserted) unique.push_back(p);
        welded[i] = it->second;
    }
    return welded;
}

// 2. The faces with three distinct corners and a non-zero area, over the
// welded vertices.
std::vector<std::array<std::uint32_t, 3>> kept_faces(const TriangleSoup& soup, const std::vector<std::uint32_t>& welded,
                                                     const std::vector<glm::dvec3>& unique, MeshReport& report,
                                                     std::vector<std::uint32_t>& face_source) {
    std::vector<std::array<std::uint32_t, 3>> faces;
    faces.reserve(soup.triangles.size());
    for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
        std::array<std::uint32_t, 3> t{};
        for (int k = 0; k < 3; ++k) {
            const auto i = soup.triangles[f][k];
            if (i >= soup.positions.size())
                throw Error("face " + std::to_string(f + 1) + " refers to vertex " + std::to_string(i + 1) +
                            " but there are only " + std::to_string(soup.positions.size()) + " vertices");
            t[k] = welded[i];
        }
        if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || is_degenerate(unique[t[0]], unique[t[1]], unique[t[2]])) {
            ++report.dropped_faces;
            continue;
        }
        faces.push_back(t);
        face_source.push_back(std::uint32_t(f));
    }
    if (faces.empty())
        throw Error(soup.triangles.empty() ? "the mesh has no faces" : "the mesh has no faces with a non-zero area");
    return faces;
}

// 3. Edge statistics of the input, before any repair.
void count_edges(const std::vector<std::array<std::uint32_t, 3>>& faces, MeshReport& report) {
    std::vector<std::uint64_t> edges;
    edges.reserve(faces.size() * 3);
    for (const auto& t : faces)
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = t[k], b = t[(k + 1) % 3];
            edges.push_back(a < b ? (a << 32 | b) : (b << 32 | a));
        }
    std::sort(edges.begin(), edges.end());
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        ++report.edges;
        if (j - i == 1) ++report.boundary_edges;
        if (j - i > 2) ++report.nonmanifold_edges;
        i = j;
    }
}

// 5b. Fans that add_face accepted around one vertex (bow ties, also left by
// the repairs of step 5): the mesh is built again with a copy of the vertex
// for each fan but the first. Rare, so only then. Returns the copies made.
std::size_t split_complex_vertices(Mesh& mesh, OpenMesh::VPropHandleT<std::uint32_t> soup_vertex,
                                   OpenMesh::FPropHandleT<std::uint32_t> soup_face) {
    auto complex_vertex = [&] {
        return std::any_of(mesh.vertices_begin(), mesh.vertices_end(), [&](auto vh) { return !mesh.is_manifold(vh); });
    };
    std::size_t copies = 0;
    for (int round = 0; round < 4 && complex_vertex(); ++round) { // a rebuild's own repairs may leave one more
        std::vector<std::array<std::uint32_t, 3>> built;
        std::vector<std::uint32_t> built_source;
        built.reserve(mesh.n_faces());
        for (const auto fh : mesh.faces()) {
            std::array<std::uint32_t, 3> t{};
            int k = 0;
            for (const auto vh : mesh.fv_range(fh)) t[k++] = std::uint32_t(vh.idx());
            built.push_back(t);
            built_source.push_back(mesh.property(soup_face, fh));
        }
        std::vector<glm::dvec3> points;
        std::vector<std::uint32_t> sources;
        for (const auto vh : mesh.vertices()) {
            points.push_back(to_glm(mesh.point(vh)));
            sources.push_back(mesh.property(soup_vertex, vh));
        }
        const std::size_t fan_copies = split_fans(built, points, sources);
        mesh.clean();
        std::vector<Mesh::VertexHandle> again;
        again.reserve(points.size());
        for (std::size_t v = 0; v < points.size(); ++v) {
            again.push_back(mesh.add_vertex(to_om(points[v])));
            mesh.property(soup_vertex, again.back()) = sources[v];
        }
        RepairingFaceAdder readder(mesh, soup_vertex);
        for (std::size_t f = 0; f < built.size(); ++f) {
            const auto& t = built[f];
            if (const auto fh = readder.add({again[t[0]], again[t[1]], again[t[2]]}); fh.is_valid())
                mesh.property(soup_face, fh) = built_source[f];
        }
        copies += fan_copies + readder.finish();
    }
    return copies;
}

// 6. Components; closed ones that enclose negative volume face inward (some
// scanners write them so) and are turned outward, because shading contours
// (N.L) depend on which side is out.
void orient_components(Mesh& mesh, MeshReport& report, std::vector<std::uint32_t>& face_source) {
    UnionFind components(mesh.n_vertices());
    for (const auto eh : mesh.edges())
        components.unite(static_cast<std::uint32_t>(mesh.from_vertex_handle(mesh.halfedge_handle(eh, 0)).idx()),
                         static_cast<std::uint32_t>(mesh.to_vertex_handle(mesh.halfedge_handle(eh, 0)).idx()));
    for (std::uint32_t v = 0; v < mesh.n_vertices(); ++v)
        if (components.find(v) == v) ++report.components;
    std::vector<double> volume(mesh.n_vertices(), 0.0);
    std::vector<std::uint8_t> open(mesh.n_vertices(), 0);
    std::vector<glm::dvec3> anchor(mesh.n_vertices());
    for (const auto vh : mesh.vertices()) anchor[components.find(vh.idx())] = to_glm(mesh.point(vh));
    for (const auto fh : mesh.faces()) {
        auto it = mesh.cfv_iter(fh);
        const auto a = *it, b = *++it, c = *++it;
        const std::uint32_t root = components.find(a.idx());
        const glm::dvec3 o = anchor[root];
        volume[root] +=
            glm::dot(to_glm(mesh.point(a)) - o, glm::cross(to_glm(mesh.point(b)) - o, to_glm(mesh.point(c)) - o));
    }
    for (const auto heh : mesh.halfedges())
        if (mesh.is_boundary(heh)) open[components.find(mesh.to_vertex_handle(heh).idx())] = 1;
    std::vector<std::uint8_t> flip(mesh.n_vertices(), 0);
    for (std::uint32_t v = 0; v < mesh.n_vertices(); ++v)
        if (components.find(v) == v && !open[v] && volume[v] < 0.0) {
            flip[v] = 1;
            ++report.flipped_components;
        }
    if (!report.flipped_components) return;
    Mesh turned;
    turned.reserve(mesh.n_vertices(), mesh.n_edges(), mesh.n_faces());
    for (const auto vh : mesh.vertices()) turned.add_vertex(mesh.point(vh));
    std::vector<std::uint32_t> turned_source;
    turned_source.reserve(face_source.size());
    for (const auto fh : mesh.faces()) {
        std::array<Mesh::VertexHandle, 3> c;
        int k = 0;
        for (const auto vh : mesh.fv_range(fh)) c[k++] = vh;
        if (flip[components.find(c[0].idx())]) std::swap(c[1], c[2]);
        if (turned.add_face(c[0], c[1], c[2]).is_valid()) turned_source.push_back(face_source[slot(fh)]);
    }
    mesh = std::move(turned);
    face_source = std::move(turned_source);
}

// 7. The file's normal at each corner of each face: the corner of the
// face's soup triangle at the same (welded, exact) position.
std::vector<std::array<glm::dvec3, 3>> corner_normals(const Mesh& mesh, const TriangleSoup& soup,
                                                      const std::vector<std::uint32_t>& face_source) {
    std::vector<std::array<glm::dvec3, 3>> out(mesh.n_faces());
    for (const auto fh : mesh.faces()) {
        const auto& tri = soup.triangles[face_source[slot(fh)]];
        auto corner = out[slot(fh)].begin();
        for (const auto vh : mesh.fv_range(fh)) {
            const glm::dvec3 p = to_glm(mesh.point(vh));
            glm::dvec3 n(0.0); // none found: matches any (a repair's copy keeps its position, so it is found)
            for (const std::uint32_t i : tri)
                if (soup.positions[i] == p) n = soup.normals[i];
            *corner++ = n;
        }
    }
    return out;
}

} // namespace

LoadedMesh build_mesh(const TriangleSoup& soup, const std::string& source) {
    // Refused before anything is allocated for it: a mesh that cannot be
    // drawn in this machine's memory (the estimate: a toon drawing of a
    // million faces peaks near 400 MB; animation and the window need more).
    const std::uint64_t estimate = std::uint64_t(soup.triangles.size()) * kBytesPerFace;
    if (const std::uint64_t machine = machine_memory_bytes(); estimate > machine)
        throw Error(std::to_string(soup.triangles.size()) + " faces need an estimated " + describe_bytes(estimate) +
                    " of memory to draw, more than this machine's " + describe_bytes(machine) +
                    "; simplify the mesh (decimate it) first");
    LoadedMesh out;
    MeshReport& report = out.report;
    report.source = source;
    std::vector<glm::dvec3> unique;
    const std::vector<std::uint32_t> welded = weld(soup, unique);
    std::vector<std::uint32_t> kept_source; // per kept face, its soup triangle
    const auto faces = kept_faces(soup, welded, unique, report, kept_source);
    count_edges(faces, report);

    // 4. Vertices referenced by a kept face, in first-use order of the input.
    std::vector<std::int64_t> remap(unique.size(), -1);
    Mesh& mesh = out.mesh;
    mesh.reserve(unique.size(), faces.size() * 3 / 2 + 16, faces.size());
    std::vector<Mesh::VertexHandle> handles;
    handles.reserve(unique.size());
    std::vector<std::uint32_t> unique_source(unique.size());
    for (std::size_t i = soup.positions.size(); i-- > 0;) unique_source[welded[i]] = std::uint32_t(i);
    OpenMesh::VPropHandleT<std::uint32_t> soup_vertex;
    mesh.add_property(soup_vertex);
    for (const auto& t : faces)
        for (const auto v : t)
            if (remap[v] < 0) {
                remap[v] = static_cast<std::int64_t>(handles.size());
                handles.push_back(mesh.add_vertex(to_om(unique[v])));
                mesh.property(soup_vertex, handles.back()) = unique_source[v];
            }

    // 5. Faces, repairing non-manifold configurations by splitting vertices.
    omerr().disable(); // failed add_face attempts are expected and handled
    OpenMesh::FPropHandleT<std::uint32_t> soup_face;
    mesh.add_property(soup_face);
    RepairingFaceAdder adder(mesh, soup_vertex);
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const auto& t = faces[f];
        if (const auto fh = adder.add({handles[remap[t[0]]], handles[remap[t[1]]], handles[remap[t[2]]]}); fh.is_valid())
            mesh.property(soup_face, fh) = kept_source[f];
    }
    report.split_vertices = adder.finish();
    report.split_vertices += split_complex_vertices(mesh, soup_vertex, soup_face);
    omerr().enable();
    out.vertex_source.resize(mesh.n_vertices());
    for (const auto vh : mesh.vertices()) out.vertex_source[vh.idx()] = mesh.property(soup_vertex, vh);
    mesh.remove_property(soup_vertex);
    std::vector<std::uint32_t> face_source(mesh.n_faces());
    for (const auto fh : mesh.faces()) face_source[slot(fh)] = mesh.property(soup_face, fh);
    mesh.remove_property(soup_face);

    report.vertices = handles.size(); // welded input; split copies are counted apart
    report.faces = mesh.n_faces();
    orient_components(mesh, report, face_source);
    compute_vertex_normals(mesh);
    if (!soup.normals.empty()) out.corner_normals = corner_normals(mesh, soup, face_source);
    if (soup.triangle_object.size() == soup.triangles.size() && soup.triangle_material.size() == soup.triangles.size() &&
        !soup.triangles.empty()) {
        out.objects = soup.objects;
        out.materials = soup.materials;
        out.face_object.resize(mesh.n_faces());
        out.face_material.resize(mesh.n_faces());
        for (std::size_t f = 0; f < face_source.size(); ++f) {
            out.face_object[f] = soup.triangle_object[face_source[f]];
            out.face_material[f] = soup.triangle_material[face_source[f]];
        }
    }

    report.bbox_min = report.bbox_max = to_glm(mesh.point(Mesh::VertexHandle(0)));
    for (const auto vh : mesh.vertices()) {
        const glm::dvec3 p = to_glm(mesh.point(vh));
        report.bbox_min = glm::min(report.bbox_min, p);
        report.bbox_max = glm::max(report.bbox_max, p);
    }
    return out;
}

} // namespace snaxels
