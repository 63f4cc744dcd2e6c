#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include <glm/glm.hpp>
#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/error.h"
#include "snaxels/export/drawing.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/curvature.h"
#include "snaxels/snaxel/suggestive.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/style/style.h"
#include "snaxels/visibility/visibility.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

// proc:torus: major radius 1 about +Z, minor radius 0.4 (core/mesh/procedural.cpp).
constexpr double kR = 1.0, kTube = 0.4;

/// A point of the analytic torus by its angles: phi round +Z, theta round
/// the tube from the outer equator.
glm::dvec3 torus_point(double theta, double phi) {
    const double ring = kR + kTube * std::cos(theta);
    return {ring * std::cos(phi), ring * std::sin(phi), kTube * std::sin(theta)};
}

glm::dvec3 torus_normal(double theta, double phi) {
    return {std::cos(theta) * std::cos(phi), std::cos(theta) * std::sin(phi), std::sin(theta)};
}

void torus_angles(const glm::dvec3& p, double& theta, double& phi) {
    phi = std::atan2(p.y, p.x);
    theta = std::atan2(p.z, std::hypot(p.x, p.y) - kR);
}

/// The analytic radial curvature at (theta, phi) seen along the unit vector
/// @p v toward an orthographic viewer: the normal curvature in the direction
/// of v's projection onto the tangent plane, from the principal curvatures
/// 1/r round the tube and cos(theta) / (R + r cos(theta)) along the parallel.
double analytic_kr(double theta, double phi, const glm::dvec3& v) {
    const glm::dvec3 n = torus_normal(theta, phi);
    const glm::dvec3 w = v - glm::dot(v, n) * n;
    const glm::dvec3 tube_dir{-std::sin(theta) * std::cos(phi), -std::sin(theta) * std::sin(phi), std::cos(theta)};
    const glm::dvec3 parallel_dir{-std::sin(phi), std::cos(phi), 0.0};
    const double a = glm::dot(w, tube_dir), b = glm::dot(w, parallel_dir);
    const double len2 = a * a + b * b;
    if (len2 < 1e-24) return 0.0;
    return (a * a / kTube + b * b * std::cos(theta) / (kR + kTube * std::cos(theta))) / len2;
}

/// The analytic derivative of kappa_r along the unit projected view, by a
/// central difference over the surface (steps taken in the tangent plane and
/// put back on the torus through its angles).
double analytic_derivative(double theta, double phi, const glm::dvec3& v) {
    const glm::dvec3 p = torus_point(theta, phi), n = torus_normal(theta, phi);
    glm::dvec3 w = v - glm::dot(v, n) * n;
    if (glm::length(w) < 1e-12) return 0.0;
    w = glm::normalize(w);
    const double h = 1e-4;
    double t1, p1, t0, p0;
    torus_angles(p + h * w, t1, p1);
    torus_angles(p - h * w, t0, p0);
    return (analytic_kr(t1, p1, v) - analytic_kr(t0, p0, v)) / (2.0 * h);
}

glm::dvec3 random_direction(std::mt19937& rng) {
    std::normal_distribution<double> g;
    glm::dvec3 d;
    do d = {g(rng), g(rng), g(rng)};
    while (glm::length(d) < 1e-3);
    return glm::normalize(d);
}

} // namespace

