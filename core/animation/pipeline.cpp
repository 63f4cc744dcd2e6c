#include "snaxels/animation/pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include <tbb/parallel_pipeline.h>

#include "snaxels/error.h"
#include "snaxels/animation/still.h"
#include "snaxels/export/stroke_parameter.h"
#include "snaxels/export/stroke_weight.h"
#include "snaxels/export/lottie.h"
#include "snaxels/export/raster.h"
#include "snaxels/export/svg.h"
#include "snaxels/export/video.h"
#include "snaxels/snaxel/parabolic.h"
#include "snaxels/util/atomic_file.h"
#include "snaxels/planarmap/region_tracker.h"
#include "snaxels/util/detail/float_mode.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

bool set_output(AnimationJob& job, const std::string& path) {
    const std::optional<OutputKind> kind = output_kind_for(path);
    if (!kind) return false;
    if (is_video(*kind)) {
        job.video = path;
        job.video_kind = *kind;
        job.output.clear();
        job.document = false;
    } else {
        job.output = path;
        job.format = document_format(*kind);
        job.encoding = document_encoding(*kind);
        job.document = true;
    }
    return true;
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

/// Frames between tracking and the writer at once (run_animation).
constexpr std::size_t kFramesInFlight = 8;

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

/// The finished document: into @p file (encoded as it asks), or into
/// out.document.
void finish_output(AnimationWriter& writer, DocumentFile* file, AnimationOutput& out) {
    if (!file) {
        writer.finish([&](std::string_view piece) { out.document += piece; }, &out.stats);
        out.bytes = out.document.size();
        return;
    }
    writer.finish([&](std::string_view piece) { file->write(piece); }, &out.stats);
    file->finish();
    out.bytes = file->document_bytes();
}

} // namespace

namespace {

/// A frame on its way through run_animation's stages.
struct InFlight {
    int k = 0;
    FramePose pose;
    std::vector<ContourResult> results;
    std::vector<ContourVisibility> visibility;
    AnimationFrame frame;
    std::string still; ///< the frame's static SVG, when it is rendered
    RgbaImage picture; ///< the rendered frame, for a video or PNG files
};

/// The frames of one export: what carries from frame to frame (trackers,
/// the ray scene, stroke parameters, the writer) and the five stages each
/// frame goes through (run_animation).
class FrameStages {
  public:
    FrameStages(const AnimationJob& job, FrameDriver& driver, const MeshTopology& rest, const ImageFrame& image,
                int frames, AnimationOutput& out)
        : job_(job), driver_(driver), image_(image), frames_(frames), out_(out),
          fills_(!job.scene.style.regions.empty()), fill_specs_(job.scene.style.fill_contours()),
          writer_(job.format, std::size_t(frames), job.animation.fps, job.svg, job.scene.style) {
        // One tracker per line: line sets of one line (other parts) share it.
        for (std::size_t c = 0; c < job.scene.kinds.size(); ++c) {
            const ContourSpec& spec = job.scene.kinds[c];
            std::size_t t = 0;
            while (t < c && !job.scene.kinds[t].line().same_as(spec.line())) ++t;
            if (t == c) {
                tracker_of_.push_back(trackers_.size());
                trackers_.emplace_back(rest, spec.line(), job.scene.engine);
            } else {
                tracker_of_.push_back(tracker_of_[t]);
            }
            const ContourStyle cs = job.scene.style.contour(spec);
            stroke_parameters_.push_back((cs.visible.draw && cs.visible.carries_parameter()) ||
                                                 (cs.hidden.draw && cs.hidden.carries_parameter())
                                             ? std::make_unique<StrokeParameter>()
                                             : nullptr);
        }
        // Fills: the planar map's contours the drawn ones lack are tracked too.
        if (fills_)
            for (const ContourSpec& spec : fill_specs_)
                if (std::none_of(job.scene.kinds.begin(), job.scene.kinds.end(), [&](const ContourSpec& k) { return k.line().same_as(spec); }))
                    fill_trackers_.emplace_back(rest, spec, job.scene.engine);
    }

    AnimationWriter& writer() { return writer_; }

