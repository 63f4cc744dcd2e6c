#include "snaxels/animation/scene_settings.h"

namespace snaxels {

Light job_light(const Style& style, const Camera& camera, const std::optional<Light>& light) {
    return light ? *light : style.light ? *style.light : default_light(camera);
}

std::vector<ContourSpec> style_kinds(const Style& style) {
    std::vector<ContourSpec> kinds;
    for (const ContourStyle& cs : style.contours) kinds.push_back(cs.spec);
    if (kinds.empty()) kinds.push_back({});
    return kinds;
}

SceneSettings scene_settings(const Style& style, const Camera& camera, const SceneOverrides& overrides) {
    SceneSettings scene;
    scene.camera = camera;
    scene.light = job_light(style, camera, overrides.light);
    scene.kinds = overrides.kinds.empty() ? style_kinds(style) : overrides.kinds;
    scene.style = style;
    scene.visibility = overrides.visibility;
    scene.planar_map = overrides.planar_map.has_value();
    scene.map_kind = overrides.planar_map.value_or(PlanarMapKind::Snaxel);
    scene.refine = overrides.refine;
    if (overrides.check_invariants) scene.engine.check_invariants = *overrides.check_invariants;
    return scene;
}

} // namespace snaxels
