#include "snaxels/export/detail/animated_strokes.h"
#include "snaxels/export/detail/stroke_writer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <unordered_map>

#include "snaxels/export/detail/animated_paths.h"
#include "snaxels/export/detail/path_keys.h"
#include "snaxels/export/detail/polyline.h"
#include "snaxels/export/stroke_dashes.h"
#include "snaxels/export/stroke_parameter.h"
#include "snaxels/export/stroke_weight.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

std::vector<ClassSpan> class_spans(const std::vector<std::pair<double, StrokeClass>>& changes, StrokeClass cls0, bool closed,
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
        StrokeClass cls = cls0;
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

using namespace detail;

constexpr double kTwoPi = 6.283185307179586;

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
    if (dl.qi.empty()) return {{StrokeClass::Visible, p.closed, 0.0, 1.0}}; // no visibility: visible
    const std::size_t n = p.pts.size();
    auto cls = [&](std::size_t k) { return stroke_class(dl.qi[k]); };
    std::vector<std::pair<double, StrokeClass>> changes;
    for (std::size_t k = 0; k < n; ++k) {
        if (!p.closed && k == 0) continue;
        const std::size_t prev = (k + n - 1) % n;
        if (cls(prev) == cls(k)) continue;
        changes.push_back({p.u_of_arc(change_arc(p, dl, k)), cls(k)});
    }
    std::sort(changes.begin(), changes.end());
    // The class at u = 0: after the last change before it (cyclically).
    const StrokeClass cls0 = p.closed && !changes.empty() ? changes.back().second : cls(0);
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
void track_runs(std::vector<LifeFrame>& life, StrokeClass cls, int& next_id) {
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
void brief_paths(const ByClass<std::map<int, anim::Shape>>& brief, std::size_t c, std::vector<AnimatedPathData>& out) {
    // The brief contours' path: each frame's shape holds until the next
    // frame (nothing corresponds from one frame to the next); frames without
    // any draw a lone move.
    for (const StrokeClass cls : kDrawnClasses) {
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
    const ByClass<const StrokeStyle*> strokes{{&cs.visible, &cs.hidden, nullptr}}; // nothing draws what is left out
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
    ByClass<std::map<int, anim::Shape>> brief; // per class: frame -> the runs of one-frame contours
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
            for (const StrokeClass cls : kDrawnClasses) {
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
