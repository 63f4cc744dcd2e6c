#include "snaxels/snaxel/parabolic.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <list>
#include <mutex>
#include <queue>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>

#include <glm/glm.hpp>

#include "snaxels/util/detail/parallel.h"

namespace snaxels {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr NoElement kNone = MeshTopology::kNone;
/// "No point" among the points a PointGrid or a tree of points is built on.
constexpr std::size_t kNoPoint = ~std::size_t(0);

/// Points hashed into cubes of side @p cell, for neighbours within a cell.
class PointGrid {
  public:
    PointGrid(std::span<const glm::dvec3> points, double cell) : points_(points), cell_(cell) {
        for (std::size_t i = 0; i < points.size(); ++i) cells_[key(points[i])].push_back(i);
    }
    /// Calls fn(j) for every point within @p radius (<= cell) of @p p.
    template <class Fn> void near(const glm::dvec3& p, double radius, Fn&& fn) const {
        const glm::ivec3 c = cell_of(p);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find(pack(c + glm::ivec3(dx, dy, dz)));
                    if (it == cells_.end()) continue;
                    for (const std::size_t j : it->second)
                        if (glm::length(points_[j] - p) <= radius) fn(j);
                }
    }
    /// The point nearest @p p (kNoPoint when there are none), searching shells of
    /// cells outward until one holds a point and the next cannot hold a nearer one.
    std::size_t nearest(const glm::dvec3& p) const {
        if (points_.empty()) return kNoPoint;
        const glm::ivec3 c = cell_of(p);
        std::size_t best = kNoPoint;
        double best_d = std::numeric_limits<double>::max();
        for (int r = 0; r < 1 << 20; ++r) {
            for (int dx = -r; dx <= r; ++dx)
                for (int dy = -r; dy <= r; ++dy)
                    for (int dz = -r; dz <= r; ++dz) {
                        if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != r) continue;
                        const auto it = cells_.find(pack(c + glm::ivec3(dx, dy, dz)));
                        if (it == cells_.end()) continue;
                        for (const std::size_t j : it->second) {
                            const double d = glm::length(points_[j] - p);
                            if (d < best_d) best_d = d, best = j;
                        }
                    }
            if (best != kNoPoint && best_d <= r * cell_) break;
        }
        return best;
    }

  private:
    glm::ivec3 cell_of(const glm::dvec3& p) const { return glm::ivec3(glm::floor(p / cell_)); }
    static std::int64_t pack(const glm::ivec3& c) {
        return (std::int64_t(c.x) & 0x1fffff) | (std::int64_t(c.y) & 0x1fffff) << 21 | (std::int64_t(c.z) & 0x1fffff) << 42;
    }
    std::int64_t key(const glm::dvec3& p) const { return pack(cell_of(p)); }
    std::span<const glm::dvec3> points_;
    double cell_;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

/// The point of triangle (a, b, c) closest to @p p (Ericson, Real-Time
/// Collision Detection, 5.1.5).
glm::dvec3 closest_on_triangle(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const glm::dvec3 bp = p - b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
    const glm::dvec3 cp = p - c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denom = 1.0 / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

/// A point on the surface: where @p p projects onto the faces around the
/// vertex nearest it.
struct SurfacePoint {
    glm::dvec3 p{0.0};
    FaceId face;
};

SurfacePoint project_to_surface(const MeshTopology& topo, const PointGrid& vertices, const glm::dvec3& p) {
    SurfacePoint best;
    const std::size_t nearest = vertices.nearest(p);
    if (nearest == kNoPoint) return best;
    double best_d = std::numeric_limits<double>::max();
    topo.for_each_face_beside_edges(VertexId(nearest), [&](FaceId f) {
        const auto& fv = topo.face_vertices()[f];
        const auto P = topo.positions();
        const glm::dvec3 q = closest_on_triangle(p, P[fv[0]], P[fv[1]], P[fv[2]]);
        const double d = glm::length(q - p);
        if (d < best_d) best_d = d, best = {q, f};
    });
    return best;
}

/// Hilbert index of cell (x, y) of an n x n grid (n a power of two).
std::uint64_t hilbert_index(std::uint32_t n, std::uint32_t x, std::uint32_t y) {
    std::uint64_t d = 0;
    for (std::uint32_t s = n / 2; s > 0; s /= 2) {
        const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
        d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) x = n - 1 - x, y = n - 1 - y;
            std::swap(x, y);
        }
    }
    return d;
}

/// A vertex whose crossing of the visual contour, somewhere in a step,
/// changes the contour's topology.
struct CriticalCrossing {
    VertexId vertex;
    bool saddle = false;     ///< a split or merge (else a loop born or gone)
    glm::dvec3 dir{0.0};     ///< the view direction at which N.V passes zero there
};

