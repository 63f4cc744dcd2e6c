#include "snaxels/export/stroke_weight.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "snaxels/export/detail/polyline.h"
#include "snaxels/snaxel/suggestive.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr double kTwoPi = 2.0 * kPi;
/// Points a round cap adds between the two sides of a line's end.
constexpr int kRoundCapPoints = 5;

double wrap(double x, double period) {
    const double r = std::fmod(x, period);
    return r < 0.0 ? r + period : r;
}

double median(std::vector<double> v) {
    const std::size_t m = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(m), v.end());
    return v[m];
}

// The index of the first of @p v's values (nondecreasing) above @p x.
std::size_t upper_index(const std::vector<double>& v, double x, std::size_t end) {
    return std::size_t(std::upper_bound(v.begin(), v.begin() + std::ptrdiff_t(end), x) - v.begin());
}

// Arc length at each point of a polyline from its first (closed: the
// closing segment not included).
std::vector<double> cumulative(const std::vector<glm::dvec2>& q) {
    std::vector<double> cum(q.size(), 0.0);
    for (std::size_t k = 1; k < q.size(); ++k) cum[k] = cum[k - 1] + glm::length(q[k] - q[k - 1]);
    return cum;
}

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

/// How far along a line (pixels) either side of a point its direction is
/// taken: the chord from kDirectionReach before to as far after, so that
/// the zigzags of a contour at mesh resolution and points that nearly
/// coincide do not turn an outline's sides over (which would open holes
/// under the nonzero rule) or swing a nib's width.
constexpr double kDirectionReach = 2.0;

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

/// The most a point's stroke parameter moves in a frame (pixels) as it is
/// relaxed toward uniform arc length.
constexpr double kMaxRelaxPx = 0.5;

/// Half the window (pixels of line) over which a carried parameter's
/// departures from uniform are averaged (StrokeParameter::step).
constexpr double kUniformReach = 50.0;

/// Where a carried parameter's departures from uniform jump by more than
/// this between neighbouring snaxels (pixels), an event joined stretches
/// of the line whose parameters do not meet: each keeps its own, and the
/// averaging of departures does not cross the join.
constexpr double kJoinPx = 8.0;

/// The mean of @p v over the points within @p reach of arc length of each
/// (@p s: arc length of each point from the first; round a ring of @p length
/// when @p ring), not across a jump of more than kJoinPx between neighbours.
std::vector<double> arc_mean(const std::vector<double>& v, const std::vector<double>& s, double length, bool ring,
                             double reach) {
    const std::size_t n = v.size();
    std::vector<double> out(n, 0.0);
    if (n == 0) return out;
    auto joined = [&](std::size_t a, std::size_t b) { return std::abs(v[a] - v[b]) <= kJoinPx; };
    // Points laid out thrice round a ring (arc - length, arc, arc + length),
    // so that windows need not wrap; prefix sums of the values, so that a
    // window is one subtraction.
    const std::size_t m = ring ? 3 * n : n;
    std::vector<double> arc(m), prefix(m + 1, 0.0);
    // The stretch between joins each point is in: [first[i], last[i]].
    std::vector<std::size_t> first(m), last(m);
    for (std::size_t i = 0; i < m; ++i) {
        const std::size_t k = i % n;
        arc[i] = s[k] + (ring ? (double(i / n) - 1.0) * length : 0.0);
        prefix[i + 1] = prefix[i] + v[k];
        first[i] = i > 0 && joined((i - 1) % n, k) ? first[i - 1] : i;
    }
    for (std::size_t i = m; i-- > 0;) last[i] = i + 1 < m && joined(i % n, (i + 1) % n) ? last[i + 1] : i;
    std::size_t lo = 0, hi = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const std::size_t i = ring ? k + n : k;
        while (lo < i && arc[lo] < arc[i] - reach) ++lo;
        while (hi < m && arc[hi] <= arc[i] + reach) ++hi;
        const std::size_t a = std::max(lo, first[i]), b = std::min(hi, last[i] + 1);
        out[k] = (prefix[b] - prefix[a]) / double(b - a);
    }
    return out;
}

