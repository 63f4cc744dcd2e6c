#include "core/export/animated_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

#include "core/export/polyline.h"
#include "core/export/svg_writer.h"

namespace snaxels {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kMinLoopArea = 4.0; // square pixels: smaller fill loops are not animated
constexpr double kMaxFillSweepPx = 2.0; // how far a fill outline may stray between two frames

double wrap01(double u) { return u - std::floor(u); }

/// One loop of one frame, parameterized by arc length: u in [0, 1) runs
/// round the loop from an anchor that follows the snaxels' identities.
struct ParamLoop {
    int frame = 0;
    bool closed = true;
    std::vector<glm::dvec2> pts;
    std::vector<double> cum; ///< arc length at each point from point 0
    double length = 0.0;
    double anchor = 0.0;     ///< arc length where u = 0 (closed loops)
    double dash_phase = 0.0; ///< surface-fastened dash phase at point 0
    std::vector<std::uint64_t> ids;
    /// QI changes: (u, qi after it), sorted by u; `qi0` holds at u = 0.
    std::vector<std::pair<double, int>> changes;
    int qi0 = 0;

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
        // First cumulative length beyond arc.
        std::size_t k = std::size_t(std::upper_bound(cum.begin(), cum.end(), arc) - cum.begin());
        k = std::clamp<std::size_t>(k, 1, segs);
        const std::size_t i = k - 1, j = k % n;
        const double seg = (k < n ? cum[k] : length) - cum[i];
        const double t = seg > 0.0 ? std::clamp((arc - cum[i]) / seg, 0.0, 1.0) : 0.0;
        return (1.0 - t) * pts[i] + t * pts[j];
    }
    glm::dvec2 at(double u) const { return at_arc(arc_of_u(u)); }
};

/// A stretch of equal QI of one frame's loop: u in [u0, u1] (u1 may pass 1
/// on closed loops), or the whole loop.
struct Span {
    int qi = 0;
    bool whole = false;
    double u0 = 0.0, u1 = 1.0;
};

struct RunSequence {
    int qi = 0;
    bool whole = false, closed = false;
    std::vector<std::pair<const ParamLoop*, Span>> frames;
};

// Largest distance from a vertex of one polyline to the other, both ways.
// Vertex i of each corresponds roughly to vertex i of the other (same
// count, same parameterization), so only a window of segments around i is
// searched.
double shape_distance(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b, bool closed) {
    const std::int64_t n = std::int64_t(a.size());
    constexpr std::int64_t kWindow = 6;
    auto one_way = [&](const std::vector<glm::dvec2>& from, const std::vector<glm::dvec2>& to) {
        double worst = 0.0;
        for (std::int64_t i = 0; i < n; ++i) {
            double best = 1e300;
            for (std::int64_t k = i - kWindow; k < i + kWindow && best > 0.0; ++k) {
                std::int64_t s0 = k, s1 = k + 1;
                if (closed) {
                    s0 = ((s0 % n) + n) % n;
                    s1 = ((s1 % n) + n) % n;
                } else if (s0 < 0 || s1 >= n) {
                    continue;
                }
                best = std::min(best, point_segment(from[std::size_t(i)], to[std::size_t(s0)], to[std::size_t(s1)]));
            }
            if (n == 1) best = glm::length(from[0] - to[0]);
            worst = std::max(worst, best);
        }
        return worst;
    };
    return std::max(one_way(a, b), one_way(b, a));
}

// Keyframes to keep so that linear interpolation between them reproduces
// the shape of every in-between frame within `tol` (Douglas-Peucker over
// time; vertices may slide along the curve, the drawn line may not move).
void simplify_time(const std::vector<std::vector<glm::dvec2>>& frames, std::size_t i, std::size_t j,
                   double tol, bool closed, std::vector<std::uint8_t>& keep) {
    if (j <= i + 1) return;
    double worst = -1.0;
    std::size_t at = i;
    std::vector<glm::dvec2> interp(frames[i].size());
    for (std::size_t k = i + 1; k < j; ++k) {
        const double u = double(k - i) / double(j - i);
        for (std::size_t v = 0; v < interp.size(); ++v) interp[v] = (1.0 - u) * frames[i][v] + u * frames[j][v];
        const double d = shape_distance(interp, frames[k], closed);
        if (d > worst) worst = d, at = k;
    }
    if (worst <= tol) return;
    keep[at] = 1;
    simplify_time(frames, i, at, tol, closed, keep);
    simplify_time(frames, at, j, tol, closed, keep);
}

std::string key_time(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", std::clamp(t, 0.0, 1.0));
    return buf;
}

/// A path shown from the start of frame @p first to the end of frame @p last
/// of @p total: its display animation (discrete).
std::string display_animation(int first, int last, std::size_t total, const char* dur) {
    std::string times = first > 0 ? "0;" + key_time(double(first) / double(total)) : "0";
    std::string values = first > 0 ? "none;inline" : "inline";
    if (last + 1 < int(total)) {
        times += ";" + key_time(double(last + 1) / double(total));
        values += ";none";
    }
    return "<animate attributeName=\"display\" dur=\"" + std::string(dur) +
           "\" repeatCount=\"indefinite\" calcMode=\"discrete\" keyTimes=\"" + times + "\" values=\"" + values +
           "\"/>";
}

