#pragma once
// Internal to core/export: the pieces of SVG text the static and the
// animated exporters share, so both draw with the same look.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/snaxel/contour_function.h"

namespace snaxels::svg {

/// A coordinate with at most two decimals (a hundredth of a pixel).
void append_number(std::string& out, double v);
/// Path data "M x,y L x,y x,y ... [Z]".
void append_path_data(std::string& out, const std::vector<glm::dvec2>& q, bool closed);
/// Compact path data for animation: "m x,y l dx,dy ..." with positions
/// rounded to 0.1 px first (so rounding never accumulates) and numbers
/// joined as tightly as the SVG path grammar allows. Every keyframe of a
/// path has the same commands, so browsers interpolate it.
void append_compact_path_data(std::string& out, const std::vector<glm::dvec2>& q, bool closed);

/// XML declaration, <svg> start tag and white background.
std::string document_start(int width, int height);
/// Start tag of the group of one contour kind.
std::string kind_group(const ContourSpec& spec);
/// Start tag of the group of visible (hidden = false) or hidden lines.
std::string visibility_group(bool hidden);
/// Start tag of the group used when visibility was not computed.
std::string plain_group();

} // namespace snaxels::svg
