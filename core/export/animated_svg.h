#pragma once
/// Animated SVG whose paths move (the paper's "3-D SVG Animation"): one
/// <path> per contour sequence and visibility run, its vertex list fixed for
/// the sequence and its geometry animated with SMIL <animate> (values,
/// keyTimes, calcMode="linear"), shown only while its sequence lives.
/// Snaxel identities give the correspondence: a snaxel not yet born or
/// already gone sits on its predecessor along the loop, so every keyframe
/// has the same commands and browsers interpolate between them.
/// Region fills animate the same way: one <path> per region track and run
/// of frames with the same number of loops (a topology event starts the
/// next), each loop resampled by arc length from an anchor that follows it.

#include <cstdint>
#include <string>
#include <vector>

#include "core/export/drawing.h"
#include "core/planarmap/post_map.h"
#include "core/style/style.h"

namespace snaxels {

/// Per loop of a frame's DrawnContour: its contour sequence and snaxel ids.
struct AnimatedLoop {
    std::uint64_t sequence = 0;
    std::vector<std::uint64_t> ids; ///< parallel to the DrawnLoop's snaxels
};

struct AnimationFrame {
    Drawing drawing;
    std::vector<std::vector<AnimatedLoop>> loops; ///< [contour][loop], parallel to drawing.contours
    /// The planar map's regions (when the style fills them) and, parallel,
    /// the track each belongs to: one region followed from frame to frame.
    std::vector<MapRegion> regions;
    std::vector<std::uint64_t> region_tracks;
};

struct AnimatedSvgOptions {
    /// Pixels: path vertices, and keyframes, that linear interpolation
    /// reproduces within this distance in every frame are dropped.
    double tolerance_px = 0.25;
    /// A path serves at most this many frames; longer sequences are handed
    /// from path to path without a visible seam.
    std::size_t max_chunk_frames = 12;
    /// Visible or hidden stretches shorter than this (pixels) take their
    /// neighbour's visibility: flicker at T-junctions, not lines.
    double min_run_px = 3.0;
    /// Where a visible or hidden stretch's end moves along a bend of the
    /// curve deeper than this (pixels) in one frame, the stretch is cut there
    /// instead of interpolated (interpolation would sweep across the bend).
    double max_sweep_px = 1.0;
};

struct AnimatedSvgStats {
    std::size_t paths = 0;
    std::size_t keyframes = 0;        ///< kept, over all paths
    std::size_t frames_spanned = 0;   ///< frames the paths are shown in, summed
    std::size_t vertices = 0;         ///< path vertices, summed over paths
};

/// The animated SVG of @p frames played at @p fps, looping, drawn as @p style says.
std::string to_animated_svg(const std::vector<AnimationFrame>& frames, double fps,
                            const AnimatedSvgOptions& options = {}, const Style& style = default_style(),
                            AnimatedSvgStats* stats = nullptr);

} // namespace snaxels
