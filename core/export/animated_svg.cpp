#include "core/export/animated_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <list>
#include <map>
#include <unordered_map>

#include "core/export/svg_writer.h"

namespace snaxels {
namespace {

constexpr std::int64_t kNoGap = -1;

/// One loop of one frame, in the sequence's master vertex order.
struct MasterFrame {
    int frame = 0;
    std::vector<glm::dvec2> pos;   ///< per master vertex
    std::vector<int> qi;           ///< per master vertex
    std::map<std::int64_t, glm::dvec2> change; ///< gap g (before master vertex g) -> change point
};

/// A stretch of equal QI in master space at one frame: vertices [a, b)
/// (unwrapped: indices taken modulo the master size), or the whole loop.
struct RunSpan {
    int qi = 0;
    bool whole = false;
    std::int64_t a = 0, b = 0;
    glm::dvec2 start{0.0}, end{0.0};
};

struct RunSequence {
    int qi = 0;
    bool whole = false, closed = false;
    std::int64_t a = 0, b = 0; ///< union of the spans
    std::vector<std::pair<const MasterFrame*, RunSpan>> frames;
};

double point_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

// Vertices to keep so that, in every frame, the polyline through them stays
// within `tol` of the full one (Douglas-Peucker over all frames at once).
void simplify_joint(const std::vector<std::vector<glm::dvec2>>& frames, std::size_t i, std::size_t j,
                    double tol, std::vector<std::uint8_t>& keep) {
    if (j <= i + 1) return;
    double worst = -1.0;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
        double d = 0.0;
        for (const auto& f : frames) d = std::max(d, point_segment(f[k], f[i], f[j]));
        if (d > worst) {
            worst = d;
            at = k;
        }
    }
    if (worst <= tol) return;
    keep[at] = 1;
    simplify_joint(frames, i, at, tol, keep);
    simplify_joint(frames, at, j, tol, keep);
}

// Keyframes to keep so that linear interpolation between them reproduces
// every frame within `tol` (Douglas-Peucker over time).
void simplify_time(const std::vector<std::vector<glm::dvec2>>& frames, std::size_t i, std::size_t j,
                   double tol, std::vector<std::uint8_t>& keep) {
    if (j <= i + 1) return;
    double worst = -1.0;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
        const double u = double(k - i) / double(j - i);
        double d = 0.0;
        for (std::size_t v = 0; v < frames[k].size(); ++v)
            d = std::max(d, glm::length(frames[k][v] - ((1.0 - u) * frames[i][v] + u * frames[j][v])));
        if (d > worst) {
            worst = d;
            at = k;
        }
    }
    if (worst <= tol) return;
    keep[at] = 1;
    simplify_time(frames, i, at, tol, keep);
    simplify_time(frames, at, j, tol, keep);
}

std::string key_time(double t) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", std::clamp(t, 0.0, 1.0));
    return buf;
}

class Writer {
  public:
    Writer(const std::vector<AnimationFrame>& frames, double fps, const AnimatedSvgOptions& options,
           AnimatedSvgStats& stats)
        : frames_(frames), fps_(fps), options_(options), stats_(stats) {}

    /// Paths of contour kind `c`, split by visibility into the two outputs.
    void contour(std::size_t c, std::string& hidden_out, std::string& visible_out) {
        // Loops by sequence, and sequences cut where a loop opens or closes.
        std::map<std::uint64_t, std::vector<std::pair<int, std::size_t>>> by_sequence;
        for (std::size_t f = 0; f < frames_.size(); ++f)
            for (std::size_t l = 0; l < frames_[f].loops[c].size(); ++l)
                by_sequence[frames_[f].loops[c][l].sequence].push_back({int(f), l});
        for (auto& [seq, members] : by_sequence) {
            std::size_t start = 0;
            for (std::size_t k = 1; k <= members.size(); ++k) {
                const bool cut = k == members.size() ||
                                 loop(c, members[k]).closed != loop(c, members[start]).closed ||
                                 members[k].first != members[k - 1].first + 1;
                if (!cut) continue;
                bounded(c, std::vector(members.begin() + long(start), members.begin() + long(k)),
                        hidden_out, visible_out);
                start = k;
            }
        }
    }

