#include "snaxels/export/detail/animated_fills.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>

#include "snaxels/export/detail/animated_paths.h"
#include "snaxels/export/detail/path_keys.h"
#include "snaxels/export/detail/polyline.h"

namespace snaxels {
namespace {

constexpr double kMinLoopArea = 4.0;    // square pixels: smaller fill loops are left out
constexpr double kMaxFillSweepPx = 2.0; // how far a fill outline may stray between two frames
constexpr std::size_t kMaxSegmentFrames = 48;

using Loop = std::vector<glm::dvec2>;

double twice_area(const Loop& loop) {
    double a = 0.0;
    for (std::size_t q = 0; q < loop.size(); ++q)
        a += loop[q].x * loop[(q + 1) % loop.size()].y - loop[(q + 1) % loop.size()].x * loop[q].y;
    return a;
}

double loop_length(const Loop& loop) {
    double l = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) l += glm::length(loop[(i + 1) % loop.size()] - loop[i]);
    return l;
}

glm::dvec2 loop_centroid(const Loop& loop) {
    glm::dvec2 c(0.0);
    for (const glm::dvec2& p : loop) c += p;
    return loop.empty() ? c : c / double(loop.size());
}

/// Arc-length resampling of a closed loop into @p n points starting at arc @p start.
Loop resample_loop(const Loop& loop, std::size_t n, double start) {
    std::vector<double> cum(loop.size() + 1, 0.0);
    for (std::size_t i = 0; i < loop.size(); ++i) cum[i + 1] = cum[i] + glm::length(loop[(i + 1) % loop.size()] - loop[i]);
    const double length = cum.back();
    Loop out;
    out.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        const double arc = length > 0.0 ? std::fmod(start + length * double(k) / double(n), length) : 0.0;
        std::size_t i = std::size_t(std::upper_bound(cum.begin(), cum.end(), arc) - cum.begin());
        i = std::clamp<std::size_t>(i, 1, loop.size()) - 1;
        const double seg = cum[i + 1] - cum[i];
        const double t = seg > 0.0 ? (arc - cum[i]) / seg : 0.0;
        out.push_back((1.0 - t) * loop[i] + t * loop[(i + 1) % loop.size()]);
    }
    return out;
}

/// Arc length along @p loop to its vertex nearest @p p.
double arc_nearest(const Loop& loop, const glm::dvec2& p) {
    double best = 1e300, arc = 0.0, at = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const double d = glm::length(loop[i] - p);
        if (d < best) best = d, at = arc;
        arc += glm::length(loop[(i + 1) % loop.size()] - loop[i]);
    }
    return at;
}

/// Where a loop starts when nothing before says: its top-left-most vertex.
double first_start(const Loop& loop) {
    std::size_t top = 0;
    for (std::size_t k = 1; k < loop.size(); ++k)
        if (loop[k].x + loop[k].y < loop[top].x + loop[top].y) top = k;
    return arc_nearest(loop, loop[top]);
}

std::size_t samples_for(double length) { return std::clamp<std::size_t>(std::size_t(std::ceil(length / 2.0)), 8, 4096); }

// Linear interpolation between two resampled outlines must stay between
// them: the largest distance of the half-way outline from both.
double stray(const Loop& a, const Loop& b) {
    const std::size_t n = a.size();
    double worst = 0.0;
    for (std::size_t v = 0; v < n && worst <= kMaxFillSweepPx; ++v) {
        const glm::dvec2 mid = 0.5 * (a[v] + b[v]);
        double best = 1e300;
        for (std::size_t w = v + n - 6; w < v + n + 6 && best > kMaxFillSweepPx; ++w) {
            const std::size_t w0 = w % n, w1 = (w + 1) % n;
            best = std::min({best, point_segment(mid, a[w0], a[w1]), point_segment(mid, b[w0], b[w1])});
        }
        worst = std::max(worst, best);
    }
    return worst;
}

bool boxes_meet(const Loop& a, const Loop& b) {
    glm::dvec2 alo(1e300), ahi(-1e300), blo(1e300), bhi(-1e300);
    for (const glm::dvec2& p : a) alo = glm::min(alo, p), ahi = glm::max(ahi, p);
    for (const glm::dvec2& p : b) blo = glm::min(blo, p), bhi = glm::max(bhi, p);
    return alo.x <= bhi.x && blo.x <= ahi.x && alo.y <= bhi.y && blo.y <= ahi.y;
}