/// Every vertex whose N.d changes sign on the great-circle arc from @p d0 to
/// @p d1 and which, at the direction where it is zero, is a critical point
/// of the contour's vertex signs: around it the signs of N.d change other
/// than twice (none: a loop is born or gone; four or more: loops split or
/// merge). These are exactly the places where the front set R = {N.V >= 0}
/// changes topology as the view turns. Vertices on a mesh boundary are left out.
void critical_crossings(const MeshTopology& topo, const VertexData<std::uint8_t>& boundary, const glm::dvec3& d0,
                        const glm::dvec3& d1, std::vector<CriticalCrossing>& out) {
    out.clear();
    const double omega = std::acos(std::clamp(glm::dot(d0, d1), -1.0, 1.0));
    if (omega <= 0.0) return;
    const double so = std::sin(omega), co = std::cos(omega);
    const auto N = topo.normals();
    for (const VertexId v : topo.vertices()) {
        const double a = glm::dot(N[v], d0), b = glm::dot(N[v], d1);
        if ((a >= 0.0) == (b >= 0.0) || boundary[v]) continue;
        // a sin((1-t)w) + b sin(tw) = 0 on the slerp d0 -> d1.
        const double s = a >= 0.0 ? 1.0 : -1.0;
        const double tw = std::atan2(s * a * so, s * (a * co - b));
        const glm::dvec3 dir = glm::normalize(std::sin(omega - tw) * d0 + std::sin(tw) * d1);
        const std::span<const VertexId> ring = topo.neighbours(v);
        if (ring.size() < 3) continue;
        int changes = 0;
        bool last = glm::dot(N[ring.back()], dir) >= 0.0;
        for (const VertexId w : ring) {
            const bool sign = glm::dot(N[w], dir) >= 0.0;
            changes += sign != last;
            last = sign;
        }
        if (changes != 2) out.push_back({v, changes > 2, dir});
    }
}

/// The vertices on a mesh boundary or on a split sharp edge (a corner of a
/// zero-area strip face: the normals jump there, and the contour's events
/// at them are the edge's, not the smooth surface's parabolic curves).
VertexData<std::uint8_t> boundary_vertices(const MeshTopology& topo) {
    VertexData<std::uint8_t> boundary(topo.n_vertices(), 0);
    for (const EdgeId e : topo.edges())
        if (topo.is_boundary_edge(e))
            for (const VertexId v : topo.edge_vertices()[e]) boundary[v] = 1;
    for (const FaceId f : topo.faces())
        if (topo.has_strips() && !face_has_area(topo, f))
            for (const VertexId v : topo.face_vertices()[f]) boundary[v] = 1;
    return boundary;
}

/// The longest path of a tree given as adjacency lists (weighted by length),
/// in the component of @p start.
struct TreeScratch {
    std::vector<double> dist;
    std::vector<std::size_t> parent, touched;
};

/// A tree (or forest) of points: each point's neighbours and the lengths to them.
using PointTree = std::vector<std::vector<std::pair<std::size_t, double>>>;

std::vector<std::size_t> tree_diameter(const PointTree& tree, std::size_t start, TreeScratch& scratch) {
    // Scratch space for the whole forest, reset only where a walk went:
    // the cost is the component's size, not the forest's.
    std::vector<double>& dist = scratch.dist;
    std::vector<std::size_t>& parent = scratch.parent;
    std::vector<std::size_t>& touched = scratch.touched;
    if (dist.size() != tree.size()) dist.assign(tree.size(), -1.0), parent.assign(tree.size(), kNoPoint), touched.clear();
    auto farthest = [&](std::size_t from) {
        for (const std::size_t t : touched) dist[t] = -1.0, parent[t] = kNoPoint;
        touched.clear();
        std::vector<std::size_t> stack{from};
        dist[from] = 0.0;
        touched.push_back(from);
        std::size_t far = from;
        while (!stack.empty()) {
            const std::size_t v = stack.back();
            stack.pop_back();
            if (dist[v] > dist[far]) far = v;
            for (const auto& [w, len] : tree[v])
                if (dist[w] < 0.0) {
                    dist[w] = dist[v] + len;
                    parent[w] = v;
                    touched.push_back(w);
                    stack.push_back(w);
                }
        }
        return far;
    };
    const std::size_t a = farthest(start);
    const std::size_t b = farthest(a);
    std::vector<std::size_t> path;
    for (std::size_t v = b; v != kNoPoint; v = parent[v]) path.push_back(v);
    for (const std::size_t t : touched) dist[t] = -1.0, parent[t] = kNoPoint;
    touched.clear();
    return path;
}

