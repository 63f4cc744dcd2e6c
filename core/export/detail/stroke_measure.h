#pragma once
// Internal to core/export: measures along a stroke's centre line shared by
// the stroke parameter, the weights, the dashes and the shape. Not installed.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels::detail {

inline double wrap(double x, double period) {
    const double r = std::fmod(x, period);
    return r < 0.0 ? r + period : r;
}

// The index of the first of @p v's values (nondecreasing) above @p x.
inline std::size_t upper_index(const std::vector<double>& v, double x, std::size_t end) {
    return std::size_t(std::upper_bound(v.begin(), v.begin() + std::ptrdiff_t(end), x) - v.begin());
}

// Arc length at each point of a polyline from its first (closed: the
// closing segment not included).
inline std::vector<double> cumulative(const std::vector<glm::dvec2>& q) {
    std::vector<double> cum(q.size(), 0.0);
    for (std::size_t k = 1; k < q.size(); ++k) cum[k] = cum[k - 1] + glm::length(q[k] - q[k - 1]);
    return cum;
}

} // namespace snaxels::detail
