#include "snaxels/export/detail/animated_strokes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <unordered_map>

#include "snaxels/export/detail/animated_paths.h"
#include "snaxels/export/detail/path_keys.h"
#include "snaxels/export/detail/polyline.h"
#include "snaxels/export/stroke_weight.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

std::vector<ClassSpan> class_spans(const std::vector<std::pair<double, int>>& changes, int cls0, bool closed,
                                   double min_u) {
    std::vector<ClassSpan> spans;
    if (changes.empty()) return {{cls0, closed, 0.0, 1.0}};
    if (closed) {
        for (std::size_t k = 0; k < changes.size(); ++k) {
            const double u0 = changes[k].first;
            const double u1 = k + 1 < changes.size() ? changes[k + 1].first : changes[0].first + 1.0;
            spans.push_back({changes[k].second, false, u0, u1});
        }
    } else {
        double u0 = 0.0;
        int cls = cls0;
        for (const auto& [u, after] : changes) {
            spans.push_back({cls, false, u0, u});
            u0 = u;
            cls = after;
        }
        spans.push_back({cls, false, u0, 1.0});
    }
    // Coalesce equal neighbours (cyclically on closed loops); a closed loop
    // of one class is whole.
    auto coalesce = [&] {
        std::vector<ClassSpan> merged;
        for (const ClassSpan& sp : spans) {
            if (!merged.empty() && merged.back().cls == sp.cls) merged.back().u1 = sp.u1;
            else merged.push_back(sp);
        }
        if (closed && merged.size() > 1 && merged.front().cls == merged.back().cls) {
            merged.back().u1 = merged.front().u1 + 1.0;
            merged.erase(merged.begin());
        }
        if (merged.size() == 1 && closed) merged[0] = {merged[0].cls, true, 0.0, 1.0};
        spans = std::move(merged);
    };
    coalesce();
    // Stretches shorter than min_u are flicker (a grazing ray at a
    // T-junction) rather than lines a reader could see: they take the class
    // of their longer neighbour.
    while (spans.size() > 1) {
        std::size_t shortest = 0;
        for (std::size_t k = 1; k < spans.size(); ++k)
            if (spans[k].u1 - spans[k].u0 < spans[shortest].u1 - spans[shortest].u0) shortest = k;
        if (spans[shortest].u1 - spans[shortest].u0 >= min_u) break;
        const std::size_t n = spans.size();
        const bool has_prev = closed || shortest > 0, has_next = closed || shortest + 1 < n;
        const std::size_t prev = (shortest + n - 1) % n, next = (shortest + 1) % n;
        const double lp = has_prev ? spans[prev].u1 - spans[prev].u0 : -1.0;
        const double ln = has_next ? spans[next].u1 - spans[next].u0 : -1.0;
        spans[shortest].cls = lp >= ln ? spans[prev].cls : spans[next].cls;
        coalesce();
    }
    return spans;
}

namespace {

constexpr double kTwoPi = 6.283185307179586;
/// A canonical segment (keys of one vertex set) spans at most this many frames.
constexpr std::size_t kMaxSegmentFrames = 8;

double wrap01(double u) { return u - std::floor(u); }

/// One loop of one frame, parameterized by arc length: u in [0, 1) runs
/// round the loop from an anchor that follows the snaxels' identities.
struct ParamLoop {
    bool closed = true;
    std::vector<glm::dvec2> pts;
    std::vector<double> cum; ///< arc length at each point from point 0
    double length = 0.0;
    double anchor = 0.0;     ///< arc length where u = 0 (closed loops)
    double spacing = 1.0;    ///< mean distance between its points
    std::vector<std::uint64_t> ids;
    std::vector<ClassSpan> spans;
    /// Screen dashes: arc lengths where the QI changes (restarts_of).
    std::vector<double> restarts;
    /// With line weight: the drawn loop's stroke parameter and weights,
    /// and the frame's time (the wobble's boil).
    std::shared_ptr<const LoopAttributes> attributes;
    double u_period = 0.0;
    double seconds = 0.0;

