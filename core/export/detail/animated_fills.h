#pragma once
// Internal to core/export: animated region fills (fill_paths in
// animated_paths.h). One path per region track for as long as the region
// lives; its loops (outer outlines and holes) are the path's subpaths,
// resampled by arc length from an anchor that follows them. A loop that appears grows from a point (a
// zero-area subpath), one that closes shrinks to one.

#include <cstddef>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>

namespace snaxels {

/// Loops of two frames that are the same loop: pairs (index in @p a, index
/// in @p b), nearest centres first, only loops wound the same way (outline
/// or hole) and near each other (centres closer than their mean radius
/// plus @p slack_px).
std::vector<std::pair<std::size_t, std::size_t>> match_loops(const std::vector<std::vector<glm::dvec2>>& a,
                                                             const std::vector<std::vector<glm::dvec2>>& b,
                                                             double slack_px);

} // namespace snaxels
