#pragma once
/// The contour data as JSON (format documented in docs/contours-json.md).

#include <nlohmann/json.hpp>

#include "snaxels/export/drawing.h"
#include "snaxels/planarmap/post_map.h"
#include "snaxels/mesh/report.h"

namespace snaxels {

/// One JSON document with the mesh, camera, light, image size, every
/// contour's loops of snaxels (p in 3-D, q in pixels) and engine statistics.
/// With @p regions, a "regions" member lists the planar map.
nlohmann::json contours_to_json(const MeshReport& mesh, const Camera& camera, const Light& light,
                                const Drawing& drawing, const std::vector<ContourResult>& results,
                                const std::vector<MapRegion>* regions = nullptr);

} // namespace snaxels
