#pragma once
/// The post-processed planar map (the paper's "Planar Map Generation", first
/// method): the projected regions that the contours bound, clipped with
/// Clipper into non-overlapping image regions, each with its class.
///
/// Front-facing patches (the regions of the visual contour) are taken
/// nearest first; each keeps what no nearer patch already covers. Inside a
/// patch, the regions of the shadow contour, the isophotes (ascending) and
/// the gleams split it into shadow, lit, isophote bands and highlights.

#include <vector>

#include <glm/glm.hpp>

#include "core/scene/camera.h"
#include "core/snaxel/snaxel_engine.h"

namespace snaxels {

enum class RegionClass { Shadow, Lit, Band, Highlight };

const char* region_class_name(RegionClass cls);

struct MapRegion {
    RegionClass cls = RegionClass::Lit;
    double k = 0.0;  ///< band: the isophote level it starts at; highlight: the gleam threshold
    int depth = 0;   ///< depth order of its patch, 0 nearest
    std::vector<std::vector<glm::dvec2>> polygons; ///< image pixels; holes wind the other way (use even-odd)
    double area = 0.0; ///< square pixels
};

struct PostMapInput {
    const ContourResult* visual = nullptr;              ///< required: its regions are the patches
    const ContourResult* shadow = nullptr;              ///< lit where f >= 0; none: the patch is lit
    std::vector<const ContourResult*> isophotes;        ///< ascending k
    const ContourResult* gleam = nullptr;               ///< highlights
};

/// The regions of the map; they do not overlap and cover the projection of
/// the front-facing surface.
std::vector<MapRegion> build_post_map(const SnaxelEngine& engine, const PostMapInput& input,
                                      const ImageProjection& projection, const Camera& camera);

/// Shrinks a region's polygons by @p pixels (morphological erosion, round joins).
std::vector<std::vector<glm::dvec2>> erode(const std::vector<std::vector<glm::dvec2>>& polygons, double pixels);

} // namespace snaxels
