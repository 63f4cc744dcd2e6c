// A planar map's regions cut where the scene's parts meet (see
// split_regions_by_part in planar_map.h).

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

#include "snaxels/planarmap/detail/clip.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/snaxel/feature_edges.h"
#include "snaxels/snaxel/intersections.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

namespace {

/// Half the width of the strips the boundaries are cut with, in Clipper
/// units (1/1024 px): the strips are 1/64 px wide.
constexpr double kHalfStrip = 8.0;

/// The material and object lines of @p engine's mesh: lines of the
/// surface, the same in every pose of its connectivity, so found once per
/// mesh (the last mesh's are kept; maps of other meshes find their own).
std::shared_ptr<const std::vector<Fronts>> boundary_fronts(const SnaxelEngine& engine) {
    static std::mutex mutex;
    static std::weak_ptr<const MeshConnectivity> cached_for;
    static std::shared_ptr<const std::vector<Fronts>> cached;
    const std::shared_ptr<const MeshConnectivity>& connectivity = engine.topology().connectivity();
    {
        const std::lock_guard<std::mutex> lock(mutex);
        if (cached && cached_for.lock() == connectivity) return cached;
    }
    auto fronts = std::make_shared<std::vector<Fronts>>();
    for (const ContourKind kind : {ContourKind::Material, ContourKind::Object}) {
        ContourSpec spec;
        spec.kind = kind;
        fronts->push_back(feature_fronts(engine.topology(), spec));
    }
    const std::lock_guard<std::mutex> lock(mutex);
    cached_for = connectivity;
    cached = fronts;
    return cached;
}

} // namespace

