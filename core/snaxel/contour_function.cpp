#include "snaxels/snaxel/contour_function.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "snaxels/error.h"
#include "snaxels/snaxel/suggestive.h"
#include "snaxels/snaxel/feature_edges.h"

namespace snaxels {

std::string ContourSpec::kind_name() const {
    switch (kind) {
    case ContourKind::Visual: return "visual";
    case ContourKind::Shadow: return "shadow";
    case ContourKind::Isophote: return "isophote";
    case ContourKind::Gleam: return "gleam";
    case ContourKind::Parabolic: return "parabolic";
    case ContourKind::Crease: return "crease";
    case ContourKind::Border: return "border";
    case ContourKind::Suggestive: return "suggestive";
    case ContourKind::Material: return "material";
    case ContourKind::Object: return "object";
    case ContourKind::Intersection: return "intersection";
    }
    return "visual";
}

std::string ContourSpec::label() const {
    const std::string selector = parts.empty() ? "" : " " + parts.text();
    if (kind == ContourKind::Visual || kind == ContourKind::Shadow || kind == ContourKind::Parabolic ||
        kind == ContourKind::Border || kind == ContourKind::Material || kind == ContourKind::Object ||
        kind == ContourKind::Intersection)
        return kind_name() + selector;
    char buf[96];
    if (kind == ContourKind::Suggestive && test == SuggestiveTest::Rtsc) std::snprintf(buf, sizeof buf, "suggestive:rtsc:%g", k);
    else if (kind == ContourKind::Suggestive) std::snprintf(buf, sizeof buf, "suggestive:%g:%g", k, min_angle);
    else std::snprintf(buf, sizeof buf, "%s:%g", kind_name().c_str(), k);
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

ContourSpec ContourSpec::parse(const std::string& text) {
    const auto colon = text.find(':');
    const std::string name = text.substr(0, colon);
    ContourSpec spec;
    if (name == "visual" || name == "shadow" || name == "parabolic" || name == "border" || name == "material" ||
        name == "object" || name == "intersection") {
        if (colon != std::string::npos)
            throw Error("contour kind '" + text + "': " + name + " takes no value");
        spec.kind = name == "visual"     ? ContourKind::Visual
                    : name == "shadow"   ? ContourKind::Shadow
                    : name == "border"   ? ContourKind::Border
                    : name == "material" ? ContourKind::Material
                    : name == "object"   ? ContourKind::Object
                    : name == "intersection" ? ContourKind::Intersection
                                         : ContourKind::Parabolic;
        return spec;
    }
    if (name == "crease") {
        spec.kind = ContourKind::Crease;
        spec.k = kDefaultCreaseDegrees;
        if (colon == std::string::npos) return spec;
        if (!read_number(text.substr(colon + 1), spec.k) || spec.k <= 0.0 || spec.k >= 180.0)
            throw Error("contour kind '" + text + "': the crease angle must be a number of degrees above 0 and below 180");
        return spec;
    }
    if (name == "suggestive") {
        // rtsc's test unless the derivative test's values are given.
        spec.kind = ContourKind::Suggestive;
        spec.test = SuggestiveTest::Rtsc;
        spec.k = kDefaultRtscThreshold;
        if (colon == std::string::npos) return spec;
        spec.test = SuggestiveTest::Derivative;
        spec.k = kDefaultSuggestiveDerivative;
        spec.min_angle = kDefaultSuggestiveAngle;
        const std::string rest = text.substr(colon + 1);
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
            return spec;
        }
        read(rest.substr(0, second), spec.k, 0.0, 1e6, "the least derivative D must be a number of at least 0");
        if (second != std::string::npos)
            read(rest.substr(second + 1), spec.min_angle, 0.0, 89.0,
                 "the least angle must be a number of degrees from 0 to 89");
        return spec;
    }
    if (name != "isophote" && name != "gleam")
        throw Error("unknown contour kind '" + text +
                    "' (expected visual, shadow, isophote:K, gleam:K, parabolic, crease[:DEG], border, "
                    "suggestive[:D[:DEG]], suggestive:rtsc[:T], material, object or intersection)");
    spec.kind = name == "isophote" ? ContourKind::Isophote : ContourKind::Gleam;
    if (colon == std::string::npos)
        throw Error("contour kind '" + text + "' needs a value, for example " + name +
                    (name == "gleam" ? ":0.9" : ":0.5"));
    if (!read_number(text.substr(colon + 1), spec.k) || spec.k < -1.0 || spec.k > 1.0)
        throw Error("contour kind '" + text + "': K must be a number from -1 to 1 (a cosine)");
    return spec;
}

ContourFunction::ContourFunction(const ContourSpec& spec, const Camera& camera, const Light& light)
    : spec_(spec), camera_(camera), light_(light) {
    linear_ = spec.kind == ContourKind::Visual && camera.orthographic() && glm::length(camera.view_dir) > 0.0;
    if (linear_) v_ = -glm::normalize(camera.view_dir);
    const bool view_fixed = camera.orthographic() && glm::length(camera.view_dir) > 0.0;
    const bool light_fixed = spec.kind == ContourKind::Visual || (!light.point && glm::length(light.dir) > 0.0);
    closed_ = !spec.on_surface() && spec.kind != ContourKind::Suggestive && view_fixed && light_fixed;
    if (closed_) {
        v_ = camera.to_viewer(glm::dvec3(0.0));
        if (spec.kind != ContourKind::Visual) l_ = light.to_light(glm::dvec3(0.0));
    }
}

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kHalfPi = 1.5707963267948966192313216916398; // std::acos(0.0), to the bit

/// The first y in [0, span] where c0 + a cos y + b sin y turns negative
/// (it is >= 0 at y = 0), or +inf when it does not.
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

} // namespace

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
    double pv, qv;
    coefficients(v_, pv, qv);
    double x = first_downward(0.0, pv, qv, w); // N.V, a term of every kind
    if (spec_.kind == ContourKind::Shadow || spec_.kind == ContourKind::Isophote) {
        const double k = spec_.kind == ContourKind::Isophote ? spec_.k : 0.0;
        double pl, ql;
        coefficients(l_, pl, ql);
        x = std::min(x, first_downward(-k, pl, ql, w));
    } else if (spec_.kind == ContourKind::Gleam) {
        // V.R - k = 2 (N.L)(N.V) - L.V - k: a sinusoid in 2x.
        double pl, ql;
        coefficients(l_, pl, ql);
        const double c0 = pl * pv + ql * qv - glm::dot(l_, v_) - spec_.k;
        x = std::min(x, 0.5 * first_downward(c0, pl * pv - ql * qv, pl * qv + ql * pv, 2.0 * w));
    }
    if (!std::isfinite(x)) return std::numeric_limits<double>::quiet_NaN();
    return std::clamp(x / w, 0.0, 1.0);
}

