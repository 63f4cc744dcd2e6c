// From-scratch contour extraction: the snaxel engine against brute-force
// marching triangles over every edge (the tests' oracle), on the same mesh,
// view and light. Meshes are loaded once per benchmark, outside the timing.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>

#include "bench/brute_force_contour.h"
#include "snaxels/animation/frame_driver.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/curvature.h"
#include "snaxels/snaxel/snaxel_engine.h"

using namespace snaxels;

namespace {

struct Prepared {
    LoadedMesh mesh;
    MeshTopology topology;
};

const Prepared& prepared(const std::string& spec) {
    static std::map<std::string, std::unique_ptr<Prepared>> cache;
    auto& slot = cache[spec];
    if (!slot) {
        const std::string path =
            spec.rfind("proc:", 0) == 0 ? spec : std::string(SNAXELS_TEST_ASSETS) + "/" + spec;
        slot = std::make_unique<Prepared>(Prepared{load_mesh(path), {}});
        slot->topology = build_topology(slot->mesh.mesh);
    }
    return *slot;
}

Camera view() {
    Camera c;
    c.view_dir = glm::normalize(glm::dvec3(0.4, -0.3, 1.0));
    return c;
}

void engine_bench(benchmark::State& state, const std::string& spec, ContourSpec kind) {
    const Prepared& p = prepared(spec);
    const SnaxelEngine engine(p.topology);
    EngineOptions options;
    options.check_invariants = false;
    const Camera cam = view();
    const Light light = default_light(cam);
    std::size_t snaxels = 0;
    for (auto _ : state) {
        ContourResult r = engine.compute(kind, cam, light, options);
        snaxels = r.fronts.snaxels.size();
        benchmark::DoNotOptimize(r.fronts.snaxels.data());
    }
    state.counters["faces"] = double(p.topology.n_faces());
    state.counters["snaxels"] = double(snaxels);
}

void oracle_bench(benchmark::State& state, const std::string& spec, ContourSpec kind) {
    const Prepared& p = prepared(spec);
    const Camera cam = view();
    const ContourFunction f(kind, cam, default_light(cam));
    for (auto _ : state) {
        // The same 8-step bracketing scan as the engine uses for non-visual kinds.
        auto r = bench::marching_triangles(p.topology, f, kind.kind == ContourKind::Visual ? 1 : 8);
        benchmark::DoNotOptimize(r.points.data());
    }
    state.counters["faces"] = double(p.topology.n_faces());
}

void topology_bench(benchmark::State& state, const std::string& spec) {
    const Prepared& p = prepared(spec);
    for (auto _ : state) {
        MeshTopology t = build_topology(p.mesh.mesh);
        benchmark::DoNotOptimize(t.edge_vertices().data());
    }
}

} // namespace

BENCHMARK_CAPTURE(engine_bench, horse_visual, "horse.ply", ContourSpec{})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(oracle_bench, horse_visual, "horse.ply", ContourSpec{})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(engine_bench, horse_shadow, "horse.ply", ContourSpec{ContourKind::Shadow, 0.0})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(oracle_bench, horse_shadow, "horse.ply", ContourSpec{ContourKind::Shadow, 0.0})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(engine_bench, horse_gleam, "horse.ply", ContourSpec{ContourKind::Gleam, 0.9})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(engine_bench, bumpy1M_visual, "proc:bumpy:1000000", ContourSpec{})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(oracle_bench, bumpy1M_visual, "proc:bumpy:1000000", ContourSpec{})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(engine_bench, torus1M_visual, "proc:torus:1000000", ContourSpec{})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(topology_bench, horse, "horse.ply")->Unit(benchmark::kMillisecond);

// Per-vertex curvature tensors of one pose (#21: under 30 ms on the horse).
void curvature_bench(benchmark::State& state, const std::string& spec) {
    const Prepared& p = prepared(spec);
    for (auto _ : state) {
        CurvatureField field = vertex_curvatures(p.topology);
        benchmark::DoNotOptimize(field.k1.data());
    }
    state.counters["vertices"] = double(p.topology.n_vertices());
}
BENCHMARK_CAPTURE(curvature_bench, horse, "horse.ply")->Unit(benchmark::kMillisecond);

// The pose's curvature as suggestive contours read it: the tensors smoothed
// (require_curvature), on a fresh copy of the pose each time (a copy keeps none).
void pose_curvature_bench(benchmark::State& state, const std::string& spec) {
    const Prepared& p = prepared(spec);
    for (auto _ : state) {
        const MeshTopology fresh = p.topology.posed(std::make_shared<const MeshPose>(*p.topology.pose()));
        const auto field = require_curvature(fresh);
        benchmark::DoNotOptimize(field->k1.data());
    }
    state.counters["vertices"] = double(p.topology.n_vertices());
}
BENCHMARK_CAPTURE(pose_curvature_bench, horse, "horse.ply")->Unit(benchmark::kMillisecond);

// A moving mesh's curvature (issue 38: at most 10 ms a frame): Assimp's
// Wuson walking through 360 frames of its clip, each frame a new pose of
// the engine's (refined) topology whose curvature suggestive contours need,
// computed as the export computes it (require_curvature). The counter is
// the median over the frames; poses are made outside the timing.
static void BM_ClipCurvatureWuson360(benchmark::State& state) {
    const std::string path = std::string(SNAXELS_TEST_ASSETS) + "/anim/Testwuson.X";
    const LoadedMesh mesh = load_mesh(path);
    const MeshTopology rest = engine_topology(mesh);
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Clip;
    spec.frames = 360;
    const Camera camera;
    FrameDriver driver(spec, mesh, rest, camera, default_light(camera), mesh.report.centre(), path);
    std::vector<double> ms;
    for (auto _ : state) {
        ms.clear();
        for (int k = 0; k < spec.frames; ++k) {
            const FramePose pose = driver.pose(k);
            const auto t0 = std::chrono::steady_clock::now();
            const auto field = require_curvature(pose.mesh);
            ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
            benchmark::DoNotOptimize(field->k1.data());
        }
    }
    std::sort(ms.begin(), ms.end());
    state.counters["median_frame_ms"] = ms[ms.size() / 2];
    state.counters["vertices"] = double(rest.n_vertices());
}
BENCHMARK(BM_ClipCurvatureWuson360)->Unit(benchmark::kMillisecond)->Iterations(1);
