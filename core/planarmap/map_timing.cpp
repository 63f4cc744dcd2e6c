#include "snaxels/planarmap/map_timing.h"

#include "snaxels/planarmap/planar_map.h"

#include <algorithm>
#include <chrono>

#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/planarmap/snaxel_map.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {

double median_of(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

TrackedMapTiming time_tracked_snaxel_map(const MeshTopology& topo, const MeshReport& report, int frames,
                                         const glm::dvec3& view_dir, const glm::dvec3& up, int size, double k) {
    const SnaxelEngine engine(topo);
    const RayScene rays(topo);
    const glm::dvec3 centre = report.centre();
    const double radius = 0.5 * glm::length(report.bbox_max - report.bbox_min);
    EngineOptions options;
    options.check_invariants = false;
    ContourTracker visual(topo, ContourSpec{}, options), shadow(topo, {ContourKind::Shadow, 0.0}, options),
        iso(topo, {ContourKind::Isophote, k}, options);
    TrackedMapTiming out;
    for (int f = 0; f < frames; ++f) {
        Camera cam;
        cam.up = up;
        cam.view_dir = glm::rotate(glm::normalize(view_dir), glm::radians(double(f)), glm::normalize(up));
        const Light light = default_light(cam);
        const auto t0 = std::chrono::steady_clock::now();
        // The three kinds track independently: one thread each.
        ContourTracker* trackers[3] = {&visual, &shadow, &iso};
        const TrackedFrame* tracked[3] = {};
        parallel_for(3, [&](std::size_t i) { tracked[i] = &trackers[i]->step(cam, light); }, 1);
        const auto t1 = std::chrono::steady_clock::now();
        // The map as the product builds it: the snaxel map made a partition.
        const ImageProjection proj(cam, centre, radius, size, size);
        const PlanarMap map = build_planar_map(PlanarMapKind::Snaxel, engine,
                                               {&tracked[0]->contour, &tracked[1]->contour, &tracked[2]->contour},
                                               &rays, proj, cam, light);
        const auto t2 = std::chrono::steady_clock::now();
        out.regions += map.regions.size();
        if (f == 0) continue; // tracking from scratch
        out.map_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
        out.frame_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t0).count());
    }
    return out;
}

} // namespace snaxels
