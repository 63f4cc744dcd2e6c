#include "core/export/svg.h"

#include <cmath>
#include <cstdio>

#include "core/export/svg_writer.h"

namespace snaxels {
namespace svg {

void append_number(std::string& out, double v) {
    char buf[32];
    int n = std::snprintf(buf, sizeof buf, "%.2f", v);
    while (n > 0 && buf[n - 1] == '0') --n;
    if (n > 0 && buf[n - 1] == '.') --n;
    if (n == 2 && buf[0] == '-' && buf[1] == '0') {
        buf[0] = '0';
        n = 1;
    }
    out.append(buf, std::size_t(n));
}

void append_path_data(std::string& out, const std::vector<glm::dvec2>& q, bool closed) {
    out += 'M';
    for (std::size_t i = 0; i < q.size(); ++i) {
        if (i) out += i == 1 ? " L" : " ";
        append_number(out, q[i].x);
        out += ',';
        append_number(out, q[i].y);
    }
    if (closed) out += " Z";
}

namespace {

// Tenths of a pixel as text: "12.3", "-0.4" -> "-.4", "5" (no ".0").
void append_tenths(std::string& out, long tenths) {
    if (tenths < 0) {
        out += '-';
        tenths = -tenths;
    }
    const long whole = tenths / 10, frac = tenths % 10;
    if (whole) out += std::to_string(whole);
    if (frac) {
        out += '.';
        out += char('0' + frac);
    } else if (!whole) {
        out += '0';
    }
}

// Appends a number, with a separator only where the grammar needs one.
void append_joined(std::string& out, long tenths) {
    std::string text;
    append_tenths(text, tenths);
    const char last = out.empty() ? ' ' : out.back();
    const bool last_is_digit = last >= '0' && last <= '9';
    const bool prev_has_point = [&] {
        for (auto it = out.rbegin(); it != out.rend(); ++it) {
            if (*it == '.') return true;
            if (!(*it >= '0' && *it <= '9')) return false;
        }
        return false;
    }();
    const bool needs_space = (last_is_digit || last == '.') &&
                             (text[0] != '-' && !(text[0] == '.' && prev_has_point));
    if (needs_space) out += ' ';
    out += text;
}

} // namespace

void append_compact_path_data(std::string& out, const std::vector<glm::dvec2>& q, bool closed) {
    std::string d = "m";
    long px = 0, py = 0;
    for (std::size_t i = 0; i < q.size(); ++i) {
        const long x = std::lround(q[i].x * 10.0), y = std::lround(q[i].y * 10.0);
        if (i == 1) d += 'l';
        append_joined(d, x - px);
        append_joined(d, y - py);
        px = x;
        py = y;
    }
    if (closed) d += 'z';
    out += d;
}

std::string document_start(int width, int height) {
    const std::string w = std::to_string(width), h = std::to_string(height);
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
           "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + w + "\" height=\"" + h +
           "\" viewBox=\"0 0 " + w + " " + h + "\">\n"
           "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
}

std::string kind_group(const ContourSpec& spec) {
    return "<g class=\"contour\" data-kind=\"" + spec.kind_name() + "\" data-label=\"" + spec.label() +
           "\" stroke=\"" + default_stroke(spec.kind) + "\">\n";
}

std::string visibility_group(bool hidden) {
    return hidden ? "<g id=\"hidden\" fill=\"none\" stroke-width=\"1\" stroke-opacity=\"0.55\" "
                    "stroke-dasharray=\"4 3\" stroke-linejoin=\"round\">\n"
                  : "<g id=\"visible\" fill=\"none\" stroke-width=\"1.5\" stroke-linejoin=\"round\" "
                    "stroke-linecap=\"round\">\n";
}

std::string plain_group() {
    return "<g fill=\"none\" stroke-width=\"1.5\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
}

} // namespace svg

const char* default_stroke(ContourKind kind) {
    switch (kind) {
    case ContourKind::Visual: return "#111111";
    case ContourKind::Shadow: return "#2f5fa8";
    case ContourKind::Isophote: return "#8a4fb0";
    case ContourKind::Gleam: return "#d98c00";
    }
    return "#111111";
}

namespace {

void append_path(std::string& out, const std::vector<glm::dvec2>& q, bool closed) {
    if (q.size() < 2) return;
    out += "<path d=\"";
    svg::append_path_data(out, q, closed);
    out += "\"/>\n";
}

} // namespace

std::string to_svg(const Drawing& drawing) {
    std::string out = svg::document_start(drawing.width, drawing.height);
    bool with_visibility = false;
    for (const DrawnContour& c : drawing.contours)
        for (const DrawnLoop& loop : c.loops) with_visibility |= !loop.runs.empty();

    if (!with_visibility) {
        out += svg::plain_group();
        for (const DrawnContour& c : drawing.contours) {
            out += svg::kind_group(c.spec);
            for (const DrawnLoop& loop : c.loops) append_path(out, loop.q, loop.closed);
            out += "</g>\n";
        }
        out += "</g>\n</svg>\n";
        return out;
    }
    // Hidden lines first, so visible strokes are drawn over them.
    for (const bool hidden : {true, false}) {
        out += svg::visibility_group(hidden);
        for (const DrawnContour& c : drawing.contours) {
            out += svg::kind_group(c.spec);
            for (const DrawnLoop& loop : c.loops)
                for (const DrawnRun& run : loop.runs)
                    if ((run.qi > 0) == hidden) append_path(out, run.q, run.closed);
            out += "</g>\n";
        }
        out += "</g>\n";
    }
    out += "</svg>\n";
    return out;
}

} // namespace snaxels
