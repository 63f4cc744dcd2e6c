// libFuzzer target: the style XML parser (pugixml and snaxels' reading of
// it). Any input parses or throws snaxels::Error, and a style that parses
// holds what the renderers rely on: finite, non-negative widths, opacities
// in [0, 1], positive dashes, colours the colour table knows.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "snaxels/error.h"
#include "snaxels/style/style.h"

namespace {

void require(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "style invariant broken: %s\n", what);
    std::abort();
}

void check_colour(const std::string& c) {
    if (c == "none") return;
    (void)snaxels::colour_rgb(c); // throws (a crash here) on a colour the parser should have refused
}

void check_stroke(const snaxels::StrokeStyle& s) {
    require(std::isfinite(s.width) && s.width >= 0, "stroke width");
    require(std::isfinite(s.opacity) && s.opacity >= 0 && s.opacity <= 1, "stroke opacity");
    require(std::isfinite(s.smoothing) && s.smoothing >= 0, "smoothing");
    for (const double d : s.dash) require(std::isfinite(d) && d >= 0, "dash length");
    check_colour(s.colour);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    std::vector<snaxels::StyleDiagnostic> warnings;
    snaxels::Style style;
    try {
        style = snaxels::parse_style(text, "fuzz.xml", &warnings);
    } catch (const snaxels::StyleError&) { // the documented failure, with its line and column
        return 0;
    }
    require(style.width > 0 && style.height > 0, "canvas size");
    require(std::isfinite(style.margin), "margin");
    check_colour(style.background);
    for (const auto& c : style.contours) {
        check_stroke(c.visible);
        check_stroke(c.hidden);
        (void)style.contour(c.spec);
    }
    for (const auto& r : style.regions) {
        require(std::isfinite(r.k) && std::isfinite(r.erosion) && r.erosion >= 0, "region numbers");
        require(r.opacity >= 0 && r.opacity <= 1, "region opacity");
        check_colour(r.fill);
    }
    (void)style.fill_contours();
    return 0;
}
