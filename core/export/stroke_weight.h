#pragma once
/// Line weight (docs/styles.md, "Line weight"): the width a style gives
/// each point of a line (width-by), and a loop's stroke points (where,
/// its stroke parameter, its weight) between its snaxels. The parameter is
/// stroke_parameter.h's; dashes are stroke_dashes.h's; the shape a line
/// is drawn as (wobble, outlines) stroke_shape.h's.

#include <vector>

#include <glm/glm.hpp>

#include "snaxels/export/drawing.h"
#include "snaxels/style/style.h"

namespace snaxels {

/// Fills DrawnLoop::weight (0 to 1, toward width-max) for the kinds whose
/// style's strokes have width-by: depth (1 nearest the camera over the
/// bounding sphere of @p centre and @p radius), light (1 where the surface
/// faces away from @p light), curvature (1 where the line bends with a
/// radius of kCurvatureRadiusPx or less), qi (1 at QI 0, 0 from QI 4).
/// @p results: what @p drawing was made from (make_drawing), on @p engine.
void weigh_strokes(Drawing& drawing, const Style& style, const SnaxelEngine& engine,
                   const std::vector<ContourResult>& results, const Camera& camera, const Light& light,
                   const glm::dvec3& centre, double radius);
/// Whether @p style's strokes of @p spec need DrawnLoop::weight.
bool needs_weights(const Style& style, const ContourSpec& spec);
constexpr double kCurvatureRadiusPx = 6.0;

/// The longest step (pixels) between the points a line of varying width or
/// a wobble is drawn through: longer segments (the straight edges of hard
/// surfaces) are subdivided, so that taper, width and noise vary along them.
constexpr double kMaxStrokeStepPx = 3.0;

/// A point of a line's centre: where, its stroke parameter and its weight.
struct StrokePoint {
    glm::dvec2 q;
    double u = 0.0;
    double weight = 1.0;
};

/// Parameter and weight of a loop interpolated at arc length (pixels from
/// its first point): what a point of a run between snaxels takes.
class LoopAttributes {
  public:
    explicit LoopAttributes(const DrawnLoop& loop);
    /// The stroke point at arc @p arc (taken round a closed loop).
    StrokePoint at(double arc) const;
    /// Arc length of the point of the loop nearest @p p.
    double arc_of(const glm::dvec2& p) const;
    double length() const { return length_; }
    /// @p run's points with their parameters and weights, segments longer
    /// than kMaxStrokeStepPx subdivided.
    std::vector<StrokePoint> run(const DrawnRun& run) const;

  private:
    const DrawnLoop& loop_;
    std::vector<double> cum_;
    double length_ = 0.0;
};

} // namespace snaxels
