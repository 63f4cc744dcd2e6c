// The snaxel-defined planar map while tracking: a 120-frame horse turntable
// (1 degree per frame), the visual, shadow and one isophote contour tracked
// each frame (in parallel, as the animation pipeline does), then the
// visible-surface map built from them. The counters
// are per frame: the map alone, and tracking plus map.

#include <benchmark/benchmark.h>

#include <algorithm>

#include "snaxels/mesh/import.h"
#include "snaxels/planarmap/map_timing.h"

using namespace snaxels;

static void BM_SnaxelMapHorseTurntable(benchmark::State& state) {
    const LoadedMesh mesh = import_mesh(std::string(SNAXELS_TEST_ASSETS) + "/horse.ply");
    const MeshTopology topo = build_topology(mesh.mesh);
    TrackedMapTiming timing;
    for (auto _ : state) {
        timing = time_tracked_snaxel_map(topo, mesh.report, 120, {1.0, 0.2, 0.3}, {0.0, 0.0, 1.0}, 800, 0.5);
        benchmark::DoNotOptimize(timing.regions);
    }
    state.counters["map_median_ms"] = median_of(timing.map_ms);
    state.counters["map_max_ms"] = *std::max_element(timing.map_ms.begin(), timing.map_ms.end());
    state.counters["frame_median_ms"] = median_of(timing.frame_ms);
    state.counters["regions_per_frame"] = double(timing.regions) / 120.0;
}
BENCHMARK(BM_SnaxelMapHorseTurntable)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
