// The weights a style gives the points of a line, and a loop's stroke
// points between its snaxels.
#include "snaxels/export/stroke_weight.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "snaxels/export/detail/stroke_measure.h"
#include "snaxels/export/detail/polyline.h"
#include "snaxels/snaxel/suggestive.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {
namespace {

using namespace detail;


} // namespace

bool needs_weights(const Style& style, const ContourSpec& spec) {
    const ContourStyle cs = style.contour(spec);
    return (cs.visible.draw && cs.visible.width_by != StrokeStyle::WidthBy::None) ||
           (cs.hidden.draw && cs.hidden.width_by != StrokeStyle::WidthBy::None);
}

void weigh_strokes(Drawing& drawing, const Style& style, const SnaxelEngine& engine,
                   const std::vector<ContourResult>& results, const Camera& camera, const Light& light,
                   const glm::dvec3& centre, double radius) {
    for (std::size_t c = 0; c < drawing.contours.size() && c < results.size(); ++c) {
        DrawnContour& contour = drawing.contours[c];
        if (!needs_weights(style, contour.spec)) continue;
        const ContourStyle cs = style.contour(contour.spec);
        // One quantity per kind: the visible strokes' if they have one.
        const StrokeStyle::WidthBy by =
            cs.visible.width_by != StrokeStyle::WidthBy::None ? cs.visible.width_by : cs.hidden.width_by;
        const Fronts& fronts = results[c].fronts;
        std::vector<double> strength;
        if (by == StrokeStyle::WidthBy::Strength && contour.spec.kind == ContourKind::Suggestive) {
            const MeshTopology& topo = engine.topology();
            strength = suggestive_strength(topo, *require_curvature(topo), fronts, camera, contour.spec);
        }
        for (std::size_t l = 0; l < contour.loops.size() && l < fronts.loops.size(); ++l) {
            DrawnLoop& loop = contour.loops[l];
            const std::size_t n = loop.q.size();
            loop.weight.assign(n, 1.0f);
            if (by == StrokeStyle::WidthBy::Depth) {
                const glm::dvec3 forward = camera.forward();
                for (std::size_t k = 0; k < n && k < loop.p.size(); ++k) {
                    const double d = glm::dot(loop.p[k] - centre, forward) / std::max(radius, 1e-12);
                    loop.weight[k] = float(std::clamp(0.5 * (1.0 - d), 0.0, 1.0));
                }
            } else if (by == StrokeStyle::WidthBy::Light) {
                std::size_t k = 0;
                fronts.for_each_in_loop(fronts.loops[l], [&](std::int32_t s) {
                    if (k >= n) return;
                    const Snaxel& sn = fronts.snaxels[s];
                    const double ndotl = glm::dot(engine.normal(sn), light.to_light(engine.position(sn)));
                    loop.weight[k++] = float(std::clamp(0.5 * (1.0 - ndotl), 0.0, 1.0));
                });
            } else if (by == StrokeStyle::WidthBy::Strength) {
                // How far the test passes, faded as rtsc fades its lines:
                // m / (fade + m), 0 where it does not pass.
                const double fade = cs.fade_or_default();
                std::size_t k = 0;
                fronts.for_each_in_loop(fronts.loops[l], [&](std::int32_t s) {
                    if (k >= n || strength.empty()) return;
                    const double m = strength[std::size_t(s)];
                    loop.weight[k++] = m > 0.0 ? float(m / (fade + m)) : 0.0f;
                });
            } else if (by == StrokeStyle::WidthBy::Qi) {
                for (std::size_t k = 0; k < n && k < loop.qi.size(); ++k)
                    loop.weight[k] = loop.qi[k] == kNotDrawn ? 0.0f : float(1.0 - std::min(loop.qi[k], 4) / 4.0);
            } else if (by == StrokeStyle::WidthBy::Curvature && n >= 3) {
                // The circle through the points 4 px either side along the line.
                const std::vector<double> cum = cumulative(loop.q);
                const double length = cum.back() + (loop.closed ? glm::length(loop.q.front() - loop.q.back()) : 0.0);
                DrawnLoop copy;
                copy.q = loop.q;
                copy.closed = loop.closed;
                const LoopAttributes along(copy);
                constexpr double h = 4.0;
                for (std::size_t k = 0; k < n; ++k) {
                    double a = cum[k] - h, b = cum[k] + h;
                    if (!loop.closed) a = std::max(a, 0.0), b = std::min(b, length);
                    const glm::dvec2 p = along.at(a).q, q = loop.q[k], r = along.at(b).q;
                    const double ab = glm::length(q - p), bc = glm::length(r - q), ac = glm::length(r - p);
                    const double cross = std::abs((q - p).x * (r - p).y - (q - p).y * (r - p).x);
                    const double kappa = ab * bc * ac > 1e-12 ? 2.0 * cross / (ab * bc * ac) : 0.0;
                    loop.weight[k] = float(std::clamp(kappa * kCurvatureRadiusPx, 0.0, 1.0));
                }
            }
        }
    }
}

