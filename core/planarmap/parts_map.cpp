// A planar map's regions cut where the scene's parts meet (see
// split_regions_by_part in planar_map.h).

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>

#include "snaxels/error.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/planarmap/detail/clip.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/snaxel/feature_edges.h"
#include "snaxels/snaxel/intersections.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/util/detail/segment.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {

namespace {

/// Half the width of the strips the boundaries are cut with, in Clipper
/// units (1/1024 px): the strips are 1/256 px wide. A strip goes whole to
/// its region's largest piece, so a pixel's centre that falls in one
/// (an upright post's outline along a column of centres) shows that piece.
constexpr double kHalfStrip = 2.0;

/// How far apart, in the image, a line hidden at both ends of a segment
/// is asked whether it is seen in between.
constexpr double kHiddenStepPixels = 4.0;

/// Points of a cut per strip: a long line is cut as several strips, so
/// that a region meets only the strips that pass near it.
constexpr std::size_t kStripPoints = 24;

/// How far from the straight line between its neighbours, in Clipper
/// units, a point of a cut may lie and be left out (1/256 px).
constexpr double kStraight = 4.0;

/// The side of the tiles whose cuts are widened together, in pixels.
constexpr double kTilePixels = 32.0;

/// An object and a material.
using Part = std::pair<std::uint32_t, std::uint32_t>;
/// A part and a shading class (as ShadingClasses numbers them).
using PartClass = std::pair<Part, int>;
constexpr Part kNoPart{~0u, ~0u};

/// Pieces narrower than kSliverWidth on average (twice the area over the
/// perimeter), in pixels, and smaller than kSliverArea square pixels are
/// slivers.
constexpr double kSliverWidth = 0.5;
constexpr double kSliverArea = 4.0;

/// The material and object lines of @p engine's mesh: lines of the
/// surface, the same in every pose of its connectivity, so found once per
/// mesh and kept in the connectivity's quantities.
std::shared_ptr<const std::vector<Fronts>> boundary_fronts(const SnaxelEngine& engine) {
    const MeshTopology& topo = engine.topology();
    return topo.connectivity()->quantities.require(Quantity<std::vector<Fronts>>{"material and object lines"}, [&] {
        std::vector<Fronts> fronts;
        for (const ContourKind kind : {ContourKind::Material, ContourKind::Object}) {
            ContourSpec spec;
            spec.kind = kind;
            fronts.push_back(feature_fronts(topo, spec));
        }
        return fronts;
    });
}

/// The lines a map's regions are cut along, in the image, as strips
/// 1/256 px wide, each with its box.
class Strips {
  public:
    Strips(const ImageProjection& projection, const NearPlane& near) : projection_(projection), near_(near) {}

    /// Adds the polyline through @p points (world space), what of it lies
    /// past the near plane; @p known_seen: it is seen all along (widen()
    /// does not ask).
    void add(std::vector<glm::dvec3> points, bool known_seen = false) {
        for (std::vector<glm::dvec3>& piece : near_.clip_polyline(std::move(points))) {
            lines_.push_back(std::move(piece));
            known_seen_.push_back(known_seen);
        }
    }

