#pragma once
/// Snaxels and the fronts (loops) they form. A front is the boundary of a
/// set of vertices R: every snaxel sits on an edge with one end in R (the
/// inside vertex) and one outside, at parameter t from the inside end.
/// Fronts are circular doubly linked lists over one snaxel pool; loops on
/// closed meshes are closed, loops that reach a mesh boundary are open and
/// end on boundary edges (the front stops there: it never walks off).

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "snaxels/mesh/topology.h"

namespace snaxels {

/// Snaxels are numbered by their place in Fronts::snaxels, loops by theirs
/// in Fronts::loops; this is "no snaxel" (the end of an open loop) and "no loop".
inline constexpr std::int32_t kNoSnaxel = -1;

struct Snaxel {
    EdgeId edge;
    VertexId inside;  ///< end vertex in R
    VertexId outside; ///< end vertex not in R
    double t = 0.5;   ///< 0 at inside, 1 at outside
    std::int32_t prev = kNoSnaxel, next = kNoSnaxel;
    std::int32_t loop = kNoSnaxel;
};

struct FrontLoop {
    std::int32_t first = kNoSnaxel; ///< an open loop starts at its first snaxel
    std::int32_t size = 0;
    bool closed = true;
};

struct Fronts {
    std::vector<Snaxel> snaxels;
    std::vector<FrontLoop> loops;
    EdgeData<std::int32_t> edge_snaxel; ///< the snaxel on each edge, or kNoSnaxel

    /// Calls fn(snaxel index) along a loop from its first snaxel.
    template <class Fn> void for_each_in_loop(const FrontLoop& loop, Fn&& fn) const {
        std::int32_t s = loop.first;
        for (std::int32_t k = 0; k < loop.size; ++k, s = snaxels[s].next) fn(s);
    }
};

/// The fronts bounding the vertex set @p inside (1 = in R): one snaxel per
/// edge with exactly one end in R (t = 0.5 until polished), linked face by
/// face so R lies on the left when seen from the surface's front side.
Fronts extract_fronts(const MeshTopology& topology, const VertexData<std::uint8_t>& inside);

/// The same, when the caller already knows the edges R crosses (each once):
/// costs time in proportion to the front, not to the mesh, when it also
/// hands over @p edge_snaxel, a lookup of one entry per edge, every one
/// kNoSnaxel (a tracker's from the frame before, cleared where its snaxels
/// were); given empty, one is made.
Fronts extract_fronts(const MeshTopology& topology, const VertexData<std::uint8_t>& inside,
                      const std::vector<EdgeId>& crossing_edges, EdgeData<std::int32_t> edge_snaxel = {});

/// Appends to @p fronts a loop with one snaxel per entry of @p edges, at
/// @p t[k] from the edge's first vertex (edge_vertices()[e][0], its inside
/// end), linked in order and, when @p closed, round; each edge's first
/// snaxel goes into edge_snaxel (sized to the edges). How lines of the mesh
/// that bound no vertex set (parabolic curves, creases, borders) become
/// fronts the later stages take like any contour.
void append_edge_loop(const MeshTopology& topology, std::span<const EdgeId> edges, std::span<const double> t,
                      bool closed, Fronts& fronts);

/// The invariants of a front set: each snaxel on a live edge with t in
/// [0,1] and its inside/outside ends as @p inside says, at most one snaxel
/// per edge and one on every edge R crosses, loop neighbours on a common
/// face, links symmetric, closed loops closed and open ones ending on mesh
/// boundary edges. Returns an empty string, or what is broken.
std::string check_fronts(const MeshTopology& topology, const Fronts& fronts,
                         const VertexData<std::uint8_t>& inside);

} // namespace snaxels
