#pragma once
// Whether a frame's visual-contour fronts are exactly the independent
// marching-triangles oracle's crossings (tests/support/marching_triangles.h):
// the same edges, as many loops, each snaxel at the oracle's point.

#include <algorithm>
#include <cmath>
#include <vector>
#include <span>
#include <string>

#include <gtest/gtest.h>

#include "snaxels/snaxel/snaxel_engine.h"
#include "tests/support/oracle_setup.h"
#include "tests/support/plain_mesh.h"

namespace snaxels::test {

/// Snaxels lie within 1e-6 of their edge's length of the oracle's point, or
/// within @p floor (edges of no length: a split sharp edge's strip). The
/// oracle computes its own area-weighted normals, or takes @p normals (a
/// mesh whose file gives its normals: the tracking is checked, not them);
/// @p edge_on: OracleSetup::edge_on.
inline ::testing::AssertionResult fronts_match_oracle(const MeshTopology& topo, const SnaxelEngine& engine,
                                                      const Fronts& fronts, const Camera& cam, const Light& light,
                                                      double floor = 0.0, std::span<const glm::dvec3> normals = {},
                                                      double edge_on = 0.0) {
    OracleSetup setup = oracle_setup({}, cam, light);
    setup.edge_on = edge_on;
    const auto faces = plain_faces(topo);
    const auto oracle = marching_triangles(topo.positions(), faces, setup, 1, normals);
    const std::vector<glm::dvec3> normal = !normals.empty() ? std::vector<glm::dvec3>(normals.begin(), normals.end())
                                                            : oracle_normals(topo.positions(), faces);
    // On an edge with an end in the edge-on band the crossing sits where the
    // band's rounding puts it: its edge is checked, not its place.
    auto in_band = [&](VertexId v) {
        return std::abs(oracle_f(setup, topo.positions()[v], normal[std::size_t(v.index())])) < 2.0 * edge_on;
    };
    if (fronts.snaxels.size() != oracle.crossing.size())
        return ::testing::AssertionFailure() << fronts.snaxels.size() << " snaxels, the oracle " << oracle.crossing.size();
    if (fronts.loops.size() != oracle.loops)
        return ::testing::AssertionFailure() << fronts.loops.size() << " loops, the oracle " << oracle.loops;
    for (const Snaxel& s : fronts.snaxels) {
        const auto o = oracle.crossing.find({std::min(s.inside, s.outside).index(), std::max(s.inside, s.outside).index()});
        if (o == oracle.crossing.end()) return ::testing::AssertionFailure() << "a snaxel on an edge the oracle does not cross";
        const double len = glm::length(topo.positions()[s.inside] - topo.positions()[s.outside]);
        if (edge_on > 0.0 && (in_band(s.inside) || in_band(s.outside))) continue;
        if (glm::length(engine.position(s) - o->second) > std::max(1e-6 * len, floor))
            return ::testing::AssertionFailure() << "a snaxel " << glm::length(engine.position(s) - o->second)
                                                 << " from the oracle's point";
    }
    return ::testing::AssertionSuccess();
}

} // namespace snaxels::test
