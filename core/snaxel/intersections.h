#pragma once
/// Intersection curves: where two surfaces of the scene pass through each
/// other (two objects, or one object through itself), the curve where they
/// meet. Each point of the curve is where an edge of one surface pierces a
/// face of the other, so the curve is a loop of snaxels on the edges of
/// both surfaces, alternating between them as it crosses their faces.
/// Which edges pierce which faces is decided by exact orientation signs
/// (core/util/detail/predicates.h), with ties broken the same way for every
/// face that shares an edge, so loops close. Surfaces that only touch (a
/// box standing on a floor: faces in one plane, an edge or a vertex lying
/// on the other surface without passing through it) meet in no curve.

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "snaxels/mesh/topology.h"
#include "snaxels/snaxel/fronts.h"

namespace snaxels {

/// The intersection curves of one pose.
struct IntersectionCurves {
    /// The curves as a front set (as feature_fronts makes of creases): each
    /// snaxel on the edge that pierces, at t from the edge's first vertex;
    /// each curve a loop, closed where it closes, open where it runs off a
    /// surface's border. edge_snaxel holds each edge's first snaxel (an
    /// edge may pierce several faces).
    Fronts fronts;
    /// Per snaxel: the face of the other surface its edge pierces there.
    std::vector<FaceId> pierced;
    /// The pairs of faces that cross, each as (f, g) with f < g, ascending:
    /// the curve's segment in f and g runs between two of the snaxels.
    std::vector<std::pair<FaceId, FaceId>> crossing_faces;
};

/// The intersection curves of @p topology in its pose: faces with an area
/// only, pairs of faces that share no point (their vertices, or copies of
/// one along a split sharp edge), broad phase by Embree's BVH collision.
IntersectionCurves find_intersections(const MeshTopology& topology);

/// The same, computed once per pose and kept in it (PoseQuantities).
std::shared_ptr<const IntersectionCurves> require_intersections(const MeshTopology& topology);

/// Pairs (f, g), f < g, of faces with an area of @p topology in its pose
/// whose bounding boxes overlap and which share no point, ascending.
std::vector<std::pair<FaceId, FaceId>> overlapping_face_pairs(const MeshTopology& topology);

} // namespace snaxels
