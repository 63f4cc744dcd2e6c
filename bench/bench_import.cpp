// Import and mesh-building throughput. Run: build/bin/snaxels-bench

#include <benchmark/benchmark.h>

#include "snaxels/mesh/import.h"
#include "snaxels/mesh/procedural.h"

using namespace snaxels;

static void BM_ImportHorsePly(benchmark::State& state) {
    const std::string path = std::string(SNAXELS_TEST_ASSETS) + "/horse.ply";
    for (auto _ : state) {
        LoadedMesh m = import_mesh(path);
        benchmark::DoNotOptimize(m.mesh.n_faces());
    }
    state.SetLabel("48485 V, 96966 F");
}
BENCHMARK(BM_ImportHorsePly)->Unit(benchmark::kMillisecond);

static void BM_ImportBunnyObj(benchmark::State& state) {
    const std::string path = std::string(SNAXELS_TEST_ASSETS) + "/stanford-bunny.obj";
    for (auto _ : state) {
        LoadedMesh m = import_mesh(path);
        benchmark::DoNotOptimize(m.mesh.n_faces());
    }
}
BENCHMARK(BM_ImportBunnyObj)->Unit(benchmark::kMillisecond);

// Generating and building (weld, edge counts, halfedge mesh, normals) a
// procedural mesh of about state.range(0) faces.
static void BM_ProceduralTorus(benchmark::State& state) {
    for (auto _ : state) {
        LoadedMesh m = build_mesh(make_torus(static_cast<std::size_t>(state.range(0))), "torus");
        benchmark::DoNotOptimize(m.mesh.n_faces());
    }
    state.counters["faces"] = double(state.range(0));
}
BENCHMARK(BM_ProceduralTorus)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

static void BM_ProceduralBumpySphere1M(benchmark::State& state) {
    for (auto _ : state) {
        LoadedMesh m = build_mesh(make_bumpy_sphere(1'000'000), "bumpy");
        benchmark::DoNotOptimize(m.mesh.n_faces());
    }
}
BENCHMARK(BM_ProceduralBumpySphere1M)->Unit(benchmark::kMillisecond);


