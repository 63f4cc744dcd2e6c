#pragma once
// The view, light, contour-kind and image options that 'contours' and
// 'animate' share: their help entries and their parsing, done before any
// mesh is loaded so mistakes are reported at once.

#include <optional>
#include <vector>

#include "app/cli/args.h"
#include "snaxels/mesh/report.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/snaxel/refine.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/style/style.h"

namespace snaxels::cli {

struct SceneOptions {
    Camera camera;
    std::optional<glm::dvec3> target; ///< perspective target, if given
    std::optional<Light> light;       ///< --light-*, else the style's, else the default light
    std::vector<ContourSpec> kinds;   ///< --kind, else the style's contours, else visual
    Style style = default_style();    ///< --style, with --size applied to its canvas
    bool visibility = true;
    bool check = false;
    /// --planar-map: which map (and, for contours, list its regions); fills
    /// use the snaxel map when it is not given.
    std::optional<PlanarMapKind> planar_map;
    int refine = kAutoRefine; ///< --refine: levels of refinement for the engine
};

std::vector<OptionSpec> scene_option_specs();
/// Parses the options and reads --style (its warnings go to standard error).
SceneOptions parse_scene_options(const Args& args);
/// Fills what depends on the mesh: the perspective target (its centre by
/// default) and the default light.
void complete_scene(SceneOptions& options, const MeshReport& report);

glm::dvec3 parse_vec3(const std::string& option, const std::string& text, bool direction);
double parse_number(const std::string& option, const std::string& text, double lo, double hi);
int parse_int(const std::string& option, const std::string& text, int lo, int hi);

} // namespace snaxels::cli