/// The linear animation of a path's d through its kept keyframes (@p key,
/// per sample; sample f is frame @p frame_of[f] of @p total); @p data(out,
/// f) appends sample f's path data. Before its first frame and after its
/// last the path holds its first and last shape.
template <class PathData>
std::string d_animation(const std::vector<std::uint8_t>& key, const std::vector<int>& frame_of, std::size_t total,
                        const char* dur, PathData&& data) {
    std::string times, values;
    auto add = [&](double t, std::size_t f) {
        if (!times.empty()) times += ';', values += ';';
        times += key_time(t);
        data(values, f);
    };
    if (frame_of.front() > 0) add(0.0, 0);
    for (std::size_t f = 0; f < key.size(); ++f)
        if (key[f]) add(double(frame_of[f]) / double(total), f);
    add(1.0, key.size() - 1);
    return "<animate attributeName=\"d\" dur=\"" + std::string(dur) +
           "\" repeatCount=\"indefinite\" calcMode=\"linear\" keyTimes=\"" + times + "\" values=\"" + values +
           "\"/>";
}

/// The rest of a `<path` element that animates: its first shape as d, its
/// display animation unless it shows all along (samples are frames
/// @p frame_of, up to frame @p last of @p total) and the d animation
/// through the kept keyframes @p key; leaves the element open for more
/// children. Returns the keyframes kept.
template <class PathData>
std::size_t append_path_animation(std::string& out, PathData&& path_data, const std::vector<std::uint8_t>& key,
                                  const std::vector<int>& frame_of, int last, std::size_t total, const char* dur) {
    const int first = frame_of.front();
    out += " d=\"";
    path_data(out, 0);
    out += "\"";
    const bool always = first == 0 && last + 1 == int(total);
    if (!always) out += " display=\"none\"";
    out += ">";
    if (!always) out += display_animation(first, last, total, dur);
    std::size_t kept = 0;
    for (const auto k : key) kept += k;
    if (kept > 1) out += d_animation(key, frame_of, total, dur, path_data);
    return kept;
}

// --- region fills ----------------------------------------------------------

/// Arc-length resampling of a closed loop into @p n points starting at arc
/// @p start.
std::vector<glm::dvec2> resample_loop(const std::vector<glm::dvec2>& loop, std::size_t n, double start) {
    std::vector<double> cum(loop.size() + 1, 0.0);
    for (std::size_t i = 0; i < loop.size(); ++i) cum[i + 1] = cum[i] + glm::length(loop[(i + 1) % loop.size()] - loop[i]);
    const double length = cum.back();
    std::vector<glm::dvec2> out;
    out.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
        double arc = length > 0.0 ? std::fmod(start + length * double(k) / double(n), length) : 0.0;
        std::size_t i = std::size_t(std::upper_bound(cum.begin(), cum.end(), arc) - cum.begin());
        i = std::clamp<std::size_t>(i, 1, loop.size()) - 1;
        const double seg = cum[i + 1] - cum[i];
        const double t = seg > 0.0 ? (arc - cum[i]) / seg : 0.0;
        out.push_back((1.0 - t) * loop[i] + t * loop[(i + 1) % loop.size()]);
    }
    return out;
}

double loop_length(const std::vector<glm::dvec2>& loop) {
    double l = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) l += glm::length(loop[(i + 1) % loop.size()] - loop[i]);
    return l;
}

glm::dvec2 loop_centroid(const std::vector<glm::dvec2>& loop) {
    glm::dvec2 c(0.0);
    for (const glm::dvec2& p : loop) c += p;
    return loop.empty() ? c : c / double(loop.size());
}

/// Arc length along @p loop to its vertex nearest @p p.
double arc_nearest(const std::vector<glm::dvec2>& loop, const glm::dvec2& p) {
    double best = 1e300, arc = 0.0, at = 0.0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const double d = glm::length(loop[i] - p);
        if (d < best) best = d, at = arc;
        arc += glm::length(loop[(i + 1) % loop.size()] - loop[i]);
    }
    return at;
}

struct RegionSample {
    int frame = 0;
    std::vector<std::vector<glm::dvec2>> loops;
};

