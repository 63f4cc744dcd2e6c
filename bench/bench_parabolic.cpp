// Parabolic curves (#17): 2,000 view directions over the sphere, the visual
// contour tracked between them, events marked and chained, on the horse
// (97K faces). The target is under 15 s on two cores.
#include <benchmark/benchmark.h>

#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/parabolic.h"
#include "snaxels/mesh/refine.h"

using namespace snaxels;

static void BM_ParabolicHorse(benchmark::State& state) {
    const LoadedMesh m = load_mesh(std::string(SNAXELS_TEST_ASSETS) + "/horse.ply");
    const MeshTopology topo = engine_topology(m.mesh);
    ParabolicOptions options;
    options.samples = int(state.range(0));
    ParabolicResult r;
    for (auto _ : state) r = find_parabolic(topo, options);
    state.counters["view_steps"] = double(r.walks ? options.orders * r.samples : 0);
    state.counters["events"] = double(r.events);
    state.counters["marks"] = double(r.points.size());
    state.counters["curves"] = double(r.curves.size());
}
BENCHMARK(BM_ParabolicHorse)->Arg(2000)->ArgName("samples")->Unit(benchmark::kMillisecond)->Iterations(1);
