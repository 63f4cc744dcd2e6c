#include "snaxels/style/style.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <pugixml.hpp>

#include "snaxels/error.h"
#include "snaxels/snaxel/feature_edges.h"

namespace snaxels {
namespace {
// The words of an attribute's value, split at spaces and commas.
std::vector<std::string> split_words(std::string v) {
    std::replace(v.begin(), v.end(), ',', ' ');
    std::istringstream in(v);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}
// Whether @p word is one finite number and nothing else (into @p x).
bool whole_number(const std::string& word, double& x) {
    std::size_t used = 0;
    try {
        x = std::stod(word, &used);
    } catch (const std::exception&) {
        return false;
    }
    return !word.empty() && used == word.size() && std::isfinite(x);
}
} // namespace

const char* width_by_name(StrokeStyle::WidthBy by) {
    switch (by) {
    case StrokeStyle::WidthBy::Depth: return "depth";
    case StrokeStyle::WidthBy::Light: return "light";
    case StrokeStyle::WidthBy::Curvature: return "curvature";
    case StrokeStyle::WidthBy::Qi: return "qi";
    case StrokeStyle::WidthBy::Strength: return "strength";
    case StrokeStyle::WidthBy::None: break;
    }
    return "none";
}

namespace {

/// Every contour kind's name, in the table's order.
std::vector<std::string> kind_names() {
    std::vector<std::string> names;
    for (const ContourKindInfo* info : contour_kinds()) names.emplace_back(info->name);
    return names;
}

} // namespace

const std::vector<StyleElement>& style_vocabulary() {
    static const std::vector<StyleElement> vocabulary = [] {
        const std::vector<StyleAttribute> stroke = {
            {"draw", {"true", "false"}, "whether to draw this part"},
            {"stroke", {}, "line colour"},
            {"width", {}, "line width"},
            {"opacity", {}, "line opacity"},
            {"dash", {}, "dash pattern, on and off lengths"},
            {"dash-space", {"screen", "surface"}, "`surface` fastens the dashes to the surface"},
            {"cap", {"butt", "round", "square"}, "line ends"},
            {"join", {"miter", "round", "bevel"}, "line joins"},
            {"smoothing", {}, "when above 0, lines are drawn as chains of cubic Béziers"},
            {"taper", {}, "the line's width grows from 0 over its first length and falls to 0 over its last"},
            {"width-by", {"none", "depth", "light", "curvature", "qi", "strength"}, "what the line's width follows between width-min and width-max (strength: how far a suggestive contour passes its test)"},
            {"width-min", {}, "the thinnest width-by draws"},
            {"width-max", {}, "the thickest width-by draws"},
            {"calligraphy", {}, "a flat nib: an angle and how thin a line along it is against one across it"},
            {"wobble", {}, "the line displaced across itself by a smooth noise fastened to the surface"},
            {"boil", {}, "the wobble drawn afresh this many times a second"}};
        return std::vector<StyleElement>{
            {"style", "the root: a canvas, a light, contours and regions", {{"version", {"1"}, "the language version"}}},
            {"canvas",
             "the image: its size, margin and background",
             {{"width", {}, "image width"},
              {"height", {}, "image height"},
              {"margin", {}, "space between the mesh's bounding circle and the image edge; on paper, the page's margin"},
              {"background", {"none"}, "the background fill"},
              {"paper", {"A0", "A1", "A2", "A3", "A4", "A5", "A6", "B4", "B5", "letter", "legal", "tabloid"},
               "the page: a paper size, or WxH in mm, cm or in"},
              {"orientation", {"portrait", "landscape"}, "the paper turned upright or on its side"},
              {"fit", {"fit", "fill"}, "whether the view fits inside the page or fills it"},
              {"scale", {}, "an orthographic view drawn at 1:N in the model's units"},
              {"model-units", {"m", "cm", "mm", "in", "ft"}, "the length of the model's unit, for scale"}}},
            {"light",
             "the light: a direction or a point",
             {{"dir", {}, "a directional light: the direction from the surface toward it"},
              {"pos", {}, "a point light at this position"}}},
            {"surface",
             "how the surface is shaded: where its edges are sharp",
             {{"sharp-angle", {"file"}, "edges whose faces meet at more than this angle are sharp"}}},
            {"contour",
             "which contour to find and how to draw it",
             {{"kind", kind_names(), "the contour function"},
              {"k", {}, "the isophote level N.L = k, or the gleam threshold V.R = k"},
              {"angle", {}, "the crease angle"},
              {"min-length", {}, "chains (runs of crease, border, material or object edges from end to end, or junction to junction) shorter than this are left out"},
              {"test", {"rtsc", "derivative"}, "which test draws a suggestive contour's parts: rtsc (DeCarlo et al.'s, threshold) or derivative (min-derivative and min-angle)"},
              {"min-derivative", {}, "the least derivative of kappa_r along the view that is drawn"},
              {"min-angle", {}, "parts where the surface faces the viewer within this angle of its normal are left out"},
              {"threshold", {}, "the rtsc test's threshold on feature size squared times tan(theta) times the derivative of kappa_r along the view"},
              {"fade", {}, "the strength past its test's threshold at which a suggestive contour's width-by=\"strength\" stroke is half way to width-max"},
              {"object", {}, "draws the line only on the objects these patterns select"},
              {"material", {}, "draws the line only on the materials these patterns select"},
              {"over", {"objects"}, "draws a visual contour only where it lies over another object in the image"}}},
            {"object",
             "how the scene's objects are drawn",
             {{"name", {}, "the objects it sets: a pattern matched against their names and paths"},
              {"draw", {"true", "false"}, "`false` keeps the objects as occluders: they hide what is behind them"},
              {"hide", {"true", "false"}, "`true` leaves the objects out of the scene"}}},
            {"visible", "how the contour's visible parts are drawn", stroke},
            {"hidden", "how the contour's hidden parts are drawn", stroke},
            {"region",
             "a fill of the planar map's regions of one class",
             {{"class", {"shadow", "lit", "band", "highlight"}, "`shadow`: N.L < 0"},
              {"k", {}, "the isophote level a band starts at"},
              {"fill", {"material"}, "fill colour"},
              {"shade", {}, "with fill=\"material\": the factor the material's colour is shaded by"},
              {"object", {}, "fills only the regions of the objects these patterns select"},
              {"material", {}, "fills only the regions of the materials these patterns select"},
              {"opacity", {}, "fill opacity"},
              {"erosion", {}, "shrinks the fill"}}},
        };
    }();
    return vocabulary;
}

const StyleElement* style_element(const std::string& name) {
    for (const StyleElement& e : style_vocabulary())
        if (e.name == name) return &e;
    return nullptr;
}

namespace {

// CSS colour keywords accepted besides #rgb and #rrggbb, with their values.
const std::map<std::string, std::uint32_t>& colour_names() {
    static const std::map<std::string, std::uint32_t> names = {
        {"black", 0x000000},     {"white", 0xffffff},     {"gray", 0x808080},      {"grey", 0x808080},
        {"silver", 0xc0c0c0},    {"red", 0xff0000},       {"maroon", 0x800000},    {"orange", 0xffa500},
        {"gold", 0xffd700},      {"yellow", 0xffff00},    {"olive", 0x808000},     {"lime", 0x00ff00},
        {"green", 0x008000},     {"teal", 0x008080},      {"aqua", 0x00ffff},      {"cyan", 0x00ffff},
        {"blue", 0x0000ff},      {"navy", 0x000080},      {"purple", 0x800080},    {"fuchsia", 0xff00ff},
        {"magenta", 0xff00ff},   {"pink", 0xffc0cb},      {"brown", 0xa52a2a},     {"tan", 0xd2b48c},
        {"beige", 0xf5f5dc},     {"ivory", 0xfffff0},     {"khaki", 0xf0e68c},     {"coral", 0xff7f50},
        {"salmon", 0xfa8072},    {"crimson", 0xdc143c},   {"indigo", 0x4b0082},    {"violet", 0xee82ee},
        {"turquoise", 0x40e0d0}, {"skyblue", 0x87ceeb},   {"steelblue", 0x4682b4}, {"slategray", 0x708090},
        {"slategrey", 0x708090}, {"darkgray", 0xa9a9a9},  {"darkgrey", 0xa9a9a9},  {"lightgray", 0xd3d3d3},
        {"lightgrey", 0xd3d3d3}, {"dimgray", 0x696969},   {"dimgrey", 0x696969},   {"whitesmoke", 0xf5f5f5},
        {"gainsboro", 0xdcdcdc}, {"wheat", 0xf5deb3},     {"linen", 0xfaf0e6},     {"seashell", 0xfff5ee}};
    return names;
}

struct Parser {
    const std::string& text;
    const std::string& source;
    std::vector<StyleDiagnostic>* warnings;

