#include "snaxels/style/page.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "snaxels/error.h"
#include "snaxels/style/style.h"

namespace snaxels {
namespace {

struct Paper {
    const char* name;
    double width_mm, height_mm;
};
// ISO 216 (A and B series) and the North American sizes (ANSI), portrait.
constexpr Paper kPapers[] = {{"A0", 841, 1189}, {"A1", 594, 841},     {"A2", 420, 594},        {"A3", 297, 420},
                             {"A4", 210, 297},  {"A5", 148, 210},     {"A6", 105, 148},        {"B4", 250, 353},
                             {"B5", 176, 250},  {"letter", 215.9, 279.4}, {"legal", 215.9, 355.6}, {"tabloid", 279.4, 431.8}};

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

/// A positive finite number that is the whole of @p text.
std::optional<double> positive(const std::string& text) {
    if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return std::nullopt;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || !std::isfinite(v) || !(v > 0.0)) return std::nullopt;
    return v;
}

/// Millimetres per unit of @p unit (mm, cm, in, pt, px), or 0.
double unit_in_mm(const std::string& unit) {
    if (unit == "mm") return 1.0;
    if (unit == "cm") return 10.0;
    if (unit == "in") return 25.4;
    if (unit == "pt") return 25.4 / 72.0;
    if (unit == "px") return 1.0 / kPixelsPerMm;
    return 0.0;
}

} // namespace

std::optional<glm::dvec2> paper_size(const std::string& name) {
    const std::string n = lower(name);
    for (const Paper& p : kPapers)
        if (n == lower(p.name)) return glm::dvec2(p.width_mm, p.height_mm);
    const auto x = n.find('x');
    if (x == std::string::npos || n.size() < x + 3) return std::nullopt;
    const std::string unit = n.substr(n.size() - 2);
    const double mm = unit == "px" || unit == "pt" ? 0.0 : unit_in_mm(unit);
    const auto w = positive(n.substr(0, x)), h = positive(n.substr(x + 1, n.size() - 2 - x - 1));
    if (!(mm > 0.0) || !w || !h) return std::nullopt;
    return glm::dvec2(*w * mm, *h * mm);
}

std::string paper_names() {
    std::string out;
    for (const Paper& p : kPapers) out += std::string(p.name) + ", ";
    return out + "or WxH in mm, cm or in (210x297mm, 8.5x11in)";
}

void set_paper(Style& style, const glm::dvec2& size_mm, bool landscape) {
    const double a = std::min(size_mm.x, size_mm.y), b = std::max(size_mm.x, size_mm.y);
    const double w = std::round((landscape ? b : a) * kPixelsPerMm), h = std::round((landscape ? a : b) * kPixelsPerMm);
    if (w < 16 || h < 16 || w > 20000 || h > 20000)
        throw Error("a paper of " + std::to_string(int(std::lround(a))) + " x " + std::to_string(int(std::lround(b))) +
                    " mm makes a canvas outside 16 .. 20000 pixels a side");
    style.page.width_mm = landscape ? b : a;
    style.page.height_mm = landscape ? a : b;
    style.width = int(w);
    style.height = int(h);
    style.margin = 10.0 * kPixelsPerMm;
}

std::optional<double> length_pixels(const std::string& text) {
    std::string number = text, unit = "px";
    if (text.size() > 2 && std::isalpha(static_cast<unsigned char>(text.back()))) {
        unit = lower(text.substr(text.size() - 2));
        number = text.substr(0, text.size() - 2);
    }
    const double mm = unit_in_mm(unit);
    if (!(mm > 0.0)) return std::nullopt;
    if (number == "0") return 0.0;
    const auto v = positive(number);
    if (!v) return std::nullopt;
    return unit == "px" ? *v : *v * mm * kPixelsPerMm;
}

std::optional<double> model_unit_mm(const std::string& name) {
    if (name == "m") return 1000.0;
    if (name == "ft") return 304.8;
    const double mm = name == "px" || name == "pt" ? 0.0 : unit_in_mm(name);
    if (mm > 0.0) return mm;
    return std::nullopt;
}

std::optional<double> parse_scale(const std::string& text) {
    const auto colon = text.find(':');
    if (colon == std::string::npos) return std::nullopt;
    const auto a = positive(text.substr(0, colon)), b = positive(text.substr(colon + 1));
    if (!a || !b) return std::nullopt;
    return *b / *a;
}

ImageProjection drawing_projection(const Style& style, const Camera& camera, const glm::dvec3& centre, double radius) {
    const Page& page = style.page;
    const double w = style.width, h = style.height, m = style.margin;
    Camera c = camera;
    // Where the view's span (what fits the smaller side) lies: on paper within
    // the margin, every view; filling, across the larger side.
    const double native = c.own_frame ? h : std::min(w, h);
    double span = native;
    if (page.fit == Page::Fit::Fill && !c.own_frame) span = std::max(w, h);
    else if (page.paper()) span = std::max((c.own_frame ? h : std::min(w, h)) - 2.0 * m, 1.0);
    const bool fitted = c.orthographic() && !c.own_frame && !(c.ortho_height > 0.0);
    if (c.orthographic() && page.scale > 0.0) {
        // At scale: the model's units to the paper's millimetres, about the
        // view's line through the eye (through the centre for a fitted view).
        if (fitted) c.eye = centre - c.forward() * radius;
        c.ortho_height = native / (page.unit_mm / page.scale * kPixelsPerMm);
    } else if (fitted) {
        if (page.fit == Page::Fit::Fit) return ImageProjection(c, centre, radius, style.width, style.height, m);
        c.eye = centre - c.forward() * radius; // the bounding circle across the larger side
        c.ortho_height = 2.0 * radius * native / span;
    } else if (span != native) {
        if (c.orthographic()) c.ortho_height *= native / span;
        else c.fov_deg = glm::degrees(2.0 * std::atan(std::tan(glm::radians(0.5 * c.fov_deg)) * native / span));
    }
    return ImageProjection(c, centre, radius, style.width, style.height, m);
}

} // namespace snaxels