/// The mesh's bounding radius.
/// Traces the surface from @p a (in face a.face) to @p b (in face b.face)
/// along the plane through both that holds their mean normal: the edges it
/// crosses, in order, are appended to @p curve. False when the walk does not
/// reach b's face (a boundary, or it strays).
bool trace_between(const MeshTopology& topo, const SurfacePoint& a, const SurfacePoint& b, ParabolicCurve& curve) {
    if (a.face == b.face) return true;
    const glm::dvec3 along = b.p - a.p;
    const double len2 = glm::dot(along, along);
    if (len2 <= 0.0) return true;
    const auto P = topo.positions();
    auto face_normal = [&](FaceId f) {
        const auto& fv = topo.face_vertices()[f];
        const glm::dvec3 n = glm::cross(P[fv[1]] - P[fv[0]], P[fv[2]] - P[fv[0]]);
        const double l = glm::length(n);
        return l > 0.0 ? n / l : glm::dvec3(0.0);
    };
    glm::dvec3 m = glm::cross(along, face_normal(a.face) + face_normal(b.face));
    if (glm::length(m) <= 0.0) return false;
    m = glm::normalize(m);
    auto side = [&](VertexId v) { return glm::dot(m, P[v] - a.p); };
    FaceId face = a.face;
    EdgeId came_over;
    const int limit = 64 + int(8.0 * std::sqrt(len2) / std::max(topo.mean_edge_length(), 1e-300));
    for (int step = 0; step < limit; ++step) {
        if (face == b.face) return true;
        // The edge of this face the plane crosses going on towards b.
        EdgeId best_edge;
        double best_t = 0.0, best_ahead = -std::numeric_limits<double>::max();
        for (const EdgeId e : topo.face_edges()[face]) {
            if (e == came_over) continue;
            const auto [u, w] = topo.edge_vertices()[e];
            const double su = side(u), sw = side(w);
            if ((su >= 0.0) == (sw >= 0.0)) continue;
            const double t = su / (su - sw);
            const glm::dvec3 x = glm::mix(P[u], P[w], t);
            const double ahead = glm::dot(x - a.p, along);
            if (ahead > best_ahead) best_ahead = ahead, best_edge = e, best_t = t;
        }
        if (best_edge == kNone) return false;
        if (best_ahead > len2 * 1.5) return false; // went past b without meeting its face
        const auto [u, w] = topo.edge_vertices()[best_edge];
        const auto& ef = topo.edge_faces()[best_edge];
        const FaceId next = ef[0] == face ? ef[1] : ef[0];
        if (next == kNone) return false;
        // Going back over the edge just crossed undoes that crossing.
        if (!curve.edges.empty() && curve.edges.back() == best_edge) {
            curve.points.pop_back(), curve.edges.pop_back(), curve.t.pop_back();
            if (!curve.faces.empty()) curve.faces.pop_back();
        } else {
            if (!curve.edges.empty()) curve.faces.push_back(face);
            curve.points.push_back(glm::mix(P[u], P[w], best_t));
            curve.edges.push_back(best_edge);
            curve.t.push_back(best_t);
        }
        came_over = best_edge;
        face = next;
    }
    return false;
}

/// Passes of one-ring normal averaging that smooth over about @p scale:
/// each pass spreads a normal by about 0.65 edge lengths (variance 3/7 of
/// an edge length squared on a regular grid), at most 400 passes.
int smoothing_passes(double scale, double edge) {
    if (scale <= 0.0) return 0;
    const double r = scale / edge;
    return int(std::min(400.0, std::ceil(r * r * 7.0 / 3.0)));
}

/// @p topo with its normals smoothed by @p passes of one-ring averaging.
MeshTopology smooth_normals(const MeshTopology& topo, int passes) {
    if (passes <= 0) return topo;
    auto pose = std::make_shared<MeshPose>(*topo.pose());
    VertexData<glm::dvec3>& normals = pose->normals;
    VertexData<glm::dvec3> next(topo.n_vertices());
    for (int pass = 0; pass < passes; ++pass) {
        parallel_for(topo.vertices(), [&](VertexId v) {
            glm::dvec3 sum = normals[v];
            for (const VertexId w : topo.neighbours(v)) sum += normals[w];
            const double l = glm::length(sum);
            next[v] = l > 0.0 ? sum / l : normals[v];
        }, 4096);
        std::swap(normals, next);
    }
    return topo.posed(std::move(pose));
}

