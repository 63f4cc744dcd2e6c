#pragma once
// A mesh's connectivity as plain integer arrays, for the tests' oracles,
// which work on index arrays of their own and share no code (nor element
// types) with the engine.

#include <array>
#include <cstdint>
#include <vector>

#include "snaxels/mesh/topology.h"

namespace snaxels::test {

inline std::vector<std::array<std::int32_t, 3>> plain_faces(const MeshTopology& topo) {
    std::vector<std::array<std::int32_t, 3>> out;
    out.reserve(topo.n_faces());
    for (const auto& f : topo.face_vertices()) out.push_back({f[0].index(), f[1].index(), f[2].index()});
    return out;
}

inline std::vector<std::array<std::int32_t, 2>> plain_edges(const MeshTopology& topo) {
    std::vector<std::array<std::int32_t, 2>> out;
    out.reserve(topo.n_edges());
    for (const auto& e : topo.edge_vertices()) out.push_back({e[0].index(), e[1].index()});
    return out;
}

} // namespace snaxels::test