    double arc_of_u(double u) const {
        return closed ? std::fmod(anchor + wrap01(u) * length, length) : std::clamp(u, 0.0, 1.0) * length;
    }
    double u_of_arc(double arc) const {
        if (length <= 0.0) return 0.0;
        return closed ? wrap01((arc - anchor) / length) : std::clamp(arc / length, 0.0, 1.0);
    }
    glm::dvec2 at_arc(double arc) const {
        if (pts.size() == 1 || length <= 0.0) return pts[0];
        const std::size_t n = pts.size();
        const std::size_t segs = closed ? n : n - 1;
        std::size_t k = std::size_t(std::upper_bound(cum.begin(), cum.end(), arc) - cum.begin());
        k = std::clamp<std::size_t>(k, 1, segs);
        const std::size_t i = k - 1, j = k % n;
        const double seg = (k < n ? cum[k] : length) - cum[i];
        const double t = seg > 0.0 ? std::clamp((arc - cum[i]) / seg, 0.0, 1.0) : 0.0;
        return (1.0 - t) * pts[i] + t * pts[j];
    }
    glm::dvec2 at(double u) const { return at_arc(arc_of_u(u)); }
    /// The stroke point at @p u (its position that of at(u)).
    StrokePoint stroke_at(double u) const {
        StrokePoint p = attributes ? attributes->at(arc_of_u(u)) : StrokePoint{};
        p.q = at(u);
        return p;
    }
};

/// Arc lengths along loop @p w from @p a0 to @p a1 (past the end of a closed
/// loop it comes round again): the ends and the loop's points between, and
/// the dash measure at each: arc length from a0 (screen dashes, as a dash
/// array measures a subpath), or the stroke parameter (@p surface).
void dash_measure(const ParamLoop& w, double a0, double a1, bool surface, std::vector<double>& arcs,
                  std::vector<double>& along) {
    // The run's ends and the loop's points between them: the parameter is
    // linear in arc length between points, so these give it exactly.
    arcs.push_back(a0);
    const std::size_t n = w.cum.size();
    if (n > 0 && w.length > 0.0) {
        const double turn = w.closed ? w.length : 0.0;
        for (double base = w.closed ? std::floor(a0 / w.length) * w.length : 0.0; base < a1; base += turn) {
            for (std::size_t k = 0; k < n; ++k) {
                const double a = base + w.cum[k];
                if (a > a0 && a < a1) arcs.push_back(a);
            }
            if (!w.closed) break;
        }
    }
    arcs.push_back(a1);
    for (const double a : arcs) along.push_back(surface ? (w.attributes ? w.attributes->at(a).u : a) : a - a0);
}

/// The stretches of [a0, a1] between the loop's QI changes; round a
/// whole ring, from its first point, or between its changes if it has
/// any.
std::vector<std::pair<double, double>> screen_pieces(const ParamLoop& w, double a0, double a1, bool ring) {
    std::vector<double> cuts;
    for (const double r : w.restarts)
        for (const double shift : {0.0, w.length})
            if (r + shift > a0 + 1e-9 && r + shift < a1 - 1e-9) cuts.push_back(r + shift);
    std::sort(cuts.begin(), cuts.end());
    std::vector<std::pair<double, double>> out;
    if (ring && !w.restarts.empty()) { // from change to change round the ring
        for (std::size_t i = 0; i < w.restarts.size(); ++i) {
            const double from = w.restarts[i];
            const double to = i + 1 < w.restarts.size() ? w.restarts[i + 1] : w.restarts[0] + w.length;
            out.push_back({from, to});
        }
        return out;
    }
    double from = a0;
    for (const double c : cuts) out.push_back({from, c}), from = c;
    out.push_back({from, a1});
    return out;
}

/// The line @p centre as @p stroke draws it with line weight (the frame's
/// time @p seconds, the loop's parameter period @p period when closed):
/// wobbled, and as filled outlines where its width varies.
void weigh(const StrokeStyle& stroke, std::vector<StrokePoint> centre, bool closed, double period, double seconds,
           anim::Shape& out) {
    wobble(stroke, centre, closed, closed ? period : 0.0, seconds);
    if (!stroke.variable_width()) {
        anim::Subpath sp;
        sp.closed = closed;
        for (const StrokePoint& p : centre) sp.pts.push_back(p.q);
        out.push_back(std::move(sp));
        return;
    }
    std::vector<std::vector<glm::dvec2>> outline;
    stroke_outline(stroke, centre, closed, outline);
    for (auto& poly : outline) out.push_back({std::move(poly), true});
}

ParamLoop parameterize(const DrawnLoop& dl, const AnimatedLoop& al, const Drawing& drawing, bool weighted) {
    ParamLoop p;
    if (weighted) {
        p.attributes = std::make_shared<const LoopAttributes>(dl);
        p.u_period = dl.u_period;
        p.seconds = drawing.seconds;
    }
    p.closed = dl.closed;
    p.pts = dl.q;
    p.ids = al.ids;
    const std::size_t n = p.pts.size();
    p.cum.assign(n, 0.0);
    for (std::size_t k = 1; k < n; ++k) p.cum[k] = p.cum[k - 1] + glm::length(p.pts[k] - p.pts[k - 1]);
    p.length = n ? p.cum[n - 1] + (p.closed ? glm::length(p.pts[0] - p.pts[n - 1]) : 0.0) : 0.0;
    const std::size_t segs = p.closed ? n : (n ? n - 1 : 0);
    p.spacing = segs ? std::max(p.length / double(segs), 0.5) : 1.0;
    return p;
}

// Where the loop's visibility class (visible: QI 0, hidden: QI > 0, left
// out: kNotDrawn, which is never drawn) changes,
// in u, once the anchor is known: on the segment before each snaxel whose
// class differs from its predecessor's, at the change point.
// Arc length along @p p where the QI changes before snaxel @p k (the change point on the segment before it).
double change_arc(const ParamLoop& p, const DrawnLoop& dl, std::size_t k) {
    const std::size_t n = p.pts.size(), prev = (k + n - 1) % n;
    const glm::dvec2 a = p.pts[prev], b = p.pts[k], c = dl.change_before[k];
    const double seg = glm::length(b - a);
    const double t = seg > 0.0 ? std::clamp(glm::dot(c - a, b - a) / (seg * seg), 0.0, 1.0) : 0.0;
    return (k == 0 ? p.length - seg : p.cum[prev]) + t * seg;
}

// Arc lengths where the loop's QI changes (sorted): where the static
// frame's visibility runs, each a path of its own, restart a dash array.
std::vector<double> restarts_of(const ParamLoop& p, const DrawnLoop& dl) {
    std::vector<double> out;
    if (dl.qi.empty()) return out;
    const std::size_t n = p.pts.size();
    for (std::size_t k = p.closed ? 0 : 1; k < n; ++k)
        if (dl.qi[(k + n - 1) % n] != dl.qi[k]) out.push_back(change_arc(p, dl, k));
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<ClassSpan> spans_of(const ParamLoop& p, const DrawnLoop& dl, double min_run_px) {
    if (dl.qi.empty()) return {{0, p.closed, 0.0, 1.0}};
    const std::size_t n = p.pts.size();
    auto cls = [&](std::size_t k) { return dl.qi[k] == kNotDrawn ? kLeftOut : dl.qi[k] > 0 ? 1 : 0; };
    std::vector<std::pair<double, int>> changes;
    for (std::size_t k = 0; k < n; ++k) {
        if (!p.closed && k == 0) continue;
        const std::size_t prev = (k + n - 1) % n;
        if (cls(prev) == cls(k)) continue;
        changes.push_back({p.u_of_arc(change_arc(p, dl, k)), cls(k)});
    }
    std::sort(changes.begin(), changes.end());
    // The class at u = 0: after the last change before it (cyclically).
    const int cls0 = p.closed && !changes.empty() ? changes.back().second : cls(0);
    return class_spans(changes, cls0, p.closed, p.length > 0.0 ? min_run_px / p.length : 0.0);
}

// Where u = 0 goes in `cur`: every shared identity votes for an anchor that
// keeps its u from the previous frame; the votes are averaged on the circle.
// Without shared identities, the nearest point to the old anchor.
double follow_anchor(const ParamLoop& prev, const ParamLoop& cur) {
    std::unordered_map<std::uint64_t, std::size_t> prev_index;
    for (std::size_t k = 0; k < prev.ids.size(); ++k) prev_index[prev.ids[k]] = k;
    double sx = 0.0, sy = 0.0;
    std::size_t votes = 0;
    for (std::size_t k = 0; k < cur.ids.size(); ++k) {
        const auto it = prev_index.find(cur.ids[k]);
        if (it == prev_index.end()) continue;
        const double u_prev = prev.u_of_arc(prev.cum[it->second]);
        const double angle = kTwoPi * (cur.cum[k] - u_prev * cur.length) / cur.length;
        sx += std::cos(angle);
        sy += std::sin(angle);
        ++votes;
    }
    if (votes && std::hypot(sx, sy) > 1e-9 * double(votes)) {
        const double a = std::atan2(sy, sx) / kTwoPi * cur.length;
        return a < 0.0 ? a + cur.length : a;
    }
    const glm::dvec2 target = prev.at(0.0);
    double best = 1e300, arc = 0.0;
    for (std::size_t k = 0; k < cur.pts.size(); ++k) {
        const double d = glm::length(cur.pts[k] - target);
        if (d < best) best = d, arc = cur.cum[k];
    }
    return arc;
}

// A loop that changes abruptly (absorbs or sheds a large piece, most of its
// snaxels replaced) cannot be interpolated: the path jumps there.
bool abrupt(const ParamLoop& a, const ParamLoop& b) {
    if (a.closed != b.closed) return true;
    const double dl = std::abs(b.length - a.length);
    if (dl > 0.1 * std::max(a.length, b.length) && dl > 10.0) return true;
    std::unordered_map<std::uint64_t, char> ids;
    for (const auto id : a.ids) ids[id] = 1;
    std::size_t shared = 0;
    for (const auto id : b.ids) shared += ids.count(id);
    return 2 * shared < std::min(a.ids.size(), b.ids.size());
}

/// A visibility run of one frame, in u aligned with the run it continues.
struct Run {
    int id = 0;
    ClassSpan span;
};

/// One frame of a contour sequence's life.
struct LifeFrame {
    const ParamLoop* loop = nullptr;
    bool jump = false; ///< not interpolated from the frame before
    std::vector<Run> runs[3]; ///< per class (visible, hidden, kLeftOut: not drawn), sorted by id
};

double extent(const ClassSpan& s) { return s.whole ? 1.0 : s.u1 - s.u0; }

// How much of `s` overlaps `last`, with the whole shift of `s` that does it best.
double overlap(const ClassSpan& last, const ClassSpan& s, bool closed, double& shift) {
    shift = 0.0;
    if (last.whole || s.whole) return std::min(extent(last), extent(s));
    const double base = closed ? std::round(0.5 * (last.u0 + last.u1) - 0.5 * (s.u0 + s.u1)) : 0.0;
    double best = -1e300;
    for (const double d : {-1.0, 0.0, 1.0}) {
        if (!closed && d != 0.0) continue;
        const double o = std::min(last.u1, s.u1 + base + d) - std::max(last.u0, s.u0 + base + d);
        if (o > best) best = o, shift = base + d;
    }
    return best;
}

// Runs followed from frame to frame: a run continues the previous frame's
// run it overlaps most when that one overlaps it most too.
void track_runs(std::vector<LifeFrame>& life, int cls, int& next_id) {
    for (std::size_t i = 0; i < life.size(); ++i) {
        std::vector<Run>& runs = life[i].runs[cls];
        const bool follow = i > 0 && !life[i].jump;
        const std::vector<Run> empty;
        const std::vector<Run>& prev = follow ? life[i - 1].runs[cls] : empty;
        std::vector<int> best_prev(runs.size(), -1), best_cur(prev.size(), -1);
        std::vector<double> best_o(runs.size(), 0.0), best_po(prev.size(), 0.0), shift(runs.size(), 0.0);
        for (std::size_t s = 0; s < runs.size(); ++s)
            for (std::size_t r = 0; r < prev.size(); ++r) {
                double sh = 0.0;
                const double o = overlap(prev[r].span, runs[s].span, life[i].loop->closed, sh);
                if (o <= 0.0) continue;
                if (o > best_o[s]) best_o[s] = o, best_prev[s] = int(r), shift[s] = sh;
                if (o > best_po[r]) best_po[r] = o, best_cur[r] = int(s);
            }
        for (std::size_t s = 0; s < runs.size(); ++s) {
            if (best_prev[s] >= 0 && best_cur[best_prev[s]] == int(s)) {
                runs[s].id = prev[best_prev[s]].id;
                runs[s].span.u0 += shift[s];
                runs[s].span.u1 += shift[s];
            } else {
                runs[s].id = next_id++;
            }
        }
        std::sort(runs.begin(), runs.end(), [](const Run& a, const Run& b) { return a.id < b.id; });
    }
}

/// Whether two frames have the same runs (by id; both sorted by id).
bool same_runs(const std::vector<Run>& a, const std::vector<Run>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Run& x, const Run& y) { return x.id == y.id; });
}

