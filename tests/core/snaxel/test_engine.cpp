#include <gtest/gtest.h>

#include <random>

#include "snaxels/error.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "tests/support/assets.h"
#include "tests/support/plain_mesh.h"
#include "tests/support/oracle_setup.h"

using namespace snaxels;

namespace {

glm::dvec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    glm::dvec3 v;
    do v = {n(rng), n(rng), n(rng)};
    while (glm::length(v) < 1e-6);
    return glm::normalize(v);
}

// Views alternate between orthographic and perspective; lights between
// directional and point lights.
struct ViewSetup {
    Camera camera;
    Light light;
    std::vector<ContourSpec> kinds;
};

ViewSetup random_setup(std::mt19937& rng, const MeshTopology& topo, int i) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const auto& p : topo.positions()) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = 0.5 * glm::length(hi - lo);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    ViewSetup s;
    if (i % 2 == 0) {
        s.camera.view_dir = random_unit(rng);
    } else {
        s.camera.projection = Camera::Projection::Perspective;
        s.camera.target = centre;
        s.camera.eye = centre + random_unit(rng) * radius * (2.5 + 3.0 * u(rng));
        s.camera.fov_deg = 40.0;
    }
    if (i % 4 < 2) {
        s.light.dir = random_unit(rng);
    } else {
        s.light.point = true;
        s.light.pos = centre + random_unit(rng) * radius * (1.5 + 3.0 * u(rng));
    }
    s.kinds = {ContourSpec{ContourKind::Visual, 0.0}, ContourSpec{ContourKind::Shadow, 0.0},
               ContourSpec{ContourKind::Isophote, 0.1 + 0.8 * u(rng)},
               ContourSpec{ContourKind::Gleam, 0.5 + 0.45 * u(rng)}};
    return s;
}

void expect_matches_oracle(const SnaxelEngine& engine, const MeshTopology& topo, const ContourResult& r,
                           const test::OracleSetup& setup, bool closed_mesh) {
    // Only positions and the face list go to the oracle.
    const auto oracle = test::marching_triangles(topo.positions(), test::plain_faces(topo), setup);
    ASSERT_EQ(oracle.edges, topo.n_edges());
    ASSERT_EQ(r.fronts.snaxels.size(), oracle.crossing.size());
    EXPECT_EQ(r.fronts.loops.size(), oracle.loops);
    std::size_t open = 0;
    for (const auto& loop : r.fronts.loops) open += !loop.closed;
    EXPECT_EQ(open, oracle.open_loops);
    if (closed_mesh) {
        EXPECT_EQ(open, 0u);
    }
    for (const EdgeId e : topo.edges()) {
        const auto [a, b] = topo.edge_vertices()[e];
        const std::int32_t s = r.fronts.edge_snaxel[e];
        const auto o = oracle.crossing.find({std::min(a, b).index(), std::max(a, b).index()});
        ASSERT_EQ(s >= 0, o != oracle.crossing.end()) << "edge " << e;
        if (s < 0) continue;
        const double len = glm::length(topo.positions()[a] - topo.positions()[b]);
        const double d = glm::length(engine.position(r.fronts.snaxels[s]) - o->second);
        ASSERT_LE(d, 1e-6 * len) << "edge " << e << " of " << r.spec.label();
    }
    for (const VertexId v : topo.vertices())
        ASSERT_EQ(r.regions[r.vertex_region[v]].sign > 0, r.vertex_f[v] >= 0.0) << "vertex " << v;
}

struct MeshCase {
    std::string spec;
    bool closed;
};

} // namespace

class EngineOracle : public ::testing::TestWithParam<MeshCase> {};

