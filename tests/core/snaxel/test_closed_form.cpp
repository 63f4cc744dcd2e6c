// The four contour kinds on a finely tessellated unit sphere, checked from
// the paper's formulas as the tests' oracle writes them out
// (tests/support/marching_triangles.h; V toward the eye, L toward the
// light, R = 2(N.L)N - L):
//   visual   N.V = 0
//   shadow   min(N.L, N.V) = 0        (the light's terminator: the circle N.L = 0)
//   isophote min(N.L - k, N.V) = 0    (the circle of centre kL and radius sqrt(1 - k^2))
//   gleam    min(V.R - k, N.V) = 0
// Twice: with the mesh's normals as the design defines them (area-weighted
// face normals at the vertices, slerped along edges), computed by the oracle, every
// snaxel is a root and every edge whose ends differ in sign holds exactly
// one snaxel, none other does; with the sphere's exact normals p / |p| the
// snaxels lie on the closed-form curves within the tessellation's error.
// Nothing here calls the engine's contour functions, normals or topology:
// edges and normals come from the face list and the vertex positions.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "tests/support/oracle_setup.h"
#include "tests/support/plain_mesh.h"

using namespace snaxels;


TEST(ClosedForm, SphereContoursFollowThePapersFormulas) {
    const LoadedMesh mesh = load_mesh("proc:sphere:80000");
    const MeshTopology topo = build_topology(mesh.mesh);
    // The sphere is the unit sphere about the origin.
    for (const glm::dvec3& p : topo.positions()) ASSERT_NEAR(glm::length(p), 1.0, 1e-9);
    // Edges from the face list: vertex pair -> number of snaxels found on it.
    std::map<std::pair<std::int32_t, std::int32_t>, int> edges;
    const auto faces = test::plain_faces(topo);
    for (const auto& f : faces)
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = f[std::size_t(k)], b = f[std::size_t((k + 1) % 3)];
            edges[{std::min(a, b), std::max(a, b)}] = 0;
        }
    // Vertex normals: area-weighted face normals (the design's definition).
    // Vertex normals: area-weighted face normals (the design's definition),
    // computed by the tests' oracle (tests/support/marching_triangles.h).
    const std::vector<glm::dvec3> normal = test::oracle_normals(topo.positions(), faces);
    const SnaxelEngine engine(topo);
    std::mt19937 rng(5);
    std::normal_distribution<double> nd;
    auto unit = [&] {
        glm::dvec3 v;
        do v = {nd(rng), nd(rng), nd(rng)};
        while (glm::length(v) < 1e-3);
        return glm::normalize(v);
    };
    const double root = 1e-5;      // |f| at a snaxel with the mesh's normals (polished to 1e-6 in t)
    const double on_curve = 1e-2;  // |f| at a snaxel with the sphere's exact normals (tessellation error)
    int checked_kinds = 0;
    for (int view = 0; view < 6; ++view) {
        Camera cam;
        cam.view_dir = unit();
        Light light;
        light.dir = unit();
        const glm::dvec3 V = -glm::normalize(cam.view_dir), L = glm::normalize(light.dir);
        for (const ContourSpec& spec : {ContourSpec{ContourKind::Visual, 0.0}, ContourSpec{ContourKind::Shadow, 0.0},
                                       ContourSpec{ContourKind::Isophote, 0.5}, ContourSpec{ContourKind::Isophote, -0.3},
                                       ContourSpec{ContourKind::Gleam, 0.9}, ContourSpec{ContourKind::Gleam, 0.6}}) {
            const test::OracleSetup setup = test::oracle_setup(spec, cam, light);
            // Orthographic view and directional light: f depends on the normal alone.
            auto f = [&](const glm::dvec3& n) { return test::oracle_f(setup, glm::dvec3(0.0), n); };
            const ContourResult r = engine.compute(spec, cam, light);
            for (auto& [e, count] : edges) count = 0;
            double worst_root = 0.0, worst_exact = 0.0, worst_circle = 0.0;
            for (const FrontLoop& loop : r.fronts.loops)
                r.fronts.for_each_in_loop(loop, [&](std::int32_t s) {
                    const Snaxel& sn = r.fronts.snaxels[std::size_t(s)];
                    const std::int32_t a = sn.inside.index(), b = sn.outside.index(); // as the oracle numbers them
                    worst_root = std::max(worst_root, std::abs(f(test::oracle_slerp(normal[std::size_t(a)], normal[std::size_t(b)], sn.t))));
                    const glm::dvec3 n = glm::normalize((1.0 - sn.t) * topo.positions()[sn.inside] + sn.t * topo.positions()[sn.outside]);
                    worst_exact = std::max(worst_exact, std::abs(f(n)));
                    // Where the curve is the light's circle (not the outline), as a circle.
                    if ((spec.kind == ContourKind::Shadow || spec.kind == ContourKind::Isophote) && glm::dot(n, V) > on_curve)
                        worst_circle = std::max(worst_circle, std::abs(glm::length(n - spec.k * L) - std::sqrt(1.0 - spec.k * spec.k)));
                    ++edges[{std::min(a, b), std::max(a, b)}];
                });
            EXPECT_LE(worst_root, root) << spec.label() << " view " << view;
            EXPECT_LE(worst_exact, on_curve) << spec.label() << " view " << view;
            EXPECT_LE(worst_circle, on_curve) << spec.label() << " view " << view;
            std::size_t missing = 0, extra = 0, crossings = 0;
            for (const auto& [e, count] : edges) {
                const bool ia = f(normal[std::size_t(e.first)]) >= 0.0, ib = f(normal[std::size_t(e.second)]) >= 0.0;
                crossings += ia != ib;
                missing += ia != ib && count != 1;
                extra += ia == ib && count != 0;
            }
            EXPECT_EQ(missing, 0u) << spec.label() << " view " << view << " (" << crossings << " crossings)";
            EXPECT_EQ(extra, 0u) << spec.label() << " view " << view;
            if (crossings > 0) ++checked_kinds;
        }
    }
    EXPECT_GE(checked_kinds, 30); // most kinds in most views have a curve to check
}

