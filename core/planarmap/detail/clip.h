#pragma once
/// Polygon clipping for the planar maps, on Clipper's integer grid
/// (1/1024 pixel): conversions, boolean operations and areas.

#include <vector>

#include <glm/glm.hpp>
#include <polyclipping/clipper.hpp>

namespace snaxels::clip {

using ClipperLib::Paths;

constexpr double kScale = 1024.0; ///< Clipper works in integers: 1/1024 pixel

Paths to_paths(const std::vector<std::vector<glm::dvec2>>& polygons);
std::vector<std::vector<glm::dvec2>> from_paths(const Paths& paths);
/// @p a op @p b, both filled non-zero.
Paths op(const Paths& a, const Paths& b, ClipperLib::ClipType type);
/// Square pixels covered (signed areas add up: holes wind the other way).
double area(const Paths& paths);

} // namespace snaxels::clip
