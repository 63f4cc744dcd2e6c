#pragma once
// Internal to core/export: the animated paths of an animation as geometry,
// between the tracker's frames and the file formats that write them (SMIL
// in the animated SVG, shape keyframes in Lottie). A path is a list of
// segments; within one, every key has the same subpaths, each with the
// same vertex count and closedness, so a player interpolates between keys.
// Consecutive segments meet at keys that draw the same shape a thousandth
// of a frame apart (see path_keys.h).

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "snaxels/export/animated_svg.h"
#include "snaxels/export/detail/animated_strokes.h"
#include "snaxels/export/detail/path_keys.h"

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
    // or hidden, and whether this is the kind's path of one-frame contours.
    std::size_t contour = 0;
    StrokeClass cls = StrokeClass::Visible;
    bool brief = false;
    /// Strokes: the object the contour lies on where it starts (DrawnLoop::object),
    /// -1 for none (no parts, or the path of brief contours).
    std::int32_t object = -1;
    // Fills: the region class's name and its style.
    std::string region_class;
    const RegionStyle* region = nullptr;
    std::string fill_colour; ///< the region's fill (its material's with fill="material")
    int first = 0, last = 0; ///< frames shown
    /// Strokes: the contour sequence; fills: the region track: what a path
    /// follows, so that a path written in pieces (AnimationWriter) goes on
    /// from piece to piece.
    std::uint64_t track = 0;
    std::vector<PathSegment> segments;
};

/// When @p frames are a chunk of a longer animation (AnimationWriter): its
/// first frame is the last of the chunk before, its last the first of the
/// next. A one-frame contour there is drawn by one chunk only.
struct ChunkContext {
    /// Not the last chunk: one-frame contours at the last frame are left to the next.
    bool defer_last = false;
    /// (contour, sequence) of the contours the chunk before drew at the first frame.
    std::set<std::pair<std::size_t, std::uint64_t>> drawn_first;
};

/// The stroke paths of contour @p c of @p frames (appended to @p out).
void stroke_paths(const std::vector<AnimationFrame>& frames, std::size_t c, const Style& style,
                  const AnimatedSvgOptions& options, std::vector<AnimatedPathData>& out,
                  const ChunkContext* chunk = nullptr);

/// The fill paths of every region track of @p frames (appended to @p out).
void fill_paths(const std::vector<AnimationFrame>& frames, const Style& style, const AnimatedSvgOptions& options,
                std::vector<AnimatedPathData>& out);

/// The totals of @p stats' path list.
void sum_stats(AnimatedSvgStats& stats);

/// Lottie pieces (core/export/lottie.cpp) for AnimationWriter: a segment's
/// shape layer after its name (`,"ip":..,"op":..,...}`, empty when it draws
/// nothing; @p keys counts its keyframes), a layer's start up to its name,
/// the document's start and its background layer.
std::string lottie_layer_body(const PathSegment& seg, double ip, double op, const AnimatedPathData& path,
                              const StrokeStyle& stroke, std::size_t& keys);
std::string lottie_layer_start(std::size_t ind, const std::string& name);
std::string lottie_document_start(double fps, std::size_t frames, int width, int height);
std::string lottie_background_layer(const Style& style, std::size_t frames, int width, int height, std::size_t ind);

/// Every path of the animation: the fills, then each contour kind's strokes.
std::vector<AnimatedPathData> animated_paths(const std::vector<AnimationFrame>& frames, const Style& style,
                                             const AnimatedSvgOptions& options, const ChunkContext* chunk = nullptr);

} // namespace snaxels
