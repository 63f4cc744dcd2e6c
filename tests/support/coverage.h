#pragma once
// How many regions cover each sample of an image: an oracle for planar
// partitions written for the tests alone. Samples lie on an s x s grid in
// every pixel; a region covers a sample by the non-zero rule of its loops.
// Crossings are half-open (a sample on an edge shared by two regions
// belongs to one of them), and each edge's crossing is computed from its
// endpoints in a fixed order, so the two regions sharing it agree exactly.

#include <algorithm>
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
    double overlap_fraction() const { return covered ? double(multiple) / double(covered) : 0.0; }
};

inline Coverage coverage(const std::vector<Loops>& regions, int width, int height, int s) {
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
