#include "core/export/animated_svg.h"

#include "core/export/animated_fills.h"
#include "core/export/animated_strokes.h"
#include "core/export/smil.h"
#include "core/export/svg_writer.h"

namespace snaxels {
namespace {

/// An Inkscape layer (a plain group elsewhere), named for what it holds.
std::string layer(const std::string& id, const std::string& label) {
    return "<g id=\"" + id + "\" inkscape:groupmode=\"layer\" inkscape:label=\"" + label + "\">\n";
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
    std::string fills;
    write_fills(frames, style, options, clock, fills, st);
    if (!fills.empty()) {
        // write_fills opens <g id="fills" ...>: make it a layer too.
        fills.insert(std::string("<g").size(), " inkscape:groupmode=\"layer\" inkscape:label=\"fills\"");
        out += fills;
    }
    std::vector<std::string> hidden(d0.contours.size()), visible(d0.contours.size());
    for (std::size_t c = 0; c < d0.contours.size(); ++c)
        write_strokes(frames, c, style, options, clock, hidden[c], visible[c], st);
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
                                       label + " (" + part + ")\"") +
                   (is_hidden ? hidden[c] : visible[c]) + "</g>\n";
        }
        out += "</g>\n";
    }
    out += "</svg>\n";
    for (const PathStats& p : st.path_stats) {
        ++st.paths;
        st.keyframes += p.keyframes;
        st.frames_spanned += p.frames_shown;
        st.vertices += p.vertices;
    }
    return out;
}

} // namespace snaxels
