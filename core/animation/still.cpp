#include "snaxels/animation/still.h"
#include "snaxels/export/stroke_weight.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "snaxels/error.h"
#include "snaxels/export/svg.h"
#include "snaxels/util/detail/float_mode.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {

StillJob make_still_job(const Style& style, const Camera& camera, const std::optional<Light>& light) {
    SceneOverrides overrides;
    overrides.light = light;
    overrides.check_invariants = false;
    StillJob job{scene_settings(style, camera, overrides)};
    job.all_hidden_levels = false;
    return job;
}

StillTracking::StillTracking(double max_step_deg) : max_step_deg_(max_step_deg) {}

namespace {

double angle_deg(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)));
}

} // namespace

std::vector<ContourResult> StillTracking::compute(const MeshTopology& topology, const std::vector<ContourSpec>& specs,
                                                  const Camera& camera, const Light& light,
                                                  const EngineOptions& options, const glm::dvec3& centre,
                                                  bool vertex_data) {
    // A far step: another mesh, or what the view and the light look like
    // from the mesh's centre.
    bool far = connectivity_ != topology.connectivity() || !camera_ || !light_ || camera_->projection != camera.projection || light_->point != light.point;
    if (!far)
        far = angle_deg(camera_->to_viewer(centre), camera.to_viewer(centre)) > max_step_deg_ ||
              angle_deg(light_->to_light(centre), light.to_light(centre)) > max_step_deg_;
    if (far) trackers_.clear();
    connectivity_ = topology.connectivity();
    camera_ = camera;
    light_ = light;
    // Trackers for the kinds asked for, in order; the others forgotten.
    std::map<std::string, std::unique_ptr<ContourTracker>> kept;
    std::vector<ContourTracker*> tracker(specs.size(), nullptr);
    for (std::size_t i = 0; i < specs.size(); ++i) {
        if (specs[i].on_surface()) continue; // the mesh's own lines: found, not tracked
        const std::string key = specs[i].line().label(); // line sets of one line share its tracker
        auto it = kept.find(key);
        if (it == kept.end()) {
            auto old = trackers_.find(key);
            std::unique_ptr<ContourTracker> t = old != trackers_.end() && old->second
                                                    ? std::move(old->second)
                                                    : std::make_unique<ContourTracker>(topology, specs[i], options);
            it = kept.emplace(key, std::move(t)).first;
        }
        tracker[i] = it->second.get();
    }
    trackers_ = std::move(kept);
    std::vector<ContourResult> results(specs.size());
    std::vector<char> fresh(specs.size(), 0);
    const SnaxelEngine engine(topology);
    // One tracker may serve two equal specs: each tracker steps once.
    std::vector<std::size_t> first_of(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i) {
        first_of[i] = i;
        for (std::size_t j = 0; j < i; ++j)
            if (tracker[i] && tracker[j] == tracker[i]) {
                first_of[i] = j;
                break;
            }
    }
    parallel_for(specs.size(), [&](std::size_t i) {
        if (!tracker[i]) {
            results[i] = engine.compute(specs[i], camera, light, options);
        } else if (first_of[i] == i) {
            fresh[i] = tracker[i]->frames() == 0;
            const ContourResult& tracked = tracker[i]->step(topology, camera, light).contour;
            results[i] = vertex_data ? tracked : lines_of(tracked);
        }
    }, 1);
    for (std::size_t i = 0; i < specs.size(); ++i) {
        if (first_of[i] != i) results[i] = results[first_of[i]];
        else if (tracker[i]) (fresh[i] ? restarts_ : tracked_) += 1;
    }
    for (std::size_t i = 0; i < specs.size(); ++i) results[i].spec = specs[i]; // each line set's parts
    return results;
}

namespace {

/// The contours a planar map of @p style is built from (the snaxel-defined
/// map unless the job asks for the post-processed one): the fills', or,
/// without fills, the whole map's (patches, lit and shadow).
std::vector<ContourSpec> map_contours(const Style& style) {
    std::vector<ContourSpec> needed = style.fill_contours();
    if (needed.empty()) needed = {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}};
    return needed;
}

/// @p drawn, then those of @p needed that no drawn line set has.
std::vector<ContourSpec> contours_to_find(const std::vector<ContourSpec>& drawn, const std::vector<ContourSpec>& needed) {
    std::vector<ContourSpec> specs = drawn;
    for (const ContourSpec& spec : needed)
        if (std::none_of(specs.begin(), specs.end(), [&](const ContourSpec& s) { return s.line().same_as(spec); }))
            specs.push_back(spec);
    return specs;
}

/// Every contour of @p specs from scratch, in parallel; line sets of one
/// line (other parts) share its computation.
std::vector<ContourResult> compute_line_sets(const SnaxelEngine& engine, const std::vector<ContourSpec>& specs,
                                             const SceneSettings& scene) {
    std::vector<std::size_t> first(specs.size());
    for (std::size_t i = 0; i < specs.size(); ++i)
        for (first[i] = 0; !specs[first[i]].line().same_as(specs[i].line());) ++first[i];
    std::vector<ContourResult> all(specs.size());
    parallel_for(specs.size(), [&](std::size_t i) {
        if (first[i] == i) all[i] = engine.compute(specs[i], scene.camera, scene.light, scene.engine);
    }, 1);
    for (std::size_t i = 0; i < specs.size(); ++i)
        if (first[i] != i) {
            all[i] = all[first[i]];
            all[i].spec = specs[i];
        }
    return all;
}

} // namespace