    StyleDiagnostic where(std::ptrdiff_t offset, std::string message) const {
        // Node offsets point at the element name: report its '<'.
        if (offset > 0 && offset <= std::ptrdiff_t(text.size()) && text[offset - 1] == '<') --offset;
        StyleDiagnostic d;
        d.line = 1;
        d.column = 1;
        for (std::ptrdiff_t i = 0; i < offset && i < std::ptrdiff_t(text.size()); ++i) {
            if (text[i] == '\n') {
                ++d.line;
                d.column = 1;
            } else {
                ++d.column;
            }
        }
        d.message = std::move(message);
        return d;
    }
    [[noreturn]] void fail(const pugi::xml_node& node, const std::string& message) const {
        throw StyleError(source, where(node.offset_debug(), message));
    }
    void warn(const pugi::xml_node& node, const std::string& message) const {
        if (warnings) warnings->push_back(where(node.offset_debug(), message));
    }
    // Warns about every attribute of `node` that its element (in the
    // vocabulary) does not take.
    void check_attributes(const pugi::xml_node& node) const {
        const StyleElement* element = style_element(node.name());
        for (const pugi::xml_attribute a : node.attributes()) {
            const bool ok = element && std::any_of(element->attributes.begin(), element->attributes.end(),
                                                   [&](const StyleAttribute& k) { return k.name == a.name(); });
            if (!ok) warn(node, "unknown attribute '" + std::string(a.name()) + "' on <" + node.name() + ">");
        }
    }
    // A <contour>'s attributes that some kinds take and its kind does not
    // (the table of kinds says which kinds take which).
    void check_kind_attributes(const pugi::xml_node& node, const ContourKindInfo& info) const {
        const std::vector<const ContourKindInfo*> kinds = contour_kinds();
        auto takes = [](const ContourKindInfo& k, const char* attr) {
            const std::string a = attr;
            return std::any_of(k.attributes.begin(), k.attributes.end(), [&](const char* b) { return a == b; }) ||
                   (a == "angle" && k.value == ContourValue::Angle);
        };
        for (const pugi::xml_attribute a : node.attributes()) {
            if (takes(info, a.name())) continue;
            std::vector<std::string> which;
            for (const ContourKindInfo* k : kinds)
                if (takes(*k, a.name())) which.emplace_back(k->name);
            if (which.empty()) continue; // every kind's, or none's
            std::string list;
            for (std::size_t i = 0; i < which.size(); ++i)
                list += (i ? i + 1 == which.size() ? " and " : ", " : "") + which[i];
            fail(node, which.size() == 1 ? "only a " + list + " contour takes " + a.name()
                                         : "only " + list + " contours take " + a.name());
        }
    }
    // The words attribute `name` of `node`'s element takes (the vocabulary's).
    static const std::vector<std::string>& words(const pugi::xml_node& node, const char* name) {
        static const std::vector<std::string> none;
        if (const StyleElement* element = style_element(node.name()))
            for (const StyleAttribute& a : element->attributes)
                if (a.name == name) return a.values;
        return none;
    }

