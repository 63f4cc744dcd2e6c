#include "core/planarmap/planar_map.h"

#include <algorithm>

#include "core/error.h"

namespace snaxels {

PlanarMapKind parse_planar_map_kind(const std::string& text) {
    if (text == "snaxel") return PlanarMapKind::Snaxel;
    if (text == "post") return PlanarMapKind::Post;
    throw Error("unknown planar map '" + text + "' (expected snaxel or post)");
}

const char* planar_map_kind_name(PlanarMapKind kind) { return kind == PlanarMapKind::Snaxel ? "snaxel" : "post"; }

PlanarMap build_planar_map(PlanarMapKind kind, const SnaxelEngine& engine, const std::vector<const ContourResult*>& contours,
                           const RayScene* rays, const ImageProjection& projection, const Camera& camera,
                           const Light& light) {
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
    if (kind == PlanarMapKind::Post) {
        map.regions = build_post_map(engine, {visual, shadow, isophotes, gleams}, projection, camera, light);
        return map;
    }
    if (!rays) throw Error("the snaxel planar map needs the ray-tracing scene");
    SnaxelMapInput in;
    in.visual = visual;
    in.shadow = shadow;
    in.isophotes = isophotes;
    in.gleams = gleams;
    SnaxelMap built = build_snaxel_map(engine, in, *rays, projection, camera, light);
    map.regions = std::move(built.regions);
    map.vertex_region = std::move(built.vertex_region);
    return map;
}

} // namespace snaxels
