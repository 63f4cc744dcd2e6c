#include "snaxels/planarmap/planar_map.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "snaxels/error.h"
#include "snaxels/planarmap/detail/clip.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {

PlanarMapKind parse_planar_map_kind(const std::string& text) {
    if (text == "snaxel") return PlanarMapKind::Snaxel;
    if (text == "post") return PlanarMapKind::Post;
    throw Error("unknown planar map '" + text + "' (expected snaxel or post)");
}

const char* planar_map_kind_name(PlanarMapKind kind) { return kind == PlanarMapKind::Snaxel ? "snaxel" : "post"; }

PlanarMap build_planar_map(PlanarMapKind kind, const SnaxelEngine& engine, const std::vector<const ContourResult*>& contours,
                           const RayScene* rays, const ImageProjection& projection, const Camera& camera,
                           const Light& light, const VertexSight* sight) {
    const ContourResult* visual = nullptr;
    const ContourResult* shadow = nullptr;
    std::vector<const ContourResult*> isophotes, gleams;
    for (const ContourResult* r : contours) {
        if (r->spec.kind == ContourKind::Visual) visual = r;
        if (r->spec.kind == ContourKind::Shadow) shadow = r;
        if (r->spec.kind == ContourKind::Isophote) isophotes.push_back(r);
        if (r->spec.kind == ContourKind::Gleam) gleams.push_back(r);
    }
    if (!visual) throw Error("a planar map needs the visual contour");
    auto by_k = [](const ContourResult* a, const ContourResult* b) { return a->spec.k < b->spec.k; };
    std::sort(isophotes.begin(), isophotes.end(), by_k);
    std::sort(gleams.begin(), gleams.end(), by_k);
    PlanarMap map;
    if (!rays) throw Error("a planar map needs the ray-tracing scene");
    SnaxelMapInput in;
    in.visual = visual;
    in.shadow = shadow;
    in.isophotes = isophotes;
    in.gleams = gleams;
    in.sight = sight;
    const ShadingClasses classes = shading_classes(in);
    if (kind == PlanarMapKind::Post) {
        map.regions = build_post_map(engine, {visual, shadow, isophotes, gleams}, *rays, projection, camera, light);
        subtract_nearer_regions(map);
        split_regions_by_part(map, engine, *rays, projection, classes, camera, light);
        return map;
    }
    SnaxelMap built = build_snaxel_map(engine, in, *rays, projection, camera, light);
    map.regions = std::move(built.regions);
    map.vertex_region = std::move(built.vertex_region);
    subtract_nearer_regions(map);
    fill_snaxel_map_gaps(map, engine, in, *rays, projection, camera, light);
    split_regions_by_part(map, engine, *rays, projection, classes, camera, light);
    return map;
}

void subtract_nearer_regions(PlanarMap& map) {
    const std::size_t n = map.regions.size();
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return map.regions[a].depth < map.regions[b].depth; });
    std::vector<clip::Paths> paths(n);
    std::vector<std::vector<clip::Box>> boxes(n); // per polygon
    std::vector<clip::Box> box(n);                // per region
    // Each region's loops filled on their own (non-zero) first: loops of two
    // regions winding opposite ways would cancel in one clip set.
    parallel_for(n, [&](std::size_t i) { paths[i] = clip::op(clip::to_paths(map.regions[i].polygons), {}, ClipperLib::ctUnion); }, 1);
    for (std::size_t i = 0; i < n; ++i) {
        for (const auto& path : paths[i]) {
            clip::Box b;
            b.add(path);
            boxes[i].push_back(b);
            box[i].add(b);
        }
    }
    // Each region against the nearer ones as they were (their union is the
    // union of what they keep), cut to its own box (two units wider, so the
    // cut runs clear of the region).
    std::vector<char> keep(n, 1);
    parallel_for(n, [&](std::size_t at) {
        const std::size_t r = order[at];
        if (paths[r].empty()) {
            keep[r] = 0;
            return;
        }
        const clip::Box wide = box[r].widened(2);
        clip::Paths nearer;
        for (std::size_t before = 0; before < at; ++before) {
            const std::size_t q = order[before];
            if (!box[q].meets(wide)) continue;
            for (std::size_t k = 0; k < paths[q].size(); ++k) {
                if (!boxes[q][k].meets(wide)) continue;
                ClipperLib::Path part = clip::cropped(paths[q][k], boxes[q][k], wide);
                if (part.size() >= 3) nearer.push_back(std::move(part));
            }
        }
        // Every region leaves normalized: outlines wound one way, holes the
        // other (the animated fills tell holes by their winding).
        const clip::Paths rest = nearer.empty() ? paths[r] : clip::op(paths[r], nearer, ClipperLib::ctDifference);
        MapRegion& region = map.regions[r];
        region.area = clip::area(rest);
        region.polygons = clip::from_paths(rest);
        keep[r] = region.area > 0.0;
    }, 1);
    std::vector<std::int32_t> index(n, -1);
    std::vector<MapRegion> kept;
    for (std::size_t i = 0; i < n; ++i)
        if (keep[i]) index[i] = std::int32_t(kept.size()), kept.push_back(std::move(map.regions[i]));
    map.regions = std::move(kept);
    for (std::int32_t& r : map.vertex_region)
        if (r >= 0) r = index[r];
}

} // namespace snaxels
