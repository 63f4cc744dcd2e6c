#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/scene_options.h"
#include "snaxels/error.h"
#include "snaxels/mesh/file_cameras.h"
#include "snaxels/mesh/import.h"
#include "snaxels/animation/pipeline.h"
#include "snaxels/export/video.h"
#include "snaxels/util/atomic_file.h"

namespace snaxels::cli {

namespace {

/// --stats: every path of the animated SVG, and totals.
nlohmann::json stats_json(const AnimationOutput& result) {
    const AnimatedSvgStats& st = result.stats;
    nlohmann::json paths = nlohmann::json::array();
    std::size_t one_frame = 0;
    for (const PathStats& p : st.path_stats) {
        nlohmann::json path = {{"kind", p.kind}, {"label", p.label}, {"part", p.part}, {"first_frame", p.first},
                               {"last_frame", p.last}, {"frames_shown", p.frames_shown}, {"vertices", p.vertices},
                               {"keyframes", p.keyframes}, {"segments", p.segments}};
        if (!p.object.empty()) path["object"] = p.object;
        paths.push_back(std::move(path));
        one_frame += p.frames_shown == 1;
    }
    return {{"frames", result.frames},
            {"bytes", result.bytes},
            {"paths", st.paths},
            {"paths_shown_one_frame", one_frame},
            {"keyframes", st.keyframes},
            {"path_frames", st.frames_spanned},
            {"vertices", st.vertices},
            {"path_list", paths}};
}

/// What moves in the animation, from the options: exactly one source
/// (--turntable, --light-orbit, --clip, --sequence, or --camera alone for
/// a camera the file animates), with its rate and in point.
AnimationSpec animation_source(const Args& args, const SceneOptions& scene) {
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
    if (scene.file_camera) anim.camera = *scene.file_camera;
    // The file's camera alone: it moves through its own clip (checked once
    // the file is read: a camera no clip moves has nothing to animate).
    if (sources == 0 && scene.file_camera) anim.kind = AnimationSpec::Kind::Camera;
    else if (sources != 1)
        throw UsageError("give exactly one of --turntable, --light-orbit, --clip, --sequence (or --camera NAME alone, "
                         "for a camera the file animates)");
    if (const auto v = args.value("fps")) anim.fps = parse_number("fps", *v, 0.0, 1000.0);
    if (const auto v = args.value("start")) anim.start = parse_int("start", *v, 0, 1000000);
    return anim;
}

/// The line that says what was written, and how long it took.
void print_summary(const std::string& output, const AnimationOutput& result, const AnimationJob& job,
                   const AnimationSpec& anim, std::chrono::steady_clock::time_point t_start) {
    const double total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_start).count();
    double tracking = 0.0;
    for (const double ms : result.tracking_ms) tracking += ms;
    const AnimatedSvgStats& stats = result.stats;
    if (!job.video.empty()) {
        std::printf("%s: %d frames at %g fps, %ux%u, %ju bytes; tracking %.2f ms per frame, %.0f ms in all; %zu events\n",
                    output.c_str(), result.frames, anim.fps, unsigned(job.scene.style.width), unsigned(job.scene.style.height),
                    std::uintmax_t(std::filesystem::file_size(output)), tracking / std::max(1, result.frames), total_ms,
                    result.events.size());
        return;
    }
    const std::uintmax_t on_disk = std::filesystem::file_size(output);
    const std::string compressed = on_disk != result.bytes ? " (" + std::to_string(on_disk) + " compressed)" : "";
    std::printf("%s: %d frames at %g fps, %zu paths, %zu keyframes (of %zu path-frames), %zu bytes%s; "
                "tracking %.2f ms per frame, %.0f ms in all; %zu events\n",
                output.c_str(), result.frames, anim.fps, stats.paths, stats.keyframes, stats.frames_spanned,
                result.bytes, compressed.c_str(), tracking / std::max(1, result.frames), total_ms, result.events.size());
}

} // namespace

