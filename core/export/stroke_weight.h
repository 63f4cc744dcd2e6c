#pragma once
/// Line weight (docs/styles.md, "Line weight"): a stroke parameter that
/// lives on the surface, the width a style gives each point of a line, the
/// wobble of a hand, and lines of varying width as filled outlines.
///
/// The stroke parameter u of a loop is arc length in pixels from a seam.
/// In a still it starts at the loop's first snaxel. Through an animation
/// it is carried by the snaxels' identities (after Kalnins et al. 2003,
/// "Coherent stylized silhouettes"): where a snaxel goes on, its u goes on,
/// and the loop's parameter is refit toward uniform arc length only as fast
/// as kRelaxToUniform says. Taper, wobble and width read it in stills and
/// in every frame of an animation alike, so a frame of an animated export
/// draws what the static frame draws.

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/export/animated_svg.h"
#include "snaxels/mesh/elements.h"
#include "snaxels/export/drawing.h"
#include "snaxels/style/style.h"

namespace snaxels {

/// Each frame, a carried parameter's departure from uniform arc length (the
/// stretch of an open line, a ring's period against its length, the ripple
/// of the departures along the line) moves this fraction of the way back,
/// and no point's parameter by more than half a pixel: the weight of
/// uniformity against coherence. 0 would keep any stretch for ever (u
/// fastened to the snaxels, its spacing drifting as the line grows); 1
/// would refit arc length every frame (the parameter sliding with every
/// change of the line's length).
constexpr double kRelaxToUniform = 0.1;

/// Fills DrawnLoop::u and u_period of every loop of @p contour with arc
/// length from its first snaxel (a still's parameter), unless it has one.
void parameterize_still(DrawnContour& contour);

/// The stroke parameter of one contour kind carried from frame to frame
/// through the snaxels' identities.
/// A point of the surface: parameter t on the edge from vertex a to vertex b.
struct SurfacePoint {
    VertexId a, b;
    double t = 0.0;
};

class StrokeParameter {
  public:
    /// Fills u and u_period of each loop of @p contour (this frame), whose
    /// snaxel identities are @p loops (parallel to contour.loops).
    /// With @p surface (per loop, the surface point of each snaxel) and
    /// @p project (a surface point in this frame's image), a snaxel that
    /// goes on hands its u to where the surface point it stood on last
    /// frame now shows on the line, not to itself: a snaxel slides along
    /// its edge as the contour moves over the surface, the surface does not.
    void step(DrawnContour& contour, const std::vector<AnimatedLoop>& loops,
              const std::vector<std::vector<SurfacePoint>>* surface = nullptr,
              const std::function<glm::dvec2(const SurfacePoint&)>& project = {});

  private:
    struct Carried {
        double u;
        std::uint32_t loop;
        SurfacePoint where;
    };
    std::unordered_map<std::uint64_t, Carried> previous_;
    std::vector<double> previous_period_; ///< per loop of the last frame; 0: open
    std::vector<double> previous_stretch_;
};

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

/// One dash of a line: the pattern's dash @p id (k times its number of
/// dashes plus the dash's place in it, k the pattern's repeat) over
/// [from, to] of a measure along the line.
struct Dash {
    std::int64_t id = 0;
    double from = 0.0, to = 0.0;
    double length = 0.0; ///< the pattern's length for this dash
};

/// The stretches of a line where @p pattern is on, the pattern laid along
/// a measure m given at arc lengths @p arcs (@p m linear between them): the
/// stroke parameter for dashes fastened to the surface, arc length from a
/// run's start for screen dashes. m may run backwards (a dash is where m is
/// on, whichever way the line goes); round a loop's seam, where m falls by
/// about @p period, it comes round again. Returns [from, to] in arc length
/// with the dash's id; where m passes one dash twice, the second piece's id
/// is offset by 2^40 (ids stay unique).
std::vector<Dash> dash_spans(const std::vector<double>& arcs, const std::vector<double>& m,
                             const std::vector<double>& pattern, double period);

/// The pieces of polyline @p q (arc length @p arcs at its points) over
/// @p spans: each a polyline from its start through the points inside it
/// to its end.
std::vector<std::vector<glm::dvec2>> dash_pieces(const std::vector<glm::dvec2>& q, const std::vector<double>& arcs,
                                                 const std::vector<Dash>& spans);

/// Whether @p stroke's dashes are drawn as pieces of the line (geometry)
/// in animations: a dashed line of constant width, unless its dashes are
/// screen dashes and @p screen_dash_array keeps them a dash array (Lottie,
/// where a shape per dash would multiply the file). A path with a dash
/// array restarts it at every subpath, which differs from the static
/// frame's wherever the subpaths differ.
inline bool dashes_as_geometry(const StrokeStyle& stroke, bool screen_dash_array = false) {
    return !stroke.dash.empty() && !stroke.variable_width() && (stroke.dash_on_surface || !screen_dash_array);
}

/// The centre line @p centre (open, or a closed ring) displaced across
/// itself by the style's wobble at @p seconds (boil). @p period: the
/// parameter's period on a closed loop (the noise wraps there smoothly).
void wobble(const StrokeStyle& style, std::vector<StrokePoint>& centre, bool closed, double period, double seconds);

/// The filled outline of a line of varying width along @p centre, as
/// @p style says (taper toward the ends of an open run, width-by, the
/// calligraphic nib; caps as `cap` says, round or flat; joins without
/// spikes). An open run gives one closed polygon; a closed ring two (the
/// outer one and the inner one reversed, a hole under the nonzero rule).
/// Vertex counts depend only on the centre's point count and closedness,
/// so outlines of one subpath interpolate from key to key.
void stroke_outline(const StrokeStyle& style, const std::vector<StrokePoint>& centre, bool closed,
                    std::vector<std::vector<glm::dvec2>>& out);

} // namespace snaxels
