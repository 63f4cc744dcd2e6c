#include "snaxels/scene/orbit.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace snaxels {

glm::dvec3 model_front(const glm::dvec3& up_in) {
    const glm::dvec3 up = glm::normalize(up_in);
    const glm::dvec3 z(0.0, 0.0, 1.0);
    glm::dvec3 f = std::abs(up.z) < 0.9 ? z : glm::dvec3(0.0, up.z > 0.0 ? -1.0 : 1.0, 0.0);
    return glm::normalize(f - glm::dot(f, up) * up);
}

glm::dvec3 default_view_dir(const glm::dvec3& up_in) { return view_dir_at(up_in, kDefaultYaw, kDefaultPitch); }

glm::dvec3 view_dir_at(const glm::dvec3& up_in, double yaw, double pitch) {
    const glm::dvec3 up = glm::normalize(up_in);
    const glm::dvec3 front = model_front(up), right = glm::cross(up, front);
    // As the orbit places its eye at a yaw: toward +right for a negative yaw.
    const glm::dvec3 level = std::cos(yaw) * front - std::sin(yaw) * right;
    const glm::dvec3 to_eye = std::cos(pitch) * level + std::sin(pitch) * up;
    return -glm::normalize(to_eye);
}

const std::vector<NamedView>& named_views() {
    static const std::vector<NamedView> views{
        {"front", 0.0, 0.0, "the model's front, level"},
        {"back", M_PI, 0.0, "its back, level"},
        {"left", M_PI_2, 0.0, "its left side, level"},
        {"right", -M_PI_2, 0.0, "its right side, level"},
        {"top", 0.0, kMaxPitch, "from above (short of straight down by the orbit's pitch limit)"},
        {"iso", -M_PI_4, std::atan(1.0 / std::sqrt(2.0)), "isometric: 45 degrees around, 35.264 above", true},
        {"dimetric", -M_PI_4, M_PI / 6.0, "the 2:1 dimetric: 45 degrees around, 30 above", true},
        {"trimetric", -M_PI / 6.0, M_PI / 9.0, "trimetric: 30 degrees around, 20 above", true},
    };
    return views;
}

namespace {

/// World to the model's frame: rows right, up, front (an orthonormal,
/// right-handed basis; the identity for +Y up).
glm::dmat4 model_frame(const glm::dvec3& up_in) {
    const glm::dvec3 up = glm::normalize(up_in);
    const glm::dvec3 front = model_front(up);
    const glm::dvec3 right = glm::cross(up, front);
    glm::dmat4 m(1.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = right[c];
        m[c][1] = up[c];
        m[c][2] = front[c];
    }
    return m;
}

} // namespace

double framing_distance(double radius, double fov_deg) {
    return radius / std::sin(glm::radians(fov_deg * 0.5)) * 1.05;
}

OrbitView framing_view(const glm::dvec3& centre, double radius, const glm::dvec3& up) {
    OrbitView v;
    v.centre = centre;
    v.up = glm::normalize(up);
    v.distance = framing_distance(radius, v.fov_deg);
    return v;
}

glm::dmat4 orbit_view_matrix(const OrbitView& o) {
    glm::dmat4 v = glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.0, -o.distance) + o.pan);
    v = glm::rotate(v, o.pitch, glm::dvec3(1, 0, 0));
    // The camera orbits by +turntable: the world turns the other way.
    v = glm::rotate(v, o.yaw - o.turntable, glm::dvec3(0, 1, 0));
    if (o.up != glm::dvec3(0.0, 1.0, 0.0)) v = v * model_frame(o.up);
    return glm::translate(v, -o.centre);
}

const NamedView* find_named_view(const std::string& name) {
    for (const NamedView& v : named_views())
        if (name == v.name) return &v;
    return nullptr;
}

OrbitView preset_view(OrbitView view, const NamedView& preset) {
    // Right looks from +X of the model's frame (right = up x front), the
    // front view's right hand, as Blender's and Maya's right views do.
    view.yaw = preset.yaw;
    view.pitch = preset.pitch;
    if (preset.axonometric) view.orthographic = true;
    return view;
}

double orbit_view_height(const OrbitView& o) { return 2.0 * o.distance * std::tan(glm::radians(o.fov_deg * 0.5)); }

Camera orbit_camera(const OrbitView& o) {
    // The inverse view matrix gives the eye and its axes in world space.
    const glm::dmat4 inv = glm::inverse(orbit_view_matrix(o));
    Camera c;
    c.projection = o.orthographic ? Camera::Projection::Orthographic : Camera::Projection::Perspective;
    c.eye = glm::dvec3(inv * glm::dvec4(0, 0, 0, 1));
    const glm::dvec3 forward = glm::normalize(glm::dvec3(inv * glm::dvec4(0, 0, -1, 0)));
    c.target = c.eye + forward * o.distance;
    c.up = glm::normalize(glm::dvec3(inv * glm::dvec4(0, 1, 0, 0)));
    c.fov_deg = o.fov_deg;
    if (o.orthographic) {
        c.view_dir = forward;
        c.ortho_height = orbit_view_height(o);
    }
    return c;
}

Camera orbit_base_camera(OrbitView o) {
    o.turntable = 0.0;
    Camera c = orbit_camera(o);
    c.up = glm::normalize(o.up); // the turntable's axis; the screen basis is the same (no roll)
    return c;
}

} // namespace snaxels