StillOutput render_still(const LoadedMesh& mesh, const MeshTopology& topology, const RayScene* rays,
                         const StillJob& job, StillTracking* tracking) {
    const FloatModeGuard float_mode;
    const SceneSettings& scene = job.scene;
    StillOutput out;
    const MeshReport& report = mesh.report;
    const glm::dvec3 centre = report.centre();
    const double radius = std::max(0.5 * glm::length(report.bbox_max - report.bbox_min), 1e-12);
    if (rays && rays->topology().pose() != topology.pose())
        throw InternalError("render_still: the ray scene is of another pose than the topology");
    require_eye_off_surface(scene.camera, topology);
    const SnaxelEngine engine(topology);

    // Every contour at once (in parallel): the drawn kinds, then those the
    // fills need that are not drawn.
    const bool map = !scene.style.regions.empty() || scene.planar_map;
    const std::vector<ContourSpec> needed = map ? map_contours(scene.style) : std::vector<ContourSpec>{};
    const std::vector<ContourSpec> specs = contours_to_find(scene.kinds, needed);
    std::unique_ptr<RayScene> own_rays;
    if (!rays && (scene.visibility || map)) rays = (own_rays = std::make_unique<RayScene>(topology)).get();
    // The snaxel map's rays from the vertices need only the visual
    // contour's function, not its fronts: they are cast beside the contours.
    std::optional<VertexSight> sight;
    const auto visual = std::find_if(needed.begin(), needed.end(), [](const ContourSpec& s) { return s.kind == ContourKind::Visual; });
    auto see = [&] {
        if (map && scene.map_kind == PlanarMapKind::Snaxel && visual != needed.end())
            sight = see_vertices(topology, *rays, scene.camera, scene.light, *visual);
    };
    std::vector<ContourResult> all;
    auto find_contours = [&] {
        if (tracking) {
            all = tracking->compute(topology, specs, scene.camera, scene.light, scene.engine, centre, map);
            return;
        }
        all = compute_line_sets(engine, specs, scene);
    };
    parallel_invoke(find_contours, see);
    out.results.assign(std::make_move_iterator(all.begin()), std::make_move_iterator(all.begin() + std::ptrdiff_t(scene.kinds.size())));
    const std::vector<ContourResult> fill_results(std::make_move_iterator(all.begin() + std::ptrdiff_t(scene.kinds.size())),
                                                  std::make_move_iterator(all.end()));

    const ImageProjection projection = drawing_projection(scene.style, scene.camera, centre, radius);
    // The lines (hidden lines of every kind at once, the drawing) and the
    // planar map are made at once: they share only what they read.
    auto lines = [&] {
        if (scene.visibility) {
            const VisibilitySampler sampler(*rays, scene.camera);
            out.visibility.resize(out.results.size());
            auto levels = [&](const ContourSpec& spec) {
                if (job.all_hidden_levels) return VisibilitySampler::HiddenLevels::Counted;
                const ContourStyle cs = scene.style.contour(spec);
                const bool by_qi = cs.visible.width_by == StrokeStyle::WidthBy::Qi || cs.hidden.width_by == StrokeStyle::WidthBy::Qi;
                return cs.hidden.draw || by_qi ? VisibilitySampler::HiddenLevels::Counted
                                               : VisibilitySampler::HiddenLevels::WhereSeen;
            };
            parallel_for(out.results.size(), [&](std::size_t c) {
                out.visibility[c] = sampler.classify(engine, out.results[c], levels(out.results[c].spec));
            }, 1);
        }
        out.drawing = make_drawing(engine, out.results, projection, scene.visibility ? &out.visibility : nullptr);
        weigh_strokes(out.drawing, scene.style, engine, out.results, scene.camera, scene.light, centre, radius);
    };
    auto fills = [&] {
        if (!map) return;
        auto result_of = [&](const ContourSpec& spec) -> const ContourResult* {
            for (const ContourResult& r : out.results)
                if (r.spec.line().same_as(spec)) return &r;
            for (const ContourResult& r : fill_results)
                if (r.spec.line().same_as(spec)) return &r;
            return nullptr;
        };
        std::vector<const ContourResult*> contours;
        for (const ContourSpec& spec : needed) contours.push_back(result_of(spec));
        out.regions = build_planar_map(scene.map_kind, engine, contours, rays, projection, scene.camera, scene.light,
                                       sight ? &*sight : nullptr).regions;
    };
    parallel_invoke(lines, fills);
    out.svg = to_svg(out.drawing, scene.style, out.regions.empty() ? nullptr : &out.regions);
    return out;
}

} // namespace snaxels
