#pragma once
/// Animated SVG whose paths move (the paper's "3-D SVG Animation"): one
/// visible and one hidden <path> per contour sequence, shown for the
/// sequence's whole life, its geometry animated with SMIL <animate>
/// (values, keyTimes, calcMode="linear"). Each loop is parameterized by arc
/// length with u = 0 carried by the snaxel identities; visibility runs are
/// the path's subpaths, on a grid fixed in u. A path's life is a chain of
/// segments of one vertex set each, joined by keys a thousandth of a frame
/// apart that draw the same shape (core/export/path_keys.h).
/// Region fills animate the same way: one <path> per region track for the
/// region's whole life, its loops (outlines and holes) growing from and
/// shrinking to points as they appear and close.

#include <cstdint>
#include <string>
#include <vector>

#include "snaxels/export/drawing.h"
#include "snaxels/planarmap/post_map.h"
#include "snaxels/style/style.h"

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
    /// Visible or hidden stretches shorter than this (pixels) take their
    /// neighbour's visibility: flicker at T-junctions, not lines.
    double min_run_px = 3.0;
    /// Where a visibility run's end glides between two frames along a bend of
    /// the curve deeper than this (pixels), interpolating would cut across
    /// the bend: the path holds its shape until the next frame and switches
    /// then instead.
    double max_sweep_px = 1.0;
    /// Screen dashes stay a dash array instead of pieces of the line
    /// (dashes_as_geometry): Lottie's choice.
    bool screen_dash_array = false;
};

/// One path of the animated SVG, for --stats.
struct PathStats {
    std::string kind;  ///< "stroke" or "fill"
    std::string label; ///< the contour kind's label (strokes) or the region class (fills)
    std::string part;  ///< "visible", "hidden" or "fill"
    int first = 0, last = 0;      ///< frames shown
    std::size_t frames_shown = 0;
    std::size_t vertices = 0;     ///< the most any of its keyframes has
    std::size_t keyframes = 0;
    std::size_t segments = 0;     ///< stretches of one vertex set
    std::string object; ///< strokes in a scene of several objects: the object's path (else empty)
};

struct AnimatedSvgStats {
    std::size_t paths = 0;
    std::size_t keyframes = 0;        ///< kept, over all paths
    std::size_t frames_spanned = 0;   ///< frames the paths are shown in, summed
    std::size_t vertices = 0;         ///< path vertices, summed over paths
    std::vector<PathStats> path_stats;
};

/// The animated SVG of @p frames played at @p fps, looping, drawn as @p style says.
std::string to_animated_svg(const std::vector<AnimationFrame>& frames, double fps,
                            const AnimatedSvgOptions& options = {}, const Style& style = default_style(),
                            AnimatedSvgStats* stats = nullptr);

} // namespace snaxels
