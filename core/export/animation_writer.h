#pragma once
/// Writing an animation as its frames come in, in memory bounded by the
/// paths alive at once rather than by the frame count. Frames are encoded
/// in chunks of kChunkFrames (each chunk shares its first frame with the
/// chunk before): the paths of a chunk (core/export/animated_paths.h) go on
/// the paths of the chunk before that end on the shared frame (the same
/// contour sequence, region track or dash run), joined there by keys a
/// thousandth of a frame apart as any two segments of a path are; each
/// path's text (SMIL keyTimes and values, Lottie layers) is spilled to a
/// temporary file as it is made, and the document is assembled from it at
/// the end.

#include <functional>
#include <memory>
#include <string_view>

#include "snaxels/export/animated_svg.h"

namespace snaxels {

/// The file an animation is written as.
enum class AnimationFormat {
    Svg,    ///< animated SVG (SMIL), docs/animation.md
    Lottie, ///< Lottie JSON, docs/lottie.md
};

class AnimationWriter {
  public:
    /// Frames a chunk encodes at once (after the frame it shares).
    static constexpr std::size_t kChunkFrames = 48;

    /// An animation of @p frames frames played at @p fps.
    AnimationWriter(AnimationFormat format, std::size_t frames, double fps, const AnimatedSvgOptions& options,
                    const Style& style);
    ~AnimationWriter();
    AnimationWriter(const AnimationWriter&) = delete;
    AnimationWriter& operator=(const AnimationWriter&) = delete;

    /// The next frame (their number is the one given to the constructor).
    void add(AnimationFrame frame);

    /// Encodes what is left and writes the whole document through @p sink,
    /// in pieces; @p stats as for to_animated_svg.
    void finish(const std::function<void(std::string_view)>& sink, AnimatedSvgStats* stats = nullptr);

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

/// The document of @p frames, in memory (to_animated_svg, to_lottie).
std::string animation_document(AnimationFormat format, const std::vector<AnimationFrame>& frames, double fps,
                               const AnimatedSvgOptions& options, const Style& style, AnimatedSvgStats* stats);

} // namespace snaxels
