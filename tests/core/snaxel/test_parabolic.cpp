#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

#include "snaxels/animation/still.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/parabolic.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/visibility/visibility.h"
#include "tests/support/assets.h"
#include "tests/support/plain_mesh.h"

using namespace snaxels;

namespace {

constexpr double kPi = 3.141592653589793;

LoadedMesh load(const std::string& spec) {
    return load_mesh(spec.rfind("proc:", 0) == 0 ? spec : test::asset(spec));
}

// ---------------------------------------------------------------------------
// The oracle: where the sign of the Gaussian curvature changes, from the
// face list alone (nothing of core/ but the mesh's positions and faces).
// Angle defect per interior vertex, averaged over its one ring, and the
// zero crossing of that average on every edge whose ends differ in sign.

struct SignChanges {
    std::vector<glm::dvec3> places;
    double mean_edge = 0.0;
};

SignChanges gaussian_sign_changes(std::span<const glm::dvec3> positions,
                                  std::span<const std::array<std::int32_t, 3>> faces) {
    const std::size_t nv = positions.size();
    std::vector<double> angle_sum(nv, 0.0);
    std::map<std::pair<std::int32_t, std::int32_t>, int> edge_uses;
    for (const auto& f : faces)
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = f[std::size_t(k)], b = f[std::size_t((k + 1) % 3)], c = f[std::size_t((k + 2) % 3)];
            const glm::dvec3 u = glm::normalize(positions[std::size_t(b)] - positions[std::size_t(a)]);
            const glm::dvec3 w = glm::normalize(positions[std::size_t(c)] - positions[std::size_t(a)]);
            angle_sum[std::size_t(a)] += std::acos(std::clamp(glm::dot(u, w), -1.0, 1.0));
            ++edge_uses[{std::min(a, b), std::max(a, b)}];
        }
    std::vector<std::vector<std::int32_t>> ring(nv);
    std::vector<bool> border(nv, false);
    SignChanges out;
    for (const auto& [e, uses] : edge_uses) {
        ring[std::size_t(e.first)].push_back(e.second);
        ring[std::size_t(e.second)].push_back(e.first);
        if (uses != 2) border[std::size_t(e.first)] = border[std::size_t(e.second)] = true;
        out.mean_edge += glm::length(positions[std::size_t(e.first)] - positions[std::size_t(e.second)]);
    }
    out.mean_edge /= double(edge_uses.size());
    std::vector<double> defect(nv, 0.0), smooth(nv, 0.0);
    for (std::size_t v = 0; v < nv; ++v) defect[v] = border[v] ? 0.0 : 2.0 * kPi - angle_sum[v];
    for (std::size_t v = 0; v < nv; ++v) {
        double sum = defect[v];
        for (const std::int32_t w : ring[v]) sum += defect[std::size_t(w)];
        smooth[v] = sum / double(1 + ring[v].size());
    }
    for (const auto& [e, uses] : edge_uses) {
        const double ka = smooth[std::size_t(e.first)], kb = smooth[std::size_t(e.second)];
        if (border[std::size_t(e.first)] || border[std::size_t(e.second)] || !(ka * kb < 0.0)) continue;
        const double t = ka / (ka - kb);
        out.places.push_back((1.0 - t) * positions[std::size_t(e.first)] + t * positions[std::size_t(e.second)]);
    }
    return out;
}

/// Share of @p points within @p radius of one of @p places (a hashed grid).
double share_near(const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& places, double radius) {
    auto key = [&](const glm::dvec3& p) {
        const glm::dvec3 c = glm::floor(p / radius);
        return std::make_tuple(std::int64_t(c.x), std::int64_t(c.y), std::int64_t(c.z));
    };
    std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t>, std::vector<glm::dvec3>> grid;
    for (const glm::dvec3& p : places) grid[key(p)].push_back(p);
    std::size_t near = 0;
    for (const glm::dvec3& p : points) {
        const auto [x, y, z] = key(p);
        bool found = false;
        for (int dx = -1; dx <= 1 && !found; ++dx)
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dz = -1; dz <= 1 && !found; ++dz) {
                    const auto it = grid.find({x + dx, y + dy, z + dz});
                    if (it == grid.end()) continue;
                    for (const glm::dvec3& q : it->second)
                        if (glm::length(q - p) <= radius) {
                            found = true;
                            break;
                        }
                }
        near += found;
    }
    return points.empty() ? 0.0 : double(near) / double(points.size());
}

double total_length(const ParabolicResult& r) {
    double l = 0.0;
    for (const ParabolicCurve& c : r.curves) {
        for (std::size_t k = 1; k < c.points.size(); ++k) l += glm::length(c.points[k] - c.points[k - 1]);
        if (c.closed) l += glm::length(c.points.front() - c.points.back());
    }
    return l;
}

} // namespace