void split_regions_by_part(PlanarMap& map, const SnaxelEngine& engine, const RayScene& rays,
                           const ImageProjection& projection, const ContourResult& visual,
                           const ShadingClasses& classes, const Camera& camera, const Light& light) {
    const MeshTopology& topo = engine.topology();
    const FaceParts* parts = topo.parts();
    if (!parts || parts->objects.empty() || parts->materials.empty()) return;
    if (!parts->several()) {
        for (MapRegion& r : map.regions) r.object = 0, r.material = 0;
        return;
    }
    // The boundaries between parts, seen or not: the material and object
    // lines, in the image; and where one object may show in front of
    // another or enter it: every object's outline (the visual contour)
    // and the intersection curves. A boundary that does not show cuts a
    // region of one part into pieces that all see that part, and they join
    // again.
    clip::Paths cuts;
    const std::shared_ptr<const std::vector<Fronts>> lines = boundary_fronts(engine);
    std::vector<const Fronts*> cutting;
    for (const Fronts& fronts : *lines) cutting.push_back(&fronts);
    cutting.push_back(&visual.fronts);
    std::shared_ptr<const IntersectionCurves> meeting;
    if (parts->objects.size() > 1) {
        meeting = require_intersections(topo);
        cutting.push_back(&meeting->fronts);
    }
    // The faceted outline too: the edges between a face turned to the
    // viewer and one turned away (across a split sharp edge's strip, the
    // faces it parts), and the borders. Where a file's normals round an
    // edge the rays see (a cylinder whose smooth sides take its flat caps'
    // normals at the rims), the visual contour runs elsewhere.
    clip::Paths outline_edges;
    if (parts->objects.size() > 1) {
        const glm::dvec3 eye_dir = camera.orthographic() ? camera.to_viewer(glm::dvec3(0.0)) : glm::dvec3(0.0);
        auto facing = [&](FaceId f) {
            const auto& fv = topo.face_vertices()[f];
            const glm::dvec3 a = topo.positions()[fv[0]];
            const glm::dvec3 n = glm::cross(topo.positions()[fv[1]] - a, topo.positions()[fv[2]] - a);
            return glm::dot(n, camera.orthographic() ? eye_dir : camera.eye - a) > 0.0;
        };
        for (const EdgeId e : topo.edges()) {
            if (topo.has_strips() && edge_in_strip(topo, e)) continue;
            const auto faces = faces_beside(topo, e);
            if (faces[0].valid() && faces[1].valid() && facing(faces[0]) == facing(faces[1])) continue;
            ClipperLib::Path path;
            for (const VertexId v : topo.edge_vertices()[e]) {
                const glm::dvec2 q = projection.project(topo.positions()[v]);
                path.push_back({ClipperLib::cInt(std::llround(q.x * clip::kScale)), ClipperLib::cInt(std::llround(q.y * clip::kScale))});
            }
            outline_edges.push_back(std::move(path));
        }
    }
    for (const Fronts* cut : cutting)
        for (const Fronts& fronts = *cut; const FrontLoop& loop : fronts.loops) {
            ClipperLib::Path path;
            fronts.for_each_in_loop(loop, [&](std::int32_t sn) {
                const glm::dvec2 q = projection.project(engine.position(fronts.snaxels[sn]));
                path.push_back({ClipperLib::cInt(std::llround(q.x * clip::kScale)), ClipperLib::cInt(std::llround(q.y * clip::kScale))});
            });
            if (loop.closed && !path.empty()) path.push_back(path.front());
            if (path.size() >= 2) cuts.push_back(std::move(path));
        }
    clip::Paths strips;
    if (!cuts.empty()) {
        ClipperLib::ClipperOffset offset;
        offset.AddPaths(cuts, ClipperLib::jtSquare, ClipperLib::etOpenButt);
        offset.Execute(strips, kHalfStrip);
    }
    if (!outline_edges.empty()) {
        // Each edge on its own, its ends squared past its vertices, so the
        // strips of two edges that meet at an angle leave no gap between.
        clip::Paths more;
        ClipperLib::ClipperOffset offset;
        offset.AddPaths(outline_edges, ClipperLib::jtSquare, ClipperLib::etOpenSquare);
        offset.Execute(more, kHalfStrip);
        strips.insert(strips.end(), more.begin(), more.end());
    }
    // The part seen through an image point: the nearest face on its ray,
    // with the shading class there.
    const double back = 4.0 * bounding_radius(topo) + 1.0;
    using Part = std::pair<std::uint32_t, std::uint32_t>;
    auto seen_at = [&](const glm::dvec2& pixel) -> std::optional<std::pair<Part, int>> {
        VisibilityRay ray;
        projection.pixel_ray(pixel, back, ray.origin, ray.dir);
        ray.tfar = std::numeric_limits<double>::infinity();
        const RayHit hit = rays.nearest(ray);
        if (!hit.hit()) return std::nullopt;
        return std::pair(Part(parts->object[hit.face], parts->material[hit.face]), shading_class_at(topo, hit, classes, camera, light));
    };
    auto part_at = [&](const glm::dvec2& pixel) -> std::optional<Part> {
        const auto seen = seen_at(pixel);
        return seen ? std::optional<Part>(seen->first) : std::nullopt;
    };
    auto class_index = [&](const MapRegion& r) {
        for (int c = 0; c < classes.count(); ++c)
            if (classes.region_class(c) == r.cls && classes.level(c) == r.k) return c;
        return -1;
    };
    // Each region cut by the strips; its pieces take the part seen inside
    // them, those of one part joined, the strips' share going to the largest.
    std::vector<clip::Box> strip_box(strips.size());
    for (std::size_t k = 0; k < strips.size(); ++k) strip_box[k].add(strips[k]);
    std::vector<std::vector<MapRegion>> split(map.regions.size());
    parallel_for(map.regions.size(), [&](std::size_t i) {
        const MapRegion& region = map.regions[i];
        const clip::Paths whole = clip::to_paths(region.polygons);
        clip::Box box;
        for (const auto& path : whole) box.add(path);
        // Only the strips over the region cut it.
        clip::Paths near;
        for (std::size_t k = 0; k < strips.size(); ++k)
            if (strip_box[k].meets(box)) near.push_back(strips[k]);
        ClipperLib::PolyTree tree;
        clip::difference_tree(whole, near, tree);
        std::vector<clip::Paths> pieces = clip::pieces_of(tree);
        const int own_class = class_index(region);
        // Pieces by (part, class): a piece keeps its region's class where
        // a fair share of its rays see that class on its part; a piece of
        // another object's image (the region was ranked nearer than what
        // hides it) takes the class seen there.
        std::map<std::pair<Part, int>, clip::Paths> by_part;
        std::pair<Part, int> largest_part{{0, 0}, own_class};
        double largest = -1.0;
        for (const clip::Paths& piece : pieces) {
            // The part seen through the piece: the one the rays through its
            // inside points meet over most of the spans' width (a ray may
            // slip past a thin piece's edge, and a piece that reaches over
            // another part's image, where a map's region strays past an
            // outline, is still seen as the part most of it shows).
            std::optional<Part> part;
            const std::vector<clip::InsidePoint> points = clip::inside_points(piece);
            std::map<Part, double> votes;
            std::map<std::pair<Part, int>, double> class_votes;
            for (const clip::InsidePoint& point : points)
                if (const auto seen = seen_at(point.at)) {
                    votes[seen->first] += point.width;
                    class_votes[*seen] += point.width;
                }
            double most = 0.0;
            for (const auto& [seen, width] : votes)
                if (width > most) most = width, part = seen;
            // A speck whose rays all slip past the surface takes the part
            // seen right beside it.
            for (double reach = 0.5; !part && !points.empty() && reach <= 4.0; reach *= 2.0)
                for (int a = 0; a < 8 && !part; ++a)
                    part = part_at(points.front().at + reach * glm::dvec2(std::cos(a * 0.785398), std::sin(a * 0.785398)));
            int cls = own_class;
            if (part && class_votes[{*part, own_class}] < 0.25 * most) {
                double best = 0.0;
                for (const auto& [seen, width] : class_votes)
                    if (seen.first == *part && width > best) best = width, cls = seen.second;
            }
            const std::pair<Part, int> key{part.value_or(Part(~0u, ~0u)), part ? cls : own_class};
            clip::Paths& into = by_part[key];
            into.insert(into.end(), piece.begin(), piece.end());
            const double a = clip::area(piece);
            if (a > largest && part) largest = a, largest_part = key;
        }
        // Pieces no ray found a part for (slivers at the edge of the
        // surface) join the largest piece, as do the strips' share.
        if (const auto none = by_part.find({Part(~0u, ~0u), own_class}); none != by_part.end()) {
            if (largest >= 0.0) {
                clip::Paths& into = by_part[largest_part];
                into.insert(into.end(), none->second.begin(), none->second.end());
                by_part.erase(none);
            }
        }
        if (!near.empty() && by_part.size() > 0) {
            const clip::Paths share = clip::op(whole, near, ClipperLib::ctIntersection);
            clip::Paths& into = by_part.count(largest_part) ? by_part[largest_part] : by_part.begin()->second;
            into = clip::op(into, share, ClipperLib::ctUnion);
        }
        for (auto& [key, paths] : by_part) {
            const auto& [part, cls] = key;
            MapRegion piece = region;
            piece.polygons = clip::from_paths(paths);
            piece.area = clip::area(paths);
            if (cls >= 0) piece.cls = classes.region_class(cls), piece.k = classes.level(cls);
            if (part.first != ~0u) piece.object = std::int32_t(part.first), piece.material = std::int32_t(part.second);
            if (piece.area > 0.0) split[i].push_back(std::move(piece));
        }
    }, 1);
    // The regions in their order, each replaced by its pieces; each vertex
    // goes with the piece of its faces' material.
    std::vector<MapRegion> out;
    std::vector<std::vector<std::int32_t>> index(split.size());
    for (std::size_t i = 0; i < split.size(); ++i)
        for (MapRegion& piece : split[i]) index[i].push_back(std::int32_t(out.size())), out.push_back(std::move(piece));
    for (const VertexId v : map.vertex_region.ids()) {
        std::int32_t& r = map.vertex_region[v];
        if (r < 0) continue;
        const auto& candidates = index[r];
        std::int32_t chosen = candidates.empty() ? -1 : candidates.front();
        for (const FaceCorner corner : topo.faces_around(v))
            for (const std::int32_t c : candidates)
                if (out[c].material == std::int32_t(parts->material[corner.face])) chosen = c;
        r = chosen;
    }
    map.regions = std::move(out);
}

} // namespace snaxels
