#pragma once
/// The whole animation pipeline, shared by the CLI and the application:
/// pose each frame, track every contour kind, classify hidden lines, draw,
/// and write the animated SVG or Lottie (and, on request, each frame as
/// static SVG).

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "snaxels/error.h"
#include "snaxels/export/animated_svg.h"
#include "snaxels/export/animation_writer.h"
#include "snaxels/export/output_file.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/animation/frame_driver.h"
#include "snaxels/animation/scene_settings.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/style/style.h"

namespace snaxels {

/// The largest side of a rendered frame (a video's or --png-dir's): eight
/// frames are in flight at 4 bytes a pixel, 2 GB at this size.
inline constexpr int kMaxRenderedSide = 8192;

struct AnimationJob {
    AnimationSpec animation;
    /// What each frame draws and how, seen at frame 0 (the animation moves
    /// the camera, the light or the mesh from there).
    SceneSettings scene;
    AnimatedSvgOptions svg; ///< tolerances, for either format
    AnimationFormat format = AnimationFormat::Svg;
    std::string frames_dir; ///< when set, every frame is also written there as static SVG
    /// With a file's camera (animation.camera): the canvas's height follows
    /// its aspect (the style's width kept), unless the size was chosen.
    bool canvas_follows_camera = true;
    /// The light is the default one (no user's or style's light): with a
    /// file's camera it is placed from that camera where it starts.
    bool light_from_camera = false;
    /// When set, the animation is written to this file as it is made
    /// (atomically: the file appears, whole, when the run succeeds) and
    /// AnimationOutput::document stays empty; memory then does not grow
    /// with the frame count (core/export/animation_writer.h).
    std::string output;
    /// How `output`'s document is stored: plain, gzip (.svgz) or in the
    /// dotLottie zip (.lottie).
    DocumentEncoding encoding = DocumentEncoding::Plain;
    /// When set, the frames (each frame's static SVG, as frames_dir has
    /// them) are rendered and encoded as a video of kind video_kind there
    /// (core/export/video.h), atomically.
    std::string video;
    OutputKind video_kind = OutputKind::Mp4;
    /// The video's (and --png-dir's) frames this many pixels across, the
    /// height by the canvas's aspect; 0: the canvas's size.
    int video_width = 0;
    /// The video's quality (VideoEncoder: FFmpeg's CRF, lower is better and
    /// bigger); -1: the format's default.
    int video_crf = -1;
    /// When set, every frame is also rendered there as PNG (frame_00000.png).
    std::string png_dir;
    /// Whether the animated document is made at all (not for a video alone).
    bool document = true;
    /// Called after each frame is written with (frames done, frames in
    /// all), one call at a time and in frame order, from whichever of the
    /// export's threads wrote it.
    std::function<void(int, int)> progress;
    /// When a kind is parabolic and the curves are not known yet: called as
    /// the search over view directions goes, with (steps done, in all).
    std::function<void(int, int)> parabolic_progress;
    /// Asked before each frame is tracked (on the thread tracking it); true
    /// stops the run with AnimationCancelled.
    std::function<bool()> cancelled;
};

/// Thrown by run_animation when the job's `cancelled` says so.
struct AnimationCancelled : Cancelled {
    AnimationCancelled() : Cancelled("the animation export was cancelled") {}
};

struct AnimationOutput {
    std::string document; ///< the animated SVG or the Lottie JSON, as job.format says (unless job.output is set)
    /// The visual events, with the index of their kind in job.kinds (kept
    /// compact: a long animation has thousands): events_json() lists them.
    std::vector<std::pair<std::size_t, VisualEvent>> events;
    /// The document's size, before compression (a .svgz or .lottie file
    /// holds fewer bytes: its size on disk is the file's).
    std::size_t bytes = 0;
    AnimatedSvgStats stats;
    std::vector<double> tracking_ms; ///< per frame, all kinds
    int frames = 0;
};

/// Points @p job's output at @p path, as its extension asks: the document
/// (output, format and encoding) for .svg, .svgz, .json and .lottie; a
/// video alone (video, video_kind, no document) for .mp4, .webm and .gif.
/// False, and @p job unchanged, for an extension no output has
/// (output_extensions() lists them).
bool set_output(AnimationJob& job, const std::string& path);

/// The job the application and a project export: @p animation seen from
/// @p camera (frame 0), lit by @p light, else the style's light, else the
/// default light for the camera; the style's contours (visual if none).
AnimationJob make_animation_job(const Style& style, const AnimationSpec& animation, const Camera& camera,
                                const std::optional<Light>& light);

/// @p out's events as JSON: [{frame, kind, contour, where}], contour the
/// label of the kind in @p job.scene.
nlohmann::json events_json(const AnimationOutput& out, const AnimationJob& job);

/// Runs @p job on @p mesh (read from @p mesh_path, which clips need).
/// Throws snaxels::Error on bad input (a missing sequence file, an unknown clip).
AnimationOutput run_animation(const LoadedMesh& mesh, const std::string& mesh_path, const AnimationJob& job);

} // namespace snaxels
