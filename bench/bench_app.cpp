// The application's update path (ui/contour_overlay: what the 3-D view and
// the SVG pane show after each camera step) while the user orbits the horse
// one degree at a time: per-step medians and 95th percentiles, with the
// shading-lines preset (five kinds, hidden lines) and the toon preset
// (fills from the snaxel map); and the same on a noisy 100K-face scan.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <ctime>

#include "snaxels/mesh/import.h"
#include "snaxels/scene/orbit.h"
#include "snaxels/style/style.h"
#include "ui/contour_overlay.h"

using namespace snaxels;

namespace {

/// The process's CPU time so far (every thread, waiting workers' spinning too), ms.
double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

double percentile(std::vector<double> v, double p) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[std::min(v.size() - 1, std::size_t(p * double(v.size())))];
}

void orbit(benchmark::State& state, const std::string& path, const char* style_file) {
    const LoadedMesh mesh = load_mesh(path);
    const Style style = load_style(std::string(SNAXELS_STYLES_DIR) + "/" + style_file, nullptr);
    const glm::dvec3 centre = 0.5 * (mesh.report.bbox_min + mesh.report.bbox_max);
    const double radius = 0.5 * glm::length(mesh.report.bbox_max - mesh.report.bbox_min);
    std::vector<double> ms, cpu;
    std::size_t snaxels = 0;
    for (auto _ : state) {
        const std::shared_ptr<ui::ContourScene> scene = ui::make_contour_scene(mesh, path);
        OrbitView view = framing_view(centre, radius);
        ms.clear();
        cpu.clear();
        for (int step = 0; step <= 120; ++step) {
            const auto t0 = std::chrono::steady_clock::now();
            const double c0 = process_cpu_ms();
            const ui::OverlayResult r = ui::compute_overlay(mesh, *scene, orbit_camera(view), style);
            const double t = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if (step > 0) { // step 0 is the first view, from scratch
                ms.push_back(t);
                cpu.push_back(process_cpu_ms() - c0);
            }
            snaxels = r.snaxels;
            view.yaw += glm::radians(1.0);
        }
    }
    state.counters["median_step_ms"] = percentile(ms, 0.5);
    state.counters["p95_step_ms"] = percentile(ms, 0.95);
    // CPU time over both cores: what the step costs beyond its wait on the slower core.
    state.counters["median_cpu_ms"] = percentile(cpu, 0.5);
    state.counters["snaxels"] = double(snaxels);
}

const std::string kHorse = std::string(SNAXELS_TEST_ASSETS) + "/horse.ply";
const std::string kScan = "proc:scan:100000"; // a noisy scan's many small loops (bench_animation.cpp)

} // namespace

static void BM_AppOrbitHorseShadingLines(benchmark::State& state) { orbit(state, kHorse, "shading-lines.xml"); }
BENCHMARK(BM_AppOrbitHorseShadingLines)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

static void BM_AppOrbitHorseToon(benchmark::State& state) { orbit(state, kHorse, "toon.xml"); }
BENCHMARK(BM_AppOrbitHorseToon)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

static void BM_AppOrbitScanShadingLines(benchmark::State& state) { orbit(state, kScan, "shading-lines.xml"); }
BENCHMARK(BM_AppOrbitScanShadingLines)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

static void BM_AppOrbitScanToon(benchmark::State& state) { orbit(state, kScan, "toon.xml"); }
BENCHMARK(BM_AppOrbitScanToon)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();
