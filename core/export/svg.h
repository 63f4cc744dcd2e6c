#pragma once
/// Static SVG of a drawing: one group per contour kind, one path per loop.

#include <string>

#include "core/export/drawing.h"

namespace snaxels {

/// Default stroke colour of a contour kind (until styles say otherwise).
const char* default_stroke(ContourKind kind);

/// The SVG document text. With visibility, hidden runs (QI > 0) are drawn
/// dashed in <g id="hidden"> under the visible ones in <g id="visible">.
std::string to_svg(const Drawing& drawing);

} // namespace snaxels
