#pragma once
// The snaxel-defined planar map's construction (build_snaxel_map in
// snaxels/planarmap/snaxel_map.h), shared by its two source files: the
// labels, points and steps it works with, the visual contour's image, and
// the builder, whose stages label the vertices, grow the regions and place
// the edge points (snaxel_map.cpp), then walk the faces, take the rim past
// creases, cancel steps walked both ways, chain the outlines and class and
// rank the regions (snaxel_map_walk.cpp). Not installed.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numeric>
#include <thread>
#include <tuple>
#include <unordered_map>

#include "snaxels/planarmap/detail/polygon_cut.h"
#include "snaxels/planarmap/snaxel_map.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels::detail {

/// A vertex in no region of the map (hidden, or turned away).
constexpr std::int32_t kNoRegion = -1;

/// What a vertex shows the viewer once every kind's front has converged:
/// hidden behind a nearer surface, turned away and unseen, or seen with a
/// shading class (0 shadow, 1 lit, 2.. the bands, then the highlight levels)
/// on the near side of the surface or on its far side (seen through a hole,
/// or a corner past the contour of interpolated normals). Labels order as
/// occluded < away < near classes < far classes, which breaks ties.
class VertexLabel {
  public:
    VertexLabel() = default;
    static VertexLabel occluded() { return VertexLabel(kOccludedCode); }
    static VertexLabel away() { return VertexLabel(kAwayCode); }
    static VertexLabel near_side(int cls) { return VertexLabel(cls); }
    static VertexLabel far_side(int cls) { return VertexLabel(kFarCode + cls); }

    bool seen() const { return code_ >= 0; }
    bool is_occluded() const { return code_ == kOccludedCode; }
    bool is_away() const { return code_ == kAwayCode; }
    bool on_far_side() const { return code_ >= kFarCode; }
    /// The shading class of a seen vertex, on either side.
    int cls() const { return on_far_side() ? code_ - kFarCode : code_; }
    auto operator<=>(const VertexLabel&) const = default;

  private:
    static constexpr int kOccludedCode = -1; // behind a nearer surface
    static constexpr int kAwayCode = -2;     // turned away from the viewer, not seen (N.V < 0)
    static constexpr int kFarCode = 64;      // added to the class of a seen vertex turned away (N.V < 0)
    explicit VertexLabel(int code) : code_(code) {}
    int code_ = kOccludedCode;
};

/// A point an outline passes through. Each kind has its own range of ids, so
/// steps sort by region, then by point, whatever the kind.
struct PointId {
    std::int64_t value = 0;
    auto operator<=>(const PointId&) const = default;
};

enum class PointKind {
    Vertex,    ///< a mesh vertex
    EdgePoint, ///< where fronts stop on an edge whose labels differ
    Junction,  ///< inside a face whose three corners carry three labels
    Level,     ///< past the contour: where N.L crosses a level on an edge (shared by both faces)
    Across     ///< past the contour: where N.L crosses a level inside a face
};

/// The id ranges of the point kinds for one mesh and number of N.L levels.
class PointIds {
  public:
    PointIds(const MeshTopology& topology, std::size_t levels)
        : edge_base_(std::int64_t(topology.n_vertices())), junction_base_(edge_base_ + std::int64_t(topology.n_edges())),
          level_base_(junction_base_ + std::int64_t(topology.n_faces())), levels_(std::int64_t(levels)),
          across_base_(level_base_ + std::int64_t(topology.n_edges()) * levels_) {}

    PointId vertex(VertexId v) const { return {v.index()}; }
    PointId edge(EdgeId e) const { return {edge_base_ + e.index()}; }
    PointId junction(FaceId f) const { return {junction_base_ + f.index()}; }
    PointId level(EdgeId e, std::size_t level) const { return {level_base_ + e.index() * levels_ + std::int64_t(level)}; }
    /// The k-th crossing of @p level along a part of face @p f (at most 8).
    PointId across(FaceId f, std::size_t level, std::size_t k) const {
        return {across_base_ + (f.index() * levels_ + std::int64_t(level)) * 8 + std::int64_t(k)};
    }