// Done-when 2: on a torus, over 10 random views, every drawn suggestive
// snaxel lies within two mean edge lengths of a zero of the analytic radial
// curvature, where its analytic derivative toward the viewer is positive;
// and every strong analytic zero (derivative well past the threshold, the
// surface at a clear slant) has a drawn snaxel within two edge lengths.
TEST(Suggestive, TorusZerosMatchTheAnalyticRadialCurvature) {
    const LoadedMesh mesh = load_mesh("proc:torus:40000");
    const MeshTopology topo = build_topology(mesh.mesh);
    const SnaxelEngine engine(topo);
    const double e = topo.mean_edge_length(), reach = 2.0 * e;
    // The typical curvature (median |k1|) of this torus is 1/r everywhere.
    const double typical = 1.0 / kTube;
    const ContourSpec spec = ContourSpec::parse("suggestive:0.1:10");
    std::mt19937 rng(20261202);
    std::size_t drawn_total = 0, strong_total = 0;
    for (int view = 0; view < 10; ++view) {
        Camera cam;
        cam.view_dir = random_direction(rng);
        const glm::dvec3 v = -cam.view_dir;
        const ContourResult r = engine.compute(spec, cam, Light{});
        ASSERT_EQ(r.snaxel_margin.size(), r.fronts.snaxels.size());
        std::vector<glm::dvec3> drawn;
        for (std::size_t i = 0; i < r.fronts.snaxels.size(); ++i) {
            if (r.snaxel_margin[i] < 0.0) continue;
            const glm::dvec3 p = engine.position(r.fronts.snaxels[i]);
            drawn.push_back(p);
            double theta, phi;
            torus_angles(p, theta, phi);
            // A sign change of the analytic kappa_r within reach of p.
            bool positive = false, negative = false;
            const double dt = reach / kTube, dp = reach / (kR + kTube * std::cos(theta));
            for (int a = -8; a <= 8; ++a)
                for (int b = -8; b <= 8; ++b) {
                    const double th = theta + dt * a / 8.0, ph = phi + dp * b / 8.0;
                    if (glm::length(torus_point(th, ph) - p) > reach) continue;
                    const double k = analytic_kr(th, ph, v);
                    positive |= k >= 0.0;
                    negative |= k <= 0.0;
                }
            EXPECT_TRUE(positive && negative) << "view " << view << ": a drawn snaxel at (" << p.x << ", " << p.y
                                              << ", " << p.z << ") is not within two edge lengths of a zero";
            EXPECT_GT(analytic_derivative(theta, phi, v), 0.0)
                << "view " << view << ": a drawn snaxel where kappa_r falls toward the viewer";
        }
        drawn_total += drawn.size();
        // The strong analytic zeros: along each parallel's circle of theta,
        // the sign changes of kappa_r, bisected.
        const int parallels = 720, steps = 720;
        for (int j = 0; j < parallels; ++j) {
            const double phi = 2.0 * M_PI * j / parallels;
            for (int i = 0; i < steps; ++i) {
                double t0 = 2.0 * M_PI * i / steps, t1 = 2.0 * M_PI * (i + 1) / steps;
                double k0 = analytic_kr(t0, phi, v), k1 = analytic_kr(t1, phi, v);
                if ((k0 >= 0.0) == (k1 >= 0.0)) continue;
                for (int it = 0; it < 40; ++it) {
                    const double tm = 0.5 * (t0 + t1), km = analytic_kr(tm, phi, v);
                    if ((km >= 0.0) == (k0 >= 0.0)) t0 = tm, k0 = km;
                    else t1 = tm, k1 = km;
                }
                const double theta = 0.5 * (t0 + t1);
                const double nv = glm::dot(torus_normal(theta, phi), v);
                const double strength = analytic_derivative(theta, phi, v) / (typical * typical);
                if (strength < 3.0 * spec.k || nv < 0.1 || nv > std::cos(glm::radians(spec.min_angle)) - 0.05) continue;
                const glm::dvec3 p = torus_point(theta, phi);
                double nearest = 1e300;
                for (const glm::dvec3& q : drawn) nearest = std::min(nearest, glm::length(q - p));
                ++strong_total;
                EXPECT_LE(nearest, reach) << "view " << view << ": a strong zero at (" << p.x << ", " << p.y << ", "
                                          << p.z << ") has no drawn snaxel near it";
            }
        }
    }
    std::printf("torus: %zu drawn snaxels checked, %zu strong analytic zeros found drawn\n", drawn_total, strong_total);
    EXPECT_GT(drawn_total, 100u);
    EXPECT_GT(strong_total, 100u);
}

namespace {

/// kappa_r sin^2(theta) at every vertex from the pose's curvature field,
/// computed here: k1 c^2 + k2 s^2 with c and s the components along dir1
/// and dir2 of the unit view's projection onto the tangent plane;
/// positive at a vertex facing away whose neighbours all face away too
/// (the tracked function's convention: kappa_r is kept one ring past the
/// side seen).
VertexData<double> oracle_kr(const MeshTopology& topo, const CurvatureField& field, const Camera& cam) {
    VertexData<double> kr(topo.n_vertices());
    std::vector<bool> facing(topo.n_vertices());
    for (const VertexId v : topo.vertices())
        facing[std::size_t(v.index())] = glm::dot(topo.normals()[v], cam.to_viewer(topo.positions()[v])) > 0.0;
    for (const VertexId v : topo.vertices()) {
        const glm::dvec3 n = topo.normals()[v];
        const glm::dvec3 view = cam.to_viewer(topo.positions()[v]);
        bool near = facing[std::size_t(v.index())];
        for (const VertexId w : topo.neighbours(v)) near = near || facing[std::size_t(w.index())];
        if (!near) {
            kr[v] = 1.0;
            continue;
        }
        const glm::dvec3 w = view - glm::dot(view, n) * n;
        const double c = glm::dot(w, field.dir1[v]), s = glm::dot(w, field.dir2[v]);
        // kappa_r sin^2(theta), as rtsc interpolates it: |w|^2 = sin^2(theta).
        kr[v] = field.k1[v] * c * c + field.k2[v] * s * s;
    }
    return kr;
}

} // namespace

