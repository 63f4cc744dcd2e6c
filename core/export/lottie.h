#pragma once
/// The animation as Lottie (Bodymovin JSON, docs/lottie.md), for lottie-web,
/// lottie-android/ios, rlottie and After Effects. The paths are those of the
/// animated SVG (core/export/animated_paths.h): fills under hidden lines
/// under visible lines, each path's keys as `sh` keyframes with linear
/// easing. A Lottie shape keeps the vertex count and closedness of its first
/// keyframe for all its keyframes (lottie-web interpolates only that many
/// vertices), so each segment of a path, a stretch of keys with one vertex
/// set, is a shape layer of its own whose in and out points are the
/// segment's life; consecutive layers of a path meet where the SVG's keys a
/// thousandth of a frame apart switch structure.

#include <string>
#include <vector>

#include "snaxels/export/animated_svg.h"

namespace snaxels {

/// The Lottie JSON of @p frames played at @p fps, drawn as @p style says;
/// @p stats as for to_animated_svg (keyframes: `sh` keyframes written).
std::string to_lottie(const std::vector<AnimationFrame>& frames, double fps, const AnimatedSvgOptions& options = {},
                      const Style& style = default_style(), AnimatedSvgStats* stats = nullptr);

} // namespace snaxels