  private:
    // Snaxels slide and are replaced as a contour travels, so the identities
    // a long sequence collects outgrow any one frame; its path then carries
    // vertices that are mostly folded away. Cut it into segments whose
    // identities stay within a margin of the largest frame's count; a cut
    // is seamless (the next segment starts from the same geometry).
    void bounded(std::size_t c, const std::vector<std::pair<int, std::size_t>>& members,
                 std::string& hidden_out, std::string& visible_out) {
        constexpr double kGrowth = 1.3;
        std::size_t start = 0, largest = 0;
        std::unordered_map<std::uint64_t, char> seen;
        for (std::size_t k = 0; k < members.size(); ++k) {
            const auto& id = ids(c, members[k]).ids;
            std::size_t fresh = 0;
            for (const auto i : id) fresh += !seen.count(i);
            const std::size_t grown = seen.size() + fresh, biggest = std::max(largest, id.size());
            if (k > start && double(grown) > kGrowth * double(biggest) + 8) {
                sequence(c, std::vector(members.begin() + long(start), members.begin() + long(k)),
                         hidden_out, visible_out);
                start = k;
                seen.clear();
                largest = 0;
            }
            for (const auto i : id) seen[i] = 1;
            largest = std::max(largest, id.size());
        }
        sequence(c, std::vector(members.begin() + long(start), members.end()), hidden_out, visible_out);
    }

    const DrawnLoop& loop(std::size_t c, const std::pair<int, std::size_t>& m) const {
        return frames_[m.first].drawing.contours[c].loops[m.second];
    }
    const AnimatedLoop& ids(std::size_t c, const std::pair<int, std::size_t>& m) const {
        return frames_[m.first].loops[c][m.second];
    }

