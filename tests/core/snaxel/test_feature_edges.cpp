#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include <glm/glm.hpp>

#include "snaxels/animation/still.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/feature_edges.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/style/style.h"
#include "tests/support/assets.h"
#include "tests/support/reference_raster.h"

using namespace snaxels;

namespace {

/// The drawn segments of @p result: consecutive snaxel positions along each
/// loop, each as its pair of end points (ordered), so that they compare
/// with the face list's edges whatever the vertex numbering.
using Segment = std::pair<std::array<double, 3>, std::array<double, 3>>;

std::set<Segment> drawn_segments(const SnaxelEngine& engine, const ContourResult& result) {
    std::set<Segment> out;
    const Fronts& fronts = result.fronts;
    for (const FrontLoop& loop : fronts.loops) {
        std::vector<glm::dvec3> points;
        fronts.for_each_in_loop(loop, [&](std::int32_t s) { points.push_back(engine.position(fronts.snaxels[std::size_t(s)])); });
        if (loop.closed) points.push_back(points.front());
        for (std::size_t i = 0; i + 1 < points.size(); ++i) {
            std::array<double, 3> a{points[i].x, points[i].y, points[i].z}, b{points[i + 1].x, points[i + 1].y, points[i + 1].z};
            EXPECT_TRUE(out.insert({std::min(a, b), std::max(a, b)}).second) << "a segment drawn twice";
        }
    }
    return out;
}

/// The face list's edges (the tests' own reader) that are creases over
/// @p degrees, or (degrees < 0) borders, as position pairs.
std::set<Segment> face_list_segments(const std::string& path, double degrees) {
    const ref::Mesh m = ref::read_mesh(path);
    std::map<std::pair<int, int>, std::vector<glm::dvec3>> normals_at_edge;
    for (const auto& f : m.faces) {
        const glm::dvec3 a = m.positions[std::size_t(f[0])];
        const glm::dvec3 n = glm::normalize(glm::cross(m.positions[std::size_t(f[1])] - a, m.positions[std::size_t(f[2])] - a));
        for (int k = 0; k < 3; ++k) {
            const int u = f[std::size_t(k)], w = f[std::size_t((k + 1) % 3)];
            normals_at_edge[{std::min(u, w), std::max(u, w)}].push_back(n);
        }
    }
    std::set<Segment> out;
    for (const auto& [edge, n] : normals_at_edge) {
        const bool take = degrees < 0.0 ? n.size() == 1
                                        : n.size() == 2 && std::acos(std::clamp(glm::dot(n[0], n[1]), -1.0, 1.0)) >
                                                               degrees * M_PI / 180.0;
        if (!take) continue;
        const glm::dvec3 a = m.positions[std::size_t(edge.first)], b = m.positions[std::size_t(edge.second)];
        const std::array<double, 3> pa{a.x, a.y, a.z}, pb{b.x, b.y, b.z};
        out.insert({std::min(pa, pb), std::max(pa, pb)});
    }
    return out;
}

/// Checks that @p chains hold each of @p edges once and only them, that
/// each chain is a connected walk along them, and that chains end only
/// where one or three and more of the edges meet.
void check_chains(const MeshTopology& topo, const std::vector<EdgeId>& edges, const std::vector<EdgeChain>& chains) {
    std::multiset<EdgeId> seen;
    std::map<VertexId, int> degree;
    for (const EdgeId e : edges)
        for (const VertexId v : topo.edge_vertices()[e]) ++degree[v];
    for (const EdgeChain& c : chains) {
        ASSERT_EQ(c.vertices.size(), c.edges.size() + 1);
        for (std::size_t i = 0; i < c.edges.size(); ++i) {
            seen.insert(c.edges[i]);
            const auto& ends = topo.edge_vertices()[c.edges[i]];
            const std::set<VertexId> a{ends[0], ends[1]}, b{c.vertices[i], c.vertices[i + 1]};
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
    EXPECT_EQ(seen, std::multiset<EdgeId>(edges.begin(), edges.end()));
}

} // namespace

// Fandisk, a machined part: the creases found are those an independent
// reading of the file's face list finds, at several angles.
TEST(FeatureEdges, FandiskCreasesMatchTheFaceList) {
    const std::string path = test::asset("fandisk.obj");
    const MeshTopology topo = build_topology(import_mesh(path).mesh);
    for (const double degrees : {20.0, 30.0, 45.0, 60.0}) {
        const std::size_t expected = face_list_segments(path, degrees).size();
        const std::vector<EdgeId> creases = crease_edges(topo, degrees);
        std::printf("fandisk: %zu creases over %g degrees\n", creases.size(), degrees);
        EXPECT_EQ(creases.size(), expected) << degrees << " degrees";
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
        const std::vector<EdgeId> borders = border_edges(topo);
        EXPECT_EQ(borders.size(), face_list_segments(path, -1.0).size()) << file;
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
    std::vector<EdgeId> all(topo.n_edges());
    std::iota(all.begin(), all.end(), EdgeId(0));
    const std::vector<EdgeChain> chains = chain_edges(topo, all);
    check_chains(topo, all, chains);
    EXPECT_EQ(chains.size(), all.size()); // each edge its own chain, from junction to junction
    // One vertex's ring of neighbours: a closed loop of edges that meet in twos.
    std::vector<EdgeId> ring;
    const auto around = topo.neighbours(VertexId(0));
    for (std::size_t i = 0; i < around.size(); ++i) {
        const VertexId a = around[i], b = around[(i + 1) % around.size()];
        for (const auto [w, e] : topo.ring_of(a))
            if (w == b) ring.push_back(e);
    }
    ASSERT_EQ(ring.size(), around.size());
    const std::vector<EdgeChain> loop = chain_edges(topo, ring);
    ASSERT_EQ(loop.size(), 1u);
    EXPECT_TRUE(loop[0].closed);
    check_chains(topo, ring, loop);
    // Without one edge it is one open path from end to end.
    const std::vector<EdgeId> path(ring.begin() + 1, ring.end());
    const std::vector<EdgeChain> open = chain_edges(topo, path);
    ASSERT_EQ(open.size(), 1u);
    EXPECT_FALSE(open[0].closed);
    EXPECT_EQ(open[0].edges.size(), path.size());
    check_chains(topo, path, open);
}


// Done-when 1: on fandisk every edge over the angle is drawn, and nothing
// else; on the teapot and the bunny every boundary edge is drawn. The drawn
// segments are compared, end point for end point, with the face list's.
TEST(FeatureEdges, DrawnCreasesAndBordersAreTheFaceListsEdges) {
    struct Case {
        std::string file;
        ContourSpec spec;
    };
    for (const Case& c : {Case{"fandisk.obj", {ContourKind::Crease, 30.0}}, Case{"fandisk.obj", {ContourKind::Crease, 50.0}},
                          Case{"teapot.obj", {ContourKind::Border, 0.0}}, Case{"stanford-bunny.obj", {ContourKind::Border, 0.0}}}) {
        const std::string path = test::asset(c.file);
        const MeshTopology topo = build_topology(import_mesh(path).mesh);
        const SnaxelEngine engine(topo);
        Camera camera;
        const ContourResult result = engine.compute(c.spec, camera, default_light(camera));
        const std::set<Segment> expected =
            face_list_segments(path, c.spec.kind == ContourKind::Crease ? c.spec.k : -1.0);
        EXPECT_FALSE(expected.empty());
        // The importer keeps positions in single precision: matched within a
        // millionth of the mesh's size, one to one.
        const std::set<Segment> drawn = drawn_segments(engine, result);
        EXPECT_EQ(drawn.size(), expected.size()) << c.file << " " << c.spec.label();
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const glm::dvec3& p : topo.positions()) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const double tolerance = 1e-6 * glm::length(hi - lo);
        auto close = [&](const std::array<double, 3>& a, const std::array<double, 3>& b) {
            return std::abs(a[0] - b[0]) <= tolerance && std::abs(a[1] - b[1]) <= tolerance && std::abs(a[2] - b[2]) <= tolerance;
        };
        std::vector<Segment> left(expected.begin(), expected.end());
        std::size_t unmatched = 0;
        for (const Segment& d : drawn) {
            const auto it = std::find_if(left.begin(), left.end(), [&](const Segment& e) {
                return (close(d.first, e.first) && close(d.second, e.second)) || (close(d.first, e.second) && close(d.second, e.first));
            });
            if (it == left.end()) ++unmatched;
            else left.erase(it);
        }
        EXPECT_EQ(unmatched, 0u) << c.file << " " << c.spec.label() << ": drawn segments that are no such edge";
        EXPECT_TRUE(left.empty()) << c.file << " " << c.spec.label() << ": " << left.size() << " edges not drawn";
        EXPECT_TRUE(result.vertex_f.empty()); // no vertex set: no regions
    }
}

// Creases are the mesh's: tracking keeps the same snaxels and ids frame to
// frame (only their projection and visibility change) and equals a
// computation from scratch at every frame of a turntable.
TEST(FeatureEdges, TrackedCreasesEqualFromScratchThroughATurntable) {
    const MeshTopology topo = engine_topology(import_mesh(test::asset("fandisk.obj")).mesh);
    const SnaxelEngine engine(topo);
    const ContourSpec spec{ContourKind::Crease, 30.0};
    ContourTracker tracker(topo, spec);
    std::vector<std::uint64_t> ids;
    for (int frame = 0; frame < 120; ++frame) {
        Camera camera;
        const double a = glm::radians(3.0 * frame);
        camera.view_dir = glm::dvec3(std::sin(a), -0.3, std::cos(a));
        const TrackedFrame& tf = tracker.step(camera, default_light(camera));
        const ContourResult fresh = engine.compute(spec, camera, default_light(camera));
        ASSERT_EQ(tf.contour.fronts.snaxels.size(), fresh.fronts.snaxels.size());
        for (std::size_t s = 0; s < fresh.fronts.snaxels.size(); ++s) {
            ASSERT_EQ(tf.contour.fronts.snaxels[s].edge, fresh.fronts.snaxels[s].edge);
            ASSERT_EQ(tf.contour.fronts.snaxels[s].t, fresh.fronts.snaxels[s].t);
        }
        if (frame == 0) ids = tf.snaxel_id;
        EXPECT_EQ(tf.snaxel_id, ids) << "frame " << frame;
        EXPECT_TRUE(tf.events.empty());
    }
}

// Hidden creases are classified and drawn as the style says: the
// technical-drawing preset dashes them.
TEST(FeatureEdges, HiddenCreasesAreDashedWhereTheStyleSaysSo) {
    const LoadedMesh mesh = import_mesh(test::asset("fandisk.obj"));
    const MeshTopology topo = engine_topology(mesh.mesh);
    StillJob job = make_still_job(load_style(std::string(SNAXELS_STYLES_DIR) + "/technical-drawing.xml", nullptr),
                                  Camera{}, std::nullopt);
    job.scene.camera.view_dir = glm::normalize(glm::dvec3(0.3, -0.5, 1.0));
    job.scene.light = default_light(job.scene.camera);
    const StillOutput out = render_still(mesh, topo, nullptr, job);
    std::size_t crease = 0, hidden = 0, visible = 0;
    for (std::size_t c = 0; c < out.results.size(); ++c) {
        if (out.results[c].spec.kind != ContourKind::Crease) continue;
        crease = c;
        for (const LoopVisibility& loop : out.visibility[c].loops)
            for (const VisibilityRun& run : loop.runs) (run.qi > 0 ? hidden : visible) += 1;
    }
    EXPECT_EQ(out.results[crease].spec.label(), "crease:30");
    EXPECT_GT(hidden, 0u);
    EXPECT_GT(visible, 0u);
    // The hidden creases' group is dashed, the visible one's is not.
    const auto hidden_group = out.svg.find("data-kind=\"crease\" data-label=\"crease:30\" fill=\"none\" stroke=\"#1b1b1b\" stroke-width=\"0.7\"");
    ASSERT_NE(hidden_group, std::string::npos) << "no hidden crease group";
    const std::string group = out.svg.substr(hidden_group, out.svg.find('>', hidden_group) - hidden_group);
    EXPECT_NE(group.find("stroke-dasharray=\"6 3\""), std::string::npos) << group;
}

// min-length leaves out exactly the chains shorter than that fraction of the
// mesh's diagonal: on a scanned surface (the bunny) most of its scattered
// sharp edges, on a machined part (fandisk) none of its long creases.
TEST(FeatureEdges, MinLengthLeavesOutExactlyTheShortChains) {
    for (const std::string file : {"stanford-bunny.obj", "fandisk.obj"}) {
        const MeshTopology topo = build_topology(import_mesh(test::asset(file)).mesh);
        const SnaxelEngine engine(topo);
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const glm::dvec3& p : topo.positions()) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const double limit = 0.04 * glm::length(hi - lo);
        auto lengths = [&](const ContourResult& r) {
            std::multiset<double> out;
            for (const FrontLoop& loop : r.fronts.loops) {
                std::vector<glm::dvec3> p;
                r.fronts.for_each_in_loop(loop, [&](std::int32_t s) { p.push_back(engine.position(r.fronts.snaxels[std::size_t(s)])); });
                if (loop.closed) p.push_back(p.front());
                double sum = 0.0;
                for (std::size_t i = 0; i + 1 < p.size(); ++i) sum += glm::length(p[i + 1] - p[i]);
                out.insert(sum);
            }
            return out;
        };
        Camera camera;
        ContourSpec all{ContourKind::Crease, 30.0}, long_only{ContourKind::Crease, 30.0, 0.04};
        const std::multiset<double> every = lengths(engine.compute(all, camera, default_light(camera)));
        const std::multiset<double> kept = lengths(engine.compute(long_only, camera, default_light(camera)));
        std::multiset<double> expected;
        for (const double l : every)
            if (l >= limit) expected.insert(l);
        EXPECT_EQ(kept, expected) << file;
        std::printf("%s: %zu crease chains, %zu of at least 4 per cent of the diagonal\n", file.c_str(), every.size(), kept.size());
        if (file == "fandisk.obj") EXPECT_GE(kept.size(), every.size() - 2);
        else EXPECT_LT(kept.size(), every.size() / 10);
    }
}
