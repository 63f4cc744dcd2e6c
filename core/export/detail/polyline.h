#pragma once
// Internal to core/export: small polyline helpers shared by the exporters.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/util/detail/segment.h"

namespace snaxels {

/// Douglas-Peucker over several frames of one polyline at once: marks in
/// @p keep the vertices between @p i and @p j (indices taken modulo the
/// vertex count, so a closed ring can run past its end) needed for every
/// frame to stay within @p tolerance.
inline void douglas_peucker_joint(const std::vector<std::vector<glm::dvec2>>& frames, std::size_t i, std::size_t j,
                                  double tolerance, std::vector<std::uint8_t>& keep) {
    if (j <= i + 1) return;
    const std::size_t n = frames[0].size();
    // The farthest vertex (the first of equals) by its distance, which is
    // the square root of its greatest square: a square no greater than the
    // worst's cannot make a greater distance, so only the others take a root.
    double worst = -1.0, worst_square = -1.0;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
        double square = 0.0;
        for (const auto& f : frames) square = std::max(square, point_segment_squared(f[k % n], f[i % n], f[j % n]));
        if (!(square > worst_square)) continue;
        const double d = std::sqrt(square);
        if (d > worst) worst = d, worst_square = square, at = k;
    }
    if (worst <= tolerance) return;
    keep[at % n] = 1;
    douglas_peucker_joint(frames, i, at, tolerance, keep);
    douglas_peucker_joint(frames, at, j, tolerance, keep);
}

/// The vertices of @p q needed to stay within @p tolerance of it (the ends
/// of an open polyline; a closed one keeps its first vertex and the one
/// half way round).
inline std::vector<glm::dvec2> simplify_polyline(const std::vector<glm::dvec2>& q, bool closed, double tolerance) {
    if (q.size() < 4) return q;
    std::vector<std::uint8_t> keep(q.size(), 0);
    const std::vector<std::vector<glm::dvec2>> frames{q};
    keep.front() = 1;
    if (closed) {
        const std::size_t half = q.size() / 2;
        keep[half] = 1;
        douglas_peucker_joint(frames, 0, half, tolerance, keep);
        douglas_peucker_joint(frames, half, q.size(), tolerance, keep);
    } else {
        keep.back() = 1;
        douglas_peucker_joint(frames, 0, q.size() - 1, tolerance, keep);
    }
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < q.size(); ++i)
        if (keep[i]) out.push_back(q[i]);
    return out;
}

} // namespace snaxels