// Done-when 1 and 3: converged snaxels are exactly the sign changes of f over
// the edges, under 20 random views and lights and every kind, and region
// labels agree with the sign of f.
TEST_P(EngineOracle, ConvergedSnaxelsAreTheSignChangesOfF) {
    const std::string& spec = GetParam().spec;
    const LoadedMesh m = load_mesh(spec.rfind("proc:", 0) == 0 ? spec : test::asset(spec));
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    std::mt19937 rng(1234);
    EngineOptions options;
    options.check_invariants = false; // checked once below; per-iteration checks in their own test
    for (int i = 0; i < 20; ++i) {
        const ViewSetup s = random_setup(rng, topo, i);
        for (const ContourSpec& kind : s.kinds) {
            SCOPED_TRACE(spec + " view " + std::to_string(i) + " " + kind.label());
            const ContourResult r = engine.compute(kind, s.camera, s.light, options);
            VertexData<std::uint8_t> inside(topo.n_vertices());
            for (const VertexId v : topo.vertices()) inside[v] = r.vertex_f[v] >= 0.0;
            EXPECT_EQ(check_fronts(topo, r.fronts, inside), "");
            expect_matches_oracle(engine, topo, r, test::oracle_setup(kind, s.camera, s.light), GetParam().closed);
            if (HasFatalFailure()) return;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, EngineOracle,
                         ::testing::Values(MeshCase{"spot.obj", true}, MeshCase{"fandisk.obj", true},
                                           MeshCase{"horse.ply", true},
                                           MeshCase{"proc:torus:20000", true},
                                           MeshCase{"proc:sphere:20000", true},
                                           MeshCase{"proc:bumpy:40000", true},
                                           MeshCase{"proc:nose:40000", true},
                                           MeshCase{"teapot.obj", false},
                                           MeshCase{"suzanne.obj", false},
                                           MeshCase{"stanford-bunny.obj", false}),
                         [](const auto& p) { return test::test_name(p.param.spec); });

// The invariant checker runs after every sweep iteration (as in debug builds).
TEST(Engine, InvariantsHoldAfterEveryIteration) {
    for (const std::string spec : {"proc:nose:8000", "proc:torus:6000", "spot.obj", "teapot.obj",
                                   "suzanne.obj"}) {
        const LoadedMesh m = load_mesh(spec.rfind("proc:", 0) == 0 ? spec : test::asset(spec));
        const MeshTopology topo = build_topology(m.mesh);
        const SnaxelEngine engine(topo);
        std::mt19937 rng(99);
        EngineOptions options;
        options.check_invariants = true;
        for (int i = 0; i < 4; ++i) {
            const ViewSetup s = random_setup(rng, topo, i);
            for (const ContourSpec& kind : s.kinds) {
                SCOPED_TRACE(spec + " " + kind.label());
                ContourResult r;
                ASSERT_NO_THROW(r = engine.compute(kind, s.camera, s.light, options));
                EXPECT_GT(r.stats.iterations, 0u);
            }
        }
    }
}

TEST(Engine, InvariantCheckerCatchesBrokenFronts) {
    const LoadedMesh m = load_mesh("proc:sphere:2000");
    const MeshTopology topo = build_topology(m.mesh);
    const ContourResult r = SnaxelEngine(topo).compute({}, Camera{}, Light{});
    VertexData<std::uint8_t> inside(topo.n_vertices());
    for (const VertexId v : topo.vertices()) inside[v] = r.vertex_f[v] >= 0.0;
    ASSERT_EQ(check_fronts(topo, r.fronts, inside), "");
    Fronts broken = r.fronts;
    broken.snaxels[3].t = 1.5;
    EXPECT_NE(check_fronts(topo, broken, inside), "");
    broken = r.fronts;
    std::swap(broken.snaxels[0].next, broken.snaxels[7].next);
    EXPECT_NE(check_fronts(topo, broken, inside), "");
    broken = r.fronts;
    broken.snaxels.pop_back();
    EXPECT_NE(check_fronts(topo, broken, inside), "");
}

// A sphere seen orthographically: one closed visual contour, the great
// circle orthogonal to the view, and two regions (front and back).
TEST(Engine, SphereHasOneGreatCircleSilhouette) {
    const LoadedMesh m = load_mesh("proc:sphere:20000");
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    Camera cam;
    cam.view_dir = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
    const ContourResult r = engine.compute({}, cam, Light{});
    ASSERT_EQ(r.fronts.loops.size(), 1u);
    EXPECT_TRUE(r.fronts.loops[0].closed);
    EXPECT_EQ(r.regions.size(), 2u);
    for (const Snaxel& s : r.fronts.snaxels)
        EXPECT_NEAR(glm::dot(engine.position(s), cam.view_dir), 0.0, 1e-2);
}

// A torus seen along its axis: two silhouette loops (outer and inner rim)
// bounding one front-facing annulus.
TEST(Engine, TorusAlongItsAxisHasTwoLoops) {
    const LoadedMesh m = load_mesh("proc:torus:20000");
    const MeshTopology topo = build_topology(m.mesh);
    Camera cam;
    cam.view_dir = {0.0, 0.0, -1.0};
    const ContourResult r = SnaxelEngine(topo).compute({}, cam, Light{});
    EXPECT_EQ(r.fronts.loops.size(), 2u);
    int positive = 0;
    for (const Region& reg : r.regions) positive += reg.sign > 0;
    EXPECT_EQ(positive, 1);
}

TEST(ContourSpec, ParsesAndRejects) {
    EXPECT_EQ(ContourSpec::parse("visual").kind, ContourKind::Visual);
    EXPECT_EQ(ContourSpec::parse("shadow").kind, ContourKind::Shadow);
    EXPECT_DOUBLE_EQ(ContourSpec::parse("isophote:0.25").k, 0.25);
    EXPECT_EQ(ContourSpec::parse("gleam:0.9").label(), "gleam:0.9");
    EXPECT_THROW(ContourSpec::parse("gleam"), Error);
    EXPECT_THROW(ContourSpec::parse("isophote:2"), Error);
    EXPECT_THROW(ContourSpec::parse("isophote:x"), Error);
    EXPECT_THROW(ContourSpec::parse("visual:1"), Error);
    EXPECT_THROW(ContourSpec::parse("outline"), Error);
    EXPECT_EQ(ContourSpec::parse("crease").label(), "crease:30"); // the default angle
    EXPECT_DOUBLE_EQ(ContourSpec::parse("crease:45").k, 45.0);
    EXPECT_EQ(ContourSpec::parse("border").label(), "border");
    EXPECT_TRUE(ContourSpec::parse("border").on_surface());
    EXPECT_FALSE(ContourSpec::parse("visual").on_surface());
    EXPECT_THROW(ContourSpec::parse("crease:0"), Error);
    EXPECT_THROW(ContourSpec::parse("crease:180"), Error);
    EXPECT_THROW(ContourSpec::parse("crease:sharp"), Error);
    EXPECT_THROW(ContourSpec::parse("border:1"), Error);
}

// An eye or a point light exactly at a vertex leaves V or L undefined there;
// the engine must still label every vertex and keep its invariants.
TEST(Engine, EyeOrLightAtAVertex) {
    const LoadedMesh m = load_mesh("proc:sphere:2000");
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    EngineOptions options;
    options.check_invariants = true;
    Camera cam;
    cam.projection = Camera::Projection::Perspective;
    cam.eye = topo.positions()[VertexId(7)];
    cam.target = glm::dvec3(0.0);
    Light light;
    light.point = true;
    light.pos = topo.positions()[VertexId(11)];
    for (const ContourSpec& kind : {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}, ContourSpec{ContourKind::Gleam, 0.8}})
        EXPECT_NO_THROW(engine.compute(kind, cam, light, options)) << kind.label();
}