/// One fill path for frames [i, j) of @p samples (same number of loops).
void emit_region(const std::vector<RegionSample>& samples, std::size_t i, std::size_t j, const RegionStyle& rs,
                 RegionClass cls, std::size_t total, const char* dur, double tolerance, std::string& out,
                 AnimatedSvgStats& stats) {
    const std::size_t frames = j - i, loops = samples[i].loops.size();
    // The loops in one order for every frame: the first frame's by size,
    // later ones matched to the nearest loop of the frame before.
    std::vector<std::vector<std::vector<glm::dvec2>>> ordered(frames);
    ordered[0] = samples[i].loops;
    std::sort(ordered[0].begin(), ordered[0].end(),
              [](const auto& a, const auto& b) { return loop_length(a) > loop_length(b); });
    for (std::size_t f = 1; f < frames; ++f) {
        std::vector<std::vector<glm::dvec2>> pool = samples[i + f].loops;
        for (std::size_t l = 0; l < loops; ++l) {
            const glm::dvec2 c = loop_centroid(ordered[f - 1][l]);
            std::size_t best = 0;
            for (std::size_t k = 1; k < pool.size(); ++k)
                if (glm::length(loop_centroid(pool[k]) - c) < glm::length(loop_centroid(pool[best]) - c)) best = k;
            ordered[f].push_back(std::move(pool[best]));
            pool.erase(pool.begin() + std::ptrdiff_t(best));
        }
    }
    // Each loop resampled at ~2 px from an anchor that follows it, then
    // thinned jointly over the frames (Douglas-Peucker) and keyframed.
    std::vector<std::vector<std::vector<glm::dvec2>>> kept(frames, std::vector<std::vector<glm::dvec2>>(loops));
    std::vector<std::uint8_t> cut(frames, 0);
    for (std::size_t l = 0; l < loops; ++l) {
        double longest = 0.0;
        for (std::size_t f = 0; f < frames; ++f) longest = std::max(longest, loop_length(ordered[f][l]));
        const std::size_t n = std::clamp<std::size_t>(std::size_t(std::ceil(longest / 2.0)), 8, 4096);
        std::vector<std::vector<glm::dvec2>> geom(frames);
        for (std::size_t f = 0; f < frames; ++f) {
            const auto& loop = ordered[f][l];
            double start = 0.0;
            if (f == 0) {
                std::size_t top = 0; // the top-left-most vertex
                for (std::size_t k = 1; k < loop.size(); ++k)
                    if (loop[k].x + loop[k].y < loop[top].x + loop[top].y) top = k;
                start = arc_nearest(loop, loop[top]);
            } else {
                start = arc_nearest(loop, geom[f - 1][0]);
            }
            geom[f] = resample_loop(loop, n, start);
        }
        // Linear interpolation between two frames must stay between their
        // outlines: where the half-way outline strays further than
        // kMaxFillSweepPx from both, the path is cut there.
        for (std::size_t f = 1; f < frames; ++f) {
            const auto& a = geom[f - 1];
            const auto& b = geom[f];
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
            if (worst > kMaxFillSweepPx) cut[f] = 1;
        }
        std::vector<std::uint8_t> keep(n, 0);
        keep[0] = keep[n / 2] = 1;
        douglas_peucker_joint(geom, 0, n / 2, tolerance, keep);
        douglas_peucker_joint(geom, n / 2, n, tolerance, keep);
        for (std::size_t f = 0; f < frames; ++f)
            for (std::size_t k = 0; k < n; ++k)
                if (keep[k]) kept[f][l].push_back(geom[f][k]);
    }
    if (std::find(cut.begin() + 1, cut.end(), std::uint8_t(1)) != cut.end()) {
        // Separate paths for the stretches between cuts.
        std::size_t from = 0;
        for (std::size_t f = 1; f <= frames; ++f)
            if (f == frames || cut[f]) {
                emit_region(samples, i + from, i + f, rs, cls, total, dur, tolerance, out, stats);
                from = f;
            }
        return;
    }
    std::vector<std::vector<glm::dvec2>> flat(frames); // every loop's points, for keyframing
    for (std::size_t f = 0; f < frames; ++f)
        for (const auto& loop : kept[f]) flat[f].insert(flat[f].end(), loop.begin(), loop.end());
    std::vector<std::uint8_t> key(frames, 0);
    key.front() = key.back() = 1;
    simplify_time(flat, 0, frames - 1, tolerance, false, key);
    auto path_data = [&](std::string& to, std::size_t f) {
        for (std::size_t l = 0; l < loops; ++l)
            svg::append_compact_path_data(to, kept[f][l], true, l ? kept[f][l - 1][0] : glm::dvec2(0.0));
    };
    const int last = samples[j - 1].frame;
    out += "<path class=\"region\" data-class=\"" + std::string(region_class_name(cls)) + "\" fill=\"" + rs.fill + "\"";
    if (rs.opacity < 1.0) {
        out += " fill-opacity=\"";
        svg::append_number(out, rs.opacity);
        out += "\"";
    }
    std::vector<int> frame_of;
    for (std::size_t f = i; f < j; ++f) frame_of.push_back(samples[f].frame);
    const std::size_t keyframes = append_path_animation(out, path_data, key, frame_of, last, total, dur);
    out += "</path>\n";
    ++stats.paths;
    stats.keyframes += keyframes;
    stats.frames_spanned += frames;
    stats.vertices += flat[0].size();
}

