#include "snaxels/snaxel/fronts.h"

#include <array>
#include <memory>

#include "snaxels/util/detail/parallel.h"

namespace snaxels {
namespace {

/// What a front crossing an edge needs of the edge's two faces, in one
/// record per edge (one cache line, where the faces' own arrays are four):
/// for the face in which the edge runs from its vertex 0 to its vertex 1
/// (side 0) and the one in which it runs back (side 1), the face's third
/// vertex, the edge after this one in the face (from the edge's end to the
/// third vertex) and the edge before it (from the third vertex to the
/// edge's start). MeshTopology::kNone on a boundary side.
struct EdgeWing {
    VertexId third;
    EdgeId after, before;
};
using EdgeWings = EdgeData<std::array<EdgeWing, 2>>;

std::shared_ptr<const EdgeWings> make_edge_wings(const MeshTopology& topo) {
    auto wings = std::make_shared<EdgeWings>(topo.n_edges());
    for (const FaceId f : topo.faces()) {
        const auto& fv = topo.face_vertices()[f];
        const auto& fe = topo.face_edges()[f];
        for (int k = 0; k < 3; ++k) {
            const EdgeId e = fe[k];
            const int side = topo.edge_vertices()[e][0] == fv[k] ? 0 : 1;
            (*wings)[e][side] = EdgeWing{fv[(k + 2) % 3], fe[(k + 1) % 3], fe[(k + 2) % 3]};
        }
    }
    return wings;
}

} // namespace

Fronts extract_fronts(const MeshTopology& topo, const VertexData<std::uint8_t>& inside) {
    std::vector<EdgeId> crossing;
    for (const EdgeId e : topo.edges()) {
        const auto [a, b] = topo.edge_vertices()[e];
        if (inside[a] != inside[b]) crossing.push_back(e);
    }
    return extract_fronts(topo, inside, crossing);
}

Fronts extract_fronts(const MeshTopology& topo, const VertexData<std::uint8_t>& inside,
                      const std::vector<EdgeId>& crossing_edges, EdgeData<std::int32_t> edge_snaxel) {
    Fronts fronts;
    fronts.edge_snaxel = std::move(edge_snaxel);
    if (fronts.edge_snaxel.size() != topo.n_edges()) fronts.edge_snaxel.assign(topo.n_edges(), kNoSnaxel);
    const std::size_t n = crossing_edges.size();
    fronts.snaxels.resize(n);
    parallel_for(n, [&](std::size_t i) {
        const EdgeId e = crossing_edges[i];
        const auto [a, b] = topo.edge_vertices()[e];
        Snaxel& s = fronts.snaxels[i];
        s.edge = e;
        s.inside = inside[a] ? a : b;
        s.outside = inside[a] ? b : a;
        fronts.edge_snaxel[e] = static_cast<std::int32_t>(i);
    }, 2048);
    // In each face the boundary enters across the edge whose halfedge runs
    // outside -> inside and leaves across the one running inside -> outside;
    // linking leave -> enter keeps R on the left of every loop. Every face
    // the front crosses is reached from its leaving snaxel, which links it:
    // a snaxel's next is set from one face and its prev from another, by
    // one iteration each, so the iterations run in parallel. (The two faces
    // of an edge run it in opposite directions, as the halfedge mesh it was
    // built from guarantees, so a snaxel leaves one and enters the other.)
    //
    // The face a snaxel leaves is the one in which its edge runs from the
    // inside vertex to the outside one; of its other two edges the front
    // enters across the one from the outside vertex to the third vertex
    // when the third is inside, else across the one from the third vertex
    // back to the inside one.
    const std::shared_ptr<const EdgeWings> wings = topo.connectivity()->quantities.require(
        Quantity<EdgeWings>{"edge wings"}, [&] { return make_edge_wings(topo); });
    parallel_for(n, [&](std::size_t i) {
        const EdgeId e = crossing_edges[i];
        const Snaxel& s = fronts.snaxels[i];
        const EdgeWing& wing = (*wings)[e][topo.edge_vertices()[e][0] == s.inside ? 0 : 1];
        if (wing.third == MeshTopology::kNone) return; // the front leaves the mesh here
        const EdgeId enter_edge = inside[wing.third] ? wing.after : wing.before;
        const std::int32_t enter = fronts.edge_snaxel[enter_edge];
        if (enter == kNoSnaxel) return; // (an incomplete edge list: check_fronts says so)
        fronts.snaxels[i].next = enter;
        fronts.snaxels[enter].prev = static_cast<std::int32_t>(i);
    }, 1024);
    // Loops: open chains from their start, then the remaining cycles.
    auto trace = [&](std::int32_t start, bool closed) {
        FrontLoop loop;
        loop.first = start;
        loop.closed = closed;
        const auto id = static_cast<std::int32_t>(fronts.loops.size());
        std::int32_t s = start;
        do {
            fronts.snaxels[s].loop = id;
            ++loop.size;
            s = fronts.snaxels[s].next;
        } while (s != kNoSnaxel && s != start);
        fronts.loops.push_back(loop);
    };
    for (std::size_t s = 0; s < fronts.snaxels.size(); ++s)
        if (fronts.snaxels[s].prev == kNoSnaxel) trace(static_cast<std::int32_t>(s), false);
    for (std::size_t s = 0; s < fronts.snaxels.size(); ++s)
        if (fronts.snaxels[s].loop == kNoSnaxel) trace(static_cast<std::int32_t>(s), true);
    return fronts;
}

void append_edge_loop(const MeshTopology& topo, std::span<const EdgeId> edges, std::span<const double> t, bool closed,
                      Fronts& fronts) {
    const auto loop = std::int32_t(fronts.loops.size()), first = std::int32_t(fronts.snaxels.size());
    const auto n = std::int32_t(edges.size());
    for (std::size_t k = 0; k < edges.size(); ++k) {
        Snaxel s;
        s.edge = edges[k];
        s.inside = topo.edge_vertices()[s.edge][0];
        s.outside = topo.edge_vertices()[s.edge][1];
        s.t = t[k];
        s.loop = loop;
        const std::int32_t at = first + std::int32_t(k), last = first + n - 1;
        s.prev = at > first ? at - 1 : closed ? last : kNoSnaxel;
        s.next = at < last ? at + 1 : closed ? first : kNoSnaxel;
        if (fronts.edge_snaxel[s.edge] == kNoSnaxel) fronts.edge_snaxel[s.edge] = at;
        fronts.snaxels.push_back(s);
    }
    fronts.loops.push_back({first, n, closed});
}

std::string check_fronts(const MeshTopology& topo, const Fronts& fronts,
                         const VertexData<std::uint8_t>& inside) {
    const auto n = static_cast<std::int32_t>(fronts.snaxels.size());
    EdgeData<std::uint8_t> edge_used(topo.n_edges(), 0);
    for (std::int32_t i = 0; i < n; ++i) {
        const Snaxel& s = fronts.snaxels[i];
        const std::string at = "snaxel " + std::to_string(i) + ": ";
        if (!s.edge.valid() || s.edge >= EdgeId(topo.n_edges())) return at + "not on a live edge";
        const auto [a, b] = topo.edge_vertices()[s.edge];
        if (!((s.inside == a && s.outside == b) || (s.inside == b && s.outside == a)))
            return at + "its ends are not its edge's vertices";
        if (!inside[s.inside] || inside[s.outside]) return at + "does not separate R from the rest";
        if (!(s.t >= 0.0 && s.t <= 1.0)) return at + "t = " + std::to_string(s.t) + " outside [0,1]";
        if (edge_used[s.edge]++) return at + "shares its edge with another snaxel";
        if (fronts.edge_snaxel[s.edge] != i) return at + "the edge lookup does not point back";
        for (const std::int32_t other : {s.next, s.prev}) {
            if (other == kNoSnaxel) {
                if (!topo.is_boundary_edge(s.edge)) return at + "loop ends on an interior edge";
                continue;
            }
            if (other < 0 || other >= n) return at + "links outside the pool";
            const auto& f1 = topo.edge_faces()[s.edge];
            const auto& f2 = topo.edge_faces()[fronts.snaxels[other].edge];
            bool common = false;
            for (const auto x : f1)
                for (const auto y : f2) common |= x != MeshTopology::kNone && x == y;
            if (!common) return at + "its loop neighbour is not on a common face";
        }
        if (s.next != kNoSnaxel && fronts.snaxels[s.next].prev != i) return at + "next/prev not symmetric";
        if (s.loop < 0 || std::size_t(s.loop) >= fronts.loops.size()) return at + "belongs to no loop";
    }
    for (const EdgeId e : topo.edges()) {
        const auto [a, b] = topo.edge_vertices()[e];
        if (inside[a] != inside[b] && !edge_used[e])
            return "edge " + std::to_string(e.index()) + " crosses the front but holds no snaxel";
    }
    std::size_t counted = 0;
    for (std::size_t l = 0; l < fronts.loops.size(); ++l) {
        const FrontLoop& loop = fronts.loops[l];
        std::int32_t s = loop.first;
        if (!loop.closed && fronts.snaxels[s].prev != kNoSnaxel) return "open loop " + std::to_string(l) + " does not start at its end";
        for (std::int32_t k = 0; k < loop.size; ++k) {
            if (s == kNoSnaxel) return "loop " + std::to_string(l) + " is shorter than its size";
            if (fronts.snaxels[s].loop != std::int32_t(l)) return "loop " + std::to_string(l) + " runs into another loop";
            s = fronts.snaxels[s].next;
        }
        if (loop.closed && s != loop.first) return "loop " + std::to_string(l) + " is not closed";
        if (!loop.closed && s != kNoSnaxel) return "open loop " + std::to_string(l) + " does not end";
        counted += std::size_t(loop.size);
    }
    if (counted != fronts.snaxels.size()) return "loops do not cover every snaxel";
    return {};
}

} // namespace snaxels
