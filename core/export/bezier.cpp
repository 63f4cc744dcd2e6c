#include "snaxels/export/bezier.h"
#include "snaxels/export/detail/polyline.h"

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <limits>

namespace snaxels {
namespace {

glm::dvec2 cubic(const glm::dvec2& p0, const glm::dvec2& c1, const glm::dvec2& c2, const glm::dvec2& p1, double t) {
    const double s = 1.0 - t;
    return s * s * s * p0 + 3.0 * s * s * t * c1 + 3.0 * s * t * t * c2 + t * t * t * p1;
}

/// Whether @p p lies farther than @p worst from the polyline of @p size
/// points (two or more) at @p line, and if so, in @p d, how far: the least
/// distance to its segments (1e300 when none has one). Segments are
/// visited from segment @p near outward, so a point close to the line stops
/// after a few; the distance is the square root of the least square, which
/// is the least of the square roots to the bit.
bool farther_than(const glm::dvec2& p, const glm::dvec2* line, std::size_t size, std::size_t near, double worst,
                  double& d) {
    const std::size_t segments = size - 1;
    near = std::min(near, segments - 1);
    double best = std::numeric_limits<double>::infinity();
    auto closer = [&](std::size_t i) { // a nearer segment within worst
        const double sq = point_segment_squared(p, line[i], line[i + 1]);
        if (!(sq < best)) return false;
        best = sq;
        return std::sqrt(best) <= worst;
    };
    if (closer(near)) return false;
    for (std::size_t step = 1; step <= near || near + step < segments; ++step) {
        if (step <= near && closer(near - step)) return false;
        if (near + step < segments && closer(near + step)) return false;
    }
    d = best < std::numeric_limits<double>::infinity() ? std::sqrt(best) : 1e300;
    return d > worst;
}

} // namespace

namespace {

// Unit tangent at knot k (of m) from its neighbouring knots; none at open
// ends and at sharp corners (more than 60 degrees), which stay corners.
glm::dvec2 knot_tangent(const std::vector<glm::dvec2>& points, const std::vector<std::size_t>& knots, std::size_t k,
                        bool closed) {
    const std::size_t m = knots.size();
    if (!closed && (k == 0 || k + 1 == m)) return glm::dvec2(0.0);
    const glm::dvec2 prev = points[knots[(k + m - 1) % m]], next = points[knots[(k + 1) % m]], here = points[knots[k]];
    const glm::dvec2 in = here - prev, out = next - here;
    const double li = glm::length(in), lo = glm::length(out);
    if (li <= 0.0 || lo <= 0.0) return glm::dvec2(0.0);
    if (glm::dot(in, out) < 0.5 * li * lo) return glm::dvec2(0.0);
    const glm::dvec2 t = in / li + out / lo;
    const double lt = glm::length(t);
    return lt > 0.0 ? t / lt : glm::dvec2(0.0);
}

// The control points of segment s (knot s to the next).
void segment_controls(const std::vector<glm::dvec2>& points, const std::vector<std::size_t>& knots, bool closed,
                      std::size_t s, glm::dvec2& c1, glm::dvec2& c2) {
    const std::size_t m = knots.size(), n = points.size();
    const std::size_t a = s, b = (s + 1) % m;
    const glm::dvec2 p0 = points[knots[a]], p1 = points[knots[b]];
    const double chord = glm::length(p1 - p0);
    // Knots that were neighbouring points: the polyline is straight there.
    const std::size_t span = closed ? (knots[b] + n - knots[a]) % n : knots[b] - knots[a];
    if (span <= 1) {
        c1 = p0 + (p1 - p0) / 3.0;
        c2 = p1 - (p1 - p0) / 3.0;
        return;
    }
    const glm::dvec2 d = chord > 0.0 ? (p1 - p0) / chord : glm::dvec2(0.0);
    const glm::dvec2 ta = knot_tangent(points, knots, a, closed), tb = knot_tangent(points, knots, b, closed);
    const glm::dvec2 t0 = ta != glm::dvec2(0.0) ? ta : d;
    const glm::dvec2 t1 = tb != glm::dvec2(0.0) ? tb : d;
    c1 = p0 + t0 * (chord / 3.0);
    c2 = p1 - t1 * (chord / 3.0);
}

} // namespace

BezierChain bezier_chain(const std::vector<glm::dvec2>& points, const std::vector<std::size_t>& knots, bool closed) {
    BezierChain chain;
    chain.closed = closed;
    const std::size_t m = knots.size();
    for (const std::size_t k : knots) chain.knots.push_back(points[k]);
    if (m < 2) return chain;
    const std::size_t segments = closed ? m : m - 1;
    chain.c1.resize(segments);
    chain.c2.resize(segments);
    for (std::size_t s = 0; s < segments; ++s) segment_controls(points, knots, closed, s, chain.c1[s], chain.c2[s]);
    return chain;
}

std::vector<glm::dvec2> sample_chain(const BezierChain& chain, int per_segment) {
    std::vector<glm::dvec2> out;
    const std::size_t m = chain.knots.size();
    if (m == 0) return out;
    out.push_back(chain.knots[0]);
    for (std::size_t s = 0; s < chain.c1.size(); ++s)
        for (int i = 1; i <= per_segment; ++i)
            out.push_back(cubic(chain.knots[s], chain.c1[s], chain.c2[s], chain.knots[(s + 1) % m], double(i) / per_segment));
    return out;
}

std::vector<std::size_t> fit_knots(const std::vector<std::vector<glm::dvec2>>& frames, bool closed, double tolerance) {
    const std::size_t n = frames.empty() ? 0 : frames[0].size();
    if (n <= 2) {
        std::vector<std::size_t> all(n);
        for (std::size_t i = 0; i < n; ++i) all[i] = i;
        return all;
    }
    std::vector<std::uint8_t> keep(n, 0);
    keep[0] = 1;
    if (closed) {
        std::size_t far = 0;
        for (std::size_t k = 1; k < n; ++k)
            if (glm::length(frames[0][k] - frames[0][0]) > glm::length(frames[0][far] - frames[0][0])) far = k;
        keep[far] = 1;
        douglas_peucker_joint(frames, 0, far, tolerance, keep);
        douglas_peucker_joint(frames, far, n, tolerance, keep);
    } else {
        keep[n - 1] = 1;
        douglas_peucker_joint(frames, 0, n - 1, tolerance, keep);
    }
    // The curve bends away from the chords where the polyline turns: add the
    // worst point of each segment that strays until none does. A segment's
    // curve depends on its knots and their neighbours alone: rounds that
    // leave those four alone reuse what it found.
    struct Found {
        double worst;
        std::size_t point;
    };
    std::map<std::array<std::size_t, 4>, Found> found;
    constexpr std::size_t kCurvePoints = 17; // a segment's curve, sampled at sixteenths
    std::vector<glm::dvec2> poly;            // a segment's stretch of the polyline
    for (;;) {
        std::vector<std::size_t> knots;
        for (std::size_t i = 0; i < n; ++i)
            if (keep[i]) knots.push_back(i);
        const std::size_t m = knots.size();
        bool added = false;
        const std::size_t segments = closed ? m : m - 1;
        for (std::size_t s = 0; s < segments; ++s) {
            const std::size_t a = knots[s], b = knots[(s + 1) % m];
            const std::size_t before = closed || s > 0 ? knots[(s + m - 1) % m] : n;
            const std::size_t after = closed || s + 2 < m ? knots[(s + 2) % m] : n;
            auto [it, fresh] = found.try_emplace({before, a, b, after}, Found{tolerance, n});
            Found& f = it->second;
            const std::size_t count = closed ? (b + n - a) % n : b - a;
            if (fresh && count > 1) {
                for (const auto& pts : frames) {
                    glm::dvec2 c1, c2;
                    segment_controls(pts, knots, closed, s, c1, c2);
                    const glm::dvec2 p0 = pts[a], p1 = pts[b];
                    std::array<glm::dvec2, kCurvePoints> curve;
                    for (std::size_t i = 0; i < kCurvePoints; ++i) curve[i] = cubic(p0, c1, c2, p1, double(i) / 16.0);
                    poly.clear();
                    for (std::size_t k = 0; k <= count; ++k) poly.push_back(pts[(a + k) % n]);
                    double d = 0.0;
                    for (std::size_t k = 1; k < count; ++k)
                        if (farther_than(poly[k], curve.data(), kCurvePoints, k * 16 / count, f.worst, d))
                            f.worst = d, f.point = (a + k) % n;
                    // The curve's own bulge away from the polyline.
                    for (std::size_t i = 0; i < kCurvePoints; ++i)
                        if (farther_than(curve[i], poly.data(), poly.size(), i * count / 16, f.worst, d)) {
                            f.worst = d;
                            f.point = (a + count / 2) % n;
                        }
                }
            }
            if (f.point < n && !keep[f.point]) keep[f.point] = 1, added = true;
        }
        if (!added) return knots;
    }
}

BezierChain smooth_polyline(const std::vector<glm::dvec2>& points, bool closed, double tolerance) {
    return bezier_chain(points, fit_knots({points}, closed, tolerance), closed);
}

} // namespace snaxels