/// Departures @p e known at the snaxels @p has marks, spread to those
/// between by arc length @p s (round a ring of @p length); between kept
/// snaxels whose departures do not meet (an event put new line between
/// them) the new line goes on uniformly from the one before and the
/// parameter jumps at the one after, rather than squeezing it between them.
void spread(std::vector<double>& e, const std::vector<char>& has, const std::vector<double>& s, double length, bool ring) {
    const std::size_t n = e.size();
    std::vector<std::size_t> at; // the kept snaxels in loop order
    for (std::size_t k = 0; k < n; ++k)
        if (has[k]) at.push_back(k);
    for (std::size_t i = 0; i < at.size(); ++i) {
        const bool last = i + 1 == at.size();
        if (last && !ring) break;
        const std::size_t p = at[i], q = last ? at[0] : at[i + 1];
        const double sp = s[p], sq = last ? s[q] + length : s[q];
        // Between kept snaxels whose departures do not meet (an
        // event put new line between them), the new line goes on
        // uniformly from the one before and the parameter jumps at
        // the one after, rather than squeezing it between them.
        const bool join = std::abs(e[q] - e[p]) > kJoinPx;
        for (std::size_t k = (p + 1) % n; k != q; k = (k + 1) % n) {
            const double sk = k > p ? s[k] : s[k] + length;
            const double f = join ? 0.0 : sq > sp ? std::clamp((sk - sp) / (sq - sp), 0.0, 1.0) : 0.0;
            e[k] = (1.0 - f) * e[p] + f * e[q];
        }
    }
    if (!ring) { // before the first kept snaxel and after the last: theirs
        for (std::size_t k = 0; k < at.front(); ++k) e[k] = e[at.front()];
        for (std::size_t k = at.back() + 1; k < n; ++k) e[k] = e[at.back()];
    }
}

/// The arc length from snaxel @p k of @p loop to where @p landed (a surface
/// point it stood on last frame, seen now) falls on the segments beside
/// it; 0 where it falls farther than 2 px from them.
double landed_offset(const DrawnLoop& loop, std::size_t k, const glm::dvec2& landed) {
    const std::size_t n = loop.q.size(), reach = 2;
    if (n < 2) return 0.0;
    double best = 1e300, along = 0.0;
    for (std::size_t d = 0; d < 2 * reach; ++d) {
        if (!loop.closed && (k + d < reach || k + d - reach + 1 >= n)) continue;
        const std::size_t i = (k + n + d - reach) % n, j = (i + 1) % n;
        const glm::dvec2 a = loop.q[i], b = loop.q[j], ab = b - a;
        const double l2 = glm::dot(ab, ab);
        const double f = l2 > 0.0 ? std::clamp(glm::dot(landed - a, ab) / l2, 0.0, 1.0) : 0.0;
        const double dist = glm::length(landed - (a + f * ab));
        // Signed: a segment before snaxel k gives a negative offset.
        if (dist < best) best = dist, along = (d < reach ? -1.0 : 1.0) * glm::length(a + f * ab - loop.q[k]);
    }
    return best <= 2.0 ? along : 0.0;
}

} // namespace