    PointKind kind(PointId p) const {
        return p.value < edge_base_       ? PointKind::Vertex
               : p.value < junction_base_ ? PointKind::EdgePoint
               : p.value < level_base_    ? PointKind::Junction
               : p.value < across_base_   ? PointKind::Level
                                          : PointKind::Across;
    }
    /// The vertex of a vertex point, the edge of an edge point, the face of a junction.
    VertexId vertex_of(PointId p) const { return VertexId(std::int32_t(p.value)); }
    EdgeId edge_of(PointId p) const { return EdgeId(std::int32_t(p.value - edge_base_)); }
    FaceId face_of(PointId p) const { return FaceId(std::int32_t(p.value - junction_base_)); }

  private:
    std::int64_t edge_base_, junction_base_, level_base_, levels_, across_base_;
};

/// One step of a region's outline, from one point to the next, sorted by
/// region and start.
struct Step {
    std::uint64_t key = 0; ///< region << 40 | from
    PointId to;
    Step() = default;
    Step(std::int32_t region, PointId from, PointId next)
        : key((std::uint64_t(region) << 40) | std::uint64_t(from.value)), to(next) {}
    std::int32_t region() const { return std::int32_t(key >> 40); }
    PointId from() const { return {std::int64_t(key & ((std::uint64_t(1) << 40) - 1))}; }
    bool operator<(const Step& o) const { return key < o.key || (key == o.key && to < o.to); }
    bool operator==(const Step& o) const { return key == o.key && to == o.to; }
};

/// A point of a face's part past the contour: its id, the face edge the
/// part's boundary follows from it (-1: across the face), where it is and N.L there.
struct RimPoint {
    PointId id;
    int along = -1;
    glm::dvec3 p{0.0};
    double nl = 0.0;
};

/// Root of the linear interpolant of fa (at 0) and fb (at 1), else the middle.
inline double linear_root(double fa, double fb) {
    if ((fa < 0.0) == (fb < 0.0) || fa == fb) return 0.5;
    return std::clamp(fa / (fa - fb), 0.0, 1.0);
}

/// Labels are decided at the refined mesh's own scale: a vertex near a fold
/// of a large face is hidden by the refined faces next to it.
inline VisibilityOptions refined_scale() {
    VisibilityOptions options;
    options.original_neighbourhood = false;
    return options;
}

/// Whether @p topology has a mesh-boundary edge: on a closed mesh a point
/// turned away is always behind the surface (rays from the fold's far side
/// only graze it), so no ray is cast from it.
inline bool is_open(const MeshTopology& topology) {
    const auto edges = topology.edges();
    return std::any_of(edges.begin(), edges.end(), [&](EdgeId e) { return topology.is_boundary_edge(e); });
}

/// The ray from vertex @p v (from its back side when @p turned_away), as
/// VertexSight codes it.
inline std::uint8_t sight_of(const RayScene& rays, const VisibilitySampler& sampler, VertexId v, bool turned_away, bool open) {
    std::uint8_t code = turned_away ? VertexSight::kTurnedAway : 0;
    // Nearer the eye than the near plane: cut from the picture, seen by no ray.
    if (sampler.past_near(rays.topology().positions()[v]) < 0.0) return code | VertexSight::kCast | VertexSight::kBlocked;
    if (!open && turned_away) return code;
    code |= VertexSight::kCast;
    if (rays.occluded(sampler.vertex_ray(v, turned_away))) code |= VertexSight::kBlocked;
    return code;
}

