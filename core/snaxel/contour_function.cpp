#include "snaxels/snaxel/contour_function.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "snaxels/error.h"
#include "snaxels/snaxel/feature_edges.h"

namespace snaxels {

std::string ContourSpec::kind_name() const { return contour_kind_info(kind).name; }

std::string ContourSpec::label() const {
    const std::string selector = parts.empty() ? "" : " " + parts.text();
    char buf[96];
    switch (contour_kind_info(kind).value) {
    case ContourValue::None: return kind_name() + selector;
    case ContourValue::Suggestive:
        if (test == SuggestiveTest::Rtsc) std::snprintf(buf, sizeof buf, "%s:rtsc:%g", kind_name().c_str(), k);
        else std::snprintf(buf, sizeof buf, "%s:%g:%g", kind_name().c_str(), k, min_angle);
        break;
    case ContourValue::Cosine:
    case ContourValue::Angle: std::snprintf(buf, sizeof buf, "%s:%g", kind_name().c_str(), k); break;
    }
    return buf + selector;
}

bool ContourSpec::same_as(const ContourSpec& other) const {
    return kind == other.kind && test == other.test && std::abs(k - other.k) < 1e-9 &&
           std::abs(min_length - other.min_length) < 1e-9 &&
           std::abs(min_angle - other.min_angle) < 1e-9 && parts == other.parts;
}

namespace {

/// @p value as a finite number, all of it read; false if it is not one.
bool read_number(const std::string& value, double& out) {
    const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), out);
    return ec == std::errc() && end == value.data() + value.size() && std::isfinite(out);
}

} // namespace

namespace {

/// The rest of a suggestive contour's --kind after "suggestive:" into @p spec.
void read_suggestive(const std::string& text, const std::string& rest, ContourSpec& spec) {
    spec.test = SuggestiveTest::Derivative;
    spec.k = kDefaultSuggestiveDerivative;
    spec.min_angle = kDefaultSuggestiveAngle;
    const auto second = rest.find(':');
    auto read = [&](const std::string& value, double& out, double lo, double hi, const char* what) {
        if (!read_number(value, out) || out < lo || out > hi) throw Error("contour kind '" + text + "': " + what);
    };
    if (rest.substr(0, second) == "rtsc") {
        spec.test = SuggestiveTest::Rtsc;
        spec.k = kDefaultRtscThreshold;
        spec.min_angle = 0.0;
        if (second != std::string::npos)
            read(rest.substr(second + 1), spec.k, 0.0, 1e6, "the rtsc threshold T must be a number of at least 0");
        return;
    }
    read(rest.substr(0, second), spec.k, 0.0, 1e6, "the least derivative D must be a number of at least 0");
    if (second != std::string::npos)
        read(rest.substr(second + 1), spec.min_angle, 0.0, 89.0, "the least angle must be a number of degrees from 0 to 89");
}

} // namespace

ContourSpec ContourSpec::parse(const std::string& text) {
    const auto colon = text.find(':');
    const std::string name = text.substr(0, colon);
    const ContourKindInfo* info = find_contour_kind(name);
    if (!info) throw Error("unknown contour kind '" + text + "' (expected " + contour_kind_usages(" or ") + ")");
    ContourSpec spec;
    spec.kind = info->kind;
    const bool valued = colon != std::string::npos;
    const std::string value = valued ? text.substr(colon + 1) : std::string();
    switch (info->value) {
    case ContourValue::None:
        if (valued) throw Error("contour kind '" + text + "': " + name + " takes no value");
        break;
    case ContourValue::Angle:
        spec.k = kDefaultCreaseDegrees;
        if (valued && (!read_number(value, spec.k) || spec.k <= 0.0 || spec.k >= 180.0))
            throw Error("contour kind '" + text + "': the " + name + " angle must be a number of degrees above 0 and below 180");
        break;
    case ContourValue::Suggestive:
        // rtsc's test unless the derivative test's values are given.
        spec.test = SuggestiveTest::Rtsc;
        spec.k = kDefaultRtscThreshold;
        if (valued) read_suggestive(text, value, spec);
        break;
    case ContourValue::Cosine:
        if (!valued)
            throw Error("contour kind '" + text + "' needs a value, for example " + name + ":" + (name == "gleam" ? "0.9" : "0.5"));
        if (!read_number(value, spec.k) || spec.k < -1.0 || spec.k > 1.0)
            throw Error("contour kind '" + text + "': K must be a number from -1 to 1 (a cosine)");
        break;
    }
    return spec;
}

