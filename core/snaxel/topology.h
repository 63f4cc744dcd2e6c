#pragma once
/// Flat, cache-friendly connectivity of a Mesh for the snaxel engine:
/// edges with their end vertices and faces, faces with their corners and
/// edges, and every vertex's neighbours in circular order.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>

#include "snaxels/mesh/mesh.h"

namespace snaxels {

struct MeshRefinement;  // core/snaxel/refine.h
struct ParabolicResult; // core/snaxel/parabolic.h

struct MeshTopology {
    static constexpr std::int32_t kNone = -1;

    std::vector<glm::dvec3> positions;  ///< #V
    std::vector<glm::dvec3> normals;    ///< #V, unit
    std::vector<std::array<std::int32_t, 2>> edge_vertices; ///< #E, (from, to) of halfedge 0
    std::vector<std::array<std::int32_t, 2>> edge_faces;    ///< #E, kNone on a boundary side
    std::vector<std::array<std::int32_t, 3>> face_vertices; ///< #F, counter-clockwise
    std::vector<std::array<std::int32_t, 3>> face_edges;    ///< #F, edge k joins corners k, k+1
    /// CSR: neighbours of v are ring[ring_start[v] .. ring_start[v+1]), with
    /// the edge to each in ring_edge, in the circulator's circular order.
    std::vector<std::int32_t> ring_start, ring, ring_edge;
    double mean_edge_length = 0.0;
    /// Set on a refined coarse mesh (refine_topology): how the vertices past
    /// the original ones follow them.
    std::shared_ptr<const MeshRefinement> refinement;
    /// When set, the parabolic curves the engine draws for this mesh (found
    /// once, on the pose a job starts from, and carried by its edges as it
    /// moves); else the engine finds them (cached_parabolic).
    std::shared_ptr<const ParabolicResult> parabolic;

    std::size_t n_vertices() const { return positions.size(); }
    /// The mesh's own vertices (the first ones; all of them unless refined).
    std::size_t n_base_vertices() const;
    std::size_t n_edges() const { return edge_vertices.size(); }
    std::size_t n_faces() const { return face_vertices.size(); }
    bool is_boundary_edge(std::int32_t e) const {
        return edge_faces[e][0] == kNone || edge_faces[e][1] == kNone;
    }
    /// The edge's other end.
    std::int32_t opposite(std::int32_t e, std::int32_t v) const {
        return edge_vertices[e][0] == v ? edge_vertices[e][1] : edge_vertices[e][0];
    }
};

/// Builds the flat connectivity of @p mesh (normals as stored on the mesh).
MeshTopology build_topology(const Mesh& mesh);

/// Connected sets of vertices: one set grows from each vertex that
/// @p seeds accepts and no set holds yet, over the edges (v, w) that
/// @p joins accepts. @p set_of[v] becomes v's set, or -1; returns the count.
template <class Seeds, class Joins>
std::int32_t grow_vertex_sets(const MeshTopology& topo, std::vector<std::int32_t>& set_of, Seeds&& seeds, Joins&& joins) {
    set_of.assign(topo.n_vertices(), -1);
    std::vector<std::int32_t> stack;
    std::int32_t count = 0;
    for (std::int32_t seed = 0; seed < std::int32_t(topo.n_vertices()); ++seed) {
        if (set_of[std::size_t(seed)] >= 0 || !seeds(seed)) continue;
        set_of[std::size_t(seed)] = count;
        stack.push_back(seed);
        while (!stack.empty()) {
            const std::int32_t v = stack.back();
            stack.pop_back();
            for (std::int32_t i = topo.ring_start[std::size_t(v)]; i < topo.ring_start[std::size_t(v) + 1]; ++i) {
                const std::int32_t w = topo.ring[std::size_t(i)];
                if (set_of[std::size_t(w)] < 0 && joins(v, w)) {
                    set_of[std::size_t(w)] = count;
                    stack.push_back(w);
                }
            }
        }
        ++count;
    }
    return count;
}

} // namespace snaxels

namespace snaxels {

/// Recomputes every vertex normal of @p topology from its current positions
/// (area-weighted face normals, as on import), after the mesh moved. On a
/// refined mesh, after its base vertices moved: the added vertices follow
/// them (positions and normals interpolated over the original faces).
void recompute_normals(MeshTopology& topology);

} // namespace snaxels