// Done-when 1: the torus's parabolic circles (distance 1 from the axis,
// height +-0.4): the marks lie on them and the curves go all round each.
TEST(Parabolic, TorusMarksLieOnTheParabolicCirclesAndCurvesCoverThem) {
    const LoadedMesh m = load("proc:torus:100000");
    const MeshTopology topo = build_topology(m.mesh);
    const ParabolicResult r = find_parabolic(topo);
    auto off_circle = [](const glm::dvec3& p) {
        const double rho = std::hypot(p.x, p.y);
        return std::min(std::hypot(rho - 1.0, p.z - 0.4), std::hypot(rho - 1.0, p.z + 0.4));
    };
    ASSERT_GT(r.points.size(), 100u);
    std::size_t on = 0;
    for (const ParabolicPoint& p : r.points) on += off_circle(p.where) <= 0.02;
    const double share = double(on) / double(r.points.size());
    // Coverage: the angle each circle's curve segments span, in 0.1-degree bins.
    std::vector<std::vector<bool>> covered(2, std::vector<bool>(3600, false));
    for (const ParabolicCurve& c : r.curves) {
        const std::size_t n = c.points.size(), segments = c.closed ? n : n - 1;
        for (std::size_t k = 0; k < segments; ++k) {
            const glm::dvec3 a = c.points[k], b = c.points[(k + 1) % n];
            if (off_circle(a) > 0.05 || off_circle(b) > 0.05 || a.z * b.z <= 0.0) continue;
            const double ta = std::atan2(a.y, a.x) * 180.0 / kPi;
            const double dt = std::remainder(std::atan2(b.y, b.x) * 180.0 / kPi - ta, 360.0);
            if (std::abs(dt) > 10.0) continue; // not a step along the circle
            const int lo = int(std::floor(std::min(ta, ta + dt) * 10.0)), hi = int(std::ceil(std::max(ta, ta + dt) * 10.0));
            for (int bin = lo; bin < hi; ++bin) covered[a.z > 0.0 ? 0 : 1][std::size_t(((bin % 3600) + 3600) % 3600)] = true;
        }
    }
    double coverage[2];
    for (int c = 0; c < 2; ++c)
        coverage[c] = double(std::count(covered[std::size_t(c)].begin(), covered[std::size_t(c)].end(), true)) / 3600.0;
    std::printf("torus 100K: %zu marks, %.1f%% within 0.02 of the circles; %zu curves, %.3f long (circles 12.566); "
                "coverage %.1f%% (z = 0.4), %.1f%% (z = -0.4); %d directions in %d walks, %.0f ms\n",
                r.points.size(), 100.0 * share, r.curves.size(), total_length(r), 100.0 * coverage[0], 100.0 * coverage[1],
                r.samples, r.walks, r.ms);
    EXPECT_GE(share, 0.95);
    EXPECT_GE(coverage[0], 0.90);
    EXPECT_GE(coverage[1], 0.90);
}

// Done-when 2: marks lie where the sign of the Gaussian curvature changes,
// as the oracle above finds it, within two mean edge lengths.
class ParabolicOnSurfaces : public ::testing::TestWithParam<std::string> {};

TEST_P(ParabolicOnSurfaces, MarksLieWhereGaussianCurvatureChangesSign) {
    const LoadedMesh m = load(GetParam());
    const MeshTopology topo = build_topology(m.mesh);
    const ParabolicResult r = find_parabolic(topo);
    const SignChanges reference = gaussian_sign_changes(topo.positions(), test::plain_faces(topo));
    std::vector<glm::dvec3> marks;
    for (const ParabolicPoint& p : r.points) marks.push_back(p.where);
    const double share = share_near(marks, reference.places, 2.0 * reference.mean_edge);
    std::printf("%s: %zu faces, %zu marks, %.1f%% within 2 mean edge lengths (%.4g) of a Gaussian curvature sign "
                "change (%zu edges change sign); %zu curves, %.4g long; %.0f ms\n",
                GetParam().c_str(), topo.n_faces(), marks.size(), 100.0 * share, 2.0 * reference.mean_edge,
                reference.places.size(), r.curves.size(), total_length(r), r.ms);
    ASSERT_GT(marks.size(), 20u);
    EXPECT_GE(share, 0.90);
    EXPECT_FALSE(r.curves.empty());
}

