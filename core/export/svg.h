#pragma once
/// Static SVG of a drawing: one group per contour kind, one path per loop.

#include <string>

#include "snaxels/export/drawing.h"
#include "snaxels/planarmap/post_map.h"
#include "snaxels/style/style.h"

namespace snaxels {

/// The SVG document text, drawn as @p style says. Hidden runs (QI > 0) go in
/// <g id="hidden"> under the visible ones in <g id="visible">; without
/// visibility every line is drawn with its visible stroke.
/// With @p regions (the planar map), the regions the style fills are drawn
/// first, in <g id="fills">.
std::string to_svg(const Drawing& drawing, const Style& style = default_style(),
                   const std::vector<MapRegion>* regions = nullptr);

} // namespace snaxels