/// The fills of every region track: one path per run of frames in which
/// the track keeps its number of loops (after erosion).
void write_regions(const std::vector<AnimationFrame>& frames, double fps, const AnimatedSvgOptions& options,
                   const Style& style, std::string& out, AnimatedSvgStats& stats) {
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
    const std::size_t total = frames.size();
    char dur[32];
    std::snprintf(dur, sizeof dur, "%.6gs", double(total) / fps);
    out += "<g id=\"fills\" stroke=\"none\" fill-rule=\"nonzero\">\n";
    for (const std::uint64_t id : order) {
        const auto& track = tracks[id];
        const MapRegion& r0 = *track.front().second;
        const RegionStyle* rs = style.region(region_class_name(r0.cls), r0.k);
        if (!rs) continue;
        std::vector<RegionSample> samples;
        for (const auto& [f, region] : track) {
            RegionSample s{f, {}};
            // Loops under a few square pixels (specks, pinholes) are left
            // out: they would only break the path at every frame they blink.
            for (auto& loop : erode(region->polygons, rs->erosion)) {
                double twice_area = 0.0;
                for (std::size_t q = 0; q < loop.size(); ++q)
                    twice_area += loop[q].x * loop[(q + 1) % loop.size()].y - loop[(q + 1) % loop.size()].x * loop[q].y;
                if (loop.size() >= 3 && std::abs(twice_area) >= 2.0 * kMinLoopArea) s.loops.push_back(std::move(loop));
            }
            samples.push_back(std::move(s));
        }
        for (std::size_t i = 0; i < samples.size();) {
            std::size_t j = i + 1;
            while (j < samples.size() && samples[j].frame == samples[j - 1].frame + 1 &&
                   samples[j].loops.size() == samples[i].loops.size())
                ++j;
            if (!samples[i].loops.empty())
                emit_region(samples, i, j, *rs, r0.cls, total, dur, options.tolerance_px, out, stats);
            i = j;
        }
    }
    out += "</g>\n";
}

ParamLoop parameterize(int frame, const DrawnLoop& dl, const AnimatedLoop& al) {
    ParamLoop p;
    p.frame = frame;
    p.closed = dl.closed;
    p.dash_phase = dl.dash_phase;
    p.pts = dl.q;
    p.ids = al.ids;
    const std::size_t n = p.pts.size();
    p.cum.assign(n, 0.0);
    for (std::size_t k = 1; k < n; ++k) p.cum[k] = p.cum[k - 1] + glm::length(p.pts[k] - p.pts[k - 1]);
    p.length = n ? p.cum[n - 1] + (p.closed ? glm::length(p.pts[0] - p.pts[n - 1]) : 0.0) : 0.0;
    return p;
}

// QI changes in u, once the anchor is known: on the segment before each
// snaxel whose QI differs from its predecessor's, at the change point.
void locate_changes(ParamLoop& p, const DrawnLoop& dl) {
    if (dl.qi.empty()) return;
    const std::size_t n = p.pts.size();
    p.qi0 = dl.qi[0];
    for (std::size_t k = 0; k < n; ++k) {
        if (!p.closed && k == 0) continue;
        const std::size_t prev = (k + n - 1) % n;
        if (dl.qi[prev] == dl.qi[k]) continue;
        const glm::dvec2 a = p.pts[prev], b = p.pts[k], c = dl.change_before[k];
        const double seg = glm::length(b - a);
        const double t = seg > 0.0 ? std::clamp(glm::dot(c - a, b - a) / (seg * seg), 0.0, 1.0) : 0.0;
        const double arc = (k == 0 ? p.length - seg : p.cum[prev]) + t * seg;
        p.changes.push_back({p.u_of_arc(arc), dl.qi[k]});
    }
    std::sort(p.changes.begin(), p.changes.end());
    if (!p.changes.empty()) {
        // QI at u = 0 is the one after the last change before it (cyclically).
        if (p.closed) p.qi0 = p.changes.back().second;
        else p.qi0 = dl.qi[0];
    }
}

