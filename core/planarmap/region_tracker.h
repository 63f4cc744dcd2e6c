#pragma once
/// Region identities across frames, for animated fills: a region continues
/// the previous frame's region of its class (and material) with which it shares the most
/// vertices (snaxel map) or, for the post-processed map, whose centre is
/// nearest. Where regions merge the oldest track goes on. A region that
/// continues none starts a new track; the animated SVG draws each track as
/// one path.

#include <cstdint>
#include <vector>

#include "snaxels/planarmap/planar_map.h"

namespace snaxels {

class RegionTracker {
  public:
    /// The track of each of @p map's regions (parallel to map.regions).
    std::vector<std::uint64_t> step(const PlanarMap& map);

  private:
    struct Summary {
        RegionClass cls;
        double k;
        std::int32_t material;
        std::size_t loops;
        glm::dvec2 centre;
        double area;
    };
    VertexData<std::int32_t> prev_vertex_region_;
    std::vector<Summary> prev_;
    std::vector<std::uint64_t> prev_tracks_;
    std::uint64_t next_ = 0;
};

} // namespace snaxels
