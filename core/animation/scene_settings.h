#pragma once
/// What decides a drawing apart from the mesh and its pose: the view, the
/// light, the contour kinds, the style (strokes, fills, canvas), hidden
/// lines, the planar map, the engine's refinement and options. One value,
/// built once from a style and what a command line or the application sets
/// over it, and read by stills (StillJob), animations (AnimationJob), the
/// command line and the application alike.

#include <optional>
#include <vector>

#include "snaxels/mesh/build.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/style/style.h"

namespace snaxels {

struct SceneSettings {
    Camera camera;
    Light light;
    std::vector<ContourSpec> kinds{ContourSpec{}}; ///< the contours drawn
    Style style = default_style();
    bool visibility = true;  ///< hidden lines classified (quantitative invisibility)
    bool planar_map = false; ///< the planar map built (and its regions listed) even without fills
    PlanarMapKind map_kind = PlanarMapKind::Snaxel; ///< the map fills and regions come from
    int refine = kAutoRefine; ///< levels the mesh is refined by for the engine (core/mesh/refine.h)
    EngineOptions engine;
};

/// What a command line or the application sets over a style.
struct SceneOverrides {
    std::optional<Light> light;      ///< else the style's light, else the default light for the camera
    std::vector<ContourSpec> kinds;  ///< else the style's contours, else the visual contour
    bool visibility = true;
    std::optional<PlanarMapKind> planar_map; ///< a map asked for: built and listed, and the fills' map
    int refine = kAutoRefine;
    std::optional<bool> check_invariants; ///< whether the engine checks its invariants (else its default)
};

/// The scene @p style draws from @p camera, with @p overrides over it.
SceneSettings scene_settings(const Style& style, const Camera& camera, const SceneOverrides& overrides = {});

/// The light of a scene: @p light, else the style's, else the default for @p camera.
Light job_light(const Style& style, const Camera& camera, const std::optional<Light>& light);

/// The contours @p style draws (its <contour> kinds), or the visual contour.
std::vector<ContourSpec> style_kinds(const Style& style);

/// The surface the engine draws of @p loaded under @p style: without the
/// objects the style hides (<object hide="true">: without_objects), split
/// along its sharp edges (<surface>: split_sharp_edges); @p loaded itself
/// when neither changes it. @p storage holds a changed mesh.
const LoadedMesh& scene_surface(const LoadedMesh& loaded, const Style& style, std::optional<LoadedMesh>& storage);

} // namespace snaxels
