#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/mesh/import.h"
#include "core/mesh/procedural.h"
#include "core/visibility/visibility.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

// Brute force: every triangle, Möller-Trumbore in double. Returns the QI and
// whether the ray passed within `margin` (barycentric) of a triangle's edge,
// where float BVH traversal and this test may legitimately disagree.
struct BruteQi {
    int qi = 0;
    bool grazing = false;
};

BruteQi brute_force_qi(const MeshTopology& topo, const VisibilityRay& ray) {
    int front = 0, back = 0;
    bool grazing = false;
    constexpr double margin = 1e-5;
    for (std::size_t f = 0; f < topo.n_faces(); ++f) {
        const auto& fv = topo.face_vertices[f];
        bool ignored = false;
        for (const auto v : fv)
            for (const auto w : ray.ignore) ignored |= v == w;
        if (ignored) continue;
        const glm::dvec3 a = topo.positions[fv[0]], b = topo.positions[fv[1]], c = topo.positions[fv[2]];
        const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(ray.dir, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-300) continue;
        const glm::dvec3 s = ray.origin - a;
        const double u = glm::dot(s, p) / det;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(ray.dir, q) / det;
        const double t = glm::dot(e2, q) / det;
        if (t <= 0.0 || t > ray.tfar) continue;
        const double w = 1.0 - u - v;
        const bool in = u >= 0 && v >= 0 && w >= 0;
        const bool near_edge = std::min({std::abs(u), std::abs(v), std::abs(w)}) < margin;
        if (near_edge && u > -margin && v > -margin && w > -margin) grazing = true;
        if (!in) continue;
        if (glm::dot(glm::cross(e1, e2), ray.dir) > 0.0) ++front;
        else ++back;
    }
    return {std::max(front, back), grazing};
}

glm::dvec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> n;
    return glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
}

LoadedMesh two_spheres(std::size_t faces_each, const glm::dvec3& offset) {
    TriangleSoup a = make_sphere(faces_each), b = make_sphere(faces_each);
    const auto base = static_cast<std::uint32_t>(a.positions.size());
    for (const auto& p : b.positions) a.positions.push_back(p + offset);
    for (const auto& t : b.triangles) a.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    return build_mesh(a, "two spheres");
}

double run_length(const VisibilityRun& run) {
    double len = 0.0;
    for (std::size_t i = 1; i < run.points.size(); ++i) len += glm::length(run.points[i] - run.points[i - 1]);
    if (run.closed && run.points.size() > 1) len += glm::length(run.points.front() - run.points.back());
    return len;
}

} // namespace

// Done-when 1: Embree's counts equal brute-force ray/triangle intersection at
// every sample away from QI changes and grazing rays.
TEST(Visibility, MatchesBruteForceIntersection) {
    for (const std::string spec : {"spot.obj", "suzanne.obj", "teapot.obj", "proc:nose:6000",
                                   "proc:torus:4000", "proc:bumpy:6000"}) {
        const LoadedMesh m = load_mesh(spec.rfind("proc:", 0) == 0 ? spec : test::asset(spec));
        const MeshTopology topo = build_topology(m.mesh);
        const SnaxelEngine engine(topo);
        const RayScene rays(topo);
        std::mt19937 rng(7);
        std::size_t compared = 0, hidden = 0;
        for (int view = 0; view < 10; ++view) {
            Camera cam;
            if (view % 2) {
                cam.projection = Camera::Projection::Perspective;
                const glm::dvec3 centre = 0.5 * (m.report.bbox_min + m.report.bbox_max);
                const double radius = 0.5 * glm::length(m.report.bbox_max - m.report.bbox_min);
                cam.target = centre;
                cam.eye = centre + 3.0 * radius * random_unit(rng);
            } else {
                cam.view_dir = random_unit(rng);
            }
            Light light;
            light.dir = random_unit(rng);
            const VisibilitySampler sampler(rays, cam);
            for (const ContourSpec kind : {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}}) {
                const ContourResult r = engine.compute(kind, cam, light);
                const ContourVisibility vis = sampler.classify(engine, r);
                for (std::size_t l = 0; l < r.fronts.loops.size(); ++l) {
                    std::vector<std::int32_t> order;
                    r.fronts.for_each_in_loop(r.fronts.loops[l], [&](std::int32_t s) { order.push_back(s); });
                    const auto& qi = vis.loops[l].snaxel_qi;
                    for (std::size_t k = 0; k < order.size(); ++k) {
                        const int prev = qi[(k + order.size() - 1) % order.size()], next = qi[(k + 1) % order.size()];
                        if (prev != qi[k] || next != qi[k]) continue; // at a QI change
                        const Snaxel& s = r.fronts.snaxels[order[k]];
                        const VisibilityRay ray = sampler.snaxel_ray(s, engine.position(s), engine.normal(s));
                        const BruteQi brute = brute_force_qi(topo, ray);
                        if (brute.grazing) continue;
                        ASSERT_EQ(qi[k], brute.qi) << spec << " view " << view << " " << kind.label();
                        ++compared;
                        hidden += qi[k] > 0;
                    }
                }
            }
        }
        EXPECT_GT(compared, 500u) << spec;
        if (spec != "proc:bumpy:6000") {
            EXPECT_GT(hidden, 0u) << spec << ": no hidden sample tested";
        }
    }
}

