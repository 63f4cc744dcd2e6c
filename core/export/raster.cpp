#include "snaxels/export/raster.h"

#include <memory>

#include <cairo-pdf.h>
#include <cairo.h>
#include <librsvg/rsvg.h>

#include "snaxels/error.h"
#include "snaxels/util/atomic_file.h"

namespace snaxels {

namespace {

struct HandleFree {
    void operator()(RsvgHandle* h) const { g_object_unref(h); }
};
struct SurfaceFree {
    void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
struct ContextFree {
    void operator()(cairo_t* c) const { cairo_destroy(c); }
};
using Handle = std::unique_ptr<RsvgHandle, HandleFree>;
using Surface = std::unique_ptr<cairo_surface_t, SurfaceFree>;
using Context = std::unique_ptr<cairo_t, ContextFree>;

Handle read_svg(const std::string& svg) {
    GError* error = nullptr;
    RsvgHandle* h = rsvg_handle_new_from_data(reinterpret_cast<const guint8*>(svg.data()), svg.size(), &error);
    if (!h) {
        const std::string why = error ? error->message : "unknown error";
        if (error) g_error_free(error);
        throw Error("cannot render the SVG: " + why);
    }
    return Handle(h);
}

/// The document's own size in pixels (its width and height attributes).
void svg_size(RsvgHandle* h, double& width, double& height) {
    if (!rsvg_handle_get_intrinsic_size_in_pixels(h, &width, &height) || !(width > 0.0) || !(height > 0.0))
        throw Error("cannot render the SVG: it has no width and height in pixels");
}

void render(RsvgHandle* h, cairo_t* cr, double width, double height) {
    const RsvgRectangle viewport{0.0, 0.0, width, height};
    GError* error = nullptr;
    if (!rsvg_handle_render_document(h, cr, &viewport, &error)) {
        const std::string why = error ? error->message : "unknown error";
        if (error) g_error_free(error);
        throw Error("cannot render the SVG: " + why);
    }
}

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
}

} // namespace

RgbaImage render_svg(const std::string& svg, int width, int height, bool opaque) {
    if (width <= 0 || height <= 0) throw Error("cannot render the SVG at " + std::to_string(width) + "x" + std::to_string(height));
    const Handle h = read_svg(svg);
    const Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height));
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
        throw Error("cannot render the SVG: no memory for a " + std::to_string(width) + "x" + std::to_string(height) + " image");
    {
        const Context cr(cairo_create(surface.get()));
        if (opaque) {
            cairo_set_source_rgb(cr.get(), 1.0, 1.0, 1.0);
            cairo_paint(cr.get());
        }
        render(h.get(), cr.get(), width, height);
    }
    cairo_surface_flush(surface.get());
    RgbaImage image;
    image.width = width;
    image.height = height;
    image.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    const unsigned char* data = cairo_image_surface_get_data(surface.get());
    const std::ptrdiff_t stride = cairo_image_surface_get_stride(surface.get()), row_bytes = std::ptrdiff_t{4} * width;
    for (std::ptrdiff_t y = 0; y < height; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(data + y * stride);
        std::uint8_t* out = image.rgba.data() + y * row_bytes;
        for (int x = 0; x < width; ++x) {
            // Cairo's ARGB32: premultiplied, native-endian 0xAARRGGBB.
            const std::uint32_t p = row[x];
            const unsigned a = p >> 24, r = (p >> 16) & 0xff, g = (p >> 8) & 0xff, b = p & 0xff;
            auto straight = [a](unsigned c) { return std::uint8_t(a == 0 ? 0 : (c * 255 + a / 2) / a); };
            out[4 * x + 0] = straight(r);
            out[4 * x + 1] = straight(g);
            out[4 * x + 2] = straight(b);
            out[4 * x + 3] = std::uint8_t(a);
        }
    }
    return image;
}

void write_png(const std::string& path, const RgbaImage& image) {
    const Surface surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, image.width, image.height));
    if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) throw Error("cannot write " + path + ": no memory");
    cairo_surface_flush(surface.get());
    unsigned char* data = cairo_image_surface_get_data(surface.get());
    const std::ptrdiff_t stride = cairo_image_surface_get_stride(surface.get()), row_bytes = std::ptrdiff_t{4} * image.width;
    for (std::ptrdiff_t y = 0; y < image.height; ++y) {
        auto* row = reinterpret_cast<std::uint32_t*>(data + y * stride);
        const std::uint8_t* in = image.rgba.data() + y * row_bytes;
        for (int x = 0; x < image.width; ++x) {
            const unsigned a = in[4 * x + 3];
            auto pre = [a](unsigned c) { return (c * a + 127) / 255; };
            row[x] = (a << 24) | (pre(in[4 * x]) << 16) | (pre(in[4 * x + 1]) << 8) | pre(in[4 * x + 2]);
        }
    }
    cairo_surface_mark_dirty(surface.get());
    std::string png;
    if (cairo_surface_write_to_png_stream(surface.get(), append_to_string, &png) != CAIRO_STATUS_SUCCESS)
        throw Error("cannot write " + path + ": PNG encoding failed");
    write_file_atomically(path, png);
}

void write_pdf(const std::string& path, const std::string& svg) {
    const Handle h = read_svg(svg);
    // A point a pixel at 72 to the inch: a page of paper (width and height
    // in mm) is its size in points, a canvas of pixels a point a pixel.
    rsvg_handle_set_dpi(h.get(), 72.0);
    double width = 0.0, height = 0.0;
    svg_size(h.get(), width, height);
    std::string pdf;
    {
        const Surface surface(cairo_pdf_surface_create_for_stream(append_to_string, &pdf, width, height));
        if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) throw Error("cannot write " + path + ": no memory");
        {
            const Context cr(cairo_create(surface.get()));
            render(h.get(), cr.get(), width, height);
            cairo_show_page(cr.get());
        }
        cairo_surface_finish(surface.get());
        if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
            throw Error("cannot write " + path + ": " + cairo_status_to_string(cairo_surface_status(surface.get())));
    }
    write_file_atomically(path, pdf);
}

} // namespace snaxels
