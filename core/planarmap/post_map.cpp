#include "core/planarmap/post_map.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>
#include <unordered_set>

#include "core/planarmap/clip.h"

namespace snaxels {
namespace {

using clip::area;
using clip::from_paths;
using clip::Paths;
using clip::to_paths;

// The region of the visual contour every vertex lies in: the engine's own
// labels, or (for tracked contours, which carry none) the connected sets of
// equal sign of f.
std::vector<std::int32_t> patch_labels(const MeshTopology& topo, const ContourResult& visual) {
    if (visual.vertex_region.size() == topo.n_vertices()) return visual.vertex_region;
    std::vector<std::int32_t> label;
    grow_vertex_sets(topo, label, [](std::int32_t) { return true; }, [&](std::int32_t v, std::int32_t w) {
        return (visual.vertex_f[std::size_t(v)] >= 0.0) == (visual.vertex_f[std::size_t(w)] >= 0.0);
    });
    return label;
}

// The projected loops of each positive region of `result`, grouped by the
// visual patch the region lies in (its vertices face the viewer).
std::map<std::int32_t, Paths> regions_by_patch(const SnaxelEngine& engine, const ContourResult& result,
                                                const std::vector<std::int32_t>& patch_of, const ImageProjection& projection) {
    std::map<std::int32_t, std::vector<std::vector<glm::dvec2>>> loops;
    for (const FrontLoop& loop : result.fronts.loops) {
        const Snaxel& first = result.fronts.snaxels[loop.first];
        const std::int32_t patch = patch_of[std::size_t(first.inside)];
        std::vector<glm::dvec2> poly;
        result.fronts.for_each_in_loop(loop, [&](std::int32_t s) { poly.push_back(projection.project(engine.position(result.fronts.snaxels[s]))); });
        loops[patch].push_back(std::move(poly));
    }
    std::map<std::int32_t, Paths> out;
    for (auto& [patch, polys] : loops) out[patch] = clip::op(to_paths(polys), {}, ClipperLib::ctUnion);
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
                                      const ImageProjection& projection, const Camera& camera, const Light& light) {
    std::vector<MapRegion> regions;
    const ContourResult& visual = *in.visual;
    const std::vector<std::int32_t> patch_of = patch_labels(engine.topology(), visual);
    const std::map<std::int32_t, Paths> patches = regions_by_patch(engine, visual, patch_of, projection);
    // Nearest first, by the mean depth of each patch's contour.
    std::vector<std::pair<double, std::int32_t>> order;
    for (const auto& [patch, paths] : patches) {
        double depth = 0.0;
        std::size_t n = 0;
        for (const FrontLoop& loop : visual.fronts.loops) {
            if (patch_of[std::size_t(visual.fronts.snaxels[loop.first].inside)] != patch) continue;
            visual.fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                const glm::dvec3 p = engine.position(visual.fronts.snaxels[s]);
                depth += camera.orthographic() ? glm::dot(p, camera.forward()) : glm::length(p - camera.eye);
                ++n;
            });
        }
        order.push_back({n ? depth / double(n) : 0.0, patch});
    }
    std::sort(order.begin(), order.end());

    std::map<std::int32_t, Paths> lit;
    if (in.shadow) lit = regions_by_patch(engine, *in.shadow, patch_of, projection);
    std::vector<std::map<std::int32_t, Paths>> bands;
    for (const ContourResult* iso : in.isophotes) bands.push_back(regions_by_patch(engine, *iso, patch_of, projection));
    std::vector<std::map<std::int32_t, Paths>> highlights;
    for (const ContourResult* g : in.gleams) highlights.push_back(regions_by_patch(engine, *g, patch_of, projection));
    auto of = [](const std::map<std::int32_t, Paths>& m, std::int32_t patch) {
        const auto it = m.find(patch);
        return it == m.end() ? Paths{} : it->second;
    };

