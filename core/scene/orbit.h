#pragma once
/// The application's orbiting camera as numbers a project file keeps: the
/// camera circles a point (the mesh's centre, shifted by a pan in screen
/// space) at a distance, turned by yaw and pitch, with a turntable angle on
/// top. One function turns it into the engine's Camera, so the 3-D view,
/// the project file and the command line see the very same camera.

#include <glm/glm.hpp>

#include "snaxels/scene/camera.h"

namespace snaxels {

struct OrbitView {
    glm::dvec3 centre{0.0}; ///< the mesh's bounding-box centre
    glm::dvec3 pan{0.0};    ///< screen-space shift (x right, y up) in world units
    double yaw = 3.8;       ///< radians about world +Y
    double pitch = 0.3;     ///< radians above the horizon
    double distance = 3.0;  ///< eye to the orbited point
    double turntable = 0.0; ///< radians; the camera orbits by this about world +Y
    double fov_deg = 35.0;  ///< vertical field of view

    bool operator==(const OrbitView&) const = default;
};

/// A three-quarter view from slightly above that frames a sphere of
/// @p radius about @p centre.
OrbitView framing_view(const glm::dvec3& centre, double radius);

/// World to eye space (OpenGL convention: the eye looks down -Z).
glm::dmat4 orbit_view_matrix(const OrbitView& view);

/// The perspective camera of @p view.
Camera orbit_camera(const OrbitView& view);

/// The camera of @p view before the turntable turns, with world +Y up: what
/// an animation export starts from.
Camera orbit_base_camera(OrbitView view);

} // namespace snaxels
