#include "snaxels/animation/pipeline.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "snaxels/error.h"
#include "snaxels/animation/still.h"
#include "snaxels/export/stroke_weight.h"
#include "snaxels/export/lottie.h"
#include "snaxels/export/svg.h"
#include "snaxels/snaxel/parabolic.h"
#include "snaxels/util/atomic_file.h"
#include "snaxels/planarmap/region_tracker.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

AnimationFormat animation_format_for(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".json" ? AnimationFormat::Lottie : AnimationFormat::Svg;
}

AnimationJob make_animation_job(const Style& style, const AnimationSpec& animation, const Camera& camera,
                                const std::optional<Light>& light) {
    // The same scene as the view's still frame, animated.
    AnimationJob job;
    job.animation = animation;
    job.scene = make_still_job(style, camera, light).scene;
    job.light_from_camera = !light && !style.light;
    return job;
}

nlohmann::json events_json(const AnimationOutput& out, const AnimationJob& job) {
    nlohmann::json events = nlohmann::json::array();
    for (const auto& [c, e] : out.events)
        events.push_back({{"frame", e.frame},
                          {"kind", event_name(e.kind)},
                          {"contour", job.scene.kinds[c].label()},
                          {"where", {e.where.x, e.where.y, e.where.z}}});
    return events;
}

namespace {

/// Parabolic curves are the mesh's: found once, on the pose as loaded, and
/// carried by the edges as the mesh moves (require_parabolic keeps them in
/// the pose, and the frames' poses are made from it).
void attach_parabolic(const MeshTopology& topology, const AnimationJob& job) {
    if (std::none_of(job.scene.kinds.begin(), job.scene.kinds.end(), [](const ContourSpec& k) { return k.kind == ContourKind::Parabolic; }))
        return;
    ParabolicOptions options;
    options.progress = job.parabolic_progress;
    options.cancelled = job.cancelled;
    try {
        require_parabolic(topology, options);
    } catch (const ParabolicCancelled&) {
        throw AnimationCancelled();
    }
}

/// What the image is framed on, and the camera of a moving mesh.
struct ImageFrame {
    glm::dvec3 centre{0.0};
    double radius = 1.0;
    Camera camera;
};

/// The image frame: the mesh's bounding sphere over every frame; a mesh that
/// moves is framed on the union of its poses over the animation (its rest
/// pose, as loaded, may stand elsewhere and at another scale).
ImageFrame frame_image(FrameDriver& driver, const LoadedMesh& mesh, const AnimationJob& job, int frames) {
    const glm::dvec3 mesh_centre = mesh.report.centre();
    glm::dvec3 lo = mesh.report.bbox_min, hi = mesh.report.bbox_max;
    ImageFrame out;
    out.camera = job.scene.camera;
    if (driver.mesh_moves()) {
        lo = glm::dvec3(1e300), hi = glm::dvec3(-1e300);
        for (int k = 0; k < frames; ++k) {
            const FramePose pose = driver.pose(k); // named: the positions are a view into it
            for (const auto& p : pose.mesh.positions()) lo = glm::min(lo, p), hi = glm::max(hi, p);
        }
        // A perspective camera aimed at the loaded mesh's centre (the
        // default) follows it to the poses' centre.
        const glm::dvec3 shift = 0.5 * (lo + hi) - mesh_centre;
        if (!out.camera.orthographic() &&
            glm::length(out.camera.target - mesh_centre) <= 1e-9 * (1.0 + glm::length(mesh_centre))) {
            out.camera.target += shift;
            out.camera.eye += shift;
        }
    }
    out.centre = 0.5 * (lo + hi);
    out.radius = std::max(0.5 * glm::length(hi - lo), 1e-12);
    return out;
}

/// A tracked frame's loops as the animation writer takes them: snaxel ids.
std::vector<AnimatedLoop> animated_loops(const TrackedFrame& tf) {
    std::vector<AnimatedLoop> loops;
    for (std::size_t l = 0; l < tf.contour.fronts.loops.size(); ++l) {
        AnimatedLoop al;
        al.sequence = tf.loop_sequence[l];
        tf.contour.fronts.for_each_in_loop(tf.contour.fronts.loops[l], [&](std::int32_t s) { al.ids.push_back(tf.snaxel_id[s]); });
        loops.push_back(std::move(al));
    }
    return loops;
}

/// The surface point of every snaxel of every loop of @p fronts.
std::vector<std::vector<SurfacePoint>> surface_points(const Fronts& fronts) {
    std::vector<std::vector<SurfacePoint>> out(fronts.loops.size());
    for (std::size_t l = 0; l < fronts.loops.size(); ++l)
        fronts.for_each_in_loop(fronts.loops[l], [&](std::int32_t s) {
            const Snaxel& sn = fronts.snaxels[s];
            out[l].push_back({sn.inside, sn.outside, sn.t});
        });
    return out;
}

/// The finished document: into @p file in blocks of about a megabyte, or
/// into out.document.
void finish_output(AnimationWriter& writer, AtomicFile* file, AnimationOutput& out) {
    if (!file) {
        writer.finish([&](std::string_view piece) { out.document += piece; }, &out.stats);
        out.bytes = out.document.size();
        return;
    }
    std::string block;
    writer.finish(
        [&](std::string_view piece) {
            block += piece;
            out.bytes += piece.size();
            if (block.size() > (1u << 20)) file->write(block), block.clear();
        },
        &out.stats);
    file->write(block);
    file->commit();
}

} // namespace