/// Winding number of the loops about @p p (non-zero: inside the region).
int winding(const glm::dvec2& p, const std::vector<Loop>& loops) {
    int w = 0;
    for (const Loop& loop : loops)
        for (std::size_t k = 0; k < loop.size(); ++k) {
            const glm::dvec2 a = loop[k], b = loop[(k + 1) % loop.size()];
            const double cross = (b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y);
            if (a.y <= p.y && b.y > p.y && cross > 0.0) ++w;
            else if (a.y > p.y && b.y <= p.y && cross < 0.0) --w;
        }
    return w;
}

/// Whether @p loop, present in one frame only, stands where the other
/// frame's region (@p other) is as it would be without it: an outline over
/// what the other frame leaves uncovered, a hole in what it covers (nine in
/// ten of its vertices).
bool changes_cover(const Loop& loop, const std::vector<Loop>& other) {
    const bool hole = twice_area(loop) < 0.0;
    std::size_t agree = 0;
    for (const glm::dvec2& p : loop) agree += (winding(p, other) != 0) == hole;
    return 10 * agree >= 9 * loop.size();
}

struct FillFrame {
    int frame = 0;
    std::vector<Loop> loops;
    std::vector<int> ids; ///< per loop: the loop it is from frame to frame
    bool jump = false;    ///< not interpolated from the frame before
};

struct FillPlan {
    std::vector<int> ids;         ///< loops (-1: a lone move, for frames without loops)
    std::vector<std::size_t> at;  ///< life frames of the keys
    std::vector<double> times;    ///< key times (frames)
    bool transition = false;      ///< two keys, from life frame at[0] to the next
};

class FillWriter {
  public:
    explicit FillWriter(const std::vector<FillFrame>& life) : life_(life) {}

    std::vector<FillPlan> plan() const {
        std::vector<FillPlan> plans;
        auto ids_of = [&](std::size_t i) {
            std::vector<int> ids = life_[i].ids;
            std::sort(ids.begin(), ids.end());
            if (ids.empty()) ids.push_back(-1);
            return ids;
        };
        auto time_of = [&](std::size_t i) { return double(life_[i].frame); };
        FillPlan cur{ids_of(0), {0}, {time_of(0)}, false};
        std::size_t cur_first = 0;
        for (std::size_t i = 0; i + 1 < life_.size(); ++i) {
            const std::vector<int> next = ids_of(i + 1);
            if (life_[i + 1].jump) {
                cur.at.push_back(i), cur.times.push_back(time_of(i) + 0.5);
                plans.push_back(std::move(cur));
                cur = FillPlan{next, {i + 1, i + 1}, {time_of(i) + 0.5 + anim::kSwitch, time_of(i + 1)}, false};
                cur_first = i + 1;
            } else if (next == cur.ids) {
                if (i + 1 - cur_first >= kMaxSegmentFrames) {
                    plans.push_back(std::move(cur));
                    cur = FillPlan{next, {i}, {time_of(i) + anim::kSwitch}, false};
                    cur_first = i;
                }
                cur.at.push_back(i + 1), cur.times.push_back(time_of(i + 1));
            } else {
                std::vector<int> both = cur.ids;
                plans.push_back(std::move(cur));
                both.insert(both.end(), next.begin(), next.end());
                std::sort(both.begin(), both.end());
                both.erase(std::unique(both.begin(), both.end()), both.end());
                if (both.size() > 1) both.erase(std::remove(both.begin(), both.end(), -1), both.end());
                plans.push_back({both, {i, i}, {time_of(i) + anim::kSwitch, time_of(i + 1) - anim::kSwitch}, true});
                cur = FillPlan{next, {i + 1}, {time_of(i + 1)}, false};
                cur_first = i + 1;
            }
        }
        plans.push_back(std::move(cur));
        return plans;
    }