class SuggestiveTurntable : public ::testing::TestWithParam<std::string> {};

// Done-when 3: through a 120-frame turntable the tracked suggestive contour
// is, at every frame, the from-scratch one: the same snaxels on the same
// edges at the same points (each the zero of kappa_r sin^2(theta), linear
// along its edge, on exactly the edges where the oracle's changes sign), the
// same parts drawn, each passing its test by as much (what a faded stroke
// follows); and the tracker keeps identities across frames. For both tests.
TEST_P(SuggestiveTurntable, TrackedEqualsFromScratchAtEveryFrame) {
    const LoadedMesh m = load_mesh(test::asset(GetParam()));
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    EngineOptions options;
    options.check_invariants = false;
    for (const char* text : {"suggestive:4:15", "suggestive:rtsc"}) {
        SCOPED_TRACE(text);
        const ContourSpec spec = ContourSpec::parse(text);
        ContourTracker tracker(topo, spec, options);
        std::set<std::uint64_t> previous;
        const CurvatureField& field =
            *require_curvature(topo); // the (smoothed) field the kind reads: the oracle's input
        std::size_t kept_ids = 0, moves = 0;
        for (int frame = 0; frame < 120; ++frame) {
            Camera cam;
            cam.view_dir = glm::rotate(glm::normalize(glm::dvec3(0.3, -0.35, 1.0)),
                                       glm::radians(3.0 * frame), glm::dvec3(0, 1, 0));
            const TrackedFrame& tf = tracker.step(cam, Light{});
            const ContourResult fresh = engine.compute(spec, cam, Light{}, options);
            const Fronts& a = tf.contour.fronts;
            const Fronts& b = fresh.fronts;
            ASSERT_EQ(a.snaxels.size(), b.snaxels.size()) << "frame " << frame;
            ASSERT_EQ(tf.contour.snaxel_margin.size(), a.snaxels.size());
            // Oracle: the edges where kappa_r changes sign.
            const VertexData<double> kr = oracle_kr(topo, field, cam);
            std::size_t crossing = 0;
            for (const auto& [u, w] : topo.edge_vertices()) {
                crossing += (kr[u] >= 0.0) != (kr[w] >= 0.0);
            }
            ASSERT_EQ(a.snaxels.size(), crossing) << "frame " << frame;
            for (std::size_t i = 0; i < a.snaxels.size(); ++i) {
                const Snaxel& s = a.snaxels[i];
                const std::int32_t j = b.edge_snaxel[s.edge];
                ASSERT_NE(j, kNoSnaxel) << "frame " << frame;
                const double len =
                    glm::length(topo.positions()[s.inside] - topo.positions()[s.outside]);
                ASSERT_LE(
                    glm::length(engine.position(s) - engine.position(b.snaxels[std::size_t(j)])),
                    1e-9 * len);
                const double ki = kr[s.inside], ko = kr[s.outside];
                if (ki != 1.0 && ko != 1.0)
                    ASSERT_NEAR(s.t, ki / (ki - ko), 1e-9) << "frame " << frame;
                else
                    ASSERT_LT(tf.contour.snaxel_margin[i], 0.0)
                        << "frame " << frame; // the rim: never drawn
                ASSERT_EQ(tf.contour.snaxel_margin[i] >= 0.0,
                          fresh.snaxel_margin[std::size_t(j)] >= 0.0)
                    << "frame " << frame;
            }
            // How far each passes its test (what a faded stroke's width
            // follows): the same tracked as from scratch.
            const std::vector<double> ma = suggestive_strength(topo, field, a, cam, spec);
            const std::vector<double> mb = suggestive_strength(topo, field, b, cam, spec);
            for (std::size_t i = 0; i < a.snaxels.size(); ++i) {
                const double x = ma[i], y = mb[std::size_t(b.edge_snaxel[a.snaxels[i].edge])];
                if (std::isfinite(x) || std::isfinite(y)) {
                    ASSERT_NEAR(x, y, 1e-9 * (1.0 + std::abs(y))) << "frame " << frame;
                }
            }
            std::set<std::uint64_t> ids(tf.snaxel_id.begin(), tf.snaxel_id.end());
            ASSERT_EQ(ids.size(), tf.snaxel_id.size()) << "frame " << frame;
            for (const auto id : ids)
                kept_ids += previous.count(id);
            moves += tf.fanouts + tf.retreats;
            previous = std::move(ids);
        }
        EXPECT_GT(moves, 0u);
        EXPECT_GT(kept_ids, 0u); // snaxels live on from frame to frame
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, SuggestiveTurntable, ::testing::Values("spot.obj", "horse.ply"),
                         [](const auto& p) { return test::test_name(p.param); });

// The drawing leaves out exactly the parts with a negative margin: with no
// threshold every front-facing zero where kappa_r grows is drawn; with an
// impossible one nothing is; in between, less. With hidden lines the parts
// left out are kNotDrawn runs.
TEST(Suggestive, DrawingLeavesOutWeakParts) {
    const LoadedMesh m = load_mesh(test::asset("spot.obj"));
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    Camera cam;
    cam.view_dir = glm::normalize(glm::dvec3(-1.0, -0.2, -0.4));
    const ImageProjection projection(cam, glm::dvec3(0.0), bounding_radius(topo), 800, 800, 32.0);
    auto drawn_length = [&](const ContourSpec& spec, std::size_t* all_snaxels = nullptr) {
        const ContourResult r = engine.compute(spec, cam, Light{});
        if (all_snaxels) *all_snaxels = r.fronts.snaxels.size();
        const Drawing d = make_drawing(engine, {r}, projection);
        double length = 0.0;
        for (const DrawnLoop& loop : d.contours[0].loops) {
            EXPECT_FALSE(loop.runs.empty());
            for (const DrawnRun& run : loop.runs) {
                if (run.qi == kNotDrawn) continue;
                EXPECT_EQ(run.qi, 0);
                for (std::size_t k = 1; k < run.q.size(); ++k) length += glm::length(run.q[k] - run.q[k - 1]);
            }
        }
        return length;
    };
    std::size_t snaxels = 0;
    const double loose = drawn_length(ContourSpec::parse("suggestive:0:0"), &snaxels);
    const double usual = drawn_length(ContourSpec::parse("suggestive:4:15"));
    const double none = drawn_length(ContourSpec::parse("suggestive:1000000"));
    std::printf("spot: %zu snaxels; drawn length %.0f px with no threshold, %.0f by default, %.0f past any\n", snaxels,
                loose, usual, none);
    EXPECT_GT(snaxels, 0u);
    EXPECT_EQ(none, 0.0);
    EXPECT_GT(usual, 0.0);
    EXPECT_LT(usual, loose);

    // With visibility: every snaxel left out is kNotDrawn, every other one has a QI.
    const ContourResult r = engine.compute(ContourSpec::parse("suggestive"), cam, Light{});
    const RayScene rays(topo);
    const ContourVisibility vis = VisibilitySampler(rays, cam).classify(engine, r);
    std::size_t left_out = 0, k = 0;
    for (std::size_t l = 0; l < r.fronts.loops.size(); ++l) {
        std::vector<std::int32_t> order;
        r.fronts.for_each_in_loop(r.fronts.loops[l], [&](std::int32_t s) { order.push_back(s); });
        ASSERT_EQ(vis.loops[l].snaxel_qi.size(), order.size());
        for (std::size_t i = 0; i < order.size(); ++i, ++k) {
            const bool weak = r.snaxel_margin[std::size_t(order[i])] < 0.0;
            EXPECT_EQ(vis.loops[l].snaxel_qi[i] == kNotDrawn, weak);
            left_out += weak;
        }
    }
    EXPECT_GT(left_out, 0u);
    EXPECT_LT(left_out, k);
}

// Smoothing the pose's curvature: on a smooth torus the principal curvatures
// stay the analytic ones; on a scanned mesh (the horse) kappa_r changes sign
// on fewer edges (its noise loops go) and the smoothed field varies less
// from a vertex to its neighbours.
TEST(Suggestive, SmoothingKeepsShapeAndRemovesNoise) {
    {
        const MeshTopology topo = build_topology(load_mesh("proc:torus:40000").mesh);
        const std::shared_ptr<const CurvatureField> field = require_curvature(topo);
        double worst = 0.0;
        for (const VertexId v : topo.vertices()) {
            double theta, phi;
            torus_angles(topo.positions()[v], theta, phi);
            worst = std::max({worst, std::abs(field->k1[v] - 1.0 / kTube),
                              std::abs(field->k2[v] - std::cos(theta) / (kR + kTube * std::cos(theta)))});
        }
        EXPECT_LT(worst, 0.05) << "smoothing moved the torus's curvature";
        EXPECT_NEAR(field->typical, 1.0 / kTube, 0.05);
    }
    const MeshTopology horse = build_topology(load_mesh(test::asset("horse.ply")).mesh);
    const CurvatureField raw = vertex_curvatures(horse);
    const CurvatureField& smooth = *require_curvature(horse);
    Camera cam;
    cam.view_dir = glm::normalize(glm::dvec3(-1.0, -0.2, -0.3));
    auto sign_changes = [&](const CurvatureField& f) {
        const VertexData<double> kr = oracle_kr(horse, f, cam);
        std::size_t n = 0;
        for (const auto& [a, b] : horse.edge_vertices()) n += (kr[a] >= 0.0) != (kr[b] >= 0.0);
        return n;
    };
    auto roughness = [&](const CurvatureField& f) { // mean |k1 - k1 of a neighbour| over the edges, in typical units
        double sum = 0.0;
        for (const auto& [a, b] : horse.edge_vertices()) sum += std::abs(f.k1[a] - f.k1[b]);
        return sum / double(horse.n_edges()) / f.typical;
    };
    const std::size_t before = sign_changes(raw), after = sign_changes(smooth);
    std::printf("horse: kappa_r changes sign on %zu edges raw, %zu smoothed; roughness %.3f -> %.3f\n", before, after,
                roughness(raw), roughness(smooth));
    EXPECT_LT(double(after), 0.8 * double(before));
    EXPECT_LT(roughness(smooth), 0.6 * roughness(raw));
}

// The kind's text: parsed, labelled and refused as the CLI says.
TEST(Suggestive, SpecParsesAndRefuses) {
    // Named alone: rtsc's test at its threshold; with a value, the derivative test.
    const ContourSpec r = ContourSpec::parse("suggestive");
    EXPECT_EQ(r.test, SuggestiveTest::Rtsc);
    EXPECT_DOUBLE_EQ(r.k, kDefaultRtscThreshold);
    EXPECT_TRUE(ContourSpec::parse(r.label()).same_as(r));
    const ContourSpec d = ContourSpec::parse("suggestive:4");
    EXPECT_EQ(d.kind, ContourKind::Suggestive);
    EXPECT_EQ(d.test, SuggestiveTest::Derivative);
    EXPECT_DOUBLE_EQ(d.k, kDefaultSuggestiveDerivative);
    EXPECT_DOUBLE_EQ(d.min_angle, kDefaultSuggestiveAngle);
    EXPECT_FALSE(d.on_surface());
    EXPECT_FALSE(r.same_as(d));
    const ContourSpec s = ContourSpec::parse("suggestive:2.5:20");
    EXPECT_DOUBLE_EQ(s.k, 2.5);
    EXPECT_DOUBLE_EQ(s.min_angle, 20.0);
    EXPECT_TRUE(ContourSpec::parse(s.label()).same_as(s));
    EXPECT_FALSE(s.same_as(d));
    for (const char* bad : {"suggestive:", "suggestive:-1", "suggestive:x", "suggestive:1:90", "suggestive:1:-2",
                            "suggestive:1:5:3"})
        EXPECT_THROW(ContourSpec::parse(bad), Error) << bad;
}

// The style's attributes: read into the spec, refused where they do not belong.
TEST(Suggestive, StyleAttributes) {
    const std::string head = "<style version=\"1\">";
    const Style s = parse_style(head + "<contour kind=\"suggestive\" min-derivative=\"2.5\" min-angle=\"20\"/></style>",
                                "test", nullptr);
    ASSERT_EQ(s.contours.size(), 1u);
    EXPECT_EQ(s.contours[0].spec.kind, ContourKind::Suggestive);
    EXPECT_DOUBLE_EQ(s.contours[0].spec.k, 2.5);
    EXPECT_DOUBLE_EQ(s.contours[0].spec.min_angle, 20.0);
    EXPECT_FALSE(s.contours[0].hidden.draw); // hidden suggestive contours are left out by default
    const Style d = parse_style(head + "<contour kind=\"suggestive\"/></style>", "test", nullptr);
    EXPECT_TRUE(d.contours[0].spec.same_as(ContourSpec::parse("suggestive")));
    for (const std::string bad : {"<contour kind=\"suggestive\" k=\"1\"/>", "<contour kind=\"visual\" min-derivative=\"1\"/>",
                                  "<contour kind=\"crease\" min-angle=\"10\"/>", "<contour kind=\"suggestive\" min-angle=\"95\"/>",
                                  "<contour kind=\"suggestive\" min-derivative=\"-1\"/>"})
        EXPECT_THROW(parse_style(head + bad + "</style>", "test", nullptr), Error) << bad;
}
