#pragma once
// Internal to core/export: the pieces of SVG text the static and the
// animated exporters share, so both draw with the same look.

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/util/detail/xml_text.h"
#include "snaxels/export/bezier.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/style/style.h"

namespace snaxels::svg {

/// A coordinate with at most two decimals (a hundredth of a pixel).
void append_number(std::string& out, double v);
/// Path data "M x,y L x,y x,y ... [Z]".
void append_path_data(std::string& out, const std::vector<glm::dvec2>& q, bool closed);
/// Compact path data for animation: "m x,y l dx,dy ..." with positions
/// rounded to 0.1 px first (so rounding never accumulates) and numbers
/// joined as tightly as the SVG path grammar allows. Every keyframe of a
/// path has the same commands, so browsers interpolate it. @p from is the
/// current point the first move is relative to: the origin, or after a
/// closed subpath its first point (several loops in one path).
void append_compact_path_data(std::string& out, const std::vector<glm::dvec2>& q, bool closed,
                              glm::dvec2 from = glm::dvec2(0.0));

/// A Bézier chain as absolute path data "M x,y C x,y x,y x,y ... [Z]".
void append_chain_data(std::string& out, const BezierChain& chain);
/// The compact, relative form of a Bézier chain (see append_compact_path_data).
void append_compact_chain_data(std::string& out, const BezierChain& chain, glm::dvec2 from = glm::dvec2(0.0));

/// XML declaration, <svg> start tag and the background (unless "none");
/// with @p inkscape, the namespace of Inkscape's layer attributes. On
/// @p page's paper the width and height are the paper's, in millimetres,
/// and the viewBox the canvas's pixels.
std::string document_start(int width, int height, const std::string& background, const Page& page = {},
                           bool inkscape = false);
/// The opening tag of an object's sublayer inside a kind's group: class
/// "object", data-object its path, an Inkscape layer labelled with its name.
std::string object_group(const SceneObject& object);
/// Start tag of the group of one contour kind, drawn with @p stroke, with
/// @p attributes (" name=\"value\" ...") added.
std::string kind_group(const ContourSpec& spec, const StrokeStyle& stroke, const std::string& attributes = {});

} // namespace snaxels::svg