std::vector<Span> spans_of(const ParamLoop& p, double min_run_px) {
    std::vector<Span> spans;
    if (p.changes.empty()) {
        spans.push_back({p.qi0, p.closed, 0.0, 1.0});
        return spans;
    }
    if (p.closed) {
        for (std::size_t k = 0; k < p.changes.size(); ++k) {
            const double u0 = p.changes[k].first;
            const double u1 = k + 1 < p.changes.size() ? p.changes[k + 1].first : p.changes[0].first + 1.0;
            spans.push_back({p.changes[k].second, false, u0, u1});
        }
    } else {
        double u0 = 0.0;
        int qi = p.qi0;
        for (const auto& [u, after] : p.changes) {
            spans.push_back({qi, false, u0, u});
            u0 = u;
            qi = after;
        }
        spans.push_back({qi, false, u0, 1.0});
    }
    // Runs shorter than min_run_px are QI flicker (a grazing ray at a
    // T-junction) rather than lines a reader could see: they take the QI of
    // their longer neighbour, and equal neighbours join.
    const double min_u = p.length > 0.0 ? min_run_px / p.length : 0.0;
    for (;;) {
        if (spans.size() < 2) break;
        std::size_t shortest = 0;
        for (std::size_t k = 1; k < spans.size(); ++k)
            if (spans[k].u1 - spans[k].u0 < spans[shortest].u1 - spans[shortest].u0) shortest = k;
        if (spans[shortest].u1 - spans[shortest].u0 >= min_u) break;
        const std::size_t n = spans.size();
        const bool has_prev = p.closed || shortest > 0, has_next = p.closed || shortest + 1 < n;
        const std::size_t prev = (shortest + n - 1) % n, next = (shortest + 1) % n;
        const double lp = has_prev ? spans[prev].u1 - spans[prev].u0 : -1.0;
        const double ln = has_next ? spans[next].u1 - spans[next].u0 : -1.0;
        spans[shortest].qi = lp >= ln ? spans[prev].qi : spans[next].qi;
        // Coalesce equal neighbours (cyclically on closed loops).
        std::vector<Span> merged;
        for (const Span& sp : spans) {
            if (!merged.empty() && merged.back().qi == sp.qi) merged.back().u1 = sp.u1;
            else merged.push_back(sp);
        }
        if (p.closed && merged.size() > 1 && merged.front().qi == merged.back().qi) {
            merged.back().u1 = merged.front().u1 + 1.0;
            merged.erase(merged.begin());
        }
        if (merged.size() == 1 && p.closed) merged[0] = {merged[0].qi, true, 0.0, 1.0};
        spans = std::move(merged);
    }
    return spans;
}

// How much of span `s` overlaps the last span of a run (circular in u for
// closed loops); 0 when QI or kind differ.
double overlap(const RunSequence& rs, const Span& s) {
    if (rs.qi != s.qi || rs.whole != s.whole) return 0.0;
    if (s.whole) return 1.0;
    const Span& last = rs.frames.back().second;
    double best = 0.0;
    for (const double shift : {-1.0, 0.0, 1.0})
        best = std::max(best, std::min(last.u1, s.u1 + shift) - std::max(last.u0, s.u0 + shift));
    return best;
}

void align(const RunSequence& rs, Span& s) {
    if (s.whole) return;
    const Span& last = rs.frames.back().second;
    double best = -1e9, shift_best = 0.0;
    for (const double shift : {-1.0, 0.0, 1.0}) {
        const double o = std::min(last.u1, s.u1 + shift) - std::max(last.u0, s.u0 + shift);
        if (o > best) best = o, shift_best = shift;
    }
    s.u0 += shift_best;
    s.u1 += shift_best;
}

class Writer {
  public:
    Writer(const std::vector<AnimationFrame>& frames, double fps, const AnimatedSvgOptions& options,
           const Style& style, AnimatedSvgStats& stats)
        : frames_(frames), fps_(fps), options_(options), style_(style), stats_(stats) {}

    void contour(std::size_t c, std::string& hidden_out, std::string& visible_out) {
        const ContourStyle cs = style_.contour(frames_[0].drawing.contours[c].spec);
        visible_stroke_ = cs.visible;
        hidden_stroke_ = cs.hidden;
        std::map<std::uint64_t, std::vector<std::pair<int, std::size_t>>> by_sequence;
        for (std::size_t f = 0; f < frames_.size(); ++f)
            for (std::size_t l = 0; l < frames_[f].loops[c].size(); ++l)
                by_sequence[frames_[f].loops[c][l].sequence].push_back({int(f), l});
        for (auto& [seq, members] : by_sequence) {
            // A sequence is cut where its loop opens or closes (the path's
            // commands would change) or skips a frame.
            std::size_t start = 0;
            for (std::size_t k = 1; k <= members.size(); ++k) {
                const bool cut = k == members.size() || loop(c, members[k]).closed != loop(c, members[start]).closed ||
                                 members[k].first != members[k - 1].first + 1;
                if (!cut) continue;
                sequence(c, std::vector(members.begin() + long(start), members.begin() + long(k)),
                         hidden_out, visible_out);
                start = k;
            }
        }
    }

  private:
    const DrawnLoop& loop(std::size_t c, const std::pair<int, std::size_t>& m) const {
        return frames_[m.first].drawing.contours[c].loops[m.second];
    }