namespace {

/// Of the snaxels @p kept from last frame (each from the loop
/// @p kept_from says), those of the loop most of them come from are kept
/// (where loops merged, that side keeps its u; the other side's are taken
/// as new); returns that loop (of equal counts, the first).
std::uint32_t keep_main_source(std::vector<std::pair<std::size_t, double>>& kept, const std::vector<std::uint32_t>& kept_from) {
    std::unordered_map<std::uint32_t, std::size_t> from;
    for (const std::uint32_t loop : kept_from) ++from[loop];
    std::uint32_t source = 0;
    std::size_t most = 0;
    for (const auto& [p, count] : from)
        if (count > most || (count == most && p < source)) most = count, source = p;
    std::vector<std::pair<std::size_t, double>> own;
    own.reserve(kept.size());
    for (std::size_t i = 0; i < kept.size(); ++i)
        if (kept_from[i] == source) own.push_back(kept[i]);
    kept = std::move(own);
    return source;
}

/// The most common value of @p d on the circle of @p period (where an event
/// joined stretches whose u do not meet, the mean would fall between
/// them): the fullest 16-px bin, refined by the mean round it. Between
/// -period/2 and period/2 (@p nearest takes a difference the short way
/// round), so that u = c + b s + e stays within the old period where the
/// old u did, and the new period wraps it only past its end.
template <class Nearest> double circular_mode(const std::vector<double>& d, double period, Nearest&& nearest) {
    const long bins = std::max(1L, std::lround(std::floor(period / 16.0)));
    std::map<long, std::size_t> count;
    for (const double x : d) ++count[std::min(bins - 1, std::lround(std::floor(wrap(x, period) / period * double(bins))))];
    long best = 0;
    std::size_t fullest = 0;
    const auto in_bin = [&](long bin) {
        const auto it = count.find((bin + bins) % bins);
        return it == count.end() ? 0 : it->second;
    };
    for (const auto& entry : count) {
        const std::size_t around = in_bin(entry.first - 1) + entry.second + in_bin(entry.first + 1);
        if (around > fullest) fullest = around, best = entry.first;
    }
    const double centre = (double(best) + 0.5) / double(bins) * period;
    double sum = 0.0;
    std::size_t near = 0;
    for (const double x : d) {
        const double off = nearest(x - centre);
        if (std::abs(off) <= 32.0) sum += off, ++near;
    }
    return nearest(centre + (near ? sum / double(near) : 0.0));
}

} // namespace

void parameterize_still(DrawnContour& contour) {
    for (DrawnLoop& loop : contour.loops) {
        if (!loop.u.empty() || loop.q.empty()) continue;
        loop.u = cumulative(loop.q);
        loop.u_period = loop.closed ? loop.u.back() + glm::length(loop.q.front() - loop.q.back()) : 0.0;
    }
}