    /// Widens the lines into strips where they may be seen (the segments
    /// with an end @p seen, or, both ends hidden, some point between that
    /// @p seen_along finds; a line hidden all along parts nothing that
    /// shows), each end squared a little past its last point, so that cuts
    /// that meet at an angle (chains broken at a strip or a junction) leave
    /// no gap between their strips.
    template <class Seen, class SeenAlong> void widen(Seen&& seen, SeenAlong&& seen_along) {
        std::vector<std::vector<ClipperLib::Path>> cuts(lines_.size());
        parallel_for(lines_.size(), [&](std::size_t i) {
            const std::vector<glm::dvec3>& points = lines_[i];
            std::vector<bool> at(points.size());
            for (std::size_t k = 0; k < points.size(); ++k) at[k] = known_seen_[i] || seen(points[k]);
            std::size_t start = 0;
            for (std::size_t k = 0; k + 1 <= points.size(); ++k) {
                const bool on = k + 1 < points.size() && (at[k] || at[k + 1] || seen_along(points[k], points[k + 1]));
                if (!on) {
                    cut(points, start, k + 1, cuts[i]);
                    start = k + 1;
                }
            }
        }, 16);
        // Cuts are widened together tile by tile (by where each starts), so
        // that strips that overlap (an outline along a material line, the
        // ends of a line's pieces) are one polygon, while a region meets
        // only the tiles' polygons near it.
        std::map<std::pair<ClipperLib::cInt, ClipperLib::cInt>, ClipperLib::ClipperOffset> tiles;
        const ClipperLib::cInt tile = ClipperLib::cInt(kTilePixels * clip::kScale);
        for (const std::vector<ClipperLib::Path>& line : cuts)
            for (const ClipperLib::Path& path : line) {
                const ClipperLib::IntPoint& p = path.front();
                const auto key = std::pair(p.X >= 0 ? p.X / tile : p.X / tile - 1, p.Y >= 0 ? p.Y / tile : p.Y / tile - 1);
                tiles[key].AddPath(path, ClipperLib::jtSquare, ClipperLib::etOpenSquare);
            }
        std::vector<ClipperLib::ClipperOffset*> offsets;
        for (auto& [key, offset] : tiles) offsets.push_back(&offset);
        std::vector<clip::Paths> widened(offsets.size());
        parallel_for(offsets.size(), [&](std::size_t i) { offsets[i]->Execute(widened[i], kHalfStrip); }, 4);
        for (clip::Paths& strip : widened)
            for (ClipperLib::Path& path : strip) {
                boxes_.emplace_back().add(path);
                strips_.push_back(std::move(path));
            }
        lines_.clear();
        known_seen_.clear();
    }

    /// The strips whose boxes meet @p box, cut to it widened by a pixel (a
    /// strip reaches over many regions; what lies past a region's box
    /// cannot cut it).
    clip::Paths over(const clip::Box& box) const {
        const clip::Box wide = box.widened(ClipperLib::cInt(clip::kScale));
        clip::Paths near;
        for (std::size_t k = 0; k < strips_.size(); ++k) {
            if (!boxes_[k].meets(box)) continue;
            if (ClipperLib::Path part = clip::cropped(strips_[k], boxes_[k], wide); !part.empty()) near.push_back(std::move(part));
        }
        return near;
    }

  private:
    /// @p points from @p begin to @p end (past the last), in the image, in
    /// pieces of kStripPoints, into @p out.
    void cut(const std::vector<glm::dvec3>& points, std::size_t begin, std::size_t end, std::vector<ClipperLib::Path>& out) const {
        // The points in the image, a point that lies on the straight line
        // between its neighbours kept (within kStraight) left out: a refined
        // mesh's outline runs along its faces as loaded, many of its points
        // in a row.
        std::vector<glm::dvec2> kept;
        std::size_t run_start = 0; // in kept: the last point kept for good
        std::vector<glm::dvec2> skipped;
        for (std::size_t k = begin; k < end; ++k) {
            const glm::dvec2 q = projection_.project(points[k]) * clip::kScale;
            if (kept.size() >= 2) {
                // Try leaving the last point out: it and those left out
                // before it must lie near the line from the run's start to q.
                const glm::dvec2 a = kept[run_start];
                bool straight_on = true;
                skipped.push_back(kept.back());
                for (const glm::dvec2& m : skipped)
                    if (point_segment(m, a, q) > kStraight) { straight_on = false; break; }
                if (straight_on) {
                    kept.back() = q;
                    continue;
                }
                skipped.clear();
                run_start = kept.size() - 1;
            }
            kept.push_back(q);
        }
        for (std::size_t start = 0; start + 1 < kept.size(); start += kStripPoints - 1) {
            ClipperLib::Path& path = out.emplace_back();
            for (std::size_t k = start; k < std::min(kept.size(), start + kStripPoints); ++k)
                path.push_back({ClipperLib::cInt(std::llround(kept[k].x)), ClipperLib::cInt(std::llround(kept[k].y))});
        }
    }