    void sequence(std::size_t c, const std::vector<std::pair<int, std::size_t>>& members,
                  std::string& hidden_out, std::string& visible_out) {
        const bool closed = loop(c, members[0]).closed;
        // 1. Master order: every identity the sequence ever has, each new one
        // placed after its predecessor along the loop in the frame it appears.
        std::list<std::uint64_t> order;
        std::unordered_map<std::uint64_t, std::list<std::uint64_t>::iterator> where;
        for (const auto& m : members) {
            const auto& id = ids(c, m).ids;
            const std::size_t n = id.size();
            for (std::size_t k = 0; k < n; ++k) {
                if (where.count(id[k])) continue;
                auto at = order.begin();
                bool placed = false;
                for (std::size_t back = 1; back <= n && (closed || back <= k); ++back) {
                    const auto it = where.find(id[(k + n - back) % n]);
                    if (it != where.end()) {
                        at = std::next(it->second);
                        placed = true;
                        break;
                    }
                }
                if (!placed) at = order.begin();
                where[id[k]] = order.insert(at, id[k]);
            }
        }
        const std::vector<std::uint64_t> master(order.begin(), order.end());
        const std::int64_t m = std::int64_t(master.size());
        if (m < 2) return;
        std::unordered_map<std::uint64_t, std::int64_t> index;
        for (std::int64_t i = 0; i < m; ++i) index[master[i]] = i;

        // 2. Every frame in master order; the absent sit on their predecessor.
        std::vector<MasterFrame> mf(members.size());
        for (std::size_t f = 0; f < members.size(); ++f) {
            const DrawnLoop& dl = loop(c, members[f]);
            const auto& id = ids(c, members[f]).ids;
            MasterFrame& out = mf[f];
            out.frame = members[f].first;
            out.pos.assign(m, glm::dvec2(0.0));
            out.qi.assign(m, 0);
            std::vector<std::uint8_t> alive(m, 0);
            for (std::size_t k = 0; k < id.size(); ++k) {
                const std::int64_t i = index[id[k]];
                alive[i] = 1;
                out.pos[i] = dl.q[k];
                if (!dl.qi.empty()) {
                    out.qi[i] = dl.qi[k];
                    const int prev = dl.qi[(k + id.size() - 1) % id.size()];
                    if ((closed || k > 0) && prev != dl.qi[k]) out.change[i] = dl.change_before[k];
                }
            }
            std::int64_t first = 0;
            while (first < m && !alive[first]) ++first;
            for (std::int64_t i = 0; i < first; ++i) out.pos[i] = out.pos[first], out.qi[i] = out.qi[first];
            for (std::int64_t s = 1; s < m; ++s) {
                const std::int64_t i = (first + s) % m, p = (i + m - 1) % m;
                if (!closed && i < first) break;
                if (!alive[i]) out.pos[i] = out.pos[p], out.qi[i] = out.qi[p];
            }
        }

        // 3. Runs of equal QI per frame, followed from frame to frame.
        std::vector<RunSequence> runs;
        std::vector<std::size_t> live; // run sequences continued by the previous frame's spans
        for (std::size_t f = 0; f < mf.size(); ++f) {
            const std::vector<RunSpan> spans = frame_spans(mf[f], closed);
            // Each span continues the live run it overlaps most, when that run
            // overlaps no other span more; the rest start new runs.
            std::vector<std::size_t> next_live;
            std::vector<std::int64_t> best_run(spans.size(), -1), best_overlap(spans.size(), 0);
            std::map<std::size_t, std::pair<std::int64_t, std::size_t>> run_best; // run -> (overlap, span)
            for (std::size_t s = 0; s < spans.size(); ++s)
                for (const std::size_t r : live) {
                    const std::int64_t o = overlap(runs[r], spans[s], m);
                    if (o <= 0) continue;
                    if (o > best_overlap[s]) best_overlap[s] = o, best_run[s] = std::int64_t(r);
                    auto& rb = run_best[r];
                    if (o > rb.first) rb = {o, s};
                }
            for (std::size_t s = 0; s < spans.size(); ++s) {
                RunSpan span = spans[s];
                if (best_run[s] >= 0 && run_best[std::size_t(best_run[s])].second == s) {
                    RunSequence& rs = runs[std::size_t(best_run[s])];
                    align(rs, span, m);
                    rs.a = std::min(rs.a, span.a);
                    rs.b = std::max(rs.b, span.b);
                    if (rs.b - rs.a > m) rs.b = rs.a + m;
                    rs.frames.push_back({&mf[f], span});
                    next_live.push_back(std::size_t(best_run[s]));
                } else {
                    runs.push_back({span.qi, span.whole, closed, span.a, span.b, {{&mf[f], span}}});
                    next_live.push_back(runs.size() - 1);
                }
            }
            live = std::move(next_live);
        }
        for (const RunSequence& rs : runs) emit(rs, m, rs.qi > 0 ? hidden_out : visible_out);
    }

    static std::vector<RunSpan> frame_spans(const MasterFrame& f, bool closed) {
        const std::int64_t m = std::int64_t(f.pos.size());
        std::vector<std::int64_t> gaps;
        for (std::int64_t i = closed ? 0 : 1; i < m; ++i)
            if (f.qi[i] != f.qi[(i + m - 1) % m]) gaps.push_back(i);
        auto change_at = [&](std::int64_t g) {
            const auto it = f.change.find(((g % m) + m) % m);
            return it != f.change.end() ? it->second : f.pos[((g % m) + m) % m];
        };
        std::vector<RunSpan> spans;
        if (gaps.empty()) {
            RunSpan s{f.qi[0], closed, 0, m, f.pos[0], f.pos[m - 1]};
            spans.push_back(s);
            return spans;
        }
        if (closed) {
            for (std::size_t k = 0; k < gaps.size(); ++k) {
                const std::int64_t a = gaps[k], b = k + 1 < gaps.size() ? gaps[k + 1] : gaps[0] + m;
                spans.push_back({f.qi[a], false, a, b, change_at(a), change_at(b)});
            }
            return spans;
        }
        std::int64_t a = 0;
        glm::dvec2 start = f.pos[0];
        for (const std::int64_t g : gaps) {
            spans.push_back({f.qi[a], false, a, g, start, change_at(g)});
            a = g;
            start = change_at(g);
        }
        spans.push_back({f.qi[a], false, a, m, start, f.pos[m - 1]});
        return spans;
    }

