#pragma once
// How many regions cover each sample of an image: an oracle for planar
// partitions written for the tests alone. Samples lie on an s x s grid in
// every pixel; a region covers a sample by the non-zero rule of its loops.
// Crossings are half-open (a sample on an edge shared by two regions
// belongs to one of them), and each edge's crossing is computed from its
// endpoints in a fixed order, so the two regions sharing it agree exactly.

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels::test {

using Loops = std::vector<std::vector<glm::dvec2>>;

struct Coverage {
    std::uint64_t covered = 0; ///< samples inside at least one region
    std::uint64_t multiple = 0; ///< samples inside two or more
    std::uint64_t wide = 0;     ///< of those, samples whose whole (2 wide_reach + 1)^2 neighbourhood is inside two or more
    double overlap_fraction() const { return covered ? double(multiple) / double(covered) : 0.0; }
    double wide_fraction() const { return covered ? double(wide) / double(covered) : 0.0; }
};

/// With @p wide_reach > 0, also the overlap wider than 2 wide_reach / s
/// pixels in both directions (slivers along shared outlines left out).
inline Coverage coverage(const std::vector<Loops>& regions, int width, int height, int s, int wide_reach = 0) {
    const int W = width * s, H = height * s;
    std::vector<std::uint8_t> count(std::size_t(W) * std::size_t(H), 0);
    std::vector<std::pair<double, int>> xs;
    for (const Loops& region : regions) {
        double lo = 1e300, hi = -1e300;
        for (const auto& loop : region)
            for (const glm::dvec2& p : loop) lo = std::min(lo, p.y), hi = std::max(hi, p.y);
        const int r0 = std::max(0, int(std::floor(lo * s)) - 1), r1 = std::min(H - 1, int(std::ceil(hi * s)) + 1);
        for (int row = r0; row <= r1; ++row) {
            const double cy = (row + 0.5) / s;
            xs.clear();
            for (const auto& loop : region)
                for (std::size_t i = 0; i < loop.size(); ++i) {
                    glm::dvec2 a = loop[i], b = loop[(i + 1) % loop.size()];
                    if ((a.y <= cy) == (b.y <= cy)) continue;
                    const int dir = b.y > a.y ? 1 : -1;
                    if (a.y > b.y || (a.y == b.y && a.x > b.x)) std::swap(a, b);
                    xs.push_back({a.x + (cy - a.y) / (b.y - a.y) * (b.x - a.x), dir});
                }
            std::sort(xs.begin(), xs.end());
            int winding = 0;
            for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
                winding += xs[i].second;
                if (winding == 0) continue;
                // Samples at sx with xs[i] <= sx < xs[i+1].
                const int c0 = std::max(0, int(std::ceil(xs[i].first * s - 0.5)));
                const int c1 = std::min(W, int(std::ceil(xs[i + 1].first * s - 0.5)));
                for (int col = c0; col < c1; ++col) {
                    std::uint8_t& c = count[std::size_t(row) * std::size_t(W) + std::size_t(col)];
                    if (c < 255) ++c;
                }
            }
        }
    }
    Coverage out;
    for (const std::uint8_t c : count) out.covered += c >= 1, out.multiple += c >= 2;
    if (wide_reach > 0)
        for (int row = wide_reach; row < H - wide_reach; ++row)
            for (int col = wide_reach; col < W - wide_reach; ++col) {
                bool all = true;
                for (int dy = -wide_reach; dy <= wide_reach && all; ++dy)
                    for (int dx = -wide_reach; dx <= wide_reach && all; ++dx)
                        all = count[std::size_t(row + dy) * std::size_t(W) + std::size_t(col + dx)] >= 2;
                out.wide += all;
            }
    return out;
}

/// The loops of absolute SVG path data of M, L (or implicit line-to pairs)
/// and Z commands, as the static SVG writes its fills.
inline Loops parse_absolute_path(const std::string& d) {
    Loops loops;
    std::size_t i = 0;
    auto number = [&]() {
        while (i < d.size() && (d[i] == ' ' || d[i] == ',')) ++i;
        std::size_t used = 0;
        const double v = std::stod(d.substr(i, 32), &used);
        i += used;
        return v;
    };
    while (i < d.size()) {
        const char c = d[i];
        if (c == ' ' || c == ',') {
            ++i;
        } else if (c == 'M') {
            ++i;
            loops.emplace_back();
            const double x = number();
            loops.back().push_back({x, number()});
        } else if (c == 'Z' || c == 'z') {
            ++i;
        } else {
            if (c == 'L') ++i;
            const double x = number();
            loops.back().push_back({x, number()});
        }
    }
    return loops;
}

/// Every `d` of the <path class="region"> elements of an SVG document.
inline std::vector<Loops> svg_region_paths(const std::string& svg) {
    std::vector<Loops> out;
    for (std::size_t at = svg.find("<path class=\"region\""); at != std::string::npos;
         at = svg.find("<path class=\"region\"", at + 1)) {
        const std::size_t d = svg.find(" d=\"", at) + 4;
        out.push_back(parse_absolute_path(svg.substr(d, svg.find('"', d) - d)));
    }
    return out;
}

} // namespace snaxels::test