    const ImageProjection& projection_;
    const NearPlane& near_;
    std::vector<std::vector<glm::dvec3>> lines_;
    std::vector<bool> known_seen_;
    clip::Paths strips_;
    std::vector<clip::Box> boxes_;
};

/// What the rays through image points see: the nearest face's object and
/// material, and the shading class there.
class PartProbe {
  public:
    PartProbe(const MeshTopology& topo, const RayScene& rays, const ImageProjection& projection, const ShadingClasses& classes,
              const Camera& camera, const Light& light)
        : topo_(topo), parts_(*topo.parts()), rays_(rays), projection_(projection), classes_(classes), camera_(camera), light_(light),
          back_(4.0 * bounding_radius(topo) + 1.0), depth_slack_(0.01 * bounding_radius(topo)), near_(camera, topo) {}

    /// Whether @p p may be seen: nothing on the ray through it lies more
    /// than 1% of the scene's radius nearer.
    bool may_see(const glm::dvec3& p) const {
        VisibilityRay ray;
        projection_.pixel_ray(projection_.project(p), back_, ray.origin, ray.dir);
        ray.origin = near_.ray_start(ray.origin, ray.dir);
        ray.tfar = glm::dot(p - ray.origin, ray.dir) - depth_slack_;
        return ray.tfar <= 0.0 || !rays_.occluded(ray);
    }

    std::optional<PartClass> seen_at(const glm::dvec2& pixel) const {
        const RayHit hit = nearest(pixel);
        if (!hit.hit()) return std::nullopt;
        return PartClass(part_of(hit.face), shading_class_at(topo_, hit, classes_, camera_, light_));
    }

    /// The part seen nearest @p pixel, up to 4 px away (a speck whose rays
    /// all slip past the surface takes the part seen right beside it).
    std::optional<Part> part_near(const glm::dvec2& pixel) const {
        for (double reach = 0.5; reach <= 4.0; reach *= 2.0)
            for (int a = 0; a < 8; ++a) {
                const RayHit hit = nearest(pixel + reach * glm::dvec2(std::cos(a * 0.785398), std::sin(a * 0.785398)));
                if (hit.hit()) return part_of(hit.face);
            }
        return std::nullopt;
    }

    /// Whether some point strictly between @p a and @p b (both known
    /// hidden) may be seen: asked every kHiddenStepPixels, the middle at
    /// least (a rod's long side edge runs from inside one ball to inside
    /// another, seen between them over a few pixels).
    bool may_see_between(const glm::dvec3& a, const glm::dvec3& b) const {
        const int steps = int(std::clamp(std::ceil(pixels_between(a, b) / kHiddenStepPixels), 2.0, 256.0));
        for (int k = 1; k < steps; ++k)
            if (may_see(a + (b - a) * (double(k) / steps))) return true;
        return false;
    }

    /// Whether some surface lies behind @p p on the ray through it (the
    /// faces around @p ignore skipped: the outline's own).
    bool behind(const glm::dvec3& p, const std::array<VertexId, 3>& ignore) const {
        VisibilityRay ray;
        projection_.pixel_ray(projection_.project(p), back_, ray.origin, ray.dir);
        // From a little in front of the point: a surface the object rests
        // on, through the point, is behind it too.
        ray.origin = p - 0.1 * depth_slack_ * ray.dir;
        ray.tfar = std::numeric_limits<double>::infinity();
        ray.ignore = ignore;
        return rays_.occluded(ray);
    }

    /// How far apart @p a and @p b lie in the image, in pixels.
    double pixels_between(const glm::dvec3& a, const glm::dvec3& b) const {
        return glm::length(projection_.project(b) - projection_.project(a));
    }

  private:
    RayHit nearest(const glm::dvec2& pixel) const {
        VisibilityRay ray;
        projection_.pixel_ray(pixel, back_, ray.origin, ray.dir);
        ray.origin = near_.ray_start(ray.origin, ray.dir);
        ray.tfar = std::numeric_limits<double>::infinity();
        return rays_.nearest(ray);
    }
    Part part_of(FaceId f) const { return {parts_.object[f], parts_.material[f]}; }

    const MeshTopology& topo_;
    const FaceParts& parts_;
    const RayScene& rays_;
    const ImageProjection& projection_;
    const ShadingClasses& classes_;
    const Camera& camera_;
    const Light& light_;
    double back_;
    double depth_slack_;
    NearPlane near_; ///< rays start on it: what lies nearer is cut

