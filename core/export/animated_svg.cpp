#include "core/export/animated_svg.h"

#include <algorithm>

#include "core/export/animated_paths.h"
#include "core/export/smil.h"
#include "core/export/svg_writer.h"

namespace snaxels {
namespace {

/// An Inkscape layer (a plain group elsewhere), named for what it holds.
std::string layer(const std::string& id, const std::string& label) {
    return "<g id=\"" + id + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + label + "\">\n";
}

/// The keys of @p path's segments as SMIL path data, never two at one time.
smil::AnimatedPath smil_path(const AnimatedPathData& path) {
    smil::AnimatedPath out;
    for (const PathSegment& seg : path.segments)
        for (std::size_t k = 0; k < seg.times.size(); ++k) {
            if (!out.times.empty() && seg.times[k] <= out.times.back()) continue;
            out.times.push_back(seg.times[k]);
            out.values.push_back(anim::path_data(seg.shapes[k], seg.knots.empty() ? nullptr : &seg.knots));
        }
    out.shown = {{path.first, path.last}};
    return out;
}

} // namespace

std::string to_animated_svg(const std::vector<AnimationFrame>& frames, double fps, const AnimatedSvgOptions& options,
                            const Style& style, AnimatedSvgStats* stats) {
    AnimatedSvgStats local;
    AnimatedSvgStats& st = stats ? *stats : local;
    st = {};
    if (frames.empty()) return svg::document_start(16, 16, style.background, true) + "</svg>\n";
    const Drawing& d0 = frames[0].drawing;
    std::string out = svg::document_start(d0.width, d0.height, style.background, true);
    const smil::Clock clock{frames.size(), fps};
    bool with_visibility = false;
    for (const AnimationFrame& f : frames)
        for (const DrawnContour& c : f.drawing.contours)
            for (const DrawnLoop& loop : c.loops) with_visibility |= !loop.qi.empty();
    const std::vector<AnimatedPathData> paths = animated_paths(frames, style, options);
    bool any_fill = false;
    for (const AnimatedPathData& path : paths) {
        if (!path.fill) continue;
        if (!any_fill)
            out += "<g id=\"fills\" inkscape:groupmode=\"layer\" inkscape:label=\"fills\" stroke=\"none\" "
                   "fill-rule=\"nonzero\">\n";
        any_fill = true;
        std::string attributes =
            " class=\"region\" data-class=\"" + path.region_class + "\" fill=\"" + path.region->fill + "\"";
        if (path.region->opacity < 1.0) {
            attributes += " fill-opacity=\"";
            svg::append_number(attributes, path.region->opacity);
            attributes += "\"";
        }
        const std::size_t keys = smil::append_path(out, attributes, smil_path(path), clock);
        st.path_stats.push_back(path_stats(path, path.region_class, keys));
    }
    if (any_fill) out += "</g>\n";
    for (const bool is_hidden : {true, false}) {
        if (is_hidden && !with_visibility) continue;
        const std::string part = is_hidden ? "hidden" : "visible";
        out += layer(part, part + " lines");
        for (std::size_t c = 0; c < d0.contours.size(); ++c) {
            const ContourStyle cs = style.contour(d0.contours[c].spec);
            const StrokeStyle& stroke = is_hidden ? cs.hidden : cs.visible;
            if (!stroke.draw) continue;
            const std::string label = d0.contours[c].spec.label();
            out += svg::kind_group(d0.contours[c].spec, stroke,
                                   " id=\"" + part + "-" + label + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" +
                                       label + " (" + part + ")\"");
            for (const AnimatedPathData& path : paths) {
                if (path.fill || path.contour != c || path.cls != int(is_hidden)) continue;
                const std::string children =
                    path.dash_times.empty() ? std::string()
                                            : smil::number_animation("stroke-dashoffset", path.dash_times,
                                                                     path.dash_values, clock);
                const std::size_t keys =
                    smil::append_path(out, path.brief ? " class=\"brief\"" : "", smil_path(path), clock, children);
                st.path_stats.push_back(path_stats(path, label, keys));
            }
            out += "</g>\n";
        }
        out += "</g>\n";
    }
    out += "</svg>\n";
    sum_stats(st);
    return out;
}

} // namespace snaxels
