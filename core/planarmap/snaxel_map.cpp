#include "snaxels/planarmap/snaxel_map.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <thread>
#include <cmath>
#include <tuple>
#include <unordered_map>

#include "snaxels/util/detail/parallel.h"
#include "snaxels/visibility/visibility.h"

namespace snaxels {
namespace {

/// One step of a region's outline, from one point to the next (point ids:
/// vertices, then edge points, junctions and crossings), sorted by region
/// and start.
struct Step {
    std::uint64_t key = 0; ///< region << 40 | from
    std::int64_t to = 0;
    Step() = default;
    Step(std::int32_t region, std::int64_t from, std::int64_t next)
        : key((std::uint64_t(region) << 40) | std::uint64_t(from)), to(next) {}
    std::int32_t region() const { return std::int32_t(key >> 40); }
    std::int64_t from() const { return std::int64_t(key & ((std::uint64_t(1) << 40) - 1)); }
    bool operator<(const Step& o) const { return key < o.key || (key == o.key && to < o.to); }
    bool operator==(const Step& o) const { return key == o.key && to == o.to; }
};

/// A point of a face's part past the contour: its id, the face edge the
/// part's boundary follows from it (-1: across the face), where it is and N.L there.
struct RimPoint {
    std::int64_t id = 0;
    int along = -1;
    glm::dvec3 p{0.0};
    double nl = 0.0;
};

constexpr int kOccluded = -1; // behind a nearer surface
constexpr int kAway = -2;     // turned away from the viewer, not seen (N.V < 0)
constexpr int kBack = 64;     // added to the class of a visible vertex turned away (N.V < 0)

/// Root of the linear interpolant of fa (at 0) and fb (at 1), else the middle.
double linear_root(double fa, double fb) {
    if ((fa < 0.0) == (fb < 0.0) || fa == fb) return 0.5;
    return std::clamp(fa / (fa - fb), 0.0, 1.0);
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
            std::int32_t prev = MeshTopology::kNone, first = MeshTopology::kNone;
            auto add = [&](std::int32_t s0, std::int32_t s1) {
                const glm::dvec3 a = engine.position(fronts.snaxels[std::size_t(s0)]);
                const glm::dvec3 b = engine.position(fronts.snaxels[std::size_t(s1)]);
                segments_.push_back({projection.project(a), projection.project(b), depth(a), depth(b)});
            };
            fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                if (prev != MeshTopology::kNone) add(prev, s);
                else first = s;
                prev = s;
            });
            if (loop.closed && first != MeshTopology::kNone && prev != first) add(prev, first);
        }
        cols_ = std::max(1, int(std::ceil(width_ / kCell))) + 2;
        rows_ = std::max(1, int(std::ceil(height_ / kCell))) + 2;
        cells_.assign(std::size_t(cols_) * std::size_t(rows_), {});
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
            for (int x = x0; x <= x1; ++x) fn(cells[std::size_t(y) * std::size_t(cols_) + std::size_t(x)]);
    }
    template <class Fn> void for_cells(glm::dvec2 a, glm::dvec2 b, Fn&& fn) { visit(cells_, a, b, fn); }
    template <class Fn> void for_cells(glm::dvec2 a, glm::dvec2 b, Fn&& fn) const { visit(cells_, a, b, fn); }

    double width_, height_;
    int cols_ = 1, rows_ = 1;
    std::vector<Segment> segments_;
    std::vector<std::vector<std::uint32_t>> cells_;
};

} // namespace