/// The visual contour's segments in the image, bucketed on a grid, with
/// their depth: what an edge's image collides with (rule 2). What lies
/// nearer the eye than @p near is cut off.
class ContourImage {
  public:
    template <class Depth>
    ContourImage(const SnaxelEngine& engine, const ContourResult& visual, const ImageProjection& projection,
                 const NearPlane& near, Depth&& depth)
        : width_(projection.width()), height_(projection.height()) {
        const Fronts& fronts = visual.fronts;
        for (const FrontLoop& loop : fronts.loops) {
            std::int32_t prev = kNoSnaxel, first = kNoSnaxel;
            auto add = [&](std::int32_t s0, std::int32_t s1) {
                glm::dvec3 a = engine.position(fronts.snaxels[s0]);
                glm::dvec3 b = engine.position(fronts.snaxels[s1]);
                if (near.cuts(a) && near.cuts(b)) return;
                if (near.cuts(a)) a = glm::mix(a, b, near.crossing(a, b));
                else if (near.cuts(b)) b = glm::mix(a, b, near.crossing(a, b));
                segments_.push_back({projection.project(a), projection.project(b), depth(a), depth(b)});
            };
            fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                if (prev != kNoSnaxel) add(prev, s);
                else first = s;
                prev = s;
            });
            if (loop.closed && first != kNoSnaxel && prev != first) add(prev, first);
        }
        cols_ = std::max(1, int(std::ceil(width_ / kCell))) + 2;
        rows_ = std::max(1, int(std::ceil(height_ / kCell))) + 2;
        cells_.assign(std::size_t(cols_ * rows_), {});
        for (std::size_t i = 0; i < segments_.size(); ++i)
            for_cells(segments_[i].a, segments_[i].b, [&](std::vector<std::uint32_t>& cell) { cell.push_back(std::uint32_t(i)); });
    }

    /// The parameter along p0 -> p1 of the first crossing with a segment
    /// nearer than the point there (depth(s) gives the point's depth), or -1.
    template <class Depth> double first_crossing(glm::dvec2 p0, glm::dvec2 p1, Depth&& depth) const {
        double best = 2.0;
        for_cells(p0, p1, [&](const std::vector<std::uint32_t>& cell) {
            for (const std::uint32_t i : cell) {
                const Segment& g = segments_[i];
                const glm::dvec2 r = p1 - p0, q = g.b - g.a;
                const double denom = r.x * q.y - r.y * q.x;
                if (std::abs(denom) < 1e-12) continue;
                const glm::dvec2 w = g.a - p0;
                const double t = (w.x * q.y - w.y * q.x) / denom;
                const double u = (w.x * r.y - w.y * r.x) / denom;
                if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0 || t >= best) continue;
                if (g.da + u * (g.db - g.da) < depth(t)) best = t;
            }
        });
        return best <= 1.0 ? best : -1.0;
    }

  private:
    static constexpr double kCell = 8.0;
    struct Segment {
        glm::dvec2 a, b;
        double da, db;
    };
    template <class Cells, class Fn> void visit(Cells& cells, glm::dvec2 a, glm::dvec2 b, Fn&& fn) const {
        const int x0 = std::clamp(int(std::floor(std::min(a.x, b.x) / kCell)) + 1, 0, cols_ - 1);
        const int x1 = std::clamp(int(std::floor(std::max(a.x, b.x) / kCell)) + 1, 0, cols_ - 1);
        const int y0 = std::clamp(int(std::floor(std::min(a.y, b.y) / kCell)) + 1, 0, rows_ - 1);
        const int y1 = std::clamp(int(std::floor(std::max(a.y, b.y) / kCell)) + 1, 0, rows_ - 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) fn(cells[y * cols_ + x]);
    }
    template <class Fn> void for_cells(glm::dvec2 a, glm::dvec2 b, Fn&& fn) { visit(cells_, a, b, fn); }
    template <class Fn> void for_cells(glm::dvec2 a, glm::dvec2 b, Fn&& fn) const { visit(cells_, a, b, fn); }

    double width_, height_;
    int cols_ = 1, rows_ = 1;
    std::vector<Segment> segments_;
    std::vector<std::vector<std::uint32_t>> cells_;
};

/// The map's construction as named stages over shared state, in order:
/// label vertices, grow regions (dissolving flecks), place edge points, walk
/// faces, take the rim past creases, cancel steps walked both ways, chain
/// outlines, and class and rank the regions by depth.

class SnaxelMapBuilder {
  public:
    SnaxelMapBuilder(const SnaxelEngine& engine, const SnaxelMapInput& in, const RayScene& rays,
                     const ImageProjection& projection, const Camera& camera, const Light& light)
        : engine_(engine), in_(in), rays_(rays), projection_(projection), camera_(camera), light_(light),
          topo_(engine.topology()), visual_(*in.visual), classes_(shading_classes(in)),
          highlight_(classes_.first_highlight()), levels_(shading_levels(in)), ids_(topo_, levels_.size()),
          sampler_(rays, camera, refined_scale()), near_(camera, topo_) {}

    SnaxelMap build();

  private:
    /// The levels of N.L the classes change at: 0 (shadow), then each band's.
    static std::vector<double> shading_levels(const SnaxelMapInput& in);
    /// The shading class of a point on the far side of the surface from N.L alone.
    int class_of(double nl) const { return classes_.from_nl(nl); }
    const glm::dvec3& position(VertexId v) const { return topo_.positions()[v]; }
    VertexLabel label(VertexId v) const { return label_[v]; }
    double depth_of(const glm::dvec3& p) const {
        return camera_.orthographic() ? glm::dot(p, camera_.forward()) : glm::dot(p - camera_.eye, camera_.forward());
    }
    bool face_hidden(FaceId f) const;

