#pragma once
/// Flat, cache-friendly connectivity of a Mesh for the snaxel engine:
/// edges with their end vertices and faces, faces with their corners and
/// edges, and every vertex's neighbours in circular order.

#include <array>
#include <cstdint>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "snaxels/mesh/mesh.h"

namespace snaxels {

struct MeshRefinement;  // core/snaxel/refine.h
struct ParabolicResult; // core/snaxel/parabolic.h
struct CurvatureField;  // core/snaxel/curvature.h

/// A mesh's connectivity: fixed for the mesh's life, so one copy, never
/// changed once built, is shared by every pose, frame and thread.
struct MeshConnectivity {
    std::vector<std::array<std::int32_t, 2>> edge_vertices; ///< #E, (from, to) of halfedge 0
    std::vector<std::array<std::int32_t, 2>> edge_faces;    ///< #E, MeshTopology::kNone on a boundary side
    std::vector<std::array<std::int32_t, 3>> face_vertices; ///< #F, counter-clockwise
    std::vector<std::array<std::int32_t, 3>> face_edges;    ///< #F, edge k joins corners k, k+1
    /// CSR: neighbours of v are ring[ring_start[v] .. ring_start[v+1]), with
    /// the edge to each in ring_edge, in the circulator's circular order.
    std::vector<std::int32_t> ring_start, ring, ring_edge;
    /// The mean edge length in the pose the mesh was loaded in: the scale of
    /// the engine's tolerances, kept as the mesh moves so they stay the same
    /// from frame to frame.
    double mean_edge_length = 0.0;
    /// Set on a refined coarse mesh (refine_topology): how the vertices past
    /// the original ones follow them.
    std::shared_ptr<const MeshRefinement> refinement;

    std::size_t n_vertices() const { return ring_start.empty() ? 0 : ring_start.size() - 1; }
    /// The mesh's own vertices (the first ones; all of them unless refined).
    std::size_t n_base_vertices() const;
};

/// Where a mesh's vertices are in one frame: a value (build_topology makes
/// the loaded one, make_pose and FrameDriver one per frame).
struct MeshPose {
    std::vector<glm::dvec3> positions; ///< #V
    std::vector<glm::dvec3> normals;   ///< #V, unit

    /// The pose's curvature, found on first use (pose_curvature() in
    /// core/snaxel/curvature.h) and kept while the pose lives. A copy of a
    /// pose starts without it (its positions may be changed before use).
    class CurvatureCache {
      public:
        CurvatureCache() = default;
        CurvatureCache(const CurvatureCache&) {}
        CurvatureCache& operator=(const CurvatureCache&) { return *this; }
        std::shared_ptr<const CurvatureField> get() const;
        /// Keeps @p field unless one is kept already; returns the kept one.
        std::shared_ptr<const CurvatureField> keep(std::shared_ptr<const CurvatureField> field) const;

      private:
        mutable std::mutex mutex_;
        mutable std::shared_ptr<const CurvatureField> field_;
    };
    CurvatureCache curvature{};
};

/// One pose of one connectivity: what the engine, the tracker, the ray scene
/// and the planar maps read. Both parts are shared and never change, so a
/// topology is a value, cheap to copy and safe to read from any thread; a
/// moving mesh is the same connectivity in a new pose (posed()).
class MeshTopology {
  public:
    static constexpr std::int32_t kNone = -1;

    MeshTopology(); ///< no mesh
    MeshTopology(std::shared_ptr<const MeshConnectivity> connectivity, std::shared_ptr<const MeshPose> pose);

    /// This connectivity in @p pose (as many vertices; else std::invalid_argument).
    MeshTopology posed(std::shared_ptr<const MeshPose> pose) const;
    const std::shared_ptr<const MeshConnectivity>& connectivity() const { return connectivity_; }
    const std::shared_ptr<const MeshPose>& pose() const { return pose_; }
    /// Whether @p other is a pose of the same connectivity (the same object).
    bool same_connectivity(const MeshTopology& other) const { return connectivity_ == other.connectivity_; }

    // Views into the shared parts: valid while this topology (or a copy of
    // it) lives, so name a topology a function returns before looping over
    // one of its views.
    std::span<const glm::dvec3> positions() const { return positions_; } ///< #V
    std::span<const glm::dvec3> normals() const { return normals_; }     ///< #V, unit
    std::span<const std::array<std::int32_t, 2>> edge_vertices() const { return edge_vertices_; }
    std::span<const std::array<std::int32_t, 2>> edge_faces() const { return edge_faces_; }
    std::span<const std::array<std::int32_t, 3>> face_vertices() const { return face_vertices_; }
    std::span<const std::array<std::int32_t, 3>> face_edges() const { return face_edges_; }
    std::span<const std::int32_t> ring_start() const { return ring_start_; }
    std::span<const std::int32_t> ring() const { return ring_; }
    std::span<const std::int32_t> ring_edge() const { return ring_edge_; }
    double mean_edge_length() const { return connectivity_->mean_edge_length; }
    const std::shared_ptr<const MeshRefinement>& refinement() const { return connectivity_->refinement; }

    std::size_t n_vertices() const { return positions_.size(); }
    /// The mesh's own vertices (the first ones; all of them unless refined).
    std::size_t n_base_vertices() const { return connectivity_->n_base_vertices(); }
    std::size_t n_edges() const { return edge_vertices_.size(); }
    std::size_t n_faces() const { return face_vertices_.size(); }
    bool is_boundary_edge(std::int32_t e) const {
        return edge_faces_[std::size_t(e)][0] == kNone || edge_faces_[std::size_t(e)][1] == kNone;
    }
    /// The edge's other end.
    std::int32_t opposite(std::int32_t e, std::int32_t v) const {
        const auto& ends = edge_vertices_[std::size_t(e)];
        return ends[0] == v ? ends[1] : ends[0];
    }

    /// When set, the parabolic curves the engine draws for this mesh (found
    /// once, on the pose a job starts from, and carried by its edges as it
    /// moves); else the engine finds them (cached_parabolic).
    std::shared_ptr<const ParabolicResult> parabolic;

  private:
    std::shared_ptr<const MeshConnectivity> connectivity_;
    std::shared_ptr<const MeshPose> pose_;
    // Views of the two parts, so the engine's loops read them as directly as vectors.
    std::span<const glm::dvec3> positions_, normals_;
    std::span<const std::array<std::int32_t, 2>> edge_vertices_, edge_faces_;
    std::span<const std::array<std::int32_t, 3>> face_vertices_, face_edges_;
    std::span<const std::int32_t> ring_start_, ring_, ring_edge_;
};

/// Builds the flat connectivity of @p mesh, in its pose (normals as stored
/// on the mesh); @p refinement, when the mesh is a refined one, says how its
/// added vertices follow the original ones.
MeshTopology build_topology(const Mesh& mesh, std::shared_ptr<const MeshRefinement> refinement = nullptr);

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
            for (std::int32_t i = topo.ring_start()[std::size_t(v)]; i < topo.ring_start()[std::size_t(v) + 1]; ++i) {
                const std::int32_t w = topo.ring()[std::size_t(i)];
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

/// Half the diagonal of @p topology's bounding box in its pose (0 for no vertices).
double bounding_radius(const MeshTopology& topology);

/// The pose of @p connectivity whose own vertices are at @p positions (its
/// first n_base_vertices() entries; the rest, on a refined mesh, follow
/// them over the original faces), with area-weighted vertex normals as on
/// import.
MeshPose make_pose(const MeshConnectivity& connectivity, std::vector<glm::dvec3> positions);

} // namespace snaxels
