#include "core/snaxel/contour_function.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "core/error.h"

namespace snaxels {

std::string ContourSpec::kind_name() const {
    switch (kind) {
    case ContourKind::Visual: return "visual";
    case ContourKind::Shadow: return "shadow";
    case ContourKind::Isophote: return "isophote";
    case ContourKind::Gleam: return "gleam";
    case ContourKind::Parabolic: return "parabolic";
    }
    return "visual";
}

std::string ContourSpec::label() const {
    if (kind == ContourKind::Visual || kind == ContourKind::Shadow || kind == ContourKind::Parabolic) return kind_name();
    char buf[64];
    std::snprintf(buf, sizeof buf, "%s:%g", kind_name().c_str(), k);
    return buf;
}

ContourSpec ContourSpec::parse(const std::string& text) {
    const auto colon = text.find(':');
    const std::string name = text.substr(0, colon);
    ContourSpec spec;
    if (name == "visual" || name == "shadow" || name == "parabolic") {
        if (colon != std::string::npos)
            throw Error("contour kind '" + text + "': " + name + " takes no value");
        spec.kind = name == "visual" ? ContourKind::Visual : name == "shadow" ? ContourKind::Shadow : ContourKind::Parabolic;
        return spec;
    }
    if (name != "isophote" && name != "gleam")
        throw Error("unknown contour kind '" + text +
                    "' (expected visual, shadow, isophote:K, gleam:K or parabolic)");
    spec.kind = name == "isophote" ? ContourKind::Isophote : ContourKind::Gleam;
    if (colon == std::string::npos)
        throw Error("contour kind '" + text + "' needs a value, for example " + name +
                    (name == "gleam" ? ":0.9" : ":0.5"));
    const std::string value = text.substr(colon + 1);
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), spec.k);
    if (ec != std::errc() || end != value.data() + value.size() || !std::isfinite(spec.k) ||
        spec.k < -1.0 || spec.k > 1.0)
        throw Error("contour kind '" + text + "': K must be a number from -1 to 1 (a cosine)");
    return spec;
}

ContourFunction::ContourFunction(const ContourSpec& spec, const Camera& camera, const Light& light)
    : spec_(spec), camera_(camera), light_(light) {
    linear_ = spec.kind == ContourKind::Visual && camera.orthographic() && glm::length(camera.view_dir) > 0.0;
    if (linear_) v_ = -glm::normalize(camera.view_dir);
}

void ContourFunction::evaluate_vertices(const std::vector<glm::dvec3>& positions, const std::vector<glm::dvec3>& normals,
                                        std::vector<double>& out) const {
    out.resize(positions.size());
    if (linear_) {
        for (std::size_t i = 0; i < normals.size(); ++i) out[i] = glm::dot(normals[i], v_);
        return;
    }
    for (std::size_t i = 0; i < positions.size(); ++i) out[i] = (*this)(positions[i], normals[i]);
}

double slerp_dot_root(const glm::dvec3& na, const glm::dvec3& nb, double a, double b) {
    if (a <= 0.0) return 0.0;
    const double c = std::clamp(glm::dot(na, nb), -1.0, 1.0);
    const double w = std::acos(c), s = std::sin(w);
    if (s < 1e-9) { // aligned (or opposite): the slerp's limit is linear
        const double t = a / (a - b);
        return std::clamp(t, 0.0, 1.0);
    }
    // a sin(w - tw) + b sin(tw) = 0  <=>  tan(tw) = a s / (a c - b).
    const double tw = std::atan2(a * s, a * c - b);
    return std::clamp(tw / w, 0.0, 1.0);
}

double ContourFunction::operator()(const glm::dvec3& p, const glm::dvec3& n) const {
    const double f = evaluate(p, n);
    // At the eye or a point light itself V or L is undefined: such a point
    // is taken to lie on the contour.
    return std::isfinite(f) ? f : 0.0;
}

double ContourFunction::evaluate(const glm::dvec3& p, const glm::dvec3& n) const {
    const glm::dvec3 v = camera_.to_viewer(p);
    const double nv = glm::dot(n, v);
    switch (spec_.kind) {
    case ContourKind::Visual:
    case ContourKind::Parabolic: return nv; // not a contour function; see ContourKind
    case ContourKind::Shadow: return std::min(glm::dot(n, light_.to_light(p)), nv);
    case ContourKind::Isophote: return std::min(glm::dot(n, light_.to_light(p)) - spec_.k, nv);
    case ContourKind::Gleam: {
        const glm::dvec3 l = light_.to_light(p);
        const glm::dvec3 r = 2.0 * glm::dot(n, l) * n - l;
        return std::min(glm::dot(v, r) - spec_.k, nv);
    }
    }
    return nv;
}

SlerpArc::SlerpArc(const glm::dvec3& na, const glm::dvec3& nb)
    : na_(na), nb_(nb), c_(std::clamp(glm::dot(na, nb), -1.0, 1.0)), theta_(std::acos(c_)), s_(std::sin(theta_)) {}

glm::dvec3 SlerpArc::operator()(double t) const {
    if (s_ < 1e-9) {
        // Aligned: the limit is na. (Opposite normals have no unique arc;
        // fall back to normalized linear interpolation.)
        if (c_ > 0.0) return na_;
        const glm::dvec3 m = (1.0 - t) * na_ + t * nb_;
        const double len = glm::length(m);
        return len > 1e-12 ? m / len : na_;
    }
    return (std::sin((1.0 - t) * theta_) * na_ + std::sin(t * theta_) * nb_) / s_;
}

glm::dvec3 slerp_normal(const glm::dvec3& na, const glm::dvec3& nb, double t) { return SlerpArc(na, nb)(t); }

} // namespace snaxels
