#pragma once
/// The post-processed planar map (the paper's "Planar Map Generation", first
/// method): the projected regions that the contours bound, clipped with
/// Clipper into non-overlapping image regions, each with its class.
///
/// Front-facing patches (the regions of the visual contour) are taken
/// nearest first; each keeps what no nearer patch already covers. Faces
/// turned to the viewer past the visual contour fill the rest of the mesh's
/// outline. Inside a
/// patch, the regions of the shadow contour, the isophotes (ascending) and
/// the gleams split it into shadow, lit, isophote bands and highlights.

#include <vector>

#include <glm/glm.hpp>

#include "snaxels/planarmap/region.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/visibility/ray_scene.h"

namespace snaxels {

struct PostMapInput {
    const ContourResult* visual = nullptr;              ///< required: its regions are the patches
    const ContourResult* shadow = nullptr;              ///< lit where f >= 0; none: the patch is lit
    std::vector<const ContourResult*> isophotes;        ///< ascending k
    std::vector<const ContourResult*> gleams;          ///< ascending k: nested highlight levels
};

/// The regions of the map; they do not overlap and cover the projection of
/// the front-facing surface: the visual contour's patches and, past them,
/// the silhouette band of faces turned to the viewer that the contour of
/// interpolated normals leaves out (classed by their own N.L, depth after
/// every patch). @p light classes that band.
std::vector<MapRegion> build_post_map(const SnaxelEngine& engine, const PostMapInput& input, const RayScene& rays,
                                      const ImageProjection& projection, const Camera& camera, const Light& light);

/// Shrinks a region's polygons by @p pixels (morphological erosion, round joins).
std::vector<std::vector<glm::dvec2>> erode(const std::vector<std::vector<glm::dvec2>>& polygons, double pixels);

} // namespace snaxels
