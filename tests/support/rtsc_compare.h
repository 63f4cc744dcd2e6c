#pragma once
// The product's side of a comparison with the rtsc oracle
// (tests/support/rtsc_oracle.h): the engine's surface as the oracle's plain
// mesh (positions, vertex normals, faces: the same curvature preparation on
// both sides), and the product's drawn suggestive lines as segments.

#include <algorithm>
#include <vector>

#include "snaxels/mesh/topology.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/visibility/visibility.h"
#include "tests/support/rtsc_oracle.h"

namespace snaxels::test {

/// The engine's surface as rtsc would read it: a surface split along its
/// sharp edges is the patches between them, as rtsc sees a file whose
/// vertices are split there; the strips of faces without area that the
/// product adds to join them are left out.
inline RtscMesh rtsc_mesh_of(const MeshTopology& topo) {
    RtscMesh m;
    m.p.assign(topo.positions().begin(), topo.positions().end());
    m.n.assign(topo.normals().begin(), topo.normals().end());
    for (const auto& f : topo.face_vertices()) {
        const glm::dvec3 a = m.p[std::size_t(f[0].index())], b = m.p[std::size_t(f[1].index())], c = m.p[std::size_t(f[2].index())];
        const double longest = std::max({glm::dot(b - a, b - a), glm::dot(c - a, c - a), glm::dot(c - b, c - b)});
        if (!(glm::length(glm::cross(b - a, c - a)) > 1e-12 * longest)) continue;
        m.f.push_back({f[0].index(), f[1].index(), f[2].index()});
    }
    return m;
}

/// The drawn runs of a suggestive contour (margins >= 0, seen) as segments.
inline std::vector<RtscSegment> drawn_suggestive_segments(const SnaxelEngine& engine, const ContourResult& r) {
    std::vector<RtscSegment> out;
    const ContourVisibility parts = drawn_parts(engine, r);
    for (const LoopVisibility& loop : parts.loops)
        for (const VisibilityRun& run : loop.runs) {
            if (run.qi != 0) continue;
            for (std::size_t i = 0; i + 1 < run.points.size(); ++i) out.push_back({run.points[i], run.points[i + 1]});
            if (run.closed && run.points.size() > 2) out.push_back({run.points.back(), run.points.front()});
        }
    return out;
}

} // namespace snaxels::test