/// A key of a path: the shape at time `time` (frames), between life frame
/// `i` and the next at fraction `s`, each subpath drawing `spans[j]`.
struct Key {
    std::size_t i = 0;
    double s = 0.0;
    double time = 0.0;
    std::vector<ClassSpan> spans;
};

/// Keys of one structure (a segment): subpaths `ids` (run ids; -1 is a
/// lone move, for frames without runs), whole rings or open.
struct Plan {
    std::vector<int> ids;
    std::vector<Key> keys;
};

class StrokeWriter {
  public:
    StrokeWriter(const std::vector<LifeFrame>& life, int first_frame, const AnimatedSvgOptions& options)
        : life_(life), first_frame_(first_frame), options_(options) {}

    /// A segment of a plan: its first and last life frames, the time of its
    /// first key.
    struct Range {
        std::size_t first, last;
        double start;
        bool hold_after = false; ///< a jump follows: hold the last shape until then
    };

    /// The runs of @p cls that @p keep selects, over life frames [a, b]:
    /// the path's segments. A segment's subpaths are the runs alive in any
    /// of its frames; in frames before a run appears it is a point where it
    /// will appear (the middle of its first span), after it vanishes a
    /// point where it was, so it grows and shrinks between frames.
    template <class Select>
    std::vector<Plan> plan(int cls, std::size_t a, std::size_t b, Select keep) const {
        std::vector<std::vector<Run>> runs(b - a + 1);
        for (std::size_t i = a; i <= b; ++i)
            for (const Run& r : life_[i].runs[cls])
                if (keep(r.id)) runs[i - a].push_back(r);
        const std::vector<Range> ranges = ranges_of(runs, a, b);
        std::vector<Plan> plans;
        for (std::size_t q = 0; q < ranges.size(); ++q) {
            const Range& rg = ranges[q];
            if (q > 0 && ranges[q - 1].last + 1 == rg.first && !ranges[q - 1].hold_after)
                plans.push_back(transition(runs[rg.first - 1 - a], runs[rg.first - a], rg.first - 1));
            plans.push_back(plan_of(runs, a, rg));
        }
        return plans;
    }