  public:
    const NearPlane& near_plane() const { return near_; }
};

/// The material and object lines (the same in every pose) and, on a scene
/// of several objects, the intersection curves, cut into @p strips.
void add_part_lines(const SnaxelEngine& engine, const FaceParts& parts, Strips& strips) {
    const std::shared_ptr<const std::vector<Fronts>> lines = boundary_fronts(engine);
    std::vector<const Fronts*> cutting;
    for (const Fronts& fronts : *lines) cutting.push_back(&fronts);
    std::shared_ptr<const IntersectionCurves> meeting;
    if (parts.objects.size() > 1) {
        meeting = require_intersections(engine.topology());
        cutting.push_back(&meeting->fronts);
    }
    std::vector<glm::dvec3> line;
    for (const Fronts* fronts : cutting)
        for (const FrontLoop& loop : fronts->loops) {
            line.clear();
            fronts->for_each_in_loop(loop, [&](std::int32_t sn) { line.push_back(engine.position(fronts->snaxels[sn])); });
            if (loop.closed && !line.empty()) line.push_back(line.front());
            strips.add(line);
        }
}

/// An edge that may lie on a faceted outline and the faces it parts.
struct OutlineCandidate {
    EdgeId edge;
    std::array<FaceId, 2> faces; ///< a border's second is not valid
};

/// The edges that may lie on a faceted outline in some pose of @p topo's
/// connectivity, with the faces they part: on a refined mesh only those
/// between faces of different original faces (the faces of one original
/// face stay in its plane) and borders; an edge of a split sharp edge's
/// strip parts nothing, and across the strip the faces beside it are those
/// it parts (faces_beside). Found once: a strip has no area in any pose.
std::shared_ptr<const std::vector<OutlineCandidate>> outline_candidates(const MeshTopology& topo) {
    return topo.connectivity()->quantities.require(Quantity<std::vector<OutlineCandidate>>{"faceted outline candidates"}, [&] {
        std::vector<OutlineCandidate> edges;
        const std::shared_ptr<const MeshRefinement>& refinement = topo.refinement();
        auto with_area = [&](FaceId f) { return f.valid() && (!topo.has_strips() || face_has_area(topo, f)); };
        for (const EdgeId e : topo.edges()) {
            std::array<FaceId, 2> faces = topo.edge_faces()[e];
            const bool border = !faces[0].valid() || !faces[1].valid();
            if (refinement && !border && refinement->face_origin[faces[0]] == refinement->face_origin[faces[1]]) continue;
            const bool area[2] = {with_area(faces[0]), with_area(faces[1])};
            if (!area[0] && !area[1]) continue;
            if (!border && area[0] != area[1]) faces = faces_beside(topo, e);
            edges.push_back({e, faces});
        }
        return edges;
    });
}

/// The stretches of @p chain (an outline of one object) that part that
/// object from another where they may be seen, as polylines in @p out.
/// First, at points about kHiddenStepPixels apart in the image (vertices,
/// and points between on a longer edge), whether some surface lies behind
/// the outline (past an outline the viewer sees what lies behind it; where
/// nothing does, the outline parts the object from nothing). Then, on each
/// edge next to such a point, whether it may be seen: at its ends, or, both
/// hidden, between them.
void outline_stretches(const MeshTopology& topo, const EdgeChain& chain, const PartProbe& probe,
                       std::vector<std::vector<glm::dvec3>>& out) {
    const auto& vs = chain.vertices;
    const std::size_t n = vs.size() - 1; // edges
    auto at = [&](std::size_t k) { return topo.positions()[vs[k]]; };
    // Per edge: whether something lies behind an asked point on it or at
    // the asked points on either side of it.
    std::vector<std::uint8_t> backed(n, 0);
    std::size_t last_edge = 0; // the first edge after the last asked point
    bool last_backed = probe.behind(at(0), {vs[0], VertexId(), VertexId()});
    double since = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
        const double pixels = probe.pixels_between(at(k), at(k + 1));
        const int steps = int(std::min(std::floor(pixels / kHiddenStepPixels), 256.0));
        for (int s = 1; s <= steps; ++s) {
            const bool b = probe.behind(at(k) + (at(k + 1) - at(k)) * (double(s) / (steps + 1)), {vs[k], vs[k + 1], VertexId()});
            if (b || last_backed)
                for (std::size_t e = last_edge; e <= k; ++e) backed[e] = 1;
            last_edge = k, last_backed = b;
        }
        since = steps > 0 ? pixels / (steps + 1) : since + pixels;
        if (since >= kHiddenStepPixels || k + 1 == n) {
            const bool b = probe.behind(at(k + 1), {vs[k + 1], VertexId(), VertexId()});
            if (b || last_backed)
                for (std::size_t e = last_edge; e <= k; ++e) backed[e] = 1;
            last_edge = k + 1, last_backed = b, since = 0.0;
        }
    }
    // Per vertex: 0 not asked, 1 hidden, 2 may be seen.
    std::vector<std::uint8_t> seen(vs.size(), 0);
    auto seen_at = [&](std::size_t k) {
        if (!seen[k]) seen[k] = probe.may_see(at(k)) ? 2 : 1;
        return seen[k] == 2;
    };
    std::vector<glm::dvec3>* line = nullptr;
    for (std::size_t k = 0; k < n; ++k) {
        // Between two hidden ends, a longer edge is asked along it (a
        // rod's side edge from inside one ball to inside another, seen
        // between them); a shorter one is as finely asked as its ends are.
        const bool cut = backed[k] && (seen_at(k) || seen_at(k + 1) ||
                                       (probe.pixels_between(at(k), at(k + 1)) > kHiddenStepPixels && probe.may_see_between(at(k), at(k + 1))));
        if (!cut) {
            line = nullptr;
            continue;
        }
        if (!line) line = &out.emplace_back(1, at(k));
        line->push_back(at(k + 1));
    }
}