    void sequence(std::size_t c, const std::vector<std::pair<int, std::size_t>>& members,
                  std::string& hidden_out, std::string& visible_out) {
        // 1. Each frame's loop by arc length, u = 0 carried along by the
        // identities the frame shares with the one before.
        std::vector<ParamLoop> pl;
        pl.reserve(members.size());
        for (const auto& m : members) {
            ParamLoop p = parameterize(m.first, loop(c, m), frames_[m.first].loops[c][m.second]);
            if (p.pts.empty()) return;
            if (!pl.empty() && p.closed && p.length > 0.0) p.anchor = follow_anchor(pl.back(), p);
            locate_changes(p, loop(c, m));
            pl.push_back(std::move(p));
        }
        // 2. Abrupt changes (a loop absorbing or shedding a large piece, most
        // of its snaxels replaced) are hard cuts: interpolating across them
        // would sweep the line through places it never is.
        std::size_t start = 0;
        for (std::size_t k = 1; k <= pl.size(); ++k)
            if (k == pl.size() || abrupt(pl[k - 1], pl[k])) {
                stretch(pl, start, k, hidden_out, visible_out);
                start = k;
            }
    }

    // A run whose end moves along a bend of the curve is cut rather than
    // interpolated: its path would fold the stretch it lost (or gained)
    // along a straight line between frames, sweeping across places the
    // contour never is. Along straight stretches the fold is harmless.
    bool ends_glide(const RunSequence& rs, Span span, const ParamLoop& p) const {
        if (span.whole) return true;
        align(rs, span);
        const Span& last = rs.frames.back().second;
        const ParamLoop& q = *rs.frames.back().first;
        auto bend = [](const ParamLoop& loop, double ua, double ub) {
            const glm::dvec2 a = loop.at(ua), b = loop.at(ub);
            double worst = 0.0;
            for (int k = 1; k < 16; ++k) worst = std::max(worst, point_segment(loop.at(ua + (ub - ua) * k / 16.0), a, b));
            return worst;
        };
        double worst = 0.0;
        for (const auto& [from, to] : {std::pair{last.u0, span.u0}, std::pair{last.u1, span.u1}})
            worst = std::max({worst, bend(q, from, to), bend(p, from, to)});
        return worst <= options_.max_sweep_px;
    }

    // Surface-fastened dashes: the dash phase where the path starts, per
    // frame (unwrapped so it interpolates), animated on stroke-dashoffset.
    std::string dash_offset_animation(const RunSequence& rs, const StrokeStyle& stroke, bool closed_path, int first,
                                      const char* dur) const {
        double period = 0.0;
        for (const double d : stroke.dash) period += d;
        if (period <= 0.0) return {};
        std::vector<std::vector<glm::dvec2>> offsets; // 1-D values as points, for simplify_time
        double previous = 0.0;
        for (std::size_t f = 0; f < rs.frames.size(); ++f) {
            const ParamLoop& p = *rs.frames[f].first;
            const double start = p.arc_of_u(closed_path ? 0.0 : rs.frames[f].second.u0);
            double o = std::fmod(p.dash_phase + start, period);
            if (f > 0) o += period * std::round((previous - o) / period);
            previous = o;
            offsets.push_back({glm::dvec2(o, 0.0)});
        }
        std::vector<std::uint8_t> key(offsets.size(), 0);
        key.front() = key.back() = 1;
        simplify_time(offsets, 0, offsets.size() - 1, options_.tolerance_px, false, key);
        const std::size_t total = frames_.size();
        std::string times, values;
        auto add = [&](double t, double v) {
            if (!times.empty()) times += ';', values += ';';
            times += key_time(t);
            svg::append_number(values, v);
        };
        if (first > 0) add(0.0, offsets.front()[0].x);
        for (std::size_t f = 0; f < offsets.size(); ++f)
            if (key[f]) add(double(rs.frames[f].first->frame) / double(total), offsets[f][0].x);
        add(1.0, offsets.back()[0].x);
        return "<animate attributeName=\"stroke-dashoffset\" dur=\"" + std::string(dur) +
               "\" repeatCount=\"indefinite\" calcMode=\"linear\" keyTimes=\"" + times + "\" values=\"" + values + "\"/>";
    }

    static bool abrupt(const ParamLoop& a, const ParamLoop& b) {
        const double dl = std::abs(b.length - a.length);
        if (dl > 0.1 * std::max(a.length, b.length) && dl > 10.0) return true;
        std::unordered_map<std::uint64_t, char> ids;
        for (const auto id : a.ids) ids[id] = 1;
        std::size_t shared = 0;
        for (const auto id : b.ids) shared += ids.count(id);
        return 2 * shared < std::min(a.ids.size(), b.ids.size());
    }

