#include "snaxels/export/animated_svg.h"

#include "snaxels/export/animation_writer.h"

namespace snaxels {

std::string to_animated_svg(const std::vector<AnimationFrame>& frames, double fps, const AnimatedSvgOptions& options,
                            const Style& style, AnimatedSvgStats* stats) {
    return animation_document(AnimationFormat::Svg, frames, fps, options, style, stats);
}

} // namespace snaxels
