#include "snaxels/scene/camera.h"

#include <cmath>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

#include "snaxels/error.h"

namespace snaxels {

void Camera::screen_basis(glm::dvec3& right, glm::dvec3& screen_up) const {
    const glm::dvec3 f = forward();
    glm::dvec3 u = glm::normalize(up);
    // Looking straight along `up` (no direction is left across it): fall
    // back to another world axis. Only then: a view a degree off the up
    // axis (an orbit's top view) still takes its roll from `up`, as the
    // orbit's own basis does.
    glm::dvec3 across = glm::cross(f, u);
    if (glm::dot(across, across) < 1e-18) {
        u = std::abs(f.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
        across = glm::cross(f, u);
    }
    right = glm::normalize(across);
    screen_up = glm::cross(right, f);
}

Light default_light(const Camera& camera) {
    glm::dvec3 right, up;
    camera.screen_basis(right, up);
    Light light;
    light.dir = glm::normalize(-camera.forward() + up - right);
    return light;
}

ImageProjection::ImageProjection(const Camera& camera, const glm::dvec3& centre, double radius,
                                 int width, int height, double margin)
    : camera_(camera), centre_(centre), width_(width), height_(height) {
    camera.screen_basis(right_, up_);
    forward_ = camera.forward();
    const double half = 0.5 * (camera.own_frame ? height : std::min(width, height));
    if (camera.orthographic() && (camera.own_frame || camera.ortho_height > 0.0)) {
        // Centred on the eye's line, at the bounding sphere's depth (where
        // pixel rays start from, `back` before it).
        centre_ = camera.eye + forward_ * glm::dot(centre - camera.eye, forward_);
        scale_ = half / std::max(0.5 * camera.ortho_height, 1e-12);
    } else if (camera.orthographic()) {
        scale_ = std::max(half - margin, 1.0) / std::max(radius, 1e-12);
    } else {
        scale_ = half / std::tan(0.5 * camera.fov_deg * M_PI / 180.0);
        near_ = std::max(camera.near_plane(radius), 1e-12);
    }
}

glm::dvec2 ImageProjection::project(const glm::dvec3& p) const {
    if (camera_.orthographic()) {
        const glm::dvec3 d = p - centre_;
        return {0.5 * width_ + scale_ * glm::dot(d, right_), 0.5 * height_ - scale_ * glm::dot(d, up_)};
    }
    const glm::dvec3 d = p - camera_.eye;
    const double depth = std::max(glm::dot(d, forward_), near_);
    return {0.5 * width_ + scale_ * glm::dot(d, right_) / depth,
            0.5 * height_ - scale_ * glm::dot(d, up_) / depth};
}

void ImageProjection::pixel_ray(const glm::dvec2& pixel, double back, glm::dvec3& origin, glm::dvec3& dir) const {
    const double x = (pixel.x - 0.5 * width_) / scale_, y = (0.5 * height_ - pixel.y) / scale_;
    if (camera_.orthographic()) {
        dir = forward_;
        origin = centre_ + x * right_ + y * up_ - back * forward_;
    } else {
        origin = camera_.eye;
        dir = glm::normalize(forward_ + x * right_ + y * up_);
    }
}

nlohmann::json to_json(const Camera& c) {
    nlohmann::json j;
    if (c.orthographic())
        j = {{"projection", "orthographic"}, {"view_dir", {c.view_dir.x, c.view_dir.y, c.view_dir.z}}};
    else
        j = {{"projection", "perspective"},
             {"eye", {c.eye.x, c.eye.y, c.eye.z}},
             {"target", {c.target.x, c.target.y, c.target.z}},
             {"fov_deg", c.fov_deg}};
    // A file's camera: where it stands and what it frames; an orthographic
    // view of the application's orbit: what it frames.
    if (c.own_frame) j["up"] = {c.up.x, c.up.y, c.up.z};
    if (c.orthographic() && (c.own_frame || c.ortho_height > 0.0)) {
        j["eye"] = {c.eye.x, c.eye.y, c.eye.z};
        j["ortho_height"] = c.ortho_height;
    }
    return j;
}

nlohmann::json to_json(const Light& l) {
    if (l.point) return {{"pos", {l.pos.x, l.pos.y, l.pos.z}}};
    const glm::dvec3 d = glm::normalize(l.dir);
    return {{"dir", {d.x, d.y, d.z}}};
}

} // namespace snaxels