ContourFunction::ContourFunction(const ContourSpec& spec, const Camera& camera, const Light& light)
    : spec_(spec), kind_(&contour_kind_info(spec.kind)), camera_(camera), light_(light) {
    linear_ = spec.kind == ContourKind::Visual && camera.orthographic() && glm::length(camera.view_dir) > 0.0;
    if (linear_) v_ = -glm::normalize(camera.view_dir);
    const bool view_fixed = camera.orthographic() && glm::length(camera.view_dir) > 0.0;
    const bool light_fixed = !kind_->lit || (!light.point && glm::length(light.dir) > 0.0);
    closed_ = kind_->origin == ContourOrigin::View && view_fixed && light_fixed;
    if (closed_) {
        v_ = camera.to_viewer(glm::dvec3(0.0));
        if (kind_->lit) l_ = light.to_light(glm::dvec3(0.0));
    }
}

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kHalfPi = 1.5707963267948966192313216916398; // std::acos(0.0), to the bit

} // namespace

double first_downward(double c0, double a, double b, double span) {
    // Zeros at y = phi +- alpha, alpha = acos(-c0 / r); the one with phi +
    // alpha goes down. With no constant term (N.V's and the shadow's) there
    // are zeros unless a = b = 0 (r = hypot(a, b) > 0 otherwise, and a NaN
    // gives no zero either way), and alpha is acos(0): pi/2, the double acos
    // returns for it, without the calls.
    double alpha = kHalfPi;
    if (c0 == 0.0) {
        if (a == 0.0 && b == 0.0) return std::numeric_limits<double>::infinity();
    } else {
        const double r = std::hypot(a, b);
        if (!(r > std::abs(c0))) return c0 < 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
        alpha = std::acos(-c0 / r);
    }
    const double phi = std::atan2(b, a);
    double y = std::fmod(phi + alpha, kTwoPi);
    if (y < 0.0) y += kTwoPi;
    if (y > kTwoPi - 1e-12) y = 0.0; // at the start itself
    return y <= span ? y : std::numeric_limits<double>::infinity();
}

NormalArc normal_arc(const glm::dvec3& na, const glm::dvec3& nb) {
    const double c = std::clamp(glm::dot(na, nb), -1.0, 1.0), w = std::acos(c);
    return NormalArc{c, w, std::sin(w)};
}

double ContourFunction::first_zero(const glm::dvec3& na, const glm::dvec3& nb, double f_a, double f_b) const {
    return first_zero(na, nb, normal_arc(na, nb), f_a, f_b);
}

double ContourFunction::first_zero(const glm::dvec3& na, const glm::dvec3& nb, const NormalArc& arc, double f_a,
                                   double f_b) const {
    const double c = arc.c, w = arc.w, s = arc.s;
    if (s < 1e-9) {
        if (c < 0.0) return std::numeric_limits<double>::quiet_NaN(); // no unique arc
        return f_a <= 0.0 ? 0.0 : std::clamp(f_a / (f_a - f_b), 0.0, 1.0); // aligned: the slerp's limit is linear
    }
    // Along the arc, at angle x: N.u = P cos x + Q sin x.
    auto coefficients = [&](const glm::dvec3& u, double& p, double& q) {
        p = glm::dot(na, u);
        q = (glm::dot(nb, u) - p * c) / s;
    };
    if (!kind_->arc_zero) return std::numeric_limits<double>::quiet_NaN(); // no closed form: bracketed
    ArcTerms terms;
    terms.w = w;
    coefficients(v_, terms.pv, terms.qv);
    double x = first_downward(0.0, terms.pv, terms.qv, w); // N.V, a term of every kind
    if (kind_->lit) {
        coefficients(l_, terms.pl, terms.ql);
        terms.lv = glm::dot(l_, v_);
    }
    x = std::min(x, kind_->arc_zero(terms, spec_.k));
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    return std::clamp(x / w, 0.0, 1.0);
}

