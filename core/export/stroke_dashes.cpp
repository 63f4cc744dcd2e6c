// Dashes as pieces of a line.
#include "snaxels/export/stroke_dashes.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "snaxels/export/detail/stroke_measure.h"

namespace snaxels {
namespace {

using namespace detail;


} // namespace

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

} // namespace snaxels