    // `cs` with its fade read, once its strokes are: width-by="strength" is a
    // suggestive contour's.
    ContourStyle finished(const pugi::xml_node& node, ContourStyle cs) const {
        const bool suggestive = contour_kind_info(cs.spec.kind).value == ContourValue::Suggestive;
        for (const StrokeStyle* s : {&cs.visible, &cs.hidden})
            if (!suggestive && s->width_by == StrokeStyle::WidthBy::Strength)
                fail(node, "width-by=\"strength\" follows a suggestive contour's test: a " + cs.spec.kind_name() + " contour has none");
        cs.fade = number(node, "fade", -1.0, 0.0, 1e6);
        if (node.attribute("fade") && !(cs.fade > 0.0)) fail(node, "fade must be above 0");
        return cs;
    }
    // A suggestive contour's test and its values into `spec`.
    void suggestive(const pugi::xml_node& node, ContourSpec& spec) const {
        std::string test = node.attribute("test").value();
        if (!test.empty() && test != "derivative" && test != "rtsc") fail(node, "test=\"" + test + "\" must be derivative or rtsc");
        // Without test: rtsc's, unless the derivative test's values are given
        // (styles written before there were two tests).
        if (test.empty()) test = node.attribute("min-derivative") || node.attribute("min-angle") ? "derivative" : "rtsc";
        if (test == "rtsc") {
            for (const char* attr : {"min-derivative", "min-angle"})
                if (node.attribute(attr)) fail(node, std::string("the rtsc test takes threshold=\"T\", not ") + attr);
            spec.test = SuggestiveTest::Rtsc;
            spec.k = number(node, "threshold", kDefaultRtscThreshold, 0.0, 1e6);
            return;
        }
        if (node.attribute("threshold"))
            fail(node, "threshold=\"T\" is the rtsc test's: the derivative test takes min-derivative and min-angle");
        spec.k = number(node, "min-derivative", kDefaultSuggestiveDerivative, 0.0, 1e6);
        spec.min_angle = number(node, "min-angle", kDefaultSuggestiveAngle, 0.0, 89.0);
    }
    double number(const pugi::xml_node& node, const char* name, double fallback, double lo, double hi) const {
        const pugi::xml_attribute a = node.attribute(name);
        if (!a) return fallback;
        const std::string v = a.value();
        std::size_t used = 0;
        double x = 0.0;
        try {
            x = std::stod(v, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        while (used < v.size() && std::isspace(static_cast<unsigned char>(v[used]))) ++used;
        if (used == 0 || used != v.size() || !std::isfinite(x))
            fail(node, std::string(name) + "=\"" + v + "\" is not a number");
        if (x < lo || x > hi) {
            std::ostringstream msg;
            msg << name << "=\"" << v << "\" is outside " << lo << " .. " << hi;
            fail(node, msg.str());
        }
        return x;
    }
    bool boolean(const pugi::xml_node& node, const char* name, bool fallback) const {
        const pugi::xml_attribute a = node.attribute(name);
        if (!a) return fallback;
        const std::string v = a.value();
        if (v == "true" || v == "yes" || v == "1") return true;
        if (v == "false" || v == "no" || v == "0") return false;
        fail(node, std::string(name) + "=\"" + v + "\" must be true or false");
    }
    // The attribute's value, one of its words in the vocabulary.
    std::string choice(const pugi::xml_node& node, const char* name, const std::string& fallback) const {
        const pugi::xml_attribute a = node.attribute(name);
        if (!a) return fallback;
        const std::string v = a.value();
        std::string list;
        for (const std::string& c : words(node, name)) {
            if (v == c) return v;
            list += (list.empty() ? "" : ", ") + c;
        }
        fail(node, std::string(name) + "=\"" + v + "\" must be one of " + list);
    }
    std::string colour(const pugi::xml_node& node, const char* name, const std::string& fallback, bool allow_none) const {
        const pugi::xml_attribute a = node.attribute(name);
        if (!a) return fallback;
        std::string v = a.value();
        std::string lower = v;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        if (allow_none && lower == "none") return lower;
        if (!lower.empty() && lower[0] == '#' && (lower.size() == 4 || lower.size() == 7) &&
            std::all_of(lower.begin() + 1, lower.end(), [](unsigned char c) { return std::isxdigit(c); }))
            return lower;
        if (colour_names().count(lower)) return lower;
        // The words the attribute takes besides colours (none, material), as the vocabulary has them.
        std::string others;
        for (const std::string& w : words(node, name)) others += (others.empty() ? ", or " : " or ") + w;
        if (others.empty() && allow_none) others = ", or none";
        fail(node, std::string(name) + "=\"" + v + "\" is not a colour (use #rrggbb, #rgb or a CSS colour name" + others + ")");
    }
    glm::dvec3 vector(const pugi::xml_node& node, const char* name) const {
        const std::string v = node.attribute(name).value();
        glm::dvec3 out{};
        char c1 = 0, c2 = 0;
        std::istringstream in(v);
        in >> out.x >> c1 >> out.y >> c2 >> out.z;
        if (in.fail() || c1 != ',' || c2 != ',' || !(in >> std::ws).eof() || !std::isfinite(out.x) ||
            !std::isfinite(out.y) || !std::isfinite(out.z))
            fail(node, std::string(name) + "=\"" + v + "\" must be three numbers x,y,z");
        return out;
    }

    // The object= and material= patterns of a <contour> or <region>, noted
    // in the style (with where they are) to be checked against a scene.
    PartSelector selector(const pugi::xml_node& node, Style& style) const {
        PartSelector out;
        out.objects = split_patterns(node.attribute("object").value());
        out.materials = split_patterns(node.attribute("material").value());
        for (const char* attr : {"object", "material"})
            if (node.attribute(attr) && split_patterns(node.attribute(attr).value()).empty())
                fail(node, std::string(attr) + "=\"" + node.attribute(attr).value() +
                               "\" selects nothing: give a name or a pattern such as wheel*");
        for (const auto* list : {&out.objects, &out.materials})
            for (const std::string& p : *list)
                if (p == "!") fail(node, "\"!\" must be followed by the pattern it excludes");
        if (!out.empty()) {
            const StyleDiagnostic at = where(node.offset_debug(), "");
            style.part_patterns.push_back({out, at.line, at.column});
        }
        return out;
    }

    StrokeStyle stroke(const pugi::xml_node& node, StrokeStyle s) const {
        check_attributes(node);
        s.draw = boolean(node, "draw", s.draw);
        s.colour = colour(node, "stroke", s.colour, false);
        s.width = number(node, "width", s.width, 0.0, 1000.0);
        s.opacity = number(node, "opacity", s.opacity, 0.0, 1.0);
        if (const pugi::xml_attribute a = node.attribute("dash")) {
            s.dash.clear();
            for (const std::string& word : split_words(a.value())) {
                double x = -1.0;
                if (!whole_number(word, x) || !(x >= 0.0))
                    fail(node, "dash=\"" + std::string(a.value()) + "\" must be lengths in pixels, like \"4 3\"");
                s.dash.push_back(x);
            }
            if (!s.dash.empty() && std::all_of(s.dash.begin(), s.dash.end(), [](double x) { return x == 0.0; }))
                fail(node, "dash=\"" + std::string(a.value()) + "\" has no length");
            if (s.dash.size() % 2) { // SVG repeats an odd list; make it explicit
                const auto copy = s.dash;
                s.dash.insert(s.dash.end(), copy.begin(), copy.end());
            }
        }
        s.dash_on_surface = choice(node, "dash-space", s.dash_on_surface ? "surface" : "screen") == "surface";
        s.cap = choice(node, "cap", s.cap);
        s.join = choice(node, "join", s.join);
        s.smoothing = number(node, "smoothing", s.smoothing, 0.0, 100.0);
        if (const pugi::xml_attribute a = node.attribute("taper")) {
            const std::vector<std::string> w = split_words(a.value());
            if (w.empty() || w.size() > 2)
                fail(node, "taper=\"" + std::string(a.value()) + "\" must be one or two lengths, like \"12 20\" (pixels) or \"10% 30%\"");
            auto length = [&](const std::string& word, bool& fraction) {
                fraction = !word.empty() && word.back() == '%';
                double x = -1.0;
                if (!whole_number(fraction ? word.substr(0, word.size() - 1) : word, x) || !(x >= 0.0) ||
                    x > (fraction ? 100.0 : 100000.0))
                    fail(node, "taper=\"" + std::string(a.value()) + "\": \"" + word +
                                   "\" is not a length (pixels, or a percentage of the line up to 100%)");
                return fraction ? x / 100.0 : x;
            };
            s.taper_start = length(w[0], s.taper_start_fraction);
            s.taper_end = length(w.size() > 1 ? w[1] : w[0], s.taper_end_fraction);
        }
        const std::string by = choice(node, "width-by", width_by_name(s.width_by));
        for (const auto b : {StrokeStyle::WidthBy::None, StrokeStyle::WidthBy::Depth, StrokeStyle::WidthBy::Light,
                             StrokeStyle::WidthBy::Curvature, StrokeStyle::WidthBy::Qi, StrokeStyle::WidthBy::Strength})
            if (by == width_by_name(b)) s.width_by = b;
        s.width_min = number(node, "width-min", s.width_min, 0.0, 1000.0);
        s.width_max = number(node, "width-max", s.width_max, 0.0, 1000.0);
        if (s.width_min >= 0.0 && s.width_max >= 0.0 && s.width_min > s.width_max)
            fail(node, "width-min is larger than width-max");
        auto pair = [&](const char* name, double& x, double& y, double lo_x, double hi_x, double lo_y, double hi_y,
                        const char* example) {
            const pugi::xml_attribute a = node.attribute(name);
            if (!a) return;
            const std::vector<std::string> w = split_words(a.value());
            double v[2] = {0.0, 0.0};
            bool ok = w.size() == 2 && whole_number(w[0], v[0]) && whole_number(w[1], v[1]);
            ok = ok && v[0] >= lo_x && v[0] <= hi_x && v[1] >= lo_y && v[1] <= hi_y;
            if (!ok) fail(node, std::string(name) + "=\"" + a.value() + "\" must be two numbers, like \"" + example + "\"");
            x = v[0], y = v[1];
        };
        pair("calligraphy", s.calligraphy_angle, s.calligraphy_ratio, -360.0, 360.0, 0.01, 1.0, "30 0.3 (degrees, and a ratio from 0.01 to 1)");
        pair("wobble", s.wobble_amplitude, s.wobble_wavelength, 0.0, 100.0, 1.0, 10000.0, "1.5 40 (pixels: amplitude, wavelength from 1)");
        s.boil_rate = number(node, "boil", s.boil_rate, 0.0, 120.0);
        // A line of varying width is a filled outline, and a wobbling line
        // has no dash pattern either: a dash the element gives is an error,
        // one it inherits (hidden lines are dashed by default) is dropped.
        if (!s.dash.empty() && (s.variable_width() || s.wobble_amplitude > 0.0)) {
            if (node.attribute("dash"))
                fail(node, std::string("dash cannot be combined with ") +
                               (s.wobble_amplitude > 0.0 ? "wobble" : "taper, width-by or calligraphy (a line of varying width is a filled outline)"));
            s.dash.clear();
        }
        return s;
    }

    /// <light>: a direction or a point the style lights the scene from.
    void light_element(const pugi::xml_node& child, Style& style) const {
        check_attributes(child);
        const bool dir = bool(child.attribute("dir")), pos = bool(child.attribute("pos"));
        if (dir == pos) fail(child, "<light> takes either dir=\"x,y,z\" or pos=\"x,y,z\"");
        Light light;
        if (dir) {
            light.dir = vector(child, "dir");
            if (glm::length(light.dir) < 1e-12) fail(child, "dir must not be the zero vector");
            light.dir = glm::normalize(light.dir);
        } else {
            light.point = true;
            light.pos = vector(child, "pos");
        }
        style.light = light;
    }

    /// <surface>: where the surface is shaded hard (sharp-angle).
    void surface_element(const pugi::xml_node& child, Style& style) const {
        check_attributes(child);
        const std::string angle = child.attribute("sharp-angle").value();
        if (angle == "file") {
            style.surface.sharp_angle = kFileNormals;
        } else {
            char* end = nullptr;
            const double degrees = std::strtod(angle.c_str(), &end);
            if (child.attribute("sharp-angle") && (end == angle.c_str() || *end != '\0' || !(degrees >= 0.0 && degrees <= 180.0)))
                fail(child, "sharp-angle=\"" + angle + "\" must be degrees from 0 to 180, or file");
            style.surface.sharp_angle = number(child, "sharp-angle", kFileNormals, 0.0, 180.0);
        }
    }

    /// <contour>: a line set (its kind and value, the parts it takes) and its strokes.
    void contour_element(const pugi::xml_node& child, Style& style) const {
        check_attributes(child);
        const std::string kind = child.attribute("kind").value();
        const ContourKindInfo* info = find_contour_kind(kind);
        if (!info) {
            std::string kinds;
            const auto& all = contour_kinds();
            for (std::size_t i = 0; i < all.size(); ++i)
                kinds += (i ? i + 1 == all.size() ? " or " : ", " : "") + std::string(all[i]->name);
            fail(child, "kind=\"" + kind + "\" must be " + kinds);
        }
        check_kind_attributes(child, *info);
        ContourSpec spec;
        spec.kind = info->kind;
        spec.min_length = number(child, "min-length", 0.0, 0.0, 1.0);
        switch (info->value) {
        case ContourValue::None:
            if (child.attribute("k")) fail(child, "a " + kind + " contour takes no k");
            break;
        case ContourValue::Angle:
            if (child.attribute("k")) fail(child, "a " + kind + " contour takes angle=\"DEGREES\", not k");
            spec.k = number(child, "angle", kDefaultCreaseDegrees, 0.01, 179.99);
            break;
        case ContourValue::Suggestive:
            if (child.attribute("k"))
                fail(child, "a " + kind + " contour takes min-derivative=\"D\" and min-angle=\"DEGREES\", not k");
            suggestive(child, spec);
            break;
        case ContourValue::Cosine:
            if (!child.attribute("k")) fail(child, "an " + kind + " contour needs k (a cosine in -1 .. 1)");
            spec.k = number(child, "k", 0.0, -1.0, 1.0);
            break;
        }
        spec.parts = selector(child, style);
        if (child.attribute("over")) {
            spec.parts.over_objects = choice(child, "over", "objects") == "objects";
        }
        for (const ContourStyle& existing : style.contours)
            if (existing.spec.label() == spec.label()) fail(child, "a second <contour> for " + spec.label());
        ContourStyle cs = default_contour_style(spec);
        for (const pugi::xml_node part : child.children()) {
            if (part.type() != pugi::node_element) continue;
            const std::string part_name = part.name();
            if (part_name == "visible") cs.visible = stroke(part, cs.visible);
            else if (part_name == "hidden") cs.hidden = stroke(part, cs.hidden);
            else warn(part, "unknown element <" + part_name + "> in <contour> (expected <visible> or <hidden>)");
        }
        style.contours.push_back(finished(child, cs));
    }

    /// <region>: a fill of a shading class (and level), over the parts it takes.
    void region_element(const pugi::xml_node& child, Style& style) const {
        check_attributes(child);
        RegionStyle rs;
        const std::string cls = choice(child, "class", "");
        if (cls.empty()) fail(child, "<region> needs class=\"shadow|lit|band|highlight\"");
        rs.cls = *parse_region_class(cls); // choice() admits only the names
        const bool needs_k = region_class_has_level(rs.cls);
        if (needs_k && !child.attribute("k"))
            fail(child, "a " + cls + " region needs k (" +
                            (rs.cls == RegionClass::Band ? "the isophote level it starts at" : "the gleam threshold") + ")");
        if (!needs_k && child.attribute("k")) fail(child, "a " + cls + " region takes no k");
        rs.k = number(child, "k", 0.0, -1.0, 1.0);
        rs.fill_material = std::string(child.attribute("fill").value()) == "material";
        if (!rs.fill_material) rs.fill = colour(child, "fill", rs.fill, false);
        if (child.attribute("shade") && !rs.fill_material)
            fail(child, "shade goes with fill=\"material\" (it shades the material's colour)");
        rs.shade = number(child, "shade", rs.shade, 0.0, 2.0);
        rs.opacity = number(child, "opacity", rs.opacity, 0.0, 1.0);
        rs.erosion = number(child, "erosion", rs.erosion, 0.0, 100.0);
        rs.parts = selector(child, style);
        for (const RegionStyle& other : style.regions)
            if (other.cls == rs.cls && std::abs(other.k - rs.k) < 1e-9 && other.parts == rs.parts)
                fail(child, "a second <region> for " + cls + (rs.parts.empty() ? "" : " " + rs.parts.text()));
        style.regions.push_back(rs);
    }

    /// <object>: a pattern of objects hidden or kept as occluders.
    void object_element(const pugi::xml_node& child, Style& style) const {
        check_attributes(child);
        const std::string pattern = child.attribute("name").value();
        if (pattern.empty()) fail(child, "<object> needs name=\"PATTERN\" (an object's name, or a glob such as wheel*)");
        if (pattern[0] == '!') fail(child, "<object name=\"" + pattern + "\">: name a pattern to set, without !");
        const bool hide = boolean(child, "hide", false), draw = boolean(child, "draw", true);
        if (hide) style.hidden_objects.push_back(pattern);
        else if (!draw) style.occluders.push_back(pattern);
        if (hide || !draw) {
            const StyleDiagnostic at = where(child.offset_debug(), "");
            style.part_patterns.push_back({{{pattern}, {}}, at.line, at.column});
        }
    }

    // A length attribute: pixels, or a number with a unit (10mm, 0.5in).
    double length(const pugi::xml_node& node, const char* name, double fallback, double hi) const {
        const pugi::xml_attribute a = node.attribute(name);
        if (!a) return fallback;
        const auto px = length_pixels(a.value());
        if (!px) fail(node, std::string(name) + "=\"" + a.value() + "\" is not a length (a number of pixels, or with mm, cm, in or pt)");
        if (*px > hi) fail(node, std::string(name) + "=\"" + a.value() + "\" is longer than " + std::to_string(int(hi)) + " pixels");
        return *px;
    }
    void canvas_element(const pugi::xml_node& node, Style& style) const {
        check_attributes(node);
        Page& page = style.page;
        if (const pugi::xml_attribute paper = node.attribute("paper")) {
            for (const char* size : {"width", "height"})
                if (node.attribute(size)) fail(node, std::string("paper sets the canvas's size: it excludes ") + size);
            const auto mm = paper_size(paper.value());
            if (!mm) fail(node, "paper=\"" + std::string(paper.value()) + "\" must be " + paper_names());
            const std::string turn = choice(node, "orientation", mm->x > mm->y ? "landscape" : "portrait");
            try {
                set_paper(style, *mm, turn == "landscape"); // a 10 mm margin, unless the margin says
            } catch (const Error& e) {
                fail(node, "paper=\"" + std::string(paper.value()) + "\": " + e.what());
            }
        } else if (node.attribute("orientation")) {
            fail(node, "orientation turns a paper: it needs paper=\"...\"");
        }
        style.width = int(number(node, "width", style.width, 16, 20000));
        style.height = int(number(node, "height", style.height, 16, 20000));
        style.margin = length(node, "margin", style.margin, 10000.0);
        style.background = colour(node, "background", style.background, true);
        page.fit = choice(node, "fit", "fit") == "fill" ? Page::Fit::Fill : Page::Fit::Fit;
        if (const pugi::xml_attribute scale = node.attribute("scale")) {
            const auto n = parse_scale(scale.value());
            if (!n) fail(node, "scale=\"" + std::string(scale.value()) + "\" must be a ratio such as 1:50");
            if (node.attribute("fit")) fail(node, "scale sets the drawing's size: it excludes fit");
            page.scale = *n;
        }
        if (const pugi::xml_attribute units = node.attribute("model-units")) {
            if (!node.attribute("scale")) warn(node, "model-units says what scale measures: without scale it does nothing");
            page.unit_mm = *model_unit_mm(choice(node, "model-units", "m"));
        }
    }

    Style parse() const {
        pugi::xml_document doc;
        const pugi::xml_parse_result result = doc.load_buffer(text.data(), text.size());
        if (!result) throw StyleError(source, where(result.offset, std::string("malformed XML: ") + result.description()));
        const pugi::xml_node root = doc.document_element();
        if (std::string(root.name()) != "style")
            fail(root, "the root element must be <style>, not <" + std::string(root.name()) + ">");
        check_attributes(root);
        if (root.attribute("version") && std::string(root.attribute("version").value()) != "1")
            fail(root, "version=\"" + std::string(root.attribute("version").value()) + "\" is not supported (only 1)");
        Style style;
        for (const pugi::xml_node child : root.children()) {
            if (child.type() != pugi::node_element) continue;
            const std::string name = child.name();
            if (name == "canvas") {
                canvas_element(child, style);
            } else if (name == "light") {
                light_element(child, style);
            } else if (name == "surface") {
                surface_element(child, style);
            } else if (name == "contour") {
                contour_element(child, style);
            } else if (name == "region") {
                region_element(child, style);
            } else if (name == "object") {
                object_element(child, style);
            } else {
                warn(child, "unknown element <" + name +
                                "> (expected <canvas>, <light>, <surface>, <contour>, <region> or <object>)");
            }
        }
        // Occluder-only objects are left out of every line set and fill.
        for (ContourStyle& cs : style.contours) cs.spec = style.drawn(cs.spec);
        for (RegionStyle& rs : style.regions)
            for (const std::string& pattern : style.occluders) rs.parts.objects.push_back("!" + pattern);
        if (2.0 * style.margin >= std::min(style.width, style.height))
            fail(root, "the canvas margin leaves no room for the drawing");
        return style;
    }
};

} // namespace

const char* default_stroke(ContourKind kind) { return contour_kind_info(kind).stroke; }

std::uint32_t colour_rgb(const std::string& colour) {
    if (colour.size() == 7 && colour[0] == '#') return std::uint32_t(std::stoul(colour.substr(1), nullptr, 16));
    if (colour.size() == 4 && colour[0] == '#') {
        std::uint32_t rgb = 0;
        for (int i = 1; i < 4; ++i) {
            const std::uint32_t d = std::uint32_t(std::stoul(colour.substr(std::size_t(i), 1), nullptr, 16));
            rgb = rgb << 8 | (d << 4 | d);
        }
        return rgb;
    }
    const auto it = colour_names().find(colour);
    return it == colour_names().end() ? 0 : it->second;
}

StyleError::StyleError(const std::string& source, StyleDiagnostic diagnostic)
    : Error(source + ":" + std::to_string(diagnostic.line) + ":" + std::to_string(diagnostic.column) +
                         ": " + diagnostic.message),
      diagnostic_(std::move(diagnostic)) {}

ContourStyle default_contour_style(const ContourSpec& spec) {
    ContourStyle cs;
    cs.spec = spec;
    cs.visible.colour = default_stroke(spec.kind);
    cs.hidden = cs.visible;
    cs.hidden.width = 1.0;
    cs.hidden.opacity = 0.55;
    cs.hidden.dash = {4.0, 3.0};
    cs.hidden.cap = "butt";
    // Hidden suggestive contours suggest nothing: the surface in front hides the fold.
    if (spec.kind == ContourKind::Suggestive) cs.hidden.draw = false;
    return cs;
}

Style default_style() {
    Style s;
    s.contours.push_back(default_contour_style(ContourSpec{}));
    return s;
}

std::vector<ContourSpec> Style::fill_contours() const {
    std::vector<ContourSpec> out;
    auto add = [&](ContourSpec spec) {
        for (const ContourSpec& s : out)
            if (s.kind == spec.kind && std::abs(s.k - spec.k) < 1e-9) return;
        out.push_back(spec);
    };
    if (regions.empty()) return out;
    add({ContourKind::Visual, 0.0});
    for (const RegionStyle& r : regions) {
        if (r.cls != RegionClass::Highlight) add({ContourKind::Shadow, 0.0});
        if (r.cls == RegionClass::Band) add({ContourKind::Isophote, r.k});
        if (r.cls == RegionClass::Highlight) add({ContourKind::Gleam, r.k});
    }
    return out;
}

const RegionStyle* Style::region(RegionClass cls, double k) const {
    for (const RegionStyle& r : regions)
        if (r.cls == cls && (!region_class_has_level(cls) || std::abs(r.k - k) < 1e-9)) return &r;
    return nullptr;
}

const RegionStyle* Style::region(const MapRegion& r, const FaceParts* parts) const {
    for (const RegionStyle& rs : regions) {
        if (rs.cls != r.cls || (region_class_has_level(r.cls) && std::abs(rs.k - r.k) >= 1e-9)) continue;
        if (rs.parts.empty() || r.object < 0) return &rs; // every part, or a mesh without parts
        // A part the occluder-only patterns leave undrawn is not filled either.
        const PartMatcher matcher(rs.parts, parts);
        if (r.object >= 0 && r.material >= 0 && matcher.object(std::uint32_t(r.object)) &&
            matcher.material(std::uint32_t(r.material)))
            return &rs;
    }
    return nullptr;
}

int srgb_byte(double linear) {
    const double v = std::clamp(linear, 0.0, 1.0);
    return int(std::lround(255.0 * (v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055)));
}

double region_shade(RegionClass cls) {
    switch (cls) {
    case RegionClass::Shadow: return 0.55;
    case RegionClass::Lit: return 1.0;
    case RegionClass::Band: return 1.2;
    case RegionClass::Highlight: return 1.7;
    }
    return 1.0;
}

std::string region_fill_colour(const RegionStyle& rs, const MapRegion& region, const FaceParts* parts) {
    if (!rs.fill_material || !parts || region.material < 0 || region.material >= std::int32_t(parts->materials.size()))
        return rs.fill;
    const double shade = rs.shade >= 0.0 ? rs.shade : region_shade(region.cls);
    const glm::dvec4& c = parts->materials[std::uint32_t(region.material)].colour;
    char out[8];
    auto channel = [&](double v) { return srgb_byte(shade <= 1.0 ? v * shade : v + (1.0 - v) * (shade - 1.0)); };
    std::snprintf(out, sizeof out, "#%02x%02x%02x", channel(c.r), channel(c.g), channel(c.b));
    return out;
}

ContourStyle Style::contour(const ContourSpec& spec) const {
    // The line set of these parts, else the first of the kind.
    for (const ContourStyle& c : contours)
        if (c.spec.kind == spec.kind && std::abs(c.spec.k - spec.k) < 1e-9 && c.spec.parts == spec.parts) return c;
    for (const ContourStyle& c : contours)
        if (c.spec.kind == spec.kind && std::abs(c.spec.k - spec.k) < 1e-9) {
            ContourStyle out = c;
            out.spec.parts = spec.parts;
            return out;
        }
    return default_contour_style(spec);
}

ContourSpec Style::drawn(ContourSpec spec) const {
    for (const std::string& pattern : occluders) {
        const std::string excluded = "!" + pattern;
        if (std::find(spec.parts.objects.begin(), spec.parts.objects.end(), excluded) == spec.parts.objects.end())
            spec.parts.objects.push_back(excluded);
    }
    return spec;
}

std::vector<StyleDiagnostic> check_parts(const Style& style, const FaceParts& parts) {
    std::vector<StyleDiagnostic> out;
    for (const Style::PartPatterns& site : style.part_patterns)
        for (std::string& message : unmatched_patterns(site.selector, parts))
            out.push_back({site.line, site.column, std::move(message)});
    return out;
}

Style parse_style(const std::string& text, const std::string& source, std::vector<StyleDiagnostic>* warnings) {
    return Parser{text, source, warnings}.parse();
}

Style load_style(const std::string& path, std::vector<StyleDiagnostic>* warnings) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) throw Error(path + ": is a directory, not a style file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot be read (" + std::strerror(errno) + ")");
    std::ostringstream text;
    text << in.rdbuf();
    return parse_style(text.str(), path, warnings);
}

} // namespace snaxels
