#include "snaxels/planarmap/snaxel_map.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <numeric>
#include <thread>
#include <cmath>
#include <tuple>
#include <unordered_map>

#include "snaxels/planarmap/detail/polygon_cut.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {
namespace {

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
double linear_root(double fa, double fb) {
    if ((fa < 0.0) == (fb < 0.0) || fa == fb) return 0.5;
    return std::clamp(fa / (fa - fb), 0.0, 1.0);
}

/// Labels are decided at the refined mesh's own scale: a vertex near a fold
/// of a large face is hidden by the refined faces next to it.
VisibilityOptions refined_scale() {
    VisibilityOptions options;
    options.original_neighbourhood = false;
    return options;
}

/// Whether @p topology has a mesh-boundary edge: on a closed mesh a point
/// turned away is always behind the surface (rays from the fold's far side
/// only graze it), so no ray is cast from it.
bool is_open(const MeshTopology& topology) {
    const auto edges = topology.edges();
    return std::any_of(edges.begin(), edges.end(), [&](EdgeId e) { return topology.is_boundary_edge(e); });
}

/// The ray from vertex @p v (from its back side when @p turned_away), as
/// VertexSight codes it.
std::uint8_t sight_of(const RayScene& rays, const VisibilitySampler& sampler, VertexId v, bool turned_away, bool open) {
    std::uint8_t code = turned_away ? VertexSight::kTurnedAway : 0;
    if (!open && turned_away) return code;
    code |= VertexSight::kCast;
    if (rays.occluded(sampler.vertex_ray(v, turned_away))) code |= VertexSight::kBlocked;
    return code;
}

/// The visual contour's segments in the image, bucketed on a grid, with
/// their depth: what an edge's image collides with (rule 2).
class ContourImage {
  public:
    template <class Depth>
    ContourImage(const SnaxelEngine& engine, const ContourResult& visual, const ImageProjection& projection,
                 Depth&& depth)
        : width_(projection.width()), height_(projection.height()) {
        const Fronts& fronts = visual.fronts;
        for (const FrontLoop& loop : fronts.loops) {
            std::int32_t prev = kNoSnaxel, first = kNoSnaxel;
            auto add = [&](std::int32_t s0, std::int32_t s1) {
                const glm::dvec3 a = engine.position(fronts.snaxels[s0]);
                const glm::dvec3 b = engine.position(fronts.snaxels[s1]);
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
          sampler_(rays, camera, refined_scale()) {}

    SnaxelMap build() {
        const auto start = std::chrono::steady_clock::now();
        label_vertices();
        grow_regions();
        place_edge_points();
        select_faces();
        walk_faces();
        take_rim_rings();
        cancel_opposite_steps();
        chain_outlines();
        class_and_rank_regions();
        map_.vertex_region = std::move(comp_);
        map_.stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return std::move(map_);
    }

  private:
    /// The levels of N.L the classes change at: 0 (shadow), then each band's.
    static std::vector<double> shading_levels(const SnaxelMapInput& in) {
        std::vector<double> l{0.0};
        for (const ContourResult* iso : in.isophotes) l.push_back(iso->spec.k);
        return l;
    }
    /// The shading class of a point on the far side of the surface from N.L alone.
    int class_of(double nl) const { return classes_.from_nl(nl); }
    const glm::dvec3& position(VertexId v) const { return topo_.positions()[v]; }
    VertexLabel label(VertexId v) const { return label_[v]; }
    double depth_of(const glm::dvec3& p) const {
        return camera_.orthographic() ? glm::dot(p, camera_.forward()) : glm::dot(p - camera_.eye, camera_.forward());
    }
    bool face_hidden(FaceId f) const {
        const auto& fv = topo_.face_vertices()[f];
        const glm::dvec3 &p0 = position(fv[0]), &p1 = position(fv[1]), &p2 = position(fv[2]);
        const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
        if (topo_.has_strips() && !face_has_area(topo_, f)) return true; // a sharp edge's strip covers nothing
        return rays_.occluded(sampler_.face_ray(f, (p0 + p1 + p2) / 3.0, glm::normalize(n)));
    }

    // ---- label vertices -------------------------------------------------

    /// Where every kind's converged front leaves each vertex (rules 1 and
    /// 4), after the image-plane test against nearer surfaces (rule 2).
    void label_vertices() {
        label_.assign(topo_.n_vertices(), VertexLabel::occluded());
        nl_.assign(topo_.n_vertices(), 0.0);
        // The rays cast beforehand, if cast in this pose and camera.
        const VertexSight* sight = in_.sight && in_.sight->pose == topo_.pose() && in_.sight->camera == camera_ &&
                                           in_.sight->code.size() == topo_.n_vertices()
                                       ? in_.sight
                                       : nullptr;
        const bool open = sight ? sight->open : is_open(topo_);
        parallel_for(topo_.vertices(), [&](VertexId v) {
            label_[v] = label_vertex(v, open, sight);
            // N.L of the vertices turned away too, which the walk past the contour uses.
            if (label_[v].is_away()) nl_[v] = glm::dot(topo_.normals()[v], light_.to_light(position(v)));
        }, 256);
    }

    VertexLabel label_vertex(VertexId v, bool open, const VertexSight* sight) {
        const bool turned_away = visual_.vertex_f[v] < 0.0;
        // The ray cast beforehand where it was cast from this side.
        const bool same_side =
            sight && bool(sight->code[v] & VertexSight::kTurnedAway) == turned_away;
        const std::uint8_t code = same_side ? sight->code[v] : sight_of(rays_, sampler_, v, turned_away, open);
        if (!(code & VertexSight::kCast)) return VertexLabel::away();
        if (code & VertexSight::kBlocked) {
            // Hidden; one turned away is hidden by its own fold as often as
            // not, and faces past the contour may still be seen whole.
            return turned_away ? VertexLabel::away() : VertexLabel::occluded();
        }
        nl_[v] = glm::dot(topo_.normals()[v], light_.to_light(position(v)));
        // Seen although turned away: through a hole of an open mesh, or a
        // corner past the contour of interpolated normals. Its side of the
        // surface forms its own regions, classed by N.L alone.
        if (turned_away) return VertexLabel::far_side(class_of(nl_[v]));
        return VertexLabel::near_side(classes_.classify(
            in_.shadow && in_.shadow->vertex_f[v] < 0.0, [&](int b) { return in_.isophotes[b]->vertex_f[v] >= 0.0; },
            [&](int h) { return in_.gleams[h]->vertex_f[v] >= 0.0; }));
    }

    // ---- grow regions, dissolve flecks ----------------------------------

    /// Regions: grown from a seed over edges of equal label; every vertex no
    /// region reached seeds a new one (rule 3: same kinds merge). A front
    /// needs room on the mesh: a region with no vertex whose whole ring
    /// shares its label is thinner than the tessellation and cannot hold
    /// one; when it is also a fleck of a few vertices, its vertices join the
    /// label most of their neighbours outside it carry, and the regions they
    /// reach are grown again. (Long thin bands along a coarse mesh are kept.)
    void grow_regions() {
        comp_label_.resize(std::size_t(grow_vertex_sets(
            topo_, comp_, [&](VertexId v) { return label(v).seen(); },
            [&](VertexId v, VertexId w) { return label(v) == label(w); })));
        for (const VertexId v : topo_.vertices())
            if (comp_[v] != kNoRegion) comp_label_[comp_[v]] = label(v);
        map_.stats.seeds = comp_label_.size();
        for (int pass = 0; pass < 3; ++pass) { // dissolving can leave a new fleck behind
            const auto moves = fleck_moves();
            if (moves.empty()) break;
            regrow_moved(moves);
            map_.stats.seeds += comp_label_.size();
        }
        for (const VertexLabel l : label_) { // as the flecks left them
            if (l.seen()) ++map_.stats.visible_vertices;
            if (l.is_occluded()) ++map_.stats.occluded_vertices;
        }
    }

    /// A vertex's share of the image: a third of its faces' projected areas
    /// (each face meets two of the vertex's ring edges).
    double vertex_area(VertexId v) const {
        double area = 0.0;
        topo_.for_each_face_beside_edges(v, [&](FaceId f) {
            const auto& fv = topo_.face_vertices()[f];
            const glm::dvec2 p0 = projection_.project(position(fv[0]));
            const glm::dvec2 p1 = projection_.project(position(fv[1]));
            const glm::dvec2 p2 = projection_.project(position(fv[2]));
            area += std::abs((p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y)) / 12.0;
        });
        return area;
    }

    /// The vertices of unsupported flecks, each with the label most of its
    /// neighbours outside the fleck carry.
    std::vector<std::pair<VertexId, VertexLabel>> fleck_moves() const {
        std::vector<char> supported(comp_label_.size(), 0);
        std::vector<int> size(comp_label_.size(), 0);
        for (const std::int32_t r : comp_)
            if (r != kNoRegion) ++size[r];
        // Only the vertices of regions of few vertices can be flecks.
        std::vector<VertexId> small;
        for (const VertexId v : topo_.vertices()) {
            const std::int32_t r = comp_[v];
            if (r != kNoRegion && size[r] < in_.min_unsupported_vertices) small.push_back(v);
        }
        std::vector<double> image_area(comp_label_.size(), 0.0);
        for (const VertexId v : small) image_area[comp_[v]] += vertex_area(v);
        for (std::size_t r = 0; r < size.size(); ++r)
            supported[r] = size[r] >= in_.min_unsupported_vertices || image_area[r] >= in_.min_fleck_area_px;
        for (const VertexId v : small) {
            const std::int32_t r = comp_[v];
            if (supported[r]) continue;
            const auto ring = topo_.neighbours(v);
            const bool interior = !ring.empty() && std::all_of(ring.begin(), ring.end(), [&](VertexId w) { return label(w) == label(v); });
            supported[r] = interior;
        }
        std::vector<std::pair<VertexId, VertexLabel>> moves;
        for (const VertexId v : small) {
            const std::int32_t r = comp_[v];
            if (supported[r]) continue;
            VertexLabel best = label(v);
            int best_count = 0;
            const auto ring = topo_.neighbours(v);
            for (const VertexId w : ring) {
                if (comp_[w] == r) continue;
                const VertexLabel candidate = label(w);
                int count = 0;
                for (const VertexId u : ring) count += comp_[u] != r && label(u) == candidate;
                if (count > best_count || (count == best_count && candidate > best)) best = candidate, best_count = count;
            }
            if (best != label(v)) moves.emplace_back(v, best);
        }
        return moves;
    }

    /// The moved vertices join the regions they now touch: regions grown
    /// again locally, joined where a moved vertex bridges two, then numbered
    /// again.
    void regrow_moved(const std::vector<std::pair<VertexId, VertexLabel>>& moves) {
        std::vector<std::int32_t> parent(comp_label_.size());
        std::iota(parent.begin(), parent.end(), 0);
        auto find = [&](std::int32_t r) {
            while (parent[r] != r) r = parent[r] = parent[parent[r]];
            return r;
        };
        constexpr std::int32_t kToGrow = -2;
        for (const auto& [v, l] : moves) {
            label_[v] = l;
            comp_[v] = kToGrow;
        }
        std::vector<VertexId> stack;
        for (const auto& [v0, l0] : moves) {
            if (comp_[v0] != kToGrow) continue;
            if (!l0.seen()) {
                comp_[v0] = kNoRegion;
                continue;
            }
            const auto id = std::int32_t(comp_label_.size());
            comp_label_.push_back(l0);
            parent.push_back(id);
            comp_[v0] = id;
            stack.push_back(v0);
            while (!stack.empty()) {
                const VertexId v = stack.back();
                stack.pop_back();
                for (const VertexId w : topo_.neighbours(v)) {
                    if (label(w) != l0) continue;
                    if (comp_[w] == kToGrow) {
                        comp_[w] = id;
                        stack.push_back(w);
                    } else if (comp_[w] != kNoRegion) {
                        parent[find(comp_[w])] = find(id);
                    }
                }
            }
        }
        std::vector<std::int32_t> index(comp_label_.size(), kNoRegion);
        std::vector<VertexLabel> labels;
        for (std::int32_t& r : comp_) {
            if (r == kNoRegion) continue;
            const std::int32_t root = find(r);
            if (index[root] == kNoRegion) {
                index[root] = std::int32_t(labels.size());
                labels.push_back(comp_label_[root]);
            }
            r = index[root];
        }
        comp_label_ = std::move(labels);
    }

    // ---- place edge points ----------------------------------------------

    /// Where fronts stop on edges whose labels differ (rules 3 and 4).
    void place_edge_points() {
        // Found in parallel stretches of the edges, joined in edge order.
        constexpr std::size_t kStretches = 64;
        std::vector<std::vector<EdgeId>> cut(kStretches);
        const std::size_t n_edges = topo_.n_edges();
        parallel_for(kStretches, [&](std::size_t k) {
            for (std::size_t i = k * n_edges / kStretches; i < (k + 1) * n_edges / kStretches; ++i) {
                const EdgeId e{std::int32_t(i)};
                if (label(topo_.edge_vertices()[e][0]) != label(topo_.edge_vertices()[e][1]))
                    cut[k].push_back(e); // both hidden: a junction may still use its middle
            }
        }, 1);
        for (const std::vector<EdgeId>& stretch : cut) cut_edges_.insert(cut_edges_.end(), stretch.begin(), stretch.end());
        edge_point_.assign(topo_.n_edges(), glm::dvec3(0.0));
        // Which faces are turned to the viewer (by their own winding).
        front_face_.assign(topo_.n_faces(), 0);
        parallel_for(topo_.faces(), [&](FaceId f) {
            const auto& fv = topo_.face_vertices()[f];
            const glm::dvec3 &p0 = position(fv[0]), &p1 = position(fv[1]), &p2 = position(fv[2]);
            front_face_[f] = glm::dot(glm::cross(p1 - p0, p2 - p0), camera_.to_viewer((p0 + p1 + p2) / 3.0)) > 0.0;
        }, 4096);
        const ContourImage occluder(engine_, visual_, projection_, [&](const glm::dvec3& p) { return depth_of(p); });
        parallel_for(cut_edges_.size(), [&](std::size_t i) {
            const EdgeId e = cut_edges_[i];
            edge_point_[e] = edge_point(e, occluder);
        }, 64);
    }

    /// Where @p r's front crosses edge @p e from @p a to @p b: its snaxel
    /// there, else the root of its function's linear interpolant.
    glm::dvec3 snaxel_point(const ContourResult& r, EdgeId e, VertexId a, VertexId b) const {
        const std::int32_t s = r.fronts.edge_snaxel.empty() ? kNoSnaxel : r.fronts.edge_snaxel[e];
        if (s != kNoSnaxel) return engine_.position(r.fronts.snaxels[s]);
        const double t = linear_root(r.vertex_f[a], r.vertex_f[b]);
        return glm::mix(position(a), position(b), t);
    }

    glm::dvec3 edge_point(EdgeId e, const ContourImage& occluder) const {
        const auto [a, b] = topo_.edge_vertices()[e];
        const VertexLabel la = label(a), lb = label(b);
        if (!la.seen() && !lb.seen()) return 0.5 * (position(a) + position(b));
        if (la.is_away() || lb.is_away()) return snaxel_point(visual_, e, a, b); // the visual contour (closed meshes)
        if (la.on_far_side() != lb.on_far_side() && la.seen() && lb.seen())
            return snaxel_point(visual_, e, a, b); // the visual contour between the two sides
        if (la.is_occluded() || lb.is_occluded()) return occlusion_point(e, occluder);
        if (la.on_far_side()) {
            // Two classes on the far side: the root of N.L at the level between them.
            const int top = std::max(la, lb).cls();
            const double level = levels_[std::max(top - 1, 0)];
            return glm::mix(position(a), position(b), linear_root(nl_[a] - level, nl_[b] - level));
        }
        // Two shading classes: the front of the brighter one's kind.
        const int top = std::max(la, lb).cls();
        const ContourResult* kind = top >= highlight_ ? in_.gleams[top - highlight_]
                                    : top >= 2        ? in_.isophotes[top - 2]
                                                      : in_.shadow;
        return kind ? snaxel_point(*kind, e, a, b) : 0.5 * (position(a) + position(b));
    }

    /// Rule 2: the visible side's front stops where the edge's image meets
    /// the image of a nearer front (the occluder's visual contour), so both
    /// sides of the occlusion share one curve. If no such crossing shows,
    /// the ray to the viewer is bisected.
    glm::dvec3 occlusion_point(EdgeId e, const ContourImage& occluder) const {
        const auto [a, b] = topo_.edge_vertices()[e];
        const VertexId from = label(a).seen() ? a : b, to = label(a).seen() ? b : a;
        const glm::dvec3& p0 = position(from);
        const glm::dvec3& p1 = position(to);
        const double t = occluder.first_crossing(projection_.project(p0), projection_.project(p1),
                                                 [&](double s) { return depth_of(glm::mix(p0, p1, s)); });
        if (t >= 0.0) return glm::mix(p0, p1, t);
        double lo = from == a ? 0.0 : 1.0, hi = 1.0 - lo; // lo visible, hi occluded
        const double pixels = glm::length(projection_.project(p0) - projection_.project(p1));
        const int steps =
            std::clamp(int(std::ceil(std::log2(std::max(pixels / in_.tolerance_px, 1.0)))), 1, in_.bisection_steps);
        for (int step = 0; step < steps; ++step) {
            const double mid = 0.5 * (lo + hi);
            (rays_.occluded(sampler_.edge_ray(e, mid)) ? hi : lo) = mid;
        }
        return glm::mix(position(a), position(b), 0.5 * (lo + hi));
    }

    // ---- walk faces -----------------------------------------------------

    glm::dvec3 point_of(PointId id) const {
        switch (ids_.kind(id)) {
        case PointKind::Vertex: return position(ids_.vertex_of(id));
        case PointKind::EdgePoint: return edge_point_[ids_.edge_of(id)];
        case PointKind::Junction: {
            const auto& fe = topo_.face_edges()[ids_.face_of(id)];
            return (edge_point_[fe[0]] + edge_point_[fe[1]] + edge_point_[fe[2]]) / 3.0;
        }
        default: return extra_point_.at(id.value);
        }
    }
    /// N.L at a point of a piece: at a vertex its own, on an edge
    /// interpolated along it, at a junction the mean of its face's edge points'.
    double nl_on_edge(EdgeId e) const {
        const auto [u, w] = topo_.edge_vertices()[e];
        const double len = glm::length(position(w) - position(u));
        const double t = len > 0.0 ? glm::length(edge_point_[e] - position(u)) / len : 0.5;
        return glm::mix(nl_[u], nl_[w], std::clamp(t, 0.0, 1.0));
    }
    double nl_of(PointId id) const {
        switch (ids_.kind(id)) {
        case PointKind::Vertex: return nl_[ids_.vertex_of(id)];
        case PointKind::EdgePoint: return nl_on_edge(ids_.edge_of(id));
        default: {
            const auto& fe = topo_.face_edges()[ids_.face_of(id)];
            return (nl_on_edge(fe[0]) + nl_on_edge(fe[1]) + nl_on_edge(fe[2])) / 3.0;
        }
        }
    }

    /// The faces the walk visits. A face turned away from the viewer that
    /// lies in a region of the near side (past the contour, or at a crease
    /// where the normals are averaged) is hidden, yet its image, wound the
    /// other way, would cancel the faces it folds over: its pieces are
    /// walked backwards, so they add nothing to their regions' images.
    void select_faces() {
        folded_.assign(topo_.n_faces(), 0);
        FaceData<char> walked(topo_.n_faces(), 0);
        parallel_for(topo_.faces(), [&](FaceId f) {
            const auto& fv = topo_.face_vertices()[f];
            const auto& fe = topo_.face_edges()[f];
            bool near_side = false;
            for (const VertexId v : fv) {
                const std::int32_t r = comp_[v];
                near_side = near_side || (r != kNoRegion && !comp_label_[r].on_far_side());
            }
            folded_[f] = near_side && !front_face_[f];
            // Only faces with a cut edge or a seen mesh-boundary edge, and
            // folded faces, have such steps.
            bool walk = folded_[f];
            for (std::size_t k = 0; k < 3 && !walk; ++k) {
                const VertexLabel la = label(fv[k]), lb = label(fv[(k + 1) % 3]);
                walk = la != lb || (la.seen() && topo_.is_boundary_edge(fe[k]));
            }
            walked[f] = walk;
        }, 4096);
        faces_.reserve(2 * cut_edges_.size());
        for (const FaceId f : topo_.faces())
            if (walked[f]) faces_.push_back(f);
    }

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
    void walk_faces() {
        const auto first_strip = std::int32_t(comp_label_.size());
        // Strip regions are added while other threads read the labels: room
        // for one per class is made first, so adding one never moves them.
        comp_label_.reserve(comp_label_.size() + std::size_t(classes_.count()));
        const std::size_t chunks = std::max<std::size_t>(1, std::thread::hardware_concurrency());
        std::vector<WalkOut> walk(chunks);
        parallel_for(chunks, [&](std::size_t chunk) {
            for (std::size_t fi = chunk * faces_.size() / chunks; fi < (chunk + 1) * faces_.size() / chunks; ++fi)
                walk_face(faces_[fi], walk[chunk]);
        }, 1);
        for (WalkOut& w : walk) {
            steps_.insert(steps_.end(), w.steps.begin(), w.steps.end());
            rim_faces_.insert(rim_faces_.end(), w.rim_faces.begin(), w.rim_faces.end());
        }
        number_strips_by_class(first_strip);
    }

    /// The strip regions were numbered as the threads came upon them: they
    /// are numbered again in class order, so the map is the same every run.
    void number_strips_by_class(std::int32_t first_strip) {
        if (outline_regions_.empty()) return;
        std::vector<std::pair<int, std::int32_t>> by_class(outline_regions_.begin(), outline_regions_.end());
        std::sort(by_class.begin(), by_class.end());
        std::vector<std::int32_t> renumbered(comp_label_.size());
        std::iota(renumbered.begin(), renumbered.end(), 0);
        for (std::size_t i = 0; i < by_class.size(); ++i) {
            const std::int32_t id = first_strip + std::int32_t(i);
            renumbered[by_class[i].second] = id;
            comp_label_[id] = VertexLabel::near_side(by_class[i].first);
            outline_regions_[by_class[i].first] = id;
        }
        for (Step& step : steps_) step = Step(renumbered[step.region()], step.from(), step.to);
        for (auto& [r, f] : vertexless_faces_) r = renumbered[r];
    }

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

    void walk_face(FaceId f, WalkOut& out) {
        const auto& fv = topo_.face_vertices()[f];
        const auto& fe = topo_.face_edges()[f];
        FaceWalk w{f, fv, fe, {label(fv[0]), label(fv[1]), label(fv[2])}, {comp_[fv[0]], comp_[fv[1]], comp_[fv[2]]}, false, {}, {}};
        if (!w.l[0].seen() && !w.l[1].seen() && !w.l[2].seen()) return;
        const bool uniform = w.l[0] == w.l[1] && w.l[1] == w.l[2];
        const bool rim = topo_.is_boundary_edge(fe[0]) || topo_.is_boundary_edge(fe[1]) || topo_.is_boundary_edge(fe[2]);
        if (uniform && !rim && !folded_[f]) return;
        w.three = w.l[0] != w.l[1] && w.l[1] != w.l[2] && w.l[0] != w.l[2];
        for (int owner = 0; owner < 3; ++owner) {
            const std::int32_t r = w.c[owner];
            if (r == kNoRegion) continue;
            bool seen = false; // each region once per face
            for (int k = 0; k < owner; ++k) seen = seen || w.c[k] == r;
            if (seen) continue;
            const int n = piece(w, [&](int k) { return w.c[k] == r; });
            // A folded piece: walked forwards and backwards its steps across
            // the face and along the mesh's boundary cancel; its steps
            // along interior edges remain, backwards.
            const bool backwards = folded_[f] && !comp_label_[r].on_far_side();
            for (int i = 0; i < n; ++i) {
                const PointId a = w.ids[i], b = w.ids[(i + 1) % n];
                const bool across = w.along[i] < 0 || (ids_.kind(a) != PointKind::Vertex && ids_.kind(b) != PointKind::Vertex);
                const bool outline = across || topo_.is_boundary_edge(fe[w.along[i]]);
                if (backwards) {
                    if (!outline) out.steps.emplace_back(r, b, a);
                } else if (outline) {
                    out.steps.emplace_back(r, a, b);
                }
            }
        }
        walk_part_past_contour(w, out);
    }

    /// A face turned to the viewer with corners past the contour of
    /// interpolated normals (turned away by their normals): the face is seen
    /// whole, so its part past the contour joins the region of its seen
    /// corners (the one holding most), up to the mesh's own outline instead
    /// of the approximate one. The part's steps cancel the region's steps
    /// across the face (and those of the next such face).
    void walk_part_past_contour(FaceWalk& w, WalkOut& out) {
        int away = 0, front = 0, most = 0;
        std::int32_t region = kNoRegion;
        for (int k = 0; k < 3; ++k) {
            if (w.l[k].is_away()) ++away;
            if (w.c[k] == kNoRegion) continue;
            ++front;
            int count = 0;
            for (int j = 0; j < 3; ++j) count += w.c[j] == w.c[k];
            if (count > most) most = count, region = w.c[k];
        }
        if (away == 0 || front == 0 || away + front != 3) return; // no hidden corner
        if (region == kNoRegion || !front_face_[w.f]) return;
        // Only where the face itself is seen (past a fold it may lie behind the nearer sheet).
        if (face_hidden(w.f)) return;
        const int n = piece(w, [&](int k) { return w.l[k].is_away(); });
        // The part keeps its region's class where the shading there agrees.
        double nls[7];
        bool one_class = true;
        for (int k = 0; k < n; ++k) {
            nls[k] = nl_of(w.ids[k]);
            one_class = one_class && VertexLabel::near_side(class_of(nls[k])) == comp_label_[region];
        }
        if (one_class) { // the usual case: no level crosses the part
            for (int k = 0; k < n; ++k) out.steps.emplace_back(region, w.ids[k], w.ids[(k + 1) % n]);
        } else {
            std::vector<RimPoint> part;
            for (int k = 0; k < n; ++k) part.push_back({w.ids[k], w.along[k], point_of(w.ids[k]), nls[k]});
            split_part_by_class(std::move(part), w.f, region, out);
        }
        out.rim_faces.emplace_back(w.f, region);
    }

    /// Where N.L crosses a level inside the part (a straight line: N.L is
    /// linear over the face), the other side goes to the outline strip of
    /// that class.
    void split_part_by_class(std::vector<RimPoint> part, FaceId f, std::int32_t region, WalkOut& out) {
        const std::lock_guard<std::mutex> lock(shared_points_);
        const auto& fe = topo_.face_edges()[f];
        std::vector<std::size_t> levels;
        for (std::size_t level = in_.shadow ? 0 : 1; level < levels_.size(); ++level) levels.push_back(level);
        const auto parts = detail::cut_polygon(std::move(part), levels, [&](const std::vector<RimPoint>& poly, std::size_t level) {
            return split_rim(poly, f, level, fe);
        });
        for (const auto& poly : parts) {
            double mid_nl = 0.0;
            for (const RimPoint& q : poly) mid_nl += q.nl;
            mid_nl /= double(poly.size());
            const int cls = class_of(mid_nl);
            const std::int32_t target =
                VertexLabel::near_side(cls) == comp_label_[region] ? region : outline_region(cls);
            if (target != region) vertexless_faces_.emplace_back(target, f);
            for (std::size_t k = 0; k < poly.size(); ++k) out.steps.emplace_back(target, poly[k].id, poly[(k + 1) % poly.size()].id);
        }
    }

    /// The region of the strips of class @p cls past the contour (one per
    /// class; called under shared_points_, within the room walk_faces made).
    std::int32_t outline_region(int cls) {
        const auto it = outline_regions_.find(cls);
        if (it != outline_regions_.end()) return it->second;
        const auto id = std::int32_t(comp_label_.size());
        comp_label_.push_back(VertexLabel::near_side(cls));
        outline_regions_[cls] = id;
        return id;
    }

    /// @p poly cut where N.L crosses levels_[level]: the parts below and above.
    std::pair<std::vector<RimPoint>, std::vector<RimPoint>> split_rim(const std::vector<RimPoint>& poly, FaceId f,
                                                                      std::size_t level, const std::array<EdgeId, 3>& fe) {
        const double value = levels_[level];
        auto crossing = [&](const RimPoint& a, const RimPoint& b, std::size_t k) {
            RimPoint q;
            q.along = a.along;
            if (a.along >= 0) {
                // On face edge a.along: the edge's own root, the same for both faces.
                const EdgeId e = fe[a.along];
                const auto [u, w] = topo_.edge_vertices()[e];
                const double t = linear_root(nl_[u] - value, nl_[w] - value);
                q.id = ids_.level(e, level);
                q.p = glm::mix(position(u), position(w), t);
            } else {
                const double t = std::clamp((value - a.nl) / (b.nl - a.nl), 0.0, 1.0);
                q.id = ids_.across(f, level, k);
                q.p = glm::mix(a.p, b.p, t);
            }
            q.nl = value;
            extra_point_[q.id.value] = q.p;
            return q;
        };
        return detail::split_polygon(poly, [&](const RimPoint& q) { return q.nl < value; }, crossing,
                                     [](RimPoint&, RimPoint&, bool) {});
    }

    // ---- take the rim past creases ----------------------------------------

    /// Past a crease the mesh's outline can lie a few faces beyond the
    /// contour: seen faces turned to the viewer whose corners are all turned
    /// away by their normals join the region of the face they adjoin (up to
    /// three rings).
    void take_rim_rings() {
        std::unordered_map<FaceId, std::int32_t> taken;
        for (const auto& [f, r] : rim_faces_) taken[f] = r;
        std::vector<std::pair<FaceId, std::int32_t>> ring = rim_faces_;
        for (int step = 0; step < 3 && !ring.empty(); ++step) {
            std::vector<std::pair<FaceId, std::int32_t>> next;
            for (const auto& [f, r] : ring)
                for (const EdgeId e : topo_.face_edges()[f])
                    for (const FaceId g : topo_.edge_faces()[e]) {
                        if (g == MeshTopology::kNone || taken.count(g)) continue;
                        const auto& gv = topo_.face_vertices()[g];
                        if (!label(gv[0]).is_away() || !label(gv[1]).is_away() || !label(gv[2]).is_away() || !front_face_[g])
                            continue;
                        if (face_hidden(g)) continue;
                        taken[g] = r;
                        next.emplace_back(g, r);
                        for (std::size_t k = 0; k < 3; ++k) steps_.emplace_back(r, ids_.vertex(gv[k]), ids_.vertex(gv[(k + 1) % 3]));
                    }
            ring = std::move(next);
        }
    }

    // ---- cancel steps walked both ways --------------------------------------

    /// Steps walked both ways (between two pieces of one region, or by a
    /// folded piece) cancel.
    void cancel_opposite_steps() {
        // Sorted in parallel halves, then merged.
        const auto middle = steps_.begin() + std::ptrdiff_t(steps_.size() / 2);
        parallel_for(2, [&](std::size_t half) {
            if (half == 0) std::sort(steps_.begin(), middle);
            else std::sort(middle, steps_.end());
        }, 1);
        std::inplace_merge(steps_.begin(), middle, steps_.end());
        std::vector<char> gone(steps_.size(), 0);
        for (std::size_t i = 0; i < steps_.size(); ++i) {
            if (gone[i]) continue;
            const Step back(steps_[i].region(), steps_[i].to, steps_[i].from());
            auto it = std::lower_bound(steps_.begin(), steps_.end(), back);
            while (it != steps_.end() && *it == back && gone[it - steps_.begin()]) ++it;
            if (it != steps_.end() && *it == back) gone[i] = gone[it - steps_.begin()] = 1;
        }
        std::size_t kept = 0;
        for (std::size_t i = 0; i < steps_.size(); ++i)
            if (!gone[i]) steps_[kept++] = steps_[i];
        steps_.resize(kept);
    }

    // ---- chain outlines -----------------------------------------------------

    /// Chain each region's steps into loops and project them.
    void chain_outlines() {
        regions_.assign(comp_label_.size(), MapRegion{});
        std::vector<char> used(steps_.size(), 0);
        for (std::size_t i = 0; i < steps_.size(); ++i) {
            if (used[i]) continue;
            const std::int32_t r = steps_[i].region();
            const PointId first = steps_[i].from();
            std::vector<glm::dvec2> loop;
            std::size_t at = i;
            while (true) {
                used[at] = 1;
                loop.push_back(projection_.project(point_of(steps_[at].from())));
                const PointId to = steps_[at].to;
                if (to == first) break;
                auto it = std::lower_bound(steps_.begin(), steps_.end(), Step(r, to, PointId{-1}));
                while (it != steps_.end() && it->region() == r && it->from() == to && used[it - steps_.begin()]) ++it;
                if (it == steps_.end() || it->region() != r || it->from() != to) { // an outline that does not close
                    ++map_.stats.open_outlines;
                    break;
                }
                at = std::size_t(it - steps_.begin());
            }
            if (loop.size() >= 3) regions_[r].polygons.push_back(std::move(loop));
        }
    }

    // ---- class and rank regions ---------------------------------------------

    /// Classes, areas (signed loop areas add up: holes wind the other way)
    /// and depth order (by the mean distance of the region's vertices, and
    /// of the faces of strips that hold none).
    void class_and_rank_regions() {
        std::vector<double> depth_sum(comp_label_.size(), 0.0);
        std::vector<std::size_t> depth_n(comp_label_.size(), 0);
        auto add_depth = [&](std::int32_t r, const glm::dvec3& p) {
            depth_sum[r] += camera_.orthographic() ? glm::dot(p, camera_.forward()) : glm::length(p - camera_.eye);
            ++depth_n[r];
        };
        for (const VertexId v : topo_.vertices())
            if (comp_[v] != kNoRegion) add_depth(comp_[v], position(v));
        for (const auto& [r, f] : vertexless_faces_) {
            const auto& fv = topo_.face_vertices()[f];
            add_depth(r, (position(fv[0]) + position(fv[1]) + position(fv[2])) / 3.0);
        }
        std::vector<std::size_t> order(regions_.size());
        for (std::size_t r = 0; r < regions_.size(); ++r) {
            const int cls = comp_label_[r].cls();
            MapRegion& region = regions_[r];
            region.cls = classes_.region_class(cls);
            region.k = classes_.level(cls);
            double signed_area = 0.0;
            for (const auto& poly : region.polygons)
                for (std::size_t j = 0; j < poly.size(); ++j) {
                    const glm::dvec2& p = poly[j];
                    const glm::dvec2& q = poly[(j + 1) % poly.size()];
                    signed_area += p.x * q.y - q.x * p.y;
                }
            region.area = 0.5 * std::abs(signed_area);
            order[r] = r;
        }
        auto mean = [&](std::size_t r) { return depth_sum[r] / double(std::max<std::size_t>(depth_n[r], 1)); };
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return mean(a) < mean(b); });
        for (std::size_t i = 0; i < order.size(); ++i) regions_[order[i]].depth = std::int32_t(i);
        map_.regions = std::move(regions_);
    }

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

} // namespace

VertexSight see_vertices(const MeshTopology& topology, const RayScene& rays, const Camera& camera, const Light& light,
                         const ContourSpec& visual) {
    VertexData<double> f;
    ContourFunction(visual, camera, light).evaluate_vertices(topology, f);
    const bool open = is_open(topology);
    const VisibilitySampler sampler(rays, camera, refined_scale());
    VertexSight sight;
    sight.code.assign(topology.n_vertices(), 0);
    sight.pose = topology.pose();
    sight.camera = camera;
    sight.open = open;
    parallel_for(topology.vertices(), [&](VertexId v) { sight.code[v] = sight_of(rays, sampler, v, f[v] < 0.0, open); }, 256);
    return sight;
}

SnaxelMap build_snaxel_map(const SnaxelEngine& engine, const SnaxelMapInput& in, const RayScene& rays,
                           const ImageProjection& projection, const Camera& camera, const Light& light) {
    return SnaxelMapBuilder(engine, in, rays, projection, camera, light).build();
}

} // namespace snaxels
