// The animated strokes' shapes: a path's keys planned over a sequence's
// life and shaped (the runs as polylines, with line weight, as dashes
// fastened to the screen or the surface), and a one-frame contour's runs
// shaped the same way.
#include "snaxels/export/detail/stroke_writer.h"

#include "snaxels/export/detail/path_keys.h"
#include "snaxels/export/stroke_dashes.h"
#include "snaxels/export/detail/polyline.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels::detail {
namespace {

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
    StrokeShape shape = stroke_shape(stroke, std::move(centre), closed, period, seconds);
    if (!stroke.variable_width()) {
        anim::Subpath sp;
        sp.closed = closed;
        for (const StrokePoint& p : shape.centre) sp.pts.push_back(p.q);
        out.push_back(std::move(sp));
        return;
    }
    for (auto& poly : shape.outlines) out.push_back({std::move(poly), true});
}

/// Whether two frames have the same runs (by id; both sorted by id).
bool same_runs(const std::vector<Run>& a, const std::vector<Run>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const Run& x, const Run& y) { return x.id == y.id; });
}

} // namespace

std::vector<StrokeWriter::Range> StrokeWriter::ranges_of(const std::vector<std::vector<Run>>& runs, std::size_t a, std::size_t b) const {
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

Plan StrokeWriter::plan_of(const std::vector<std::vector<Run>>& runs, std::size_t a, const Range& rg) const {
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

PathSegment StrokeWriter::emit(const Plan& plan, const StrokeStyle& stroke) const {
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

anim::Shape StrokeWriter::weighed_shape(const Plan& plan, const Key& k, const anim::Shape& shape,
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

std::vector<StrokeWriter::KeyDash> StrokeWriter::key_dashes(const Key& k, std::size_t j, bool ring, const StrokeStyle& stroke) const {
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

std::vector<StrokeWriter::KeyDash> StrokeWriter::key_dashes_over(const ParamLoop& w, double a0, double a1, const StrokeStyle& stroke) const {
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

anim::Shape StrokeWriter::dash_shape(const Plan& plan, const Key& k, const anim::Shape& shape,
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

bool StrokeWriter::glides(const std::vector<Run>& from, const std::vector<Run>& to, std::size_t i) const {
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
        const ClassSpan a = x ? *x : ClassSpan{StrokeClass::Visible, false, c, c};
        const ClassSpan b = y ? *y : ClassSpan{StrokeClass::Visible, false, c, c};
        for (const auto& [ua, ub] : {std::pair{a.u0, b.u0}, std::pair{a.u1, b.u1}})
            if (std::max(bend(p, ua, ub), bend(q, ua, ub)) > options_.max_sweep_px) return false;
    }
    return true;
}

Plan StrokeWriter::transition(const std::vector<Run>& from, const std::vector<Run>& to, std::size_t i) const {
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
                if (!r) return ClassSpan{StrokeClass::Visible, false, c, c};
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

} // namespace snaxels::detail