/// The chains of marks: per cluster of marks (linked within @p link), the
/// longest path of its minimum spanning tree, each point of it the mean of
/// the marks about it; the marks near a path are then taken out, and what
/// is left of a cluster gives further chains (branches), in a few rounds.
std::vector<std::vector<glm::dvec3>> mark_chains(const std::vector<ParabolicPoint>& points, double link, double spacing,
                                                 int min_members) {
    std::vector<std::vector<glm::dvec3>> chains;
    // The marked places: marks at one vertex are one place, weighed by their count.
    std::vector<glm::dvec3> where;
    std::vector<double> weight;
    {
        std::unordered_map<VertexId, std::size_t> place_of;
        for (const ParabolicPoint& p : points) {
            const auto [it, added] = place_of.emplace(p.vertex, where.size());
            if (added) where.push_back(p.where), weight.push_back(0.0);
            weight[it->second] += 1.0;
        }
    }
    // Each place's neighbours within the link, the nearest 24 of them (a
    // minimum spanning tree needs no more where places crowd).
    const PointGrid grid(where, link);
    PointTree near(where.size());
    parallel_for(where.size(), [&](std::size_t i) {
        grid.near(where[i], link, [&](std::size_t j) {
            if (j != i) near[i].push_back({j, glm::length(where[j] - where[i])});
        });
        constexpr std::size_t kMaxNear = 24;
        if (near[i].size() > kMaxNear) {
            std::nth_element(near[i].begin(), near[i].begin() + kMaxNear, near[i].end(),
                             [](const auto& a, const auto& b) { return a.second < b.second; });
            near[i].resize(kMaxNear);
        }
    }, 256);
    std::vector<std::uint8_t> used(where.size(), 0);
    std::vector<std::size_t> member(where.size(), kNoPoint); // the cluster's first point
    PointTree tree(where.size());
    TreeScratch scratch;
    for (int round = 0; round < 8; ++round) {
        bool any = false;
        std::fill(member.begin(), member.end(), kNoPoint);
        for (auto& t : tree) t.clear();
        for (std::size_t s = 0; s < where.size(); ++s) {
            if (used[s] || member[s] != kNoPoint) continue;
            // Prim's algorithm over the unused marks linked to s.
            using Item = std::tuple<double, std::size_t, std::size_t>; // length, point, from
            std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
            queue.push({0.0, s, kNoPoint});
            std::vector<std::size_t> cluster;
            double marks = 0.0;
            while (!queue.empty()) {
                const auto [len, v, from] = queue.top();
                queue.pop();
                if (member[v] != kNoPoint) continue;
                member[v] = s;
                cluster.push_back(v);
                marks += weight[v];
                if (from != kNoPoint) {
                    tree[v].push_back({from, len});
                    tree[from].push_back({v, len});
                }
                for (const auto& [w, d] : near[v])
                    if (!used[w] && member[w] == kNoPoint) queue.push({d, w, v});
            }
            if (marks < double(min_members)) {
                for (const std::size_t v : cluster) used[v] = 1;
                continue;
            }
            any = true;
            const std::vector<std::size_t> path = tree_diameter(tree, s, scratch);
            std::vector<glm::dvec3> chain;
            for (const std::size_t v : path) {
                glm::dvec3 sum = weight[v] * where[v];
                double count = weight[v];
                for (const auto& [w, d] : near[v])
                    if (!used[w] && d <= 0.5 * link) sum += weight[w] * where[w], count += weight[w];
                const glm::dvec3 p = sum / count;
                if (!chain.empty() && glm::length(p - chain.back()) < spacing) continue;
                chain.push_back(p);
            }
            for (const std::size_t v : path) {
                used[v] = 1;
                for (const auto& [w, d] : near[v])
                    if (d <= 0.5 * link) used[w] = 1;
            }
            chains.push_back(std::move(chain)); // a single place too: joining may take it up
        }
        if (!any) break;
    }
    return chains;
}

