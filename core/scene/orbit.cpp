#include "snaxels/scene/orbit.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace snaxels {

OrbitView framing_view(const glm::dvec3& centre, double radius) {
    OrbitView v;
    v.centre = centre;
    v.distance = radius / std::sin(glm::radians(v.fov_deg * 0.5)) * 1.05;
    return v;
}

glm::dmat4 orbit_view_matrix(const OrbitView& o) {
    glm::dmat4 v = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -o.distance) + o.pan);
    v = glm::rotate(v, o.pitch, glm::dvec3(1, 0, 0));
    // The camera orbits by +turntable: the world turns the other way.
    v = glm::rotate(v, o.yaw - o.turntable, glm::dvec3(0, 1, 0));
    return glm::translate(v, -o.centre);
}

Camera orbit_camera(const OrbitView& o) {
    // The inverse view matrix gives the eye and its axes in world space.
    const glm::dmat4 inv = glm::inverse(orbit_view_matrix(o));
    Camera c;
    c.projection = Camera::Projection::Perspective;
    c.eye = glm::dvec3(inv * glm::dvec4(0, 0, 0, 1));
    const glm::dvec3 forward = glm::normalize(glm::dvec3(inv * glm::dvec4(0, 0, -1, 0)));
    c.target = c.eye + forward * o.distance;
    c.up = glm::normalize(glm::dvec3(inv * glm::dvec4(0, 1, 0, 0)));
    c.fov_deg = o.fov_deg;
    return c;
}

Camera orbit_base_camera(OrbitView o) {
    o.turntable = 0.0;
    Camera c = orbit_camera(o);
    c.up = glm::dvec3(0.0, 1.0, 0.0); // the turntable's axis; the screen basis is the same (no roll)
    return c;
}

} // namespace snaxels
