#include "ui/contour_overlay.h"

#include <algorithm>
#include <chrono>

#include <QColor>
#include <QStringList>

#include "snaxels/animation/still.h"
#include "snaxels/error.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels::ui {

const char* view_colour(ContourKind kind) { return contour_kind_info(kind).view_colour; }

RegionShading region_shading(const Style& style, const Light& light, bool enabled) {
    RegionShading r;
    r.enabled = enabled;
    r.light = light;
    auto colour = [](const std::string& text, const glm::vec3& fallback) {
        const QColor c(QString::fromStdString(text));
        return c.isValid() ? glm::vec3(float(c.redF()), float(c.greenF()), float(c.blueF())) : fallback;
    };
    if (!style.regions.empty()) {
        // The map's classes: a shadow contour comes with any fill but highlights (Style::fill_contours).
        r.shadow_contour = std::any_of(style.regions.begin(), style.regions.end(),
                                       [](const RegionStyle& region) { return region.cls != RegionClass::Highlight; });
        for (const RegionStyle& region : style.regions) {
            if (region.cls == RegionClass::Shadow) r.shadow = colour(region.fill, r.shadow);
            else if (region.cls == RegionClass::Lit) r.lit = colour(region.fill, r.lit);
            else if (region.cls == RegionClass::Band) r.bands.emplace_back(region.k, colour(region.fill, r.lit));
            else if (region.cls == RegionClass::Highlight) r.highlights.emplace_back(region.k, colour(region.fill, glm::vec3(1.0f)));
        }
    } else {
        for (const ContourStyle& cs : style.contours) {
            if (cs.spec.kind == ContourKind::Isophote) r.bands.emplace_back(cs.spec.k, glm::vec3(0.0f));
            if (cs.spec.kind == ContourKind::Gleam) r.highlights.emplace_back(cs.spec.k, glm::vec3(1.0f, 0.98f, 0.9f));
        }
        // Bands step from the lit tone toward a pale one.
        std::sort(r.bands.begin(), r.bands.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        for (std::size_t i = 0; i < r.bands.size(); ++i)
            r.bands[i].second = glm::mix(r.lit, glm::vec3(1.0f, 0.97f, 0.9f), float(i + 1) / float(r.bands.size() + 1));
    }
    auto ascending = [](const auto& a, const auto& b) { return a.first < b.first; };
    std::sort(r.bands.begin(), r.bands.end(), ascending);
    std::sort(r.highlights.begin(), r.highlights.end(), ascending);
    return r;
}

namespace {

// The scene's surface as @p style draws it (hidden objects left out, split
// along its sharp edges), in its loaded pose.
void build_surface(const LoadedMesh& mesh, ContourScene& scene, const Style& style) {
    scene.surface = style.surface;
    scene.hidden = style.hidden_objects;
    scene_surface(mesh, style, scene.split);
    scene.rest = engine_topology(scene.split ? *scene.split : mesh);
    scene.topology = scene.rest;
    scene.rays = std::make_unique<RayScene>(scene.topology);
    scene.driver.reset();
    scene.posed = false;
    scene.tracking = std::make_unique<StillTracking>();
}

} // namespace

std::shared_ptr<ContourScene> make_contour_scene(const LoadedMesh& mesh, const std::string& path,
                                                 const SurfaceOptions& surface) {
    auto scene = std::make_shared<ContourScene>();
    Style style;
    style.surface = surface;
    build_surface(mesh, *scene, style);
    scene->mesh_path = path;
    // Only formats that carry animation are read a second time for clips.
    const QString suffix = QString::fromStdString(path).section('.', -1).toLower();
    static const QStringList animated{"gltf", "glb", "fbx", "dae", "x", "blend", "md5mesh", "ms3d", "b3d", "smd", "bvh"};
    if (path.rfind("proc:", 0) != 0 && animated.contains(suffix)) {
        scene->clips = animation_clips(path);
        scene->cameras = file_cameras(path);
    }
    return scene;
}

namespace {

/// Poses @p scene for @p pose (or back to rest); true when the mesh moved.
/// Contours track through a step of one frame of the same clip; any other
/// change of pose is a jump for them.
bool pose_scene(const LoadedMesh& mesh, ContourScene& scene, const std::optional<ClipPose>& pose) {
    if (!pose) {
        if (!scene.posed) return false;
        scene.topology = scene.rest;
        scene.posed = false;
        if (scene.tracking) scene.tracking->jump();
    } else {
        const bool same_clip = scene.driver && scene.driver_spec == pose->clip;
        if (scene.posed && same_clip && pose->frame == scene.posed_frame) return false; // already there
        if (scene.tracking && !(scene.posed && same_clip && std::abs(pose->frame - scene.posed_frame) <= 1))
            scene.tracking->jump();
        if (!scene.driver || !(scene.driver_spec == pose->clip)) {
            scene.driver.reset();
            const glm::dvec3 centre = mesh.report.centre();
            scene.driver = std::make_unique<FrameDriver>(pose->clip, mesh, scene.rest, Camera{}, Light{}, centre,
                                                         scene.mesh_path);
            scene.driver_spec = pose->clip;
        }
        scene.topology = scene.driver->pose(pose->frame).mesh;
        scene.posed = true;
        scene.posed_frame = pose->frame;
    }
    scene.rays->refit(scene.topology);
    return true;
}

} // namespace

OverlayResult compute_overlay(const LoadedMesh& mesh, ContourScene& scene, const Camera& camera,
                              const Style& style, const std::optional<Light>& light,
                              const std::optional<ClipPose>& pose,
                              std::shared_ptr<const ParabolicResult> parabolic, bool show_parabolic,
                              const std::optional<CameraShot>& shot) {
    const auto start = std::chrono::steady_clock::now();
    OverlayResult out;
    out.camera = camera;
    Style framed = style;
    try {
        // A style that moves the sharp edges gives the surface new vertices:
        // its scene is built again, and drawn anew.
        bool changed = false;
        if (!(style.surface == scene.surface) || style.hidden_objects != scene.hidden) {
            build_surface(mesh, scene, style);
            changed = true;
        }
        changed = pose_scene(scene.split ? *scene.split : mesh, scene, pose) || changed;
        if (shot) {
            // The track of the file's camera, read once per camera and clip.
            const AnimationSpec& a = shot->animation;
            const bool shared_clip = a.kind == AnimationSpec::Kind::Clip || a.kind == AnimationSpec::Kind::Camera;
            const std::string clip = shared_clip ? a.clip : "";
            if (!scene.track || scene.track_camera != a.camera || scene.track_clip != clip) {
                scene.track.reset();
                scene.track = std::make_unique<CameraTrack>(scene.mesh_path, a.camera, clip);
                scene.track_camera = a.camera;
                scene.track_clip = clip;
            }
            out.camera = camera_at_frame(a, camera, scene.track.get(), a.start + shot->frame, mesh.report.centre());
            framed.height = canvas_height_for(scene.track->info(), framed.width, framed.height);
        }
        if (changed) out.geometry = std::make_shared<MeshGeometry>(mesh_geometry(scene.topology, display_face_budget()));
    } catch (const std::exception& e) {
        out.error = QString::fromStdString(e.what());
        return out;
    }
    // Curves found before the surface was split anew lie on other edges.
    if (parabolic && parabolic->mesh_edges != scene.topology.n_edges()) parabolic.reset();
    keep_parabolic(scene.topology, ParabolicOptions{}, parabolic);
    out.canvas_width = framed.width;
    out.canvas_height = framed.height;
    StillJob job = make_still_job(framed, out.camera, light);
    auto is_parabolic = [](const ContourSpec& k) { return k.kind == ContourKind::Parabolic; };
    if (!parabolic) job.scene.kinds.erase(std::remove_if(job.scene.kinds.begin(), job.scene.kinds.end(), is_parabolic), job.scene.kinds.end());
    StillOutput still;
    try {
        still = render_still(scene.split ? *scene.split : mesh, scene.topology, scene.rays.get(), job, scene.tracking.get());
    } catch (const Error& e) { // a view the drawing cannot show (the eye on a surface): said in the status bar
        out.error = QString::fromStdString(e.what());
        return out;
    }
    out.light = job.scene.light;
    if (show_parabolic && parabolic && std::none_of(job.scene.kinds.begin(), job.scene.kinds.end(), is_parabolic)) {
        // View > Parabolic Curves: in the 3-D view only.
        const SnaxelEngine engine(scene.topology);
        still.results.push_back(engine.compute(ContourSpec{ContourKind::Parabolic, 0.0}, job.scene.camera, job.scene.light));
        still.visibility.push_back(VisibilitySampler(*scene.rays, job.scene.camera).classify(engine, still.results.back()));
    }

    out.svg = std::move(still.svg);
    for (std::size_t c = 0; c < still.results.size(); ++c) {
        const ContourResult& r = still.results[c];
        const QColor colour(view_colour(r.spec.kind));
        out.loops += r.fronts.loops.size();
        out.snaxels += r.fronts.snaxels.size();
        for (const LoopVisibility& loop : still.visibility[c].loops)
            for (const VisibilityRun& run : loop.runs) {
                if (run.qi == kNotDrawn) continue; // a part the contour leaves out
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