    /// A plan's frames: the runs of life frames [a, b] (@p runs, from a)
    /// cut into segments where a run jumps, appears or vanishes, or travels
    /// too far for one vertex set.
    std::vector<Range> ranges_of(const std::vector<std::vector<Run>>& runs, std::size_t a, std::size_t b) const {
        auto time_of = [&](std::size_t i) { return double(first_frame_ + int(i)); };
        std::vector<Range> ranges{{a, a, time_of(a)}};
        std::map<int, std::pair<double, double>> lo_hi;
        std::map<int, double> widest;
        auto reset = [&](std::size_t i) {
            lo_hi.clear(), widest.clear();
            for (const Run& r : runs[i - a]) lo_hi[r.id] = {r.span.u0, r.span.u1}, widest[r.id] = extent(r.span);
        };
        reset(a);
        for (std::size_t i = a; i < b; ++i) {
            const std::vector<Run>& next = runs[i + 1 - a];
            Range& cur = ranges.back();
            if (life_[i + 1].jump || !glides(runs[i - a], next, i)) {
                cur.hold_after = true;
                ranges.push_back({i + 1, i + 1, time_of(i + 1)});
                reset(i + 1);
                continue;
            }
            // Where a run appears or vanishes, the segment ends and a
            // transition grows or shrinks it between the two frames: within
            // a segment it would be a point at the frames it does not
            // exist in, drawn as a dot by round caps where the static frame
            // has nothing.
            if (!same_runs(runs[i - a], next)) {
                ranges.push_back({i + 1, i + 1, time_of(i + 1)}); // a transition plan goes between
                reset(i + 1);
                continue;
            }
            // Too long, or its runs travel too far along the loop for one
            // vertex set: go on with a new one from this frame's shape.
            bool split = i + 1 - cur.first >= kMaxSegmentFrames;
            for (const Run& r : next) {
                if (split || r.span.whole || !lo_hi.count(r.id)) continue;
                const double lo = std::min(lo_hi[r.id].first, r.span.u0), hi = std::max(lo_hi[r.id].second, r.span.u1);
                split = hi - lo > 1.5 * std::max(widest[r.id], extent(r.span)) + 0.02;
            }
            if (split) {
                ranges.push_back({i, i + 1, time_of(i) + anim::kSwitch});
                reset(i);
            } else {
                cur.last = i + 1;
            }
            for (const Run& r : next) {
                auto [it, fresh] = lo_hi.try_emplace(r.id, r.span.u0, r.span.u1);
                it->second = {std::min(it->second.first, r.span.u0), std::max(it->second.second, r.span.u1)};
                widest[r.id] = std::max(widest[r.id], extent(r.span));
            }
        }
        return ranges;
    }

    /// The plan of one segment @p rg of the runs @p runs (life frames from
    /// @p a): a subpath per run alive in any of its frames, a point where
    /// it will appear or was before it appears or after it vanishes.
    Plan plan_of(const std::vector<std::vector<Run>>& runs, std::size_t a, const Range& rg) const {
        auto time_of = [&](std::size_t i) { return double(first_frame_ + int(i)); };
        Plan plan;
        std::map<int, std::vector<const Run*>> by_id; // per id: its run in each frame of the range
        for (std::size_t i = rg.first; i <= rg.last; ++i)
            for (const Run& r : runs[i - a]) {
                auto& v = by_id[r.id];
                v.resize(rg.last - rg.first + 1, nullptr);
                v[i - rg.first] = &r;
            }
        const std::size_t frames = rg.last - rg.first + 1;
        std::vector<std::vector<ClassSpan>> spans(frames); // [frame][subpath]
        for (const auto& [id, present] : by_id) {
            plan.ids.push_back(id);
            std::size_t p0 = 0, p1 = frames - 1;
            while (!present[p0]) ++p0;
            while (!present[p1]) --p1;
            bool all_whole = p0 == 0 && p1 == frames - 1;
            double centre = 0.0;
            bool have_centre = false;
            for (std::size_t f = p0; f <= p1; ++f) {
                all_whole &= present[f] && present[f]->span.whole;
                if (present[f] && !present[f]->span.whole && !have_centre)
                    centre = 0.5 * (present[f]->span.u0 + present[f]->span.u1), have_centre = true;
            }
            auto open = [&](const ClassSpan& sp) {
                if (!sp.whole || all_whole) return sp;
                return ClassSpan{sp.cls, false, centre - 0.5, centre + 0.5}; // a ring opened where the run will open
            };
            const ClassSpan first = open(present[p0]->span), last = open(present[p1]->span);
            for (std::size_t f = 0; f < frames; ++f) {
                ClassSpan sp;
                if (f < p0) sp = {first.cls, false, 0.5 * (first.u0 + first.u1), 0.5 * (first.u0 + first.u1)};
                else if (f > p1) sp = {last.cls, false, 0.5 * (last.u0 + last.u1), 0.5 * (last.u0 + last.u1)};
                else if (present[f]) sp = open(present[f]->span);
                else sp = {last.cls, false, 0.5 * (last.u0 + last.u1), 0.5 * (last.u0 + last.u1)};
                spans[f].push_back(sp);
            }
        }
        if (plan.ids.empty()) {
            plan.ids.push_back(-1);
            for (auto& s : spans) s.push_back({});
        }
        for (std::size_t f = 0; f < frames; ++f) {
            const std::size_t i = rg.first + f;
            plan.keys.push_back({i, 0.0, f == 0 ? rg.start : time_of(i), spans[f]});
        }
        // Before a jump the shape holds until the next frame begins.
        if (rg.hold_after) plan.keys.push_back({rg.last, 0.0, time_of(rg.last) + 1.0 - anim::kSwitch, spans.back()});
        return plan;
    }