// Done-when 2: a sphere's whole visual contour is visible.
TEST(Visibility, SphereContourIsAllVisible) {
    const LoadedMesh m = load_mesh("proc:sphere:20000");
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    const RayScene rays(topo);
    std::mt19937 rng(3);
    for (int view = 0; view < 10; ++view) {
        Camera cam;
        if (view % 2) {
            cam.projection = Camera::Projection::Perspective;
            cam.eye = 4.0 * random_unit(rng);
        } else {
            cam.view_dir = random_unit(rng);
        }
        const ContourResult r = engine.compute({}, cam, Light{});
        const ContourVisibility vis = VisibilitySampler(rays, cam).classify(engine, r);
        ASSERT_EQ(vis.loops.size(), 1u);
        for (const int qi : vis.loops[0].snaxel_qi) ASSERT_EQ(qi, 0) << "view " << view;
        ASSERT_EQ(vis.loops[0].runs.size(), 1u);
        EXPECT_TRUE(vis.loops[0].runs[0].closed);
    }
}

// Done-when 2: two unit spheres, the far one's centre 1.2 to the side: the
// near disk hides an arc of 2 acos(0.6) of the far silhouette circle.
TEST(Visibility, TwoSpheresHideTheExpectedArc) {
    const double d = 1.2;
    const LoadedMesh m = two_spheres(80000, {d, 0.0, -3.0});
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    const RayScene rays(topo);
    Camera cam;
    cam.view_dir = {0.0, 0.0, -1.0}; // looking down -Z: the sphere at z = 0 is in front
    const ContourResult r = engine.compute({}, cam, Light{});
    const ContourVisibility vis = VisibilitySampler(rays, cam).classify(engine, r);
    ASSERT_EQ(r.fronts.loops.size(), 2u);
    double hidden = 0.0, far_total = 0.0;
    for (const auto& loop : vis.loops)
        for (const auto& run : loop.runs) {
            if (run.points[0].z < -1.0) far_total += run_length(run);
            if (run.qi > 0) {
                EXPECT_LT(run.points[0].z, -1.0) << "a hidden run on the near sphere";
                hidden += run_length(run);
            }
        }
    const double expected = 2.0 * std::acos(d / 2.0);
    // The polyline is a chordal approximation of the circle; compare the
    // hidden fraction of the far silhouette.
    const double fraction = hidden / far_total, expected_fraction = expected / (2.0 * M_PI);
    EXPECT_NEAR(fraction, expected_fraction, 0.01 * expected_fraction)
        << "hidden " << hidden << " of " << far_total;
    std::printf("hidden arc fraction %.5f, expected %.5f\n", fraction, expected_fraction);
}

// Done-when 2: a torus seen obliquely hides the parts of its inner contour
// that the near side of the tube covers; checked against ray marching the
// torus's implicit solid at every sample away from QI changes.
TEST(Visibility, ObliqueTorusHidesItsInnerContourWhereExpected) {
    const LoadedMesh m = load_mesh("proc:torus:60000");
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    const RayScene rays(topo);
    for (const double elevation : {0.2, 0.35, 0.6}) {
        Camera cam;
        cam.view_dir = glm::normalize(glm::dvec3(0.0, -std::cos(elevation), -std::sin(elevation)));
        const ContourResult r = engine.compute({}, cam, Light{});
        const VisibilitySampler sampler(rays, cam);
        const ContourVisibility vis = sampler.classify(engine, r);
        auto inside_solid = [](const glm::dvec3& p) {
            const double ring = std::sqrt(p.x * p.x + p.y * p.y) - 1.0;
            return ring * ring + p.z * p.z < 0.4 * 0.4 * 0.98; // just inside, away from the surface
        };
        std::size_t agree = 0, total = 0, hidden = 0;
        for (std::size_t l = 0; l < r.fronts.loops.size(); ++l) {
            std::vector<std::int32_t> order;
            r.fronts.for_each_in_loop(r.fronts.loops[l], [&](std::int32_t s) { order.push_back(s); });
            const auto& qi = vis.loops[l].snaxel_qi;
            for (std::size_t k = 0; k < order.size(); ++k) {
                bool near_change = false;
                for (int j = -3; j <= 3; ++j)
                    near_change |= qi[(k + order.size() + j) % order.size()] != qi[k];
                if (near_change) continue;
                const glm::dvec3 p = engine.position(r.fronts.snaxels[order[k]]);
                bool occluded = false;
                for (double t = 0.02; t < 4.0 && !occluded; t += 0.005)
                    occluded = inside_solid(p - t * cam.view_dir);
                ++total;
                agree += occluded == (qi[k] > 0);
                hidden += qi[k] > 0;
            }
        }
        EXPECT_GT(hidden, 0u) << "elevation " << elevation;
        EXPECT_EQ(agree, total) << "elevation " << elevation;
    }
}

// The BVH follows a moving mesh: refit gives what a fresh build gives.
TEST(Visibility, RefitMatchesRebuild) {
    const LoadedMesh m = load_mesh("proc:nose:6000");
    MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    RayScene rays(topo);
    for (auto& p : topo.positions) p = glm::dvec3(p.y, -p.x, p.z) + glm::dvec3(0.3, 0.0, 0.1); // turn and move
    rays.refit();
    const MeshTopology fresh_topo = topo;
    const RayScene fresh(fresh_topo);
    Camera cam;
    cam.view_dir = glm::normalize(glm::dvec3(1.0, 0.3, -0.5));
    const ContourResult r = engine.compute({}, cam, Light{});
    const auto a = VisibilitySampler(rays, cam).classify(engine, r);
    const auto b = VisibilitySampler(fresh, cam).classify(engine, r);
    std::size_t hidden = 0;
    for (std::size_t l = 0; l < a.loops.size(); ++l) {
        EXPECT_EQ(a.loops[l].snaxel_qi, b.loops[l].snaxel_qi);
        for (const int qi : a.loops[l].snaxel_qi) hidden += qi > 0;
    }
    EXPECT_GT(hidden, 0u);
}