SnaxelMap build_snaxel_map(const SnaxelEngine& engine, const SnaxelMapInput& in, const RayScene& rays,
                           const ImageProjection& projection, const Camera& camera, const Light& light) {
    const auto start = std::chrono::steady_clock::now();
    const MeshTopology& topo = engine.topology();
    const ContourResult& visual = *in.visual;
    const auto V = std::int32_t(topo.n_vertices());
    const auto E = std::int32_t(topo.n_edges());
    const int bands = int(in.isophotes.size());
    const int highlight = 2 + bands; // classes: 0 shadow, 1 lit, 2.. bands, then the highlight levels
    const int gleams = int(in.gleams.size());
    // Labels are decided at the refined mesh's own scale: a vertex near a
    // fold of a large face is hidden by the refined faces next to it.
    VisibilityOptions ray_options;
    ray_options.original_neighbourhood = false;
    const VisibilitySampler sampler(rays, camera, ray_options);
    SnaxelMap map;

    // Labels: where every kind's converged front leaves each vertex (rules
    // 1 and 4), after the image-plane test against nearer surfaces (rule 2).
    std::vector<int> label(static_cast<std::size_t>(V), kOccluded);
    std::vector<double> nl(static_cast<std::size_t>(V));
    const std::vector<double> levels = [&] {
        std::vector<double> l{0.0};
        for (const ContourResult* iso : in.isophotes) l.push_back(iso->spec.k);
        return l;
    }();
    // On a closed mesh a point turned away is always behind the surface
    // (rays from the fold's far side only graze it): no ray is needed.
    bool open = false;
    for (std::int32_t e = 0; e < E && !open; ++e) open = topo.is_boundary_edge(e);
    parallel_for(std::size_t(V), [&](std::size_t i) {
        const auto v = std::int32_t(i);
        if (!open && visual.vertex_f[i] < 0.0) {
            label[i] = kAway;
            return;
        }
        if (rays.occluded(sampler.vertex_ray(v, visual.vertex_f[i] < 0.0))) {
            // Hidden; one turned away is hidden by its own fold as often as
            // not, and faces past the contour may still be seen whole.
            label[i] = visual.vertex_f[i] < 0.0 ? kAway : kOccluded;
            return;
        }
        nl[i] = glm::dot(topo.normals[i], light.to_light(topo.positions[i]));
        if (visual.vertex_f[i] < 0.0) {
            // Seen although turned away: through a hole of an open mesh, or
            // a corner past the contour of interpolated normals. Its side of
            // the surface forms its own regions, classed by N.L alone.
            int cls = in.shadow && nl[i] < 0.0 ? 0 : 1;
            for (int k = 0; k < bands; ++k)
                if (cls != 0 && nl[i] >= levels[std::size_t(k + 1)]) cls = 2 + k;
            label[i] = kBack + cls;
            return;
        }
        int cls = in.shadow && in.shadow->vertex_f[i] < 0.0 ? 0 : 1;
        for (int k = 0; k < bands; ++k)
            if (cls != 0 && in.isophotes[std::size_t(k)]->vertex_f[i] >= 0.0) cls = 2 + k; // brighter wins
        for (int g = 0; g < gleams; ++g)
            if (in.gleams[std::size_t(g)]->vertex_f[i] >= 0.0) cls = highlight + g; // the highest threshold met
        label[i] = cls;
    }, 256);

    // Regions: grown from a seed over edges of equal label; every vertex no
    // region reached seeds a new one (rule 3: same kinds merge). A front
    // needs room on the mesh: a region with no vertex whose whole ring
    // shares its label is thinner than the tessellation and cannot hold
    // one; when it is also a fleck of a few vertices, its vertices join the
    // label most of their neighbours outside it carry, and the regions they
    // reach are grown again. (Long thin bands along a coarse mesh are kept.)
    std::vector<std::int32_t> comp(static_cast<std::size_t>(V), -1);
    std::vector<int> comp_label;
    std::vector<std::int32_t> stack;
    // A vertex's share of the image: a third of its faces' projected areas
    // (each face meets two of the vertex's ring edges).
    auto vertex_area = [&](std::int32_t v) {
        double area = 0.0;
        for (std::int32_t i = topo.ring_start[v]; i < topo.ring_start[v + 1]; ++i)
            for (const std::int32_t f : topo.edge_faces[std::size_t(topo.ring_edge[i])]) {
                if (f == MeshTopology::kNone) continue;
                const auto& fv = topo.face_vertices[std::size_t(f)];
                const glm::dvec2 p0 = projection.project(topo.positions[std::size_t(fv[0])]);
                const glm::dvec2 p1 = projection.project(topo.positions[std::size_t(fv[1])]);
                const glm::dvec2 p2 = projection.project(topo.positions[std::size_t(fv[2])]);
                area += std::abs((p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y)) / 12.0;
            }
        return area;
    };
    comp_label.resize(std::size_t(grow_vertex_sets(
        topo, comp, [&](std::int32_t v) { return label[std::size_t(v)] >= 0; },
        [&](std::int32_t v, std::int32_t w) { return label[std::size_t(v)] == label[std::size_t(w)]; })));
    for (std::int32_t v = 0; v < V; ++v)
        if (comp[std::size_t(v)] >= 0) comp_label[std::size_t(comp[std::size_t(v)])] = label[std::size_t(v)];
    std::size_t seeds = comp_label.size();
    for (int pass = 0; pass < 3; ++pass) { // dissolving can leave a new fleck behind
        std::vector<char> supported(comp_label.size(), 0);
        std::vector<int> size(comp_label.size(), 0);
        for (const std::int32_t r : comp)
            if (r >= 0) ++size[std::size_t(r)];
        // Only the vertices of regions of few vertices can be flecks.
        std::vector<std::int32_t> small;
        for (std::int32_t v = 0; v < V; ++v) {
            const std::int32_t r = comp[std::size_t(v)];
            if (r >= 0 && size[std::size_t(r)] < in.min_unsupported_vertices) small.push_back(v);
        }
        std::vector<double> image_area(comp_label.size(), 0.0);
        for (const std::int32_t v : small) image_area[std::size_t(comp[std::size_t(v)])] += vertex_area(v);
        for (std::size_t r = 0; r < size.size(); ++r)
            supported[r] = size[r] >= in.min_unsupported_vertices || image_area[r] >= in.min_fleck_area_px;
        for (const std::int32_t v : small) {
            const std::int32_t r = comp[std::size_t(v)];
            if (supported[std::size_t(r)]) continue;
            bool interior = topo.ring_start[v + 1] > topo.ring_start[v];
            for (std::int32_t i = topo.ring_start[v]; i < topo.ring_start[v + 1] && interior; ++i)
                interior = label[std::size_t(topo.ring[i])] == label[std::size_t(v)];
            supported[std::size_t(r)] = interior;
        }
        // Each fleck vertex takes the label most of its neighbours outside
        // the fleck carry.
        std::vector<std::pair<std::int32_t, int>> moves;
        for (const std::int32_t v : small) {
            const std::int32_t r = comp[std::size_t(v)];
            if (supported[std::size_t(r)]) continue;
            int best = label[std::size_t(v)], best_count = 0;
            for (std::int32_t i = topo.ring_start[v]; i < topo.ring_start[v + 1]; ++i) {
                const std::int32_t w = topo.ring[i];
                if (comp[std::size_t(w)] == r) continue;
                const int candidate = label[std::size_t(w)];
                int count = 0;
                for (std::int32_t j = topo.ring_start[v]; j < topo.ring_start[v + 1]; ++j)
                    count += comp[std::size_t(topo.ring[j])] != r && label[std::size_t(topo.ring[j])] == candidate;
                if (count > best_count || (count == best_count && candidate > best)) best = candidate, best_count = count;
            }
            if (best != label[std::size_t(v)]) moves.emplace_back(v, best);
        }
        if (moves.empty()) break;
        {
            // The moved vertices join the regions they now touch: regions
            // grown again locally, joined where a moved vertex bridges two.
            std::vector<std::int32_t> parent(comp_label.size());
            for (std::size_t r = 0; r < parent.size(); ++r) parent[r] = std::int32_t(r);
            auto find = [&](std::int32_t r) {
                while (parent[std::size_t(r)] != r) r = parent[std::size_t(r)] = parent[std::size_t(parent[std::size_t(r)])];
                return r;
            };
            for (const auto& [v, l] : moves) {
                label[std::size_t(v)] = l;
                comp[std::size_t(v)] = -2; // to be grown
            }
            for (const auto& [v0, l0] : moves) {
                if (comp[std::size_t(v0)] != -2) continue;
                if (l0 < 0) {
                    comp[std::size_t(v0)] = -1;
                    continue;
                }
                const auto id = std::int32_t(comp_label.size());
                comp_label.push_back(l0);
                parent.push_back(id);
                comp[std::size_t(v0)] = id;
                stack.push_back(v0);
                while (!stack.empty()) {
                    const std::int32_t v = stack.back();
                    stack.pop_back();
                    for (std::int32_t i = topo.ring_start[v]; i < topo.ring_start[v + 1]; ++i) {
                        const std::int32_t w = topo.ring[i];
                        if (label[std::size_t(w)] != l0) continue;
                        if (comp[std::size_t(w)] == -2) {
                            comp[std::size_t(w)] = id;
                            stack.push_back(w);
                        } else if (comp[std::size_t(w)] >= 0) {
                            parent[std::size_t(find(comp[std::size_t(w)]))] = find(id);
                        }
                    }
                }
            }
            // Number the regions that still hold vertices.
            std::vector<std::int32_t> index(comp_label.size(), -1);
            std::vector<int> labels;
            for (std::int32_t v = 0; v < V; ++v) {
                std::int32_t& r = comp[std::size_t(v)];
                if (r < 0) continue;
                const std::int32_t root = find(r);
                if (index[std::size_t(root)] < 0) {
                    index[std::size_t(root)] = std::int32_t(labels.size());
                    labels.push_back(comp_label[std::size_t(root)]);
                }
                r = index[std::size_t(root)];
            }
            comp_label = std::move(labels);
            seeds += comp_label.size();
        }
    }
    map.stats.seeds = seeds;
    for (const int l : label) {
        if (l >= 0) ++map.stats.visible_vertices;
        if (l == kOccluded) ++map.stats.occluded_vertices;
    }

    // Where fronts stop on edges whose labels differ (rules 3 and 4).
    std::vector<std::int32_t> cut_edges;
    for (std::int32_t e = 0; e < E; ++e) {
        const int la = label[std::size_t(topo.edge_vertices[e][0])], lb = label[std::size_t(topo.edge_vertices[e][1])];
        if (la != lb) cut_edges.push_back(e); // both hidden: a junction may still use its middle
    }
    std::vector<glm::dvec3> edge_point(static_cast<std::size_t>(E));
    auto depth_of = [&](const glm::dvec3& p) {
        return camera.orthographic() ? glm::dot(p, camera.forward()) : glm::dot(p - camera.eye, camera.forward());
    };
    // Which faces are turned to the viewer (by their own winding).
    std::vector<char> front_face(topo.n_faces(), 0);
    parallel_for(topo.n_faces(), [&](std::size_t f) {
        const auto& fv = topo.face_vertices[f];
        const glm::dvec3 &p0 = topo.positions[std::size_t(fv[0])], &p1 = topo.positions[std::size_t(fv[1])],
                         &p2 = topo.positions[std::size_t(fv[2])];
        front_face[f] = glm::dot(glm::cross(p1 - p0, p2 - p0), camera.to_viewer((p0 + p1 + p2) / 3.0)) > 0.0;
    }, 4096);
    const ContourImage occluder(engine, visual, projection, depth_of);
    auto snaxel_point = [&](const ContourResult& r, std::int32_t e, int a, int b) {
        const std::int32_t s = r.fronts.edge_snaxel.empty() ? MeshTopology::kNone : r.fronts.edge_snaxel[std::size_t(e)];
        if (s != MeshTopology::kNone) return engine.position(r.fronts.snaxels[std::size_t(s)]);
        const double t = linear_root(r.vertex_f[std::size_t(a)], r.vertex_f[std::size_t(b)]);
        return glm::mix(topo.positions[std::size_t(a)], topo.positions[std::size_t(b)], t);
    };
    parallel_for(cut_edges.size(), [&](std::size_t i) {
        const std::int32_t e = cut_edges[i];
        const std::int32_t a = topo.edge_vertices[e][0], b = topo.edge_vertices[e][1];
        const int la = label[std::size_t(a)], lb = label[std::size_t(b)];
        glm::dvec3& out = edge_point[std::size_t(e)];
        if (la < 0 && lb < 0) {
            out = 0.5 * (topo.positions[std::size_t(a)] + topo.positions[std::size_t(b)]);
        } else if (la == kAway || lb == kAway) {
            out = snaxel_point(visual, e, a, b); // the visual contour (closed meshes)
        } else if ((la >= kBack) != (lb >= kBack) && la >= 0 && lb >= 0) {
            out = snaxel_point(visual, e, a, b); // the visual contour between the two sides
        } else if (la == kOccluded || lb == kOccluded) {
            // Rule 2: the visible side's front stops where the edge's image
            // meets the image of a nearer front (the occluder's visual
            // contour), so both sides of the occlusion share one curve. If
            // no such crossing shows, the ray to the viewer is bisected.
            const std::int32_t from = la < 0 ? b : a, to = la < 0 ? a : b;
            const glm::dvec3& p0 = topo.positions[std::size_t(from)];
            const glm::dvec3& p1 = topo.positions[std::size_t(to)];
            const double t = occluder.first_crossing(projection.project(p0), projection.project(p1),
                                                     [&](double s) { return depth_of(glm::mix(p0, p1, s)); });
            if (t >= 0.0) {
                out = glm::mix(p0, p1, t);
            } else {
                double lo = from == a ? 0.0 : 1.0, hi = 1.0 - lo; // lo visible, hi occluded
                const double pixels = glm::length(projection.project(p0) - projection.project(p1));
                const int steps = std::clamp(int(std::ceil(std::log2(std::max(pixels / in.tolerance_px, 1.0)))), 1,
                                             in.bisection_steps);
                for (int step = 0; step < steps; ++step) {
                    const double mid = 0.5 * (lo + hi);
                    (rays.occluded(sampler.edge_ray(e, mid)) ? hi : lo) = mid;
                }
                out = glm::mix(topo.positions[std::size_t(a)], topo.positions[std::size_t(b)], 0.5 * (lo + hi));
            }
        } else if (la >= kBack) {
            // Two classes on the far side: the root of N.L at the level between them.
            const int top = std::max(la, lb) - kBack;
            const double level = levels[std::size_t(std::max(top - 1, 0))];
            out = glm::mix(topo.positions[std::size_t(a)], topo.positions[std::size_t(b)],
                           linear_root(nl[std::size_t(a)] - level, nl[std::size_t(b)] - level));
        } else {
            // Two shading classes: the front of the brighter one's kind.
            const int top = std::max(la, lb);
            const ContourResult* kind = top >= highlight ? in.gleams[std::size_t(top - highlight)]
                                        : top >= 2       ? in.isophotes[std::size_t(top - 2)]
                                                         : in.shadow;
            out = kind ? snaxel_point(*kind, e, a, b)
                       : 0.5 * (topo.positions[std::size_t(a)] + topo.positions[std::size_t(b)]);
        }
    }, 64);

    // Each region's part of every face it touches, walked counter-clockwise
    // over corners, edge points and (where three labels meet) a junction.
    // Its steps across the face, or along a mesh boundary, are the region's
    // outline; steps along interior edges are shared with the next face.
    const std::int64_t junction_base = std::int64_t(V) + E;
    std::vector<Step> steps;
    std::vector<std::pair<std::int32_t, std::int32_t>> rim_faces; // (face, region) taken past the contour
    // Points past the contour: where N.L crosses a level on a face edge (one
    // per edge and level, shared by both faces) or across a face.
    const std::int64_t level_base = junction_base + std::int64_t(topo.n_faces());
    const std::int64_t across_base = level_base + std::int64_t(E) * std::int64_t(levels.size());
    std::unordered_map<std::int64_t, glm::dvec3> extra_point;
    std::unordered_map<std::int64_t, double> extra_nl;
    // N.L of every vertex (those turned away were not lit above).
    for (std::int32_t v = 0; v < V; ++v)
        if (label[std::size_t(v)] == kAway) nl[std::size_t(v)] = glm::dot(topo.normals[std::size_t(v)], light.to_light(topo.positions[std::size_t(v)]));
    auto class_of = [&](double value) {
        int cls = in.shadow && value < 0.0 ? 0 : 1;
        for (int k = 0; k < bands; ++k)
            if (cls != 0 && value >= levels[std::size_t(k + 1)]) cls = 2 + k;
        return cls;
    };
    std::unordered_map<int, std::int32_t> outline_regions; // class -> region of the strips past the contour
    std::vector<std::pair<std::int32_t, std::int32_t>> vertexless_faces; // (strip region, face): where the strips lie
    auto outline_region = [&](int cls) {
        const auto it = outline_regions.find(cls);
        if (it != outline_regions.end()) return it->second;
        const auto id = std::int32_t(comp_label.size());
        comp_label.push_back(cls);
        outline_regions[cls] = id;
        return id;
    };
    auto split_rim = [&](const std::vector<RimPoint>& poly, std::int32_t f, std::size_t level, double value,
                         const std::array<std::int32_t, 3>& fe) {
        std::vector<RimPoint> below, above;
        const std::size_t n = poly.size();
        for (std::size_t k = 0; k < n; ++k) {
            const RimPoint& a = poly[k];
            const RimPoint& b = poly[(k + 1) % n];
            (a.nl < value ? below : above).push_back(a);
            if ((a.nl < value) == (b.nl < value)) continue;
            RimPoint q;
            q.along = a.along;
            if (a.along >= 0) {
                // On face edge a.along: the edge's own root, the same for both faces.
                const std::int32_t e = fe[std::size_t(a.along)];
                const std::int32_t u = topo.edge_vertices[e][0], w = topo.edge_vertices[e][1];
                const double t = linear_root(nl[std::size_t(u)] - value, nl[std::size_t(w)] - value);
                q.id = level_base + std::int64_t(e) * std::int64_t(levels.size()) + std::int64_t(level);
                q.p = glm::mix(topo.positions[std::size_t(u)], topo.positions[std::size_t(w)], t);
            } else {
                const double t = std::clamp((value - a.nl) / (b.nl - a.nl), 0.0, 1.0);
                q.id = across_base + (std::int64_t(f) * std::int64_t(levels.size()) + std::int64_t(level)) * 8 + std::int64_t(k);
                q.p = glm::mix(a.p, b.p, t);
            }
            q.nl = value;
            extra_point[q.id] = q.p;
            below.push_back(q);
            above.push_back(q);
        }
        return std::make_pair(std::move(below), std::move(above));
    };
    auto point_of = [&](std::int64_t id) -> glm::dvec3 {
        if (id < V) return topo.positions[std::size_t(id)];
        if (id < junction_base) return edge_point[std::size_t(id - V)];
        if (id < std::int64_t(V) + E + std::int64_t(topo.n_faces())) {
            const auto& fe = topo.face_edges[std::size_t(id - junction_base)];
            return (edge_point[std::size_t(fe[0])] + edge_point[std::size_t(fe[1])] + edge_point[std::size_t(fe[2])]) / 3.0;
        }
        return extra_point.at(id);
    };
    // N.L at a point of a piece: at a vertex its own, on an edge
    // interpolated along it, at a junction the mean of its face's edge points'.
    auto nl_on_edge = [&](std::int32_t e) {
        const std::int32_t u = topo.edge_vertices[e][0], w = topo.edge_vertices[e][1];
        const double len = glm::length(topo.positions[std::size_t(w)] - topo.positions[std::size_t(u)]);
        const double t = len > 0.0 ? glm::length(edge_point[std::size_t(e)] - topo.positions[std::size_t(u)]) / len : 0.5;
        return glm::mix(nl[std::size_t(u)], nl[std::size_t(w)], std::clamp(t, 0.0, 1.0));
    };
    auto nl_of = [&](std::int64_t id) -> double {
        if (id < V) return nl[std::size_t(id)];
        if (id < junction_base) return nl_on_edge(std::int32_t(id - V));
        const auto& fe = topo.face_edges[std::size_t(id - junction_base)];
        return (nl_on_edge(fe[0]) + nl_on_edge(fe[1]) + nl_on_edge(fe[2])) / 3.0;
    };
    // A face turned away from the viewer that lies in a region of the
    // near side (past the contour, or at a crease where the normals are
    // averaged) is hidden, yet its image, wound the other way, would cancel
    // the faces it folds over: its pieces are walked backwards, so they add
    // nothing to their regions' images.
    std::vector<char> folded(topo.n_faces(), 0), walked(topo.n_faces(), 0);
    parallel_for(topo.n_faces(), [&](std::size_t f) {
        const auto& fv = topo.face_vertices[f];
        const auto& fe = topo.face_edges[f];
        bool near_side = false;
        for (int k = 0; k < 3; ++k) {
            const std::int32_t r = comp[std::size_t(fv[std::size_t(k)])];
            near_side = near_side || (r >= 0 && comp_label[std::size_t(r)] < kBack);
        }
        folded[f] = near_side && !front_face[f];
        // Only faces with a cut edge or a seen mesh-boundary edge, and
        // folded faces, have such steps.
        bool walk = folded[f];
        for (int k = 0; k < 3 && !walk; ++k) {
            const int la = label[std::size_t(fv[std::size_t(k)])], lb = label[std::size_t(fv[std::size_t((k + 1) % 3)])];
            walk = la != lb || (la >= 0 && topo.is_boundary_edge(fe[std::size_t(k)]));
        }
        walked[f] = walk;
    }, 4096);
    std::vector<std::int32_t> faces;
    faces.reserve(2 * cut_edges.size());
    for (std::size_t f = 0; f < topo.n_faces(); ++f)
        if (walked[f]) faces.push_back(std::int32_t(f));
    // The faces are walked in parallel, each thread into its own lists.
    struct WalkOut {
        std::vector<Step> steps;
        std::vector<std::pair<std::int32_t, std::int32_t>> rim_faces;
    };
    const std::size_t chunks = std::max<std::size_t>(1, std::thread::hardware_concurrency());
    std::vector<WalkOut> walk(chunks);
    std::mutex shared_points; // the rare crossings past the contour, and strip regions
    parallel_for(chunks, [&](std::size_t chunk) {
      auto& out_steps = walk[chunk].steps;
      auto& out_rim = walk[chunk].rim_faces;
      for (std::size_t fi = chunk * faces.size() / chunks; fi < (chunk + 1) * faces.size() / chunks; ++fi) {
        const std::int32_t f = faces[fi];
        const auto& fv = topo.face_vertices[std::size_t(f)];
        const auto& fe = topo.face_edges[std::size_t(f)];
        const int l[3] = {label[std::size_t(fv[0])], label[std::size_t(fv[1])], label[std::size_t(fv[2])]};
        if (l[0] < 0 && l[1] < 0 && l[2] < 0) continue;
        const bool uniform = l[0] == l[1] && l[1] == l[2];
        const bool rim = topo.is_boundary_edge(fe[0]) || topo.is_boundary_edge(fe[1]) || topo.is_boundary_edge(fe[2]);
        if (uniform && !rim && !folded[std::size_t(f)]) continue;
        const bool three = l[0] != l[1] && l[1] != l[2] && l[0] != l[2];
        const std::int32_t c[3] = {comp[std::size_t(fv[0])], comp[std::size_t(fv[1])], comp[std::size_t(fv[2])]};
        // The piece of the corners `picks` selects: (id, face edge it leads
        // along, or -1 across the face), counter-clockwise.
        std::int64_t ids[7];
        int along[7];
        auto piece = [&](auto&& picks) {
            int n = 0;
            for (int k = 0; k < 3; ++k) {
                const int k1 = (k + 1) % 3;
                if (picks(k)) ids[n] = fv[std::size_t(k)], along[n++] = k;
                if (l[k] != l[k1] && (picks(k) || picks(k1))) {
                    ids[n] = std::int64_t(V) + fe[std::size_t(k)];
                    along[n++] = picks(k1) ? k : -1; // toward the next corner: along edge k; else across
                    if (three && picks(k)) ids[n] = junction_base + f, along[n++] = -1;
                }
            }
            return n;
        };
        for (int owner = 0; owner < 3; ++owner) {
            const std::int32_t r = c[owner];
            if (r < 0) continue;
            bool seen = false; // each region once per face
            for (int k = 0; k < owner; ++k) seen = seen || c[k] == r;
            if (seen) continue;
            const int n = piece([&](int k) { return c[k] == r; });
            // A folded piece: walked forwards and backwards its steps across
            // the face and along the mesh's boundary cancel; its steps
            // along interior edges remain, backwards.
            const bool backwards = folded[std::size_t(f)] && comp_label[std::size_t(r)] < kBack;
            for (int i = 0; i < n; ++i) {
                const std::int64_t a = ids[i], b = ids[(i + 1) % n];
                const bool across = along[i] < 0 || (a >= V && b >= V);
                const bool outline = across || topo.is_boundary_edge(fe[std::size_t(along[i])]);
                if (backwards) {
                    if (!outline) out_steps.emplace_back(r, b, a);
                } else if (outline) {
                    out_steps.emplace_back(r, a, b);
                }
            }
        }
        // A face turned to the viewer with corners past the contour of
        // interpolated normals (turned away by their normals): the face is
        // seen whole, so its part past the contour joins the region of its
        // seen corners (the one holding most), up to the mesh's own outline
        // instead of the approximate one. The
        // part's steps cancel the region's steps across the face (and those
        // of the next such face).
        int away = 0, front = 0, most = 0;
        std::int32_t region = -1;
        for (int k = 0; k < 3; ++k) {
            if (l[k] == kAway) ++away;
            if (c[k] < 0) continue;
            ++front;
            int count = 0;
            for (int j = 0; j < 3; ++j) count += c[j] == c[k];
            if (count > most) most = count, region = c[k];
        }
        if (away == 0 || front == 0 || away + front != 3) continue; // no hidden corner
        if (away == 0 || region < 0 || !front_face[std::size_t(f)]) continue;
        {
            // Only where the face itself is seen (past a fold it may lie behind the nearer sheet).
            const glm::dvec3 centroid = (topo.positions[std::size_t(fv[0])] + topo.positions[std::size_t(fv[1])] +
                                         topo.positions[std::size_t(fv[2])]) / 3.0;
            const glm::dvec3 n = glm::normalize(glm::cross(topo.positions[std::size_t(fv[1])] - topo.positions[std::size_t(fv[0])],
                                                           topo.positions[std::size_t(fv[2])] - topo.positions[std::size_t(fv[0])]));
            if (rays.occluded(sampler.face_ray(f, centroid, n))) continue;
        }
        const int n = piece([&](int k) { return l[k] == kAway; });
        // The part past the contour keeps its region's class where the
        // shading there agrees; where N.L crosses a level inside it (a
        // straight line: N.L is linear over the face), the other side goes to
        // the outline strip of that class.
        double nls[7];
        bool one_class = true;
        for (int k = 0; k < n; ++k) {
            nls[k] = nl_of(ids[k]);
            one_class = one_class && class_of(nls[k]) == comp_label[std::size_t(region)];
        }
        if (one_class) { // the usual case: no level crosses the part
            for (int k = 0; k < n; ++k) out_steps.emplace_back(region, ids[k], ids[(k + 1) % n]);
            out_rim.emplace_back(f, region);
            continue;
        }
        const std::lock_guard<std::mutex> lock(shared_points);
        std::vector<RimPoint> part;
        for (int k = 0; k < n; ++k) part.push_back({ids[k], along[k], point_of(ids[k]), nls[k]});
        std::vector<std::vector<RimPoint>> parts{std::move(part)};
        for (std::size_t level = 0; level < levels.size(); ++level) {
            if (level == 0 && !in.shadow) continue;
            std::vector<std::vector<RimPoint>> next;
            for (const auto& poly : parts) {
                auto [below, above] = split_rim(poly, f, level, levels[level], fe);
                if (below.size() >= 3) next.push_back(std::move(below));
                if (above.size() >= 3) next.push_back(std::move(above));
            }
            parts = std::move(next);
        }
        for (const auto& poly : parts) {
            glm::dvec3 mid(0.0);
            double mid_nl = 0.0;
            for (const RimPoint& q : poly) mid += q.p, mid_nl += q.nl;
            mid_nl /= double(poly.size());
            const int cls = class_of(mid_nl);
            const std::int32_t target = cls == comp_label[std::size_t(region)] ? region : outline_region(cls);
            if (target != region) vertexless_faces.emplace_back(target, f);
            for (std::size_t k = 0; k < poly.size(); ++k) out_steps.emplace_back(target, poly[k].id, poly[(k + 1) % poly.size()].id);
        }
        out_rim.emplace_back(f, region);
      }
    }, 1);
    for (WalkOut& w : walk) {
        steps.insert(steps.end(), w.steps.begin(), w.steps.end());
        rim_faces.insert(rim_faces.end(), w.rim_faces.begin(), w.rim_faces.end());
    }
    // Past a crease the mesh's outline can lie a few faces beyond the
    // contour: seen faces turned to the viewer whose corners are all turned
    // away by their normals join the region of the face they adjoin (up to
    // three rings).
    {
        std::unordered_map<std::int32_t, std::int32_t> taken;
        for (const auto& [f, r] : rim_faces) taken[f] = r;
        std::vector<std::pair<std::int32_t, std::int32_t>> ring = rim_faces;
        for (int step = 0; step < 3 && !ring.empty(); ++step) {
            std::vector<std::pair<std::int32_t, std::int32_t>> next;
            for (const auto& [f, r] : ring)
                for (const std::int32_t e : topo.face_edges[std::size_t(f)])
                    for (const std::int32_t g : topo.edge_faces[std::size_t(e)]) {
                        if (g == MeshTopology::kNone || taken.count(g)) continue;
                        const auto& gv = topo.face_vertices[std::size_t(g)];
                        if (label[std::size_t(gv[0])] != kAway || label[std::size_t(gv[1])] != kAway ||
                            label[std::size_t(gv[2])] != kAway || !front_face[std::size_t(g)])
                            continue;
                        const glm::dvec3 &p0 = topo.positions[std::size_t(gv[0])], &p1 = topo.positions[std::size_t(gv[1])],
                                         &p2 = topo.positions[std::size_t(gv[2])];
                        if (rays.occluded(sampler.face_ray(g, (p0 + p1 + p2) / 3.0, glm::normalize(glm::cross(p1 - p0, p2 - p0)))))
                            continue;
                        taken[g] = r;
                        next.emplace_back(g, r);
                        for (int k = 0; k < 3; ++k) steps.emplace_back(r, gv[std::size_t(k)], gv[std::size_t((k + 1) % 3)]);
                    }
            ring = std::move(next);
        }
    }
    // Steps walked both ways (between two pieces of one region) cancel.
    {
        // Sorted in parallel halves, then merged.
        const auto middle = steps.begin() + std::ptrdiff_t(steps.size() / 2);
        parallel_for(2, [&](std::size_t half) {
            if (half == 0) std::sort(steps.begin(), middle);
            else std::sort(middle, steps.end());
        }, 1);
        std::inplace_merge(steps.begin(), middle, steps.end());
    }
    {
        std::vector<char> gone(steps.size(), 0);
        for (std::size_t i = 0; i < steps.size(); ++i) {
            if (gone[i]) continue;
            const Step back(steps[i].region(), steps[i].to, steps[i].from());
            auto it = std::lower_bound(steps.begin(), steps.end(), back);
            while (it != steps.end() && *it == back && gone[std::size_t(it - steps.begin())]) ++it;
            if (it != steps.end() && *it == back) gone[i] = gone[std::size_t(it - steps.begin())] = 1;
        }
        std::size_t kept = 0;
        for (std::size_t i = 0; i < steps.size(); ++i)
            if (!gone[i]) steps[kept++] = steps[i];
        steps.resize(kept);
    }

    // Chain each region's steps into loops and project them.
    std::vector<char> used(steps.size(), 0);
    std::vector<MapRegion> regions(comp_label.size());
    std::vector<double> depth_sum(comp_label.size(), 0.0);
    std::vector<std::size_t> depth_n(comp_label.size(), 0);
    for (std::int32_t v = 0; v < V; ++v) {
        const std::int32_t r = comp[std::size_t(v)];
        if (r < 0) continue;
        const glm::dvec3& p = topo.positions[std::size_t(v)];
        depth_sum[std::size_t(r)] += camera.orthographic() ? glm::dot(p, camera.forward()) : glm::length(p - camera.eye);
        ++depth_n[std::size_t(r)];
    }
    for (const auto& [r, f] : vertexless_faces) {
        const auto& fv = topo.face_vertices[std::size_t(f)];
        const glm::dvec3 p = (topo.positions[std::size_t(fv[0])] + topo.positions[std::size_t(fv[1])] + topo.positions[std::size_t(fv[2])]) / 3.0;
        depth_sum[std::size_t(r)] += camera.orthographic() ? glm::dot(p, camera.forward()) : glm::length(p - camera.eye);
        ++depth_n[std::size_t(r)];
    }
    for (std::size_t i = 0; i < steps.size(); ++i) {
        if (used[i]) continue;
        const std::int32_t r = steps[i].region();
        const std::int64_t first = steps[i].from();
        std::vector<glm::dvec2> loop;
        std::size_t at = i;
        while (true) {
            used[at] = 1;
            loop.push_back(projection.project(point_of(steps[at].from())));
            const std::int64_t to = steps[at].to;
            if (to == first) break;
            auto it = std::lower_bound(steps.begin(), steps.end(), Step(r, to, -1));
            while (it != steps.end() && it->region() == r && it->from() == to && used[std::size_t(it - steps.begin())]) ++it;
            if (it == steps.end() || it->region() != r || it->from() != to) { // an outline that does not close
                ++map.stats.open_outlines;
                break;
            }
            at = std::size_t(it - steps.begin());
        }
        if (loop.size() >= 3) regions[std::size_t(r)].polygons.push_back(std::move(loop));
    }
    // Classes, areas (signed loop areas add up: holes wind the other way)
    // and depth order.
    std::vector<std::size_t> order(regions.size());
    for (std::size_t r = 0; r < regions.size(); ++r) {
        const int cls = comp_label[r] >= kBack ? comp_label[r] - kBack : comp_label[r];
        MapRegion& region = regions[r];
        region.cls = cls == 0 ? RegionClass::Shadow : cls == 1 ? RegionClass::Lit : cls >= highlight ? RegionClass::Highlight : RegionClass::Band;
        region.k = cls >= highlight ? in.gleams[std::size_t(cls - highlight)]->spec.k
                   : cls >= 2      ? in.isophotes[std::size_t(cls - 2)]->spec.k
                                   : 0.0;
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
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return depth_sum[a] / double(std::max<std::size_t>(depth_n[a], 1)) < depth_sum[b] / double(std::max<std::size_t>(depth_n[b], 1));
    });
    std::vector<std::int32_t> rank(regions.size());
    for (std::size_t i = 0; i < order.size(); ++i) rank[order[i]] = std::int32_t(i);
    for (std::size_t r = 0; r < regions.size(); ++r) regions[r].depth = rank[r];
    map.vertex_region = std::move(comp);
    map.regions = std::move(regions);
    map.stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return map;
}

} // namespace snaxels