void ContourFunction::evaluate_vertices(const MeshTopology& topology, VertexData<double>& out) const {
    if (spec_.kind == ContourKind::Suggestive) {
        // kappa_r sin^2(theta) is a curvature (its scale the mesh's), not a cosine: its
        // zeros are its own, and a flat patch's exact 0 is no sign change
        // (suggestive_margins).
        suggestive_function(topology, *require_curvature(topology), camera_, out);
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
        const double k = spec_.k;
        switch (spec_.kind) {
        case ContourKind::Shadow: each([&](const glm::dvec3& n, double) { return glm::dot(n, l_); }); break;
        case ContourKind::Isophote: each([&](const glm::dvec3& n, double) { return glm::dot(n, l_) - k; }); break;
        case ContourKind::Gleam:
            each([&](const glm::dvec3& n, double) { return glm::dot(v_, 2.0 * glm::dot(n, l_) * n - l_) - k; });
            break;
        default: each([](const glm::dvec3&, double nv) { return nv; }); break;
        }
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
    switch (spec_.kind) {
    case ContourKind::Visual:
    case ContourKind::Parabolic:
    case ContourKind::Crease:
    case ContourKind::Border:
    case ContourKind::Material:
    case ContourKind::Object:
    case ContourKind::Intersection:
    case ContourKind::Suggestive: return nv; // not a function of the point alone; see ContourKind
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
