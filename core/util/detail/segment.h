#pragma once
/// The distance from a point to a segment in the plane, shared by the
/// exporters' polyline helpers and the planar map's cuts.

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace snaxels {

/// The square of the distance from @p p to the segment from @p a to @p b
/// (point_segment is its square root, to the bit).
inline double point_segment_squared(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    const glm::dvec2 d = p - (a + t * ab);
    return glm::dot(d, d);
}

/// Distance from @p p to the segment from @p a to @p b.
inline double point_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
    return std::sqrt(point_segment_squared(p, a, b));
}

} // namespace snaxels