// The first zero along a slerped edge, which the engine solves in closed form
// for an orthographic view and a directional light (sinusoids in the arc
// angle), against a fine scan of the oracle's f on the oracle's slerp,
// bisected: the crossing nearest the inside end, also where f dips below
// zero and comes back before the outside end, and on arcs up to 175 degrees.
TEST(ClosedForm, FirstZeroOnAnEdgeIsTheScannedFirstCrossing) {
    std::mt19937 rng(11);
    std::normal_distribution<double> nd;
    std::uniform_real_distribution<double> ud(0.0, 1.0);
    auto unit = [&] {
        glm::dvec3 v;
        do v = {nd(rng), nd(rng), nd(rng)};
        while (glm::length(v) < 1e-3);
        return glm::normalize(v);
    };
    int checked = 0, dips = 0;
    for (int trial = 0; trial < 12000; ++trial) {
        Camera cam;
        cam.view_dir = unit();
        Light light;
        light.dir = unit();
        const double k = 2.0 * ud(rng) - 1.0;
        const ContourSpec spec = trial % 4 == 0 ? ContourSpec{ContourKind::Visual, 0.0}
                                 : trial % 4 == 1 ? ContourSpec{ContourKind::Shadow, 0.0}
                                 : trial % 4 == 2 ? ContourSpec{ContourKind::Isophote, k}
                                                  : ContourSpec{ContourKind::Gleam, k};
        const test::OracleSetup setup = test::oracle_setup(spec, cam, light);
        const glm::dvec3 na = unit();
        // An arc of a random angle (up to 175 degrees) toward a random direction.
        const double angle = glm::radians(175.0) * std::pow(ud(rng), 2.0);
        const glm::dvec3 side = glm::normalize(glm::cross(na, unit()));
        const glm::dvec3 nb = std::cos(angle) * na + std::sin(angle) * side;
        auto g = [&](double t) { return test::oracle_f(setup, glm::dvec3(0.0), test::oracle_slerp(na, nb, t)); };
        const double fa = g(0.0), fb = g(1.0);
        if (!(fa >= 0.0 && fb < 0.0)) continue;
        const int n = 20000;
        double t0 = 0.0, t1 = 1.0;
        int sign_changes = 0;
        bool found = false, before = true;
        for (int i = 1; i <= n; ++i) {
            const double t = double(i) / n;
            const bool now = g(t) >= 0.0;
            sign_changes += now != before;
            before = now;
            if (!now && !found) {
                t1 = t;
                t0 = double(i - 1) / n;
                found = true;
            }
        }
        for (int it = 0; it < 60; ++it) {
            const double m = 0.5 * (t0 + t1);
            (g(m) >= 0.0 ? t0 : t1) = m;
        }
        const ContourFunction f(spec, cam, light);
        ASSERT_TRUE(f.closed_form());
        const double t = f.first_zero(na, nb, fa, fb);
        ASSERT_FALSE(std::isnan(t)) << "trial " << trial;
        EXPECT_NEAR(t, t0, 1e-9) << spec.label() << " trial " << trial << " arc " << glm::degrees(angle);
        dips += sign_changes > 1;
        ++checked;
    }
    EXPECT_GT(checked, 1000);
    EXPECT_GT(dips, 10); // edges where f crosses zero three times were among them
    // A point light or a perspective view: no closed form.
    Camera persp;
    persp.projection = Camera::Projection::Perspective;
    EXPECT_FALSE(ContourFunction(ContourSpec{ContourKind::Shadow, 0.0}, persp, Light{}).closed_form());
    Light point;
    point.point = true;
    EXPECT_FALSE(ContourFunction(ContourSpec{ContourKind::Shadow, 0.0}, Camera{}, point).closed_form());
    EXPECT_TRUE(ContourFunction(ContourSpec{ContourKind::Visual, 0.0}, Camera{}, point).closed_form());
}