    /// The segment of @p plan: geometry at every key, vertices and keys
    /// reduced; the kept keys.
    PathSegment emit(const Plan& plan, const StrokeStyle& stroke) const {
        // Outlines of lines of varying width are polygons, not smoothed.
        const bool dashed = dashes_as_geometry(stroke, options_.screen_dash_array);
        const double smoothing = stroke.variable_width() || dashed ? 0.0 : stroke.smoothing;
        const bool weighted = stroke.needs_parameter();
        // Each subpath's vertices: a grid fixed in u over the plan, at the
        // loops' own sampling density; grid points outside a key's span fold
        // onto its ends.
        const std::size_t n = plan.ids.size();
        std::vector<std::vector<double>> grid(n);
        std::vector<char> ring(n, 0);
        double spacing = 1e300, longest = 0.0;
        for (const Key& k : plan.keys) {
            const ParamLoop& p = *life_[std::min(k.i + (k.s > 0.0 ? 1 : 0), life_.size() - 1)].loop;
            spacing = std::min(spacing, std::max(p.spacing, 0.5));
            longest = std::max({longest, p.length, life_[k.i].loop->length});
        }
        // Line weight varies along a line between its points: the grid is
        // at least as fine as the stroke outline's (kMaxStrokeStepPx), as
        // the static frame's lines are subdivided.
        if (weighted) spacing = std::min(spacing, kMaxStrokeStepPx);
        const double steps = std::clamp(std::ceil(longest / spacing), 3.0, 200000.0);
        for (std::size_t j = 0; j < n; ++j) {
            if (plan.ids[j] < 0) continue;
            ring[j] = plan.keys.front().spans[j].whole;
            if (ring[j]) {
                for (double g = 0; g < steps; ++g) grid[j].push_back(g / steps);
                continue;
            }
            double lo = 1e300, hi = -1e300;
            for (const Key& k : plan.keys) lo = std::min(lo, k.spans[j].u0), hi = std::max(hi, k.spans[j].u1);
            for (auto g = std::int64_t(std::floor(lo * steps)) + 1; double(g) < hi * steps; ++g)
                grid[j].push_back(double(g) / steps);
        }
        const glm::dvec2 lone_move = life_[plan.keys.front().i].loop->at(0.0);
        // Dashes drawn as pieces of the line: each subpath's dash ids over
        // the plan (the union of every key's), so that every key has the
        // same subpaths.
        std::vector<std::map<std::int64_t, std::size_t>> dash_ids(dashed ? n : 0);
        if (dashed)
            for (const Key& k : plan.keys)
                for (std::size_t j = 0; j < n; ++j)
                    if (plan.ids[j] >= 0)
                        for (const KeyDash& d : key_dashes(k, j, ring[j], stroke)) dash_ids[j].emplace(d.id, d.points);
        auto shape_at = [&](const Key& k) {
            const ParamLoop& a = *life_[k.i].loop;
            const ParamLoop& b = *life_[std::min(k.i + 1, life_.size() - 1)].loop;
            auto curve = [&](double u) { return k.s <= 0.0 ? a.at(u) : k.s >= 1.0 ? b.at(u) : (1.0 - k.s) * a.at(u) + k.s * b.at(u); };
            anim::Shape shape(n);
            for (std::size_t j = 0; j < n; ++j) {
                anim::Subpath& sp = shape[j];
                if (plan.ids[j] < 0) {
                    sp.pts = {lone_move};
                    continue;
                }
                sp.closed = ring[j];
                if (ring[j]) {
                    for (const double u : grid[j]) sp.pts.push_back(curve(u));
                    continue;
                }
                const ClassSpan& s = k.spans[j];
                sp.pts.push_back(curve(s.u0));
                for (const double u : grid[j]) sp.pts.push_back(curve(std::clamp(u, s.u0, s.u1)));
                sp.pts.push_back(curve(s.u1));
            }
            if (dashed) return dash_shape(plan, k, shape, dash_ids, stroke);
            if (!weighted) return shape;
            return weighed_shape(plan, k, shape, grid, ring, stroke);
        };
        anim::Segment seg;
        for (std::size_t k = 0; k < plan.keys.size(); ++k) {
            anim::Shape here = shape_at(plan.keys[k]);
            seg.times.push_back(plan.keys[k].time);
            seg.shapes.push_back(std::move(here));
        }
        PathSegment out;
        anim::reduce_vertices(seg, options_.tolerance_px, smoothing, &out.knots);
        // Without smoothing the vertices left are the polylines themselves.
        if (smoothing <= 0.0) out.knots.clear();
        const std::vector<std::uint8_t> keep = anim::reduce_keys(seg, options_.tolerance_px);
        for (std::size_t k = 0; k < seg.times.size(); ++k) {
            if (!keep[k]) continue;
            out.times.push_back(seg.times[k]);
            out.shapes.push_back(std::move(seg.shapes[k]));
        }
        return out;
    }

  private:
    /// A key's shape with line weight: each subpath's stroke points from
    /// the loop the key draws (its parameter, weight and time), wobbled, and
    /// outlined where the width varies. @p shape is the key's centre lines
    /// on the plan's grid (@p grid, @p ring: emit's).
    anim::Shape weighed_shape(const Plan& plan, const Key& k, const anim::Shape& shape,
                              const std::vector<std::vector<double>>& grid, const std::vector<char>& ring,
                              const StrokeStyle& stroke) const {
        const std::size_t n = plan.ids.size();
        const ParamLoop& w = *life_[k.s < 0.5 ? k.i : std::min(k.i + 1, life_.size() - 1)].loop;
        anim::Shape weighed;
        for (std::size_t j = 0; j < n; ++j) {
            if (plan.ids[j] < 0) {
                weighed.push_back(shape[j]);
                continue;
            }
            std::vector<StrokePoint> centre;
            centre.reserve(shape[j].pts.size());
            auto add = [&](double u, const glm::dvec2& q) {
                StrokePoint p = w.stroke_at(u);
                p.q = q;
                centre.push_back(p);
            };
            const ClassSpan& s = k.spans[j];
            if (ring[j]) {
                for (std::size_t g = 0; g < grid[j].size(); ++g) add(grid[j][g], shape[j].pts[g]);
            } else {
                add(s.u0, shape[j].pts.front());
                for (std::size_t g = 0; g < grid[j].size(); ++g) add(std::clamp(grid[j][g], s.u0, s.u1), shape[j].pts[g + 1]);
                add(s.u1, shape[j].pts.back());
            }
            weigh(stroke, std::move(centre), ring[j], w.u_period, w.seconds, weighed);
        }
        return weighed;
    }

    /// A dash of a key's run: its id, the loop's arc length at its ends,
    /// and how many points draw it (the same for an id in every key).
    struct KeyDash {
        std::int64_t id = 0;
        double from = 0.0, to = 0.0;
        std::size_t points = 2;
    };