/// Joins chains whose ends face each other across a gap of at most
/// @p reach (each end's direction within 35 degrees of the gap's), nearest
/// first, and closes a chain whose two ends so face each other. Returns
/// which chains are closed.
std::vector<bool> join_chains(std::vector<std::vector<glm::dvec3>>& chains, double reach, double tangent_span) {
    // The outward direction at an end: from a point about tangent_span in.
    auto outward = [&](const std::vector<glm::dvec3>& c, bool at_back) {
        const glm::dvec3 end = at_back ? c.back() : c.front();
        glm::dvec3 in = end;
        for (std::size_t k = 1; k < c.size(); ++k) {
            in = at_back ? c[c.size() - 1 - k] : c[k];
            if (glm::length(in - end) >= tangent_span) break;
        }
        const glm::dvec3 d = end - in;
        const double l = glm::length(d);
        return l > 0.0 ? d / l : glm::dvec3(0.0);
    };
    auto length = [](const std::vector<glm::dvec3>& c) {
        double l = 0.0;
        for (std::size_t k = 1; k < c.size(); ++k) l += glm::length(c[k] - c[k - 1]);
        return l;
    };
    const double cos_max = std::cos(45.0 * kPi / 180.0);
    std::vector<bool> closed(chains.size(), false);
    for (;;) {
        // The best joinable pair of ends: (gap, chain i, i's back?, chain j, j's back?).
        double best = std::numeric_limits<double>::max();
        std::size_t bi = 0, bj = 0;
        bool bi_back = false, bj_back = false;
        for (std::size_t i = 0; i < chains.size(); ++i) {
            if (closed[i] || chains[i].empty()) continue;
            for (const bool i_back : {false, true}) {
                const glm::dvec3 ei = i_back ? chains[i].back() : chains[i].front();
                const glm::dvec3 ti = outward(chains[i], i_back);
                for (std::size_t j = i; j < chains.size(); ++j) {
                    if (closed[j] || chains[j].empty()) continue;
                    for (const bool j_back : {false, true}) {
                        if (j == i && j_back == i_back) continue;
                        if (j == i && (!i_back || length(chains[i]) < 3.0 * reach)) continue; // a chain closes once, and long enough
                        const glm::dvec3 ej = j_back ? chains[j].back() : chains[j].front();
                        const double gap = glm::length(ej - ei);
                        if (gap > reach || gap >= best) continue;
                        if (gap > 0.0) {
                            const glm::dvec3 g = (ej - ei) / gap;
                            // A single point has no direction of its own and faces every way.
                            const glm::dvec3 tj = outward(chains[j], j_back);
                            if ((chains[i].size() > 1 && glm::dot(ti, g) < cos_max) ||
                                (chains[j].size() > 1 && glm::dot(tj, -g) < cos_max))
                                continue;
                        }
                        best = gap, bi = i, bj = j, bi_back = i_back, bj_back = j_back;
                    }
                }
            }
        }
        if (best == std::numeric_limits<double>::max()) break;
        if (bi == bj) {
            closed[bi] = true;
            continue;
        }
        // i's chosen end last, then j from its chosen end.
        std::vector<glm::dvec3>& ci = chains[bi];
        std::vector<glm::dvec3>& cj = chains[bj];
        if (!bi_back) std::reverse(ci.begin(), ci.end());
        if (bj_back) std::reverse(cj.begin(), cj.end());
        ci.insert(ci.end(), cj.begin(), cj.end());
        cj.clear();
    }
    std::vector<std::vector<glm::dvec3>> kept;
    std::vector<bool> kept_closed;
    for (std::size_t i = 0; i < chains.size(); ++i)
        if (chains[i].size() > 1) kept.push_back(std::move(chains[i])), kept_closed.push_back(closed[i]);
    chains.swap(kept);
    return kept_closed;
}

/// Chains clustered marks into curves across the faces. See docs/parabolic.md.
std::vector<ParabolicCurve> chain_curves(const MeshTopology& topo, const std::vector<ParabolicPoint>& points,
                                         double link, double reach, int min_members) {
    std::vector<ParabolicCurve> curves;
    if (points.empty()) return curves;
    const double edge = std::max(topo.mean_edge_length(), 1e-300);
    std::vector<std::vector<glm::dvec3>> chains = mark_chains(points, link, 2.0 * edge, min_members);
    const std::vector<bool> closed = join_chains(chains, reach, 2.0 * link);
    const PointGrid vertices(topo.positions().values(), 2.0 * edge);
    for (std::size_t c = 0; c < chains.size(); ++c) {
        std::vector<glm::dvec3>& chain = chains[c];
        // A stub no longer than two links is a lone pair of marks, not a curve.
        double span = 0.0;
        for (std::size_t k = 1; k < chain.size(); ++k) span += glm::length(chain[k] - chain[k - 1]);
        if (!closed[c] && span < 2.0 * link) continue;
        // Two passes of neighbour averaging take out the marks' jitter.
        for (int pass = 0; pass < 2; ++pass) {
            std::vector<glm::dvec3> smooth = chain;
            const std::size_t n = chain.size();
            for (std::size_t k = 0; k < n; ++k) {
                if (!closed[c] && (k == 0 || k + 1 == n)) continue;
                smooth[k] = 0.5 * chain[k] + 0.25 * (chain[(k + n - 1) % n] + chain[(k + 1) % n]);
            }
            chain.swap(smooth);
        }
        std::vector<SurfacePoint> on;
        for (const glm::dvec3& p : chain) {
            const SurfacePoint sp = project_to_surface(topo, vertices, p);
            if (sp.face != kNone) on.push_back(sp);
        }
        if (on.size() < 2) continue;
        // Across the faces from point to point; a failed stretch ends the curve there.
        ParabolicCurve curve;
        auto flush = [&](bool is_closed) {
            if (curve.points.size() >= 2) {
                curve.closed = is_closed && curve.points.size() > 2;
                if (curve.closed) {
                    // The last segment runs in the face the first and last points share.
                    FaceId shared;
                    const auto& f0 = topo.edge_faces()[curve.edges.front()];
                    const auto& f1 = topo.edge_faces()[curve.edges.back()];
                    for (const FaceId f : f0)
                        if (f != kNone && (f == f1[0] || f == f1[1])) shared = f;
                    if (shared == kNone) curve.closed = false;
                    else curve.faces.push_back(shared);
                }
                curves.push_back(std::move(curve));
            }
            curve = ParabolicCurve{};
        };
        const std::size_t legs = closed[c] ? on.size() : on.size() - 1;
        bool whole = true;
        for (std::size_t k = 0; k < legs; ++k) {
            const std::size_t before = curve.edges.size();
            const std::size_t faces_before = curve.faces.size();
            if (!trace_between(topo, on[k], on[(k + 1) % on.size()], curve)) {
                curve.points.resize(before), curve.edges.resize(before), curve.t.resize(before);
                curve.faces.resize(faces_before);
                whole = false;
                flush(false);
            }
        }
        // A closed trace may end crossing the edge it began with.
        if (closed[c] && whole && curve.edges.size() > 2 && curve.edges.front() == curve.edges.back()) {
            curve.points.pop_back(), curve.edges.pop_back(), curve.t.pop_back();
            if (!curve.faces.empty()) curve.faces.pop_back();
        }
        flush(closed[c] && whole);
    }
    return curves;
}

} // namespace

