#pragma once
/// The snaxel-defined visible-surface planar map (the paper's "Planar Map
/// Generation", second method), in the fronts-as-region-boundaries form of
/// docs/engine.md: every vertex carries the label its converged fronts give
/// it, and the map's regions are the connected sets of equal labels, bounded
/// by the fronts on the edges between them.
///
/// The paper's amended rules, and where they act here:
///  1. Fronts of every kind collide: a vertex's label combines all kinds
///     (visual, shadow, isophotes, gleam) into one map class.
///  2. Collisions in the image plane: a vertex behind a nearer surface (a
///     ray to the viewer is blocked) is inside a closer front's projection.
///  3. Same kinds merge and split (one region per connected label set);
///     different kinds push against each other: where labels differ along an
///     edge, the front stops at that kind's root (the engine's snaxel on the
///     edge), and where three labels meet in a face, at a junction inside it.
///  4. Occluded fronts yield to visible ones (f_pmap = -delta f): occluded
///     vertices leave every region, and the visible region's front stops on
///     the edge where the ray to the viewer becomes blocked (bisected), the
///     projection of the nearer front. Darker isophotes yield to brighter
///     ones: a vertex takes the brightest band whose isophote it is inside.
/// Surface seen although turned away from the viewer (inside an open mesh
/// through a hole, or a corner past the contour of interpolated normals)
/// forms regions of its own, classed by N.L.
/// The labels are the converged state: each region is grown (flood fill)
/// from a seed vertex, and every vertex no front reached is reseeded until
/// all are covered. A region must hold a vertex whose whole ring shares its
/// label (room for a front) or be more than a fleck: the corners and flecks
/// of a few vertices that interpolated normals and per-vertex tests leave
/// are dissolved into their neighbours, so slivers thinner than the tessellation, which
/// polygon clipping of separately discretized contours produces, cannot
/// arise.

#include <memory>
#include <vector>

#include "snaxels/planarmap/region.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/visibility/ray_scene.h"

namespace snaxels {

/// What a ray to the viewer finds from each vertex, cast before the
/// contours are known (they need only the pose, the camera and the visual
/// contour's function at the vertices, which every tracker of it computes
/// the same way), so that the rays run beside the tracking. The map takes a
/// vertex's result only where the side it was cast from is the side the
/// visual contour's own vertex values give; it casts the others itself.
struct VertexSight {
    /// Per vertex: kTurnedAway when cast from the back side (the visual
    /// contour's function below 0 there), kCast when a ray was cast,
    /// kBlocked when it was blocked.
    static constexpr std::uint8_t kTurnedAway = 1, kCast = 2, kBlocked = 4;
    VertexData<std::uint8_t> code;
    /// What they were cast in: a map of another pose or camera casts its own.
    std::shared_ptr<const MeshPose> pose;
    Camera camera;
    bool open = false; ///< whether the mesh has a boundary edge (else no ray from a vertex turned away)
};

/// The rays of @p topology's vertices to @p camera's viewer against
/// @p rays (of the same pose), as build_snaxel_map casts them, for the
/// visual contour @p visual.
VertexSight see_vertices(const MeshTopology& topology, const RayScene& rays, const Camera& camera, const Light& light,
                         const ContourSpec& visual);

struct SnaxelMapInput {
    const ContourResult* visual = nullptr;       ///< required: the two sides of the surface
    const ContourResult* shadow = nullptr;       ///< none: everything visible is lit
    std::vector<const ContourResult*> isophotes; ///< ascending k
    std::vector<const ContourResult*> gleams;    ///< ascending k: each a highlight level inside the one before
    /// Locating an occlusion boundary on an edge: bisection until the step
    /// projects under tolerance_px, at most bisection_steps times.
    double tolerance_px = 0.25;
    int bisection_steps = 10;
    /// A region without an interior vertex (one whose whole ring shares its
    /// label) is dissolved if it has fewer vertices than this and covers
    /// less of the image than min_fleck_area_px (its vertices' share of
    /// their faces' projected area): on a coarse mesh a few vertices can
    /// span a large, real region.
    int min_unsupported_vertices = 6;
    double min_fleck_area_px = 16.0;
    /// The vertices' rays, when cast beforehand (see_vertices); else the map casts them.
    const VertexSight* sight = nullptr;
};

struct SnaxelMapStats {
    std::size_t visible_vertices = 0, occluded_vertices = 0;
    std::size_t seeds = 0; ///< regions grown, over every pass: the first seed and every reseed
    std::size_t open_outlines = 0; ///< region outlines that failed to close (none on a manifold mesh)
    double ms = 0.0;
};

struct SnaxelMap {
    std::vector<MapRegion> regions;         ///< depth: order of mean depth, 0 nearest
    VertexData<std::int32_t> vertex_region; ///< per vertex: index into regions, or -1 (occluded)
    SnaxelMapStats stats;
};

/// The visible-surface map of @p input seen by @p camera and lit by
/// @p light; @p rays is the BVH of the engine's topology at its current
/// positions.
SnaxelMap build_snaxel_map(const SnaxelEngine& engine, const SnaxelMapInput& input, const RayScene& rays,
                           const ImageProjection& projection, const Camera& camera, const Light& light);

} // namespace snaxels