    /// The dashes of subpath @p j at key @p k, in arc length along the
    /// loop the key draws: screen dashes measured from the run's start
    /// (from the loop's first point round a whole ring), as the static
    /// frame's dash array is; surface dashes by the stroke parameter.
    std::vector<KeyDash> key_dashes(const Key& k, std::size_t j, bool ring, const StrokeStyle& stroke) const {
        const ParamLoop& w = *life_[std::min(k.i + (k.s >= 0.5 ? 1 : 0), life_.size() - 1)].loop;
        double a0 = 0.0, a1 = w.length;
        if (!ring) {
            a0 = w.arc_of_u(k.spans[j].u0);
            a1 = w.arc_of_u(k.spans[j].u1);
            if (w.closed && (a1 < a0 || (a1 == a0 && k.spans[j].u1 > k.spans[j].u0))) a1 += w.length;
        }
        std::vector<KeyDash> out;
        // Screen dashes restart where the static frame's runs do.
        const auto pieces = stroke.dash_on_surface ? std::vector<std::pair<double, double>>{{a0, a1}} : screen_pieces(w, a0, a1, ring);
        for (std::size_t i = 0; i < pieces.size(); ++i) // ids count from each piece's start
            for (const KeyDash& d : key_dashes_over(w, pieces[i].first, pieces[i].second, stroke))
                out.push_back({d.id + (std::int64_t(i) << 32), d.from, d.to, d.points});
        return out;
    }

    /// The dashes over arcs [a0, a1] of loop @p w (one stretch whose dash
    /// measure starts at a0, or the stroke parameter).
    std::vector<KeyDash> key_dashes_over(const ParamLoop& w, double a0, double a1, const StrokeStyle& stroke) const {
        std::vector<double> arcs, along;
        dash_measure(w, a0, a1, stroke.dash_on_surface, arcs, along);
        std::vector<KeyDash> out;
        for (const Dash& d : dash_spans(arcs, along, stroke.dash, stroke.dash_on_surface ? w.u_period : 0.0)) {
            // About a point per pixel of the dash (at most 64): joint vertex
            // reduction leaves those that a bend needs.
            std::size_t points = 2;
            while (points < 64 && double(points - 1) * std::max(w.spacing, 0.5) < d.length) ++points;
            out.push_back({d.id, d.from, d.to, points});
        }
        return out;
    }

    /// Key @p k's shape with its runs' subpaths replaced by their dashes,
    /// one subpath per id of @p ids (an id the key lacks is a point at the
    /// end of the dash before it, or the start of the one after).
    anim::Shape dash_shape(const Plan& plan, const Key& k, const anim::Shape& shape,
                           const std::vector<std::map<std::int64_t, std::size_t>>& ids, const StrokeStyle& stroke) const {
        const ParamLoop& w = *life_[std::min(k.i + (k.s >= 0.5 ? 1 : 0), life_.size() - 1)].loop;
        // Arc length round a closed loop past its end comes round again.
        auto at = [&](double arc) { return w.at_arc(w.closed && w.length > 0.0 ? std::fmod(arc, w.length) : arc); };
        // A dash this key lacks is a point where a dash it has ends (its cap
        // covers it): the one before it, in this run or a run before, else
        // the first dash of the key.
        std::vector<std::map<std::int64_t, KeyDash>> present(plan.ids.size());
        glm::dvec2 rest(0.0);
        bool any = false;
        for (std::size_t j = 0; j < plan.ids.size(); ++j) {
            if (plan.ids[j] < 0) continue;
            for (const KeyDash& d : key_dashes(k, j, shape[j].closed, stroke)) present[j].emplace(d.id, d);
            if (!any && !present[j].empty()) rest = at(present[j].begin()->second.from), any = true;
        }
        anim::Shape out;
        for (std::size_t j = 0; j < plan.ids.size(); ++j) {
            if (plan.ids[j] < 0) {
                out.push_back(shape[j]);
                continue;
            }
            const std::map<std::int64_t, KeyDash>& here = present[j];
            if (!any) rest = shape[j].pts.front();
            for (const auto& [id, points] : ids[j]) {
                anim::Subpath sp;
                const auto it = here.find(id);
                if (it == here.end()) {
                    sp.pts.assign(points, rest);
                } else {
                    const KeyDash& d = it->second;
                    for (std::size_t i = 0; i < points; ++i)
                        sp.pts.push_back(at(d.from + (d.to - d.from) * double(i) / double(points - 1)));
                    rest = sp.pts.back();
                }
                out.push_back(std::move(sp));
            }
        }
        return out;
    }

    /// Whether the runs of frame @p i interpolate to those of the next:
    /// every run end (a run that appears or vanishes at the middle of its
    /// span) moves along a stretch of the loop that is straight within
    /// max_sweep_px in both frames. Where an end glides round a bend,
    /// interpolation would cut across it: the path jumps there instead.
    bool glides(const std::vector<Run>& from, const std::vector<Run>& to, std::size_t i) const {
        const ParamLoop& p = *life_[i].loop;
        const ParamLoop& q = *life_[i + 1].loop;
        auto bend = [](const ParamLoop& loop, double ua, double ub) {
            const glm::dvec2 x = loop.at(ua), y = loop.at(ub);
            double worst = 0.0;
            for (int k = 1; k < 16; ++k) worst = std::max(worst, point_segment(loop.at(ua + (ub - ua) * k / 16.0), x, y));
            return worst;
        };
        std::map<int, std::pair<const ClassSpan*, const ClassSpan*>> pairs;
        for (const Run& r : from) pairs[r.id].first = &r.span;
        for (const Run& r : to) pairs[r.id].second = &r.span;
        for (const auto& [id, pair] : pairs) {
            const auto [x, y] = pair;
            if (x && y && x->whole && y->whole) continue;
            if ((x && x->whole) || (y && y->whole)) return false; // a ring opens or closes
            const double c = 0.5 * (x ? x->u0 + x->u1 : y->u0 + y->u1);
            const ClassSpan a = x ? *x : ClassSpan{0, false, c, c};
            const ClassSpan b = y ? *y : ClassSpan{0, false, c, c};
            for (const auto& [ua, ub] : {std::pair{a.u0, b.u0}, std::pair{a.u1, b.u1}})
                if (std::max(bend(p, ua, ub), bend(q, ua, ub)) > options_.max_sweep_px) return false;
        }
        return true;
    }