void ContourFunction::evaluate_vertices(const MeshTopology& topology, VertexData<double>& out) const {
    if (kind_->vertices) {
        kind_->vertices(topology, camera_, out);
        return;
    }
    evaluate_vertices(topology.positions(), topology.normals(), out);
    if (!topology.has_strips()) return;
    // A flat face seen edge-on (a box's sides in a front view) has f = 0 at
    // every corner, up to the rounding of the file's single-precision
    // normals: counted as turned away, so the outline runs along the edges
    // nearest the viewer, not along the hidden ones behind them that
    // project to the same place.
    for (double& f : out)
        if (std::abs(f) < kEdgeOn) f = -std::numeric_limits<double>::denorm_min();
}

void ContourFunction::evaluate_vertices(ElementSpan<VertexTag, const glm::dvec3> positions,
                                        ElementSpan<VertexTag, const glm::dvec3> normals, VertexData<double>& out) const {
    out.resize(positions.size());
    if (linear_) {
        for (const VertexId v : normals.ids()) out[v] = glm::dot(normals[v], v_);
        return;
    }
    if (closed_) { // V and L the same everywhere: evaluate() without normalizing them per vertex
        // One loop per kind (the kind chosen once, not per vertex).
        auto each = [&](auto g) {
            for (const VertexId v : normals.ids()) {
                const glm::dvec3& n = normals[v];
                const double nv = glm::dot(n, v_);
                out[v] = std::min(g(n, nv), nv);
            }
        };
        const auto g = kind_->g;
        const double k = spec_.k;
        each([&](const glm::dvec3& n, double) { return g(n, v_, l_, k); });
        return;
    }
    for (const VertexId v : positions.ids()) out[v] = (*this)(positions[v], normals[v]);
}

double slerp_dot_root(const glm::dvec3& na, const glm::dvec3& nb, double a, double b) {
    if (a <= 0.0) return 0.0;
    return slerp_dot_root(normal_arc(na, nb), a, b);
}

double slerp_dot_root(const NormalArc& arc, double a, double b) {
    if (a <= 0.0) return 0.0;
    const double c = arc.c, w = arc.w, s = arc.s;
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
    // Kinds with no g are no function of the point alone: N.V (see ContourKindInfo).
    if (!kind_->g) return nv;
    return std::min(kind_->g(n, v, kind_->lit ? light_.to_light(p) : glm::dvec3(0.0), spec_.k), nv);
}

SlerpArc::SlerpArc(const glm::dvec3& na, const glm::dvec3& nb) : na_(na), nb_(nb), arc_(normal_arc(na, nb)) {}

glm::dvec3 SlerpArc::operator()(double t) const {
    if (arc_.s < 1e-9) {
        // Aligned: the limit is na. (Opposite normals have no unique arc;
        // fall back to normalized linear interpolation.)
        if (arc_.c > 0.0) return na_;
        const glm::dvec3 m = (1.0 - t) * na_ + t * nb_;
        const double len = glm::length(m);
        return len > 1e-12 ? m / len : na_;
    }
    return (std::sin((1.0 - t) * arc_.w) * na_ + std::sin(t * arc_.w) * nb_) / arc_.s;
}

glm::dvec3 slerp_normal(const glm::dvec3& na, const glm::dvec3& nb, double t) { return SlerpArc(na, nb)(t); }

} // namespace snaxels
