#include "snaxels/mesh/refine.h"

#include <algorithm>
#include <memory>

#include <glm/glm.hpp>

namespace snaxels {

int auto_refine_levels(std::size_t faces) {
    int levels = 0;
    while (faces > 0 && levels < kMaxRefineLevels && faces < kRefineTargetFaces) faces *= 4, ++levels;
    return levels;
}

int refine_levels(std::size_t faces, int requested) {
    int levels = requested < 0 ? auto_refine_levels(faces) : std::min(requested, kMaxRefineLevels);
    while (levels > 0 && faces * (std::size_t(1) << (2 * levels)) > kMaxRefinedFaces) --levels;
    return levels;
}

MeshTopology engine_topology(const LoadedMesh& mesh, int levels) {
    return engine_topology(mesh.mesh, levels, loaded_parts(mesh));
}

MeshTopology engine_topology(const Mesh& mesh, int levels, std::shared_ptr<const FaceParts> parts) {
    const MeshTopology topology = build_topology(mesh, nullptr, std::move(parts));
    // The levels go by the faces of the surface: a split sharp edge's
    // zero-area strips add faces but nothing to shade.
    std::size_t faces = topology.n_faces();
    if (topology.has_strips()) {
        faces = 0;
        for (const FaceId f : topology.faces()) faces += face_has_area(topology, f);
    }
    return refine_topology(topology, refine_levels(faces, levels));
}

namespace {

/// A face of a split sharp edge's strip, refined without a grid: it covers
/// nothing, so only its edges of some length need their points (shared with
/// the faces beside them). A triangle with one edge of no length (two
/// corners at one point) becomes a zigzag between its two long edges'
/// points; one whose corners are all at one point stays whole. Appends
/// the faces, in the face's own turn, to @p out; false for a face of no
/// area with no edge of no length (refined as any face).
template <class OnEdge>
bool refine_strip_face(const MeshTopology& t, FaceId f, std::int32_t n, OnEdge&& on_edge,
                       std::vector<std::array<VertexId, 3>>& out) {
    const auto& c = t.face_vertices()[f];
    const auto& fe = t.face_edges()[f]; // edge k joins corners k and k + 1
    const auto P = t.positions();
    std::size_t zero = 0, zeros = 0;
    for (std::size_t k = 0; k < 3; ++k)
        if (P[c[k]] == P[c[(k + 1) % 3]]) zero = k, ++zeros;
    if (zeros == 3 || zeros == 2) {
        out.push_back(c);
        return true;
    }
    if (zeros == 0) return false;
    // Corners k, k + 1 at one point; the apex is corner k + 2, and the long
    // edges run from it to corner k and to corner k + 1.
    const std::size_t k = zero, k1 = (zero + 1) % 3, apex = (zero + 2) % 3;
    auto a = [&](std::int32_t i) { return i == 0 ? c[apex] : i == n ? c[k] : on_edge(fe[apex], c[apex], i); };
    auto b = [&](std::int32_t i) { return i == 0 ? c[apex] : i == n ? c[k1] : on_edge(fe[k1], c[apex], i); };
    out.push_back({c[apex], a(1), b(1)});
    for (std::int32_t i = 1; i < n; ++i) {
        out.push_back({a(i), a(i + 1), b(i + 1)});
        out.push_back({a(i), b(i + 1), b(i)});
    }
    return true;
}

} // namespace

MeshTopology refine_topology(const MeshTopology& t, int levels) {
    if (levels <= 0 || t.n_faces() == 0) return t;
    const std::int32_t n = std::int32_t(1) << levels;
    auto r = std::make_shared<MeshRefinement>();
    r->levels = levels;
    r->base_vertices = t.n_vertices();
    r->base_faces = FaceData<std::array<VertexId, 3>>({t.face_vertices().begin(), t.face_vertices().end()});
    VertexData<glm::dvec3> positions({t.positions().begin(), t.positions().end()}),
        normals({t.normals().begin(), t.normals().end()});
    auto add = [&](const std::array<VertexId, 3>& from, const glm::dvec3& w) {
        const VertexId id(positions.size());
        positions.push_back(w.x * t.positions()[from[0]] + w.y * t.positions()[from[1]] + w.z * t.positions()[from[2]]);
        const glm::dvec3 normal = w.x * t.normals()[from[0]] + w.y * t.normals()[from[1]] + w.z * t.normals()[from[2]];
        const double len = glm::length(normal);
        normals.push_back(len > 0.0 ? normal / len : t.normals()[from[0]]);
        r->from.push_back(from);
        r->weights.push_back(w);
        return id;
    };
    // Points along each edge, from its first vertex, shared by its faces
    // (none along the zero-length edges across a split sharp edge's strip).
    EdgeData<std::int32_t> edge_first(t.n_edges());
    for (const EdgeId e : t.edges()) {
        const VertexId a = t.edge_vertices()[e][0], b = t.edge_vertices()[e][1];
        edge_first[e] = std::int32_t(positions.size());
        if (t.has_strips() && t.positions()[a] == t.positions()[b]) continue;
        for (std::int32_t i = 1; i < n; ++i) {
            const double s = double(i) / double(n);
            add({a, b, a}, {1.0 - s, s, 0.0});
        }
    }
    // The point at step i of n along edge e, counted from vertex v.
    auto on_edge = [&](EdgeId e, VertexId v, std::int32_t i) {
        const std::int32_t along = t.edge_vertices()[e][0] == v ? i : n - i;
        return VertexId(edge_first[e] + along - 1);
    };
    std::vector<std::array<VertexId, 3>> faces;
    const auto side = std::size_t(n + 1);
    faces.reserve(t.n_faces() * side * side);
    std::vector<VertexId> grid(side * side);
    for (const FaceId f : t.faces()) {
        const auto& c = t.face_vertices()[f];
        const auto& fe = t.face_edges()[f]; // edge k joins corners k and k + 1
        if (t.has_strips() && !face_has_area(t, f) && refine_strip_face(t, f, n, on_edge, faces)) {
            r->face_origin.resize(faces.size(), f);
            continue;
        }
        // Point (a, b) of the face's grid: a steps from corner 0 toward 1,
        // b from corner 0 toward 2.
        auto at = [&](std::int32_t a, std::int32_t b) -> VertexId& { return grid[a * (n + 1) + b]; };
        for (std::int32_t a = 0; a <= n; ++a)
            for (std::int32_t b = 0; a + b <= n; ++b) {
                VertexId& id = at(a, b);
                if (a == 0 && b == 0) id = c[0];
                else if (a == n) id = c[1];
                else if (b == n) id = c[2];
                else if (b == 0) id = on_edge(fe[0], c[0], a);
                else if (a + b == n) id = on_edge(fe[1], c[1], b);
                else if (a == 0) id = on_edge(fe[2], c[0], b);
                else id = add(c, {double(n - a - b) / double(n), double(a) / double(n), double(b) / double(n)});
            }
        for (std::int32_t a = 0; a < n; ++a)
            for (std::int32_t b = 0; a + b < n; ++b) {
                faces.push_back({at(a, b), at(a + 1, b), at(a, b + 1)});
                r->face_origin.push_back(f);
                if (a + b + 1 < n) {
                    faces.push_back({at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)});
                    r->face_origin.push_back(f);
                }
            }
    }
    Mesh mesh;
    VertexData<Mesh::VertexHandle> handles;
    for (const VertexId v : positions.ids()) {
        handles.push_back(mesh.add_vertex(to_om(positions[v])));
        mesh.set_normal(handles[v], to_om(normals[v]));
    }
    for (const auto& f : faces) {
        if (!mesh.add_face(handles[f[0]], handles[f[1]], handles[f[2]]).is_valid())
            return t; // cannot happen on a manifold topology; the mesh is then used as it is
    }
    std::shared_ptr<FaceParts> parts;
    if (const FaceParts* base = t.parts()) {
        parts = std::make_shared<FaceParts>();
        parts->objects = base->objects;
        parts->materials = base->materials;
        parts->object.values().reserve(r->face_origin.size());
        parts->material.values().reserve(r->face_origin.size());
        for (const FaceId origin : r->face_origin) {
            parts->object.push_back(base->object[origin]);
            parts->material.push_back(base->material[origin]);
        }
    }
    MeshTopology out = build_topology(mesh, r, std::move(parts)); // faces keep the order they were added in
    if (out.n_faces() != faces.size()) return t;
    return out;
}

} // namespace snaxels