int run_animate(const std::vector<std::string>& argv) {
    auto specs = scene_option_specs();
    specs.insert(specs.begin(),
                 {{"turntable", "DEG", "the camera orbits the mesh about the up axis, DEG per frame"},
                  {"light-orbit", "DEG", "the light orbits the mesh about the up axis, DEG per frame"},
                  {"clip", "NAME", "the mesh file's own animation clip (name or index; skinning and morph targets)"},
                  {"sequence", "PATTERN", "numbered mesh files of one connectivity: #### or %04d marks the number"},
                  {"frames", "N", "number of frames (default: the clip's length; else required)"},
                  {"start", "N", "begin at the source's frame N (an in point: turntable angle, clip time, sequence file)"},
                  {"fps", "F", "frames per second (default 24)"},
                  {"tolerance", "PX", "drop path vertices and keyframes reproduced within PX pixels (default 0.25)"},
                  {"output", "OUT", "the animation to write, by its extension: .svg (animated SVG), .svgz (the same, "
                                    "gzipped), .json (Lottie), .lottie (dotLottie), .mp4, .webm or .gif (video of the frames)",
                   false, 'o'},
                  {"format", "svg|lottie", "the document's format; must agree with OUT's extension"},
                  {"frames-dir", "DIR", "also write every frame as a static SVG into DIR (a flipbook, for comparison)"},
                  {"png-dir", "DIR", "also render every frame as PNG into DIR (frame_00000.png, ...)"},
                  {"video-width", "PX", "a video's (and --png-dir's) frames PX pixels across, the height by the canvas's "
                                        "aspect (default: the canvas's size)"},
                  {"crf", "N", "a video's quality: FFmpeg's constant rate factor, lower is better and bigger "
                               "(default 18 for .mp4, 30 for .webm; 0-51 and 0-63)"},
                  {"events", "OUT.json", "write the visual events (creation, annihilation, split, merge)"},
                  {"stats", "OUT.json", "write the animated SVG's paths: frames shown, vertices, keyframes"}});
    Args args("animate",
              "animate MESH (--turntable DEG | --light-orbit DEG | --clip NAME | --sequence PATTERN | --camera NAME)\n"
              "       --frames N [--fps F] [view, light and kind options as in contours]\n"
              "       [--tolerance PX] -o OUT.svg|.svgz|.json|.lottie|.mp4|.webm|.gif [--frames-dir DIR] [--png-dir DIR]\n"
              "       [--events OUT.json] [--stats OUT.json]",
              std::string("Tracks contours through an animation and writes an animated SVG in which every\n"
                          "contour is one path whose vertices move (SMIL), keyframed only where needed,\n"
                          "or the same paths as Lottie (docs/lottie.md).\n"
                          "With --sequence, MESH is ignored if it is '-'; the first file of the sequence\n"
                          "is read instead.\n\n") +
                  kMeshArgumentHelp,
              specs, {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    SceneOptions scene = parse_scene_options(args);
    AnimationSpec anim = animation_source(args, scene);
    int frames = 0;
    if (const auto v = args.value("frames")) frames = parse_int("frames", *v, 1, 100000);
    else if (anim.kind != AnimationSpec::Kind::Clip && anim.kind != AnimationSpec::Kind::Camera)
        throw UsageError("--frames is required");
    AnimatedSvgOptions svg_options;
    if (const auto v = args.value("tolerance")) svg_options.tolerance_px = parse_number("tolerance", *v, -1e-12, 100.0);
    const auto output = args.value("output");
    if (!output) throw UsageError("-o OUT is required (" + output_extensions() + ")");
    check_output(args.value("format"), *output);
    if (is_video(*output_kind_for(*output))) require_ffmpeg(); // before the work, not after it
    const std::string frames_dir = args.value("frames-dir").value_or("");
    const std::string png_dir = args.value("png-dir").value_or("");
    const std::string events_out = args.value("events").value_or("");
    const std::string stats_out = args.value("stats").value_or("");
    if (!stats_out.empty() && is_video(*output_kind_for(*output)))
        throw UsageError("--stats describes the animated document's paths; a video (" + *output + ") has none");

    std::string mesh_path = args.positional()[0];
    if (anim.kind == AnimationSpec::Kind::Sequence && mesh_path == "-") mesh_path.clear();
    anim.frames = frames;
    const auto t_start = std::chrono::steady_clock::now();
    const LoadedMesh loaded = [&] {
        if (!mesh_path.empty()) return load_mesh(mesh_path);
        const LoadedMesh none;
        MeshTopology empty;
        const FrameDriver probe(anim, none, empty, Camera{}, Light{}, glm::dvec3(0.0), "");
        return import_mesh(probe.sequence_path(0));
    }();
    if (mesh_path.empty()) mesh_path = loaded.report.source;
    AnimationJob job;
    job.animation = anim;
    if (anim.kind == AnimationSpec::Kind::Camera) {
        const CameraTrack track(mesh_path, anim.camera);
        if (!track.info().animated())
            throw Error(mesh_path + ": camera '" + track.info().name +
                        "' is not moved by any clip; draw it with contours --camera, or animate it with --turntable");
    }
    // The first frame's camera decides the default light, as a turntable's does.
    warn_about_parts(scene.style, loaded, scene.style_source);
    job.scene = complete_scene(scene, loaded.report, mesh_path, anim.start / anim.fps);
    job.svg = svg_options;
    job.canvas_follows_camera = !scene.size_given;
    job.frames_dir = frames_dir;
    job.png_dir = png_dir;
    if (const auto v = args.value("video-width")) job.video_width = parse_int("video-width", *v, 16, kMaxRenderedSide);
    if (const auto v = args.value("crf")) job.video_crf = parse_int("crf", *v, 0, 63);
    set_output(job, *output); // written as the frames are made, atomically
    const AnimationOutput result = run_animation_with_progress(loaded, mesh_path, job);
    if (!events_out.empty()) write_file_atomically(events_out, events_json(result, job).dump(1) + "\n");
    if (!stats_out.empty()) write_file_atomically(stats_out, stats_json(result).dump(1) + "\n");
    print_summary(*output, result, job, anim, t_start);
    return 0;
}

} // namespace snaxels::cli
