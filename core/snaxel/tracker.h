#pragma once
/// Tracking one contour through an animation (the paper's "Animation"
/// section): each frame the fronts move on from where they were. Snaxels
/// that stay on their edge keep their identity; where a front passes a
/// vertex its snaxel fans out and one child (the nearest) keeps the identity,
/// the others are born from it; where a front retreats past a vertex the
/// snaxels it leaves behind are born from the one that retreated. Regions
/// that appear away from every live front are seeded fresh (creations).
/// Loops are matched across frames through these identities, which yields
/// the visual events: creation, annihilation, split and merge.

#include <cstdint>
#include <memory>
#include <vector>

#include "snaxels/snaxel/snaxel_engine.h"

namespace snaxels {

struct IntersectionCurves;

enum class EventKind { Creation, Annihilation, Split, Merge };

const char* event_name(EventKind kind);

struct VisualEvent {
    EventKind kind = EventKind::Creation;
    int frame = 0;
    glm::dvec3 where{0.0}; ///< mesh coordinates
};

/// One frame of a tracked contour.
struct TrackedFrame {
    int frame = 0;
    ContourResult contour;                 ///< fronts (polished); regions are not tracked
    std::vector<std::uint64_t> snaxel_id;  ///< per snaxel: identity, stable while it lives
    std::vector<std::uint64_t> born_from;  ///< per snaxel born this frame: its parent's id; else 0
    /// Per loop: its contour sequence. A loop continues its predecessor's
    /// sequence when each is the other's main branch (most shared snaxels),
    /// so a silhouette that absorbs or sheds a small loop goes on.
    std::vector<std::uint64_t> loop_sequence;
    std::vector<VisualEvent> events;
    std::size_t fanouts = 0, retreats = 0;
};

class ContourTracker {
  public:
    /// Tracks @p spec on @p topology's mesh, starting in its pose.
    ContourTracker(const MeshTopology& topology, const ContourSpec& spec,
                   const EngineOptions& options = {});

    /// Advances to the next frame, the mesh in the pose it was in: from
    /// scratch on the first call, tracked after.
    const TrackedFrame& step(const Camera& camera, const Light& light);
    /// Advances to the next frame with the mesh in @p pose (a moving mesh):
    /// another pose of the same connectivity, else InternalError.
    const TrackedFrame& step(const MeshTopology& pose, const Camera& camera, const Light& light);

    const TrackedFrame& current() const { return frame_; }
    /// Frames stepped so far (0: the next step starts from scratch).
    int frames() const { return frame_number_ + 1; }

  private:
    void start(const Camera& camera, const Light& light);
    void track(const Camera& camera, const Light& light);
    /// An intersection line in a new pose: found anew, each snaxel going
    /// on from the one on the same edge through the same face, else born
    /// from the nearest of the frame before.
    void track_intersections();
    // The stages of track(), in order.
    std::vector<VertexId> flip_changed_vertices();
    void sweep_parents(const Fronts& old, const std::vector<VertexId>& changed);
    std::vector<EdgeId> crossing_edges(const Fronts& old, const std::vector<VertexId>& changed);
    void place_snaxels(const ContourFunction& f, const Fronts& old, const std::vector<NormalArc>& old_arc);
    std::vector<std::int32_t> assign_identities(const TrackedFrame& prev, const std::vector<glm::dvec3>& old_position);
    void match_loops(const TrackedFrame& prev, const std::vector<glm::dvec3>& old_position,
                     const std::vector<std::int32_t>& source);

    MeshTopology topo_; ///< the mesh in the pose of the current frame
    ContourSpec spec_;
    EngineOptions options_;
    TrackedFrame frame_;
    int frame_number_ = -1;
    std::uint64_t next_id_ = 1, next_sequence_ = 1;
    VertexData<std::uint8_t> inside_;
    std::vector<glm::dvec3> snaxel_position_; ///< of the current frame's snaxels
    /// The arcs between the normals of the current frame's snaxels' edges
    /// (unknown where the root did not need one), and the pose they are of:
    /// a snaxel that stays on its edge in that pose takes its arc on.
    std::vector<NormalArc> snaxel_arc_;
    std::weak_ptr<const MeshPose> arc_pose_;
    /// An intersection line's curves in the current frame's pose.
    std::shared_ptr<const IntersectionCurves> curves_;
    // Scratch, kept between frames to avoid reallocation.
    VertexData<std::int32_t> vertex_parent_; ///< the old snaxel that passed each vertex, or kNoSnaxel
    std::vector<VertexId> parented_;          ///< the vertices vertex_parent_ holds a snaxel for
    EdgeData<std::uint8_t> edge_mark_;
    EdgeData<std::int32_t> spare_edge_snaxel_; ///< the frame before's edge lookup, cleared: the next one
};

} // namespace snaxels
