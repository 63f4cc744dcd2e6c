#pragma once
// The distance from a point to a segment, in the plane or in space, for the
// tests' own measurements.

#include <algorithm>

#include <glm/glm.hpp>

namespace snaxels::test {

template <class Vec> double segment_distance(const Vec& p, const Vec& a, const Vec& b) {
    const Vec ab = b - a;
    const double len2 = glm::dot(ab, ab);
    const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
    return glm::length(p - (a + t * ab));
}

} // namespace snaxels::test
