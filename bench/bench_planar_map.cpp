// The snaxel-defined planar map while tracking: a 120-frame horse turntable
// (1 degree per frame), the visual, shadow and one isophote contour tracked
// each frame (in parallel, as the animation pipeline does), then the
// visible-surface map built from them. The counters
// are per frame: the map alone, and tracking plus map.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include <glm/gtx/rotate_vector.hpp>

#include "core/mesh/import.h"
#include "core/planarmap/snaxel_map.h"
#include "core/snaxel/tracker.h"
#include "core/util/parallel.h"

using namespace snaxels;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

} // namespace

static void BM_SnaxelMapHorseTurntable(benchmark::State& state) {
    const LoadedMesh mesh = import_mesh(std::string(SNAXELS_TEST_ASSETS) + "/horse.ply");
    const MeshTopology topo = build_topology(mesh.mesh);
    const SnaxelEngine engine(topo);
    const RayScene rays(topo);
    const glm::dvec3 centre = 0.5 * (mesh.report.bbox_min + mesh.report.bbox_max);
    const double radius = 0.5 * glm::length(mesh.report.bbox_max - mesh.report.bbox_min);
    EngineOptions options;
    options.check_invariants = false;
    std::vector<double> map_ms, frame_ms;
    std::size_t regions = 0;
    for (auto _ : state) {
        ContourTracker visual(topo, ContourSpec{}, options), shadow(topo, {ContourKind::Shadow, 0.0}, options),
            iso(topo, {ContourKind::Isophote, 0.5}, options);
        map_ms.clear();
        frame_ms.clear();
        for (int f = 0; f < 120; ++f) {
            Camera cam;
            cam.up = {0.0, 0.0, 1.0};
            cam.view_dir = glm::rotate(glm::normalize(glm::dvec3(1.0, 0.2, 0.3)), glm::radians(double(f)), cam.up);
            const Light light = default_light(cam);
            const auto t0 = std::chrono::steady_clock::now();
            // The three kinds track independently: one thread each.
            ContourTracker* trackers[3] = {&visual, &shadow, &iso};
            const TrackedFrame* tracked[3] = {};
            parallel_for(3, [&](std::size_t k) { tracked[k] = &trackers[k]->step(cam, light); }, 1);
            const ContourResult& v = tracked[0]->contour;
            const ContourResult& s = tracked[1]->contour;
            const ContourResult& i = tracked[2]->contour;
            const auto t1 = std::chrono::steady_clock::now();
            SnaxelMapInput in;
            in.visual = &v;
            in.shadow = &s;
            in.isophotes = {&i};
            const ImageProjection proj(cam, centre, radius, 800, 800);
            const SnaxelMap map = build_snaxel_map(engine, in, rays, proj, cam, light);
            const auto t2 = std::chrono::steady_clock::now();
            regions += map.regions.size();
            benchmark::DoNotOptimize(map.regions.data());
            map_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t1).count());
            frame_ms.push_back(std::chrono::duration<double, std::milli>(t2 - t0).count());
        }
    }
    map_ms.erase(map_ms.begin()); // frame 0 tracks from scratch
    frame_ms.erase(frame_ms.begin());
    state.counters["map_median_ms"] = median(map_ms);
    state.counters["map_max_ms"] = *std::max_element(map_ms.begin(), map_ms.end());
    state.counters["frame_median_ms"] = median(frame_ms);
    state.counters["regions_per_frame"] = double(regions) / (120.0 * double(state.iterations()));
}
BENCHMARK(BM_SnaxelMapHorseTurntable)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