    void stretch(const std::vector<ParamLoop>& pl, std::size_t from, std::size_t to, std::string& hidden_out,
                 std::string& visible_out) {
        // Runs of equal QI, followed from frame to frame by their overlap in u.
        std::vector<RunSequence> runs;
        std::vector<std::size_t> live;
        for (std::size_t i = from; i < to; ++i) {
            const ParamLoop& p = pl[i];
            const std::vector<Span> spans = spans_of(p, options_.min_run_px);
            std::vector<std::int64_t> best_run(spans.size(), -1);
            std::vector<double> best_overlap(spans.size(), 0.0);
            std::map<std::size_t, std::pair<double, std::size_t>> run_best;
            for (std::size_t s = 0; s < spans.size(); ++s)
                for (const std::size_t r : live) {
                    const double o = overlap(runs[r], spans[s]);
                    if (o <= 0.0) continue;
                    if (o > best_overlap[s]) best_overlap[s] = o, best_run[s] = std::int64_t(r);
                    auto& rb = run_best[r];
                    if (o > rb.first) rb = {o, s};
                }
            std::vector<std::size_t> next_live;
            for (std::size_t s = 0; s < spans.size(); ++s) {
                Span span = spans[s];
                if (best_run[s] >= 0 && run_best[std::size_t(best_run[s])].second == s &&
                    ends_glide(runs[std::size_t(best_run[s])], span, p)) {
                    RunSequence& rs = runs[std::size_t(best_run[s])];
                    align(rs, span);
                    rs.frames.push_back({&p, span});
                    next_live.push_back(std::size_t(best_run[s]));
                } else {
                    runs.push_back({span.qi, span.whole, p.closed, {{&p, span}}});
                    next_live.push_back(runs.size() - 1);
                }
            }
            live = std::move(next_live);
        }
        // Long runs go out in chunks: a path's vertices must serve every frame
        // it spans, so a shorter span needs fewer. Each chunk also holds the
        // next chunk's first frame, which it animates toward but does not
        // show, so motion stays interpolated across the handover.
        for (const RunSequence& rs : runs) {
            std::string& out = rs.qi > 0 ? hidden_out : visible_out;
            const StrokeStyle& stroke = rs.qi > 0 ? hidden_stroke_ : visible_stroke_;
            if (!stroke.draw) continue;
            const std::size_t chunk = std::max<std::size_t>(2, options_.max_chunk_frames);
            for (std::size_t a = 0;; a += chunk) {
                RunSequence part = rs;
                const std::size_t b = std::min(rs.frames.size(), a + chunk + 1);
                part.frames.assign(rs.frames.begin() + long(a), rs.frames.begin() + long(b));
                emit(part, out, b < rs.frames.size(), stroke);
                if (b >= rs.frames.size()) break;
            }
        }
    }

