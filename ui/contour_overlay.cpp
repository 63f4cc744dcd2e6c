#include "ui/contour_overlay.h"

#include <chrono>

#include <QColor>

#include "core/animation/still.h"
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

OverlayResult compute_overlay(const LoadedMesh& mesh, const ContourScene& scene, const Camera& camera,
                              const Style& style, const std::optional<Light>& light) {
    const auto start = std::chrono::steady_clock::now();
    StillJob job;
    job.camera = camera;
    job.light = light ? *light : style.light ? *style.light : default_light(camera);
    job.kinds.clear();
    for (const ContourStyle& cs : style.contours) job.kinds.push_back(cs.spec);
    if (job.kinds.empty()) job.kinds.push_back({});
    job.style = style;
    job.engine.check_invariants = false;
    StillOutput still = render_still(mesh, scene.topology, scene.rays.get(), job);

    OverlayResult out;
    out.svg = std::move(still.svg);
    for (std::size_t c = 0; c < still.results.size(); ++c) {
        const ContourResult& r = still.results[c];
        const QColor colour(view_colour(r.spec.kind));
        out.loops += r.fronts.loops.size();
        out.snaxels += r.fronts.snaxels.size();
        for (const LoopVisibility& loop : still.visibility[c].loops)
            for (const VisibilityRun& run : loop.runs) {
                ContourStrip strip;
                strip.colour = glm::vec3(float(colour.redF()), float(colour.greenF()), float(colour.blueF()));
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
