#include "ui/contour_overlay.h"

#include <chrono>

#include <QColor>

#include "core/visibility/visibility.h"

namespace snaxels::ui {

const char* view_colour(ContourKind kind) {
    switch (kind) {
    case ContourKind::Visual: return "#e8402a";
    case ContourKind::Shadow: return "#2f7fe0";
    case ContourKind::Isophote: return "#a05fd0";
    case ContourKind::Gleam: return "#ffc000";
    }
    return "#e8402a";
}

std::shared_ptr<ContourScene> make_contour_scene(const LoadedMesh& mesh) {
    auto scene = std::make_shared<ContourScene>();
    scene->topology = build_topology(mesh.mesh);
    scene->rays = std::make_unique<RayScene>(scene->topology);
    return scene;
}

OverlayResult compute_overlay(const ContourScene& scene, const Camera& camera, const std::vector<ContourSpec>& kinds) {
    const auto start = std::chrono::steady_clock::now();
    OverlayResult out;
    const SnaxelEngine engine(scene.topology);
    const Light light = default_light(camera);
    const VisibilitySampler sampler(*scene.rays, camera);
    EngineOptions options;
    options.check_invariants = false;
    for (const ContourSpec& spec : kinds) {
        const ContourResult r = engine.compute(spec, camera, light, options);
        const ContourVisibility vis = sampler.classify(engine, r);
        const QColor c(view_colour(spec.kind));
        const glm::vec3 colour(float(c.redF()), float(c.greenF()), float(c.blueF()));
        out.loops += r.fronts.loops.size();
        out.snaxels += r.fronts.snaxels.size();
        for (const LoopVisibility& loop : vis.loops)
            for (const VisibilityRun& run : loop.runs) {
                ContourStrip strip;
                strip.colour = colour;
                strip.hidden = run.qi > 0;
                strip.closed = run.closed;
                strip.points.reserve(run.points.size());
                for (const glm::dvec3& p : run.points) strip.points.emplace_back(p);
                out.strips.push_back(std::move(strip));
            }
    }
    out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace snaxels::ui
