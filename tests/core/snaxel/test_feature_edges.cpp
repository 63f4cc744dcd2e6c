#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include <glm/glm.hpp>

#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/feature_edges.h"
#include "snaxels/snaxel/refine.h"
#include "tests/support/assets.h"
#include "tests/support/reference_raster.h"

using namespace snaxels;

namespace {

/// The edges of a mesh file's own face list (read by the tests' reader,
/// not the importer) whose two faces' planes differ by more than @p degrees, and
/// its edges with one face.
struct ObjEdges {
    std::size_t creases = 0, borders = 0;
};

ObjEdges count_obj_edges(const std::string& path, double degrees) {
    const ref::Mesh m = ref::read_mesh(path); // the tests' own reader: welds equal positions as the importer does
    const std::vector<glm::dvec3>& v = m.positions;
    const std::vector<std::array<int, 3>>& faces = m.faces;
    std::map<std::pair<int, int>, std::vector<glm::dvec3>> normals_at_edge;
    for (const auto& f : faces) {
        const glm::dvec3 n = glm::normalize(glm::cross(v[std::size_t(f[1])] - v[std::size_t(f[0])], v[std::size_t(f[2])] - v[std::size_t(f[0])]));
        for (int k = 0; k < 3; ++k) {
            const int a = f[std::size_t(k)], b = f[std::size_t((k + 1) % 3)];
            normals_at_edge[{std::min(a, b), std::max(a, b)}].push_back(n);
        }
    }
    ObjEdges out;
    for (const auto& [edge, n] : normals_at_edge) {
        if (n.size() == 1) ++out.borders;
        if (n.size() == 2 && std::acos(std::clamp(glm::dot(n[0], n[1]), -1.0, 1.0)) > degrees * M_PI / 180.0)
            ++out.creases;
    }
    return out;
}

/// Checks that @p chains hold each of @p edges once and only them, that
/// each chain is a connected walk along them, and that chains end only
/// where one or three and more of the edges meet.
void check_chains(const MeshTopology& topo, const std::vector<std::int32_t>& edges, const std::vector<EdgeChain>& chains) {
    std::multiset<std::int32_t> seen;
    std::map<std::int32_t, int> degree;
    for (const std::int32_t e : edges)
        for (const std::int32_t v : topo.edge_vertices()[std::size_t(e)]) ++degree[v];
    for (const EdgeChain& c : chains) {
        ASSERT_EQ(c.vertices.size(), c.edges.size() + 1);
        for (std::size_t i = 0; i < c.edges.size(); ++i) {
            seen.insert(c.edges[i]);
            const auto& ends = topo.edge_vertices()[std::size_t(c.edges[i])];
            const std::set<std::int32_t> a{ends[0], ends[1]}, b{c.vertices[i], c.vertices[i + 1]};
            ASSERT_EQ(a, b) << "chain step " << i;
            if (i > 0) {
                EXPECT_EQ(degree[c.vertices[i]], 2) << "a chain passes only where two edges meet";
            }
        }
        if (c.closed) {
            EXPECT_EQ(c.vertices.front(), c.vertices.back());
        } else {
            EXPECT_NE(degree[c.vertices.front()], 2) << "an open chain ends at an end or a junction";
            EXPECT_NE(degree[c.vertices.back()], 2);
        }
    }
    EXPECT_EQ(seen, std::multiset<std::int32_t>(edges.begin(), edges.end()));
}

} // namespace

// Fandisk, a machined part: the creases found are those an independent
// reading of the file's face list finds, at several angles.
TEST(FeatureEdges, FandiskCreasesMatchTheFaceList) {
    const std::string path = test::asset("fandisk.obj");
    const MeshTopology topo = build_topology(import_mesh(path).mesh);
    for (const double degrees : {20.0, 30.0, 45.0, 60.0}) {
        const ObjEdges expected = count_obj_edges(path, degrees);
        const std::vector<std::int32_t> creases = crease_edges(topo, degrees);
        std::printf("fandisk: %zu creases over %g degrees\n", creases.size(), degrees);
        EXPECT_EQ(creases.size(), expected.creases) << degrees << " degrees";
        EXPECT_GT(creases.size(), 0u);
        check_chains(topo, creases, chain_edges(topo, creases));
    }
    EXPECT_TRUE(border_edges(topo).empty()); // a closed part
}

