#include "snaxels/mesh/sharp_edges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <vector>

#include <OpenMesh/Core/System/omstream.hh>
#include <glm/glm.hpp>

namespace snaxels {
namespace {

using Halfedge = Mesh::HalfedgeHandle;

/// How far past its wedge's faces a file's normal at a split vertex may
/// lean before the wedge's own normal replaces it (leans_across).
constexpr double kLeanDegrees = 20.0;

glm::dvec3 face_normal(const Mesh& mesh, Mesh::FaceHandle fh) {
    auto it = mesh.cfv_iter(fh);
    const glm::dvec3 a = to_glm(mesh.point(*it)), b = to_glm(mesh.point(*++it)), c = to_glm(mesh.point(*++it));
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

// The file's normal at @p v's corner of @p fh (zero: none).
glm::dvec3 corner_normal(const LoadedMesh& loaded, Mesh::FaceHandle fh, Mesh::VertexHandle v) {
    auto corner = loaded.corner_normals[slot(fh)].begin();
    for (const auto vh : loaded.mesh.fv_range(fh)) {
        if (vh == v) return *corner;
        ++corner;
    }
    return glm::dvec3(0.0);
}

// Whether the file has no normals and the angle between faces decides
// (kNoNormalsSharpAngle, feature lines only).
bool by_default_angle(const LoadedMesh& loaded, const SurfaceOptions& options) {
    return options.sharp_angle < 0.0 && loaded.corner_normals.empty();
}

// Whether the edge of halfedge @p h (and its twin) is sharp.
bool is_sharp(const LoadedMesh& loaded, Halfedge h, const SurfaceOptions& options) {
    const Mesh& mesh = loaded.mesh;
    const Halfedge t = mesh.opposite_halfedge_handle(h);
    const auto left = mesh.face_handle(h), right = mesh.face_handle(t);
    if (!left.is_valid() || !right.is_valid()) return false; // a border has one side
    const double angle = by_default_angle(loaded, options) ? kNoNormalsSharpAngle : options.sharp_angle;
    if (angle >= 0.0) {
        const double cos_limit = std::cos(glm::radians(std::min(angle, 180.0)));
        return glm::dot(face_normal(mesh, left), face_normal(mesh, right)) < cos_limit;
    }
    const double same = std::cos(glm::radians(kSameNormalDegrees));
    for (const auto v : {mesh.from_vertex_handle(h), mesh.to_vertex_handle(h)}) {
        const glm::dvec3 a = corner_normal(loaded, left, v), b = corner_normal(loaded, right, v);
        const bool known = glm::dot(a, a) > 0.0 && glm::dot(b, b) > 0.0;
        if (known && glm::dot(a, b) < same) return true;
    }
    return false;
}

struct Corners {
    std::vector<std::size_t> parent;
    explicit Corners(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
    std::size_t find(std::size_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(Halfedge a, Halfedge b) { parent[find(slot(a))] = find(slot(b)); }
};

/// Clears the sharp edges of @p sharp that make no feature line. Sharp
/// edges joined at shared vertices make a set; a set's runs are what lies
/// between its ends and branchings (vertices with other than two of its
/// edges). A set is a feature line when its runs are kFeatureLineShare of
/// the bounding box's diagonal long on the average (its length over its
/// ends and branchings, at least one): a box's edges, a cylinder's rims, a
/// part's crease lines, any coarse mesh's edges. A scanner's noise or a
/// fine mesh's tight spots make short runs, short loops and networks that
/// branch at nearly every vertex.
void keep_feature_lines(const LoadedMesh& loaded, std::vector<std::uint8_t>& sharp) {
    const Mesh& mesh = loaded.mesh;
    std::vector<std::size_t> parent(mesh.n_vertices());
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    auto find = [&](std::size_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::vector<int> degree(mesh.n_vertices(), 0);
    for (const auto eh : mesh.edges())
        if (sharp[slot(eh)]) {
            const Halfedge h = mesh.halfedge_handle(eh, 0);
            ++degree[slot(mesh.from_vertex_handle(h))], ++degree[slot(mesh.to_vertex_handle(h))];
            parent[find(slot(mesh.from_vertex_handle(h)))] = find(slot(mesh.to_vertex_handle(h)));
        }
    std::vector<double> length(mesh.n_vertices(), 0.0), joints(mesh.n_vertices(), 0.0);
    for (const auto eh : mesh.edges())
        if (sharp[slot(eh)]) length[find(slot(mesh.from_vertex_handle(mesh.halfedge_handle(eh, 0))))] += mesh.calc_edge_length(eh);
    for (const auto vh : mesh.vertices())
        if (degree[slot(vh)] > 0 && degree[slot(vh)] != 2) joints[find(slot(vh))] += 1.0;
    const double least = kFeatureLineShare * glm::length(loaded.report.bbox_max - loaded.report.bbox_min);
    for (const auto eh : mesh.edges()) {
        if (!sharp[slot(eh)]) continue;
        const std::size_t set = find(slot(mesh.from_vertex_handle(mesh.halfedge_handle(eh, 0))));
        if (length[set] / std::max(1.0, joints[set]) < least) sharp[slot(eh)] = 0;
    }
}

/// A smooth mesh (no sharp edge) whose file's normals decide: @p loaded
/// with each vertex taking the mean of the file's normals at its corners
/// (an exporter's own weighting, or an artist's edited normals, shade it
/// as they do in the program that made it). Nothing when the file has no
/// normals, when they are the ones the mesh has already (within
/// kSameNormalDegrees everywhere), or when more than one vertex in a
/// hundred has a file normal turned away from its faces (a scanner's
/// unoriented normals: the mesh's own shade it then).
std::optional<LoadedMesh> with_file_normals(const LoadedMesh& loaded, const SurfaceOptions& options) {
    if (options.sharp_angle >= 0.0 || loaded.corner_normals.empty()) return std::nullopt;
    const Mesh& mesh = loaded.mesh;
    std::vector<glm::dvec3> file(mesh.n_vertices(), glm::dvec3(0.0));
    for (const auto fh : mesh.faces()) {
        auto corner = loaded.corner_normals[slot(fh)].begin();
        for (const auto vh : mesh.fv_range(fh)) file[slot(vh)] += *corner++;
    }
    const double same = std::cos(glm::radians(kSameNormalDegrees));
    bool differ = false;
    std::size_t turned = 0;
    for (auto& n : file) {
        if (const double len = glm::length(n); len > 0.0) n /= len;
    }
    for (const auto vh : mesh.vertices()) {
        const glm::dvec3& n = file[slot(vh)];
        if (glm::dot(n, n) == 0.0) continue;
        const double agree = glm::dot(n, to_glm(mesh.normal(vh)));
        differ = differ || agree < same;
        turned += agree < 0.0;
    }
    if (!differ || 100 * turned > mesh.n_vertices()) return std::nullopt;
    LoadedMesh out = loaded;
    for (const auto vh : out.mesh.vertices())
        if (const glm::dvec3& n = file[slot(vh)]; glm::dot(n, n) > 0.0) out.mesh.set_normal(vh, to_om(n));
    return out;
}

/// Whether the file's normal @p n at vertex @p v of a split mesh leans out
/// of the faces of v's wedge by more than kLeanDegrees beyond the widest of
/// them: an exporter that averages over every face at a vertex (Blender's
/// normals of a smooth cylinder with flat caps) turns the side's rim
/// normals 45 degrees toward the cap, so the side would shade, and its
/// contour run, as if it rounded into the cap, and the cap's rim, the
/// object's outline there, would draw nothing. Such a copy keeps its
/// wedge's own normal.
bool leans_across(const Mesh& m, Mesh::VertexHandle v, const glm::dvec3& n) {
    const glm::dvec3 own = to_glm(m.normal(v));
    double widest = 1.0; // the least cosine between the wedge's normal and its faces'
    bool any = false;
    for (const auto fh : m.vf_range(v)) {
        const glm::dvec3 f = face_normal(m, fh);
        if (glm::dot(f, f) == 0.0) continue; // a strip face: no area
        widest = std::min(widest, glm::dot(f, own));
        any = true;
    }
    if (!any) return false;
    const double spread = std::acos(std::clamp(widest, -1.0, 1.0));
    return std::acos(std::clamp(glm::dot(n, own), -1.0, 1.0)) > spread + glm::radians(kLeanDegrees);
}

/// Closes the hole round each vertex of @p mesh where three or more wedges
/// meet: its copies' free strip edges @p hole (per original vertex), when
/// they make one loop round it, are fanned by @p add_face(a, b, c, beside)
/// (beside: a face at the vertex, whose part the fan takes).
template <class AddFace>
void close_fans(const Mesh& mesh, const std::unordered_map<int, std::vector<std::pair<std::size_t, std::size_t>>>& hole,
                AddFace&& add_face) {
    for (const auto& [v, edges] : hole) {
        if (edges.size() < 3 || mesh.is_boundary(Mesh::VertexHandle(v))) continue;
        std::unordered_map<std::size_t, std::size_t> next;
        for (const auto& [from, to] : edges) next[from] = to;
        std::vector<std::size_t> cycle{edges.front().first};
        while (cycle.size() <= edges.size()) {
            const auto it = next.find(cycle.back());
            if (it == next.end() || it->second == cycle.front()) break;
            cycle.push_back(it->second);
        }
        if (cycle.size() != edges.size()) continue; // not one loop round the vertex: left open
        Mesh::FaceHandle beside;
        for (const auto fh : mesh.vf_range(Mesh::VertexHandle(v))) beside = fh;
        for (std::size_t i = 1; i + 1 < cycle.size(); ++i) add_face(cycle[0], cycle[i], cycle[i + 1], beside);
    }
}

/// Where the file gave the sharp edges, its own normals shade @p m (the
/// split of @p loaded, whose face corners became the vertices
/// @p corner_vertex): each vertex takes the mean of the file's normals at
/// its corners, unless it leans across its faces.
void with_file_normals_at_corners(const LoadedMesh& loaded, const std::vector<std::size_t>& corner_vertex, Mesh& m) {
    const Mesh& mesh = loaded.mesh;
    std::vector<glm::dvec3> file(m.n_vertices(), glm::dvec3(0.0));
    for (const auto h : mesh.halfedges())
        if (!mesh.is_boundary(h))
            file[corner_vertex[slot(h)]] += corner_normal(loaded, mesh.face_handle(h), mesh.to_vertex_handle(h));
    for (const auto vh : m.vertices()) {
        const double len = glm::length(file[slot(vh)]);
        if (len > 0.0 && !leans_across(m, vh, file[slot(vh)] / len)) m.set_normal(vh, to_om(file[slot(vh)] / len));
    }
}

/// Per edge of @p loaded's mesh, whether it is sharp by @p options (by
/// the default angle, only where it makes a feature line); edges on a
/// border never are.
std::vector<std::uint8_t> sharp_edges_of(const LoadedMesh& loaded, const SurfaceOptions& options) {
    const Mesh& mesh = loaded.mesh;
    std::vector<std::uint8_t> sharp(mesh.n_edges(), 0);
    for (const auto eh : mesh.edges()) {
        const Halfedge h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
        if (!mesh.is_boundary(h0) && !mesh.is_boundary(h1)) sharp[slot(eh)] = is_sharp(loaded, h0, options);
    }
    if (by_default_angle(loaded, options)) keep_feature_lines(loaded, sharp);
    return sharp;
}

/// The split mesh's vertices: the mesh's, and a copy of a vertex for each
/// of its wedges (@p wedges) but the first (counted in @p split); the
/// source vertex of each; and the new vertex of each face corner.
struct WedgeVertices {
    std::vector<Mesh::Point> points;
    std::vector<std::uint32_t> source;
    std::vector<std::size_t> corner_vertex;
};

WedgeVertices wedge_vertices(const LoadedMesh& loaded, Corners& wedges, SharpSplit& split) {
    const Mesh& mesh = loaded.mesh;
    WedgeVertices out;
    std::vector<Mesh::Point>& points = out.points;
    std::vector<std::uint32_t>& source = out.source;
    source = loaded.vertex_source;
    points.reserve(mesh.n_vertices());
    for (const auto vh : mesh.vertices()) points.push_back(mesh.point(vh));
    out.corner_vertex.assign(mesh.n_halfedges(), 0);
    std::unordered_map<std::size_t, std::size_t> vertex_of_wedge;
    for (const auto vh : mesh.vertices()) {
        vertex_of_wedge.clear();
        for (const auto h : mesh.vih_range(vh)) {
            if (mesh.is_boundary(h)) continue;
            auto [it, fresh] = vertex_of_wedge.try_emplace(wedges.find(slot(h)), slot(vh));
            if (fresh && vertex_of_wedge.size() > 1) {
                it->second = points.size();
                points.push_back(mesh.point(vh));
                source.push_back(source[slot(vh)]);
                ++split.copies;
            }
            out.corner_vertex[slot(h)] = it->second;
        }
    }
    return out;
}

} // namespace

std::optional<LoadedMesh> split_sharp_edges(const LoadedMesh& loaded, const SurfaceOptions& options, SharpSplit* what) {
    const Mesh& mesh = loaded.mesh;
    SharpSplit split;
    const std::vector<std::uint8_t> sharp = sharp_edges_of(loaded, options);
    // A face's corner at a vertex is the face's halfedge pointing to it.
    // Corners at one vertex in faces joined by a smooth edge are one wedge.
    Corners wedges(mesh.n_halfedges());
    for (const auto eh : mesh.edges()) {
        const Halfedge h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
        if (mesh.is_boundary(h0) || mesh.is_boundary(h1)) continue;
        if (sharp[slot(eh)]) {
            ++split.sharp_edges;
            continue;
        }
        wedges.unite(h0, mesh.prev_halfedge_handle(h1)); // at h0's end
        wedges.unite(h1, mesh.prev_halfedge_handle(h0)); // at h1's end
    }
    if (split.sharp_edges == 0) {
        if (what) *what = split;
        return with_file_normals(loaded, options);
    }

    auto [points, source, corner_vertex] = wedge_vertices(loaded, wedges, split);
    if (split.copies == 0) {
        if (what) *what = split;
        return std::nullopt; // sharp edges that part no vertex's faces: smooth everywhere
    }

    LoadedMesh out;
    out.report = loaded.report;
    out.vertex_source = std::move(source);
    out.objects = loaded.objects;
    out.materials = loaded.materials;
    out.face_object = loaded.face_object;
    out.face_material = loaded.face_material;
    const bool parts = !loaded.face_object.empty();
    Mesh& m = out.mesh;
    m.reserve(points.size(), mesh.n_edges() + 3 * split.sharp_edges, mesh.n_faces() + 2 * split.sharp_edges);
    std::vector<Mesh::VertexHandle> handle;
    handle.reserve(points.size());
    for (const auto& p : points) handle.push_back(m.add_vertex(p));
    omerr().disable(); // a strip or fan the halfedge structure refuses leaves a hole (below)
    for (const auto fh : mesh.faces()) {
        std::array<Mesh::VertexHandle, 3> c;
        auto corner = c.begin();
        for (const auto h : mesh.fh_range(fh)) *corner++ = handle[corner_vertex[slot(h)]];
        m.add_face(c[0], c[1], c[2]); // the corners in the face's own turn
    }
    // Strips: the face left of h (a -> b) has corners aL, bL, the one on
    // the right aR, bR; the strip is the quad bL, aL, aR, bR, a triangle
    // where one end is not parted. Its free edges at each end (aR -> aL,
    // bL -> bR) close the fan round a vertex where three or more wedges meet.
    // Per original vertex, the free edges of its copies.
    std::unordered_map<int, std::vector<std::pair<std::size_t, std::size_t>>> hole;
    // A strip or fan face belongs to the part of a face beside it.
    auto add_strip_face = [&](std::size_t a, std::size_t b, std::size_t c, Mesh::FaceHandle beside) {
        if (!m.add_face(handle[a], handle[b], handle[c]).is_valid()) return;
        ++split.strip_faces;
        if (!parts) return;
        out.face_object.push_back(beside.is_valid() ? loaded.face_object[slot(beside)] : 0);
        out.face_material.push_back(beside.is_valid() ? loaded.face_material[slot(beside)] : 0);
    };
    for (const auto eh : mesh.edges()) {
        if (!sharp[slot(eh)]) continue;
        const Halfedge h = mesh.halfedge_handle(eh, 0), t = mesh.halfedge_handle(eh, 1);
        const std::size_t bL = corner_vertex[slot(h)], aL = corner_vertex[slot(mesh.prev_halfedge_handle(h))];
        const std::size_t aR = corner_vertex[slot(t)], bR = corner_vertex[slot(mesh.prev_halfedge_handle(t))];
        if (aL != aR) {
            add_strip_face(bL, aL, aR, mesh.face_handle(h));
            hole[mesh.from_vertex_handle(h).idx()].push_back({aR, aL});
        }
        if (bL != bR) {
            add_strip_face(bL, aR, bR, mesh.face_handle(h));
            hole[mesh.to_vertex_handle(h).idx()].push_back({bL, bR});
        }
    }
    close_fans(mesh, hole, add_strip_face);
    omerr().enable();
    compute_vertex_normals(m); // zero-area faces weigh nothing: each copy takes its wedge's normal
    if (options.sharp_angle < 0.0 && !loaded.corner_normals.empty()) with_file_normals_at_corners(loaded, corner_vertex, m);
    if (what) *what = split;
    return out;
}

const LoadedMesh& with_sharp_edges(const LoadedMesh& loaded, const SurfaceOptions& options,
                                   std::optional<LoadedMesh>& storage) {
    storage = split_sharp_edges(loaded, options);
    return storage ? *storage : loaded;
}

} // namespace snaxels