double ParabolicCurve::length() const {
    double l = 0.0;
    for (std::size_t k = 1; k < points.size(); ++k) l += glm::length(points[k] - points[k - 1]);
    if (closed && points.size() > 2) l += glm::length(points.front() - points.back());
    return l;
}

std::vector<glm::dvec3> parabolic_directions(int samples, int order) {
    samples = std::max(samples, 24);
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    // Order k > 0 follows the Hilbert curve of the map turned by k radians
    // about an oblique axis: another path through the same neighbours.
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -0.5, 0.81));
    const double angle = double(order), ca = std::cos(angle), sa = std::sin(angle);
    auto turn = [&](const glm::dvec3& v) { // Rodrigues' rotation
        return v * ca + glm::cross(axis, v) * sa + axis * glm::dot(axis, v) * (1.0 - ca);
    };
    constexpr std::uint32_t kGrid = 1u << 12;
    std::vector<std::pair<std::uint64_t, glm::dvec3>> keyed;
    for (int i = 0; i < samples; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / samples, r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const glm::dvec3 d(r * std::cos(golden * i), r * std::sin(golden * i), z);
        // Octahedral map of the sphere onto [-1, 1]^2, the lower half folded out.
        const glm::dvec3 t = turn(d);
        const glm::dvec3 o = t / (std::abs(t.x) + std::abs(t.y) + std::abs(t.z));
        glm::dvec2 uv(o.x, o.y);
        if (o.z < 0.0)
            uv = glm::dvec2((1.0 - std::abs(o.y)) * (o.x >= 0.0 ? 1.0 : -1.0), (1.0 - std::abs(o.x)) * (o.y >= 0.0 ? 1.0 : -1.0));
        auto cell = [&](double c) { return std::uint32_t(std::clamp((c + 1.0) * 0.5 * kGrid, 0.0, double(kGrid - 1))); };
        keyed.push_back({hilbert_index(kGrid, cell(uv.x), cell(uv.y)), d});
    }
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<glm::dvec3> dirs;
    for (const auto& [key, d] : keyed) dirs.push_back(d);
    return dirs;
}

std::vector<std::vector<glm::dvec3>> parabolic_walks(int samples, int orders) {
    std::vector<std::vector<glm::dvec3>> out;
    for (int order = 0; order < std::max(orders, 1); ++order) {
        const std::vector<glm::dvec3> dirs = parabolic_directions(samples, order);
        // About sqrt(N)/4 walks per order: enough to keep every core busy,
        // few enough that the fresh start of each (a full contour search) costs little.
        const std::size_t walks = std::clamp<std::size_t>(std::size_t(std::lround(std::sqrt(double(dirs.size())) / 4.0)), 1,
                                                          dirs.size() / 8 + 1);
        for (std::size_t w = 0; w < walks; ++w) {
            const std::size_t begin = dirs.size() * w / walks, end = std::min(dirs.size(), dirs.size() * (w + 1) / walks + 1);
            out.emplace_back(dirs.begin() + std::ptrdiff_t(begin), dirs.begin() + std::ptrdiff_t(end));
        }
    }
    return out;
}

