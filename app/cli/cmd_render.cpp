#include <unistd.h>

#include <cstdio>
#include <iostream>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "app/cli/progress.h"
#include "app/cli/scene_options.h"
#include "snaxels/animation/pipeline.h"
#include "snaxels/animation/still.h"
#include "snaxels/error.h"
#include "snaxels/mesh/import.h"
#include "snaxels/project/project.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/util/atomic_file.h"

namespace snaxels::cli {

int run_render(const std::vector<std::string>& argv) {
    Args args("render",
              "render PROJECT.snaxels -o OUT.svg|OUT.json [--format svg|lottie] [--still [--frame N]]",
              "Renders a project saved by the application: its mesh, camera, light, animation and\n"
              "style. Without --still it writes the animated SVG (or, for OUT.json, Lottie), the\n"
              "very bytes the application's Export > Animated SVG (Export > Lottie) writes for the\n"
              "project; with --still, one frame of the animation (the project's current frame,\n"
              "or N) as static SVG.",
              {{"output", "OUT", "the file to write: SVG, or Lottie for OUT.json", false, 'o'},
               {"format", "svg|lottie", "the animation's format (default: by OUT's extension, .json for Lottie)"},
               {"still", "", "write one frame as static SVG instead of the animation"},
               {"frame", "N", "with --still: the frame (default: the project's current frame)"}},
              {"PROJECT"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    const auto output = args.value("output");
    if (!output) throw UsageError("-o OUT.svg is required (or OUT.json for Lottie)");
    if (args.flag("still") && args.value("format") && *args.value("format") != "svg")
        throw UsageError("--still writes static SVG; --format lottie is for the animation");
    const AnimationFormat format =
        args.flag("still") ? AnimationFormat::Svg : parse_animation_format(args.value("format"), *output);
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
    job.format = format;

    if (!args.flag("still")) {
        job.output = *output; // written as the frames are made, atomically
        const AnimationOutput result = run_animation_with_progress(loaded, mesh_path, job);
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
    still.scene.camera = pose.camera;
    still.scene.light = pose.light;
    const StillOutput out = render_still(surface, pose.mesh, nullptr, still);
    write_file_atomically(*output, out.svg);
    std::printf("%s: frame %d, %zu bytes\n", output->c_str(), frame, out.svg.size());
    return 0;
}

} // namespace snaxels::cli
