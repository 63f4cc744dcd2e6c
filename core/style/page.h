#pragma once
/// The page a drawing is made for: paper in millimetres or inches (the
/// A series, Letter, Legal, Tabloid or a custom size), turned portrait or
/// landscape, its margin, whether the view fits inside the page or fills
/// it, and for orthographic views a scale of 1:N in the model's units. A
/// style's <canvas> says it (docs/styles.md); the drawing's projection
/// (drawing_projection) follows it, and the SVG and PDF carry the paper's
/// physical size.
///
/// The canvas stays in CSS pixels, 96 to the inch, so line widths keep
/// their meaning: a 1.5 px line is 0.4 mm on paper.

#include <optional>
#include <string>

#include <glm/glm.hpp>

#include "snaxels/scene/camera.h"

namespace snaxels {

struct Style;

/// CSS pixels (the canvas's units) per millimetre.
inline constexpr double kPixelsPerMm = 96.0 / 25.4;

struct Page {
    /// The paper as oriented, in millimetres; 0: none (a canvas of pixels).
    double width_mm = 0.0, height_mm = 0.0;
    /// Fit: the view (the mesh's bounding circle, an orthographic view's
    /// height, a perspective field of view) spans the page's smaller side
    /// within its margin; Fill: its larger side, the rest cropped.
    enum class Fit { Fit, Fill };
    Fit fit = Fit::Fit;
    /// N of a scale of 1:N: a model unit drawn unit_mm / N millimetres long
    /// (orthographic views only); 0: none, the view is fitted.
    double scale = 0.0;
    double unit_mm = 1000.0; ///< a model unit's length: a metre unless model-units says otherwise

    bool paper() const { return width_mm > 0.0 && height_mm > 0.0; }
    bool operator==(const Page&) const = default;
};

/// The size of paper @p name in millimetres, portrait (width below height
/// for the named sizes; a custom size as written): A0 to A6, B4, B5,
/// letter, legal, tabloid (any case), or WxH with a unit, mm, cm or in
/// ("300x200mm", "8.5x11in"). None when @p name is none of these.
std::optional<glm::dvec2> paper_size(const std::string& name);
/// The names paper_size() knows, for messages.
std::string paper_names();

/// Puts @p style on paper @p size_mm (either way round), turned landscape
/// or portrait: the page's size, the canvas's pixels, and a 10 mm margin.
/// Throws snaxels::Error when the canvas would be outside 16 to 20000
/// pixels a side.
void set_paper(Style& style, const glm::dvec2& size_mm, bool landscape);

/// A length with an optional unit, px (the default), mm, cm, in or pt, in
/// CSS pixels ("10mm" is 37.8). None when @p text is not one.
std::optional<double> length_pixels(const std::string& text);

/// A model unit's length in millimetres: m, cm, mm, in or ft. None when
/// @p name is none of these.
std::optional<double> model_unit_mm(const std::string& name);

/// N of a scale written "1:N" (or "A:B", N = B / A; "2:1" enlarges).
/// None when @p text is not one, or N is not positive.
std::optional<double> parse_scale(const std::string& text);

/// The projection of @p style's drawing of a mesh whose bounding sphere
/// is @p centre, @p radius through @p camera: its canvas, margin and page
/// (fit, fill or scale). Without a page and its options this is the plain
/// ImageProjection of the canvas.
ImageProjection drawing_projection(const Style& style, const Camera& camera, const glm::dvec3& centre, double radius);

} // namespace snaxels
