#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/scene_options.h"
#include "core/error.h"
#include "core/export/contours_json.h"
#include "core/export/svg.h"
#include "core/mesh/import.h"
#include "core/snaxel/snaxel_engine.h"
#include "core/util/atomic_file.h"
#include "core/visibility/visibility.h"

namespace snaxels::cli {

int run_contours(const std::vector<std::string>& argv) {
    Args args(
        "contours",
        "contours MESH [--view-dir X,Y,Z | --eye X,Y,Z [--target X,Y,Z] [--fov DEG]]\n"
        "       [--light-dir X,Y,Z | --light-pos X,Y,Z] [--kind KIND]... [--json OUT] [--svg OUT]",
        std::string(
            "Finds contours on MESH with snaxels and writes them as JSON (docs/contours-json.md)\n"
            "and/or SVG; without --json or --svg prints a summary. KIND is visual (N.V = 0),\n"
            "shadow (N.L = 0 on front faces), isophote:K (N.L = K) or gleam:K (V.R = K), K a\n"
            "cosine in [-1, 1]. The default view is orthographic along +Z (looking toward +Z)\n"
            "and the default light comes from the viewer's upper left.\n\n") +
            kMeshArgumentHelp,
        [] {
            auto specs = scene_option_specs();
            specs.push_back({"json", "OUT", "write the contours as JSON to OUT ('-' for standard output)"});
            specs.push_back({"svg", "OUT", "write the contours as SVG to OUT ('-' for standard output)"});
            return specs;
        }(),
        {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    SceneOptions scene = parse_scene_options(args);
    const std::string json_out = args.value("json").value_or("");
    const std::string svg_out = args.value("svg").value_or("");
    if (!json_out.empty() && json_out == svg_out)
        throw UsageError("--json and --svg name the same file");

    // Everything about the command line is checked: now the expensive part.
    const LoadedMesh loaded = load_mesh(args.positional()[0]);
    const MeshReport& report = loaded.report;
    complete_scene(scene, report);
    const Camera& camera = scene.camera;
    const Light& light = *scene.light;
    const std::vector<ContourSpec>& kinds = scene.kinds;
    const glm::dvec3 centre = 0.5 * (report.bbox_min + report.bbox_max);
    const double radius = std::max(0.5 * glm::length(report.bbox_max - report.bbox_min), 1e-12);
    const int width = scene.style.width, height = scene.style.height;

    const MeshTopology topology = build_topology(loaded.mesh);
    const SnaxelEngine engine(topology);
    EngineOptions options;
    if (scene.check) options.check_invariants = true;
    std::vector<ContourResult> results;
    for (const ContourSpec& spec : kinds) results.push_back(engine.compute(spec, camera, light, options));

    std::vector<ContourVisibility> visibility;
    if (scene.visibility) {
        const RayScene rays(topology);
        const VisibilitySampler sampler(rays, camera);
        for (const ContourResult& r : results) visibility.push_back(sampler.classify(engine, r));
    }
    const ImageProjection projection(camera, centre, radius, width, height, scene.style.margin);
    const Drawing drawing =
        make_drawing(engine, results, projection, visibility.empty() ? nullptr : &visibility);

    auto emit = [](const std::string& path, const std::string& text) {
        if (path == "-") std::cout << text;
        else write_file_atomically(path, text);
    };
    // Fills: the post-processed planar map of the contours the style's
    // region classes need (computed here if they are not drawn).
    std::vector<MapRegion> regions;
    if (!scene.style.regions.empty()) {
        std::vector<ContourResult> fill_results;
        auto result_of = [&](const ContourSpec& spec) -> const ContourResult* {
            for (const ContourResult& r : results)
                if (r.spec.kind == spec.kind && std::abs(r.spec.k - spec.k) < 1e-9) return &r;
            for (const ContourResult& r : fill_results)
                if (r.spec.kind == spec.kind && std::abs(r.spec.k - spec.k) < 1e-9) return &r;
            return nullptr;
        };
        const std::vector<ContourSpec> needed = scene.style.fill_contours();
        fill_results.reserve(needed.size());
        for (const ContourSpec& spec : needed)
            if (!result_of(spec)) fill_results.push_back(engine.compute(spec, camera, light, options));
        PostMapInput input;
        for (const ContourSpec& spec : needed) {
            const ContourResult* r = result_of(spec);
            if (spec.kind == ContourKind::Visual) input.visual = r;
            if (spec.kind == ContourKind::Shadow) input.shadow = r;
            if (spec.kind == ContourKind::Isophote) input.isophotes.push_back(r);
            if (spec.kind == ContourKind::Gleam) input.gleam = r;
        }
        std::sort(input.isophotes.begin(), input.isophotes.end(),
                  [](const ContourResult* a, const ContourResult* b) { return a->spec.k < b->spec.k; });
        regions = build_post_map(engine, input, projection, camera);
    }
    if (!svg_out.empty()) emit(svg_out, to_svg(drawing, scene.style, regions.empty() ? nullptr : &regions));
    if (!json_out.empty())
        emit(json_out, contours_to_json(report, camera, light, drawing, results).dump() + "\n");
    if (json_out.empty() && svg_out.empty()) {
        std::cout << report.source << ": " << report.vertices << " vertices, " << report.faces
                  << " faces\n";
        for (std::size_t i = 0; i < results.size(); ++i) {
            const ContourResult& r = results[i];
            std::size_t snaxels = r.fronts.snaxels.size(), open = 0, hidden = 0;
            for (const auto& loop : r.fronts.loops) open += !loop.closed;
            if (!visibility.empty())
                for (const auto& lv : visibility[i].loops)
                    for (const int qi : lv.snaxel_qi) hidden += qi > 0;
            std::cout << "  " << r.spec.label() << ": " << r.fronts.loops.size() << " loops ("
                      << open << " open), " << snaxels << " snaxels";
            if (!visibility.empty()) std::cout << " (" << hidden << " hidden)";
            std::cout << ", " << r.regions.size() << " regions; " << r.stats.seeds << " seeds, "
                      << r.stats.iterations << " iterations, " << r.stats.fanouts << " fan-outs, "
                      << r.stats.merges << " merges, " << r.stats.splits << " splits, "
                      << r.stats.ms << " ms\n";
        }
    }
    return 0;
}

} // namespace snaxels::cli