INSTANTIATE_TEST_SUITE_P(Meshes, ParabolicOnSurfaces,
                         ::testing::Values("proc:nose:40000", "proc:bumpy:40000", "stanford-bunny.obj"),
                         [](const auto& p) {
                             std::string name = p.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// The curves as fronts: every snaxel on a live edge with t in [0, 1], each
// one's neighbour across a face it shares, and every point of a curve on
// the surface (on its edge).
TEST(Parabolic, CurvesRunAcrossFacesAsSnaxelLoops) {
    const LoadedMesh m = load("proc:nose:20000");
    const MeshTopology topo = build_topology(m.mesh);
    ParabolicOptions options;
    options.samples = 800;
    const ParabolicResult r = find_parabolic(topo, options);
    ASSERT_FALSE(r.curves.empty());
    const Fronts fronts = parabolic_fronts(topo, r);
    ASSERT_EQ(fronts.loops.size(), r.curves.size());
    const SnaxelEngine engine(topo);
    for (std::size_t l = 0; l < fronts.loops.size(); ++l) {
        const FrontLoop& loop = fronts.loops[l];
        const ParabolicCurve& curve = r.curves[l];
        EXPECT_EQ(loop.closed, curve.closed);
        ASSERT_EQ(std::size_t(loop.size), curve.points.size());
        std::vector<std::int32_t> order;
        fronts.for_each_in_loop(loop, [&](std::int32_t s) { order.push_back(s); });
        for (std::size_t k = 0; k < order.size(); ++k) {
            const Snaxel& s = fronts.snaxels[std::size_t(order[k])];
            ASSERT_GE(s.t, 0.0);
            ASSERT_LE(s.t, 1.0);
            ASSERT_LE(glm::length(engine.position(s) - curve.points[k]), 1e-9);
            if (k + 1 < order.size() || loop.closed) {
                const Snaxel& next = fronts.snaxels[std::size_t(order[(k + 1) % order.size()])];
                ASSERT_NE(common_face(topo, s, next), MeshTopology::kNone) << "curve " << l << " point " << k;
            }
        }
    }
}

// Drawn like any contour: projected, with hidden parts. Seen from one side,
// a torus shows part of each parabolic circle and hides the rest.
TEST(Parabolic, DrawnWithHiddenLinesLikeAnyContour) {
    const LoadedMesh m = load("proc:torus:20000");
    MeshTopology topo = engine_topology(m.mesh);
    StillJob job;
    job.scene.camera.view_dir = glm::normalize(glm::dvec3(0.2, 1.0, -0.35));
    job.scene.camera.up = {0.0, 0.0, 1.0};
    job.scene.light = default_light(job.scene.camera);
    job.scene.kinds = {ContourSpec{}, ContourSpec{ContourKind::Parabolic, 0.0}};
    const StillOutput out = render_still(m, topo, nullptr, job);
    ASSERT_EQ(out.drawing.contours.size(), 2u);
    const DrawnContour& parabolic = out.drawing.contours[1];
    EXPECT_EQ(parabolic.spec.kind, ContourKind::Parabolic);
    ASSERT_EQ(parabolic.loops.size(), 2u); // the two circles
    std::size_t seen = 0, hidden = 0;
    for (const DrawnLoop& loop : parabolic.loops)
        for (const DrawnRun& run : loop.runs) (run.qi == 0 ? seen : hidden) += run.q.size();
    std::printf("torus parabolic circles from the side: %zu samples seen, %zu hidden\n", seen, hidden);
    EXPECT_GT(seen, 50u);
    EXPECT_GT(hidden, 50u);
    EXPECT_NE(out.svg.find("#1f8a4c"), std::string::npos); // the kind's default stroke
}

// A tracked parabolic kind keeps its snaxels and ids from frame to frame and
// reports no events; on a moving mesh the points move with the surface.
TEST(Parabolic, TrackedCurvesKeepTheirIdentityAndMoveWithTheMesh) {
    const LoadedMesh m = load("proc:torus:20000");
    MeshTopology topo = build_topology(m.mesh);
    ParabolicOptions options;
    options.samples = 600;
    // Drawn as the default search's curves (what the engine requires), from
    // a cheaper search.
    keep_parabolic(topo, ParabolicOptions{}, std::make_shared<const ParabolicResult>(find_parabolic(topo, options)));
    ContourTracker tracker(topo, ContourSpec{ContourKind::Parabolic, 0.0});
    Camera camera;
    const TrackedFrame first = tracker.step(camera, default_light(camera));
    ASSERT_FALSE(first.contour.fronts.snaxels.empty());
    const glm::dvec3 p0 = SnaxelEngine(topo).position(first.contour.fronts.snaxels[0]);
    auto moved = std::make_shared<MeshPose>(*topo.pose());
    for (glm::dvec3& p : moved->positions) p += glm::dvec3(0.5, 0.0, 0.0); // the mesh moves
    const MeshTopology posed = topo.posed(moved);
    camera.view_dir = glm::normalize(glm::dvec3(0.5, 0.2, 1.0));
    const TrackedFrame& second = tracker.step(posed, camera, default_light(camera));
    EXPECT_EQ(second.snaxel_id, first.snaxel_id);
    EXPECT_EQ(second.loop_sequence, first.loop_sequence);
    EXPECT_TRUE(second.events.empty());
    const glm::dvec3 p1 = SnaxelEngine(posed).position(second.contour.fronts.snaxels[0]);
    EXPECT_NEAR(glm::length(p1 - p0 - glm::dvec3(0.5, 0.0, 0.0)), 0.0, 1e-12);
}

// No parabolic points on a sphere (positive curvature everywhere): no
// marks, no curves, and drawing the kind draws nothing without failing.
TEST(Parabolic, SphereHasNone) {
    const LoadedMesh m = load("proc:sphere:20000");
    const MeshTopology topo = build_topology(m.mesh);
    const ParabolicResult r = find_parabolic(topo);
    EXPECT_EQ(r.points.size(), 0u);
    EXPECT_EQ(r.curves.size(), 0u);
    const SnaxelEngine engine(topo);
    const ContourResult c = engine.compute(ContourSpec{ContourKind::Parabolic, 0.0}, Camera{}, Light{});
    EXPECT_TRUE(c.fronts.loops.empty());
}

// The walks step between neighbours: no step is much longer than the
// directions' spacing, and every direction is walked in every order.
TEST(Parabolic, WalksStepBetweenNeighbouringDirections) {
    const int samples = 2000;
    const double spacing = std::sqrt(4.0 * kPi / samples);
    const auto walks = parabolic_walks(samples, 3);
    std::size_t steps = 0, long_steps = 0, visits = 0;
    for (const auto& walk : walks) {
        visits += walk.size();
        for (std::size_t k = 1; k < walk.size(); ++k) {
            const double a = std::acos(std::clamp(glm::dot(walk[k - 1], walk[k]), -1.0, 1.0));
            ++steps;
            long_steps += a > 3.0 * spacing;
            EXPECT_LT(a, 8.0 * spacing);
        }
    }
    EXPECT_GE(visits, std::size_t(3 * samples));
    EXPECT_LT(double(long_steps) / double(steps), 0.02);
}

// The pose's quantity store keys a search by every option that changes it:
// another smoothing is another search, the same options the kept result,
// from the pose, from a new pose of the same mesh content (the process's
// cache) and from a pose made from it (carried by the edges).
TEST(Parabolic, RequiredOncePerPoseAndOptions) {
    const LoadedMesh m = load("proc:nose:6000");
    const MeshTopology topo = build_topology(m.mesh);
    ParabolicOptions rough, smooth;
    rough.samples = smooth.samples = 240;
    rough.smoothing = 0.0;
    smooth.smoothing = 0.08;
    int searched = 0;
    rough.progress = smooth.progress = [&](int, int) { ++searched; };
    const auto a = require_parabolic(topo, rough);
    const int after_first = searched;
    EXPECT_GT(after_first, 0);
    const auto b = require_parabolic(topo, smooth);
    EXPECT_GT(searched, after_first) << "another smoothing must search again";
    ASSERT_NE(a.get(), b.get());
    EXPECT_EQ(a->smoothing_passes, 0);
    EXPECT_GT(b->smoothing_passes, 0);
    auto marks = [](const ParabolicResult& r) {
        std::vector<VertexId> v;
        for (const ParabolicPoint& p : r.points) v.push_back(p.vertex);
        std::sort(v.begin(), v.end());
        return v;
    };
    EXPECT_NE(marks(*a), marks(*b)) << "the two smoothings found the same marks";

    const int before_again = searched;
    EXPECT_EQ(require_parabolic(topo, rough).get(), a.get());
    EXPECT_EQ(require_parabolic(topo, smooth).get(), b.get());
    // A new pose of the same content: the process's cache.
    const MeshTopology reloaded = build_topology(m.mesh);
    ASSERT_NE(reloaded.pose().get(), topo.pose().get());
    EXPECT_EQ(require_parabolic(reloaded, smooth).get(), b.get());
    // A pose made from it, moved: the curves carried (no search on the moved mesh).
    auto moved = std::make_shared<MeshPose>(*topo.pose());
    for (glm::dvec3& p : moved->positions) p += glm::dvec3(0.0, 0.25, 0.0);
    const MeshTopology posed = topo.posed(moved);
    EXPECT_EQ(require_parabolic(posed, rough).get(), a.get());
    EXPECT_EQ(searched, before_again) << "a kept search ran again";
}
