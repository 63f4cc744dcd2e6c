// Hidden-line classification: the BVH build, and QI of every snaxel plus the
// bisection of every QI change, for the visual and shadow contours of a mesh.

#include <benchmark/benchmark.h>

#include "snaxels/mesh/import.h"
#include "snaxels/visibility/visibility.h"

using namespace snaxels;

namespace {

struct Scene {
    LoadedMesh mesh;
    MeshTopology topology;
    Camera camera;
    std::vector<ContourResult> contours;
};

const Scene& horse() {
    static const Scene scene = [] {
        Scene s{import_mesh(std::string(SNAXELS_TEST_ASSETS) + "/horse.ply"), {}, {}, {}};
        s.topology = build_topology(s.mesh.mesh);
        s.camera.view_dir = glm::normalize(glm::dvec3(1.0, 0.2, 0.3));
        s.camera.up = {0.0, 0.0, 1.0};
        const SnaxelEngine engine(s.topology);
        const Light light = default_light(s.camera);
        s.contours.push_back(engine.compute({}, s.camera, light));
        s.contours.push_back(engine.compute({ContourKind::Shadow, 0.0}, s.camera, light));
        return s;
    }();
    return scene;
}

} // namespace

static void BM_VisibilityBvhBuildHorse(benchmark::State& state) {
    const Scene& s = horse();
    for (auto _ : state) {
        RayScene rays(s.topology);
        benchmark::DoNotOptimize(&rays);
    }
}
BENCHMARK(BM_VisibilityBvhBuildHorse)->Unit(benchmark::kMillisecond);

static void BM_VisibilityRefitHorse(benchmark::State& state) {
    const Scene& s = horse();
    RayScene rays(s.topology);
    for (auto _ : state) rays.refit(s.topology); // the same pose: the upload and refit are what is timed
}
BENCHMARK(BM_VisibilityRefitHorse)->Unit(benchmark::kMillisecond);

// Classification alone (BVH built once outside the loop).
static void BM_VisibilityClassifyHorseVisualShadow(benchmark::State& state) {
    const Scene& s = horse();
    const SnaxelEngine engine(s.topology);
    const RayScene rays(s.topology);
    const VisibilitySampler sampler(rays, s.camera);
    std::size_t samples = 0;
    for (auto _ : state) {
        samples = 0;
        for (const ContourResult& r : s.contours) {
            ContourVisibility v = sampler.classify(engine, r);
            samples += r.fronts.snaxels.size();
            benchmark::DoNotOptimize(v.loops.data());
        }
    }
    state.counters["samples"] = double(samples);
}
BENCHMARK(BM_VisibilityClassifyHorseVisualShadow)->Unit(benchmark::kMillisecond)->UseRealTime();

// Build and classification together: what one still frame costs.
static void BM_VisibilityBuildAndClassifyHorse(benchmark::State& state) {
    const Scene& s = horse();
    const SnaxelEngine engine(s.topology);
    for (auto _ : state) {
        const RayScene rays(s.topology);
        const VisibilitySampler sampler(rays, s.camera);
        for (const ContourResult& r : s.contours) {
            ContourVisibility v = sampler.classify(engine, r);
            benchmark::DoNotOptimize(v.loops.data());
        }
    }
}
BENCHMARK(BM_VisibilityBuildAndClassifyHorse)->Unit(benchmark::kMillisecond)->UseRealTime();