void StrokeParameter::step(DrawnContour& contour, const std::vector<AnimatedLoop>& loops,
                           const std::vector<std::vector<SurfacePoint>>* surface,
                           const std::function<glm::dvec2(const SurfacePoint&)>& project) {
    std::unordered_map<std::uint64_t, Carried> next;
    next.reserve(previous_.size() + previous_.size() / 4);
    std::vector<double> periods(contour.loops.size(), 0.0), stretches(contour.loops.size(), 1.0);
    for (std::size_t l = 0; l < contour.loops.size(); ++l) {
        DrawnLoop& loop = contour.loops[l];
        const std::vector<std::uint64_t>& ids = loops[l].ids;
        const std::vector<double> s = cumulative(loop.q);
        const std::size_t n = loop.q.size();
        const double length = n ? s.back() + (loop.closed ? glm::length(loop.q.front() - loop.q.back()) : 0.0) : 0.0;
        // The snaxels that go on, and the previous loop most of them come from.
        std::vector<std::pair<std::size_t, double>> kept; // (snaxel, its u last frame)
        std::vector<std::uint32_t> kept_from;              // the loop it was on
        for (std::size_t k = 0; k < n && k < ids.size(); ++k) {
            const auto it = previous_.find(ids[k]);
            if (it == previous_.end()) continue;
            double u = it->second.u;
            if (surface && project) u -= landed_offset(loop, k, project(it->second.where));
            kept.push_back({k, u});
            kept_from.push_back(it->second.loop);
        }
        const std::uint32_t source = keep_main_source(kept, kept_from);
        const bool ring = loop.closed && !kept.empty() && previous_period_[source] > 0.0;
        loop.u = s; // a new line: arc length from its first snaxel
        loop.u_period = loop.closed ? length : 0.0;
        if (kept.size() >= 2 && length > 0.0) {
            // The uniform parameter the kept snaxels follow, c + b s. On an
            // open line b is the ratio of u to arc length summed between
            // neighbours (not across an event's join), relaxed toward 1; on
            // a ring b is its period (relaxed toward its length) over its
            // length. c is what is left: the median on an open line, the
            // most common value on the circle round a ring (their u
            // differences taken the short way round the old period).
            const double old_period = ring ? previous_period_[source] : 0.0;
            auto nearest = [&](double du) { return old_period > 0.0 ? du - old_period * std::round(du / old_period) : du; };
            double sum_du = 0.0, sum_ds = 0.0;
            for (std::size_t i = 1; i < kept.size(); ++i) {
                const double ds = s[kept[i].first] - s[kept[i - 1].first];
                const double du = nearest(kept[i].second - kept[i - 1].second);
                if (std::abs(du - ds) <= 4.0 + 0.5 * ds) sum_du += du, sum_ds += ds;
            }
            const double fit = sum_ds > 1.0 ? sum_du / sum_ds : previous_stretch_[source];
            // Relaxed toward uniform arc length by kRelaxToUniform of the
            // way, but so that no point's parameter moves more than
            // kMaxRelaxPx a frame: a ring's period (after an event, far
            // from its length) changes by at most that, an open line's
            // stretch moves its far end by at most that.
            double b = 0.0, period = 0.0;
            if (ring) {
                period = old_period + std::clamp(kRelaxToUniform * (length - old_period), -kMaxRelaxPx, kMaxRelaxPx);
                b = period / length;
            } else {
                const double span = std::max(s.back(), 1.0);
                b = std::clamp(fit + std::clamp(kRelaxToUniform * (1.0 - fit), -kMaxRelaxPx / span, kMaxRelaxPx / span), 0.5, 2.0);
            }
            std::vector<double> d(kept.size());
            for (std::size_t i = 0; i < kept.size(); ++i) d[i] = kept[i].second - b * s[kept[i].first];
            double c = 0.0;
            if (ring) c = circular_mode(d, old_period, nearest);
            else c = median(d);
            // Each kept snaxel's departure from that uniform parameter (on a
            // ring the nearest way round its old period), spread to the
            // snaxels between them by arc length.
            std::vector<double> e(n, 0.0);
            std::vector<char> has(n, 0);
            for (std::size_t i = 0; i < kept.size(); ++i) e[kept[i].first] = nearest(d[i] - c), has[kept[i].first] = 1;
            spread(e, has, s, length, ring);
            // The departures are kept but for their ripple: each frame they
            // move kRelaxToUniform of the way to their mean over
            // kUniformReach px of the line either side, so the parameter's
            // spacing evens out where the line stretched unevenly.
            const std::vector<double> mean = arc_mean(e, s, length, ring, kUniformReach);
            for (std::size_t k = 0; k < n; ++k)
                loop.u[k] = c + b * s[k] + e[k] + std::clamp(kRelaxToUniform * (mean[k] - e[k]), -kMaxRelaxPx, kMaxRelaxPx);
            if (ring) { // round the old period, then stretched to the new one
                for (double& u : loop.u) u = wrap(u, old_period) * (period / old_period);
                loop.u_period = period;
            } else if (loop.closed) { // a line that closed: its seam at its first snaxel
                const double u0 = loop.u[0];
                for (double& u : loop.u) u = wrap(u - u0, b * length);
                loop.u_period = b * length;
            }
            stretches[l] = b;
        }
        periods[l] = loop.u_period;
        for (std::size_t k = 0; k < n && k < ids.size(); ++k)
            next[ids[k]] = {loop.u[k], std::uint32_t(l), surface && l < surface->size() && k < (*surface)[l].size() ? (*surface)[l][k] : SurfacePoint{}};
    }
    previous_ = std::move(next);
    previous_period_ = std::move(periods);
    previous_stretch_ = std::move(stretches);
}

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

