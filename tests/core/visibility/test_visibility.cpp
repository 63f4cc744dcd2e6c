#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>

#include "snaxels/error.h"
#include "snaxels/mesh/build.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/parts.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/mesh/procedural.h"
#include "snaxels/visibility/visibility.h"
#include "tests/support/assets.h"
#include "tests/support/marching_triangles.h"
#include "tests/support/plain_mesh.h"

using namespace snaxels;

namespace {

// Brute force, deciding its own ambiguous rays: from @p origin
// toward the viewer along @p dir (up to @p tfar), every triangle,
// Möller-Trumbore in double. QI is the larger of the front- and back-facing
// layers crossed (open sheets seen from behind count too). Hits closer than
// @p near on faces that touch @p a_vertex or @p b_vertex (the snaxel's edge:
// its own surface) are the point's own. Any other hit that close, or a ray
// passing within `margin` (barycentric) of a triangle's edge or hitting one
// within a milliradian of its plane, makes the ray grazing: a contour's ray runs along the tangent plane, which the faceted
// surface leaves and meets again within a few edge lengths, and there
// float traversal and this test may legitimately disagree.
struct BruteQi {
    int qi = 0;
    bool grazing = false;
};

BruteQi brute_force_qi(const MeshTopology& topo, const glm::dvec3& origin, const glm::dvec3& dir, double tfar,
                       VertexId a_vertex, VertexId b_vertex, double near) {
    int front = 0, back = 0;
    bool grazing = false;
    constexpr double margin = 1e-5;
    for (const auto& fv : topo.face_vertices()) {
        const glm::dvec3 a = topo.positions()[fv[0]], b = topo.positions()[fv[1]], c = topo.positions()[fv[2]];
        const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(dir, e2);
        const double det = glm::dot(e1, p);
        if (std::abs(det) < 1e-300) continue;
        const glm::dvec3 s = origin - a;
        const double u = glm::dot(s, p) / det;
        const glm::dvec3 q = glm::cross(s, e1);
        const double v = glm::dot(dir, q) / det;
        const double t = glm::dot(e2, q) / det;
        if (t <= 0.0 || t > tfar) continue;
        const double w = 1.0 - u - v;
        const bool in = u >= 0 && v >= 0 && w >= 0;
        const bool near_edge = std::min({std::abs(u), std::abs(v), std::abs(w)}) < margin;
        if (near_edge && u > -margin && v > -margin && w > -margin) grazing = true;
        if (!in) continue;
        // A face the ray runs along (within a milliradian of its plane).
        if (std::abs(glm::dot(glm::normalize(glm::cross(e1, e2)), dir)) < 1e-3) grazing = true;
        if (t < near) {
            // The faces around the snaxel's edge, met where the ray leaves:
            // the point's own surface. Met farther on, or any other face
            // this close: the facets fold over the tangent plane.
            const bool own = fv[0] == a_vertex || fv[1] == a_vertex || fv[2] == a_vertex || fv[0] == b_vertex ||
                             fv[1] == b_vertex || fv[2] == b_vertex;
            if (!own || t > 0.01 * near) grazing = true;
            continue;
        }
        if (glm::dot(glm::cross(e1, e2), dir) < 0.0) ++front;
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

// Done-when 1: Embree's counts equal brute-force ray/triangle intersection
// at every sample the brute force judges unambiguous (its own rays, its own
// QI changes and grazing rays; nothing of the product's sampling).
TEST(Visibility, MatchesBruteForceIntersection) {
    for (const std::string spec : {"spot.obj", "suzanne.obj", "teapot.obj", "proc:nose:6000",
                                   "proc:torus:4000", "proc:bumpy:6000"}) {
        const LoadedMesh m = load_mesh(spec.rfind("proc:", 0) == 0 ? spec : test::asset(spec));
        const MeshTopology topo = build_topology(m.mesh);
        const SnaxelEngine engine(topo);
        const RayScene rays(topo);
        std::mt19937 rng(7);
        std::size_t compared = 0, hidden = 0, samples = 0;
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
            const std::vector<glm::dvec3> normal = test::oracle_normals(topo.positions(), test::plain_faces(topo));
            for (const ContourSpec& kind : {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}}) {
                const ContourResult r = engine.compute(kind, cam, light);
                const ContourVisibility vis = sampler.classify(engine, r);
                for (std::size_t l = 0; l < r.fronts.loops.size(); ++l) {
                    std::vector<std::int32_t> order;
                    r.fronts.for_each_in_loop(r.fronts.loops[l], [&](std::int32_t s) { order.push_back(s); });
                    const auto& qi = vis.loops[l].snaxel_qi;
                    // The oracle's own QI at every snaxel, from the point
                    // straight toward the viewer.
                    // Its rays start off the surface along its own smooth
                    // normal; where starting 0.02, 0.05, 0.2 or 0.5 edge
                    // lengths off gives different answers, the sample is
                    // ambiguous (the product starts within that span: less
                    // than a fifth of the edge beside narrow faces).
                    std::vector<BruteQi> brute(order.size());
                    for (std::size_t k = 0; k < order.size(); ++k) {
                        const Snaxel& s = r.fronts.snaxels[order[k]];
                        const glm::dvec3 p = engine.position(s);
                        const glm::dvec3 n = test::oracle_slerp(normal[std::size_t(s.inside.index())], normal[std::size_t(s.outside.index())], s.t);
                        const double h = glm::length(topo.positions()[s.inside] - topo.positions()[s.outside]);
                        BruteQi at[4];
                        const double offsets[4] = {0.02, 0.05, 0.2, 0.5};
                        for (int i = 0; i < 4; ++i) {
                            const glm::dvec3 origin = p + offsets[i] * h * n;
                            const glm::dvec3 to_eye = cam.orthographic() ? -glm::normalize(cam.view_dir) : cam.eye - origin;
                            at[i] = brute_force_qi(topo, origin, glm::normalize(to_eye), cam.orthographic() ? 1e300 : glm::length(to_eye),
                                                   s.inside, s.outside, 4.0 * h);
                        }
                        brute[k] = at[1];
                        for (int i = 0; i < 4; ++i)
                            brute[k].grazing = brute[k].grazing || at[i].grazing || at[i].qi != at[1].qi;
                    }
                    for (std::size_t k = 0; k < order.size(); ++k) {
                        // Ambiguous by the oracle's own judgement: a grazing
                        // ray, or next to a change of its own QI.
                        const std::size_t n = order.size();
                        const BruteQi& prev = brute[(k + n - 1) % n];
                        const BruteQi& next = brute[(k + 1) % n];
                        ++samples;
                        if (brute[k].grazing || prev.qi != brute[k].qi || next.qi != brute[k].qi) continue;
                        ASSERT_EQ(qi[k], brute[k].qi) << spec << " view " << view << " " << kind.label();
                        ++compared;
                        hidden += qi[k] > 0;
                    }
                }
            }
        }
        std::printf("%s: %zu of %zu samples compared (%zu hidden), the rest ambiguous to the brute force\n", spec.c_str(), compared,
                    samples, hidden);
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
            std::vector<char> occluded(order.size(), 0);
            for (std::size_t k = 0; k < order.size(); ++k) {
                const glm::dvec3 p = engine.position(r.fronts.snaxels[order[k]]);
                for (double t = 0.02; t < 4.0 && !occluded[k]; t += 0.005) occluded[k] = inside_solid(p - t * cam.view_dir);
            }
            for (std::size_t k = 0; k < order.size(); ++k) {
                // Next to a change of the ray march's own answer the
                // sample is ambiguous.
                bool near_change = false;
                for (int j = -3; j <= 3; ++j) near_change |= occluded[(k + order.size() + j) % order.size()] != occluded[k];
                if (near_change) continue;
                ++total;
                agree += bool(occluded[k]) == (qi[k] > 0);
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
    const MeshTopology rest = build_topology(m.mesh);
    RayScene rays(rest);
    auto moved = std::make_shared<MeshPose>(*rest.pose());
    for (auto& p : moved->positions) p = glm::dvec3(p.y, -p.x, p.z) + glm::dvec3(0.3, 0.0, 0.1); // turn and move
    const MeshTopology topo = rest.posed(moved);
    rays.refit(topo);
    EXPECT_EQ(rays.topology().pose(), topo.pose());
    const SnaxelEngine engine(topo);
    // A fresh build of the moved mesh from its own connectivity.
    const MeshTopology fresh_topo(std::make_shared<MeshConnectivity>(*rest.connectivity()), moved);
    const RayScene fresh(fresh_topo);
    EXPECT_THROW(rays.refit(fresh_topo), InternalError); // not a pose of the scene's mesh
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

// A scene of several objects: the ray scene keeps each object's box and
// each face's plane in its pose. A point of one object is near every other
// object whose box holds it, and near no object whose box lies farther than
// the reach; after a refit both follow the new pose.
TEST(Visibility, ObjectBoxesAndFacePlanesFollowThePose) {
    const MeshTopology rest = engine_topology(import_mesh(test::asset("meet/apart.dae")));
    const FaceParts* parts = rest.parts();
    ASSERT_TRUE(parts != nullptr);
    ASSERT_GE(parts->objects.size(), 5u);
    RayScene rays(rest);
    auto check = [&](const MeshTopology& topo) {
        ASSERT_EQ(rays.face_planes().size(), topo.n_faces());
        // The test's own boxes, from the faces.
        const double inf = std::numeric_limits<double>::infinity();
        std::vector<std::pair<glm::dvec3, glm::dvec3>> boxes(parts->objects.size(), {glm::dvec3(inf), glm::dvec3(-inf)});
        for (const FaceId f : topo.faces())
            for (const VertexId v : topo.face_vertices()[f]) {
                boxes[parts->object[f]].first = glm::min(boxes[parts->object[f]].first, topo.positions()[v]);
                boxes[parts->object[f]].second = glm::max(boxes[parts->object[f]].second, topo.positions()[v]);
            }
        std::size_t apart = 0;
        for (const FaceId f : topo.faces()) {
            if (f.index() % 7 != 0) continue;
            const auto& fv = topo.face_vertices()[f];
            const glm::dvec3 a = topo.positions()[fv[0]], b = topo.positions()[fv[1]], c = topo.positions()[fv[2]];
            const RayScene::FacePlane& plane = rays.face_planes()[f];
            EXPECT_LT(glm::length(plane.normal - glm::cross(b - a, c - a)), 1e-12 * (1.0 + glm::length(plane.normal)));
            EXPECT_EQ(plane.corner, a);
            const glm::dvec3 p = (a + b + c) / 3.0;
            const std::int64_t own = parts->object[f];
            // The distance to the nearest other box.
            double gap = inf;
            for (std::size_t o = 0; o < boxes.size(); ++o) {
                if (std::int64_t(o) == own) continue;
                const glm::dvec3 d = glm::max(glm::max(boxes[o].first - p, p - boxes[o].second), glm::dvec3(0.0));
                gap = std::min(gap, glm::length(d));
            }
            EXPECT_TRUE(rays.near_other_object(p, own, gap * 1.01 + 1e-9));
            if (gap > 0.01) {
                EXPECT_FALSE(rays.near_other_object(p, own, 0.5 * gap));
                ++apart;
            }
            EXPECT_TRUE(rays.near_other_object(p, (own + 1) % std::int64_t(boxes.size()), 0.0)); // its own object's box
        }
        EXPECT_GT(apart, 50u);
    };
    check(rest);
    auto moved = std::make_shared<MeshPose>(*rest.pose());
    for (auto& p : moved->positions) p = glm::dvec3(p.y, -p.x, 2.0 * p.z) + glm::dvec3(0.3, 0.0, 0.1);
    const MeshTopology posed = rest.posed(moved);
    rays.refit(posed);
    check(posed);
}

// Near-plane clipping: a unit sphere seen from (0, 0, 3) looking along
// (1, 0, -1): its visual contour is the circle z = 1/3 of radius sqrt(8)/3,
// whose depth along the line of sight runs from 1.22 to 2.55. With the near
// plane at 1.9 the part nearer the eye (x < 1.9 sqrt 2 - 8/3) is not drawn,
// cut exactly at the plane; a small ball between the eye and the plane,
// over the contour in the image, hides nothing (with the plane nearer than
// it, it does). Expected lengths worked out from the circle.
TEST(Visibility, TheNearPlaneClipsAndWhatLiesNearerHidesNothing) {
    TriangleSoup soup = make_sphere(40000);
    TriangleSoup ball = make_sphere(4000);
    const glm::dvec3 eye(0.0, 0.0, 3.0), forward = glm::normalize(glm::dvec3(1.0, 0.0, -1.0));
    // The ball on the way from the eye to the contour point (0.7, 0.3, 1/3), 0.6 of the way to it.
    const glm::dvec3 seen(0.7, 0.3, 1.0 / 3.0);
    const glm::dvec3 centre = eye + 0.25 * (seen - eye);
    const auto base = static_cast<std::uint32_t>(soup.positions.size());
    for (const auto& p : ball.positions) soup.positions.push_back(centre + 0.08 * p);
    for (const auto& t : ball.triangles) soup.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    const LoadedMesh m = build_mesh(soup, "sphere and ball");
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    const RayScene rays(topo);
    Camera cam;
    cam.projection = Camera::Projection::Perspective;
    cam.eye = eye;
    cam.target = eye + forward;
    cam.up = {0.0, 1.0, 0.0};
    const ContourResult r = engine.compute({}, cam, Light{});
    const double r0 = std::sqrt(8.0) / 3.0;
    auto depth = [&](const glm::dvec3& p) { return glm::dot(p - eye, forward); };

    cam.near_clip = 1.9;
    const ContourVisibility vis = VisibilitySampler(rays, cam).classify(engine, r);
    double drawn = 0.0;
    int cuts = 0;
    for (const auto& loop : vis.loops)
        for (const auto& run : loop.runs) {
            if (run.qi == kNotDrawn) continue;
            EXPECT_EQ(run.qi, 0) << "hidden by what lies nearer than the near plane";
            for (const glm::dvec3& p : run.points) {
                ASSERT_GE(depth(p), 1.9 - 1e-9) << "a drawn point nearer than the near plane";
                EXPECT_GT(glm::length(p), 0.99) << "the ball's contour, nearer than the plane, drawn";
            }
            for (const glm::dvec3* end : {&run.points.front(), &run.points.back()})
                if (!run.closed && std::abs(depth(*end) - 1.9) < 1e-9) ++cuts;
            drawn += run_length(run);
        }
    EXPECT_EQ(cuts, 2); // the circle's arc cut at both its ends, on the plane
    const double x0 = 1.9 * std::sqrt(2.0) - 8.0 / 3.0;
    const double expected = 2.0 * std::acos(x0 / r0) * r0;
    EXPECT_NEAR(drawn, expected, 0.01 * expected);
    std::printf("drawn past the near plane %.5f, expected %.5f\n", drawn, expected);
    // Without hidden lines, the drawing's runs are clipped the same.
    double parts = 0.0;
    for (const auto& loop : drawn_parts(engine, r, &cam).loops)
        for (const auto& run : loop.runs)
            if (run.qi != kNotDrawn) {
                for (const glm::dvec3& p : run.points) ASSERT_GE(depth(p), 1.9 - 1e-9);
                parts += glm::length(run.points.front()) > 0.99 ? run_length(run) : 0.0;
            }
    EXPECT_NEAR(parts, expected, 0.01 * expected);

    // The plane nearer than the ball: the ball hides a stretch of the contour.
    cam.near_clip = 0.1;
    double hidden = 0.0;
    for (const auto& loop : VisibilitySampler(rays, cam).classify(engine, r).loops)
        for (const auto& run : loop.runs)
            if (run.qi > 0 && glm::length(run.points.front()) > 0.99) hidden += run_length(run);
    EXPECT_GT(hidden, 0.05);
}

// The near plane's cuts, which the planar maps and the 3-D view share: a
// polygon keeps what lies past the plane, closed along it; a polyline
// breaks into the pieces past it; a face's crossings are the same points,
// with the same ids, from both faces beside an edge; rays start on it.
TEST(NearPlane, CutsPolygonsPolylinesAndFacesOnThePlane) {
    Camera cam;
    cam.projection = Camera::Projection::Perspective;
    cam.eye = {0.0, 0.0, 0.0};
    cam.target = {0.0, 0.0, -1.0};
    cam.up = {0.0, 1.0, 0.0};
    const NearPlane near(cam, 1.0);
    ASSERT_TRUE(near.active());
    EXPECT_NEAR(near.past({5.0, 3.0, -3.0}), 2.0, 1e-12);
    EXPECT_TRUE(near.cuts({0.0, 0.0, 2.0})); // behind the eye
    // A square from depth 0.5 to 2.5: what lies past depth 1 is the
    // rectangle from depth 1 to 2.5, of area 1.5 on the x-z plane.
    const std::vector<glm::dvec3> square{{-0.5, 0.0, -0.5}, {0.5, 0.0, -0.5}, {0.5, 0.0, -2.5}, {-0.5, 0.0, -2.5}};
    const std::vector<glm::dvec3> kept = near.clip(square);
    ASSERT_EQ(kept.size(), 4u);
    double area = 0.0;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        const glm::dvec3 &a = kept[i], &b = kept[(i + 1) % kept.size()];
        area += a.x * b.z - b.x * a.z;
        EXPECT_GE(near.past(a), -1e-12);
    }
    EXPECT_NEAR(std::abs(area) / 2.0, 1.5, 1e-12);
    EXPECT_TRUE(near.clip(std::vector<glm::dvec3>{{0, 0, 1}, {1, 0, 1}, {0, 1, -0.5}}).empty());
    // A polyline out, in, out and in again: two pieces, each ending on the plane.
    const auto pieces = near.clip_polyline({{0, 0, -3}, {0, 0, -0.5}, {0, 1, -0.2}, {0, 1, -4}});
    ASSERT_EQ(pieces.size(), 2u);
    EXPECT_NEAR(near.past(pieces[0].back()), 0.0, 1e-12);
    EXPECT_NEAR(near.past(pieces[1].front()), 0.0, 1e-12);
    // Two faces sharing an edge that crosses the plane agree on its crossing.
    TriangleSoup soup;
    soup.positions = {{-1, 0, -0.5}, {1, 0, -0.5}, {0, 0, -3}, {0, 1, -0.2}};
    soup.triangles = {{0, 1, 2}, {1, 0, 3}};
    const LoadedMesh mesh = build_mesh(soup, "two faces");
    const MeshTopology topo = engine_topology(mesh.mesh, 0);
    std::map<std::int64_t, glm::dvec3> seen;
    for (const FaceId f : topo.faces()) {
        std::vector<NearPlane::FacePoint> cut;
        near.cut_face(topo, f, cut);
        for (const auto& q : cut) {
            EXPECT_GE(near.past(q.p), -1e-12);
            if (q.id < std::int64_t(topo.n_vertices())) continue;
            const auto [it, fresh] = seen.emplace(q.id, q.p);
            if (!fresh) {
                EXPECT_EQ(it->second, q.p) << "a crossing placed apart by the faces beside its edge";
            }
        }
    }
    EXPECT_FALSE(seen.empty());
    // A ray from the eye starts on the plane.
    const glm::dvec3 dir = glm::normalize(glm::dvec3(1.0, 0.0, -1.0));
    EXPECT_NEAR(near.past(near.ray_start(cam.eye, dir)), 0.0, 1e-12);
    // Orthographic views cut nothing.
    cam.projection = Camera::Projection::Orthographic;
    cam.view_dir = {0.0, 0.0, -1.0};
    EXPECT_FALSE(NearPlane(cam, 1.0).active());
    EXPECT_FALSE(NearPlane(cam, 1.0).cuts({0.0, 0.0, 5.0}));
}