    PathSegment emit(const FillPlan& plan, double tolerance) const {
        anim::Segment seg;
        seg.times = plan.times;
        seg.shapes.assign(plan.times.size(), anim::Shape(plan.ids.size()));
        for (std::size_t j = 0; j < plan.ids.size(); ++j) {
            const int id = plan.ids[j];
            if (id < 0) { // a frame without loops: a lone move draws nothing
                for (anim::Shape& s : seg.shapes) s[j] = {{lone_move_at(plan.at[0])}, false};
                continue;
            }
            // The loop at each key: its outline in that frame (or, in a
            // transition, a point where it appears or vanishes).
            std::vector<const Loop*> loops(plan.times.size(), nullptr);
            for (std::size_t k = 0; k < plan.times.size(); ++k) {
                const std::size_t i = plan.at[k] + (plan.transition && k == 1 ? 1 : 0);
                loops[k] = loop_of(i, id);
            }
            double longest = 0.0;
            for (const Loop* l : loops)
                if (l) longest = std::max(longest, loop_length(*l));
            const std::size_t n = samples_for(longest);
            const Loop* any = nullptr;
            for (const Loop* l : loops) any = any ? any : l;
            const glm::dvec2 centre = loop_centroid(*any);
            for (std::size_t k = 0; k < loops.size(); ++k) {
                anim::Subpath& sp = seg.shapes[k][j];
                sp.closed = true;
                if (!loops[k]) {
                    sp.pts.assign(n, centre);
                    continue;
                }
                const anim::Subpath* before = k > 0 && loops[k - 1] ? &seg.shapes[k - 1][j] : nullptr;
                sp.pts = resample_loop(*loops[k], n, before ? arc_nearest(*loops[k], before->pts[0]) : first_start(*loops[k]));
            }
        }
        anim::reduce_vertices(seg, tolerance, 0.0);
        const std::vector<std::uint8_t> keep = anim::reduce_keys(seg, tolerance);
        PathSegment out;
        for (std::size_t k = 0; k < seg.times.size(); ++k) {
            if (!keep[k]) continue;
            out.times.push_back(seg.times[k]);
            out.shapes.push_back(std::move(seg.shapes[k]));
        }
        return out;
    }

  private:
    const Loop* loop_of(std::size_t i, int id) const {
        for (std::size_t l = 0; l < life_[i].ids.size(); ++l)
            if (life_[i].ids[l] == id) return &life_[i].loops[l];
        return nullptr;
    }
    glm::dvec2 lone_move_at(std::size_t i) const {
        for (std::size_t k = i + 1; k-- > 0;)
            if (!life_[k].loops.empty()) return life_[k].loops[0][0];
        for (std::size_t k = i; k < life_.size(); ++k)
            if (!life_[k].loops.empty()) return life_[k].loops[0][0];
        return glm::dvec2(0.0);
    }

    const std::vector<FillFrame>& life_;
};

} // namespace

std::vector<std::pair<std::size_t, std::size_t>> match_loops(const std::vector<std::vector<glm::dvec2>>& a,
                                                             const std::vector<std::vector<glm::dvec2>>& b,
                                                             double slack_px) {
    struct Candidate {
        double d;
        std::size_t i, j;
    };
    std::vector<Candidate> candidates;
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j) {
            if ((twice_area(a[i]) > 0.0) != (twice_area(b[j]) > 0.0)) continue;
            const double d = glm::length(loop_centroid(a[i]) - loop_centroid(b[j]));
            const double radius = (loop_length(a[i]) + loop_length(b[j])) / (4.0 * 3.141592653589793);
            if (d <= radius + slack_px) candidates.push_back({d, i, j});
        }
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) { return x.d < y.d; });
    std::vector<char> used_a(a.size(), 0), used_b(b.size(), 0);
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (const Candidate& c : candidates) {
        if (used_a[c.i] || used_b[c.j]) continue;
        used_a[c.i] = used_b[c.j] = 1;
        pairs.push_back({c.i, c.j});
    }
    return pairs;
}

namespace {

/// Links the loops of @p ff (a frame of one region's life) to those of
/// @p prev, the frame before: matched loops keep their ids, and ff.jump is
/// set where the path must jump instead of moving. @p class_loops(frame)
/// gives every loop of the region's class in that frame.
template <class ClassLoops> void link_loops(const FillFrame& prev, FillFrame& ff, ClassLoops&& class_loops) {
    const auto pairs = match_loops(prev.loops, ff.loops, 4.0);
    // A loop may appear (grow from a point) or vanish (shrink
    // to one) only where that changes what the region covers:
    // an outline over what the other frame leaves uncovered, a
    // hole in what it covers. Otherwise (loops that merge or
    // split, a hole pinched off an outline, a loop that moved
    // too far to match) growing and shrinking would uncover
    // what both frames cover: the path jumps there instead.
    std::vector<char> old_matched(prev.loops.size(), 0), new_matched(ff.loops.size(), 0);
    for (const auto& [i, j] : pairs) old_matched[i] = new_matched[j] = 1;
    // Nor where the other frame has the same class there in
    // another region's path (a region that split or changed
    // hands): growing from a point would uncover it.
    for (std::size_t i = 0; i < prev.loops.size() && !ff.jump; ++i)
        if (!old_matched[i])
            ff.jump = !changes_cover(prev.loops[i], ff.loops) || !changes_cover(prev.loops[i], class_loops(ff.frame));
    for (std::size_t j = 0; j < ff.loops.size() && !ff.jump; ++j)
        if (!new_matched[j])
            ff.jump = !changes_cover(ff.loops[j], prev.loops) || !changes_cover(ff.loops[j], class_loops(prev.frame));
    for (std::size_t i = 0; i < prev.loops.size() && !ff.jump; ++i)
        for (std::size_t j = 0; j < ff.loops.size() && !ff.jump; ++j)
            ff.jump = !old_matched[i] && !new_matched[j] && boxes_meet(prev.loops[i], ff.loops[j]);
    for (const auto& [i, j] : pairs) {
        ff.ids[j] = prev.ids[i];
        // A loop that would sweep outside both outlines between
        // the frames makes the path jump there instead.
        const double len = std::max(loop_length(prev.loops[i]), loop_length(ff.loops[j]));
        const std::size_t n = samples_for(len);
        const Loop a = resample_loop(prev.loops[i], n, first_start(prev.loops[i]));
        const Loop b = resample_loop(ff.loops[j], n, arc_nearest(ff.loops[j], a[0]));
        if (stray(a, b) > kMaxFillSweepPx) ff.jump = true;
    }
}

} // namespace