std::vector<Dash> dash_spans(const std::vector<double>& arcs, const std::vector<double>& m,
                             const std::vector<double>& pattern, double period) {
    std::vector<Dash> out;
    double cycle = 0.0;
    for (const double d : pattern) cycle += d;
    if (!(cycle > 0.0) || arcs.size() < 2) return out;
    const std::int64_t count = std::int64_t(pattern.size() + 1) / 2;
    // The dash at measure x: its id (-1 in a gap) and its length.
    double length = 0.0;
    auto dash_at = [&](double x) -> std::int64_t {
        const double k = std::floor(x / cycle);
        double at = x - k * cycle;
        for (std::size_t i = 0; i < pattern.size(); i += 2) {
            if (at < pattern[i]) {
                length = pattern[i];
                return std::int64_t(k) * count + std::int64_t(i / 2);
            }
            at -= pattern[i] + (i + 1 < pattern.size() ? pattern[i + 1] : 0.0);
        }
        return -1;
    };
    // The pattern's boundaries strictly between two measures.
    auto boundaries = [&](double lo, double hi, std::vector<double>& into) {
        for (double base = std::floor(lo / cycle) * cycle; base <= hi; base += cycle) {
            double at = base;
            for (std::size_t i = 0; i < pattern.size(); ++i) {
                if (at > lo && at < hi) into.push_back(at);
                at += pattern[i];
            }
        }
    };
    std::map<std::int64_t, int> seen;
    std::int64_t open = -1;
    double open_from = 0.0, open_length = 0.0;
    auto close = [&](double to) {
        if (open < 0) return;
        const int again = seen[open]++;
        out.push_back({open + (std::int64_t(again) << 40), open_from, to, open_length});
        open = -1;
    };
    std::vector<double> cuts;
    for (std::size_t i = 0; i + 1 < arcs.size(); ++i) {
        const double a0 = arcs[i], a1 = arcs[i + 1];
        double m0 = m[i], m1 = m[i + 1];
        if (period > 0.0 && std::abs(m1 - m0) > 0.5 * period) m1 -= period * std::round((m1 - m0) / period); // the seam
        cuts.clear();
        boundaries(std::min(m0, m1), std::max(m0, m1), cuts);
        cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end()); // a dash of no length starts where its gap does
        if (m1 < m0) std::reverse(cuts.begin(), cuts.end());
        double from_arc = a0, from_m = m0;
        auto piece = [&](double to_arc, double to_m) {
            const std::int64_t id = dash_at(0.5 * (from_m + to_m));
            if (id != open) {
                close(from_arc);
                if (id >= 0) open = id, open_from = from_arc, open_length = length;
            }
            from_arc = to_arc, from_m = to_m;
        };
        for (const double c : cuts) {
            const double f = m1 != m0 ? (c - m0) / (m1 - m0) : 0.0;
            piece(a0 + f * (a1 - a0), c);
            // A dash of no length (a dotted line: its caps draw the dot).
            const double k = std::floor(c / cycle);
            double at = k * cycle;
            for (std::size_t e = 0; e < pattern.size(); e += 2) {
                if (pattern[e] == 0.0 && std::abs(at - c) < 1e-9) {
                    const std::int64_t id = std::int64_t(k) * count + std::int64_t(e / 2);
                    const int again = seen[id]++;
                    out.push_back({id + (std::int64_t(again) << 40), from_arc, from_arc, 0.0});
                }
                at += pattern[e] + (e + 1 < pattern.size() ? pattern[e + 1] : 0.0);
            }
        }
        piece(a1, m1);
    }
    close(arcs.back());
    return out;
}

std::vector<std::vector<glm::dvec2>> dash_pieces(const std::vector<glm::dvec2>& q, const std::vector<double>& arcs,
                                                 const std::vector<Dash>& spans) {
    std::vector<std::vector<glm::dvec2>> out;
    auto at = [&](double x) {
        std::size_t k = upper_index(arcs, x, arcs.size());
        if (k == 0) return q.front();
        if (k >= q.size()) return q.back();
        const double span = arcs[k] - arcs[k - 1];
        const double f = span > 0.0 ? (x - arcs[k - 1]) / span : 0.0;
        return (1.0 - f) * q[k - 1] + f * q[k];
    };
    for (const Dash& d : spans) {
        std::vector<glm::dvec2> piece{at(d.from)};
        for (std::size_t k = 0; k < q.size(); ++k)
            if (arcs[k] > d.from && arcs[k] < d.to) piece.push_back(q[k]);
        piece.push_back(at(d.to));
        out.push_back(std::move(piece));
    }
    return out;
}

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

} // namespace snaxels
