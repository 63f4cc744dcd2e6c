#pragma once
// The brute-force baseline the engine is timed against: marching triangles
// over every edge of the mesh with the engine's own contour function and
// topology (the same work without fronts). The tests' oracle, which shares
// nothing with the engine, is tests/support/marching_triangles.h. Every edge whose end values of f
// differ in sign (f >= 0 counts as positive) holds one crossing, the one
// nearest the positive end (a fine scan, then plain bisection); crossings are joined through the faces they share and
// counted into loops with a union-find.

#include <cstdint>
#include <numeric>
#include <vector>

#include "snaxels/snaxel/contour_function.h"
#include "snaxels/mesh/topology.h"

namespace snaxels::bench {

struct BruteForceContour {
    EdgeData<std::int32_t> crossing_of_edge; ///< index into points or -1
    std::vector<glm::dvec3> points;
    std::size_t loops = 0;
    std::size_t open_loops = 0;
};

inline BruteForceContour marching_triangles(const MeshTopology& topo, const ContourFunction& f,
                                        int scan = 256) {
    BruteForceContour out;
    VertexData<double> fv(topo.n_vertices());
    for (const VertexId v : topo.vertices()) fv[v] = f(topo.positions()[v], topo.normals()[v]);
    out.crossing_of_edge.assign(topo.n_edges(), -1);
    for (const EdgeId e : topo.edges()) {
        // Named apart (not a structured binding): clang 14's lambdas cannot capture those.
        VertexId a = topo.edge_vertices()[e][0], b = topo.edge_vertices()[e][1];
        if ((fv[a] >= 0.0) == (fv[b] >= 0.0)) continue;
        if (fv[a] < 0.0) std::swap(a, b); // a positive, b negative
        auto g = [&](double t) {
            const glm::dvec3 p = (1.0 - t) * topo.positions()[a] + t * topo.positions()[b];
            return f(p, slerp_normal(topo.normals()[a], topo.normals()[b], t));
        };
        // f may cross zero several times on an edge: take the crossing
        // nearest the positive end, found by a fine scan, then bisect.
        double lo = 0.0, hi = 1.0;
        for (int i = 1; i < scan; ++i) {
            if (g(double(i) / scan) < 0.0) {
                hi = double(i) / scan;
                break;
            }
            lo = double(i) / scan;
        }
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (lo + hi);
            if (g(mid) >= 0.0) lo = mid;
            else hi = mid;
        }
        const double t = 0.5 * (lo + hi);
        out.crossing_of_edge[e] = static_cast<std::int32_t>(out.points.size());
        out.points.push_back((1.0 - t) * topo.positions()[a] + t * topo.positions()[b]);
    }
    std::vector<std::int32_t> parent(out.points.size());
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::int32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    };
    std::vector<int> links(out.points.size(), 0);
    for (const FaceId f_ : topo.faces()) {
        std::int32_t found[3], n = 0;
        for (const auto e : topo.face_edges()[f_])
            if (out.crossing_of_edge[e] >= 0) found[n++] = out.crossing_of_edge[e];
        if (n != 2) continue; // a triangle is crossed on zero or two edges
        parent[find(found[0])] = find(found[1]);
        ++links[found[0]];
        ++links[found[1]];
    }
    std::vector<std::uint8_t> open(out.points.size(), 0);
    for (std::size_t i = 0; i < out.points.size(); ++i)
        if (links[i] < 2) open[find(static_cast<std::int32_t>(i))] = 1;
    for (std::size_t i = 0; i < out.points.size(); ++i)
        if (find(static_cast<std::int32_t>(i)) == std::int32_t(i)) {
            ++out.loops;
            out.open_loops += open[i];
        }
    return out;
}

} // namespace snaxels::bench