    /// 1. In frame order: pose, tracking, hidden lines, the planar map
    /// (they carry state from frame to frame, and the rays are refitted to
    /// each pose).
    std::shared_ptr<InFlight> track(int k) {
        const FloatModeGuard mode;
        if (job_.cancelled && job_.cancelled()) throw AnimationCancelled();
        auto w = std::make_shared<InFlight>();
        w->k = k;
        w->pose = driver_.pose(k);
        const MeshTopology& topology = w->pose.mesh;
        const Light& light = w->pose.light;
        Camera& camera = w->pose.camera;
        // A moving mesh's camera stays (framed on its poses), unless the
        // file's camera moves with it.
        if (driver_.mesh_moves() && !driver_.camera_moves()) camera = image_.camera;
        require_eye_off_surface(camera, topology);
        if (job_.scene.visibility || fills_) {
            if (!rays_) rays_ = std::make_unique<RayScene>(topology);
            else if (driver_.mesh_moves()) rays_->refit(topology);
        }
        const SnaxelEngine engine(topology);
        double ms = 0.0;
        // The kinds track independently: in parallel.
        std::vector<const TrackedFrame*> tracked(trackers_.size() + fill_trackers_.size());
        parallel_for(tracked.size(), [&](std::size_t c) {
            tracked[c] = c < trackers_.size() ? &trackers_[c].step(topology, camera, light)
                                              : &fill_trackers_[c - trackers_.size()].step(topology, camera, light);
        }, 1);
        for (std::size_t t = 0; t < trackers_.size(); ++t) ms += tracked[t]->contour.stats.ms;
        for (std::size_t c = 0; c < job_.scene.kinds.size(); ++c) {
            const TrackedFrame& tf = *tracked[tracker_of_[c]];
            w->results.push_back(lines_of(tf.contour)); // (the map reads the tracker's own)
            w->results.back().spec = job_.scene.kinds[c]; // the line set's parts
            w->frame.loops.push_back(animated_loops(tf));
            for (const VisualEvent& e : tf.events) out_.events.push_back({c, e});
            if (job_.scene.visibility) w->visibility.push_back(VisibilitySampler(*rays_, camera).classify(engine, w->results.back()));
        }
        out_.tracking_ms.push_back(ms);
        if (fills_) {
            std::vector<const ContourResult*> contours;
            for (const ContourSpec& spec : fill_specs_) {
                const ContourResult* r = nullptr;
                for (std::size_t c = 0; c < tracked.size() && !r; ++c)
                    if (tracked[c]->contour.spec.line().same_as(spec)) r = &tracked[c]->contour;
                contours.push_back(r);
            }
            PlanarMap map = build_planar_map(job_.scene.map_kind, engine, contours, rays_.get(), projection(camera), camera, light);
            w->frame.region_tracks = region_tracker_.step(map);
            w->frame.regions = std::move(map.regions);
        }
        return w;
    }

    /// 2. Any frames at once: the drawing, from the frame's results alone.
    void draw(InFlight& w) const {
        const FloatModeGuard mode;
        const SnaxelEngine engine(w.pose.mesh);
        w.frame.drawing = make_drawing(engine, w.results, projection(w.pose.camera), job_.scene.visibility ? &w.visibility : nullptr);
        w.frame.drawing.seconds = double(w.k) / job_.animation.fps;
        weigh_strokes(w.frame.drawing, job_.scene.style, engine, w.results, w.pose.camera, w.pose.light, image_.centre,
                      image_.radius);
    }

    /// 3. In frame order: the stroke parameter (carried from frame to
    /// frame), the flipbook frame, and the writer (which encodes a chunk of
    /// frames as it fills).
    void write(InFlight& w) {
        const FloatModeGuard mode;
        const MeshTopology& topology = w.pose.mesh;
        const ImageProjection image = projection(w.pose.camera);
        for (std::size_t c = 0; c < w.results.size(); ++c)
            if (stroke_parameters_[c]) {
                const std::vector<std::vector<SurfacePoint>> points = surface_points(w.results[c].fronts);
                stroke_parameters_[c]->step(w.frame.drawing.contours[c], w.frame.loops[c], &points, [&](const SurfacePoint& sp) {
                    return image.project((1.0 - sp.t) * topology.positions()[sp.a] + sp.t * topology.positions()[sp.b]);
                });
            }
        for (auto& contour : w.frame.drawing.contours)
            for (auto& loop : contour.loops) std::vector<glm::dvec3>().swap(loop.p); // not exported: memory freed
        if (!job_.frames_dir.empty() || renders()) {
            std::string still = to_svg(w.frame.drawing, job_.scene.style, w.frame.regions.empty() ? nullptr : &w.frame.regions);
            if (!job_.frames_dir.empty())
                write_file_atomically((std::filesystem::path(job_.frames_dir) / frame_name(w.k, "svg")).string(), still);
            if (renders()) w.still = std::move(still);
        }
        if (job_.document) writer_.add(std::move(w.frame));
        else w.frame = {};
    }

    /// Whether the frames are rendered (for a video or PNG files).
    bool renders() const { return !job_.video.empty() || !job_.png_dir.empty(); }

    /// 4. Any frames at once: the rendered frame.
    void render(InFlight& w) const {
        if (!renders()) return;
        const auto [width, height] = rendered_size();
        w.picture = render_svg(w.still, width, height, !job_.video.empty());
        std::string().swap(w.still);
    }

    /// 5. In frame order: the rendered frame into the video and the PNG
    /// folder, and the progress.
    void deliver(InFlight& w) {
        if (!job_.png_dir.empty()) write_png((std::filesystem::path(job_.png_dir) / frame_name(w.k, "png")).string(), w.picture);
        if (video_) video_->add(w.picture);
        w.picture = {};
        if (job_.progress) job_.progress(w.k + 1, frames_);
    }

