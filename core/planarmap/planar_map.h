#pragma once
/// One entry point for both planar maps: which one, from which contours.
/// Stills and animations alike call it with the contours they have (drawn
/// or computed for the fills alone).

#include <string>
#include <vector>

#include "snaxels/planarmap/post_map.h"
#include "snaxels/planarmap/snaxel_map.h"

namespace snaxels {

enum class PlanarMapKind { Snaxel, Post };

/// "snaxel" or "post"; throws snaxels::Error naming the text otherwise.
PlanarMapKind parse_planar_map_kind(const std::string& text);
const char* planar_map_kind_name(PlanarMapKind kind);

struct PlanarMap {
    std::vector<MapRegion> regions;
    VertexData<std::int32_t> vertex_region; ///< snaxel map: each vertex's region (-1: none); empty for post
};

/// The map of @p kind from @p contours, which must hold the visual contour
/// and may hold shadow, isophotes and gleams (any order). @p rays, the BVH
/// of the engine's topology at its current positions, is required (a null
/// one throws snaxels::Error). The map is a partition of the image: nearer
/// regions (by depth, then by index) are subtracted from farther ones, so
/// no two regions cover the same point and paint order does not matter.
/// A snaxel map takes its vertices' rays from @p sight where given
/// (see_vertices, cast beforehand).
PlanarMap build_planar_map(PlanarMapKind kind, const SnaxelEngine& engine, const std::vector<const ContourResult*>& contours,
                           const RayScene* rays, const ImageProjection& projection, const Camera& camera,
                           const Light& light, const VertexSight* sight = nullptr);

/// The snaxel-defined @p map (a partition) completed where its regions
/// leave part of a large face (16 px2 or more) uncovered: where a corner is
/// hidden, a region's front stops on the face's edges and cuts straight
/// across between the stops, not along the outline of what hides the rest
/// (a floor of a few faces round the objects standing on it). Each
/// uncovered piece wider than half a pixel takes the class the rays
/// through it see over most of its width (the shading at the hit) and
/// joins the region of that class at one of the hit face's corners, or
/// becomes a region of its own behind the others. build_planar_map calls it.
void fill_snaxel_map_gaps(PlanarMap& map, const SnaxelEngine& engine, const SnaxelMapInput& input, const RayScene& rays,
                          const ImageProjection& projection, const Camera& camera, const Light& light);

/// On a mesh with parts, cuts @p map's regions where the parts meet in the
/// image and where one object may show in front of another: along the
/// material and object lines, every object's faceted outline (edges
/// between a face turned to the viewer and one turned away, and borders)
/// and the intersection curves (where one surface enters another), where
/// they may be seen, all cut out as strips 1/256 px wide.
/// Each piece takes the object, material and shading class seen through
/// it (the nearest face on the rays through its inside points, over most
/// of their width; the class by the shading at the hit, as @p classes
/// numbers them), so a region ranked nearer than the object that really
/// hides part of it (a tabletop's one region round a box standing on it)
/// gives that part up. The pieces of a region that show one part in one
/// class stay one region (a region that shows one part all over stays
/// whole), the strips' share goes to its largest piece, so
/// the map stays a partition of the image and no region spans two
/// materials. vertex_region follows (a vertex goes with the piece of its
/// faces' material). A mesh of one object and one material keeps its
/// regions as they are, object and material 0. build_planar_map calls it.
void split_regions_by_part(PlanarMap& map, const SnaxelEngine& engine, const RayScene& rays,
                           const ImageProjection& projection, const ShadingClasses& classes, const Camera& camera,
                           const Light& light);

/// The shading class (as @p classes numbers them) of the surface at @p hit:
/// N.L and V.R of the normalized interpolated normal there, as the
/// contours follow it.
int shading_class_at(const MeshTopology& topology, const RayHit& hit, const ShadingClasses& classes,
                     const Camera& camera, const Light& light);

/// Makes @p map a partition: each region loses what nearer ones (smaller
/// depth; equal depth: smaller index) cover; regions left empty are
/// removed (and vertex_region renumbered).
void subtract_nearer_regions(PlanarMap& map);

} // namespace snaxels
