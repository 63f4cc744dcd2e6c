#include "snaxels/animation/scene_settings.h"

#include "snaxels/mesh/parts.h"
#include "snaxels/mesh/sharp_edges.h"

namespace snaxels {

Light job_light(const Style& style, const Camera& camera, const std::optional<Light>& light) {
    return light ? *light : style.light ? *style.light : default_light(camera);
}

std::vector<ContourSpec> style_kinds(const Style& style) {
    std::vector<ContourSpec> kinds;
    for (const ContourStyle& cs : style.contours) kinds.push_back(cs.spec);
    if (kinds.empty()) kinds.push_back(style.drawn({}));
    return kinds;
}

const LoadedMesh& scene_surface(const LoadedMesh& loaded, const Style& style, std::optional<LoadedMesh>& storage) {
    std::optional<LoadedMesh> shown = without_objects(loaded, style.hidden_objects);
    std::optional<LoadedMesh> split = split_sharp_edges(shown ? *shown : loaded, style.surface);
    storage = split ? std::move(split) : std::move(shown);
    return storage ? *storage : loaded;
}

SceneSettings scene_settings(const Style& style, const Camera& camera, const SceneOverrides& overrides) {
    SceneSettings scene;
    scene.camera = camera;
    scene.light = job_light(style, camera, overrides.light);
    scene.kinds = style_kinds(style);
    if (!overrides.kinds.empty()) {
        // Kinds asked for by name are drawn as the style draws the parts.
        scene.kinds.clear();
        for (const ContourSpec& spec : overrides.kinds) scene.kinds.push_back(style.drawn(spec));
    }
    scene.style = style;
    scene.visibility = overrides.visibility;
    scene.planar_map = overrides.planar_map.has_value();
    scene.map_kind = overrides.planar_map.value_or(PlanarMapKind::Snaxel);
    scene.refine = overrides.refine;
    if (overrides.check_invariants) scene.engine.check_invariants = *overrides.check_invariants;
    return scene;
}

} // namespace snaxels
