#pragma once
/// Dashes as pieces of a line (docs/styles.md, "Dashes"): the stretches
/// of a line where a dash pattern, laid along a measure (arc length, or the
/// stroke parameter for dashes fastened to the surface), is on.

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/style/style.h"

namespace snaxels {

/// One dash of a line: the pattern's dash @p id (k times its number of
/// dashes plus the dash's place in it, k the pattern's repeat) over
/// [from, to] of a measure along the line.
struct Dash {
    std::int64_t id = 0;
    double from = 0.0, to = 0.0;
    double length = 0.0; ///< the pattern's length for this dash
};

/// The stretches of a line where @p pattern is on, the pattern laid along
/// a measure m given at arc lengths @p arcs (@p m linear between them): the
/// stroke parameter for dashes fastened to the surface, arc length from a
/// run's start for screen dashes. m may run backwards (a dash is where m is
/// on, whichever way the line goes); round a loop's seam, where m falls by
/// about @p period, it comes round again. Returns [from, to] in arc length
/// with the dash's id; where m passes one dash twice, the second piece's id
/// is offset by 2^40 (ids stay unique).
std::vector<Dash> dash_spans(const std::vector<double>& arcs, const std::vector<double>& m,
                             const std::vector<double>& pattern, double period);

/// The pieces of polyline @p q (arc length @p arcs at its points) over
/// @p spans: each a polyline from its start through the points inside it
/// to its end.
std::vector<std::vector<glm::dvec2>> dash_pieces(const std::vector<glm::dvec2>& q, const std::vector<double>& arcs,
                                                 const std::vector<Dash>& spans);

/// Whether @p stroke's dashes are drawn as pieces of the line (geometry)
/// in animations: a dashed line of constant width, unless its dashes are
/// screen dashes and @p screen_dash_array keeps them a dash array (Lottie,
/// where a shape per dash would multiply the file). A path with a dash
/// array restarts it at every subpath, which differs from the static
/// frame's wherever the subpaths differ.
inline bool dashes_as_geometry(const StrokeStyle& stroke, bool screen_dash_array = false) {
    return !stroke.dash.empty() && !stroke.variable_width() && (stroke.dash_on_surface || !screen_dash_array);
}

} // namespace snaxels
