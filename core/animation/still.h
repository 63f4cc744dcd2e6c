#pragma once
/// One still frame through the whole pipeline, shared by `snaxels-cli
/// contours` and the application's SVG pane: contours, hidden lines, the
/// planar map the style's fills need, the drawing and its SVG.

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "snaxels/animation/scene_settings.h"
#include "snaxels/export/drawing.h"
#include "snaxels/mesh/build.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/style/style.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

/// One still frame to render.
struct StillJob {
    SceneSettings scene; ///< what is drawn and how (scene_settings())
    /// Whether every hidden snaxel's QI is counted (the contours JSON
    /// reports them all). Else a contour whose hidden lines are not drawn
    /// and whose strokes no QI weighs counts them only where the parts seen
    /// need it (VisibilitySampler::HiddenLevels::WhereSeen): the same
    /// drawing at about half the rays' cost.
    bool all_hidden_levels = true;
};

struct StillOutput {
    std::vector<ContourResult> results;        ///< parallel to the job's kinds
    std::vector<ContourVisibility> visibility; ///< parallel to results, when computed
    Drawing drawing;
    std::vector<MapRegion> regions;            ///< when the style has fills or the job asks
    std::string svg;
};

/// The job the application's view draws: the style's contours (visual if
/// none) seen from @p camera, lit by @p light, else the style's light, else
/// the default light for the camera; hidden levels only where drawn.
StillJob make_still_job(const Style& style, const Camera& camera, const std::optional<Light>& light);

/// Contours followed from one still frame to the next, as the application's
/// view does while the user orbits, zooms, turns the light or scrubs: each
/// kind's tracker (core/snaxel/tracker.h) moves its fronts on from the last
/// frame instead of sweeping the whole mesh again. Tracked fronts are the
/// ones a computation from scratch finds (the tracker's tests); tracking is
/// only faster while little changes between frames, so a jump (the view or
/// the light turned by more than max_step_deg as seen from the mesh's
/// centre, a change of projection, a pose not next to the last: see jump())
/// starts from scratch, as a kind seen for the first time does. The mesh's
/// own lines (parabolic curves, creases, borders) are found, never tracked.
class StillTracking {
  public:
    explicit StillTracking(double max_step_deg = 10.0);

    /// The next frame's contour of every kind in @p specs (in order) on
    /// @p topology, each tracked from its last frame or computed from
    /// scratch; kinds not asked for are forgotten. The kinds run in
    /// parallel. The mesh may move between frames (another pose of its
    /// connectivity); another mesh starts every kind anew. Without
    /// @p vertex_data the results are the lines alone (lines_of: no planar
    /// map will read them).
    std::vector<ContourResult> compute(const MeshTopology& topology, const std::vector<ContourSpec>& specs,
                                       const Camera& camera, const Light& light, const EngineOptions& options,
                                       const glm::dvec3& centre, bool vertex_data = true);

    /// The mesh jumped (another pose, edited geometry): every kind starts anew.
    void jump() { trackers_.clear(); }

    std::size_t tracked_steps() const { return tracked_; }   ///< kind-frames tracked, over the object's life
    std::size_t restarts() const { return restarts_; }       ///< kind-frames computed from scratch

  private:
    double max_step_deg_;
    std::shared_ptr<const MeshConnectivity> connectivity_; ///< of the mesh tracked
    std::map<std::string, std::unique_ptr<ContourTracker>> trackers_; ///< by ContourSpec::label()
    std::optional<Camera> camera_;
    std::optional<Light> light_;
    std::size_t tracked_ = 0, restarts_ = 0;
};

/// Renders @p job on @p topology, whose bounding box is @p mesh's report's.
/// @p rays may be given (built once per mesh); else one is built if needed.
/// With @p tracking the contours are tracked from its last frame.
StillOutput render_still(const LoadedMesh& mesh, const MeshTopology& topology, const RayScene* rays,
                         const StillJob& job, StillTracking* tracking = nullptr);

} // namespace snaxels