    // ---- label vertices -------------------------------------------------

    /// Where every kind's converged front leaves each vertex (rules 1 and
    /// 4), after the image-plane test against nearer surfaces (rule 2).
    void label_vertices();

    VertexLabel label_vertex(VertexId v, bool open, const VertexSight* sight);

    // ---- grow regions, dissolve flecks ----------------------------------

    /// Regions: grown from a seed over edges of equal label; every vertex no
    /// region reached seeds a new one (rule 3: same kinds merge). A front
    /// needs room on the mesh: a region with no vertex whose whole ring
    /// shares its label is thinner than the tessellation and cannot hold
    /// one; when it is also a fleck of a few vertices, its vertices join the
    /// label most of their neighbours outside it carry, and the regions they
    /// reach are grown again. (Long thin bands along a coarse mesh are kept.)
    void grow_regions();

    /// A vertex's share of the image: a third of its faces' projected areas
    /// (each face meets two of the vertex's ring edges).
    double vertex_area(VertexId v) const;

    /// The vertices of unsupported flecks, each with the label most of its
    /// neighbours outside the fleck carry.
    std::vector<std::pair<VertexId, VertexLabel>> fleck_moves() const;

    /// The moved vertices join the regions they now touch: regions grown
    /// again locally, joined where a moved vertex bridges two, then numbered
    /// again.
    void regrow_moved(const std::vector<std::pair<VertexId, VertexLabel>>& moves);

    // ---- place edge points ----------------------------------------------

    /// Where fronts stop on edges whose labels differ (rules 3 and 4).
    void place_edge_points();

    /// Where @p r's front crosses edge @p e from @p a to @p b: its snaxel
    /// there, else the root of its function's linear interpolant.
    glm::dvec3 snaxel_point(const ContourResult& r, EdgeId e, VertexId a, VertexId b) const;

    glm::dvec3 edge_point(EdgeId e, const ContourImage& occluder) const;

    /// Rule 2: the visible side's front stops where the edge's image meets
    /// the image of a nearer front (the occluder's visual contour), so both
    /// sides of the occlusion share one curve. If no such crossing shows,
    /// the ray to the viewer is bisected.
    glm::dvec3 occlusion_point(EdgeId e, const ContourImage& occluder) const;

    // ---- walk faces -----------------------------------------------------

    glm::dvec3 point_of(PointId id) const;
    /// N.L at a point of a piece: at a vertex its own, on an edge
    /// interpolated along it, at a junction the mean of its face's edge points'.
    double nl_on_edge(EdgeId e) const;
    double nl_of(PointId id) const;

    /// The faces the walk visits. A face turned away from the viewer that
    /// lies in a region of the near side (past the contour, or at a crease
    /// where the normals are averaged) is hidden, yet its image, wound the
    /// other way, would cancel the faces it folds over: its pieces are
    /// walked backwards, so they add nothing to their regions' images.
    void select_faces();

    /// What a thread's share of the walk adds.
    struct WalkOut {
        std::vector<Step> steps;
        std::vector<std::pair<FaceId, std::int32_t>> rim_faces; ///< (face, region) taken past the contour
    };

    /// Each region's part of every face it touches, walked counter-clockwise
    /// over corners, edge points and (where three labels meet) a junction.
    /// Its steps across the face, or along a mesh boundary, are the region's
    /// outline; steps along interior edges are shared with the next face.
    /// The faces are walked in parallel, each thread into its own lists.
    void walk_faces();

    /// The strip regions were numbered as the threads came upon them: they
    /// are numbered again in class order, so the map is the same every run.
    void number_strips_by_class(std::int32_t first_strip);

    /// A face's corners, their labels and regions, and the pieces they cut it into.
    struct FaceWalk {
        FaceId f;
        const std::array<VertexId, 3>& fv;
        const std::array<EdgeId, 3>& fe;
        VertexLabel l[3];
        std::int32_t c[3];
        bool three; ///< three labels meet: the pieces share a junction
        // The current piece: (id, face edge it leads along, or -1 across the face).
        PointId ids[7];
        int along[7];
    };

