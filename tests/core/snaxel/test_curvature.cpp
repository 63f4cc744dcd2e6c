#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include <glm/glm.hpp>

#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/curvature.h"
#include "snaxels/snaxel/suggestive.h"
#include "snaxels/mesh/refine.h"

using namespace snaxels;

namespace {

// proc:torus: major radius 1 about +Z, minor radius 0.4 (core/mesh/procedural.cpp).
constexpr double kR = 1.0, kr = 0.4;

/// The torus's analytic principal curvatures and directions at the point
/// nearest @p p: around the tube 1/r; along the parallel
/// cos(theta) / (R + r cos(theta)), theta measured from the outer equator.
struct TorusCurvature {
    double tube, parallel;
    glm::dvec3 tube_dir, parallel_dir;
};

TorusCurvature torus_at(const glm::dvec3& p) {
    const double phi = std::atan2(p.y, p.x);
    const double theta = std::atan2(p.z, std::hypot(p.x, p.y) - kR);
    TorusCurvature c;
    c.tube = 1.0 / kr;
    c.parallel = std::cos(theta) / (kR + kr * std::cos(theta));
    c.tube_dir = {-std::sin(theta) * std::cos(phi), -std::sin(theta) * std::sin(phi), std::cos(theta)};
    c.parallel_dir = {-std::sin(phi), std::cos(phi), 0.0};
    return c;
}

struct Errors {
    double tube = 0.0, parallel = 0.0, direction = 0.0; ///< worst over the vertices
    double mean_tube = 0.0, mean_parallel = 0.0;
};

Errors torus_errors(const MeshTopology& topo) {
    const CurvatureField field = vertex_curvatures(topo);
    EXPECT_EQ(field.size(), topo.n_vertices());
    Errors worst;
    for (const VertexId v : topo.vertices()) {
        const TorusCurvature expected = torus_at(topo.positions()[v]);
        // |1/r| > |parallel| everywhere on this torus: k1 is the tube's.
        worst.tube = std::max(worst.tube, std::abs(field.k1[v] - expected.tube));
        worst.parallel = std::max(worst.parallel, std::abs(field.k2[v] - expected.parallel));
        worst.mean_tube += std::abs(field.k1[v] - expected.tube) / double(topo.n_vertices());
        worst.mean_parallel += std::abs(field.k2[v] - expected.parallel) / double(topo.n_vertices());
        worst.direction = std::max(worst.direction, 1.0 - std::abs(glm::dot(field.dir1[v], expected.tube_dir)));
        EXPECT_NEAR(std::abs(glm::dot(field.dir2[v], expected.parallel_dir)), 1.0, 1e-2) << "vertex " << v;
        EXPECT_NEAR(glm::length(field.dir1[v]), 1.0, 1e-9);
        EXPECT_NEAR(glm::dot(field.dir1[v], topo.normals()[v]), 0.0, 1e-9);
        // Normal curvature along a principal direction is that curvature.
        EXPECT_NEAR(field.normal_curvature(v, 3.0 * field.dir2[v]), field.k2[v], 1e-9);
    }
    return worst;
}

} // namespace

// The estimate agrees with the torus's analytic curvature, both signs (the
// outer half is convex, the inner half saddle-shaped), and its principal
// directions are the tube's and the parallel's.
TEST(Curvature, MatchesTheAnalyticTorus) {
    const LoadedMesh mesh = load_mesh("proc:torus:40000");
    const Errors e = torus_errors(build_topology(mesh.mesh));
    std::printf("torus 40000 faces: worst |k1 - 1/r| %.4f, |k2 - k_parallel| %.4f, 1 - |cos| %.2e\n", e.tube,
                e.parallel, e.direction);
    EXPECT_LT(e.tube, 0.02 * (1.0 / kr));
    EXPECT_LT(e.parallel, 0.02);
    EXPECT_LT(e.direction, 1e-3);
}

// Finer meshes give closer estimates (the estimate converges).
TEST(Curvature, ConvergesOnFinerMeshes) {
    const Errors coarse = torus_errors(build_topology(load_mesh("proc:torus:4000").mesh));
    const Errors fine = torus_errors(build_topology(load_mesh("proc:torus:64000").mesh));
    EXPECT_LT(fine.tube, 0.5 * coarse.tube);
    EXPECT_LT(fine.parallel, 0.5 * coarse.parallel);
}