    Paths covered;
    int depth = 0;
    for (const auto& [d, patch] : order) {
        const Paths& shape = patches.at(patch);
        Paths visible = clip::op(shape, covered, ClipperLib::ctDifference);
        covered = clip::op(covered, shape, ClipperLib::ctUnion);
        if (visible.empty()) continue;
        // Nested class sets inside the visible part: lit ⊇ band 1 ⊇ band 2 ...
        // Each level is clipped to the one before: on the surface they nest,
        // but their projected polylines are separate discretizations.
        std::vector<Paths> levels;
        levels.push_back(in.shadow ? clip::op(visible, of(lit, patch), ClipperLib::ctIntersection) : visible);
        for (const auto& band : bands) levels.push_back(clip::op(levels.back(), of(band, patch), ClipperLib::ctIntersection));
        // Highlight levels nest too: each clipped to the one before.
        std::vector<Paths> glint_levels;
        for (const auto& h : highlights)
            glint_levels.push_back(clip::op(glint_levels.empty() ? visible : glint_levels.back(), of(h, patch), ClipperLib::ctIntersection));
        const Paths glints = glint_levels.empty() ? Paths{} : glint_levels.front();
        auto emit = [&](RegionClass cls, double k, const Paths& paths) {
            const Paths kept = glints.empty() ? paths : clip::op(paths, glints, ClipperLib::ctDifference);
            const double a = area(kept);
            if (a <= 0.0) return;
            regions.push_back({cls, k, depth, from_paths(kept), a});
        };
        emit(RegionClass::Shadow, 0.0, clip::op(visible, levels[0], ClipperLib::ctDifference));
        for (std::size_t i = 0; i < levels.size(); ++i) {
            const Paths next = i + 1 < levels.size() ? levels[i + 1] : Paths{};
            const Paths part = next.empty() ? levels[i] : clip::op(levels[i], next, ClipperLib::ctDifference);
            if (i == 0) emit(RegionClass::Lit, 0.0, part);
            else emit(RegionClass::Band, in.isophotes[i - 1]->spec.k, part);
        }
        for (std::size_t g = 0; g < glint_levels.size(); ++g) {
            const Paths part = g + 1 < glint_levels.size() && !glint_levels[g + 1].empty()
                                   ? clip::op(glint_levels[g], glint_levels[g + 1], ClipperLib::ctDifference)
                                   : glint_levels[g];
            const double a = area(part);
            if (a > 0.0) regions.push_back({RegionClass::Highlight, in.gleams[g]->spec.k, depth, from_paths(part), a});
        }
        ++depth;
    }

