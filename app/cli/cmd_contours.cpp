#include <cmath>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "core/error.h"
#include "core/export/contours_json.h"
#include "core/export/svg.h"
#include "core/mesh/import.h"
#include "core/snaxel/snaxel_engine.h"
#include "core/util/atomic_file.h"
#include "core/visibility/visibility.h"

namespace snaxels::cli {
namespace {

glm::dvec3 parse_vec3(const std::string& option, const std::string& text, bool direction) {
    glm::dvec3 v{};
    std::istringstream in(text);
    char comma = 0;
    in >> v.x >> comma;
    bool ok = bool(in) && comma == ',';
    in >> v.y >> comma;
    ok = ok && bool(in) && comma == ',';
    in >> v.z;
    ok = ok && !in.fail() && (in >> std::ws).eof();
    if (!ok || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        throw UsageError("--" + option + " takes three numbers X,Y,Z, not '" + text + "'");
    if (direction && glm::length(v) < 1e-12)
        throw UsageError("--" + option + " must not be the zero vector");
    return v;
}

double parse_number(const std::string& option, const std::string& text, double lo, double hi) {
    std::size_t used = 0;
    double v = 0.0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !(v > lo && v < hi))
        throw UsageError("--" + option + " takes a number between " + std::to_string(lo) +
                         " and " + std::to_string(hi) + ", not '" + text + "'");
    return v;
}

void parse_size(const std::string& text, int& width, int& height) {
    const auto x = text.find('x');
    try {
        std::size_t a = 0, b = 0;
        if (x != std::string::npos) {
            width = std::stoi(text.substr(0, x), &a);
            height = std::stoi(text.substr(x + 1), &b);
            if (a == x && b == text.size() - x - 1 && width >= 16 && height >= 16 &&
                width <= 20000 && height <= 20000)
                return;
        }
    } catch (const std::exception&) {
    }
    throw UsageError("--size takes WIDTHxHEIGHT in pixels (16 to 20000), not '" + text + "'");
}

} // namespace

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
        {{"view-dir", "X,Y,Z", "orthographic view: the direction the camera looks"},
         {"eye", "X,Y,Z", "perspective view from this point"},
         {"target", "X,Y,Z", "perspective: the point looked at (default: the mesh's centre)"},
         {"fov", "DEG", "perspective: vertical field of view in degrees (default 35)"},
         {"up", "X,Y,Z", "the world direction shown upward (default 0,1,0)"},
         {"light-dir", "X,Y,Z", "directional light: the direction toward the light"},
         {"light-pos", "X,Y,Z", "point light at this position"},
         {"kind", "KIND", "contour to find (default visual)", true},
         {"json", "OUT", "write the contours as JSON to OUT ('-' for standard output)"},
         {"svg", "OUT", "write the contours as SVG to OUT ('-' for standard output)"},
         {"size", "WxH", "image size in pixels for q and the SVG (default 800x800)"},
         {"no-visibility", "", "skip hidden-line classification (no qi, no dashed runs)"},
         {"check", "", "check the snaxel invariants after every iteration (slower)"}},
        {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    if (args.flag("view-dir") && args.flag("eye"))
        throw UsageError("--view-dir (orthographic) and --eye (perspective) exclude each other");
    if (!args.flag("eye") && (args.flag("target") || args.flag("fov")))
        throw UsageError("--target and --fov need --eye (a perspective view)");
    if (args.flag("light-dir") && args.flag("light-pos"))
        throw UsageError("--light-dir and --light-pos exclude each other");

    std::vector<ContourSpec> kinds;
    for (const std::string& k : args.values("kind")) {
        try {
            kinds.push_back(ContourSpec::parse(k));
        } catch (const Error& e) {
            throw UsageError(e.what());
        }
    }
    if (kinds.empty()) kinds.push_back({});
    int width = 800, height = 800;
    if (const auto size = args.value("size")) parse_size(*size, width, height);

    Camera camera;
    if (const auto up = args.value("up")) camera.up = parse_vec3("up", *up, true);
    if (const auto v = args.value("view-dir")) camera.view_dir = glm::normalize(parse_vec3("view-dir", *v, true));
    const std::string json_out = args.value("json").value_or("");
    const std::string svg_out = args.value("svg").value_or("");
    if (!json_out.empty() && json_out == svg_out)
        throw UsageError("--json and --svg name the same file");

    // Everything about the command line is checked: now the expensive part.
    const LoadedMesh loaded = load_mesh(args.positional()[0]);
    const MeshReport& report = loaded.report;
    const glm::dvec3 centre = 0.5 * (report.bbox_min + report.bbox_max);
    const double radius = std::max(0.5 * glm::length(report.bbox_max - report.bbox_min), 1e-12);
    if (const auto eye = args.value("eye")) {
        camera.projection = Camera::Projection::Perspective;
        camera.eye = parse_vec3("eye", *eye, false);
        camera.target = args.value("target") ? parse_vec3("target", *args.value("target"), false) : centre;
        if (glm::length(camera.target - camera.eye) < 1e-12)
            throw UsageError("--eye and --target are the same point");
        if (const auto fov = args.value("fov")) camera.fov_deg = parse_number("fov", *fov, 0.0, 180.0);
    }
    Light light = default_light(camera);
    if (const auto d = args.value("light-dir")) light.dir = glm::normalize(parse_vec3("light-dir", *d, true));
    if (const auto p = args.value("light-pos")) {
        light.point = true;
        light.pos = parse_vec3("light-pos", *p, false);
    }

    const MeshTopology topology = build_topology(loaded.mesh);
    const SnaxelEngine engine(topology);
    EngineOptions options;
    if (args.flag("check")) options.check_invariants = true;
    std::vector<ContourResult> results;
    for (const ContourSpec& spec : kinds) results.push_back(engine.compute(spec, camera, light, options));

    std::vector<ContourVisibility> visibility;
    if (!args.flag("no-visibility")) {
        const RayScene rays(topology);
        const VisibilitySampler sampler(rays, camera);
        for (const ContourResult& r : results) visibility.push_back(sampler.classify(engine, r));
    }
    const ImageProjection projection(camera, centre, radius, width, height);
    const Drawing drawing =
        make_drawing(engine, results, projection, visibility.empty() ? nullptr : &visibility);

    auto emit = [](const std::string& path, const std::string& text) {
        if (path == "-") std::cout << text;
        else write_file_atomically(path, text);
    };
    if (!svg_out.empty()) emit(svg_out, to_svg(drawing));
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
