#include "snaxels/export/detail/path_keys.h"

#include <algorithm>
#include <cmath>

#include "snaxels/export/detail/polyline.h"
#include "snaxels/export/detail/svg_writer.h"

namespace snaxels::anim {

double shape_distance(const Subpath& a, const Subpath& b) {
    const std::int64_t n = std::int64_t(a.pts.size());
    if (n == 0) return 0.0;
    if (n == 1) return glm::length(a.pts[0] - b.pts[0]);
    constexpr std::int64_t kWindow = 6;
    auto one_way = [&](const std::vector<glm::dvec2>& from, const std::vector<glm::dvec2>& to) {
        double worst = 0.0;
        for (std::int64_t i = 0; i < n; ++i) {
            double best = 1e300;
            for (std::int64_t k = i - kWindow; k < i + kWindow && best > 0.0; ++k) {
                std::int64_t s0 = k, s1 = k + 1;
                if (a.closed) {
                    s0 = ((s0 % n) + n) % n;
                    s1 = ((s1 % n) + n) % n;
                } else if (s0 < 0 || s1 >= n) {
                    continue;
                }
                best = std::min(best, point_segment(from[i], to[s0], to[s1]));
            }
            worst = std::max(worst, best);
        }
        return worst;
    };
    return std::max(one_way(a.pts, b.pts), one_way(b.pts, a.pts));
}

double shape_distance(const Shape& a, const Shape& b) {
    double worst = 0.0;
    for (std::size_t s = 0; s < a.size(); ++s) worst = std::max(worst, shape_distance(a[s], b[s]));
    return worst;
}

namespace {

Shape lerp(const Shape& a, const Shape& b, double u) {
    Shape out = a;
    for (std::size_t s = 0; s < a.size(); ++s)
        for (std::size_t v = 0; v < a[s].pts.size(); ++v) out[s].pts[v] = (1.0 - u) * a[s].pts[v] + u * b[s].pts[v];
    return out;
}

void reduce_keys(const Segment& seg, std::size_t i, std::size_t j, double tol, std::vector<std::uint8_t>& keep) {
    if (j <= i + 1) return;
    double worst = -1.0;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
        const double u = (seg.times[k] - seg.times[i]) / (seg.times[j] - seg.times[i]);
        const double d = shape_distance(lerp(seg.shapes[i], seg.shapes[j], u), seg.shapes[k]);
        if (d > worst) worst = d, at = k;
    }
    if (worst <= tol) return;
    keep[at] = 1;
    reduce_keys(seg, i, at, tol, keep);
    reduce_keys(seg, at, j, tol, keep);
}

} // namespace

std::vector<std::uint8_t> reduce_keys(const Segment& segment, double tolerance) {
    std::vector<std::uint8_t> keep(segment.times.size(), 0);
    if (keep.empty()) return keep;
    keep.front() = keep.back() = 1;
    reduce_keys(segment, 0, keep.size() - 1, tolerance, keep);
    return keep;
}

void reduce_vertices(Segment& segment, double tolerance, double smoothing,
                     std::vector<std::vector<std::size_t>>* knots) {
    if (segment.shapes.empty()) return;
    const std::size_t subpaths = segment.shapes[0].size();
    if (knots) knots->assign(subpaths, {});
    for (std::size_t s = 0; s < subpaths; ++s) {
        const std::size_t n = segment.shapes[0][s].pts.size();
        const bool closed = segment.shapes[0][s].closed;
        if (n < 3) {
            if (knots)
                for (std::size_t k = 0; k < n; ++k) (*knots)[s].push_back(k);
            continue;
        }
        std::vector<std::vector<glm::dvec2>> frames;
        frames.reserve(segment.shapes.size());
        for (const Shape& shape : segment.shapes) frames.push_back(shape[s].pts);
        if (smoothing > 0.0 && knots) {
            (*knots)[s] = fit_knots(frames, closed, std::max(smoothing, tolerance));
            continue;
        }
        std::vector<std::uint8_t> keep(n, 0);
        if (closed) { // a ring: two chains, from vertex 0 half way round and back to 0
            keep[0] = keep[n / 2] = 1;
            douglas_peucker_joint(frames, 0, n / 2, tolerance, keep);
            douglas_peucker_joint(frames, n / 2, n, tolerance, keep);
        } else {
            keep[0] = keep[n - 1] = 1;
            douglas_peucker_joint(frames, 0, n - 1, tolerance, keep);
        }
        for (Shape& shape : segment.shapes) {
            std::vector<glm::dvec2> kept;
            for (std::size_t k = 0; k < n; ++k)
                if (keep[k]) kept.push_back(shape[s].pts[k]);
            shape[s].pts = std::move(kept);
        }
        if (knots)
            for (std::size_t k = 0, m = 0; k < n; ++k)
                if (keep[k]) (*knots)[s].push_back(m++);
    }
}

std::string path_data(const Shape& shape, const std::vector<std::vector<std::size_t>>* knots) {
    std::string out;
    glm::dvec2 at(0.0); // the current point where the previous subpath left it
    for (std::size_t s = 0; s < shape.size(); ++s) {
        const Subpath& sp = shape[s];
        if (sp.pts.empty()) continue;
        const bool chain = knots && (*knots)[s].size() >= 2 && (*knots)[s].size() < sp.pts.size();
        if (chain) {
            const BezierChain c = bezier_chain(sp.pts, (*knots)[s], sp.closed);
            svg::append_compact_chain_data(out, c, at);
            at = sp.closed ? c.knots.front() : c.knots.back();
        } else if (knots && (*knots)[s].size() < sp.pts.size()) {
            std::vector<glm::dvec2> pts;
            for (const std::size_t k : (*knots)[s]) pts.push_back(sp.pts[k]);
            svg::append_compact_path_data(out, pts, sp.closed, at);
            at = sp.closed || pts.empty() ? (pts.empty() ? at : pts.front()) : pts.back();
        } else {
            svg::append_compact_path_data(out, sp.pts, sp.closed, at);
            at = sp.closed ? sp.pts.front() : sp.pts.back();
        }
    }
    return out;
}

} // namespace snaxels::anim
