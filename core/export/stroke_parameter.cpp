// The stroke parameter: a still's, and one carried from frame to frame.
#include "snaxels/export/stroke_parameter.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "snaxels/export/detail/stroke_measure.h"

namespace snaxels {
namespace {

using namespace detail;

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

double median(std::vector<double> v) {
    const std::size_t m = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(m), v.end());
    return v[m];
}

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

} // namespace snaxels
