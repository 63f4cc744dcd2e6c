#pragma once
/// Converged contours as a drawing: every loop's snaxels in 3-D and in
/// image pixels, grouped by contour kind. What the exporters write.

#include <vector>

#include <glm/glm.hpp>

#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

/// A stretch of a loop with one quantitative invisibility, projected.
struct DrawnRun {
    int qi = 0;
    bool closed = false;
    std::vector<glm::dvec2> q;
};

struct DrawnLoop {
    bool closed = true;
    std::vector<glm::dvec3> p; ///< snaxel positions in the mesh's coordinates
    std::vector<glm::dvec2> q; ///< their projections in image pixels
    std::vector<int> qi;       ///< per snaxel; empty when visibility was not computed
    std::vector<glm::dvec2> change_before; ///< per snaxel, where qi changes before it (see LoopVisibility)
    std::vector<DrawnRun> runs; ///< empty when visibility was not computed
    /// Phase (pixels into the dash pattern) at q[0] for surface-fastened dashes.
    double dash_phase = 0.0;
};

struct DrawnContour {
    ContourSpec spec;
    std::vector<DrawnLoop> loops;
};

struct Drawing {
    int width = 800, height = 800;
    /// Visibility was computed: loops carry their QI and runs, hidden runs
    /// included. Without it, only contours that leave parts out (suggestive
    /// contours) have runs, of QI 0 and kNotDrawn; the others none.
    bool hidden_lines = false;
    std::vector<DrawnContour> contours;
};

/// Whether @p drawing has hidden lines to draw: visibility was computed
/// (hidden_lines), or a loop has a snaxel of QI above 0 (a drawing made by
/// hand, with its QIs filled in).
bool has_hidden_lines(const Drawing& drawing);

/// Projects every loop of @p results with @p projection; with @p visibility
/// (parallel to @p results) the loops carry their QI and runs too; without
/// it, a contour that leaves parts out is cut into runs by drawn_parts().
Drawing make_drawing(const SnaxelEngine& engine, const std::vector<ContourResult>& results,
                     const ImageProjection& projection,
                     const std::vector<ContourVisibility>* visibility = nullptr);

} // namespace snaxels
