#pragma once
// Points hashed into cubes, for the neighbours of a point within a cell:
// the parabolic curves' marks and the mesh's vertices near a mark. Not
// installed.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels::detail {

/// "No point" among the points a PointGrid or a tree of points is built on.
constexpr std::size_t kNoPoint = ~std::size_t(0);

/// Points hashed into cubes of side @p cell, for neighbours within a cell.
class PointGrid {
  public:
    PointGrid(std::span<const glm::dvec3> points, double cell) : points_(points), cell_(cell) {
        for (std::size_t i = 0; i < points.size(); ++i) cells_[key(points[i])].push_back(i);
    }
    /// Calls fn(j) for every point within @p radius (<= cell) of @p p.
    template <class Fn> void near(const glm::dvec3& p, double radius, Fn&& fn) const {
        const glm::ivec3 c = cell_of(p);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find(pack(c + glm::ivec3(dx, dy, dz)));
                    if (it == cells_.end()) continue;
                    for (const std::size_t j : it->second)
                        if (glm::length(points_[j] - p) <= radius) fn(j);
                }
    }
    /// The point nearest @p p (kNoPoint when there are none), searching shells of
    /// cells outward until one holds a point and the next cannot hold a nearer one.
    std::size_t nearest(const glm::dvec3& p) const {
        if (points_.empty()) return kNoPoint;
        const glm::ivec3 c = cell_of(p);
        std::size_t best = kNoPoint;
        double best_d = std::numeric_limits<double>::max();
        for (int r = 0; r < 1 << 20; ++r) {
            for (int dx = -r; dx <= r; ++dx)
                for (int dy = -r; dy <= r; ++dy)
                    for (int dz = -r; dz <= r; ++dz) {
                        if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != r) continue;
                        const auto it = cells_.find(pack(c + glm::ivec3(dx, dy, dz)));
                        if (it == cells_.end()) continue;
                        for (const std::size_t j : it->second) {
                            const double d = glm::length(points_[j] - p);
                            if (d < best_d) best_d = d, best = j;
                        }
                    }
            if (best != kNoPoint && best_d <= r * cell_) break;
        }
        return best;
    }

  private:
    glm::ivec3 cell_of(const glm::dvec3& p) const { return glm::ivec3(glm::floor(p / cell_)); }
    static std::int64_t pack(const glm::ivec3& c) {
        return (std::int64_t(c.x) & 0x1fffff) | (std::int64_t(c.y) & 0x1fffff) << 21 | (std::int64_t(c.z) & 0x1fffff) << 42;
    }
    std::int64_t key(const glm::dvec3& p) const { return pack(cell_of(p)); }
    std::span<const glm::dvec3> points_;
    double cell_;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

} // namespace snaxels::detail