/// The faceted outline where it parts two objects and may be seen: the
/// edges between a face turned to the viewer and one turned away (across a
/// split sharp edge's strip, the faces it parts), and the borders, chained.
/// It is where the rays' answer changes from one object to another (the
/// visual contour of a file's rounded normals can run well inside it: a
/// cylinder whose smooth sides take its flat caps' normals at the rims).
void add_faceted_outline(const MeshTopology& topo, const RayScene& rays, const Camera& camera, const PartProbe& probe, Strips& strips) {
    const glm::dvec3 eye_dir = camera.orthographic() ? camera.to_viewer(glm::dvec3(0.0)) : glm::dvec3(0.0);
    const FaceData<RayScene::FacePlane>& planes = rays.face_planes();
    if (planes.size() != topo.n_faces()) throw InternalError("add_faceted_outline: the ray scene has no face planes");
    FaceData<std::uint8_t> facing(topo.n_faces(), 0);
    parallel_for(topo.faces(), [&](FaceId f) {
        const RayScene::FacePlane& plane = planes[f];
        facing[f] = glm::dot(plane.normal, camera.orthographic() ? eye_dir : camera.eye - plane.corner) > 0.0;
    }, 4096);
    const std::shared_ptr<const std::vector<OutlineCandidate>> candidates = outline_candidates(topo);
    std::vector<std::uint8_t> on(candidates->size(), 0);
    parallel_for(candidates->size(), [&](std::size_t i) {
        const auto& faces = (*candidates)[i].faces;
        on[i] = !faces[0].valid() || !faces[1].valid() || facing[faces[0]] != facing[faces[1]];
    }, 4096);
    std::vector<EdgeId> outline;
    for (std::size_t i = 0; i < candidates->size(); ++i)
        if (on[i]) outline.push_back((*candidates)[i].edge);
    const std::vector<EdgeChain> chains = chain_edges(topo, outline);
    std::vector<std::vector<std::vector<glm::dvec3>>> lines(chains.size());
    parallel_for(chains.size(), [&](std::size_t i) { outline_stretches(topo, chains[i], probe, lines[i]); }, 4);
    for (auto& chain_lines : lines)
        for (auto& line : chain_lines) strips.add(std::move(line), true);
}

