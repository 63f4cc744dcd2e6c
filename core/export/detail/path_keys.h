#pragma once
// Internal to core/export: the geometry of animated paths between the
// tracker's frames and the SMIL text. A path's life is a list of segments;
// within one the keys share their subpaths' vertex counts and closedness,
// so browsers interpolate between them. Segments meet at keys a thousandth
// of a frame apart that draw the same shape (or, at a jump, at half a frame).

#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "snaxels/export/bezier.h"

namespace snaxels::anim {

/// Between the two keys of a structure switch, in frames.
constexpr double kSwitch = 1e-3;

struct Subpath {
    std::vector<glm::dvec2> pts;
    bool closed = false;
};
using Shape = std::vector<Subpath>;

struct Segment {
    std::vector<double> times; ///< frames, increasing
    std::vector<Shape> shapes; ///< parallel to times; the same structure in each
};

/// Largest distance from a vertex of one subpath to the other, both ways;
/// vertex i of each corresponds roughly to vertex i of the other, so only
/// segments near i are searched.
double shape_distance(const Subpath& a, const Subpath& b);
double shape_distance(const Shape& a, const Shape& b);

/// The keys to keep (first and last always) so that linear interpolation
/// between them reproduces every other key's shape within @p tolerance
/// (Douglas-Peucker over time; vertices may slide along the curve, the
/// drawn line may not move).
std::vector<std::uint8_t> reduce_keys(const Segment& segment, double tolerance);

/// Drops, in every key at once, the vertices of each subpath that all keys
/// reproduce within @p tolerance (joint Douglas-Peucker). With @p smoothing
/// > 0 the kept vertices are Bézier knots instead (fit within that tolerance)
/// and @p knots receives, per subpath, their indices into the full vertex
/// lists (which stay, for the chains).
void reduce_vertices(Segment& segment, double tolerance, double smoothing,
                     std::vector<std::vector<std::size_t>>* knots = nullptr);

/// Compact relative path data of @p shape (svg::append_compact_path_data
/// per subpath, each move relative to where the last subpath ended); with
/// @p knots, subpaths as Bézier chains through those vertices.
std::string path_data(const Shape& shape, const std::vector<std::vector<std::size_t>>* knots = nullptr);

} // namespace snaxels::anim
