#include "snaxels/export/detail/animated_paths.h"

#include <algorithm>

namespace snaxels {

std::size_t PathSegment::vertices() const {
    std::size_t n = 0;
    if (shapes.empty()) return n;
    for (std::size_t s = 0; s < shapes[0].size(); ++s)
        n += s < knots.size() && !knots[s].empty() ? knots[s].size() : shapes[0][s].pts.size();
    return n;
}

void sum_stats(AnimatedSvgStats& st) {
    st.paths = st.keyframes = st.frames_spanned = st.vertices = 0;
    for (const PathStats& p : st.path_stats) {
        ++st.paths;
        st.keyframes += p.keyframes;
        st.frames_spanned += p.frames_shown;
        st.vertices += p.vertices;
    }
}

std::vector<AnimatedPathData> animated_paths(const std::vector<AnimationFrame>& frames, const Style& style,
                                             const AnimatedSvgOptions& options, const ChunkContext* chunk) {
    std::vector<AnimatedPathData> paths;
    if (frames.empty()) return paths;
    fill_paths(frames, style, options, paths);
    for (std::size_t c = 0; c < frames[0].drawing.contours.size(); ++c) stroke_paths(frames, c, style, options, paths, chunk);
    return paths;
}

} // namespace snaxels