void fill_paths(const std::vector<AnimationFrame>& frames, const Style& style, const AnimatedSvgOptions& options,
                std::vector<AnimatedPathData>& out) {
    if (style.regions.empty()) return;
    std::vector<std::uint64_t> order;
    std::unordered_map<std::uint64_t, std::vector<std::pair<int, const MapRegion*>>> tracks;
    for (std::size_t f = 0; f < frames.size(); ++f)
        for (std::size_t r = 0; r < frames[f].regions.size() && r < frames[f].region_tracks.size(); ++r) {
            auto& track = tracks[frames[f].region_tracks[r]];
            if (track.empty()) order.push_back(frames[f].region_tracks[r]);
            track.push_back({int(f), &frames[f].regions[r]});
        }
    if (order.empty()) return;
    // Every region's outlines of one class in one frame (all tracks).
    std::map<std::tuple<int, int, double>, std::vector<Loop>> by_class;
    auto class_loops = [&](int frame, const MapRegion& like) -> const std::vector<Loop>& {
        const auto key = std::make_tuple(frame, int(like.cls), like.k);
        const auto it = by_class.find(key);
        if (it != by_class.end()) return it->second;
        std::vector<Loop>& loops = by_class[key];
        for (const MapRegion& r : frames[frame].regions)
            if (r.cls == like.cls && std::abs(r.k - like.k) < 1e-9) loops.insert(loops.end(), r.polygons.begin(), r.polygons.end());
        return loops;
    };
    for (const std::uint64_t id : order) {
        const auto& track = tracks[id];
        const MapRegion& r0 = *track.front().second;
        const FaceParts* parts = frames[track.front().first].drawing.parts.get();
        const RegionStyle* rs = style.region(r0, parts);
        if (!rs) continue;
        // The track's lives: runs of consecutive frames.
        for (std::size_t start = 0; start < track.size();) {
            std::size_t end = start + 1;
            while (end < track.size() && track[end].first == track[end - 1].first + 1) ++end;
            std::vector<FillFrame> life;
            int next_loop = 0;
            bool any = false;
            for (std::size_t m = start; m < end; ++m) {
                FillFrame ff;
                ff.frame = track[m].first;
                // Loops under a few square pixels (specks, pinholes) are left out.
                for (auto& loop : erode(track[m].second->polygons, rs->erosion))
                    if (loop.size() >= 3 && std::abs(twice_area(loop)) >= 2.0 * kMinLoopArea) ff.loops.push_back(std::move(loop));
                any |= !ff.loops.empty();
                ff.ids.assign(ff.loops.size(), -1);
                if (!life.empty())
                    link_loops(life.back(), ff, [&](int frame) -> const std::vector<Loop>& { return class_loops(frame, r0); });
                if (ff.jump)
                    for (int& l : ff.ids) l = -1;
                for (int& l : ff.ids)
                    if (l < 0) l = next_loop++;
                life.push_back(std::move(ff));
            }
            const int first = track[start].first, last = track[end - 1].first;
            start = end;
            if (!any) continue;
            const FillWriter writer(life);
            AnimatedPathData path;
            path.fill = true;
            path.region_class = region_class_name(r0.cls);
            path.region = rs;
            path.fill_colour = region_fill_colour(*rs, r0, parts);
            path.first = first;
            path.last = last;
            path.track = id;
            for (const FillPlan& plan : writer.plan()) path.segments.push_back(writer.emit(plan, options.tolerance_px));
            out.push_back(std::move(path));
        }
    }
}

} // namespace snaxels