    /// The piece of the corners @p picks selects, counter-clockwise, into
    /// w.ids and w.along; its number of points.
    template <class Picks> int piece(FaceWalk& w, Picks&& picks) const {
        int n = 0;
        for (int k = 0; k < 3; ++k) {
            const int k1 = (k + 1) % 3;
            if (picks(k)) w.ids[n] = ids_.vertex(w.fv[k]), w.along[n++] = k;
            if (w.l[k] != w.l[k1] && (picks(k) || picks(k1))) {
                w.ids[n] = ids_.edge(w.fe[k]);
                w.along[n++] = picks(k1) ? k : -1; // toward the next corner: along edge k; else across
                if (w.three && picks(k)) w.ids[n] = ids_.junction(w.f), w.along[n++] = -1;
            }
        }
        return n;
    }

    void walk_face(FaceId f, WalkOut& out);

    /// A face turned to the viewer with corners past the contour of
    /// interpolated normals (turned away by their normals): the face is seen
    /// whole, so its part past the contour joins the region of its seen
    /// corners (the one holding most), up to the mesh's own outline instead
    /// of the approximate one. The part's steps cancel the region's steps
    /// across the face (and those of the next such face).
    void walk_part_past_contour(FaceWalk& w, WalkOut& out);

    /// Where N.L crosses a level inside the part (a straight line: N.L is
    /// linear over the face), the other side goes to the outline strip of
    /// that class.
    void split_part_by_class(std::vector<RimPoint> part, FaceId f, std::int32_t region, WalkOut& out);

    /// The region of the strips of class @p cls past the contour (one per
    /// class; called under shared_points_, within the room walk_faces made).
    std::int32_t outline_region(int cls);

    /// @p poly cut where N.L crosses levels_[level]: the parts below and above.
    std::pair<std::vector<RimPoint>, std::vector<RimPoint>> split_rim(const std::vector<RimPoint>& poly, FaceId f,
                                                                      std::size_t level, const std::array<EdgeId, 3>& fe);

    // ---- take the rim past creases ----------------------------------------

    /// Past a crease the mesh's outline can lie a few faces beyond the
    /// contour: seen faces turned to the viewer whose corners are all turned
    /// away by their normals join the region of the face they adjoin (up to
    /// three rings).
    void take_rim_rings();

    // ---- cancel steps walked both ways --------------------------------------

    /// Steps walked both ways (between two pieces of one region, or by a
    /// folded piece) cancel.
    void cancel_opposite_steps();

    // ---- chain outlines -----------------------------------------------------

    /// Chain each region's steps into loops and project them.
    void chain_outlines();

    // ---- class and rank regions ---------------------------------------------

    /// Classes, areas (signed loop areas add up: holes wind the other way)
    /// and depth order (by the mean distance of the region's vertices, and
    /// of the faces of strips that hold none).
    void class_and_rank_regions();

    const SnaxelEngine& engine_;
    const SnaxelMapInput& in_;
    const RayScene& rays_;
    const ImageProjection& projection_;
    const Camera& camera_;
    const Light& light_;
    const MeshTopology& topo_;
    const ContourResult& visual_;
    const ShadingClasses classes_;
    const int highlight_; ///< the first highlight class
    const std::vector<double> levels_;
    const PointIds ids_;
    const VisibilitySampler sampler_;
    const NearPlane near_; ///< what lies nearer the eye is cut: no vertex there is in a region

    VertexData<VertexLabel> label_;
    VertexData<double> nl_;                           ///< N.L
    VertexData<std::int32_t> comp_;                   ///< each vertex's region, or kNoRegion
    std::vector<VertexLabel> comp_label_;             ///< per region
    std::vector<EdgeId> cut_edges_;                   ///< edges whose labels differ
    EdgeData<glm::dvec3> edge_point_;                 ///< where fronts stop on each edge (cut edges)
    FaceData<char> front_face_, folded_;
    std::vector<FaceId> faces_;                       ///< the faces walked
    std::vector<Step> steps_;                         ///< every region's outline steps
    std::vector<std::pair<FaceId, std::int32_t>> rim_faces_; ///< (face, region) taken past the contour
    std::mutex shared_points_; ///< the rare crossings past the contour, and strip regions
    std::unordered_map<std::int64_t, glm::dvec3> extra_point_;     ///< level and across points
    std::unordered_map<int, std::int32_t> outline_regions_;        ///< class -> region of the strips past the contour
    std::vector<std::pair<std::int32_t, FaceId>> vertexless_faces_; ///< (strip region, face): where the strips lie
    std::vector<MapRegion> regions_;
    SnaxelMap map_;
};

} // namespace snaxels::detail