// On the engine's topology of a coarse mesh (refined, the added vertices
// taking interpolated normals) the curvature is that of the smooth surface
// the normals describe.
TEST(Curvature, FollowsTheSmoothShadingOfARefinedCoarseMesh) {
    const LoadedMesh mesh = load_mesh("proc:torus:3000");
    const MeshTopology refined = engine_topology(mesh.mesh);
    ASSERT_TRUE(refined.refinement());
    const Errors e = torus_errors(refined);
    std::printf("torus 3000 faces refined to %zu: worst |k1 - 1/r| %.4f (mean %.4f), |k2 - k_parallel| %.4f (mean %.4f)\n",
                refined.n_faces(), e.tube, e.mean_tube, e.parallel, e.mean_parallel);
    EXPECT_LT(e.tube, 0.1 * (1.0 / kr));
    EXPECT_LT(e.parallel, 0.1 * (1.0 / kr));
    EXPECT_LT(e.mean_tube, 0.02 * (1.0 / kr));
    EXPECT_LT(e.mean_parallel, 0.02 * (1.0 / kr));
}

// A sphere of radius 2 (outward normals): both curvatures 1/2 everywhere;
// the sign says convex;
// the vertex areas sum to its surface area.
TEST(Curvature, SphereIsUmbilicAndAreasSumToTheSurface) {
    const LoadedMesh mesh = load_mesh("proc:sphere:20000");
    const MeshTopology unit = build_topology(mesh.mesh);
    auto scaled = std::make_shared<MeshPose>(*unit.pose());
    for (const VertexId v : scaled->positions.ids()) {
        glm::dvec3& p = scaled->positions[v];
        scaled->normals[v] = glm::normalize(p); // the sphere's own normals (the estimate follows the normals it is given)
        p = 2.0 * scaled->normals[v];
    }
    const MeshTopology sphere = unit.posed(scaled);
    const CurvatureField field = vertex_curvatures(sphere);
    // The cube sphere's eight valence-3 vertices and their neighbours are
    // the worst.
    double area = 0.0, mean = 0.0;
    for (const VertexId v : field.k1.ids()) {
        EXPECT_NEAR(field.k1[v], 0.5, 0.03 * 0.5) << v;
        EXPECT_NEAR(field.k2[v], 0.5, 0.03 * 0.5) << v;
        mean += (std::abs(field.k1[v] - 0.5) + std::abs(field.k2[v] - 0.5)) / double(2 * field.size());
        area += field.area[v];
    }
    EXPECT_LT(mean, 0.003 * 0.5);
    double faces = 0.0; // the triangles' own areas, summed here
    for (const auto& f : sphere.face_vertices()) {
        const glm::dvec3 a = sphere.positions()[f[0]];
        faces += 0.5 * glm::length(glm::cross(sphere.positions()[f[1]] - a, sphere.positions()[f[2]] - a));
    }
    EXPECT_NEAR(area, faces, 1e-9 * faces);
    EXPECT_NEAR(area, 4.0 * M_PI * 4.0, 0.01 * 4.0 * M_PI * 4.0);
}

// Degenerate input gives zeros, not NaN: a mesh with a face of no area.
TEST(Curvature, DegenerateFacesCountNowhere) {
    const LoadedMesh mesh = load_mesh("proc:sphere:500");
    const MeshTopology topo = build_topology(mesh.mesh);
    auto flat = std::make_shared<MeshPose>(*topo.pose());
    for (glm::dvec3& p : flat->positions) p = glm::dvec3(0.0); // every face collapsed
    const CurvatureField field = vertex_curvatures(topo.posed(flat));
    for (const VertexId v : field.k1.ids()) {
        EXPECT_EQ(field.k1[v], 0.0);
        EXPECT_EQ(field.area[v], 0.0);
        EXPECT_TRUE(std::isfinite(field.dir1[v].x));
    }
}

