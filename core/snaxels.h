#pragma once
/// Everything a program that embeds snaxels needs, in one include:
/// reading meshes, the engine's topology and its refinement, the contour
/// engine and tracker, hidden lines, planar maps, stills and animations,
/// the style language, SVG, Lottie and JSON export, projects, and the
/// library's errors and version (docs/library.md): every public header
/// (a test checks that none is left out). The library's own sources
/// include the headers they need one by one, never this one.

#include "snaxels/error.h"
#include "snaxels/version.h"

#include "snaxels/mesh/build.h"
#include "snaxels/mesh/elements.h"
#include "snaxels/mesh/file_cameras.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/isolated_import.h"
#include "snaxels/mesh/mesh.h"
#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/mesh/parts.h"
#include "snaxels/mesh/procedural.h"
#include "snaxels/mesh/quantities.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/mesh/report.h"
#include "snaxels/mesh/sharp_edges.h"
#include "snaxels/mesh/topology.h"
#include "snaxels/mesh/triangle_soup.h"

#include "snaxels/scene/camera.h"
#include "snaxels/scene/orbit.h"

#include "snaxels/snaxel/contour_function.h"
#include "snaxels/snaxel/contour_kind.h"
#include "snaxels/snaxel/curvature.h"
#include "snaxels/snaxel/feature_edges.h"
#include "snaxels/snaxel/fronts.h"
#include "snaxels/snaxel/intersections.h"
#include "snaxels/snaxel/parabolic.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/snaxel/suggestive.h"
#include "snaxels/snaxel/tracker.h"

#include "snaxels/visibility/near_plane.h"
#include "snaxels/visibility/ray_scene.h"
#include "snaxels/visibility/visibility.h"

#include "snaxels/planarmap/map_timing.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/planarmap/post_map.h"
#include "snaxels/planarmap/region.h"
#include "snaxels/planarmap/region_tracker.h"
#include "snaxels/planarmap/snaxel_map.h"

#include "snaxels/style/page.h"
#include "snaxels/style/style.h"
#include "snaxels/style/style_edit.h"

#include "snaxels/animation/frame_driver.h"
#include "snaxels/animation/pipeline.h"
#include "snaxels/animation/scene_settings.h"
#include "snaxels/animation/still.h"

#include "snaxels/export/animated_svg.h"
#include "snaxels/export/animation_writer.h"
#include "snaxels/export/bezier.h"
#include "snaxels/export/contours_json.h"
#include "snaxels/export/drawing.h"
#include "snaxels/export/lottie.h"
#include "snaxels/export/output_file.h"
#include "snaxels/export/raster.h"
#include "snaxels/export/stroke_dashes.h"
#include "snaxels/export/stroke_parameter.h"
#include "snaxels/export/stroke_shape.h"
#include "snaxels/export/stroke_weight.h"
#include "snaxels/export/svg.h"
#include "snaxels/export/video.h"

#include "snaxels/project/project.h"

#include "snaxels/util/atomic_file.h"
#include "snaxels/util/memory.h"