namespace {

/// Marks where the visual events @p events of one step of a walk (the view
/// from @p from to @p to) happened, into @p found: each at the nearest
/// topology-changing crossing of the step (@p crossings) within
/// @p place_limit, one of the event's own type first, each vertex once a
/// step. Returns how many events found no crossing near enough.
std::size_t place_events(const MeshTopology& topo, const std::vector<VisualEvent>& events,
                         const std::vector<CriticalCrossing>& crossings, const glm::dvec3& from, const glm::dvec3& to,
                         double place_limit, std::vector<ParabolicPoint>& found) {
    std::size_t unplaced = 0;
    std::vector<VertexId> marked; // vertices marked in this step
    for (const VisualEvent& e : events) {
        const bool saddle = e.kind == EventKind::Split || e.kind == EventKind::Merge;
        const CriticalCrossing* best = nullptr;
        double best_d = std::numeric_limits<double>::max();
        for (int pass = 0; pass < 2 && !best; ++pass) // a crossing of the event's type first
            for (const CriticalCrossing& c : crossings) {
                if (pass == 0 && c.saddle != saddle) continue;
                const double d = glm::length(topo.positions()[c.vertex] - e.where);
                if (d < best_d && d <= place_limit) best_d = d, best = &c;
            }
        if (!best) {
            ++unplaced;
            continue;
        }
        if (std::find(marked.begin(), marked.end(), best->vertex) != marked.end()) continue;
        marked.push_back(best->vertex);
        ParabolicPoint p;
        p.kind = e.kind;
        p.vertex = best->vertex;
        p.where = topo.positions()[best->vertex];
        p.dir = best->dir;
        p.from_dir = from;
        p.to_dir = to;
        found.push_back(p);
    }
    return unplaced;
}

} // namespace

