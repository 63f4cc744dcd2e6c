#pragma once
// An animated SVG read the way a player reads it: path data tokenized,
// curves flattened, a path's d animation interpolated number by number
// where the commands of two values agree (as browsers do) and its display
// animation taken as discrete. Written for the tests alone: it shares no
// code with the exporter it checks (tests/browser/svg_persistence.cpp,
// tests/quality/quality.cpp).

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <pugixml.hpp>

namespace snaxels::test::svg {

struct Token {
    char cmd = 0; // a command letter, or 0 for a number
    double v = 0.0;
};

inline std::vector<Token> tokenize(const std::string& d) {
    std::vector<Token> out;
    const char* s = d.c_str();
    while (*s) {
        if (std::strchr("MmLlHhVvCcSsQqTtZzAa", *s)) {
            out.push_back({*s, 0.0});
            ++s;
        } else if (std::strchr("+-.0123456789", *s)) {
            char* end = nullptr;
            const double v = std::strtod(s, &end);
            if (end == s) { ++s; continue; }
            out.push_back({0, v});
            s = end;
        } else {
            ++s;
        }
    }
    return out;
}

inline bool compatible(const std::vector<Token>& a, const std::vector<Token>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].cmd != b[i].cmd) return false;
    return true;
}

struct Pt {
    double x = 0, y = 0;
};

// Subpaths of the path, curves flattened.
inline std::vector<std::vector<Pt>> flatten(const std::vector<Token>& t) {
    std::vector<std::vector<Pt>> subs;
    Pt cur, start, last_ctrl;
    char cmd = 0, prev_cmd = 0;
    std::size_t i = 0;
    auto num = [&]() { return i < t.size() && t[i].cmd == 0 ? t[i++].v : 0.0; };
    auto line_to = [&](Pt p) {
        if (subs.empty()) subs.push_back({cur});
        subs.back().push_back(p);
        cur = p;
    };
    auto cubic = [&](Pt c1, Pt c2, Pt p) {
        const Pt p0 = cur;
        for (int k = 1; k <= 16; ++k) {
            const double u = k / 16.0, w = 1 - u;
            line_to({w * w * w * p0.x + 3 * w * w * u * c1.x + 3 * w * u * u * c2.x + u * u * u * p.x,
                     w * w * w * p0.y + 3 * w * w * u * c1.y + 3 * w * u * u * c2.y + u * u * u * p.y});
        }
        last_ctrl = c2;
    };
    while (i < t.size()) {
        if (t[i].cmd) cmd = t[i++].cmd;
        else if (cmd == 'M') cmd = 'L';
        else if (cmd == 'm') cmd = 'l';
        const bool rel = std::islower(static_cast<unsigned char>(cmd));
        const Pt base = rel ? cur : Pt{};
        switch (std::toupper(static_cast<unsigned char>(cmd))) {
        case 'M': {
            const double x = num(), y = num();
            cur = start = {base.x + x, base.y + y};
            subs.push_back({cur});
            break;
        }
        case 'L': { const double x = num(), y = num(); line_to({base.x + x, base.y + y}); break; }
        case 'H': { const double x = num(); line_to({base.x + x, cur.y}); break; }
        case 'V': { const double y = num(); line_to({cur.x, base.y + y}); break; }
        case 'C': {
            const double a = num(), b = num(), c = num(), d = num(), e = num(), f = num();
            cubic({base.x + a, base.y + b}, {base.x + c, base.y + d}, {base.x + e, base.y + f});
            break;
        }
        case 'S': {
            const bool smooth = std::strchr("CcSs", prev_cmd) != nullptr;
            const Pt c1 = smooth ? Pt{2 * cur.x - last_ctrl.x, 2 * cur.y - last_ctrl.y} : cur;
            const double c = num(), d = num(), e = num(), f = num();
            cubic(c1, {base.x + c, base.y + d}, {base.x + e, base.y + f});
            break;
        }
        case 'Q': {
            const double a = num(), b = num(), e = num(), f = num();
            const Pt q{base.x + a, base.y + b}, p{base.x + e, base.y + f}, p0 = cur;
            cubic({p0.x + 2.0 / 3 * (q.x - p0.x), p0.y + 2.0 / 3 * (q.y - p0.y)},
                  {p.x + 2.0 / 3 * (q.x - p.x), p.y + 2.0 / 3 * (q.y - p.y)}, p);
            break;
        }
        case 'Z':
            if (!subs.empty()) subs.back().push_back(start);
            cur = start;
            break;
        default: // arcs are not written by the exporter: take their end point
            if (std::toupper(static_cast<unsigned char>(cmd)) == 'A') {
                for (int k = 0; k < 5; ++k) num();
                const double x = num(), y = num();
                line_to({base.x + x, base.y + y});
            } else {
                ++i;
            }
        }
        prev_cmd = cmd;
    }
    return subs;
}

