#pragma once
/// Cutting a convex piece of a face where functions linear over the face
/// cross their levels, as both planar maps do (the snaxel map past the
/// contour, the post map on every shown face): the piece is split by one
/// level after another, each split giving the part below the level and the
/// part above, with the crossing points shared between the two.

#include <utility>
#include <vector>

namespace snaxels::detail {

/// @p poly split where its points change side: the points for which
/// @p below holds, and the rest, each part with the crossings between.
/// crossing(a, b, k) makes the point where the side changes between poly[k]
/// (a) and the next point (b); sides(in_below, in_above, a_below) may then
/// set how the two parts' copies of it differ.
template <class Point, class Below, class Crossing, class Sides>
std::pair<std::vector<Point>, std::vector<Point>> split_polygon(const std::vector<Point>& poly, Below&& below,
                                                                Crossing&& crossing, Sides&& sides) {
    std::vector<Point> lower, upper;
    const std::size_t n = poly.size();
    for (std::size_t k = 0; k < n; ++k) {
        const Point& a = poly[k];
        const Point& b = poly[(k + 1) % n];
        const bool a_below = below(a);
        (a_below ? lower : upper).push_back(a);
        if (a_below == below(b)) continue;
        const Point q = crossing(a, b, k);
        lower.push_back(q);
        upper.push_back(q);
        sides(lower.back(), upper.back(), a_below);
    }
    return {std::move(lower), std::move(upper)};
}

/// @p poly cut by each of @p cuts in turn: split(part, cut) gives a part's
/// two sides of one cut (as split_polygon does); sides of fewer than three
/// points are dropped.
template <class Point, class Cut, class Split>
std::vector<std::vector<Point>> cut_polygon(std::vector<Point> poly, const std::vector<Cut>& cuts, Split&& split) {
    std::vector<std::vector<Point>> parts{std::move(poly)};
    for (const Cut& cut : cuts) {
        std::vector<std::vector<Point>> next;
        for (const auto& part : parts) {
            auto [lower, upper] = split(part, cut);
            if (lower.size() >= 3) next.push_back(std::move(lower));
            if (upper.size() >= 3) next.push_back(std::move(upper));
        }
        parts = std::move(next);
    }
    return parts;
}

} // namespace snaxels::detail