/// The part and class a piece of a region shows: the part the rays through
/// its inside points meet over most of the spans' width (a ray may slip
/// past a thin piece's edge, and a piece that reaches over another part's
/// image, where a map's region strays past an outline, is still seen as
/// the part most of it shows). The piece keeps its region's class
/// (@p own_class) where a fair share of its rays see that class on its
/// part; a piece of another object's image (the region was ranked nearer
/// than what hides it) takes the class seen there. No part when no ray
/// near it meets the surface.
std::pair<std::optional<Part>, int> seen_in(const clip::Paths& piece, const PartProbe& probe, int own_class) {
    const std::vector<clip::InsidePoint> points = clip::inside_points(piece);
    std::map<Part, double> votes;
    std::map<PartClass, double> class_votes;
    for (const clip::InsidePoint& point : points)
        if (const auto seen = probe.seen_at(point.at)) {
            votes[seen->first] += point.width;
            class_votes[*seen] += point.width;
        }
    std::optional<Part> part;
    double most = 0.0;
    for (const auto& [seen, width] : votes)
        if (width > most) most = width, part = seen;
    if (!part && !points.empty()) part = probe.part_near(points.front().at);
    int cls = own_class;
    if (part && class_votes[{*part, own_class}] < 0.25 * most) {
        double best = 0.0;
        for (const auto& [seen, width] : class_votes)
            if (seen.first == *part && width > best) best = width, cls = seen.second;
    }
    return {part, cls};
}

/// Whether a point of @p piece lies on an edge of @p whole (within 1/512 px).
bool touches(const clip::Paths& piece, const clip::Paths& whole) {
    for (const auto& path : piece)
        for (const auto& p : path)
            for (const auto& outline : whole)
                for (std::size_t i = 0; i < outline.size(); ++i) {
                    const auto& a = outline[i];
                    const auto& b = outline[(i + 1) % outline.size()];
                    if (point_segment(glm::dvec2(p.X, p.Y), glm::dvec2(a.X, a.Y), glm::dvec2(b.X, b.Y)) <= 2.0) return true;
                }
    return false;
}

/// The shading class of @p region as @p classes numbers them (-1: none).
int class_index(const ShadingClasses& classes, const MapRegion& region) {
    for (int c = 0; c < classes.count(); ++c)
        if (classes.region_class(c) == region.cls && classes.level(c) == region.k) return c;
    return -1;
}

/// @p region cut by the strips over it (a region under kSliverArea square
/// pixels is not cut: it shows what most of it shows); its pieces take the
/// part seen inside them, those of one part and class joined, the strips'
/// share and the pieces no ray found a part for going to the largest.
std::vector<MapRegion> split_region(const MapRegion& region, const Strips& strips, const PartProbe& probe, const ShadingClasses& classes) {
    const clip::Paths whole = clip::to_paths(region.polygons);
    clip::Box box;
    for (const auto& path : whole) box.add(path);
    const clip::Paths near = region.area < kSliverArea ? clip::Paths() : strips.over(box);
    const int own_class = class_index(classes, region);
    std::vector<clip::Paths> pieces;
    if (near.empty()) {
        pieces.push_back(whole);
    } else {
        ClipperLib::PolyTree tree;
        clip::difference_tree(whole, near, tree);
        pieces = clip::pieces_of(tree);
    }
    // All strip (under 1/256 px across): the region as a whole shows a part,
    // or it is left out.
    if (pieces.empty()) pieces.push_back(whole);
    // Slivers inside the region (small, on average under half a pixel
    // across, clear of its outline: between cuts that run side by side)
    // are not asked what they show unless the region is all slivers; they
    // go with the largest piece. Those along its outline are asked (where
    // the outline and a cut beside it part two objects, the slivers add up
    // to whole pixels).
    std::vector<bool> thin(pieces.size());
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const double a = clip::area(pieces[k]);
        thin[k] = a < kSliverArea && 2.0 * a < kSliverWidth * clip::perimeter(pieces[k]) && !touches(pieces[k], whole);
    }
    const bool all_thin = std::all_of(thin.begin(), thin.end(), [](bool t) { return t; });
    std::map<PartClass, clip::Paths> by_part;
    PartClass largest_part{{0, 0}, own_class};
    double largest = -1.0;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const clip::Paths& piece = pieces[k];
        const auto [part, cls] = thin[k] && !all_thin ? std::pair<std::optional<Part>, int>() : seen_in(piece, probe, own_class);
        const PartClass key{part.value_or(kNoPart), part ? cls : own_class};
        clip::Paths& into = by_part[key];
        into.insert(into.end(), piece.begin(), piece.end());
        const double a = clip::area(piece);
        if (a > largest && part) largest = a, largest_part = key;
    }
    // No ray near any piece meets the surface: the region shows nothing.
    if (largest < 0.0) return {};
    if (const auto none = by_part.find({kNoPart, own_class}); none != by_part.end()) {
        clip::Paths& into = by_part[largest_part];
        into.insert(into.end(), none->second.begin(), none->second.end());
        by_part.erase(none);
    }
    if (by_part.size() == 1) {
        // One part and class seen all over: the region stays whole.
        by_part.begin()->second = whole;
    } else if (by_part.count(largest_part)) {
        // The largest piece takes the strips' share: all that the others
        // leave of the region.
        clip::Paths others;
        for (const auto& [key, paths] : by_part)
            if (key != largest_part) others.insert(others.end(), paths.begin(), paths.end());
        by_part[largest_part] = clip::op(whole, others, ClipperLib::ctDifference);
    }
    std::vector<MapRegion> out;
    for (auto& [key, paths] : by_part) {
        const auto& [part, cls] = key;
        MapRegion piece = region;
        piece.polygons = clip::from_paths(paths);
        piece.area = clip::area(paths);
        if (cls >= 0) piece.cls = classes.region_class(cls), piece.k = classes.level(cls);
        if (part != kNoPart) piece.object = std::int32_t(part.first), piece.material = std::int32_t(part.second);
        if (piece.area > 0.0) out.push_back(std::move(piece));
    }
    return out;
}

