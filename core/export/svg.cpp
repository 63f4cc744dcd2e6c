#include "core/export/svg.h"

#include <cstdio>
#include <sstream>

namespace snaxels {
namespace {

void append_number(std::string& out, double v) {
    char buf[32];
    // Two decimals are a hundredth of a pixel: below what any display shows.
    int n = std::snprintf(buf, sizeof buf, "%.2f", v);
    while (n > 0 && buf[n - 1] == '0') --n;
    if (n > 0 && buf[n - 1] == '.') --n;
    if (n == 2 && buf[0] == '-' && buf[1] == '0') { buf[0] = '0'; n = 1; }
    out.append(buf, std::size_t(n));
}

} // namespace

const char* default_stroke(ContourKind kind) {
    switch (kind) {
    case ContourKind::Visual: return "#111111";
    case ContourKind::Shadow: return "#2f5fa8";
    case ContourKind::Isophote: return "#8a4fb0";
    case ContourKind::Gleam: return "#d98c00";
    }
    return "#111111";
}

std::string to_svg(const Drawing& drawing) {
    std::ostringstream head;
    head << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
         << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << drawing.width
         << "\" height=\"" << drawing.height << "\" viewBox=\"0 0 " << drawing.width << ' '
         << drawing.height << "\">\n"
         << "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
    std::string out = head.str();
    for (const DrawnContour& c : drawing.contours) {
        out += "<g class=\"contour\" data-kind=\"" + c.spec.kind_name() + "\" data-label=\"" +
               c.spec.label() + "\" fill=\"none\" stroke=\"" + default_stroke(c.spec.kind) +
               "\" stroke-width=\"1.5\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
        for (const DrawnLoop& loop : c.loops) {
            if (loop.q.size() < 2) continue;
            out += "<path d=\"M";
            for (std::size_t i = 0; i < loop.q.size(); ++i) {
                if (i) out += i == 1 ? " L" : " ";
                append_number(out, loop.q[i].x);
                out += ',';
                append_number(out, loop.q[i].y);
            }
            if (loop.closed) out += " Z";
            out += "\"/>\n";
        }
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

} // namespace snaxels
