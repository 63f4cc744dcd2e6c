#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/scene_options.h"
#include "core/error.h"
#include "core/export/animated_svg.h"
#include "core/export/svg.h"
#include "core/mesh/import.h"
#include "core/scene/animation.h"
#include "core/snaxel/tracker.h"
#include "core/util/atomic_file.h"
#include "core/visibility/visibility.h"

namespace snaxels::cli {
namespace {

class Progress {
  public:
    Progress(int total, bool enabled) : total_(total), enabled_(enabled) {}
    void update(int done) {
        if (!enabled_) return;
        const int width = 40, filled = total_ ? width * done / total_ : width;
        std::fprintf(stderr, "\r[%.*s%*s] %d/%d frames", filled,
                     "########################################", width - filled, "", done, total_);
        std::fflush(stderr);
    }
    void finish() {
        if (enabled_) std::fprintf(stderr, "\n");
    }

  private:
    int total_;
    bool enabled_;
};

} // namespace

int run_animate(const std::vector<std::string>& argv) {
    auto specs = scene_option_specs();
    specs.insert(specs.begin(),
                 {{"turntable", "DEG", "the camera orbits the mesh about the up axis, DEG per frame"},
                  {"light-orbit", "DEG", "the light orbits the mesh about the up axis, DEG per frame"},
                  {"clip", "NAME", "the mesh file's own animation clip (name or index; skinning and morph targets)"},
                  {"sequence", "PATTERN", "numbered mesh files of one connectivity: #### or %04d marks the number"},
                  {"frames", "N", "number of frames (default: the clip's length; else required)"},
                  {"fps", "F", "frames per second (default 24)"},
                  {"tolerance", "PX", "drop path vertices and keyframes reproduced within PX pixels (default 0.25)"},
                  {"output", "OUT.svg", "the animated SVG to write", false, 'o'},
                  {"frames-dir", "DIR", "also write every frame as a static SVG into DIR (a flipbook, for comparison)"},
                  {"events", "OUT.json", "write the visual events (creation, annihilation, split, merge)"}});
    Args args("animate",
              "animate MESH (--turntable DEG | --light-orbit DEG | --clip NAME | --sequence PATTERN)\n"
              "       --frames N [--fps F] [view, light and kind options as in contours]\n"
              "       [--tolerance PX] -o OUT.svg [--frames-dir DIR] [--events OUT.json]",
              std::string("Tracks contours through an animation and writes an animated SVG in which every\n"
                          "contour is one path whose vertices move (SMIL), keyframed only where needed.\n"
                          "With --sequence, MESH is ignored if it is '-'; the first file of the sequence\n"
                          "is read instead.\n\n") +
                  kMeshArgumentHelp,
              specs, {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    SceneOptions scene = parse_scene_options(args);
    AnimationSpec anim;
    int sources = 0;
    if (const auto v = args.value("turntable")) {
        anim.kind = AnimationSpec::Kind::Turntable;
        anim.degrees_per_frame = parse_number("turntable", *v, -360.0, 360.0);
        ++sources;
    }
    if (const auto v = args.value("light-orbit")) {
        anim.kind = AnimationSpec::Kind::LightOrbit;
        anim.degrees_per_frame = parse_number("light-orbit", *v, -360.0, 360.0);
        ++sources;
    }
    if (const auto v = args.value("clip")) {
        anim.kind = AnimationSpec::Kind::Clip;
        anim.clip = *v;
        ++sources;
    }
    if (const auto v = args.value("sequence")) {
        anim.kind = AnimationSpec::Kind::Sequence;
        anim.pattern = *v;
        if (v->find('#') == std::string::npos && v->find('%') == std::string::npos)
            throw UsageError("--sequence needs #### or %04d in the pattern where the frame number goes");
        ++sources;
    }
    if (sources != 1)
        throw UsageError("give exactly one of --turntable, --light-orbit, --clip, --sequence");
    if (const auto v = args.value("fps")) anim.fps = parse_number("fps", *v, 0.0, 1000.0);
    int frames = 0;
    if (const auto v = args.value("frames")) frames = parse_int("frames", *v, 1, 100000);
    else if (anim.kind != AnimationSpec::Kind::Clip) throw UsageError("--frames is required");
    AnimatedSvgOptions svg_options;
    if (const auto v = args.value("tolerance")) svg_options.tolerance_px = parse_number("tolerance", *v, -1e-12, 100.0);
    const auto output = args.value("output");
    if (!output) throw UsageError("-o OUT.svg is required");
    const std::string frames_dir = args.value("frames-dir").value_or("");
    const std::string events_out = args.value("events").value_or("");

    std::string mesh_path = args.positional()[0];
    if (anim.kind == AnimationSpec::Kind::Sequence && mesh_path == "-") mesh_path.clear();
    const auto t_start = std::chrono::steady_clock::now();
    const LoadedMesh loaded = [&] {
        if (!mesh_path.empty()) return load_mesh(mesh_path);
        AnimationSpec probe = anim;
        const LoadedMesh dummy;
        MeshTopology none;
        const FrameDriver driver(probe, dummy, none, Camera{}, Light{}, glm::dvec3(0.0), "");
        return import_mesh(driver.sequence_path(0));
    }();
    if (mesh_path.empty()) mesh_path = loaded.report.source;
    complete_scene(scene, loaded.report);

    MeshTopology topology = build_topology(loaded.mesh);
    FrameDriver driver(anim, loaded, topology, scene.camera, *scene.light,
                       0.5 * (loaded.report.bbox_min + loaded.report.bbox_max), mesh_path);
    if (anim.kind == AnimationSpec::Kind::Clip && frames == 0) {
        const MeshAnimation clip(mesh_path, anim.clip);
        frames = std::max(1, int(std::lround(clip.duration() * anim.fps)) + 1);
    }

    // The image frame: the mesh's bounding sphere over every frame.
    glm::dvec3 lo = loaded.report.bbox_min, hi = loaded.report.bbox_max;
    if (driver.mesh_moves()) {
        Camera c;
        Light l;
        for (int k = 0; k < frames; ++k) {
            driver.apply(k, c, l);
            for (const auto& p : topology.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
    }
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = std::max(0.5 * glm::length(hi - lo), 1e-12);

    if (!frames_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(frames_dir, ec);
        if (ec) throw Error("cannot create " + frames_dir + ": " + ec.message());
    }
    EngineOptions engine_options;
    if (scene.check) engine_options.check_invariants = true;
    std::vector<ContourTracker> trackers;
    for (const ContourSpec& spec : scene.kinds) trackers.emplace_back(topology, spec, engine_options);
    std::unique_ptr<RayScene> rays;
    std::vector<AnimationFrame> recorded;
    recorded.reserve(std::size_t(frames));
    nlohmann::json events = nlohmann::json::array();
    Progress progress(frames, ::isatty(2));
    double tracking_ms = 0.0;
    const SnaxelEngine engine(topology);
    for (int k = 0; k < frames; ++k) {
        Camera camera;
        Light light;
        driver.apply(k, camera, light);
        if (scene.visibility) {
            if (!rays) rays = std::make_unique<RayScene>(topology);
            else if (driver.mesh_moves()) rays->refit();
        }
        std::vector<ContourResult> results;
        std::vector<ContourVisibility> visibility;
        AnimationFrame frame;
        for (std::size_t c = 0; c < trackers.size(); ++c) {
            const TrackedFrame& tf = trackers[c].step(camera, light);
            tracking_ms += tf.contour.stats.ms;
            results.push_back(tf.contour);
            std::vector<AnimatedLoop> loops;
            for (std::size_t l = 0; l < tf.contour.fronts.loops.size(); ++l) {
                AnimatedLoop al;
                al.sequence = tf.loop_sequence[l];
                tf.contour.fronts.for_each_in_loop(tf.contour.fronts.loops[l],
                                                   [&](std::int32_t s) { al.ids.push_back(tf.snaxel_id[s]); });
                loops.push_back(std::move(al));
            }
            frame.loops.push_back(std::move(loops));
            for (const VisualEvent& e : tf.events)
                events.push_back({{"frame", e.frame},
                                  {"kind", event_name(e.kind)},
                                  {"contour", scene.kinds[c].label()},
                                  {"where", {e.where.x, e.where.y, e.where.z}}});
            if (scene.visibility) visibility.push_back(VisibilitySampler(*rays, camera).classify(engine, tf.contour));
        }
        const ImageProjection projection(camera, centre, radius, scene.width, scene.height);
        frame.drawing = make_drawing(engine, results, projection, scene.visibility ? &visibility : nullptr);
        for (auto& contour : frame.drawing.contours)
            for (auto& loop : contour.loops) loop.p.clear(); // 3-D positions are not exported
        if (!frames_dir.empty()) {
            char name[64];
            std::snprintf(name, sizeof name, "frame_%05d.svg", k);
            write_file_atomically((std::filesystem::path(frames_dir) / name).string(), to_svg(frame.drawing));
        }
        recorded.push_back(std::move(frame));
        progress.update(k + 1);
    }
    progress.finish();

    AnimatedSvgStats stats;
    const std::string svg = to_animated_svg(recorded, anim.fps, svg_options, &stats);
    write_file_atomically(*output, svg);
    if (!events_out.empty()) write_file_atomically(events_out, events.dump(1) + "\n");
    const double total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_start).count();
    std::printf("%s: %d frames at %g fps, %zu paths, %zu keyframes (of %zu path-frames), %zu bytes; "
                "tracking %.2f ms per frame, %.0f ms in all; %zu events\n",
                output->c_str(), frames, anim.fps, stats.paths, stats.keyframes, stats.frames_spanned,
                svg.size(), tracking_ms / std::max(1, frames), total_ms, events.size());
    return 0;
}

} // namespace snaxels::cli
