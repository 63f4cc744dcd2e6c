#pragma once
// Internal to core/export: the animated paths of an animation as geometry,
// between the tracker's frames and the file formats that write them (SMIL
// in the animated SVG, shape keyframes in Lottie). A path is a list of
// segments; within one, every key has the same subpaths, each with the
// same vertex count and closedness, so a player interpolates between keys.
// Consecutive segments meet at keys that draw the same shape a thousandth
// of a frame apart (see path_keys.h).

#include <string>
#include <vector>

#include "core/export/animated_svg.h"
#include "core/export/path_keys.h"

namespace snaxels {

struct PathSegment {
    std::vector<double> times;    ///< frames, increasing (the kept keys)
    std::vector<anim::Shape> shapes; ///< parallel to times
    /// Per subpath, the Bézier knots (indices into its points) when the
    /// stroke is smoothed; empty: each subpath is the polyline of its points.
    std::vector<std::vector<std::size_t>> knots;
    std::size_t vertices() const; ///< knots (or points) over the subpaths
};

struct AnimatedPathData {
    bool fill = false;
    // Strokes: the contour kind (index into the drawing's contours), visible
    // (0) or hidden (1), and whether this is the kind's path of one-frame
    // contours.
    std::size_t contour = 0;
    int cls = 0;
    bool brief = false;
    // Fills: the region class's name and its style.
    std::string region_class;
    const RegionStyle* region = nullptr;
    int first = 0, last = 0; ///< frames shown
    std::vector<PathSegment> segments;
    /// Surface-fastened dashes: the dash offset (pixels) at key times (frames).
    std::vector<double> dash_times, dash_values;
};

/// The stroke paths of contour @p c of @p frames (appended to @p out).
void stroke_paths(const std::vector<AnimationFrame>& frames, std::size_t c, const Style& style,
                  const AnimatedSvgOptions& options, std::vector<AnimatedPathData>& out);

/// The fill paths of every region track of @p frames (appended to @p out).
void fill_paths(const std::vector<AnimationFrame>& frames, const Style& style, const AnimatedSvgOptions& options,
                std::vector<AnimatedPathData>& out);

/// The statistics of @p path, drawn with @p keyframes keys, for --stats.
PathStats path_stats(const AnimatedPathData& path, const std::string& label, std::size_t keyframes);
/// The totals of @p stats' path list.
void sum_stats(AnimatedSvgStats& stats);

/// Every path of the animation: the fills, then each contour kind's strokes.
std::vector<AnimatedPathData> animated_paths(const std::vector<AnimationFrame>& frames, const Style& style,
                                             const AnimatedSvgOptions& options);

} // namespace snaxels
