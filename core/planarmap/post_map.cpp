#include "core/planarmap/post_map.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <polyclipping/clipper.hpp>

namespace snaxels {
namespace {

using ClipperLib::Paths;

constexpr double kScale = 64.0; // Clipper works in integers: 1/64 pixel

Paths to_paths(const std::vector<std::vector<glm::dvec2>>& polygons) {
    Paths out;
    for (const auto& poly : polygons) {
        ClipperLib::Path path;
        for (const glm::dvec2& p : poly)
            path.push_back({ClipperLib::cInt(std::llround(p.x * kScale)), ClipperLib::cInt(std::llround(p.y * kScale))});
        if (path.size() >= 3) out.push_back(std::move(path));
    }
    return out;
}

std::vector<std::vector<glm::dvec2>> from_paths(const Paths& paths) {
    std::vector<std::vector<glm::dvec2>> out;
    for (const auto& path : paths) {
        std::vector<glm::dvec2> poly;
        for (const auto& p : path) poly.push_back({double(p.X) / kScale, double(p.Y) / kScale});
        out.push_back(std::move(poly));
    }
    return out;
}

Paths clip(const Paths& a, const Paths& b, ClipperLib::ClipType op) {
    ClipperLib::Clipper c;
    c.AddPaths(a, ClipperLib::ptSubject, true);
    c.AddPaths(b, ClipperLib::ptClip, true);
    Paths out;
    c.Execute(op, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
}

double area(const Paths& paths) {
    double a = 0.0;
    for (const auto& p : paths) a += ClipperLib::Area(p);
    return std::abs(a) / (kScale * kScale);
}

// The projected loops of each positive region of `result`, grouped by the
// visual patch the region lies in (its vertices face the viewer).
std::map<std::int32_t, Paths> regions_by_patch(const SnaxelEngine& engine, const ContourResult& result,
                                                const ContourResult& visual, const ImageProjection& projection) {
    std::map<std::int32_t, std::vector<std::vector<glm::dvec2>>> loops;
    for (const FrontLoop& loop : result.fronts.loops) {
        const Snaxel& first = result.fronts.snaxels[loop.first];
        const std::int32_t patch = visual.vertex_region[first.inside];
        std::vector<glm::dvec2> poly;
        result.fronts.for_each_in_loop(loop, [&](std::int32_t s) { poly.push_back(projection.project(engine.position(result.fronts.snaxels[s]))); });
        loops[patch].push_back(std::move(poly));
    }
    std::map<std::int32_t, Paths> out;
    for (auto& [patch, polys] : loops) out[patch] = clip(to_paths(polys), {}, ClipperLib::ctUnion);
    return out;
}

} // namespace

const char* region_class_name(RegionClass cls) {
    switch (cls) {
    case RegionClass::Shadow: return "shadow";
    case RegionClass::Lit: return "lit";
    case RegionClass::Band: return "band";
    case RegionClass::Highlight: return "highlight";
    }
    return "lit";
}

std::vector<MapRegion> build_post_map(const SnaxelEngine& engine, const PostMapInput& in,
                                      const ImageProjection& projection, const Camera& camera) {
    std::vector<MapRegion> regions;
    const ContourResult& visual = *in.visual;
    const std::map<std::int32_t, Paths> patches = regions_by_patch(engine, visual, visual, projection);
    // Nearest first, by the mean depth of each patch's contour.
    std::vector<std::pair<double, std::int32_t>> order;
    for (const auto& [patch, paths] : patches) {
        double depth = 0.0;
        std::size_t n = 0;
        for (const FrontLoop& loop : visual.fronts.loops) {
            if (visual.vertex_region[visual.fronts.snaxels[loop.first].inside] != patch) continue;
            visual.fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                const glm::dvec3 p = engine.position(visual.fronts.snaxels[s]);
                depth += camera.orthographic() ? glm::dot(p, camera.forward()) : glm::length(p - camera.eye);
                ++n;
            });
        }
        order.push_back({n ? depth / double(n) : 0.0, patch});
    }
    std::sort(order.begin(), order.end());

    std::map<std::int32_t, Paths> lit, highlight;
    if (in.shadow) lit = regions_by_patch(engine, *in.shadow, visual, projection);
    std::vector<std::map<std::int32_t, Paths>> bands;
    for (const ContourResult* iso : in.isophotes) bands.push_back(regions_by_patch(engine, *iso, visual, projection));
    if (in.gleam) highlight = regions_by_patch(engine, *in.gleam, visual, projection);
    auto of = [](const std::map<std::int32_t, Paths>& m, std::int32_t patch) {
        const auto it = m.find(patch);
        return it == m.end() ? Paths{} : it->second;
    };

    Paths covered;
    int depth = 0;
    for (const auto& [d, patch] : order) {
        const Paths& shape = patches.at(patch);
        Paths visible = clip(shape, covered, ClipperLib::ctDifference);
        covered = clip(covered, shape, ClipperLib::ctUnion);
        if (visible.empty()) continue;
        // Nested class sets inside the visible part: lit ⊇ band 1 ⊇ band 2 ...
        // Each level is clipped to the one before: on the surface they nest,
        // but their projected polylines are separate discretizations.
        std::vector<Paths> levels;
        levels.push_back(in.shadow ? clip(visible, of(lit, patch), ClipperLib::ctIntersection) : visible);
        for (const auto& band : bands) levels.push_back(clip(levels.back(), of(band, patch), ClipperLib::ctIntersection));
        const Paths glints = in.gleam ? clip(visible, of(highlight, patch), ClipperLib::ctIntersection) : Paths{};
        auto emit = [&](RegionClass cls, double k, const Paths& paths) {
            const Paths kept = glints.empty() ? paths : clip(paths, glints, ClipperLib::ctDifference);
            const double a = area(kept);
            if (a <= 0.0) return;
            regions.push_back({cls, k, depth, from_paths(kept), a});
        };
        emit(RegionClass::Shadow, 0.0, clip(visible, levels[0], ClipperLib::ctDifference));
        for (std::size_t i = 0; i < levels.size(); ++i) {
            const Paths next = i + 1 < levels.size() ? levels[i + 1] : Paths{};
            const Paths part = next.empty() ? levels[i] : clip(levels[i], next, ClipperLib::ctDifference);
            if (i == 0) emit(RegionClass::Lit, 0.0, part);
            else emit(RegionClass::Band, in.isophotes[i - 1]->spec.k, part);
        }
        if (!glints.empty()) regions.push_back({RegionClass::Highlight, in.gleam->spec.k, depth, from_paths(glints), area(glints)});
        ++depth;
    }
    return regions;
}

std::vector<std::vector<glm::dvec2>> erode(const std::vector<std::vector<glm::dvec2>>& polygons, double pixels) {
    if (pixels <= 0.0) return polygons;
    ClipperLib::ClipperOffset offset;
    offset.AddPaths(to_paths(polygons), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    Paths out;
    offset.Execute(out, -pixels * kScale);
    return from_paths(out);
}

} // namespace snaxels
