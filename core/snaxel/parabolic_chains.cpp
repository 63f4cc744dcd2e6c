// The parabolic curves' marks chained into curves across the faces: the
// marks clustered, each cluster's longest path taken, chain ends joined,
// and the chains traced over the surface (see docs/parabolic.md).
#include "snaxels/snaxel/detail/parabolic_chains.h"

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

#include "snaxels/snaxel/detail/point_grid.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels::detail {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr NoElement kNone = MeshTopology::kNone;

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

} // namespace

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


} // namespace snaxels::detail
