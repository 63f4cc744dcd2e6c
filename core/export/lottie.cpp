#include "snaxels/export/lottie.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "snaxels/export/detail/animated_paths.h"
#include "snaxels/export/animation_writer.h"

namespace snaxels {
namespace {

/// A number rounded to a multiple of 10^-digits, as short as JSON allows.
void append_fixed(std::string& out, double v, int digits) {
    const double scale = std::pow(10.0, digits);
    long long n = std::llround(v * scale);
    if (n < 0) out += '-', n = -n;
    long long whole = 1;
    for (int d = 0; d < digits; ++d) whole *= 10;
    out += std::to_string(n / whole);
    long long frac = n % whole;
    if (frac == 0) return;
    int width = digits;
    while (frac % 10 == 0) frac /= 10, --width;
    const std::string f = std::to_string(frac);
    out += '.';
    out.append(std::size_t(width) - f.size(), '0');
    out += f;
}

/// Positions and tangents: a tenth of a pixel, as the animated SVG's path data.
void coord(std::string& out, double v) { append_fixed(out, v, 1); }
/// Times (frames): keys a thousandth of a frame apart stay apart.
void time_value(std::string& out, double t) { append_fixed(out, t, 3); }
/// Colours, opacities, widths.
void value(std::string& out, double v) { append_fixed(out, v, 4); }

void json_string(std::string& out, const std::string& s) {
    out += '"';
    for (const char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;
        out += c;
    }
    out += '"';
}

void colour(std::string& out, const std::string& css) {
    const std::uint32_t rgb = colour_rgb(css);
    out += '[';
    for (int shift = 16; shift >= 0; shift -= 8) {
        value(out, double((rgb >> shift) & 0xff) / 255.0);
        out += ',';
    }
    out += "1]";
}

/// One subpath as Lottie's bezier value: vertices, and in and out tangents
/// relative to them. Positions are rounded before the tangents are taken,
/// so the controls land where the SVG's do.
struct Bez {
    bool closed = false;
    std::vector<glm::dvec2> v, in, out;
};

glm::dvec2 rounded(glm::dvec2 p) { return glm::round(p * 10.0) / 10.0; }

Bez bez_of(const anim::Subpath& sp, const std::vector<std::size_t>* knots) {
    Bez b;
    b.closed = sp.closed;
    const bool some = knots && knots->size() < sp.pts.size();
    if (some && knots->size() >= 2) {
        const BezierChain c = bezier_chain(sp.pts, *knots, sp.closed);
        const std::size_t m = c.knots.size();
        for (const glm::dvec2& k : c.knots) b.v.push_back(rounded(k));
        b.in.assign(m, glm::dvec2(0.0));
        b.out.assign(m, glm::dvec2(0.0));
        for (std::size_t s = 0; s < c.c1.size(); ++s) {
            const std::size_t from = s, to = (s + 1) % m;
            b.out[from] = rounded(c.c1[s]) - b.v[from];
            b.in[to] = rounded(c.c2[s]) - b.v[to];
        }
        return b;
    }
    if (some) {
        for (const std::size_t k : *knots) b.v.push_back(rounded(sp.pts[k]));
    } else {
        for (const glm::dvec2& p : sp.pts) b.v.push_back(rounded(p));
    }
    b.in.assign(b.v.size(), glm::dvec2(0.0));
    b.out.assign(b.v.size(), glm::dvec2(0.0));
    return b;
}

void points(std::string& out, const std::vector<glm::dvec2>& pts) {
    out += '[';
    for (std::size_t k = 0; k < pts.size(); ++k) {
        if (k) out += ',';
        out += '[';
        coord(out, pts[k].x);
        out += ',';
        coord(out, pts[k].y);
        out += ']';
    }
    out += ']';
}

std::string bezier_value(const Bez& b) {
    std::string out = b.closed ? "{\"c\":true,\"v\":" : "{\"c\":false,\"v\":";
    points(out, b.v);
    out += ",\"i\":";
    points(out, b.in);
    out += ",\"o\":";
    points(out, b.out);
    out += '}';
    return out;
}

/// Linear easing between a keyframe and the next.
constexpr const char* kLinear = ",\"i\":{\"x\":1,\"y\":1},\"o\":{\"x\":0,\"y\":0}";

// Screen dashes keep a dash array in Lottie (AnimatedSvgOptions::
// screen_dash_array); dashes fastened to the surface are pieces of the line.
std::string stroke_style(const StrokeStyle& stroke) {
    std::string out = "{\"ty\":\"st\",\"c\":{\"a\":0,\"k\":";
    colour(out, stroke.colour);
    out += "},\"o\":{\"a\":0,\"k\":";
    value(out, 100.0 * stroke.opacity);
    out += "},\"w\":{\"a\":0,\"k\":";
    value(out, stroke.width);
    out += "},\"lc\":";
    out += stroke.cap == "butt" ? '1' : stroke.cap == "square" ? '3' : '2';
    out += ",\"lj\":";
    out += stroke.join == "miter" ? '1' : stroke.join == "bevel" ? '3' : '2';
    if (stroke.join == "miter") out += ",\"ml\":4"; // SVG's default miter limit
    if (!stroke.dash.empty()) {
        // As SVG does, an odd list of lengths is repeated to make it even.
        std::vector<double> dash = stroke.dash;
        if (dash.size() % 2) dash.insert(dash.end(), stroke.dash.begin(), stroke.dash.end());
        out += ",\"d\":[";
        for (std::size_t k = 0; k < dash.size(); ++k) {
            // lottie-web needs the names: without them it fails to draw the frame.
            out += k % 2 ? "{\"n\":\"g\",\"nm\":\"gap\",\"v\":{\"a\":0,\"k\":"
                         : "{\"n\":\"d\",\"nm\":\"dash\",\"v\":{\"a\":0,\"k\":";
            value(out, dash[k]);
            out += "}},";
        }
        out += "{\"n\":\"o\",\"nm\":\"offset\",\"v\":{\"a\":0,\"k\":0}}]";
    }
    return out + '}';
}

std::string fill_style(const RegionStyle& region, const std::string& fill) {
    std::string out = "{\"ty\":\"fl\",\"c\":{\"a\":0,\"k\":";
    colour(out, fill);
    out += "},\"o\":{\"a\":0,\"k\":";
    value(out, 100.0 * region.opacity);
    return out + "},\"r\":1}";
}

/// The fill of a line of varying width's outline: the stroke's colour, nonzero.
std::string outline_fill(const StrokeStyle& stroke) {
    std::string out = "{\"ty\":\"fl\",\"c\":{\"a\":0,\"k\":";
    colour(out, stroke.colour);
    out += "},\"o\":{\"a\":0,\"k\":";
    value(out, 100.0 * stroke.opacity);
    return out + "},\"r\":1}";
}

/// The `sh` items of one segment: a shape per subpath, keyframed when it
/// moves; subpaths of a single point (a lone move) draw nothing and are
/// left out. Returns the keyframes written.
std::size_t segment_shapes(const PathSegment& seg, std::string& out) {
    std::size_t keys = 0;
    if (seg.shapes.empty()) return keys;
    const std::vector<std::vector<std::size_t>>* knots = seg.knots.empty() ? nullptr : &seg.knots;
    for (std::size_t s = 0; s < seg.shapes[0].size(); ++s) {
        if (seg.shapes[0][s].pts.size() < 2) continue;
        const std::vector<std::size_t>* kn = knots && s < knots->size() ? &(*knots)[s] : nullptr;
        std::vector<std::string> values;
        values.reserve(seg.shapes.size());
        for (const anim::Shape& shape : seg.shapes) values.push_back(bezier_value(bez_of(shape[s], kn)));
        if (!out.empty()) out += ',';
        const bool moves = std::any_of(values.begin(), values.end(), [&](const std::string& v) { return v != values[0]; });
        if (!moves) {
            out += "{\"ty\":\"sh\",\"ks\":{\"a\":0,\"k\":" + values[0] + "}}";
            ++keys;
            continue;
        }
        out += "{\"ty\":\"sh\",\"ks\":{\"a\":1,\"k\":[";
        for (std::size_t k = 0; k < values.size(); ++k) {
            if (k) out += ',';
            out += "{\"t\":";
            time_value(out, seg.times[k]);
            out += ",\"s\":[" + values[k] + "]";
            if (k + 1 < values.size()) out += kLinear;
            out += '}';
        }
        out += "]}}";
        keys += values.size();
    }
    return keys;
}

} // namespace

std::string lottie_layer_body(const PathSegment& seg, double ip, double op, const AnimatedPathData& path,
                              const StrokeStyle& stroke, std::size_t& keys) {
    std::string shapes;
    const std::size_t k = segment_shapes(seg, shapes);
    if (shapes.empty()) return {}; // nothing drawn in this stretch
    keys += k;
    shapes += ',';
    if (path.fill) shapes += fill_style(*path.region, path.fill_colour);
    else if (stroke.variable_width()) shapes += outline_fill(stroke); // lines of varying width are filled outlines
    else shapes += stroke_style(stroke);
    std::string layer = ",\"ip\":";
    time_value(layer, ip);
    layer += ",\"op\":";
    time_value(layer, op);
    layer += ",\"st\":0,\"ks\":{},\"shapes\":[" + shapes + "]}";
    return layer;
}

std::string lottie_layer_start(std::size_t ind, const std::string& name) {
    std::string out = "{\"ty\":4,\"ind\":" + std::to_string(ind) + ",\"nm\":";
    json_string(out, name);
    return out;
}

std::string lottie_document_start(double fps, std::size_t frames, int width, int height) {
    std::string out = "{\"v\":\"5.7.4\",\"nm\":\"snaxels\",\"fr\":";
    value(out, fps);
    out += ",\"ip\":0,\"op\":" + std::to_string(frames) + ",\"w\":" + std::to_string(width) +
           ",\"h\":" + std::to_string(height) + ",\"ddd\":0,\"assets\":[],\"layers\":[";
    return out;
}

std::string lottie_background_layer(const Style& style, std::size_t frames, int width, int height, std::size_t ind) {
    std::string out = "{\"ty\":1,\"ind\":" + std::to_string(ind) + ",\"nm\":\"background\",\"ip\":0,\"op\":" +
                      std::to_string(frames) + ",\"st\":0,\"ks\":{},\"sw\":" + std::to_string(width) +
                      ",\"sh\":" + std::to_string(height) + ",\"sc\":";
    json_string(out, style.background.size() == 7 ? style.background : [&] {
        char buf[8];
        std::snprintf(buf, sizeof buf, "#%06x", unsigned(colour_rgb(style.background)));
        return std::string(buf);
    }());
    return out + '}';
}

std::string to_lottie(const std::vector<AnimationFrame>& frames, double fps, const AnimatedSvgOptions& options,
                      const Style& style, AnimatedSvgStats* stats) {
    return animation_document(AnimationFormat::Lottie, frames, fps, options, style, stats);
}

} // namespace snaxels
