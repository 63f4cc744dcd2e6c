#pragma once
/// Snaxels and the fronts (loops) they form. A front is the boundary of a
/// set of vertices R: every snaxel sits on an edge with one end in R (the
/// inside vertex) and one outside, at parameter t from the inside end.
/// Fronts are circular doubly linked lists over one snaxel pool; loops on
/// closed meshes are closed, loops that reach a mesh boundary are open and
/// end on boundary edges (the front stops there: it never walks off).

#include <cstdint>
#include <string>
#include <vector>

#include "snaxels/mesh/topology.h"

namespace snaxels {

struct Snaxel {
    std::int32_t edge = MeshTopology::kNone;
    std::int32_t inside = MeshTopology::kNone;  ///< end vertex in R
    std::int32_t outside = MeshTopology::kNone; ///< end vertex not in R
    double t = 0.5;                              ///< 0 at inside, 1 at outside
    std::int32_t prev = MeshTopology::kNone, next = MeshTopology::kNone;
    std::int32_t loop = MeshTopology::kNone;
};

struct FrontLoop {
    std::int32_t first = MeshTopology::kNone; ///< an open loop starts at its first snaxel
    std::int32_t size = 0;
    bool closed = true;
};

struct Fronts {
    std::vector<Snaxel> snaxels;
    std::vector<FrontLoop> loops;
    std::vector<std::int32_t> edge_snaxel; ///< #E: the snaxel on each edge, or kNone

    /// Calls fn(snaxel index) along a loop from its first snaxel.
    template <class Fn> void for_each_in_loop(const FrontLoop& loop, Fn&& fn) const {
        std::int32_t s = loop.first;
        for (std::int32_t k = 0; k < loop.size; ++k, s = snaxels[s].next) fn(s);
    }
};

/// The fronts bounding the vertex set @p inside (1 = in R): one snaxel per
/// edge with exactly one end in R (t = 0.5 until polished), linked face by
/// face so R lies on the left when seen from the surface's front side.
Fronts extract_fronts(const MeshTopology& topology, const std::vector<std::uint8_t>& inside);

/// The same, when the caller already knows the edges R crosses (each once):
/// costs time in proportion to the front, not to the mesh.
Fronts extract_fronts(const MeshTopology& topology, const std::vector<std::uint8_t>& inside,
                      const std::vector<std::int32_t>& crossing_edges);

/// The invariants of a front set: each snaxel on a live edge with t in
/// [0,1] and its inside/outside ends as @p inside says, at most one snaxel
/// per edge and one on every edge R crosses, loop neighbours on a common
/// face, links symmetric, closed loops closed and open ones ending on mesh
/// boundary edges. Returns an empty string, or what is broken.
std::string check_fronts(const MeshTopology& topology, const Fronts& fronts,
                         const std::vector<std::uint8_t>& inside);

} // namespace snaxels
