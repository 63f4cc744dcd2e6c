#pragma once
/// Flat, cache-friendly connectivity of a Mesh for the snaxel engine:
/// edges with their end vertices and faces, faces with their corners and
/// edges, and every vertex's neighbours in circular order.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "snaxels/mesh/elements.h"
#include "snaxels/mesh/mesh.h"
#include "snaxels/mesh/quantities.h"

namespace snaxels {

struct MeshRefinement;  // core/mesh/refine.h
struct FaceParts;       // core/mesh/parts.h
struct ParabolicResult; // core/snaxel/parabolic.h
struct CurvatureField;  // core/snaxel/curvature.h

/// A mesh's connectivity: fixed for the mesh's life, so one copy, never
/// changed once built, is shared by every pose, frame and thread.
struct MeshConnectivity {
    EdgeData<std::array<VertexId, 2>> edge_vertices; ///< (from, to) of halfedge 0
    EdgeData<std::array<FaceId, 2>> edge_faces;      ///< MeshTopology::kNone on a boundary side
    FaceData<std::array<VertexId, 3>> face_vertices; ///< counter-clockwise
    FaceData<std::array<EdgeId, 3>> face_edges;      ///< edge k joins corners k, k+1
    /// CSR: neighbours of v are ring[ring_start[v] .. ring_start[v+1]), with
    /// the edge to each in ring_edge, in the circulator's circular order.
    std::vector<std::int32_t> ring_start;
    std::vector<VertexId> ring;
    std::vector<EdgeId> ring_edge;
    /// The mean edge length in the pose the mesh was loaded in: the scale of
    /// the engine's tolerances, kept as the mesh moves so they stay the same
    /// from frame to frame.
    double mean_edge_length = 0.0;
    /// Set on a refined coarse mesh (refine_topology): how the vertices past
    /// the original ones follow them.
    std::shared_ptr<const MeshRefinement> refinement;
    /// Whether the mesh has faces of zero area: the strips of split sharp
    /// edges (core/mesh/sharp_edges.h), and with them flat faces whose
    /// corners share one normal.
    bool has_strips = false;
    /// The scene's objects and materials, per face; null for a mesh
    /// without parts. A refined mesh's face has its original face's parts.
    std::shared_ptr<const FaceParts> parts;
    /// With strips: per vertex, the lowest-numbered vertex at the same point
    /// (the copies of one vertex of a sharp edge name one of them; joined
    /// through the strips' zero-length edges). Empty without strips.
    VertexData<VertexId> point_of;
    /// What is derived from the connectivity alone and so is the same in
    /// every pose (the order in which curvature gathers a vertex's faces,
    /// ...): computed on first use and kept for the mesh's life, under the
    /// keys PoseQuantities describes.
    PoseQuantities quantities{};

    std::size_t n_vertices() const { return ring_start.empty() ? 0 : ring_start.size() - 1; }
    /// The mesh's own vertices (the first ones; all of them unless refined).
    std::size_t n_base_vertices() const;
};

/// Where a mesh's vertices are in one frame: a value (build_topology makes
/// the loaded one, make_pose and FrameDriver one per frame).
struct MeshPose {
    VertexData<glm::dvec3> positions;
    VertexData<glm::dvec3> normals; ///< unit

    /// What is derived from this pose (curvature, parabolic curves, ...),
    /// computed on first use and kept while the pose lives; a copy of a
    /// pose starts without (its positions may be changed before use).
    PoseQuantities quantities{};
};

/// A neighbour of a vertex and the edge to it.
struct RingStep {
    VertexId vertex;
    EdgeId edge;
};

/// The (neighbour, edge) pairs around a vertex (MeshTopology::ring_of).
class RingRange {
  public:
    class iterator {
      public:
        iterator(const VertexId* v, const EdgeId* e) : v_(v), e_(e) {}
        RingStep operator*() const { return {*v_, *e_}; }
        iterator& operator++() { return ++v_, ++e_, *this; }
        bool operator!=(const iterator& o) const { return v_ != o.v_; }

      private:
        const VertexId* v_;
        const EdgeId* e_;
    };
    RingRange(std::span<const VertexId> ring, std::span<const EdgeId> edges)
        : begin_(ring.data(), edges.data()), end_(ring.data() + ring.size(), edges.data() + edges.size()) {}
    iterator begin() const { return begin_; }
    iterator end() const { return end_; }

  private:
    iterator begin_, end_;
};

/// A face at a vertex and the vertex's corner in it (0-2).
struct FaceCorner {
    FaceId face;
    int corner;
};

class MeshTopology;

/// The faces around a vertex, each once (MeshTopology::faces_around).
class FacesAround {
  public:
    class iterator {
      public:
        iterator(const FacesAround& range, std::size_t k) : range_(&range), k_(k) { skip(); }
        FaceCorner operator*() const;
        iterator& operator++() { return ++k_, skip(), *this; }
        bool operator!=(const iterator& o) const { return k_ != o.k_; }