ParabolicResult find_parabolic(const MeshTopology& mesh_topo, const ParabolicOptions& options) {
    const auto t0 = std::chrono::steady_clock::now();
    // The normals the contour is tracked with, smoothed at the asked scale
    // (mesh noise makes visual events everywhere; docs/parabolic.md).
    const double radius = bounding_radius(mesh_topo);
    const double edge = std::max(mesh_topo.mean_edge_length(), 1e-300);
    const int passes = smoothing_passes(options.smoothing * radius, edge);
    const MeshTopology topo = smooth_normals(mesh_topo, passes);
    ParabolicResult result;
    const std::vector<std::vector<glm::dvec3>> walks = parabolic_walks(options.samples, options.orders);
    result.walks = int(walks.size());
    result.samples = int(parabolic_directions(options.samples, 0).size());
    result.smoothing_passes = passes;
    const VertexData<std::uint8_t> boundary = boundary_vertices(topo);
    // An event farther than this from every topology-changing crossing of its
    // step is left unplaced: the contour moved that far in one step only on
    // a mesh too coarse for the sampling.
    const double place_limit = std::max(8.0 * edge, 0.1 * radius);

    std::vector<std::vector<ParabolicPoint>> found(walks.size());
    std::vector<std::size_t> events(walks.size(), 0), unplaced(walks.size(), 0);
    int total_steps = 0;
    for (const auto& w : walks) total_steps += int(w.size()) - 1;
    std::atomic<int> done{0};
    std::atomic<bool> stop{false};
    std::mutex progress_mutex;
    parallel_for(
        walks.size(),
        [&](std::size_t i) {
            const std::vector<glm::dvec3>& walk = walks[i];
            ContourTracker tracker(topo, ContourSpec{});
            std::vector<CriticalCrossing> crossings;
            for (std::size_t k = 0; k < walk.size(); ++k) {
                if (stop || (options.cancelled && options.cancelled())) {
                    stop = true;
                    return;
                }
                Camera camera;
                camera.view_dir = walk[k];
                camera.up = std::abs(walk[k].z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
                const TrackedFrame& frame = tracker.step(camera, default_light(camera));
                if (k == 0 || frame.events.empty()) continue;
                events[i] += frame.events.size();
                critical_crossings(topo, boundary, walk[k - 1], walk[k], crossings);
                unplaced[i] += place_events(topo, frame.events, crossings, walk[k - 1], walk[k], place_limit, found[i]);
            }
            const int now = done += int(walk.size()) - 1;
            if (options.progress) {
                const std::lock_guard<std::mutex> lock(progress_mutex);
                options.progress(std::min(now, total_steps), total_steps);
            }
        },
        1);
    if (stop) throw ParabolicCancelled();
    for (std::size_t i = 0; i < walks.size(); ++i) {
        result.points.insert(result.points.end(), found[i].begin(), found[i].end());
        result.events += events[i];
        result.unplaced += unplaced[i];
    }

    // Faces and confidence: marks from other view transitions nearby.
    std::vector<glm::dvec3> where;
    for (const ParabolicPoint& p : result.points) where.push_back(p.where);
    const PointGrid grid(where, 2.0 * edge);
    parallel_for(where.size(), [&](std::size_t i) {
        ParabolicPoint& p = result.points[i];
        topo.for_each_face_beside_edges(p.vertex, [&](FaceId f) {
            if (p.face == kNone) p.face = f;
        });
        p.confidence = 0;
        grid.near(p.where, 2.0 * edge, [&](std::size_t) { ++p.confidence; });
    }, 256);

    // Marks along a parabolic curve lie where walks crossed the curve's
    // asymptotic directions on the view sphere, about pi^2 / L apart in
    // direction for a walked length L; link marks a few such gaps apart.
    double walked = 0.0;
    for (const auto& walk : walks)
        for (std::size_t k = 1; k < walk.size(); ++k) walked += std::acos(std::clamp(glm::dot(walk[k - 1], walk[k]), -1.0, 1.0));
    const double gap = kPi * kPi / std::max(walked, 1e-9);
    const double link = std::max(4.0 * edge, 1.5 * gap * radius);
    result.curves = chain_curves(topo, result.points, link, 6.0 * link, 2);
    result.mesh_edges = topo.n_edges();
    result.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

namespace {

/// The options that change a search's result, as a key.
Quantity<ParabolicResult> parabolic_key(const ParabolicOptions& options) {
    char key[96];
    std::snprintf(key, sizeof key, "parabolic samples=%d orders=%d smoothing=%.17g", options.samples, options.orders,
                  options.smoothing);
    return {key};
}

/// A hash of @p topology's positions and faces.
std::uint64_t content_hash(const MeshTopology& topo) {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a
    auto mix = [&](const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
    };
    mix(topo.positions().data(), topo.positions().size() * sizeof(glm::dvec3));
    mix(topo.face_vertices().data(), topo.face_vertices().size() * sizeof(std::array<VertexId, 3>));
    return h;
}

/// The few searches most recently done in the process, newest first.
struct ProcessCache {
    std::mutex mutex;
    std::list<std::pair<std::pair<std::uint64_t, std::string>, std::shared_ptr<const ParabolicResult>>> entries;
    static constexpr std::size_t kCapacity = 4;
};
ProcessCache& process_cache() {
    static ProcessCache cache;
    return cache;
}

} // namespace

std::shared_ptr<const ParabolicResult> require_parabolic(const MeshTopology& topo, const ParabolicOptions& options) {
    const Quantity<ParabolicResult> key = parabolic_key(options);
    if (auto kept = topo.pose()->quantities.find(key)) return kept;
    const std::pair<std::uint64_t, std::string> content{content_hash(topo), key.name};
    ProcessCache& cache = process_cache();
    std::shared_ptr<const ParabolicResult> result;
    {
        const std::lock_guard<std::mutex> lock(cache.mutex);
        for (auto it = cache.entries.begin(); it != cache.entries.end(); ++it)
            if (it->first == content) {
                cache.entries.splice(cache.entries.begin(), cache.entries, it);
                result = cache.entries.front().second;
                break;
            }
    }
    if (!result) {
        result = std::make_shared<const ParabolicResult>(find_parabolic(topo, options));
        const std::lock_guard<std::mutex> lock(cache.mutex);
        cache.entries.push_front({content, result});
        while (cache.entries.size() > ProcessCache::kCapacity) cache.entries.pop_back();
    }
    return topo.pose()->quantities.keep(key, std::move(result), PoseQuantities::Lifetime::CarriedToLaterPoses);
}

void keep_parabolic(const MeshTopology& topo, const ParabolicOptions& options, std::shared_ptr<const ParabolicResult> result) {
    if (result) topo.pose()->quantities.keep(parabolic_key(options), std::move(result), PoseQuantities::Lifetime::CarriedToLaterPoses);
}

Fronts parabolic_fronts(const MeshTopology& topo, const ParabolicResult& result) {
    Fronts fronts;
    fronts.edge_snaxel.assign(topo.n_edges(), kNoSnaxel);
    for (const ParabolicCurve& curve : result.curves)
        if (curve.points.size() >= 2) append_edge_loop(topo, curve.edges, curve.t, curve.closed, fronts);
    return fronts;
}

} // namespace snaxels
