#pragma once
/// The stroke parameter (docs/styles.md, "Line weight"): u of a loop is arc
/// length in pixels from a seam. In a still it starts at the loop's first
/// snaxel. Through an animation it is carried by the snaxels' identities
/// (after Kalnins et al. 2003, "Coherent stylized silhouettes"): where a
/// snaxel goes on, its u goes on, and the loop's parameter is refit toward
/// uniform arc length only as fast as kRelaxToUniform says. Taper, wobble,
/// width and surface dashes read it in stills and in every frame of an
/// animation alike, so a frame of an animated export draws what the static
/// frame draws.

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/export/animated_svg.h"
#include "snaxels/export/drawing.h"
#include "snaxels/mesh/elements.h"

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

} // namespace snaxels