// The passes' two builds (two lanes for any x86-64, four with AVX2) give
// the same bits on a noisy mesh with degenerate and obtuse faces, through
// every smoothing pass and in the gradient operator: each lane computes
// what a scalar would, in the same order.
TEST(Curvature, WideAndNarrowLanesGiveTheSameBits) {
    if (!detail::curvature_wide_lanes_available()) GTEST_SKIP() << "no AVX2 on this processor";
    const LoadedMesh mesh = load_mesh("proc:scan:20000");
    const MeshTopology topo = build_topology(mesh.mesh);
    auto bent = std::make_shared<MeshPose>(*topo.pose());
    auto* p = bent->positions.data();
    const std::size_t n = bent->positions.size();
    for (std::size_t i = 0; i + 1 < n; i += 97) p[i] = p[i + 1]; // faces collapsed onto an edge
    const MeshTopology posed = topo.posed(bent);
    auto compute = [&](bool wide) {
        const bool before = detail::allow_curvature_wide_lanes(wide);
        std::vector<CurvatureField> fields{vertex_curvatures(posed)};
        fields.push_back(smoothed_curvatures(posed, fields.back()));
        fields.push_back(smoothed_curvatures(posed, fields.back()));
        add_gradient_operator(posed, fields.back());
        detail::allow_curvature_wide_lanes(before);
        return fields;
    };
    const std::vector<CurvatureField> wide = compute(true), narrow = compute(false);
    auto same = [](const auto& a, const auto& b) {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(*a.data())) == 0;
    };
    for (std::size_t pass = 0; pass < wide.size(); ++pass) {
        SCOPED_TRACE(pass);
        EXPECT_TRUE(same(wide[pass].k1, narrow[pass].k1));
        EXPECT_TRUE(same(wide[pass].k2, narrow[pass].k2));
        EXPECT_TRUE(same(wide[pass].dir1, narrow[pass].dir1));
        EXPECT_TRUE(same(wide[pass].dir2, narrow[pass].dir2));
        EXPECT_TRUE(same(wide[pass].area, narrow[pass].area));
        EXPECT_EQ(wide[pass].typical, narrow[pass].typical);
    }
    // The order the header promises, which a lane choosing the wrong
    // principal direction would break (both builds alike).
    for (const CurvatureField& field : wide)
        for (const VertexId v : field.k1.ids()) ASSERT_GE(std::abs(field.k1[v]), std::abs(field.k2[v])) << v.index();
    EXPECT_FALSE(wide.back().gradient_weight.empty());
    EXPECT_TRUE(same(wide.back().gradient_weight, narrow.back().gradient_weight));
    // Not trivially equal: the noise gives curvature everywhere.
    EXPECT_GT(wide.back().typical, 0.0);
}

namespace {

/// The torus point at (theta, phi), and the analytic radial curvature there seen from @p camera.
glm::dvec3 torus_point(double theta, double phi) {
    const double ring = kR + kr * std::cos(theta);
    return {ring * std::cos(phi), ring * std::sin(phi), kr * std::sin(theta)};
}

double torus_radial(double theta, double phi, const Camera& camera) {
    const glm::dvec3 p = torus_point(theta, phi);
    const TorusCurvature c = torus_at(p);
    const glm::dvec3 n{std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)};
    const glm::dvec3 view = camera.to_viewer(p);
    const glm::dvec3 w = view - glm::dot(view, n) * n;
    const double a = glm::dot(w, c.tube_dir), b = glm::dot(w, c.parallel_dir);
    return (c.tube * a * a + c.parallel * b * b) / (a * a + b * b);
}

/// Whether the analytic radial curvature changes sign within @p reach of the
/// torus point at (theta, phi) (sampled on a disk of that radius on the
/// surface), and its derivative along w at the point.
struct NearZero {
    bool within;
    double along_w;
};

NearZero torus_near_zero(double theta, double phi, double reach, const Camera& camera) {
    const double ring = kR + kr * std::cos(theta);
    const double f = torus_radial(theta, phi, camera);
    bool within = f == 0.0;
    for (int i = 1; i <= 8 && !within; ++i)
        for (int k = 0; k < 32 && !within; ++k) {
            const double rho = reach * i / 8.0, angle = 2.0 * M_PI * k / 32.0;
            const double g = torus_radial(theta + rho * std::cos(angle) / kr, phi + rho * std::sin(angle) / ring, camera);
            within = (g < 0.0) != (f < 0.0);
        }
    const double eps = 1e-6;
    const double ft = (torus_radial(theta + eps, phi, camera) - torus_radial(theta - eps, phi, camera)) / (2 * eps * kr);
    const double fp = (torus_radial(theta, phi + eps, camera) - torus_radial(theta, phi - eps, camera)) / (2 * eps * ring);
    const glm::dvec3 p = torus_point(theta, phi);
    const TorusCurvature c = torus_at(p);
    const glm::dvec3 n{std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)};
    const glm::dvec3 view = camera.to_viewer(p);
    const glm::dvec3 w = glm::normalize(view - glm::dot(view, n) * n);
    return {within, glm::dot(w, c.tube_dir) * ft + glm::dot(w, c.parallel_dir) * fp};
}

} // namespace