LoopAttributes::LoopAttributes(const DrawnLoop& loop) : loop_(loop), cum_(cumulative(loop.q)) {
    if (!loop.q.empty()) length_ = cum_.back() + (loop.closed ? glm::length(loop.q.front() - loop.q.back()) : 0.0);
}

StrokePoint LoopAttributes::at(double arc) const {
    const std::size_t n = loop_.q.size();
    if (n == 0) return {};
    auto point = [&](std::size_t k) {
        return StrokePoint{loop_.q[k], k < loop_.u.size() ? loop_.u[k] : cum_[k],
                           k < loop_.weight.size() ? double(loop_.weight[k]) : 1.0};
    };
    if (n == 1 || length_ <= 0.0) return point(0);
    if (loop_.closed) arc = wrap(arc, length_);
    else arc = std::clamp(arc, 0.0, length_);
    const std::size_t segs = loop_.closed ? n : n - 1;
    std::size_t k = upper_index(cum_, arc, cum_.size());
    k = std::clamp<std::size_t>(k, 1, segs);
    const std::size_t i = k - 1, j = k % n;
    const double seg = (k < n ? cum_[k] : length_) - cum_[i];
    const double t = seg > 0.0 ? std::clamp((arc - cum_[i]) / seg, 0.0, 1.0) : 0.0;
    const StrokePoint a = point(i), b = point(j);
    double ub = b.u;
    // Across a closed loop's seam the parameter wraps: unwrapped here.
    if (loop_.closed && loop_.u_period > 0.0) ub += loop_.u_period * std::round((a.u - ub) / loop_.u_period);
    return {(1.0 - t) * a.q + t * b.q, (1.0 - t) * a.u + t * ub, (1.0 - t) * a.weight + t * b.weight};
}

double LoopAttributes::arc_of(const glm::dvec2& p) const {
    const std::size_t n = loop_.q.size();
    const std::size_t segs = loop_.closed ? n : (n ? n - 1 : 0);
    double best = 1e300, at = 0.0;
    for (std::size_t s = 0; s < segs; ++s) {
        const glm::dvec2 a = loop_.q[s], b = loop_.q[(s + 1) % n], ab = b - a;
        const double l2 = glm::dot(ab, ab);
        const double t = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
        const double d = glm::length(p - (a + t * ab));
        if (d < best) best = d, at = cum_[s] + t * std::sqrt(l2);
    }
    return at;
}

std::vector<StrokePoint> LoopAttributes::run(const DrawnRun& run) const {
    std::vector<StrokePoint> out;
    if (run.q.empty()) return out;
    out.reserve(run.q.size());
    // Where the run starts along the loop: at its first snaxel, or the
    // change point on the segment before it (not the nearest point of the
    // loop, which near a cusp may lie on another branch).
    double arc = 0.0;
    if (run.first < loop_.q.size()) {
        arc = cum_[run.first];
        if (run.from_change) {
            arc -= glm::length(loop_.q[run.first] - run.q.front());
            if (arc < 0.0 && loop_.closed) arc += length_;
        }
    } else {
        arc = arc_of(run.q.front());
    }
    const std::size_t n = run.q.size(), segments = run.closed ? n : n - 1;
    for (std::size_t k = 0; k < n; ++k) {
        StrokePoint p = at(arc);
        p.q = run.q[k]; // the run's own point (its ends are change points)
        out.push_back(p);
        if (k >= segments) break;
        const glm::dvec2 a = run.q[k], b = run.q[(k + 1) % n];
        const double seg = glm::length(b - a);
        const int pieces = int(std::ceil(seg / kMaxStrokeStepPx));
        for (int i = 1; i < pieces; ++i) {
            const double f = double(i) / double(pieces);
            StrokePoint m = at(arc + f * seg);
            m.q = (1.0 - f) * a + f * b;
            out.push_back(m);
        }
        arc += seg;
    }
    return out;
}

} // namespace snaxels
