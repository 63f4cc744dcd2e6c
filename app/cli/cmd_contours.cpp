#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/scene_options.h"
#include "snaxels/error.h"
#include "snaxels/animation/still.h"
#include "snaxels/export/contours_json.h"
#include "snaxels/export/raster.h"
#include "snaxels/export/svg.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/util/atomic_file.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels::cli {

int run_contours(const std::vector<std::string>& argv) {
    Args args(
        "contours",
        "contours MESH [--view-dir X,Y,Z | --eye X,Y,Z [--target X,Y,Z] [--fov DEG]]\n"
        "       [--light-dir X,Y,Z | --light-pos X,Y,Z] [--kind KIND]... [--json OUT] [--svg OUT] [--pdf OUT]",
        std::string(
            "Finds contours on MESH with snaxels and writes them as JSON (docs/contours-json.md)\n"
            "and/or SVG and vector PDF; without --json, --svg or --pdf prints a summary. KIND is visual (N.V = 0),\n"
            "shadow (N.L = 0 on front faces), isophote:K (N.L = K), gleam:K (V.R = K), K a\n"
            "cosine in [-1, 1], parabolic (the mesh's parabolic curves, found from visual\n"
            "events over all views: see `snaxels-cli parabolic`), crease[:DEG] (edges whose\n"
            "faces meet at more than DEG degrees, default 30), border (edges with one face),\n"
            "suggestive[:D[:DEG]] (zeros of the radial curvature, drawn where its derivative\n"
            "toward the viewer, over the mesh's typical curvature squared, is at least D\n"
            "(default 4) and the surface is seen at DEG degrees or more from its normal,\n"
            "default 15), material and object (edges between two materials or objects) or\n"
            "intersection (where one surface passes through another or through itself).\n"
            "The default view is\n"
            "orthographic along +Z (looking toward +Z)\n"
            "and the default light comes from the viewer's upper left.\n\n") +
            kMeshArgumentHelp,
        [] {
            auto specs = scene_option_specs();
            specs.push_back({"json", "OUT", "write the contours as JSON to OUT ('-' for standard output)"});
            specs.push_back({"svg", "OUT", "write the contours as SVG to OUT ('-' for standard output)"});
            specs.push_back({"pdf", "OUT", "write the drawing as a vector PDF to OUT (the SVG's page, a pixel a point)"});
            return specs;
        }(),
        {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    SceneOptions scene = parse_scene_options(args);
    const bool planar = scene.overrides.planar_map.has_value();
    const std::string json_out = args.value("json").value_or("");
    const std::string svg_out = args.value("svg").value_or("");
    const std::string pdf_out = args.value("pdf").value_or("");
    if ((!json_out.empty() && (json_out == svg_out || json_out == pdf_out)) || (!svg_out.empty() && svg_out == pdf_out))
        throw UsageError("--json, --svg and --pdf name the same file");
    if (pdf_out == "-") throw UsageError("--pdf needs a file, not standard output");

    // Everything about the command line is checked: now the expensive part.
    const LoadedMesh loaded = load_mesh(args.positional()[0]);
    const MeshReport& report = loaded.report;
    warn_about_parts(scene.style, loaded, scene.style_source);
    StillJob job{complete_scene(scene, report, args.positional()[0])};
    job.all_hidden_levels = !json_out.empty(); // the JSON reports every hidden level; a drawing needs them where drawn
    const Camera& camera = job.scene.camera;
    const Light& light = job.scene.light;

    std::optional<LoadedMesh> split;
    const LoadedMesh& surface = scene_surface(loaded, job.scene.style, split);
    MeshTopology topology = engine_topology(surface, job.scene.refine);
    find_parabolic_with_progress(topology, job.scene.kinds);
    const StillOutput still = render_still(surface, topology, nullptr, job);
    const std::vector<ContourResult>& results = still.results;
    const std::vector<ContourVisibility>& visibility = still.visibility;

    auto emit = [](const std::string& path, const std::string& text) {
        if (path == "-") std::cout << text;
        else write_file_atomically(path, text);
    };
    if (!svg_out.empty()) emit(svg_out, still.svg);
    if (!pdf_out.empty()) write_pdf(pdf_out, still.svg);
    if (!json_out.empty()) {
        nlohmann::json doc = contours_to_json(report, camera, light, still.drawing, results,
                                              planar || !still.regions.empty() ? &still.regions : nullptr);
        doc["engine"] = {{"refine_levels", topology.refinement() ? topology.refinement()->levels : 0},
                         {"faces", topology.n_faces()}};
        emit(json_out, doc.dump() + "\n");
    }
    if (json_out.empty() && svg_out.empty() && pdf_out.empty()) {
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