/// @p map's regions in their order, each replaced by its pieces
/// (@p split); each vertex goes with the piece of its faces' material.
void replace_regions(PlanarMap& map, std::vector<std::vector<MapRegion>>&& split, const MeshTopology& topo) {
    const FaceParts& parts = *topo.parts();
    std::vector<MapRegion> out;
    std::vector<std::vector<std::int32_t>> index(split.size());
    for (std::size_t i = 0; i < split.size(); ++i)
        for (MapRegion& piece : split[i]) index[i].push_back(std::int32_t(out.size())), out.push_back(std::move(piece));
    parallel_for(map.vertex_region.ids(), [&](VertexId v) {
        std::int32_t& r = map.vertex_region[v];
        if (r < 0) return;
        const auto& candidates = index[r];
        std::int32_t chosen = candidates.empty() ? -1 : candidates.front();
        if (candidates.size() >= 2)
            for (const FaceCorner corner : topo.faces_around(v))
                for (const std::int32_t c : candidates)
                    if (out[c].material == std::int32_t(parts.material[corner.face])) chosen = c;
        r = chosen;
    }, 4096);
    map.regions = std::move(out);
}

} // namespace

void split_regions_by_part(PlanarMap& map, const SnaxelEngine& engine, const RayScene& rays,
                           const ImageProjection& projection, const ShadingClasses& classes, const Camera& camera, const Light& light) {
    const MeshTopology& topo = engine.topology();
    const FaceParts* parts = topo.parts();
    if (!parts || parts->objects.empty() || parts->materials.empty()) return;
    if (!parts->several()) {
        for (MapRegion& r : map.regions) r.object = 0, r.material = 0;
        return;
    }
    // The boundaries between parts, seen or not: the material and object
    // lines, in the image; and where one object may show in front of
    // another or enter it: the intersection curves and every object's
    // faceted outline. Only where they may be seen: a hidden boundary
    // parts nothing that shows.
    const PartProbe probe(topo, rays, projection, classes, camera, light);
    Strips strips(projection, probe.near_plane());
    add_part_lines(engine, *parts, strips);
    if (parts->objects.size() > 1) add_faceted_outline(topo, rays, camera, probe, strips);
    strips.widen(
        [&](const glm::dvec3& p) { return probe.may_see(p); }, [&](const glm::dvec3& a, const glm::dvec3& b) { return probe.may_see_between(a, b); });
    std::vector<std::vector<MapRegion>> split(map.regions.size());
    parallel_for(map.regions.size(), [&](std::size_t i) { split[i] = split_region(map.regions[i], strips, probe, classes); }, 1);
    replace_regions(map, std::move(split), topo);
}

} // namespace snaxels
