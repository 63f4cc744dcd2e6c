// Tracking through animation: a 360-frame horse turntable (1 degree per
// frame). Per-frame tracking against the brute-force extractor on the same
// frames, and the whole export (tracking, hidden lines, animated SVG).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include <glm/gtx/rotate_vector.hpp>

#include "core/animation/pipeline.h"
#include "core/mesh/import.h"
#include "bench/brute_force_contour.h"

using namespace snaxels;

namespace {

const LoadedMesh& horse_mesh() {
    static const LoadedMesh mesh = import_mesh(std::string(SNAXELS_TEST_ASSETS) + "/horse.ply");
    return mesh;
}

Camera horse_camera(int frame) {
    Camera c;
    c.up = {0.0, 0.0, 1.0};
    c.view_dir = glm::rotate(glm::normalize(glm::dvec3(1.0, 0.2, 0.3)), glm::radians(double(frame)), c.up);
    return c;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

} // namespace

// One iteration: the 360 frames, each timed; the median is the counter.
static void BM_TrackHorseTurntable360(benchmark::State& state) {
    const MeshTopology topo = build_topology(horse_mesh().mesh);
    EngineOptions options;
    options.check_invariants = false;
    std::vector<double> ms;
    for (auto _ : state) {
        ContourTracker tracker(topo, ContourSpec{}, options);
        ms.clear();
        for (int f = 0; f < 360; ++f) {
            const Camera cam = horse_camera(f);
            const auto t0 = std::chrono::steady_clock::now();
            const TrackedFrame& tf = tracker.step(cam, default_light(cam));
            benchmark::DoNotOptimize(tf.contour.fronts.snaxels.data());
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        }
    }
    ms.erase(ms.begin()); // frame 0 starts from scratch
    state.counters["median_frame_ms"] = median(ms);
    state.counters["max_frame_ms"] = *std::max_element(ms.begin(), ms.end());
}
BENCHMARK(BM_TrackHorseTurntable360)->Unit(benchmark::kMillisecond)->Iterations(3);

// The brute-force extractor on the same 360 frames, per frame.
static void BM_BruteForceHorseTurntable360(benchmark::State& state) {
    const MeshTopology topo = build_topology(horse_mesh().mesh);
    std::vector<double> ms;
    for (auto _ : state) {
        ms.clear();
        for (int f = 0; f < 360; f += 10) { // every tenth frame: the figure is per frame
            const Camera cam = horse_camera(f);
            const auto t0 = std::chrono::steady_clock::now();
            auto r = bench::marching_triangles(topo, ContourFunction({}, cam, default_light(cam)), 1);
            benchmark::DoNotOptimize(r.points.data());
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
        }
    }
    state.counters["median_frame_ms"] = median(ms);
}
BENCHMARK(BM_BruteForceHorseTurntable360)->Unit(benchmark::kMillisecond)->Iterations(1);

// The whole 360-frame export as `snaxels-cli animate` does it.
static void BM_ExportHorseTurntable360(benchmark::State& state) {
    AnimationJob job;
    job.animation.kind = AnimationSpec::Kind::Turntable;
    job.animation.degrees_per_frame = 1.0;
    job.animation.frames = 360;
    job.camera = horse_camera(0);
    job.light = default_light(job.camera);
    job.engine.check_invariants = false;
    job.visibility = state.range(0) != 0;
    std::size_t bytes = 0;
    for (auto _ : state) {
        const AnimationOutput out = run_animation(horse_mesh(), "", job);
        bytes = out.document.size();
    }
    state.counters["svg_bytes"] = double(bytes);
}
BENCHMARK(BM_ExportHorseTurntable360)->Arg(1)->Arg(0)->ArgName("visibility")->Unit(benchmark::kMillisecond)->Iterations(1);