    Plan transition(const std::vector<Run>& from, const std::vector<Run>& to, std::size_t i) const {
        std::map<int, std::pair<const Run*, const Run*>> pairs;
        for (const Run& r : from) pairs[r.id].first = &r;
        for (const Run& r : to) pairs[r.id].second = &r;
        Plan plan;
        Key k0{i, 0.0, double(first_frame_ + int(i)) + anim::kSwitch, {}};
        Key k1{i, 1.0, double(first_frame_ + int(i) + 1) - anim::kSwitch, {}};
        for (const auto& [id, pair] : pairs) {
            const auto [x, y] = pair;
            ClassSpan s0, s1;
            if (x && y && x->span.whole && y->span.whole) {
                s0 = s1 = x->span;
            } else {
                // Open at both ends: a ring opens (or closes) about the middle of
                // the run it becomes; a run that appears grows from its middle,
                // one that vanishes shrinks to its middle.
                const Run* open = y && !y->span.whole ? y : x && !x->span.whole ? x : nullptr;
                const double c = open ? 0.5 * (open->span.u0 + open->span.u1) : 0.0;
                auto end = [&](const Run* r) {
                    if (!r) return ClassSpan{0, false, c, c};
                    if (r->span.whole) return ClassSpan{r->span.cls, false, c - 0.5, c + 0.5};
                    return r->span;
                };
                s0 = end(x);
                s1 = end(y);
            }
            plan.ids.push_back(id);
            k0.spans.push_back(s0);
            k1.spans.push_back(s1);
        }
        if (plan.ids.empty()) { // neither frame has runs
            plan.ids.push_back(-1);
            k0.spans.push_back({});
            k1.spans.push_back({});
        }
        plan.keys = {std::move(k0), std::move(k1)};
        return plan;
    }

    const std::vector<LifeFrame>& life_;
    int first_frame_;
    const AnimatedSvgOptions& options_;
};

/// A run of one frame's loop as a polyline at the loop's own density,
/// simplified within the tolerance (appended to @p out; with line weight,
/// as the stroke draws it).
void run_polyline(const ParamLoop& p, const ClassSpan& span, const StrokeStyle& stroke, const AnimatedSvgOptions& options,
                  anim::Shape& out) {
    if (dashes_as_geometry(stroke, options.screen_dash_array)) { // the pieces where the dash pattern is on
        double a0 = 0.0, a1 = p.length;
        if (!span.whole) {
            a0 = p.arc_of_u(span.u0);
            a1 = p.arc_of_u(span.u1);
            if (p.closed && a1 < a0) a1 += p.length;
        }
        const auto stretches = stroke.dash_on_surface ? std::vector<std::pair<double, double>>{{a0, a1}}
                                                      : screen_pieces(p, a0, a1, span.whole);
        for (const auto& [sa, sb] : stretches) {
            std::vector<double> arcs, along;
            dash_measure(p, sa, sb, stroke.dash_on_surface, arcs, along);
            std::vector<glm::dvec2> q;
            for (const double a : arcs) q.push_back(p.at_arc(p.closed && p.length > 0.0 ? std::fmod(a, p.length) : a));
            const auto spans = dash_spans(arcs, along, stroke.dash, stroke.dash_on_surface ? p.u_period : 0.0);
            for (auto& piece : dash_pieces(q, arcs, spans)) out.push_back({simplify_polyline(piece, false, options.tolerance_px), false});
        }
        return;
    }
    if (stroke.needs_parameter()) {
        anim::Shape drawn;
        std::vector<StrokePoint> centre;
        const double step = p.length > 0.0 ? std::min(p.spacing, kMaxStrokeStepPx) / p.length : 1.0;
        if (span.whole) {
            for (double u = 0.0; u < 1.0; u += step) centre.push_back(p.stroke_at(u));
        } else {
            centre.push_back(p.stroke_at(span.u0));
            for (double u = (std::floor(span.u0 / step) + 1.0) * step; u < span.u1; u += step) centre.push_back(p.stroke_at(u));
            centre.push_back(p.stroke_at(span.u1));
        }
        weigh(stroke, std::move(centre), span.whole && p.closed, p.u_period, p.seconds, drawn);
        for (anim::Subpath& sp : drawn) {
            sp.pts = simplify_polyline(sp.pts, sp.closed, options.tolerance_px);
            out.push_back(std::move(sp));
        }
        return;
    }
    anim::Subpath sp;
    if (span.whole) {
        sp.pts = simplify_polyline(p.pts, p.closed, options.tolerance_px);
        sp.closed = p.closed;
        out.push_back(std::move(sp));
        return;
    }
    const double step = p.length > 0.0 ? p.spacing / p.length : 1.0;
    sp.pts.push_back(p.at(span.u0));
    for (double u = (std::floor(span.u0 / step) + 1.0) * step; u < span.u1; u += step) sp.pts.push_back(p.at(u));
    sp.pts.push_back(p.at(span.u1));
    sp.pts = simplify_polyline(sp.pts, false, options.tolerance_px);
    out.push_back(std::move(sp));
}

/// Frames made without a carried stroke parameter (by hand) take a
/// still's: contour @p c of every frame, parameterized as a still; none
/// when every frame carries one.
std::vector<DrawnContour> still_parameters(const std::vector<AnimationFrame>& frames, std::size_t c) {
    std::vector<DrawnContour> stills;
    const bool by_hand = std::any_of(frames.begin(), frames.end(), [&](const AnimationFrame& frame) {
        return std::any_of(frame.drawing.contours[c].loops.begin(), frame.drawing.contours[c].loops.end(),
                           [](const DrawnLoop& l) { return l.u.empty() && !l.q.empty(); });
    });
    if (!by_hand) return stills;
    stills.resize(frames.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        stills[f] = frames[f].drawing.contours[c];
        parameterize_still(stills[f]);
    }
    return stills;
}

