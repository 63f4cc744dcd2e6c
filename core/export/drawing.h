#pragma once
/// Converged contours as a drawing: every loop's snaxels in 3-D and in
/// image pixels, grouped by contour kind. What the exporters write.

#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/mesh/parts.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

/// A stretch of a loop with one quantitative invisibility, projected.
struct DrawnRun {
    int qi = 0;
    bool closed = false;
    std::vector<glm::dvec2> q;
    /// The loop index of the first snaxel among q; q[0] is the change point
    /// on the segment before it when from_change (VisibilityRun).
    std::size_t first = 0;
    bool from_change = false;
};

struct DrawnLoop {
    bool closed = true;
    std::vector<glm::dvec3> p; ///< snaxel positions in the mesh's coordinates
    std::vector<glm::dvec2> q; ///< their projections in image pixels
    std::vector<int> qi;       ///< per snaxel; empty when visibility was not computed
    std::vector<glm::dvec2> change_before; ///< per snaxel, where qi changes before it (see LoopVisibility)
    std::vector<DrawnRun> runs; ///< empty when visibility was not computed
    /// The stroke parameter (core/export/stroke_parameter.h) per snaxel, for
    /// styles whose strokes read it (wobble, lines of varying width, dashes
    /// fastened to the surface):
    /// arc length in pixels from a seam, carried by the surface through an
    /// animation; empty when nothing reads it. On a closed loop it runs
    /// from 0 to u_period (the seam's value at both ends).
    std::vector<double> u;
    double u_period = 0.0;
    /// Per snaxel, what width-by follows (0: width-min, 1: width-max);
    /// empty without width-by.
    std::vector<float> weight;
    /// With Drawing::parts: the objects and materials (indices, ascending)
    /// of the faces beside the loop's snaxels' edges: the parts it lies on.
    std::vector<std::uint32_t> objects, materials;
    /// With Drawing::parts: the object most of the loop's snaxels lie on
    /// (the one exports group it under); -1 without parts.
    std::int32_t object = -1;
};

struct DrawnContour {
    ContourSpec spec;
    std::vector<DrawnLoop> loops;
};

struct Drawing {
    int width = 800, height = 800;
    /// The frame's time in seconds (an animation's frame over its rate):
    /// what the wobble's boil reads.
    double seconds = 0.0;
    /// Visibility was computed: loops carry their QI and runs, hidden runs
    /// included. Without it, only contours that leave parts out (suggestive
    /// contours) have runs, of QI 0 and kNotDrawn; the others none.
    bool hidden_lines = false;
    std::vector<DrawnContour> contours;
    /// The scene's parts, when the mesh has them; with several objects or
    /// materials (FaceParts::several) loops say which they lie on.
    std::shared_ptr<const FaceParts> parts;
};

/// Whether @p drawing's strokes are grouped by object in exports: it has
/// parts, and more than one object.
inline bool groups_by_object(const Drawing& drawing) { return drawing.parts && drawing.parts->objects.size() > 1; }

/// Whether @p drawing's outputs name parts: the mesh has several objects
/// or materials (a mesh of one of each writes what it did before parts).
inline bool names_parts(const Drawing& drawing) { return drawing.parts && drawing.parts->several(); }

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
