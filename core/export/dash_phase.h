#pragma once
/// Surface-fastened dashes (after Kalnins et al. 2003, "Coherent stylized
/// silhouettes"): the phase of a dash pattern along each loop is carried
/// from frame to frame by the surface, so dashes stay where they are on the
/// surface as it turns instead of sliding along the screen.

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/mesh/elements.h"

namespace snaxels {

/// A point of the surface: parameter t on the edge from vertex a to vertex b.
struct SurfacePoint {
    VertexId a, b;
    double t = 0.0;
};

/// One loop of one frame: its projected polyline and the surface point of
/// each of its vertices.
struct PhaseLoop {
    std::vector<glm::dvec2> q;
    std::vector<SurfacePoint> surface;
    bool closed = true;
};

class SurfaceDashPhase {
  public:
    /// @p period: the dash pattern's length in pixels.
    explicit SurfaceDashPhase(double period) : period_(period) {}

    /// The dash phase (pixels into the pattern) at the first vertex of each
    /// loop of this frame. @p project maps a surface point to this frame's
    /// image (with this frame's mesh positions and camera). Each loop takes
    /// the phase the previous frame's dashes have where the surface carried
    /// them onto it; a loop with no such history starts at 0.
    std::vector<double> step(const std::vector<PhaseLoop>& loops,
                             const std::function<glm::dvec2(const SurfacePoint&)>& project);

    double period() const { return period_; }

  private:
    struct Sample {
        SurfacePoint where;
        double phase;
    };
    double period_;
    std::vector<Sample> previous_;
};

/// Arc length from each vertex of a polyline to its first vertex.
std::vector<double> arc_lengths(const std::vector<glm::dvec2>& q);

} // namespace snaxels
