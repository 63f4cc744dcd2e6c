#pragma once
/// The mixed Voronoi areas of a triangle's corners, shared by the
/// curvature passes (core/snaxel/curvature.cpp) and the derivative of
/// curvature (core/snaxel/curvature_derivative.cpp).

#include <array>

#include <glm/vec3.hpp>

namespace snaxels::detail {

/// The parts of a triangle's area nearest each corner (Meyer et al. 2003's
/// mixed Voronoi areas: a corner's Voronoi cell, or for an obtuse triangle
/// half the area at the obtuse corner and a quarter at the others). @p e
/// holds the edges opposite each corner, @p area the triangle's area.
std::array<double, 3> corner_areas(const std::array<glm::dvec3, 3>& e, double area);

} // namespace snaxels::detail