    // The silhouette band. The visual contour follows the interpolated
    // normals, the mesh's outline its faces: where they differ (creases,
    // coarse meshes) faces turned to the viewer reach past the contour, and
    // faces turned away inside a patch fold its outline over itself, so
    // the loop's polygon misses what lies under the fold. The band is every
    // face turned to the viewer that has a vertex with N.V < 0 (a face
    // whose vertices all face the viewer lies inside a patch) or lies
    // within two rings of the contour or of a fold; what of it no patch
    // covers joins the map, classed by the face's own N.L.
    const MeshTopology& topo = engine.topology();
    auto facing = [&](const std::array<std::int32_t, 3>& f) {
        const glm::dvec3 &a = topo.positions[f[0]], &b = topo.positions[f[1]], &c = topo.positions[f[2]];
        return glm::dot(glm::cross(b - a, c - a), camera.to_viewer((a + b + c) / 3.0)) > 0.0;
    };
    std::vector<char> fold(topo.n_vertices(), 0);
    std::vector<std::int32_t> frontier;
    auto mark = [&](std::int32_t v) {
        if (!fold[v]) fold[v] = 1, frontier.push_back(v);
    };
    // Seeds: both ends of the contour's edges (past them the surface may
    // fold back under the patch) and the corners of faces turned away
    // inside a patch.
    for (const Snaxel& s : visual.fronts.snaxels) mark(s.inside), mark(s.outside);
    for (const auto& f : topo.face_vertices) {
        if (visual.vertex_f[f[0]] < 0.0 || visual.vertex_f[f[1]] < 0.0 || visual.vertex_f[f[2]] < 0.0) continue;
        if (facing(f)) continue;
        for (const auto v : f) mark(v);
    }
    for (int ring = 0; ring < 2; ++ring) {
        std::vector<std::int32_t> next;
        for (const std::int32_t v : frontier)
            for (std::int32_t i = topo.ring_start[v]; i < topo.ring_start[v + 1]; ++i)
                if (!fold[topo.ring[i]]) fold[topo.ring[i]] = 1, next.push_back(topo.ring[i]);
        frontier = std::move(next);
    }
    const int classes = 2 + int(in.isophotes.size());
    // Each class's faces all face the viewer, so they wind one way in the
    // image: the outline of the set (its edges that no other face of the
    // set shares) has the same non-zero fill as the triangles, at a
    // fraction of the clipping cost.
    std::vector<std::unordered_set<std::uint64_t>> outline(static_cast<std::size_t>(classes));
    auto key = [](std::int32_t u, std::int32_t v) { return (std::uint64_t(std::uint32_t(u)) << 32) | std::uint32_t(v); };
    for (const auto& f : topo.face_vertices) {
        const bool outside = visual.vertex_f[f[0]] < 0.0 || visual.vertex_f[f[1]] < 0.0 || visual.vertex_f[f[2]] < 0.0;
        if (!outside && !fold[f[0]] && !fold[f[1]] && !fold[f[2]]) continue;
        if (!facing(f)) continue; // turned away: hidden on closed meshes
        int cls = 1;
        if (in.shadow) {
            double nl = 0.0;
            for (const auto v : f) nl += glm::dot(topo.normals[v], light.to_light(topo.positions[v]));
            nl /= 3.0;
            cls = nl < 0.0 ? 0 : 1;
            for (std::size_t i = 0; i < in.isophotes.size(); ++i)
                if (nl >= in.isophotes[i]->spec.k) cls = 2 + int(i);
        }
        auto& edges = outline[std::size_t(cls)];
        for (int k = 0; k < 3; ++k) {
            const std::int32_t u = f[k], v = f[(k + 1) % 3];
            if (!edges.erase(key(v, u))) edges.insert(key(u, v));
        }
    }
    std::vector<Paths> band_faces(static_cast<std::size_t>(classes)); // shadow, lit, band 1, band 2, ...
    for (std::size_t cls = 0; cls < outline.size(); ++cls) {
        // Chain the outline's edges into closed loops (any pairing at a
        // vertex where several meet gives the same winding numbers).
        std::unordered_multimap<std::int32_t, std::int32_t> next;
        for (const std::uint64_t e : outline[cls]) next.emplace(std::int32_t(e >> 32), std::int32_t(e & 0xffffffffu));
        std::vector<std::vector<glm::dvec2>> loops;
        while (!next.empty()) {
            auto it = next.begin();
            const std::int32_t start = it->first;
            std::vector<glm::dvec2> loop;
            std::int32_t v = start;
            while (it != next.end()) {
                loop.push_back(projection.project(topo.positions[v]));
                v = it->second;
                next.erase(it);
                if (v == start) break;
                it = next.find(v);
            }
            loops.push_back(std::move(loop));
        }
        band_faces[cls] = to_paths(loops);
    }
    for (int cls = classes - 1; cls >= 0; --cls) { // brighter classes first
        if (band_faces[std::size_t(cls)].empty()) continue;
        const Paths& united = band_faces[std::size_t(cls)];
        const Paths rest = clip::op(united, covered, ClipperLib::ctDifference);
        covered = clip::op(covered, united, ClipperLib::ctUnion);
        const double a = area(rest);
        if (a <= 0.0) continue;
        const RegionClass rc = cls == 0 ? RegionClass::Shadow : cls == 1 ? RegionClass::Lit : RegionClass::Band;
        const double k = cls >= 2 ? in.isophotes[std::size_t(cls - 2)]->spec.k : 0.0;
        regions.push_back({rc, k, depth, from_paths(rest), a});
    }
    return regions;
}

std::vector<std::vector<glm::dvec2>> erode(const std::vector<std::vector<glm::dvec2>>& polygons, double pixels) {
    if (pixels <= 0.0) return polygons;
    ClipperLib::ClipperOffset offset;
    offset.AddPaths(to_paths(polygons), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
    Paths out;
    offset.Execute(out, -pixels * clip::kScale);
    return from_paths(out);
}

} // namespace snaxels
