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

MeshTopology engine_topology(const Mesh& mesh, int levels) {
    return refine_topology(build_topology(mesh), refine_levels(mesh.n_faces(), levels));
}

MeshTopology refine_topology(const MeshTopology& t, int levels) {
    if (levels <= 0 || t.n_faces() == 0) return t;
    const std::int32_t n = std::int32_t(1) << levels;
    auto r = std::make_shared<MeshRefinement>();
    r->levels = levels;
    r->base_vertices = t.n_vertices();
    r->base_faces.assign(t.face_vertices().begin(), t.face_vertices().end());
    std::vector<glm::dvec3> positions(t.positions().begin(), t.positions().end()),
        normals(t.normals().begin(), t.normals().end());
    auto add = [&](const std::array<std::int32_t, 3>& from, const glm::dvec3& w) {
        const auto id = std::int32_t(positions.size());
        positions.push_back(w.x * t.positions()[std::size_t(from[0])] + w.y * t.positions()[std::size_t(from[1])] +
                            w.z * t.positions()[std::size_t(from[2])]);
        const glm::dvec3 normal = w.x * t.normals()[std::size_t(from[0])] + w.y * t.normals()[std::size_t(from[1])] +
                                  w.z * t.normals()[std::size_t(from[2])];
        const double len = glm::length(normal);
        normals.push_back(len > 0.0 ? normal / len : t.normals()[std::size_t(from[0])]);
        r->from.push_back(from);
        r->weights.push_back(w);
        return id;
    };
    // Points along each edge, from its first vertex, shared by its faces.
    std::vector<std::int32_t> edge_first(t.n_edges());
    for (std::size_t e = 0; e < t.n_edges(); ++e) {
        const std::int32_t a = t.edge_vertices()[e][0], b = t.edge_vertices()[e][1];
        edge_first[e] = std::int32_t(positions.size());
        for (std::int32_t i = 1; i < n; ++i) {
            const double s = double(i) / double(n);
            add({a, b, a}, {1.0 - s, s, 0.0});
        }
    }
    // The point at step i of n along edge e, counted from vertex v.
    auto on_edge = [&](std::int32_t e, std::int32_t v, std::int32_t i) {
        const std::int32_t along = t.edge_vertices()[std::size_t(e)][0] == v ? i : n - i;
        return edge_first[std::size_t(e)] + along - 1;
    };
    std::vector<std::array<std::int32_t, 3>> faces;
    faces.reserve(t.n_faces() * std::size_t(n) * std::size_t(n));
    r->face_origin.reserve(faces.capacity());
    std::vector<std::int32_t> grid(std::size_t(n + 1) * std::size_t(n + 1));
    for (std::size_t f = 0; f < t.n_faces(); ++f) {
        const auto& c = t.face_vertices()[f];
        const auto& fe = t.face_edges()[f]; // edge k joins corners k and k + 1
        // Point (a, b) of the face's grid: a steps from corner 0 toward 1,
        // b from corner 0 toward 2.
        for (std::int32_t a = 0; a <= n; ++a)
            for (std::int32_t b = 0; a + b <= n; ++b) {
                std::int32_t id;
                if (a == 0 && b == 0) id = c[0];
                else if (a == n) id = c[1];
                else if (b == n) id = c[2];
                else if (b == 0) id = on_edge(fe[0], c[0], a);
                else if (a + b == n) id = on_edge(fe[1], c[1], b);
                else if (a == 0) id = on_edge(fe[2], c[0], b);
                else id = add(c, {double(n - a - b) / double(n), double(a) / double(n), double(b) / double(n)});
                grid[std::size_t(a) * std::size_t(n + 1) + std::size_t(b)] = id;
            }
        auto at = [&](std::int32_t a, std::int32_t b) { return grid[std::size_t(a) * std::size_t(n + 1) + std::size_t(b)]; };
        for (std::int32_t a = 0; a < n; ++a)
            for (std::int32_t b = 0; a + b < n; ++b) {
                faces.push_back({at(a, b), at(a + 1, b), at(a, b + 1)});
                r->face_origin.push_back(std::int32_t(f));
                if (a + b + 1 < n) {
                    faces.push_back({at(a + 1, b), at(a + 1, b + 1), at(a, b + 1)});
                    r->face_origin.push_back(std::int32_t(f));
                }
            }
    }
    Mesh mesh;
    std::vector<Mesh::VertexHandle> handles;
    handles.reserve(positions.size());
    for (std::size_t v = 0; v < positions.size(); ++v) {
        handles.push_back(mesh.add_vertex(to_om(positions[v])));
        mesh.set_normal(handles.back(), to_om(normals[v]));
    }
    for (const auto& f : faces) {
        if (!mesh.add_face(handles[std::size_t(f[0])], handles[std::size_t(f[1])], handles[std::size_t(f[2])]).is_valid())
            return t; // cannot happen on a manifold topology; the mesh is then used as it is
    }
    MeshTopology out = build_topology(mesh, r); // faces keep the order they were added in
    if (out.n_faces() != faces.size()) return t;
    return out;
}

} // namespace snaxels
