#include "snaxels/export/svg.h"
#include "snaxels/util/detail/parallel.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>

#include "snaxels/export/detail/polyline.h"
#include "snaxels/export/detail/svg_writer.h"
#include "snaxels/export/detail/animated_strokes.h"
#include "snaxels/export/stroke_dashes.h"
#include "snaxels/export/stroke_parameter.h"
#include "snaxels/export/stroke_shape.h"
#include "snaxels/export/stroke_weight.h"
#include "snaxels/planarmap/planar_map.h"

namespace snaxels {
namespace svg {

void append_number(std::string& out, double v) {
    // std::to_chars with a precision writes what printf's "%.2f" writes (the
    // standard defines it so), several times faster: a still's SVG prints
    // tens of thousands of numbers.
    char buf[352]; // the longest double in fixed notation with two decimals, and a sign
    int n = int(std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 2).ptr - buf);
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

void append_compact_path_data(std::string& out, const std::vector<glm::dvec2>& q, bool closed, glm::dvec2 from) {
    std::string d = "m";
    long px = std::lround(from.x * 10.0), py = std::lround(from.y * 10.0);
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

std::string document_start(int width, int height, const std::string& background, const Page& page, bool inkscape) {
    const std::string w = std::to_string(width), h = std::to_string(height);
    std::string size = "width=\"" + w + "\" height=\"" + h + "\"";
    if (page.paper()) {
        // The paper's size, for print and for drawing programs' page.
        size = "width=\"";
        append_number(size, page.width_mm);
        size += "mm\" height=\"";
        append_number(size, page.height_mm);
        size += "mm\"";
    }
    std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                      "<svg xmlns=\"http://www.w3.org/2000/svg\"" +
                      std::string(inkscape ? " xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\"" : "") +
                      " version=\"1.1\" " + size + " viewBox=\"0 0 " + w + " " + h + "\">\n";
    // Sizes in user units, not percentages: some renderers (QtSvg) resolve
    // percentages against the widget rather than the viewBox.
    if (background != "none")
        out += "<rect x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h + "\" fill=\"" + background + "\"/>\n";
    return out;
}

std::string kind_group(const ContourSpec& spec, const StrokeStyle& stroke, const std::string& attributes) {
    std::string out = "<g" + attributes + " class=\"contour\" data-kind=\"" + spec.kind_name() + "\" data-label=\"" + spec.label();
    if (stroke.variable_width()) {
        // Lines of varying width are filled outlines (nonzero: where a
        // line's outline folds over itself at a sharp turn it stays filled).
        out += "\" data-width-by=\"" + std::string(width_by_name(stroke.width_by)) + "\" fill=\"" + stroke.colour +
               "\" fill-rule=\"nonzero\" stroke=\"none\"";
        if (stroke.opacity < 1.0) {
            out += " fill-opacity=\"";
            append_number(out, stroke.opacity);
            out += "\"";
        }
        return out + ">\n";
    }
    out += "\" fill=\"none\" stroke=\"" + stroke.colour + "\" stroke-width=\"";
    append_number(out, stroke.width);
    out += "\"";
    if (stroke.opacity < 1.0) {
        out += " stroke-opacity=\"";
        append_number(out, stroke.opacity);
        out += "\"";
    }
    if (!stroke.dash.empty() && !stroke.dash_on_surface) { // surface dashes are pieces of the line
        out += " stroke-dasharray=\"";
        for (std::size_t i = 0; i < stroke.dash.size(); ++i) {
            if (i) out += ' ';
            append_number(out, stroke.dash[i]);
        }
        out += "\"";
    }
    out += " stroke-linecap=\"" + stroke.cap + "\" stroke-linejoin=\"" + stroke.join + "\">\n";
    return out;
}

std::string object_group(const SceneObject& object) {
    return "<g class=\"object\" data-object=\"" + xml_text(object.path) + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" +
           xml_text(object.name) + "\">\n";
}

void append_chain_data(std::string& out, const BezierChain& chain) {
    if (chain.knots.empty()) return;
    out += 'M';
    append_number(out, chain.knots[0].x);
    out += ',';
    append_number(out, chain.knots[0].y);
    const std::size_t m = chain.knots.size();
    for (std::size_t s = 0; s < chain.c1.size(); ++s) {
        out += s == 0 ? " C" : " ";
        for (const glm::dvec2& p : {chain.c1[s], chain.c2[s], chain.knots[(s + 1) % m]}) {
            if (&p != &chain.c1[s]) out += ' ';
            append_number(out, p.x);
            out += ',';
            append_number(out, p.y);
        }
    }
    if (chain.closed) out += " Z";
}

void append_compact_chain_data(std::string& out, const BezierChain& chain, glm::dvec2 from) {
    if (chain.knots.empty()) return;
    std::string d = "m";
    auto tenths = [](const glm::dvec2& p) { return std::pair{std::lround(p.x * 10.0), std::lround(p.y * 10.0)}; };
    const auto [fx, fy] = tenths(from);
    auto [px, py] = tenths(chain.knots[0]);
    append_joined(d, px - fx);
    append_joined(d, py - fy);
    const std::size_t m = chain.knots.size();
    for (std::size_t s = 0; s < chain.c1.size(); ++s) {
        if (s == 0) d += 'c';
        // Control points and end relative to the segment's start.
        const auto [ax, ay] = tenths(chain.c1[s]);
        const auto [bx, by] = tenths(chain.c2[s]);
        const auto [ex, ey] = tenths(chain.knots[(s + 1) % m]);
        for (const long v : {ax - px, ay - py, bx - px, by - py, ex - px, ey - py}) append_joined(d, v);
        px = ex;
        py = ey;
    }
    if (chain.closed) d += 'z';
    out += d;
}

} // namespace svg

namespace {

/// How far a static fill's outline may move when points are left out (px).
constexpr double kFillTolerancePx = 0.01;

void append_path(std::string& out, const std::vector<glm::dvec2>& q, bool closed, const StrokeStyle& stroke) {
    if (q.size() < 2) return;
    out += "<path d=\"";
    if (stroke.smoothing > 0.0) svg::append_chain_data(out, smooth_polyline(q, closed, stroke.smoothing));
    else svg::append_path_data(out, q, closed);
    out += "\"/>\n";
}

// A loop's runs of one visibility drawn with line weight: wobbled by the
// stroke parameter, and as filled outlines where the width varies.
void draw_weighted(std::string& out, const DrawnLoop& given, bool hidden, const StrokeStyle& stroke, double seconds) {
    if (given.q.size() < 2) return;
    const DrawnLoop* loop = &given;
    DrawnLoop still;
    if (given.u.empty() && stroke.carries_parameter()) { // a still: arc length from the first snaxel
        DrawnContour one;
        one.loops.push_back(given);
        parameterize_still(one);
        still = std::move(one.loops[0]);
        loop = &still;
    }
    const LoopAttributes attributes(*loop);
    auto draw = [&](std::vector<StrokePoint> line, bool closed) {
        if (line.size() < 2) return;
        StrokeShape shape = stroke_shape(stroke, std::move(line), closed, loop->u_period, seconds);
        std::vector<StrokePoint>& centre = shape.centre;
        if (!stroke.variable_width()) {
            std::vector<glm::dvec2> q;
            for (const StrokePoint& p : centre) q.push_back(p.q);
            if (stroke.dash_on_surface && !stroke.dash.empty()) {
                // Dashes fastened to the surface: the pieces of the line
                // where the pattern, laid along its stroke parameter, is on.
                if (closed) q.push_back(q.front()), centre.push_back(centre.front());
                std::vector<double> arcs(q.size(), 0.0), u(q.size(), 0.0);
                for (std::size_t i = 0; i < q.size(); ++i) {
                    if (i) arcs[i] = arcs[i - 1] + glm::length(q[i] - q[i - 1]);
                    u[i] = centre[i].u;
                }
                const auto pieces = dash_pieces(q, arcs, dash_spans(arcs, u, stroke.dash, loop->u_period));
                if (pieces.empty()) return;
                out += "<path d=\"";
                for (std::size_t i = 0; i < pieces.size(); ++i) {
                    if (i) out += ' ';
                    svg::append_path_data(out, pieces[i], false);
                }
                out += "\"/>\n";
                return;
            }
            append_path(out, q, closed, stroke);
            return;
        }
        out += "<path d=\"";
        for (std::size_t i = 0; i < shape.outlines.size(); ++i) {
            if (i) out += ' ';
            svg::append_path_data(out, shape.outlines[i], true);
        }
        out += "\"/>\n";
    };
    if (loop->runs.empty()) { // no visibility: drawn whole, as visible
        if (hidden) return;
        DrawnRun whole{0, loop->closed, loop->q};
        draw(attributes.run(whole), loop->closed);
        return;
    }
    for (const DrawnRun& run : loop->runs)
        if (stroke_class(run.qi) == (hidden ? StrokeClass::Hidden : StrokeClass::Visible) && !run.q.empty())
            draw(attributes.run(run), run.closed);
}

/// The fills' group of a still's SVG (empty without regions or region styles).
std::string fills_svg(const Drawing& drawing, const Style& style, const std::vector<MapRegion>* regions) {
    std::string out;
    if (regions && !style.regions.empty()) {
        // Region outlines run along mesh edges in straight stretches of many
        // points: only those that bend them stay. Each region is simplified
        // on its own, which can open slivers between neighbours, so the
        // simplified regions are made a partition again.
        // Outlines are simplified before they are eroded too: the offset's
        // cost grows with their points. Regions erode in parallel.
        std::vector<MapRegion> eroded(regions->size());
        parallel_for(regions->size(), [&](std::size_t i) {
            const MapRegion& region = (*regions)[i];
            const RegionStyle* rs = style.region(region, drawing.parts.get());
            if (!rs) return;
            MapRegion& r = eroded[i];
            r = region;
            r.polygons.clear();
            std::vector<std::vector<glm::dvec2>> outline;
            for (const auto& poly : region.polygons) outline.push_back(simplify_polyline(poly, true, kFillTolerancePx));
            for (const auto& poly : erode(outline, rs->erosion)) r.polygons.push_back(simplify_polyline(poly, true, kFillTolerancePx));
        }, 1);
        PlanarMap drawn;
        for (MapRegion& r : eroded)
            if (!r.polygons.empty()) drawn.regions.push_back(std::move(r));
        subtract_nearer_regions(drawn);
        out += "<g id=\"fills\" inkscape:groupmode=\"layer\" inkscape:label=\"fills\" stroke=\"none\" fill-rule=\"nonzero\">\n";
        for (const MapRegion& region : drawn.regions) {
            const RegionStyle* rs = style.region(region, drawing.parts.get());
            out += "<path class=\"region\" data-class=\"" + std::string(region_class_name(region.cls)) + "\" fill=\"" +
                   region_fill_colour(*rs, region, drawing.parts.get()) + "\"";
            if (rs->opacity < 1.0) {
                out += " fill-opacity=\"";
                svg::append_number(out, rs->opacity);
                out += "\"";
            }
            out += " d=\"";
            for (std::size_t i = 0; i < region.polygons.size(); ++i) {
                if (i) out += ' ';
                svg::append_path_data(out, region.polygons[i], true);
            }
            out += "\"/>\n";
        }
        out += "</g>\n";
    }
    return out;
}

/// The strokes' groups of a still's SVG: hidden, then visible lines.
std::string strokes_svg(const Drawing& drawing, const Style& style, bool by_object) {
    std::string out;
    // Hidden lines first, so visible strokes are drawn over them.
    const bool with_hidden = has_hidden_lines(drawing);
    for (const bool hidden : {true, false}) {
        if (hidden && !with_hidden) continue;
        // Layers as Inkscape names them, as the animated SVG's are.
        const std::string part = hidden ? "hidden" : "visible";
        out += "<g id=\"" + part + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + part + " lines\">\n";
        for (const DrawnContour& c : drawing.contours) {
            const ContourStyle cs = style.contour(c.spec);
            const StrokeStyle& stroke = hidden ? cs.hidden : cs.visible;
            if (!stroke.draw) continue;
            const std::string label = c.spec.label();
            out += svg::kind_group(c.spec, stroke,
                                   " id=\"" + part + "-" + label + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + label +
                                       " (" + part + ")\"");
            auto draw_loop = [&](std::string& text, const DrawnLoop& loop) {
                if (stroke.needs_parameter()) {
                    draw_weighted(text, loop, hidden, stroke, drawing.seconds);
                    return;
                }
                if (loop.runs.empty()) { // no visibility: drawn whole, as visible
                    if (!hidden) append_path(text, loop.q, loop.closed, stroke);
                    return;
                }
                for (const DrawnRun& run : loop.runs) {
                    if (stroke_class(run.qi) != (hidden ? StrokeClass::Hidden : StrokeClass::Visible) || run.q.empty()) continue;
                    append_path(text, run.q, run.closed, stroke);
                }
            };
            // Each loop's paths (curves fitted, numbers printed) in
            // parallel, then joined in the loops' order.
            std::vector<std::string> text(c.loops.size());
            parallel_for(c.loops.size(), [&](std::size_t i) { draw_loop(text[i], c.loops[i]); }, 4);
            if (!by_object) {
                for (const std::string& t : text) out += t;
            } else {
                // A sublayer per object inside the kind's group (docs/styles.md says why).
                for (std::size_t o = 0; o < drawing.parts->objects.size(); ++o) {
                    std::string body;
                    for (std::size_t i = 0; i < c.loops.size(); ++i)
                        if (c.loops[i].object == std::int32_t(o)) body += text[i];
                    if (!body.empty()) out += svg::object_group(drawing.parts->objects[o]) + body + "</g>\n";
                }
                for (std::size_t i = 0; i < c.loops.size(); ++i)
                    if (c.loops[i].object < 0) out += text[i];
            }
            out += "</g>\n";
        }
        out += "</g>\n";
    }
    return out;
}

} // namespace

std::string to_svg(const Drawing& drawing, const Style& style, const std::vector<MapRegion>* regions) {
    const bool by_object = groups_by_object(drawing);
    std::string out = svg::document_start(drawing.width, drawing.height, style.background, style.page, true);
    // The fills (eroded and made a partition again with Clipper) and the
    // strokes (curves fitted) are made at once.
    std::string fills, strokes;
    parallel_invoke([&] { fills = fills_svg(drawing, style, regions); },
                    [&] { strokes = strokes_svg(drawing, style, by_object); });
    out += fills;
    out += strokes;
    out += "</svg>\n";
    return out;
}

} // namespace snaxels