namespace snaxels::test {

/// The loops of relative or absolute SVG path data of m/M, l/L (or
/// implicit line-to pairs) and z/Z commands, as the animated SVG writes
/// them ("m x,y l dx,dy ... z", numbers joined as tightly as the grammar
/// allows: "1.7.9" is 1.7 then .9).
inline Loops parse_path(const std::string& d) {
    std::vector<std::pair<char, double>> tokens; // command (0 for a number) and value
    for (std::size_t i = 0; i < d.size();) {
        const char c = d[i];
        if (std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E') {
            tokens.push_back({c, 0.0});
            ++i;
        } else if (c == '-' || c == '.' || std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t j = i + (c == '-' ? 1 : 0);
            bool dot = false;
            while (j < d.size() && (std::isdigit(static_cast<unsigned char>(d[j])) || (d[j] == '.' && !dot))) dot |= d[j++] == '.';
            if (j < d.size() && (d[j] == 'e' || d[j] == 'E')) {
                ++j;
                if (j < d.size() && (d[j] == '-' || d[j] == '+')) ++j;
                while (j < d.size() && std::isdigit(static_cast<unsigned char>(d[j]))) ++j;
            }
            tokens.push_back({0, std::stod(d.substr(i, j - i))});
            i = j;
        } else {
            ++i;
        }
    }
    Loops loops;
    glm::dvec2 at(0.0), start(0.0);
    char cmd = 0;
    for (std::size_t i = 0; i < tokens.size();) {
        if (tokens[i].first) {
            cmd = tokens[i].first;
            ++i;
            if (cmd == 'z' || cmd == 'Z') at = start;
            continue;
        }
        const glm::dvec2 v(tokens[i].second, tokens[i + 1].second);
        i += 2;
        const bool relative = cmd == 'm' || cmd == 'l';
        at = relative ? at + v : v;
        if (cmd == 'm' || cmd == 'M') {
            loops.emplace_back();
            start = at;
            cmd = relative ? 'l' : 'L';
        }
        loops.back().push_back(at);
    }
    return loops;
}

/// The animated SVG's fills at time @p fraction of the animation's duration
/// (SMIL: `display` discrete, `d` linear between key times), one list of
/// loops per region path shown then.
inline std::vector<Loops> smil_regions_at(const std::string& svg, double fraction) {
    auto attribute = [](const std::string& tag, const std::string& name) {
        const std::size_t at = tag.find(" " + name + "=\"");
        if (at == std::string::npos) return std::string();
        const std::size_t from = at + name.size() + 3;
        return tag.substr(from, tag.find('"', from) - from);
    };
    auto split = [](const std::string& text, char sep) {
        std::vector<std::string> out;
        std::size_t from = 0;
        while (true) {
            const std::size_t to = text.find(sep, from);
            out.push_back(text.substr(from, to == std::string::npos ? std::string::npos : to - from));
            if (to == std::string::npos) break;
            from = to + 1;
        }
        return out;
    };
    std::vector<Loops> out;
    for (std::size_t at = svg.find("<path class=\"region\""); at != std::string::npos;
         at = svg.find("<path class=\"region\"", at + 1)) {
        const std::size_t open_end = svg.find('>', at);
        const std::string tag = svg.substr(at, open_end - at);
        std::string d = attribute(tag, "d");
        Loops mixed;
        bool shown = attribute(tag, "display") != "none";
        if (svg[open_end - 1] != '/') {
            const std::string body = svg.substr(open_end + 1, svg.find("</path>", open_end) - open_end - 1);
            for (std::size_t a = body.find("<animate"); a != std::string::npos; a = body.find("<animate", a + 1)) {
                const std::string anim = body.substr(a, body.find("/>", a) - a);
                std::vector<double> keys;
                for (const std::string& k : split(attribute(anim, "keyTimes"), ';')) keys.push_back(std::stod(k));
                const std::vector<std::string> values = split(attribute(anim, "values"), ';');
                std::size_t i = 0;
                while (i + 1 < keys.size() && keys[i + 1] <= fraction) ++i;
                if (attribute(anim, "attributeName") == "display") {
                    shown = values[i] != "none";
                } else if (i + 1 >= keys.size() || attribute(anim, "calcMode") == "discrete") {
                    d = values[i];
                } else { // linear: both values have the same commands
                    const double u = (fraction - keys[i]) / (keys[i + 1] - keys[i]);
                    const Loops from = parse_path(values[i]), to = parse_path(values[i + 1]);
                    mixed = from;
                    for (std::size_t l = 0; l < from.size() && l < to.size(); ++l)
                        for (std::size_t p = 0; p < from[l].size() && p < to[l].size(); ++p)
                            mixed[l][p] = from[l][p] + u * (to[l][p] - from[l][p]);
                    d.clear();
                }
            }
        }
        if (shown) out.push_back(d.empty() ? mixed : parse_path(d));
    }
    return out;
}

} // namespace snaxels::test
