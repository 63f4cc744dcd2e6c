#pragma once
/// The shape a stroke draws a line as (docs/styles.md, "Line weight"): its
/// centre wobbled by a smooth noise fastened to the stroke parameter, and
/// where its width varies the filled outline that draws it. Stills and
/// animations draw this one shape.

#include <vector>

#include <glm/glm.hpp>

#include "snaxels/export/stroke_weight.h"
#include "snaxels/style/style.h"

namespace snaxels {

/// The centre line @p centre (open, or a closed ring) displaced across
/// itself by the style's wobble at @p seconds (boil). @p period: the
/// parameter's period on a closed loop (the noise wraps there smoothly).
void wobble(const StrokeStyle& style, std::vector<StrokePoint>& centre, bool closed, double period, double seconds);

/// The filled outline of a line of varying width along @p centre, as
/// @p style says (taper toward the ends of an open run, width-by, the
/// calligraphic nib; caps as `cap` says, round or flat; joins without
/// spikes). An open run gives one closed polygon; a closed ring two (the
/// outer one and the inner one reversed, a hole under the nonzero rule).
/// Vertex counts depend only on the centre's point count and closedness,
/// so outlines of one subpath interpolate from key to key.
void stroke_outline(const StrokeStyle& style, const std::vector<StrokePoint>& centre, bool closed,
                    std::vector<std::vector<glm::dvec2>>& out);

/// A line as its stroke draws it with line weight, the one shape stills
/// and animations draw: the centre line wobbled (wobble), and where the
/// width varies the filled outlines (stroke_outline) that draw it instead.
struct StrokeShape {
    std::vector<StrokePoint> centre;               ///< the wobbled centre line
    std::vector<std::vector<glm::dvec2>> outlines; ///< closed and filled; none while the width is even
};
/// The shape of @p centre (open, or a closed ring) drawn by @p style at
/// @p seconds; @p period: the stroke parameter's period on a closed loop.
StrokeShape stroke_shape(const StrokeStyle& style, std::vector<StrokePoint> centre, bool closed, double period,
                         double seconds);

} // namespace snaxels
