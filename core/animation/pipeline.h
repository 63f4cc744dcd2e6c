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

#include "core/export/animated_svg.h"
#include "core/planarmap/planar_map.h"
#include "core/scene/animation.h"
#include "core/snaxel/refine.h"
#include "core/snaxel/tracker.h"
#include "core/style/style.h"

namespace snaxels {

/// The file an animation is written as.
enum class AnimationFormat {
    Svg,    ///< animated SVG (SMIL), docs/animation.md
    Lottie, ///< Lottie JSON, docs/lottie.md
};

/// The format a file name asks for: Lottie for .json (any case), else SVG.
AnimationFormat animation_format_for(const std::string& path);

struct AnimationJob {
    AnimationSpec animation;
    Camera camera;
    Light light;
    std::vector<ContourSpec> kinds{ContourSpec{}};
    Style style = default_style(); ///< strokes, canvas (size, margin, background)
    bool visibility = true;
    PlanarMapKind map_kind = PlanarMapKind::Snaxel; ///< the map the style's fills come from
    int refine = kAutoRefine; ///< levels the mesh is refined by for the engine (core/snaxel/refine.h)
    EngineOptions engine;
    AnimatedSvgOptions svg; ///< tolerances, for either format
    AnimationFormat format = AnimationFormat::Svg;
    std::string frames_dir; ///< when set, every frame is also written there as static SVG
    /// Called after each frame with (frames done, frames in all).
    std::function<void(int, int)> progress;
    /// When a kind is parabolic and the curves are not known yet: called as
    /// the search over view directions goes, with (steps done, in all).
    std::function<void(int, int)> parabolic_progress;
    /// Asked before each frame; true stops the run with AnimationCancelled.
    std::function<bool()> cancelled;
};

/// Thrown by run_animation when the job's `cancelled` says so.
struct AnimationCancelled : std::runtime_error {
    AnimationCancelled() : std::runtime_error("the animation export was cancelled") {}
};

struct AnimationOutput {
    std::string document; ///< the animated SVG or the Lottie JSON, as job.format says
    nlohmann::json events = nlohmann::json::array(); ///< [{frame, kind, contour, where}]
    AnimatedSvgStats stats;
    std::vector<double> tracking_ms; ///< per frame, all kinds
    int frames = 0;
};

/// The job the application and a project export: @p animation seen from
/// @p camera (frame 0), lit by @p light, else the style's light, else the
/// default light for the camera; the style's contours (visual if none).
AnimationJob make_animation_job(const Style& style, const AnimationSpec& animation, const Camera& camera,
                                const std::optional<Light>& light);

/// Runs @p job on @p mesh (read from @p mesh_path, which clips need).
/// Throws snaxels::Error on bad input (a missing sequence file, an unknown clip).
AnimationOutput run_animation(const LoadedMesh& mesh, const std::string& mesh_path, const AnimationJob& job);

} // namespace snaxels
