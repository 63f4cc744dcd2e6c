// The shape a stroke draws a line as: wobbled, and as filled outlines where
// its width varies.
#include "snaxels/export/stroke_shape.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "snaxels/export/detail/stroke_measure.h"

namespace snaxels {
namespace {

using namespace detail;

constexpr double kPi = 3.141592653589793;
constexpr double kTwoPi = 2.0 * kPi;
/// Points a round cap adds between the two sides of a line's end.
constexpr int kRoundCapPoints = 5;

/// How far along a line (pixels) either side of a point its direction is
/// taken: the chord from kDirectionReach before to as far after, so that
/// the zigzags of a contour at mesh resolution and points that nearly
/// coincide do not turn an outline's sides over (which would open holes
/// under the nonzero rule) or swing a nib's width.
constexpr double kDirectionReach = 2.0;

// A value in [-1, 1] at integer lattice point @p i, from a hash.
double lattice(std::int64_t i) {
    auto x = std::uint64_t(i) * 0x9E3779B97F4A7C15ull;
    x ^= x >> 31;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 29;
    return double(x >> 11) / double(1ull << 53) * 2.0 - 1.0;
}

// Smooth noise along a line: Catmull-Rom through hashed lattice values,
// with a second octave at half the amplitude; about -1 to 1.
double noise1(double x) {
    auto octave = [](double v) {
        const double f = std::floor(v), t = v - f;
        const auto i = std::int64_t(f);
        const double p0 = lattice(i - 1), p1 = lattice(i), p2 = lattice(i + 1), p3 = lattice(i + 2);
        return 0.5 * ((2.0 * p1) + (-p0 + p2) * t + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * t * t +
                      (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * t * t * t);
    };
    return (octave(x) + 0.5 * octave(2.0 * x + 101.37)) / 1.5;
}

// Unit direction of the line at each point: the mean of the directions of
// the segments either side (the nearest that have a length, where points
// coincide), so that offsets turn smoothly and never spike at sharp turns.
std::vector<glm::dvec2> tangents(const std::vector<StrokePoint>& c, bool closed) {
    const std::size_t n = c.size();
    std::vector<glm::dvec2> seg(n, glm::dvec2(0.0)); // direction of segment k -> k+1
    const std::size_t segments = closed ? n : (n ? n - 1 : 0);
    for (std::size_t k = 0; k < segments; ++k) {
        const glm::dvec2 d = c[(k + 1) % n].q - c[k].q;
        const double l = glm::length(d);
        if (l > 1e-9) seg[k] = d / l;
    }
    auto nonzero = [](const glm::dvec2& v) { return v.x != 0.0 || v.y != 0.0; };
    // Segments without length take the nearest one's direction.
    std::vector<glm::dvec2> before(n, glm::dvec2(0.0)), after(n, glm::dvec2(0.0));
    glm::dvec2 last(0.0);
    for (std::size_t pass = 0; pass < (closed ? 2u : 1u); ++pass)
        for (std::size_t k = 0; k < n; ++k) {
            // before[k]: the segment ending at k (k-1 -> k)
            const std::size_t prev = (k + n - 1) % n;
            if ((closed || k > 0) && nonzero(seg[prev])) last = seg[prev];
            if (closed || k > 0) before[k] = last;
        }
    last = glm::dvec2(0.0);
    for (std::size_t pass = 0; pass < (closed ? 2u : 1u); ++pass)
        for (std::size_t i = n; i-- > 0;) {
            if ((closed || i + 1 < n) && nonzero(seg[i])) last = seg[i];
            if (closed || i + 1 < n) after[i] = last;
        }
    std::vector<glm::dvec2> t(n, glm::dvec2(1.0, 0.0));
    for (std::size_t k = 0; k < n; ++k) {
        glm::dvec2 sum = before[k] + after[k];
        if (glm::length(sum) < 1e-6) sum = nonzero(after[k]) ? after[k] : nonzero(before[k]) ? before[k] : glm::dvec2(1.0, 0.0);
        t[k] = glm::normalize(sum);
    }
    return t;
}

glm::dvec2 left_of(const glm::dvec2& t) { return {t.y, -t.x}; }

/// Unit direction of the line at each point over kDirectionReach either
/// side (tangents() where the line is shorter than that).
std::vector<glm::dvec2> directions(const std::vector<StrokePoint>& c, bool closed) {
    const std::size_t n = c.size();
    std::vector<glm::dvec2> t = tangents(c, closed);
    if (n < 3) return t;
    std::vector<double> cum(n + 1, 0.0);
    for (std::size_t k = 1; k <= n; ++k) cum[k] = cum[k - 1] + (k < n || closed ? glm::length(c[k % n].q - c[k - 1].q) : 0.0);
    const double total = closed ? cum[n] : cum[n - 1];
    if (total < 4.0 * kDirectionReach) return t;
    // The point at arc length a (wrapped on a closed line, clamped on an open one).
    auto at = [&](double a) {
        a = closed ? wrap(a, total) : std::clamp(a, 0.0, total);
        std::size_t k = upper_index(cum, a, closed ? n + 1 : n);
        k = std::clamp<std::size_t>(k, 1, closed ? n : n - 1);
        const std::size_t i = k - 1, j = k % n;
        const double seg = cum[k] - cum[i];
        const double f = seg > 0.0 ? std::clamp((a - cum[i]) / seg, 0.0, 1.0) : 0.0;
        return (1.0 - f) * c[i].q + f * c[j].q;
    };
    for (std::size_t k = 0; k < n; ++k) {
        const glm::dvec2 d = at(cum[k] + kDirectionReach) - at(cum[k] - kDirectionReach);
        const double l = glm::length(d);
        if (l > 1e-6) t[k] = d / l;
    }
    return t;
}

} // namespace

void wobble(const StrokeStyle& style, std::vector<StrokePoint>& centre, bool closed, double period, double seconds) {
    if (style.wobble_amplitude <= 0.0 || centre.empty()) return;
    const double lambda = std::max(style.wobble_wavelength, 1.0);
    // Boil: the noise drawn afresh `boil` times a second, far along its line.
    const double shift = style.boil_rate > 0.0 ? 7919.0 * std::floor(seconds * style.boil_rate + 1e-9) : 0.0;
    auto value = [&](double u) {
        if (!(period > 0.0)) return noise1(u / lambda + shift);
        // Round a closed loop the noise wraps: near the seam it fades into
        // the noise one period back, so it meets itself.
        const double w = wrap(u, period), blend = std::min(lambda, 0.5 * period);
        const double t = std::clamp((w - (period - blend)) / blend, 0.0, 1.0);
        const double s = t * t * (3.0 - 2.0 * t);
        return (1.0 - s) * noise1(w / lambda + shift) + s * noise1((w - period) / lambda + shift);
    };
    const std::vector<glm::dvec2> t = directions(centre, closed);
    for (std::size_t k = 0; k < centre.size(); ++k) centre[k].q += style.wobble_amplitude * value(centre[k].u) * left_of(t[k]);
}

void stroke_outline(const StrokeStyle& style, const std::vector<StrokePoint>& centre, bool closed,
                    std::vector<std::vector<glm::dvec2>>& out) {
    const std::size_t n = centre.size();
    if (n == 0) return;
    const std::vector<glm::dvec2> t = directions(centre, closed);
    std::vector<double> cum(n, 0.0);
    for (std::size_t k = 1; k < n; ++k) cum[k] = cum[k - 1] + glm::length(centre[k].q - centre[k - 1].q);
    const double length = cum.back();
    double ts = style.taper_start_fraction ? style.taper_start * length : style.taper_start;
    double te = style.taper_end_fraction ? style.taper_end * length : style.taper_end;
    if (ts + te > length && ts + te > 0.0) { // tapers longer than the line meet
        const double f = length / (ts + te);
        ts *= f, te *= f;
    }
    const bool tapered = style.taper_start > 0.0 || style.taper_end > 0.0;
    auto ease = [&](double d, double over) {
        if (over <= 0.0) return tapered && d <= 0.0 && length <= 0.0 ? 0.0 : 1.0;
        const double x = std::clamp(d / over, 0.0, 1.0);
        return x * (2.0 - x);
    };
    const double lo = style.min_width(), hi = style.max_width();
    const double nib = style.calligraphy_angle * kPi / 180.0, nib_cos = std::cos(nib), nib_sin = std::sin(nib);
    std::vector<double> half(n);
    for (std::size_t k = 0; k < n; ++k) {
        double w = style.width_by == StrokeStyle::WidthBy::None ? style.width : lo + (hi - lo) * std::clamp(centre[k].weight, 0.0, 1.0);
        if (style.calligraphy_ratio < 1.0) {
            // |sin(theta - nib)| with theta the direction as seen (y up):
            // cos theta = t.x, sin theta = -t.y.
            const double across = std::abs(-t[k].y * nib_cos - t[k].x * nib_sin);
            w *= style.calligraphy_ratio + (1.0 - style.calligraphy_ratio) * across;
        }
        if (!closed) {
            w *= ease(cum[k], ts) * ease(length - cum[k], te);
            // No wider than half the run's length: a run that appears grows
            // from a point of no width instead of a dot.
            w = std::min(w, 0.5 * length);
        }
        half[k] = 0.5 * w;
    }
    auto side = [&](std::size_t k, double sign) { return centre[k].q + sign * half[k] * left_of(t[k]); };
    if (closed) {
        std::vector<glm::dvec2> outer(n), inner(n);
        for (std::size_t k = 0; k < n; ++k) outer[k] = side(k, 1.0), inner[n - 1 - k] = side(k, -1.0);
        out.push_back(std::move(outer));
        out.push_back(std::move(inner));
        return;
    }
    std::vector<glm::dvec2> poly;
    poly.reserve(2 * n + 2 * kRoundCapPoints);
    auto cap = [&](std::size_t k, double dir) { // from the left side round to the right (dir: +1 end, -1 start)
        const glm::dvec2 a = dir * t[k], l = dir * left_of(t[k]);
        if (style.cap == "round") {
            for (int i = 1; i <= kRoundCapPoints; ++i) {
                const double phi = 0.5 * kPi - kPi * double(i) / double(kRoundCapPoints + 1);
                poly.push_back(centre[k].q + half[k] * (std::cos(phi) * a + std::sin(phi) * l));
            }
        } else if (style.cap == "square") {
            poly.push_back(centre[k].q + half[k] * (a + l));
            poly.push_back(centre[k].q + half[k] * (a - l));
        }
    };
    for (std::size_t k = 0; k < n; ++k) poly.push_back(side(k, 1.0));
    cap(n - 1, 1.0);
    for (std::size_t k = n; k-- > 0;) poly.push_back(side(k, -1.0));
    cap(0, -1.0);
    out.push_back(std::move(poly));
}

StrokeShape stroke_shape(const StrokeStyle& style, std::vector<StrokePoint> centre, bool closed, double period,
                         double seconds) {
    StrokeShape shape;
    wobble(style, centre, closed, closed ? period : 0.0, seconds);
    if (style.variable_width()) stroke_outline(style, centre, closed, shape.outlines);
    shape.centre = std::move(centre);
    return shape;
}

} // namespace snaxels