    // Where u = 0 goes in `cur`: every shared identity votes for an anchor
    // that keeps its u from the previous frame; the votes are averaged on the
    // circle. Without shared identities, the nearest point to the old anchor.
    static double follow_anchor(const ParamLoop& prev, const ParamLoop& cur) {
        std::unordered_map<std::uint64_t, std::size_t> prev_index;
        for (std::size_t k = 0; k < prev.ids.size(); ++k) prev_index[prev.ids[k]] = k;
        double sx = 0.0, sy = 0.0;
        std::size_t votes = 0;
        for (std::size_t k = 0; k < cur.ids.size(); ++k) {
            const auto it = prev_index.find(cur.ids[k]);
            if (it == prev_index.end()) continue;
            const double u_prev = prev.u_of_arc(prev.cum[it->second]);
            const double anchor = cur.cum[k] - u_prev * cur.length;
            const double angle = kTwoPi * anchor / cur.length;
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

    /// @p handover: the last frame belongs to the next chunk (animate toward
    /// it, but stop showing this path when it begins).
    void emit(const RunSequence& rs, std::string& out, bool handover, const StrokeStyle& stroke) {
        const double smoothing = stroke.smoothing;
        // Vertices sit on a grid fixed in u for the whole run, at the loops'
        // own sampling density (their snaxel spacing), so they glide with the
        // curve from frame to frame; grid points outside a frame's span fold
        // onto its ends, so only the ends move when the run grows or shrinks.
        double total_length = 0.0, longest = 0.0;
        std::size_t segments = 0;
        double lo = 1e300, hi = -1e300;
        for (const auto& [p, span] : rs.frames) {
            total_length += p->length;
            longest = std::max(longest, p->length);
            segments += p->closed ? p->pts.size() : p->pts.size() - 1;
            lo = std::min(lo, span.u0);
            hi = std::max(hi, span.u1);
        }
        const double spacing = std::max(segments ? total_length / double(segments) : 1.0, 0.5);
        const std::size_t grid = std::clamp<std::size_t>(std::size_t(std::ceil(longest / spacing)), 3, 200000);
        const bool closed_path = rs.whole && rs.closed;
        std::vector<double> grid_u; // the u of every path vertex but the two ends
        if (closed_path) {
            for (std::size_t k = 0; k < grid; ++k) grid_u.push_back(double(k) / double(grid));
        } else {
            for (auto k = std::int64_t(std::ceil(lo * double(grid))); double(k) < hi * double(grid); ++k)
                grid_u.push_back(double(k) / double(grid));
        }
        const std::size_t n = closed_path ? grid_u.size() : grid_u.size() + 2;
        std::vector<std::vector<glm::dvec2>> geom;
        geom.reserve(rs.frames.size());
        for (const auto& [p, span] : rs.frames) {
            std::vector<glm::dvec2> g;
            g.reserve(n);
            if (closed_path) {
                for (const double u : grid_u) g.push_back(p->at(u));
            } else {
                const glm::dvec2 start = p->at(span.u0), end = p->at(span.u1);
                g.push_back(start);
                for (const double u : grid_u) g.push_back(u <= span.u0 ? start : u >= span.u1 ? end : p->at(u));
                g.push_back(end);
            }
            geom.push_back(std::move(g));
        }
        // Vertices kept for every frame: Bézier knots when the stroke is
        // smoothed, else the joint Douglas-Peucker of the polyline.
        std::vector<std::uint8_t> keep(n, 0);
        if (smoothing > 0.0) {
            for (const std::size_t k : fit_knots(geom, closed_path, std::max(smoothing, options_.tolerance_px))) keep[k] = 1;
        } else if (closed_path) {
            // A ring: two chains, from vertex 0 half way round and back to 0.
            const std::size_t half = n / 2;
            keep[0] = keep[half] = 1;
            douglas_peucker_joint(geom, 0, half, options_.tolerance_px, keep);
            douglas_peucker_joint(geom, half, n, options_.tolerance_px, keep);
        } else {
            keep[0] = keep[n - 1] = 1;
            douglas_peucker_joint(geom, 0, n - 1, options_.tolerance_px, keep);
        }
        std::vector<std::size_t> knots;
        for (std::size_t k = 0; k < n; ++k)
            if (keep[k]) knots.push_back(k);
        std::vector<std::vector<glm::dvec2>> reduced(geom.size());
        for (std::size_t f = 0; f < geom.size(); ++f)
            for (const std::size_t k : knots) reduced[f].push_back(geom[f][k]);
        if (reduced[0].size() < 2) return;
        auto path_data = [&](std::string& to, std::size_t f) {
            if (smoothing > 0.0) svg::append_compact_chain_data(to, bezier_chain(geom[f], knots, closed_path));
            else svg::append_compact_path_data(to, reduced[f], closed_path);
        };

        std::vector<std::uint8_t> key(reduced.size(), 0);
        key.front() = key.back() = 1;
        simplify_time(reduced, 0, reduced.size() - 1, options_.tolerance_px, closed_path, key);

        const std::size_t total = frames_.size();
        const int first = rs.frames.front().first->frame;
        const int last = rs.frames.back().first->frame - (handover ? 1 : 0); // the last frame shown
        char dur[32];
        std::snprintf(dur, sizeof dur, "%.6gs", double(total) / fps_);

        out += "<path";
        std::vector<int> frame_of;
        for (const auto& fr : rs.frames) frame_of.push_back(fr.first->frame);
        const std::size_t kept = append_path_animation(out, path_data, key, frame_of, last, total, dur);
        if (stroke.dash_on_surface) out += dash_offset_animation(rs, stroke, closed_path, first, dur);
        out += "</path>\n";
        ++stats_.paths;
        stats_.keyframes += kept;
        stats_.frames_spanned += rs.frames.size() - (handover ? 1 : 0);
        stats_.vertices += reduced[0].size();
    }

    const std::vector<AnimationFrame>& frames_;
    double fps_;
    AnimatedSvgOptions options_;
    const Style& style_;
    StrokeStyle visible_stroke_, hidden_stroke_;
    AnimatedSvgStats& stats_;
};

} // namespace

std::string to_animated_svg(const std::vector<AnimationFrame>& frames, double fps, const AnimatedSvgOptions& options,
                            const Style& style, AnimatedSvgStats* stats) {
    AnimatedSvgStats local;
    AnimatedSvgStats& st = stats ? *stats : local;
    st = {};
    if (frames.empty()) return svg::document_start(16, 16, style.background) + "</svg>\n";
    const Drawing& d0 = frames[0].drawing;
    std::string out = svg::document_start(d0.width, d0.height, style.background);
    bool with_visibility = false;
    for (const AnimationFrame& f : frames)
        for (const DrawnContour& c : f.drawing.contours)
            for (const DrawnLoop& loop : c.loops) with_visibility |= !loop.qi.empty();
    write_regions(frames, fps, options, style, out, st);
    Writer writer(frames, fps, options, style, st);
    std::vector<std::string> hidden(d0.contours.size()), visible(d0.contours.size());
    for (std::size_t c = 0; c < d0.contours.size(); ++c) writer.contour(c, hidden[c], visible[c]);
    for (const bool is_hidden : {true, false}) {
        if (is_hidden && !with_visibility) continue;
        out += is_hidden ? "<g id=\"hidden\">\n" : "<g id=\"visible\">\n";
        for (std::size_t c = 0; c < d0.contours.size(); ++c) {
            const ContourStyle cs = style.contour(d0.contours[c].spec);
            const StrokeStyle& stroke = is_hidden ? cs.hidden : cs.visible;
            if (!stroke.draw) continue;
            out += svg::kind_group(d0.contours[c].spec, stroke) + (is_hidden ? hidden[c] : visible[c]) + "</g>\n";
        }
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

} // namespace snaxels
