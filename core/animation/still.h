#pragma once
/// One still frame through the whole pipeline, shared by `snaxels-cli
/// contours` and the application's SVG pane: contours, hidden lines, the
/// planar map the style's fills need, the drawing and its SVG.

#include <optional>
#include <string>
#include <vector>

#include "core/export/drawing.h"
#include "core/mesh/build.h"
#include "core/planarmap/planar_map.h"
#include "core/style/style.h"
#include "core/visibility/visibility.h"

namespace snaxels {

struct StillJob {
    Camera camera;
    Light light;
    std::vector<ContourSpec> kinds{ContourSpec{}}; ///< the contours drawn
    Style style = default_style();
    bool visibility = true;
    bool planar_map = false; ///< build the planar map even without fills
    PlanarMapKind map_kind = PlanarMapKind::Snaxel; ///< which map the fills (and regions) come from
    EngineOptions engine;
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
/// the default light for the camera.
StillJob make_still_job(const Style& style, const Camera& camera, const std::optional<Light>& light);

/// The light of a job: @p light, else the style's, else the default for @p camera.
Light job_light(const Style& style, const Camera& camera, const std::optional<Light>& light);

/// The contours @p style draws (its <contour> kinds), or the visual contour.
std::vector<ContourSpec> style_kinds(const Style& style);

/// Renders @p job on @p topology, whose bounding box is @p mesh's report's.
/// @p rays may be given (built once per mesh); else one is built if needed.
StillOutput render_still(const LoadedMesh& mesh, const MeshTopology& topology, const RayScene* rays,
                         const StillJob& job);

} // namespace snaxels