// The teapot and the bunny are open: every boundary edge is a border, and
// their borders chain into closed loops.
TEST(FeatureEdges, BordersOfOpenMeshes) {
    for (const std::string file : {"teapot.obj", "stanford-bunny.obj"}) {
        const std::string path = test::asset(file);
        const MeshTopology topo = build_topology(import_mesh(path).mesh);
        const std::vector<std::int32_t> borders = border_edges(topo);
        EXPECT_EQ(borders.size(), count_obj_edges(path, 180.0).borders) << file;
        ASSERT_GT(borders.size(), 0u) << file;
        const std::vector<EdgeChain> chains = chain_edges(topo, borders);
        check_chains(topo, borders, chains);
        for (const EdgeChain& c : chains) EXPECT_TRUE(c.closed) << file << ": a hole's rim is a loop";
        std::printf("%s: %zu border edges in %zu chains\n", file.c_str(), borders.size(), chains.size());
    }
}

// On the refined topology the engine uses, each crease of the coarse mesh
// is its refined edges: the same polyline, 2^levels edges for one.
TEST(FeatureEdges, RefinedCreasesAreTheCoarseOnesSplit) {
    const MeshTopology coarse = build_topology(import_mesh(test::asset("fandisk.obj")).mesh);
    const MeshTopology refined = refine_topology(coarse, 1);
    EXPECT_EQ(crease_edges(refined, 30.0).size(), 2 * crease_edges(coarse, 30.0).size());
}

// A hand-made strip of edges: a loop, a path and a junction of three.
TEST(FeatureEdges, ChainsLoopsPathsAndJunctions) {
    const MeshTopology topo = build_topology(load_mesh("proc:torus:200").mesh);
    // All the torus's edges: six meet at each vertex, junctions only.
    std::vector<std::int32_t> all(topo.n_edges());
    std::iota(all.begin(), all.end(), 0);
    const std::vector<EdgeChain> chains = chain_edges(topo, all);
    check_chains(topo, all, chains);
    EXPECT_EQ(chains.size(), all.size()); // each edge its own chain, from junction to junction
    // One vertex's ring of neighbours: a closed loop of edges that meet in twos.
    std::vector<std::int32_t> ring;
    for (std::int32_t i = topo.ring_start()[0]; i < topo.ring_start()[1]; ++i) {
        const std::int32_t a = topo.ring()[std::size_t(i)];
        const std::int32_t b = topo.ring()[std::size_t(i + 1 < topo.ring_start()[1] ? i + 1 : topo.ring_start()[0])];
        for (std::int32_t j = topo.ring_start()[std::size_t(a)]; j < topo.ring_start()[std::size_t(a) + 1]; ++j)
            if (topo.ring()[std::size_t(j)] == b) ring.push_back(topo.ring_edge()[std::size_t(j)]);
    }
    ASSERT_EQ(ring.size(), std::size_t(topo.ring_start()[1] - topo.ring_start()[0]));
    const std::vector<EdgeChain> loop = chain_edges(topo, ring);
    ASSERT_EQ(loop.size(), 1u);
    EXPECT_TRUE(loop[0].closed);
    check_chains(topo, ring, loop);
    // Without one edge it is one open path from end to end.
    const std::vector<std::int32_t> path(ring.begin() + 1, ring.end());
    const std::vector<EdgeChain> open = chain_edges(topo, path);
    ASSERT_EQ(open.size(), 1u);
    EXPECT_FALSE(open[0].closed);
    EXPECT_EQ(open[0].edges.size(), path.size());
    check_chains(topo, path, open);
}
