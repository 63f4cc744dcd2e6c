#pragma once
/// Static SVG of a drawing: one group per contour kind, one path per loop.

#include <string>

#include "core/export/drawing.h"

namespace snaxels {

/// Default stroke colour of a contour kind (until styles say otherwise).
const char* default_stroke(ContourKind kind);

/// The SVG document text.
std::string to_svg(const Drawing& drawing);

} // namespace snaxels
