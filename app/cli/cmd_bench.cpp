#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/scene_options.h"
#include "snaxels/error.h"
#include "snaxels/mesh/import.h"
#include "snaxels/planarmap/map_timing.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/snaxel/snaxel_engine.h"

namespace snaxels::cli {
namespace {

struct Timing {
    double min_ms, median_ms;
};

Timing time_it(int repeat, const std::function<void()>& work) {
    std::vector<double> ms;
    for (int i = 0; i < repeat; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        work();
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(ms.begin(), ms.end());
    return {ms.front(), ms[ms.size() / 2]};
}

void print_row(const std::string& what, const Timing& t, const std::string& note = {}) {
    std::printf("  %-28s %10.3f ms median %10.3f ms min  %s\n", what.c_str(), t.median_ms, t.min_ms,
                note.c_str());
}

} // namespace

int run_bench(const std::vector<std::string>& argv) {
    Args args("bench", "bench MESH [--kind KIND]... [--repeat N] [--planar-map FRAMES]",
              std::string("Times the pipeline on MESH: import (weld, repair, normals), engine\n"
                          "topology, and from-scratch contours of each KIND (default visual)\n"
                          "under an orthographic view along 0.4,-0.3,1; prints median and minimum.\n"
                          "With --planar-map, also the snaxel-defined planar map while tracking:\n"
                          "a turntable of FRAMES frames (1 degree each) tracking the visual, shadow\n"
                          "and isophote:0.5 contours, then the map at 800x800, per frame.\n\n") +
                  kMeshArgumentHelp,
              {{"kind", "KIND", "contour to time (as for 'contours')", true},
               {"repeat", "N", "runs per measurement (default 10)"},
               {"planar-map", "FRAMES", "time the planar map while tracking over FRAMES frames (at least 2)"}},
              {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    int repeat = 10;
    if (const auto r = args.value("repeat")) repeat = parse_int("repeat", *r, 1, 10000);
    const int map_frames = args.value("planar-map") ? parse_int("planar-map", *args.value("planar-map"), 2, 100000) : 0;
    std::vector<ContourSpec> kinds;
    for (const auto& k : args.values("kind")) {
        try {
            kinds.push_back(ContourSpec::parse(k));
        } catch (const Error& e) {
            throw UsageError(e.what());
        }
    }
    if (kinds.empty()) kinds.push_back({});

    const std::string spec = args.positional()[0];
    LoadedMesh loaded = load_mesh(spec); // fails early, with the usual message, on bad input
    std::printf("%s: %zu vertices, %zu faces; %d runs each\n", spec.c_str(), loaded.report.vertices,
                loaded.report.faces, repeat);
    const int import_runs = std::max(1, std::min(repeat, 5));
    print_row("import", time_it(import_runs, [&] { loaded = load_mesh(spec); }),
              "(" + std::to_string(import_runs) + " runs)");
    MeshTopology topology;
    print_row("topology", time_it(repeat, [&] { topology = engine_topology(loaded.mesh); }),
              topology.refinement() ? "(refined to " + std::to_string(topology.n_faces()) + " faces)" : "");
    const SnaxelEngine engine(topology);
    Camera camera;
    camera.view_dir = glm::normalize(glm::dvec3(0.4, -0.3, 1.0));
    const Light light = default_light(camera);
    EngineOptions options;
    options.check_invariants = false;
    for (const ContourSpec& kind : kinds) {
        std::size_t snaxels = 0, loops = 0;
        const Timing t = time_it(repeat, [&] {
            const ContourResult r = engine.compute(kind, camera, light, options);
            snaxels = r.fronts.snaxels.size();
            loops = r.fronts.loops.size();
        });
        print_row("contours " + kind.label(), t,
                  std::to_string(loops) + " loops, " + std::to_string(snaxels) + " snaxels");
    }
    if (map_frames > 0) {
        const TrackedMapTiming t =
            time_tracked_snaxel_map(topology, loaded.report, map_frames, camera.view_dir, camera.up, 800, 0.5);
        auto row = [](const std::vector<double>& ms) {
            return Timing{*std::min_element(ms.begin(), ms.end()), median_of(ms)};
        };
        print_row("planar map, tracking", row(t.map_ms),
                  "(snaxel map per frame, " + std::to_string(map_frames) + "-frame turntable, " +
                      std::to_string(t.regions / std::size_t(map_frames)) + " regions a frame)");
        print_row("tracking + planar map", row(t.frame_ms), "(visual, shadow, isophote:0.5 tracked, then the map)");
    }
    return 0;
}

} // namespace snaxels::cli
