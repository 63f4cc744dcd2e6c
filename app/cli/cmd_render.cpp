#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/scene_options.h"
#include "snaxels/animation/pipeline.h"
#include "snaxels/animation/still.h"
#include "snaxels/error.h"
#include "snaxels/export/raster.h"
#include "snaxels/export/video.h"
#include "snaxels/mesh/import.h"
#include "snaxels/project/project.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/util/atomic_file.h"

namespace snaxels::cli {

int run_render(const std::vector<std::string>& argv) {
    Args args("render",
              "render PROJECT.snaxels -o OUT.svg|.svgz|.json|.lottie|.mp4|.webm|.gif [--png-dir DIR]\n"
              "       | --still [--frame N] -o OUT.svg|OUT.pdf",
              "Renders a project saved by the application: its mesh, camera, light, animation and\n"
              "style. Without --still it writes the animation as OUT's extension asks: the animated\n"
              "SVG (.svg, or gzipped .svgz) or Lottie (.json, or the dotLottie .lottie), the very\n"
              "bytes the application's Export menu writes for the project, or a video of its\n"
              "frames (.mp4, .webm, .gif); with --still, one frame of the animation (the project's\n"
              "current frame, or N) as static SVG or vector PDF.",
              {{"output", "OUT", "the file to write, by its extension", false, 'o'},
               {"format", "svg|lottie", "the animation's format; must agree with OUT's extension"},
               {"png-dir", "DIR", "also render every frame of the animation as PNG into DIR"},
               {"still", "", "write one frame as static SVG (or PDF, for OUT.pdf) instead of the animation"},
               {"frame", "N", "with --still: the frame (default: the project's current frame)"}},
              {"PROJECT"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    const auto output = args.value("output");
    if (!output) throw UsageError("-o OUT is required (" + output_extensions() + "; with --still .svg or .pdf)");
    const bool still_pdf = args.flag("still") && std::filesystem::path(*output).extension() == ".pdf";
    if (args.flag("still")) {
        if (args.value("format") && *args.value("format") != "svg")
            throw UsageError("--still writes static SVG; --format lottie is for the animation");
        if (args.value("png-dir")) throw UsageError("--png-dir is for the animation, not --still");
        if (output_kind_for(*output) != OutputKind::Svg && !still_pdf)
            throw UsageError("cannot write '" + *output + "' with --still: the output's extension must be .svg or .pdf");
    } else {
        check_output(args.value("format"), *output);
        if (is_video(*output_kind_for(*output))) require_ffmpeg(); // before the work, not after it
    }
    if (args.flag("frame") && !args.flag("still")) throw UsageError("--frame goes with --still");
    const std::string project_path = args.positional()[0];
    const Project project = read_project(project_path);
    const std::string mesh_path = resolve_project_mesh(project_path, project.mesh);
    std::vector<StyleDiagnostic> warnings;
    const Style style = project.style.empty() ? default_style()
                                              : parse_style(project.style, project_path + " (style)", &warnings);
    for (const StyleDiagnostic& w : warnings)
        std::cerr << "snaxels-cli: " << project_path << " (style):" << w.line << ":" << w.column
                  << ": warning: " << w.message << '\n';
    const LoadedMesh loaded = load_mesh(mesh_path);
    warn_about_parts(style, loaded, project_path + " (style)");
    OrbitView view = project.view;
    view.centre = loaded.report.centre(); // as the application frames it
    AnimationSpec animation = project.animation;
    if (animation.kind == AnimationSpec::Kind::Sequence) // relative to the project, as its mesh is
        animation.pattern = resolve_project_mesh(project_path, animation.pattern);
    AnimationJob job = make_animation_job(style, animation, orbit_base_camera(view), project.light);
    if (!args.flag("still")) {
        set_output(job, *output); // written as the frames are made, atomically
        job.png_dir = args.value("png-dir").value_or("");
        const AnimationOutput result = run_animation_with_progress(loaded, mesh_path, job);
        if (is_video(*output_kind_for(*output))) // the encoder's file: no paths, its size on disk
            std::printf("%s: %d frames at %g fps, %ju bytes\n", output->c_str(), result.frames, project.animation.fps,
                        std::uintmax_t(std::filesystem::file_size(*output)));
        else
            std::printf("%s: %d frames at %g fps, %zu paths, %zu bytes\n", output->c_str(), result.frames,
                        project.animation.fps, result.stats.paths, result.bytes);
        return 0;
    }
    const int frame = args.value("frame") ? parse_int("frame", *args.value("frame"), 0, 100000) : project.frame;
    std::optional<LoadedMesh> split;
    const LoadedMesh& surface = scene_surface(loaded, job.scene.style, split);
    MeshTopology topology = engine_topology(surface, job.scene.refine);
    find_parabolic_with_progress(topology, job.scene.kinds); // on the pose as loaded, as the animation does
    const glm::dvec3 centre = loaded.report.centre();
    FrameDriver driver(job.animation, surface, topology, job.scene.camera, job.scene.light, centre, mesh_path);
    const FramePose pose = driver.pose(frame);
    StillJob still{job.scene}; // the animation's scene at this frame's camera and light
    still.all_hidden_levels = false; // an SVG or PDF: hidden levels only where drawn
    still.scene.camera = pose.camera;
    still.scene.light = pose.light;
    const StillOutput out = render_still(surface, pose.mesh, nullptr, still);
    if (still_pdf) write_pdf(*output, out.svg);
    else write_file_atomically(*output, out.svg);
    std::printf("%s: frame %d, %ju bytes\n", output->c_str(), frame, std::uintmax_t(std::filesystem::file_size(*output)));
    return 0;
}

} // namespace snaxels::cli