      private:
        void skip();
        const FacesAround* range_;
        std::size_t k_;
    };
    FacesAround(const MeshTopology& topology, VertexId v);
    iterator begin() const { return iterator(*this, 0); }
    iterator end() const { return iterator(*this, edges_.size()); }

  private:
    const MeshTopology* topology_;
    VertexId v_;
    std::span<const EdgeId> edges_; ///< the edges at v_
};

/// One pose of one connectivity: what the engine, the tracker, the ray scene
/// and the planar maps read. Both parts are shared and never change, so a
/// topology is a value, cheap to copy and safe to read from any thread; a
/// moving mesh is the same connectivity in a new pose (posed()).
class MeshTopology {
  public:
    /// "No element": compares equal to the invalid id of every kind.
    static constexpr NoElement kNone{};

    MeshTopology(); ///< no mesh
    MeshTopology(std::shared_ptr<const MeshConnectivity> connectivity, std::shared_ptr<const MeshPose> pose);

    /// This connectivity in @p pose (as many vertices; else
    /// InternalError). The quantities this pose carries to later
    /// poses (PoseQuantities::Lifetime) are kept in @p pose too.
    MeshTopology posed(std::shared_ptr<const MeshPose> pose) const;
    const std::shared_ptr<const MeshConnectivity>& connectivity() const { return connectivity_; }
    const std::shared_ptr<const MeshPose>& pose() const { return pose_; }
    /// Whether @p other is a pose of the same connectivity (the same object).
    bool same_connectivity(const MeshTopology& other) const { return connectivity_ == other.connectivity_; }

    // Views into the shared parts, indexed by element id: valid while this
    // topology (or a copy of it) lives, so name a topology a function
    // returns before looping over one of its views.
    ElementSpan<VertexTag, const glm::dvec3> positions() const { return positions_; }
    ElementSpan<VertexTag, const glm::dvec3> normals() const { return normals_; } ///< unit
    ElementSpan<EdgeTag, const std::array<VertexId, 2>> edge_vertices() const { return edge_vertices_; }
    ElementSpan<EdgeTag, const std::array<FaceId, 2>> edge_faces() const { return edge_faces_; }
    ElementSpan<FaceTag, const std::array<VertexId, 3>> face_vertices() const { return face_vertices_; }
    ElementSpan<FaceTag, const std::array<EdgeId, 3>> face_edges() const { return face_edges_; }
    double mean_edge_length() const { return connectivity_->mean_edge_length; }
    const std::shared_ptr<const MeshRefinement>& refinement() const { return connectivity_->refinement; }
    /// Whether the mesh has split sharp edges (MeshConnectivity::has_strips).
    bool has_strips() const { return connectivity_->has_strips; }
    /// The scene's parts per face, or nullptr (MeshConnectivity::parts).
    const FaceParts* parts() const { return connectivity_->parts.get(); }
    /// Whether @p a and @p b are one point of the surface: the same vertex,
    /// or copies of it along a split sharp edge.
    bool same_point(VertexId a, VertexId b) const {
        return a == b || (connectivity_->has_strips && connectivity_->point_of[a] == connectivity_->point_of[b]);
    }

    std::size_t n_vertices() const { return positions_.size(); }
    /// The mesh's own vertices (the first ones; all of them unless refined).
    std::size_t n_base_vertices() const { return connectivity_->n_base_vertices(); }
    std::size_t n_edges() const { return edge_vertices_.size(); }
    std::size_t n_faces() const { return face_vertices_.size(); }
    std::size_t n_corners() const { return 3 * face_vertices_.size(); }
    ElementRange<VertexTag> vertices() const { return positions_.ids(); }
    ElementRange<EdgeTag> edges() const { return edge_vertices_.ids(); }
    ElementRange<FaceTag> faces() const { return face_vertices_.ids(); }
    ElementRange<CornerTag> corners() const { return ElementRange<CornerTag>(n_corners()); }

    bool is_boundary_edge(EdgeId e) const { return edge_faces_[e][0] == kNone || edge_faces_[e][1] == kNone; }
    /// The edge's other end.
    VertexId opposite(EdgeId e, VertexId v) const {
        const auto& ends = edge_vertices_[e];
        return ends[0] == v ? ends[1] : ends[0];
    }
    /// The vertex at corner @p c.
    VertexId corner_vertex(CornerId c) const { return face_vertices_[face_of(c)][std::size_t(corner_place(c))]; }

    // Circulators: what lies around a vertex, in the ring's circular order.
    // Every stage walks a vertex's neighbourhood through these.

