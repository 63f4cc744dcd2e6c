#pragma once
// The view, light, contour-kind and image options that 'contours' and
// 'animate' share: their help entries and their parsing, done before any
// mesh is loaded so mistakes are reported at once.

#include <optional>
#include <vector>

#include "app/cli/args.h"
#include "snaxels/animation/scene_settings.h"
#include "snaxels/mesh/build.h"
#include "snaxels/mesh/report.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/style/style.h"

namespace snaxels::cli {

/// The command line's scene: what complete_scene makes a SceneSettings of
/// once the mesh is known.
struct SceneOptions {
    Camera camera;
    std::optional<glm::dvec3> target; ///< perspective target, if given
    /// --projection perspective without --eye: the eye stands along the
    /// view's direction from the target, framing the mesh (complete_scene).
    bool place_eye = false;
    Style style = default_style();    ///< --style, with --size applied to its canvas
    /// --light-*, --kind, --no-visibility, --planar-map (for contours, also
    /// listing its regions), --refine and --check over the style.
    SceneOverrides overrides;
    std::optional<std::string> file_camera; ///< --camera: one of the file's cameras
    bool size_given = false;                ///< --size (else a file camera's aspect sets the height)
    std::string style_source;               ///< the style file, as messages name it
};

std::vector<OptionSpec> scene_option_specs();
/// Parses the options and reads --style (its warnings go to standard error).
SceneOptions parse_scene_options(const Args& args);
/// The scene, with what depends on the mesh filled in: the file's camera
/// (--camera; read from @p mesh_path at @p seconds into its clip, the
/// canvas's height following its aspect), the perspective target (the
/// mesh's centre by default), the default light, and --refine lowered
/// (with a warning) where it would make too many faces.
SceneSettings complete_scene(const SceneOptions& options, const MeshReport& report, const std::string& mesh_path,
                             double seconds = 0.0);

/// Warns on standard error about each object= or material= pattern of
/// @p style that matches none of @p mesh's parts, naming the pattern and
/// what the scene has, at its place in @p source.
void warn_about_parts(const Style& style, const LoadedMesh& mesh, const std::string& source);

glm::dvec3 parse_vec3(const std::string& option, const std::string& text, bool direction);
double parse_number(const std::string& option, const std::string& text, double lo, double hi);
/// A number from @p lo to @p hi, both included; else UsageError "--OPTION
/// takes TAKES, not 'TEXT'".
double parse_closed_number(const std::string& option, const std::string& text, double lo, double hi,
                           const std::string& takes);
int parse_int(const std::string& option, const std::string& text, int lo, int hi);

} // namespace snaxels::cli
