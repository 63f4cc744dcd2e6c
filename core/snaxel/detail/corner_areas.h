#pragma once
/// The areas of a triangle's corners (rtsc's Voronoi shares), shared by the
/// curvature passes (core/snaxel/curvature.cpp) and the derivative of
/// curvature (core/snaxel/curvature_derivative.cpp).

#include <array>

#include <glm/vec3.hpp>

namespace snaxels::detail {

/// The parts of a triangle's area belonging to each corner, as rtsc's
/// trimesh2 shares them: a corner's Voronoi cell where no angle is obtuse;
/// where one is (or is right), each other corner gets the right triangle
/// between it, the middle of its edge to the obtuse corner and where that
/// edge's perpendicular bisector meets the long edge, and the obtuse
/// corner the rest. @p e holds the edges opposite each corner, @p area the
/// triangle's area.
std::array<double, 3> corner_areas(const std::array<glm::dvec3, 3>& e, double area);

} // namespace snaxels::detail