    /// The number of neighbours of @p v.
    int degree(VertexId v) const { return ring_start_[v.index() + 1] - ring_start_[v.index()]; }
    /// The neighbours of @p v.
    std::span<const VertexId> neighbours(VertexId v) const { return ring_.subspan(ring_begin(v), ring_size(v)); }
    /// The edges at @p v, to each neighbour in turn.
    std::span<const EdgeId> vertex_edges(VertexId v) const { return ring_edge_.subspan(ring_begin(v), ring_size(v)); }
    /// (neighbour, edge to it) of @p v.
    RingRange ring_of(VertexId v) const { return RingRange(neighbours(v), vertex_edges(v)); }
    /// Each face at @p v once, with v's corner in it: the face in which the
    /// edge to each neighbour leaves v (the neighbour follows v in the
    /// face's corner order), in ring order. A boundary vertex's last
    /// neighbour has no such face.
    FacesAround faces_around(VertexId v) const { return FacesAround(*this, v); }
    /// Calls @p fn(face) for the faces on both sides of each edge at @p v,
    /// in ring order: each face twice (a face's share of v's area is then
    /// half its share of each edge).
    template <class Fn> void for_each_face_beside_edges(VertexId v, Fn&& fn) const {
        for (const EdgeId e : vertex_edges(v))
            for (const FaceId f : edge_faces_[e])
                if (f != kNone) fn(f);
    }
    /// The face in which the edge @p e leaves @p v (the face on its left
    /// walking from v), or kNone on a boundary.
    FaceId face_leaving(EdgeId e, VertexId v) const { return edge_faces_[e][edge_vertices_[e][0] == v ? 0 : 1]; }
    /// @p v's corner (0-2) in face @p f, or 3 when v is not one of its corners.
    int corner_of(FaceId f, VertexId v) const {
        const auto& fv = face_vertices_[f];
        return fv[0] == v ? 0 : fv[1] == v ? 1 : fv[2] == v ? 2 : 3;
    }

  private:
    // The rings are in CSR form (MeshConnectivity::ring_start), read through
    // the circulators above.
    std::size_t ring_begin(VertexId v) const { return std::size_t(ring_start_[v.index()]); }
    std::size_t ring_size(VertexId v) const { return std::size_t(degree(v)); }

    std::shared_ptr<const MeshConnectivity> connectivity_;
    std::shared_ptr<const MeshPose> pose_;
    // Views of the two parts, so the engine's loops read them as directly as vectors.
    ElementSpan<VertexTag, const glm::dvec3> positions_, normals_;
    ElementSpan<EdgeTag, const std::array<VertexId, 2>> edge_vertices_;
    ElementSpan<EdgeTag, const std::array<FaceId, 2>> edge_faces_;
    ElementSpan<FaceTag, const std::array<VertexId, 3>> face_vertices_;
    ElementSpan<FaceTag, const std::array<EdgeId, 3>> face_edges_;
    std::span<const std::int32_t> ring_start_;
    std::span<const VertexId> ring_;
    std::span<const EdgeId> ring_edge_;
};

inline FacesAround::FacesAround(const MeshTopology& topology, VertexId v)
    : topology_(&topology), v_(v), edges_(topology.vertex_edges(v)) {}

inline void FacesAround::iterator::skip() {
    while (k_ < range_->edges_.size() &&
           range_->topology_->face_leaving(range_->edges_[k_], range_->v_) == MeshTopology::kNone)
        ++k_;
}

inline FaceCorner FacesAround::iterator::operator*() const {
    const FaceId f = range_->topology_->face_leaving(range_->edges_[k_], range_->v_);
    return {f, range_->topology_->corner_of(f, range_->v_)};
}

/// Whether face @p f has an area in @p topology's pose: not one of the
/// zero-area faces a split sharp edge adds (core/mesh/sharp_edges.h), nor a
/// face of rounding-size area made from one by refinement.
bool face_has_area(const MeshTopology& topology, FaceId f);
/// Whether edge @p e lies inside a split sharp edge's strip: none of its
/// faces has an area (a contour there runs along the sharp edge).
bool edge_in_strip(const MeshTopology& topology, EdgeId e);

/// Builds the flat connectivity of @p mesh, in its pose (normals as stored
/// on the mesh); @p refinement, when the mesh is a refined one, says how its
/// added vertices follow the original ones; @p parts, the scene's parts of
/// its faces (in the mesh's face order), when it has them.
MeshTopology build_topology(const Mesh& mesh, std::shared_ptr<const MeshRefinement> refinement = nullptr,
                            std::shared_ptr<const FaceParts> parts = nullptr);

/// Connected sets of vertices: one set grows from each vertex that
/// @p seeds accepts and no set holds yet, over the edges (v, w) that
/// @p joins accepts. @p set_of[v] becomes v's set, or -1; returns the count.
template <class Seeds, class Joins>
std::int32_t grow_vertex_sets(const MeshTopology& topo, VertexData<std::int32_t>& set_of, Seeds&& seeds, Joins&& joins) {
    set_of.assign(topo.n_vertices(), -1);
    std::vector<VertexId> stack;
    std::int32_t count = 0;
    for (const VertexId seed : topo.vertices()) {
        if (set_of[seed] >= 0 || !seeds(seed)) continue;
        set_of[seed] = count;
        stack.push_back(seed);
        while (!stack.empty()) {
            const VertexId v = stack.back();
            stack.pop_back();
            for (const VertexId w : topo.neighbours(v)) {
                if (set_of[w] < 0 && joins(v, w)) {
                    set_of[w] = count;
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
