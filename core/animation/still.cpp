#include "core/animation/still.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/export/svg.h"

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

StillJob make_still_job(const Style& style, const Camera& camera, const std::optional<Light>& light) {
    StillJob job;
    job.camera = camera;
    job.light = job_light(style, camera, light);
    job.kinds = style_kinds(style);
    job.style = style;
    job.engine.check_invariants = false;
    return job;
}

StillOutput render_still(const LoadedMesh& mesh, const MeshTopology& topology, const RayScene* rays,
                         const StillJob& job) {
    StillOutput out;
    const MeshReport& report = mesh.report;
    const glm::dvec3 centre = 0.5 * (report.bbox_min + report.bbox_max);
    const double radius = std::max(0.5 * glm::length(report.bbox_max - report.bbox_min), 1e-12);
    const SnaxelEngine engine(topology);
    for (const ContourSpec& spec : job.kinds) out.results.push_back(engine.compute(spec, job.camera, job.light, job.engine));

    std::unique_ptr<RayScene> own_rays;
    if (job.visibility) {
        if (!rays) rays = (own_rays = std::make_unique<RayScene>(topology)).get();
        const VisibilitySampler sampler(*rays, job.camera);
        for (const ContourResult& r : out.results) out.visibility.push_back(sampler.classify(engine, r));
    }
    const ImageProjection projection(job.camera, centre, radius, job.style.width, job.style.height, job.style.margin);
    out.drawing = make_drawing(engine, out.results, projection, job.visibility ? &out.visibility : nullptr);

    // Fills: the planar map (job.map_kind: the snaxel-defined map unless the
    // job asks for the post-processed one) of the contours the style's region
    // classes need (computed here if they are not drawn).
    if (!job.style.regions.empty() || job.planar_map) {
        std::vector<ContourResult> fill_results;
        auto same = [](const ContourSpec& a, const ContourSpec& b) { return a.kind == b.kind && std::abs(a.k - b.k) < 1e-9; };
        auto result_of = [&](const ContourSpec& spec) -> const ContourResult* {
            for (const ContourResult& r : out.results)
                if (same(r.spec, spec)) return &r;
            for (const ContourResult& r : fill_results)
                if (same(r.spec, spec)) return &r;
            return nullptr;
        };
        std::vector<ContourSpec> needed = job.style.fill_contours();
        if (needed.empty()) // the whole map: patches, lit and shadow
            needed = {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}};
        fill_results.reserve(needed.size()); // result_of's pointers must stay valid
        for (const ContourSpec& spec : needed)
            if (!result_of(spec)) fill_results.push_back(engine.compute(spec, job.camera, job.light, job.engine));
        std::vector<const ContourResult*> contours;
        for (const ContourSpec& spec : needed) contours.push_back(result_of(spec));
        if (!rays) rays = (own_rays = std::make_unique<RayScene>(topology)).get();
        out.regions = build_planar_map(job.map_kind, engine, contours, rays, projection, job.camera, job.light).regions;
    }
    out.svg = to_svg(out.drawing, job.style, out.regions.empty() ? nullptr : &out.regions);
    return out;
}

} // namespace snaxels
