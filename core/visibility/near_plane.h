#pragma once
/// The near plane of a perspective camera: where every image stage cuts
/// the picture. Geometry nearer the eye than the plane (and behind the eye)
/// is not drawn and hides nothing; a contour, a region's outline or a path
/// that crosses the plane ends on it. The contours themselves are found on
/// the whole mesh: only what goes into the image is cut.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/mesh/topology.h"
#include "snaxels/scene/camera.h"

namespace snaxels {

/// The near plane's distance of perspective @p camera over @p topology
/// (Camera::near_plane of its bounding radius); 0 for orthographic views.
double near_plane_of(const Camera& camera, const MeshTopology& topology);

/// A perspective camera's near plane, or none (orthographic views: nothing
/// is cut).
class NearPlane {
  public:
    NearPlane() = default; ///< none
    NearPlane(const Camera& camera, const MeshTopology& topology);
    /// The plane of perspective @p camera at @p distance from the eye.
    NearPlane(const Camera& camera, double distance);

    bool active() const { return active_; }
    double distance() const { return distance_; }

    /// How far @p p lies past the plane along the line of sight (negative:
    /// nearer the eye, cut); +infinity without a plane.
    double past(const glm::dvec3& p) const {
        return active_ ? glm::dot(p - eye_, forward_) - distance_ : std::numeric_limits<double>::infinity();
    }
    bool cuts(const glm::dvec3& p) const { return past(p) < 0.0; }

    /// Where segment @p a -> @p b meets the plane, as its parameter in
    /// [0, 1] (depth is linear along it); meaningful where one end is cut
    /// and the other not.
    double crossing(const glm::dvec3& a, const glm::dvec3& b) const;

    /// What of the planar or nearly planar polygon @p loop (closed, in
    /// order) lies past the plane: the loop itself where nothing is cut,
    /// empty where all is, else the loop with its cut stretches replaced by
    /// straight runs on the plane between the points where it crosses.
    std::vector<glm::dvec3> clip(std::span<const glm::dvec3> loop) const;

    /// The pieces of the polyline through @p points that lie past the
    /// plane, each ending where it crosses the plane; the polyline whole
    /// where nothing is cut.
    std::vector<std::vector<glm::dvec3>> clip_polyline(std::vector<glm::dvec3> points) const;

    /// A point of a face cut by the plane: a corner, whose id is its
    /// vertex's index, or where a side crosses the plane, whose id is the
    /// vertex count plus the side's edge index (the same from both faces).
    struct FacePoint {
        std::int64_t id;
        glm::dvec3 p;
    };
    /// What of face @p f of @p topology lies past the plane, as its
    /// corners and crossings in the face's order (Sutherland-Hodgman): the
    /// three corners where nothing is cut, nothing where all is. Both faces
    /// beside an edge place its crossing at the same point.
    void cut_face(const MeshTopology& topology, FaceId f, std::vector<FacePoint>& out) const;

    /// Where a ray from the eye along @p dir enters the picture: on the
    /// plane (what lies nearer is cut); @p origin without a plane.
    glm::dvec3 ray_start(const glm::dvec3& origin, const glm::dvec3& dir) const {
        return active_ ? eye_ + dir * (distance_ / std::max(glm::dot(dir, forward_), 1e-12)) : origin;
    }

  private:
    glm::dvec3 eye_{0.0}, forward_{0.0, 0.0, -1.0};
    double distance_ = 0.0;
    bool active_ = false;
};

/// A perspective eye may stand anywhere but on a surface: a face through
/// the eye is seen edge-on, on the one line of the picture where its two
/// sides meet, and its points have no depth to sort by. Throws
/// snaxels::Error naming the eye and the face when a face of @p topology
/// passes within a millionth of the mesh's bounding radius of it.
void require_eye_off_surface(const Camera& camera, const MeshTopology& topology);

} // namespace snaxels