AnimationOutput run_animation(const LoadedMesh& loaded, const std::string& mesh_path, const AnimationJob& asked) {
    AnimationOutput out;
    AnimationJob job = asked;
    std::optional<LoadedMesh> surface;
    const LoadedMesh& mesh = scene_surface(loaded, job.scene.style, surface);
    MeshTopology rest = engine_topology(mesh, job.scene.refine); // the mesh as loaded
    attach_parabolic(rest, job);
    const glm::dvec3 mesh_centre = mesh.report.centre();
    FrameDriver driver(job.animation, mesh, rest, job.scene.camera, job.scene.light, mesh_centre, mesh_path);
    if (const FileCamera* camera = driver.file_camera()) {
        if (job.canvas_follows_camera)
            job.scene.style.height = canvas_height_for(*camera, job.scene.style.width, job.scene.style.height);
        if (job.light_from_camera) {
            job.scene.light = default_light(camera->first);
            driver.set_light(job.scene.light);
        }
    }
    const int frames = animation_frame_count(job.animation, mesh_path);
    out.frames = frames;
    const ImageFrame image = frame_image(driver, mesh, job, frames);

    if (!job.frames_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(job.frames_dir, ec);
        if (ec) throw Error("cannot create " + job.frames_dir + ": " + ec.message());
    }
    // One tracker per line: line sets of one line (other parts) share it.
    std::vector<ContourTracker> trackers;
    std::vector<std::size_t> tracker_of; // per kind
    std::vector<std::unique_ptr<StrokeParameter>> stroke_parameters; // per kind, where its strokes read one
    for (std::size_t c = 0; c < job.scene.kinds.size(); ++c) {
        const ContourSpec& spec = job.scene.kinds[c];
        std::size_t t = 0;
        while (t < c && !job.scene.kinds[t].line().same_as(spec.line())) ++t;
        if (t == c) {
            tracker_of.push_back(trackers.size());
            trackers.emplace_back(rest, spec.line(), job.scene.engine);
        } else {
            tracker_of.push_back(tracker_of[t]);
        }
        const ContourStyle cs = job.scene.style.contour(spec);
        stroke_parameters.push_back((cs.visible.draw && cs.visible.carries_parameter()) || (cs.hidden.draw && cs.hidden.carries_parameter())
                                        ? std::make_unique<StrokeParameter>()
                                        : nullptr);
    }
    // Fills: the planar map's contours the drawn ones lack are tracked too.
    const bool fills = !job.scene.style.regions.empty();
    std::vector<ContourSpec> fill_specs = job.scene.style.fill_contours();
    std::vector<ContourTracker> fill_trackers;
    if (fills)
        for (const ContourSpec& spec : fill_specs)
            if (std::none_of(job.scene.kinds.begin(), job.scene.kinds.end(), [&](const ContourSpec& k) { return k.line().same_as(spec); }))
                fill_trackers.emplace_back(rest, spec, job.scene.engine);
    RegionTracker region_tracker;
    std::unique_ptr<RayScene> rays;
    // Frames are encoded as they come; the document is written at the end.
    AnimationWriter writer(job.format, std::size_t(frames), job.animation.fps, job.svg, job.scene.style);
    std::unique_ptr<AtomicFile> file;
    if (!job.output.empty()) file = std::make_unique<AtomicFile>(job.output); // fails early on a bad path
    for (int k = 0; k < frames; ++k) {
        if (job.cancelled && job.cancelled()) throw AnimationCancelled();
        FramePose pose = driver.pose(k);
        const MeshTopology& topology = pose.mesh;
        const Light& light = pose.light;
        Camera& camera = pose.camera;
        // A moving mesh's camera stays (framed on its poses), unless the
        // file's camera moves with it.
        if (driver.mesh_moves() && !driver.camera_moves()) camera = image.camera;
        require_mesh_in_front(camera, topology.positions(), image.radius);
        if (job.scene.visibility || fills) {
            if (!rays) rays = std::make_unique<RayScene>(topology);
            else if (driver.mesh_moves()) rays->refit(topology);
        }
        const SnaxelEngine engine(topology);
        std::vector<ContourResult> results;
        std::vector<ContourVisibility> visibility;
        AnimationFrame frame;
        double ms = 0.0;
        // The kinds track independently: in parallel.
        std::vector<const TrackedFrame*> tracked(trackers.size() + fill_trackers.size());
        parallel_for(tracked.size(), [&](std::size_t c) {
            tracked[c] = c < trackers.size() ? &trackers[c].step(topology, camera, light)
                                             : &fill_trackers[c - trackers.size()].step(topology, camera, light);
        }, 1);
        for (std::size_t t = 0; t < trackers.size(); ++t) ms += tracked[t]->contour.stats.ms;
        for (std::size_t c = 0; c < job.scene.kinds.size(); ++c) {
            const TrackedFrame& tf = *tracked[tracker_of[c]];
            results.push_back(tf.contour);
            results.back().spec = job.scene.kinds[c]; // the line set's parts
            frame.loops.push_back(animated_loops(tf));
            for (const VisualEvent& e : tf.events) out.events.push_back({c, e});
            if (job.scene.visibility) visibility.push_back(VisibilitySampler(*rays, camera).classify(engine, results.back()));
        }
        out.tracking_ms.push_back(ms);
        const ImageProjection projection(camera, image.centre, image.radius, job.scene.style.width, job.scene.style.height, job.scene.style.margin);
        frame.drawing = make_drawing(engine, results, projection, job.scene.visibility ? &visibility : nullptr);
        frame.drawing.seconds = double(k) / job.animation.fps;
        weigh_strokes(frame.drawing, job.scene.style, engine, results, camera, light, image.centre, image.radius);
        for (std::size_t c = 0; c < results.size(); ++c)
            if (stroke_parameters[c]) {
                const std::vector<std::vector<SurfacePoint>> points = surface_points(results[c].fronts);
                stroke_parameters[c]->step(frame.drawing.contours[c], frame.loops[c], &points, [&](const SurfacePoint& sp) {
                    return projection.project((1.0 - sp.t) * topology.positions()[sp.a] + sp.t * topology.positions()[sp.b]);
                });
            }
        if (fills) {
            std::vector<const ContourResult*> contours;
            for (const ContourSpec& spec : fill_specs) {
                const ContourResult* r = nullptr;
                for (std::size_t c = 0; c < tracked.size() && !r; ++c)
                    if (tracked[c]->contour.spec.line().same_as(spec)) r = &tracked[c]->contour;
                contours.push_back(r);
            }
            PlanarMap map = build_planar_map(job.scene.map_kind, engine, contours, rays.get(), projection, camera, light);
            frame.region_tracks = region_tracker.step(map);
            frame.regions = std::move(map.regions);
        }
        for (auto& contour : frame.drawing.contours)
            for (auto& loop : contour.loops) std::vector<glm::dvec3>().swap(loop.p); // not exported: memory freed
        if (!job.frames_dir.empty()) {
            char name[64];
            std::snprintf(name, sizeof name, "frame_%05d.svg", k);
            write_file_atomically((std::filesystem::path(job.frames_dir) / name).string(),
                                  to_svg(frame.drawing, job.scene.style, frame.regions.empty() ? nullptr : &frame.regions));
        }
        writer.add(std::move(frame));
        if (job.progress) job.progress(k + 1, frames);
    }
    finish_output(writer, file.get(), out);
    return out;
}

} // namespace snaxels