    // How many master vertices a span shares with a run's last span (modulo
    // m); 0 when their QI or kind differ.
    static std::int64_t overlap(const RunSequence& rs, const RunSpan& s, std::int64_t m) {
        if (rs.qi != s.qi || rs.whole != s.whole) return 0;
        if (s.whole) return m;
        const RunSpan& last = rs.frames.back().second;
        std::int64_t best = 0;
        for (const std::int64_t shift : {-m, std::int64_t(0), m})
            best = std::max(best, std::min(last.b, s.b + shift) - std::max(last.a, s.a + shift));
        return best;
    }

    static void align(const RunSequence& rs, RunSpan& s, std::int64_t m) {
        if (s.whole) return;
        const RunSpan& last = rs.frames.back().second;
        for (const std::int64_t shift : {std::int64_t(0), -m, m})
            if (std::max(last.a, s.a + shift) < std::min(last.b, s.b + shift)) {
                s.a += shift;
                s.b += shift;
                return;
            }
    }

    void emit(const RunSequence& rs, std::int64_t m, std::string& out) {
        // Geometry per frame: start point, the run's vertices (those outside
        // this frame's span folded onto its ends), end point.
        std::vector<std::vector<glm::dvec2>> geom;
        geom.reserve(rs.frames.size());
        for (const auto& [frame, span] : rs.frames) {
            std::vector<glm::dvec2> g;
            if (rs.whole) {
                g = frame->pos;
            } else {
                g.reserve(std::size_t(rs.b - rs.a + 2));
                g.push_back(span.start);
                for (std::int64_t u = rs.a; u < rs.b; ++u)
                    g.push_back(u < span.a ? span.start : u >= span.b ? span.end : frame->pos[((u % m) + m) % m]);
                g.push_back(span.end);
            }
            geom.push_back(std::move(g));
        }
        const bool closed_path = rs.whole && rs.closed;
        const std::size_t n = geom[0].size();
        if (n < 2) return;
        std::vector<std::uint8_t> keep(n, 0);
        if (closed_path) {
            // A ring: simplify it as two chains, from vertex 0 to the vertex
            // farthest from it and on round back to vertex 0.
            std::size_t far = 0;
            for (std::size_t k = 1; k < n; ++k)
                if (glm::length(geom[0][k] - geom[0][0]) > glm::length(geom[0][far] - geom[0][0])) far = k;
            std::vector<std::vector<glm::dvec2>> ring = geom;
            for (auto& r : ring) r.push_back(r[0]);
            std::vector<std::uint8_t> ring_keep(n + 1, 0);
            ring_keep[0] = ring_keep[far] = ring_keep[n] = 1;
            simplify_joint(ring, 0, far, options_.tolerance_px, ring_keep);
            simplify_joint(ring, far, n, options_.tolerance_px, ring_keep);
            keep.assign(ring_keep.begin(), ring_keep.begin() + long(n));
        } else {
            keep[0] = keep[n - 1] = 1;
            simplify_joint(geom, 0, n - 1, options_.tolerance_px, keep);
        }
        std::vector<std::vector<glm::dvec2>> reduced(geom.size());
        for (std::size_t f = 0; f < geom.size(); ++f)
            for (std::size_t k = 0; k < n; ++k)
                if (keep[k]) reduced[f].push_back(geom[f][k]);
        if (reduced[0].size() < 2) return;

        std::vector<std::uint8_t> key(reduced.size(), 0);
        key.front() = key.back() = 1;
        simplify_time(reduced, 0, reduced.size() - 1, options_.tolerance_px, key);

        const std::size_t total = frames_.size();
        const int first = rs.frames.front().first->frame, last = rs.frames.back().first->frame;
        const double dur = double(total) / fps_;
        char dur_text[32];
        std::snprintf(dur_text, sizeof dur_text, "%.6gs", dur);

        std::string d0;
        svg::append_path_data(d0, reduced[0], closed_path);
        out += "<path d=\"" + d0 + "\"";
        const bool always = first == 0 && last + 1 == int(total);
        if (!always) out += " display=\"none\"";
        out += ">";
        if (!always) {
            // Shown from its first frame's start to its last frame's end.
            std::string times, values;
            if (first > 0) {
                times = "0;" + key_time(double(first) / total);
                values = "none;inline";
            } else {
                times = "0";
                values = "inline";
            }
            if (last + 1 < int(total)) {
                times += ";" + key_time(double(last + 1) / total);
                values += ";none";
            }
            out += "<animate attributeName=\"display\" dur=\"" + std::string(dur_text) +
                   "\" repeatCount=\"indefinite\" calcMode=\"discrete\" keyTimes=\"" + times +
                   "\" values=\"" + values + "\"/>";
        }
        std::size_t kept = 0;
        for (const auto k : key) kept += k;
        if (kept > 1) {
            std::string times, values;
            auto add = [&](double t, const std::vector<glm::dvec2>& g) {
                if (!times.empty()) {
                    times += ';';
                    values += ';';
                }
                times += key_time(t);
                svg::append_path_data(values, g, closed_path);
            };
            if (first > 0) add(0.0, reduced.front());
            for (std::size_t f = 0; f < reduced.size(); ++f)
                if (key[f]) add(double(rs.frames[f].first->frame) / total, reduced[f]);
            if (last + 1 < int(total) || double(last) / total < 1.0) add(1.0, reduced.back());
            out += "<animate attributeName=\"d\" dur=\"" + std::string(dur_text) +
                   "\" repeatCount=\"indefinite\" calcMode=\"linear\" keyTimes=\"" + times +
                   "\" values=\"" + values + "\"/>";
        }
        out += "</path>\n";
        ++stats_.paths;
        stats_.keyframes += kept;
        stats_.frames_spanned += rs.frames.size();
        stats_.vertices += reduced[0].size();
    }