    /// The video being encoded, if any (started before the frames, so a bad
    /// path or a missing ffmpeg fails at once).
    void start_video() {
        if (!job_.video.empty())
            video_ = std::make_unique<VideoEncoder>(job_.video, job_.video_kind, rendered_size().first,
                                                    rendered_size().second, job_.animation.fps, job_.video_crf);
    }
    void finish_video() {
        if (video_) video_->finish();
    }

  private:
    /// The rendered frames' size: the canvas's, or video_width across at its aspect.
    std::pair<int, int> rendered_size() const {
        const int w = job_.scene.style.width, h = job_.scene.style.height;
        if (job_.video_width <= 0 || w <= 0) return {w, h};
        return {job_.video_width, std::max(1, int(std::lround(double(h) * job_.video_width / w)))};
    }
    static std::string frame_name(int k, const char* extension) {
        char name[64];
        std::snprintf(name, sizeof name, "frame_%05d.%s", k, extension);
        return name;
    }

    ImageProjection projection(const Camera& camera) const {
        return drawing_projection(job_.scene.style, camera, image_.centre, image_.radius);
    }

    const AnimationJob& job_;
    FrameDriver& driver_;
    const ImageFrame& image_;
    int frames_;
    AnimationOutput& out_;
    bool fills_;
    std::vector<ContourSpec> fill_specs_;
    std::vector<ContourTracker> trackers_, fill_trackers_;
    std::vector<std::size_t> tracker_of_; ///< per kind
    std::vector<std::unique_ptr<StrokeParameter>> stroke_parameters_; ///< per kind, where its strokes read one
    RegionTracker region_tracker_;
    std::unique_ptr<RayScene> rays_;
    AnimationWriter writer_; ///< frames are encoded as they come; the document is written at the end
    std::unique_ptr<VideoEncoder> video_;
};

} // namespace

AnimationOutput run_animation(const LoadedMesh& loaded, const std::string& mesh_path, const AnimationJob& asked) {
    const FloatModeGuard float_mode; // (each frame stage sets it too, on the thread it runs on)
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

    for (const std::string& dir : {job.frames_dir, job.png_dir}) {
        if (dir.empty()) continue;
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        if (ec) throw Error("cannot create " + dir + ": " + ec.message());
    }
    if ((!job.video.empty() || !job.png_dir.empty()) &&
        (job.scene.style.width > kMaxRenderedSide || job.scene.style.height > kMaxRenderedSide))
        throw Error("cannot render the frames of a " + std::to_string(job.scene.style.width) + "x" +
                    std::to_string(job.scene.style.height) + " canvas: a video or PNG frame is at most " +
                    std::to_string(kMaxRenderedSide) + " pixels a side");
    FrameStages stages(job, driver, rest, image, frames, out);
    std::unique_ptr<DocumentFile> file; // (fails early on a bad path)
    if (job.document && !job.output.empty())
        file = std::make_unique<DocumentFile>(job.output, job.encoding, dotlottie_id_for(job.output));
    stages.start_video();
    // The stages run as a pipeline, so both cores stay busy: frame k+1 is
    // tracked while frame k is drawn and written. Tokens are frames in
    // flight at once: enough that tracking goes on while the writer encodes
    // a chunk. The document is the one a frame-by-frame loop writes, byte
    // for byte.
    int next = 0;
    tbb::parallel_pipeline(
        kFramesInFlight,
        tbb::make_filter<void, std::shared_ptr<InFlight>>(tbb::filter_mode::serial_in_order,
                                                          [&](tbb::flow_control& fc) -> std::shared_ptr<InFlight> {
                                                              if (next == frames) {
                                                                  fc.stop();
                                                                  return nullptr;
                                                              }
                                                              return stages.track(next++);
                                                          }) &
            tbb::make_filter<std::shared_ptr<InFlight>, std::shared_ptr<InFlight>>(tbb::filter_mode::parallel,
                                                                                   [&](std::shared_ptr<InFlight> w) {
                                                                                       stages.draw(*w);
                                                                                       return w;
                                                                                   }) &
            tbb::make_filter<std::shared_ptr<InFlight>, std::shared_ptr<InFlight>>(tbb::filter_mode::serial_in_order,
                                                                                   [&](std::shared_ptr<InFlight> w) {
                                                                                       stages.write(*w);
                                                                                       return w;
                                                                                   }) &
            tbb::make_filter<std::shared_ptr<InFlight>, std::shared_ptr<InFlight>>(tbb::filter_mode::parallel,
                                                                                   [&](std::shared_ptr<InFlight> w) {
                                                                                       stages.render(*w);
                                                                                       return w;
                                                                                   }) &
            tbb::make_filter<std::shared_ptr<InFlight>, void>(tbb::filter_mode::serial_in_order,
                                                              [&](std::shared_ptr<InFlight> w) { stages.deliver(*w); }));
    stages.finish_video();
    if (job.document) finish_output(stages.writer(), file.get(), out);
    return out;
}

} // namespace snaxels
