#pragma once
// Internal to core/export: small polyline helpers shared by the exporters.

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels {

/// Distance from @p p to the segment from @p a to @p b.
inline double point_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

/// Douglas-Peucker over several frames of one polyline at once: marks in
/// @p keep the vertices between @p i and @p j (indices taken modulo the
/// vertex count, so a closed ring can run past its end) needed for every
/// frame to stay within @p tolerance.
inline void douglas_peucker_joint(const std::vector<std::vector<glm::dvec2>>& frames, std::size_t i, std::size_t j,
                                  double tolerance, std::vector<std::uint8_t>& keep) {
    if (j <= i + 1) return;
    const std::size_t n = frames[0].size();
    double worst = -1.0;
    std::size_t at = i;
    for (std::size_t k = i + 1; k < j; ++k) {
        double d = 0.0;
        for (const auto& f : frames) d = std::max(d, point_segment(f[k % n], f[i % n], f[j % n]));
        if (d > worst) worst = d, at = k;
    }
    if (worst <= tolerance) return;
    keep[at % n] = 1;
    douglas_peucker_joint(frames, i, at, tolerance, keep);
    douglas_peucker_joint(frames, at, j, tolerance, keep);
}

} // namespace snaxels
