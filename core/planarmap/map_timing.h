#pragma once
/// Timing the snaxel-defined planar map while tracking, as an animation
/// builds it: a turntable (1 degree per frame about the view's up axis)
/// tracking the visual, shadow and one isophote contour each frame (one
/// thread each), then the map from them. Shared by `snaxels-bench` and
/// `snaxels-cli bench --planar-map`.

#include <cstddef>
#include <vector>

#include "snaxels/mesh/build.h"
#include "snaxels/mesh/topology.h"

namespace snaxels {

struct TrackedMapTiming {
    std::vector<double> map_ms;   ///< per frame after the first: the map alone
    std::vector<double> frame_ms; ///< per frame after the first: tracking plus the map
    std::size_t regions = 0;      ///< over every frame
};

/// @p frames frames of the turntable on @p topology (whose mesh's report is
/// @p report) seen along @p view_dir with @p up, at @p size x @p size pixels,
/// the isophote at @p k. The first frame (tracking from scratch) is left out.
TrackedMapTiming time_tracked_snaxel_map(const MeshTopology& topology, const MeshReport& report, int frames,
                                         const glm::dvec3& view_dir, const glm::dvec3& up, int size, double k);

/// The median of @p values (0 when empty).
double median_of(std::vector<double> values);

} // namespace snaxels