    const std::vector<AnimationFrame>& frames_;
    double fps_;
    AnimatedSvgOptions options_;
    AnimatedSvgStats& stats_;
};

} // namespace

std::string to_animated_svg(const std::vector<AnimationFrame>& frames, double fps,
                            const AnimatedSvgOptions& options, AnimatedSvgStats* stats) {
    AnimatedSvgStats local;
    AnimatedSvgStats& st = stats ? *stats : local;
    st = {};
    if (frames.empty()) return svg::document_start(16, 16) + "</svg>\n";
    const Drawing& d0 = frames[0].drawing;
    std::string out = svg::document_start(d0.width, d0.height);
    bool with_visibility = false;
    for (const AnimationFrame& f : frames)
        for (const DrawnContour& c : f.drawing.contours)
            for (const DrawnLoop& loop : c.loops) with_visibility |= !loop.qi.empty();
    Writer writer(frames, fps, options, st);
    std::vector<std::string> hidden(d0.contours.size()), visible(d0.contours.size());
    for (std::size_t c = 0; c < d0.contours.size(); ++c) writer.contour(c, hidden[c], visible[c]);
    for (const bool is_hidden : {true, false}) {
        if (is_hidden && !with_visibility) continue;
        out += with_visibility ? svg::visibility_group(is_hidden) : svg::plain_group();
        for (std::size_t c = 0; c < d0.contours.size(); ++c)
            out += svg::kind_group(d0.contours[c].spec) + (is_hidden ? hidden[c] : visible[c]) + "</g>\n";
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

} // namespace snaxels