/// The paths of contour @p c's brief contours (@p brief: per class, frame
/// -> the runs of its one-frame contours), into @p out.
void brief_paths(const std::map<int, anim::Shape> (&brief)[2], std::size_t c, std::vector<AnimatedPathData>& out) {
    // The brief contours' path: each frame's shape holds until the next
    // frame (nothing corresponds from one frame to the next); frames without
    // any draw a lone move.
    for (const int cls : {0, 1}) {
        if (brief[cls].empty()) continue;
        AnimatedPathData path;
        path.contour = c;
        path.cls = cls;
        path.brief = true;
        path.first = brief[cls].begin()->first;
        path.last = brief[cls].rbegin()->first;
        glm::dvec2 rest = brief[cls].begin()->second.front().pts.front();
        for (int f = path.first; f <= path.last; ++f) {
            const auto it = brief[cls].find(f);
            if (it == brief[cls].end() && f > path.first && brief[cls].count(f - 1) == 0) continue; // still empty
            const anim::Shape shape = it != brief[cls].end() ? it->second : anim::Shape{anim::Subpath{{rest}, false}};
            if (it != brief[cls].end()) rest = shape.front().pts.front();
            int until = f + 1; // the next frame whose shape differs
            while (until <= path.last && it == brief[cls].end() && brief[cls].count(until) == 0) ++until;
            PathSegment seg;
            seg.times.push_back(double(f));
            seg.shapes.push_back(shape);
            if (until <= path.last) {
                seg.times.push_back(double(until) - anim::kSwitch);
                seg.shapes.push_back(shape);
            }
            path.segments.push_back(std::move(seg));
        }
        out.push_back(std::move(path));
    }
}

} // namespace

void stroke_paths(const std::vector<AnimationFrame>& frames, std::size_t c, const Style& style,
                  const AnimatedSvgOptions& options, std::vector<AnimatedPathData>& out, const ChunkContext* chunk) {
    const DrawnContour& contour0 = frames[0].drawing.contours[c];
    const ContourStyle cs = style.contour(contour0.spec);
    const StrokeStyle* strokes[2] = {&cs.visible, &cs.hidden};
    // Strokes with line weight read each loop's stroke parameter (a still's
    // where the frames were made without one, by hand).
    const bool weighted = (cs.visible.draw && cs.visible.needs_parameter()) || (cs.hidden.draw && cs.hidden.needs_parameter());
    // Visibility flicker takes its neighbour's class only where both classes
    // are drawn: else it would draw ink where the static frame has none, or
    // leave out ink it has.
    const double flicker_px = cs.visible.draw && cs.hidden.draw ? options.min_run_px : 0.0;
    auto screen = [&](const StrokeStyle& st) {
        return st.draw && dashes_as_geometry(st, options.screen_dash_array) && !st.dash_on_surface;
    };
    const bool screen_dashes = screen(cs.visible) || screen(cs.hidden);
    const bool carried = (cs.visible.draw && cs.visible.carries_parameter()) || (cs.hidden.draw && cs.hidden.carries_parameter());
    const std::vector<DrawnContour> stills = carried ? still_parameters(frames, c) : std::vector<DrawnContour>{};
    std::map<std::uint64_t, std::vector<std::pair<int, std::size_t>>> by_sequence;
    for (std::size_t f = 0; f < frames.size(); ++f)
        for (std::size_t l = 0; l < frames[f].loops[c].size(); ++l)
            by_sequence[frames[f].loops[c][l].sequence].push_back({int(f), l});
    int next_run = 1;
    std::map<int, anim::Shape> brief[2]; // per class: frame -> the runs of one-frame contours
    for (const auto& entry : by_sequence) {
        const auto sequence = entry.first; // variables, so lambdas below may capture them
        const auto& members = entry.second;
        // A sequence's life: its frames, consecutive (a gap starts another life).
        for (std::size_t start = 0; start < members.size();) {
            std::size_t end = start + 1;
            while (end < members.size() && members[end].first == members[end - 1].first + 1) ++end;
            std::vector<ParamLoop> loops;
            loops.reserve(end - start);
            std::vector<LifeFrame> life;
            bool empty = false;
            for (std::size_t m = start; m < end; ++m) {
                const auto [f, l] = members[m];
                const DrawnLoop& dl = stills.empty() ? frames[f].drawing.contours[c].loops[l] : stills[f].loops[l];
                ParamLoop p = parameterize(dl, frames[f].loops[c][l], frames[f].drawing, weighted);
                if (p.pts.empty()) {
                    empty = true;
                    break;
                }
                const bool jump = !loops.empty() && abrupt(loops.back(), p);
                if (!loops.empty() && p.closed && p.length > 0.0) p.anchor = follow_anchor(loops.back(), p);
                p.spans = spans_of(p, dl, flicker_px);
                if (screen_dashes) p.restarts = restarts_of(p, dl);
                loops.push_back(std::move(p));
                LifeFrame lf;
                lf.jump = jump;
                life.push_back(std::move(lf));
            }
            const int first = members[start].first;
            const std::int32_t object = frames[members[start].first].drawing.contours[c].loops[members[start].second].object;
            start = end;
            if (empty) continue;
            if (chunk && life.size() == 1) {
                // A one-frame contour on a frame two chunks share: the next
                // chunk draws it (it may go on there), unless the chunk before
                // drew it (it ended there).
                if (chunk->defer_last && first + 1 == int(frames.size())) continue;
                if (first == 0 && chunk->drawn_first.count({c, sequence})) continue;
            }
            for (std::size_t i = 0; i < life.size(); ++i) {
                life[i].loop = &loops[i];
                for (const ClassSpan& s : loops[i].spans) life[i].runs[s.cls].push_back({0, s});
            }
            for (const int cls : {0, 1}) {
                const StrokeStyle& stroke = *strokes[cls];
                bool any = false;
                for (const LifeFrame& lf : life) any |= !lf.runs[cls].empty();
                if (!stroke.draw || !any) continue;
                track_runs(life, cls, next_run);
                const StrokeWriter writer(life, first, options);
                if (life.size() == 1) {
                    // A contour of one frame (mostly specks of a pixel or two):
                    // drawn by the kind's path of brief contours.
                    anim::Shape drawn; // may be empty: a run's dashes can all fall in gaps
                    for (const Run& r : life[0].runs[cls]) run_polyline(loops[0], r.span, stroke, options, drawn);
                    if (!drawn.empty()) {
                        anim::Shape& shape = brief[cls][first];
                        shape.insert(shape.end(), std::make_move_iterator(drawn.begin()), std::make_move_iterator(drawn.end()));
                    }
                    continue;
                }
                AnimatedPathData path;
                path.contour = c;
                path.cls = cls;
                path.first = first;
                path.last = first + int(life.size()) - 1;
                path.track = sequence;
                path.object = object;
                for (const Plan& plan : writer.plan(cls, 0, life.size() - 1, [](int) { return true; }))
                    path.segments.push_back(writer.emit(plan, stroke));
                out.push_back(std::move(path));
            }
        }
    }
    brief_paths(brief, c, out);
}

} // namespace snaxels