// Suggestive contours' function: every zero of the estimated radial
// curvature lies within two mean edge lengths of the analytic torus's, over
// ten random views (five orthographic, five perspective); where the
// estimate grows clearly along w, the analytic one does too (all but a
// handful, next to where w vanishes).
TEST(Curvature, RadialCurvatureZerosMatchTheTorus) {
    const MeshTopology topo = build_topology(load_mesh("proc:torus:40000").mesh);
    const CurvatureField field = vertex_curvatures(topo);
    const double h = topo.mean_edge_length();
    std::mt19937 rng(21);
    std::normal_distribution<double> gauss;
    std::size_t crossings = 0, positive = 0, agree = 0;
    for (int view = 0; view < 10; ++view) {
        Camera camera;
        const glm::dvec3 d = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
        if (view % 2) {
            camera.view_dir = d;
        } else {
            camera.projection = Camera::Projection::Perspective;
            camera.eye = -4.0 * d;
            camera.target = glm::dvec3(0.0);
        }
        const VertexData<double> kr_est = radial_curvature(topo, field, camera);
        for (const EdgeId e : topo.edges()) {
            const auto [a, b] = topo.edge_vertices()[e];
            const double fa = kr_est[a], fb = kr_est[b];
            if ((fa < 0.0) == (fb < 0.0)) continue;
            const double t = fa / (fa - fb);
            const glm::dvec3 x = (1.0 - t) * topo.positions()[a] + t * topo.positions()[b];
            const double phi = std::atan2(x.y, x.x), theta = std::atan2(x.z, std::hypot(x.x, x.y) - kR);
            const NearZero z = torus_near_zero(theta, phi, 2.0 * h, camera);
            ++crossings;
            EXPECT_TRUE(z.within) << "view " << view << ", edge " << e << ": no analytic zero within two edge lengths";
            // Where the estimate clearly grows along w, so does the torus's curvature.
            const double along = derivative_along_view(topo, kr_est, topo.edge_faces()[e][0], x, camera);
            if (along > 0.5) {
                ++positive;
                agree += z.along_w > 0.0;
            }
        }
    }
    std::printf("%zu zero crossings over 10 views; %zu grow clearly along w, of which %zu do on the torus\n", crossings,
                positive, agree);
    EXPECT_GE(double(agree), 0.995 * double(positive));
    EXPECT_GT(crossings, 1000u);
    EXPECT_GT(positive, 100u);
}

// require_curvature keeps one field per pose and options: other options are
// another field, the same options the kept one, and a copy of the pose
// (whose positions may change) starts without.
TEST(Curvature, RequiredOncePerPoseAndOptions) {
    const LoadedMesh m = load_mesh("proc:bumpy:4000");
    const MeshTopology topo = build_topology(m.mesh);
    const auto smoothed = require_curvature(topo);
    CurvatureOptions raw;
    raw.smoothing = 0;
    raw.gradient = false;
    const auto unsmoothed = require_curvature(topo, raw);
    ASSERT_NE(smoothed.get(), unsmoothed.get());
    EXPECT_FALSE(smoothed->gradient_start.empty());
    EXPECT_TRUE(unsmoothed->gradient_start.empty());
    const CurvatureField direct = vertex_curvatures(topo);
    ASSERT_EQ(unsmoothed->k1.size(), direct.k1.size());
    EXPECT_EQ(unsmoothed->k1, direct.k1); // no smoothing: the tensors themselves
    EXPECT_NE(smoothed->k1, direct.k1);
    EXPECT_EQ(require_curvature(topo).get(), smoothed.get());
    EXPECT_EQ(require_curvature(topo, raw).get(), unsmoothed.get());
    const MeshTopology copy = topo.posed(std::make_shared<const MeshPose>(*topo.pose()));
    EXPECT_NE(require_curvature(copy).get(), smoothed.get());
}
