#pragma once
// Contours for the 3-D view, computed off the GUI thread: the engine's
// fronts with their hidden parts, as strips the view draws on the surface.

#include <memory>
#include <optional>
#include <vector>

#include <QString>

#include "snaxels/animation/still.h"
#include "snaxels/mesh/build.h"
#include "snaxels/snaxel/parabolic.h"
#include "snaxels/animation/frame_driver.h"
#include "snaxels/style/style.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/visibility/ray_scene.h"
#include "ui/meshview.h"

namespace snaxels::ui {

/// What contour computation needs of a loaded mesh, built once per mesh.
/// For the mesh's own clips the scene moves to another pose of the same
/// connectivity frame by frame; one computation at a time may use it.
struct ContourScene {
    SurfaceOptions surface;          ///< where the drawn surface is sharp (the style's <surface>)
    std::vector<std::string> hidden; ///< the objects the style hides (<object hide="true">)
    /// The mesh as drawn, when the style changes it: without the hidden
    /// objects, split along its sharp edges (scene_surface).
    std::optional<LoadedMesh> split;
    MeshTopology rest;              ///< the mesh as loaded (its topology for the engine)
    MeshTopology topology;          ///< the pose computed last: rest, or a clip frame
    std::unique_ptr<RayScene> rays; ///< the BVH of topology's pose
    std::string mesh_path;          ///< the file clips are read from
    std::vector<AnimationClipInfo> clips;
    std::vector<FileCamera> cameras;     ///< the file's cameras
    std::unique_ptr<CameraTrack> track;  ///< the file's camera looked through last
    std::string track_camera, track_clip; ///< its name and the clip moving it
    std::unique_ptr<FrameDriver> driver; ///< for the clip posed last
    AnimationSpec driver_spec;
    bool posed = false;  ///< topology is a clip frame, not rest
    int posed_frame = 0; ///< the clip frame posed last
    /// The contours of the last frame, followed to the next one (orbits,
    /// light turns and one-frame scrubs track; a jump starts anew).
    std::unique_ptr<StillTracking> tracking;
};

/// Builds the scene of @p mesh read from @p path (topology, ray-tracing
/// BVH, the file's clips and cameras), its sharp edges found as @p surface
/// says.
std::shared_ptr<ContourScene> make_contour_scene(const LoadedMesh& mesh, const std::string& path,
                                                 const SurfaceOptions& surface = {});

/// A clip frame to pose the mesh in before computing contours.
struct ClipPose {
    AnimationSpec clip;
    int frame = 0;
};

/// A frame seen through one of the file's cameras (animation.camera): its
/// pose at the frame, turned by a turntable, as the export sees it.
struct CameraShot {
    AnimationSpec animation;
    int frame = 0; ///< the timeline's frame (the in point is added)
};

struct OverlayResult {
    std::vector<ContourStrip> strips;
    std::string svg; ///< the frame as `snaxels-cli contours --svg` draws it
    std::size_t loops = 0, snaxels = 0;
    double ms = 0.0; ///< the whole frame: engine, visibility, drawing
    /// When the pose changed: the triangles to draw now.
    std::shared_ptr<MeshGeometry> geometry;
    QString error; ///< posing failed (the clip could not be read)
    Light light;   ///< the light the frame was computed with
    Camera camera; ///< the camera it was computed for
    int frame = 0; ///< the timeline frame it was computed for
    /// The canvas drawn on: the style's, its height following a file
    /// camera's aspect when seen through one.
    int canvas_width = 0, canvas_height = 0;
};

/// The region colouring of @p style lit by @p light: the style's fills
/// (shadow, lit, band k, highlight k), or where it has none, shadow and lit
/// tones with a band per isophote and a highlight per gleam it draws.
RegionShading region_shading(const Style& style, const Light& light, bool enabled);

/// Colours of the kinds in the 3-D view: bright enough for the shaded mesh
/// and the dark background alike.
const char* view_colour(ContourKind kind);

/// The contours of @p style seen by @p camera, lit from the viewer's upper
/// left (unless the style says otherwise): strips for the 3-D view and the
/// SVG that export writes, from one computation.
/// With @p pose the mesh is first posed at that clip frame; without, it is
/// put back in its loaded pose if a clip had moved it.
/// With @p shot the frame is seen through the file's camera instead of
/// @p camera, the canvas's height following its aspect.
/// The mesh's parabolic curves are drawn (as the style says) once @p
/// parabolic holds them (they are left out until then: finding them takes
/// seconds, see MainWindow::ensureParabolic); with @p show_parabolic they are
/// drawn in the 3-D view even when the style does not draw them (View >
/// Parabolic Curves), and not in the SVG, which stays what export writes.
OverlayResult compute_overlay(const LoadedMesh& mesh, ContourScene& scene, const Camera& camera,
                              const Style& style, const std::optional<Light>& light = std::nullopt,
                              const std::optional<ClipPose>& pose = std::nullopt,
                              std::shared_ptr<const ParabolicResult> parabolic = nullptr, bool show_parabolic = false,
                              const std::optional<CameraShot>& shot = std::nullopt);

} // namespace snaxels::ui
