#pragma once
/// Static SVG drawings made into pictures and print: rendered by librsvg
/// onto cairo surfaces, as an RGBA image (video frames, PNG files) or as a
/// vector PDF whose strokes and fills stay paths.

#include <cstdint>
#include <string>
#include <vector>

namespace snaxels {

/// An image of 8-bit RGBA pixels, rows top to bottom, not premultiplied.
struct RgbaImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
};

/// @p svg (a static document, core/export/svg.h) rendered at @p width x
/// @p height pixels, its viewBox scaled to fit; where it leaves the canvas
/// transparent (a style with background="none") the pixels stay
/// transparent unless @p opaque, in which case they are white (a video
/// has no transparency). Throws snaxels::Error when librsvg cannot read it.
RgbaImage render_svg(const std::string& svg, int width, int height, bool opaque);

/// @p image as a PNG file at @p path, written atomically.
void write_png(const std::string& path, const RgbaImage& image);

/// @p svg as a one-page vector PDF at @p path (atomically): a page of the
/// document's width x height in points (a pixel of the canvas a point; a
/// size in mm, a page on paper, that paper's size), its strokes and fills
/// PDF paths.
void write_pdf(const std::string& path, const std::string& svg);

} // namespace snaxels
