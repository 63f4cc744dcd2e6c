#pragma once
// Contours for the 3-D view, computed off the GUI thread: the engine's
// fronts with their hidden parts, as strips the view draws on the surface.

#include <memory>
#include <optional>
#include <vector>

#include "core/mesh/build.h"
#include "core/style/style.h"
#include "core/snaxel/snaxel_engine.h"
#include "core/visibility/ray_scene.h"
#include "ui/meshview.h"

namespace snaxels::ui {

/// What contour computation needs of a loaded mesh, built once per mesh.
struct ContourScene {
    MeshTopology topology;
    std::unique_ptr<RayScene> rays; ///< refers to topology: keep the scene where it is
};

/// Builds the scene of @p mesh (topology and ray-tracing BVH).
std::shared_ptr<ContourScene> make_contour_scene(const LoadedMesh& mesh);

struct OverlayResult {
    std::vector<ContourStrip> strips;
    std::string svg; ///< the frame as `snaxels-cli contours --svg` draws it
    std::size_t loops = 0, snaxels = 0;
    double ms = 0.0; ///< the whole frame: engine, visibility, drawing
};

/// Colours of the kinds in the 3-D view: bright enough for the shaded mesh
/// and the dark background alike.
const char* view_colour(ContourKind kind);

/// The contours of @p style seen by @p camera, lit from the viewer's upper
/// left (unless the style says otherwise): strips for the 3-D view and the
/// SVG that export writes, from one computation.
OverlayResult compute_overlay(const LoadedMesh& mesh, const ContourScene& scene, const Camera& camera,
                              const Style& style, const std::optional<Light>& light = std::nullopt);

} // namespace snaxels::ui
