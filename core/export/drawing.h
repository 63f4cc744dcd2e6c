#pragma once
/// Converged contours as a drawing: every loop's snaxels in 3-D and in
/// image pixels, grouped by contour kind. What the exporters write.

#include <vector>

#include <glm/glm.hpp>

#include "core/scene/camera.h"
#include "core/snaxel/snaxel_engine.h"

namespace snaxels {

struct DrawnLoop {
    bool closed = true;
    std::vector<glm::dvec3> p; ///< snaxel positions in the mesh's coordinates
    std::vector<glm::dvec2> q; ///< their projections in image pixels
};

struct DrawnContour {
    ContourSpec spec;
    std::vector<DrawnLoop> loops;
};

struct Drawing {
    int width = 800, height = 800;
    std::vector<DrawnContour> contours;
};

/// Projects every loop of @p results with @p projection.
Drawing make_drawing(const SnaxelEngine& engine, const std::vector<ContourResult>& results,
                     const ImageProjection& projection);

} // namespace snaxels