inline double length_of(const std::vector<std::vector<Pt>>& subs) {
    double l = 0;
    for (const auto& s : subs)
        for (std::size_t k = 1; k < s.size(); ++k) l += std::hypot(s[k].x - s[k - 1].x, s[k].y - s[k - 1].y);
    return l;
}

inline double area_of(const std::vector<std::vector<Pt>>& subs) {
    double a = 0; // signed: holes wound the other way subtract (non-zero rule)
    for (const auto& s : subs)
        for (std::size_t k = 0; k < s.size(); ++k) {
            const Pt& p = s[k];
            const Pt& q = s[(k + 1) % s.size()];
            a += p.x * q.y - q.x * p.y;
        }
    return std::abs(a) / 2;
}

inline std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> out(1);
    for (const char c : s) {
        if (c == sep) out.emplace_back();
        else out.back() += c;
    }
    return out;
}


inline pugi::xml_node animate_of(pugi::xml_node path, const char* attribute) {
    for (pugi::xml_node a : path.children("animate"))
        if (std::strcmp(a.attribute("attributeName").value(), attribute) == 0) return a;
    return {};
}

// The value list entry in force at normalized time t (discrete).
inline std::size_t interval_at(const std::vector<double>& times, double t) {
    std::size_t k = 0;
    while (k + 1 < times.size() && times[k + 1] <= t) ++k;
    return k;
}

inline std::vector<double> numbers(const std::string& s) {
    std::vector<double> out;
    for (const auto& p : split(s, ';')) out.push_back(std::atof(p.c_str()));
    return out;
}

/// Whether @p path is shown at normalized time @p t: its display animation
/// (discrete), else its display attribute.
inline bool shown_at(pugi::xml_node path, double t) {
    if (pugi::xml_node a = animate_of(path, "display")) {
        const std::vector<double> times = numbers(a.attribute("keyTimes").value());
        const std::vector<std::string> values = split(a.attribute("values").value(), ';');
        if (!times.empty() && times.size() == values.size()) return values[interval_at(times, t)] != "none";
    }
    return std::strcmp(path.attribute("display").value(), "none") != 0;
}

/// @p path's shape at normalized time @p t: its d animation interpolated
/// between the two values about @p t, or its d.
inline std::vector<Token> shape_at(pugi::xml_node path, double t) {
    if (pugi::xml_node a = animate_of(path, "d")) {
        const std::vector<double> times = numbers(a.attribute("keyTimes").value());
        const std::vector<std::string> values = split(a.attribute("values").value(), ';');
        if (times.size() >= 2 && times.size() == values.size()) {
            const std::size_t k = interval_at(times, t);
            const std::size_t k1 = std::min(k + 1, times.size() - 1);
            const std::vector<Token> from = tokenize(values[k]), to = tokenize(values[k1]);
            const double span = times[k1] - times[k];
            const double u = span > 0 ? std::clamp((t - times[k]) / span, 0.0, 1.0) : 0.0;
            std::vector<Token> shape = from;
            if (compatible(from, to))
                for (std::size_t i = 0; i < from.size(); ++i) shape[i].v = (1 - u) * from[i].v + u * to[i].v;
            return shape;
        }
    }
    return tokenize(path.attribute("d").value());
}

/// Calls @p fn(path) for every stroke path under @p node: a path outside
/// <g id="fills"> and outside a group of filled outlines (stroke="none"
/// with a fill: lines of varying width), drawn by its stroke.
template <class Fn> void for_each_stroke_path(pugi::xml_node node, Fn&& fn, bool in_fills = false) {
    for (pugi::xml_node c : node.children()) {
        if (std::strcmp(c.name(), "g") == 0) {
            const bool outline = std::strcmp(c.attribute("stroke").value(), "none") == 0 && c.attribute("fill") &&
                                 std::strcmp(c.attribute("fill").value(), "none") != 0;
            if (!outline) for_each_stroke_path(c, fn, in_fills || std::strcmp(c.attribute("id").value(), "fills") == 0);
        } else if (std::strcmp(c.name(), "path") == 0 && !in_fills) {
            fn(c);
        }
    }
}

/// Every stroke path of an animated SVG (for_each_stroke_path): the
/// player's view of it at time @p t, flattened.
inline void strokes_at(pugi::xml_node node, double t, std::vector<std::vector<Pt>>& out) {
    for_each_stroke_path(node, [&](pugi::xml_node path) {
        if (!shown_at(path, t)) return;
        for (auto& sub : flatten(shape_at(path, t))) out.push_back(std::move(sub));
    });
}

} // namespace snaxels::test::svg
