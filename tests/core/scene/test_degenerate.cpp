// Degenerate scenes: each has a defined outcome, a drawing whose every number
// is finite (checked here against geometry worked out independently) or a
// snaxels::Error that says what is wrong; never a crash or a hang. The
// drawings go through render_still, the pipeline `snaxels-cli contours` and
// the application use, with the engine's invariants checked.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "snaxels/animation/still.h"
#include "snaxels/error.h"
#include "snaxels/mesh/build.h"
#include "snaxels/mesh/procedural.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/style/style.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

struct Scene {
    LoadedMesh mesh;
    MeshTopology topology;
};

Scene scene_of(const TriangleSoup& soup) {
    Scene s{build_mesh(soup, "test"), {}};
    s.topology = engine_topology(s.mesh.mesh, 0);
    return s;
}

TriangleSoup moved(TriangleSoup soup, double scale, glm::dvec3 offset) {
    for (auto& p : soup.positions) p = p * scale + offset;
    return soup;
}

Style toon() {
    std::vector<StyleDiagnostic> warnings;
    return load_style(std::string(SNAXELS_STYLES_DIR) + "/toon.xml", &warnings);
}

StillOutput draw(const Scene& s, const Camera& camera, const Light& light, std::vector<ContourSpec> kinds,
                 const Style& style = default_style()) {
    StillJob job;
    job.scene.camera = camera;
    job.scene.light = light;
    job.scene.kinds = std::move(kinds);
    job.scene.style = style;
    job.scene.engine.check_invariants = true;
    return render_still(s.mesh, s.topology, nullptr, job);
}

// Every projected point of the drawing is a finite number inside a generous
// frame around the canvas, and the SVG has no non-number in it.
void expect_finite_drawing(const StillOutput& out) {
    const double w = out.drawing.width, h = out.drawing.height;
    for (const auto& c : out.drawing.contours)
        for (const auto& loop : c.loops) {
            for (const auto& q : loop.q) {
                ASSERT_TRUE(std::isfinite(q.x) && std::isfinite(q.y));
                EXPECT_GT(q.x, -10 * w);
                EXPECT_LT(q.x, 11 * w);
                EXPECT_GT(q.y, -10 * h);
                EXPECT_LT(q.y, 11 * h);
            }
            for (const auto& run : loop.runs)
                for (const auto& q : run.q) ASSERT_TRUE(std::isfinite(q.x) && std::isfinite(q.y));
        }
    EXPECT_EQ(out.svg.find("nan"), std::string::npos);
    EXPECT_EQ(out.svg.find("inf"), std::string::npos);
    EXPECT_NE(out.svg.find("</svg>"), std::string::npos);
}

std::size_t snaxel_count(const ContourResult& r) { return r.fronts.snaxels.size(); }

Camera perspective(glm::dvec3 eye, glm::dvec3 target) {
    Camera c;
    c.projection = Camera::Projection::Perspective;
    c.eye = eye;
    c.target = target;
    return c;
}

Light directional(glm::dvec3 dir) {
    Light l;
    l.dir = dir;
    return l;
}

} // namespace

TEST(Degenerate, EyeOnTheSurfaceIsRefusedAndInsideItDraws) {
    const Scene s = scene_of(make_procedural("sphere:4000"));
    const Light light = directional({0.3, 0.5, -1.0});
    // The eye on a vertex of the sphere: refused, with a message that says why.
    const glm::dvec3 on = s.topology.positions()[VertexId(0)];
    try {
        draw(s, perspective(on, {0.0, 0.0, 0.0}), light, {ContourSpec{}});
        FAIL() << "an eye on the sphere's surface drew";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("lies on the surface"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("move the eye off the surface"), std::string::npos) << e.what();
    }
    // Inside, the sphere is seen from within: every face turned away, no
    // outline, a drawing of nothing rather than a refusal.
    const StillOutput inside = draw(s, perspective({0.1, 0.2, 0.05}, {0.0, 0.0, 0.0}), light, {ContourSpec{}});
    expect_finite_drawing(inside);
    for (const DrawnContour& c : inside.drawing.contours)
        for (const DrawnLoop& loop : c.loops)
            for (std::size_t i = 0; i < loop.qi.size(); ++i) EXPECT_NE(loop.qi[i], 0) << "a line drawn from inside a closed sphere";
    // Just outside, it draws: one silhouette, a circle seen from 1.5 radii.
    const StillOutput out = draw(s, perspective({0.0, 0.0, -1.5}, {0.0, 0.0, 0.0}), light, {ContourSpec{}});
    expect_finite_drawing(out);
    ASSERT_EQ(out.results[0].fronts.loops.size(), 1u);
}

TEST(Degenerate, ViewAlongTheUpDirectionDraws) {
    // Orthographic, looking straight down the up axis: the screen basis falls
    // back to another axis. The unit sphere's silhouette is its equator
    // (y = 0), drawn as a circle about the canvas centre.
    const Scene s = scene_of(make_procedural("sphere:8000"));
    Camera c;
    c.view_dir = {0.0, -1.0, 0.0};
    c.up = {0.0, 1.0, 0.0};
    const StillOutput out = draw(s, c, directional({0.2, 1.0, 0.3}), {ContourSpec{}});
    expect_finite_drawing(out);
    const ContourResult& r = out.results[0];
    ASSERT_EQ(r.fronts.loops.size(), 1u);
    for (const auto& sn : r.fronts.snaxels) {
        const glm::dvec3 p = SnaxelEngine(s.topology).position(sn);
        EXPECT_LT(std::abs(p.y), 0.03);
    }
    const glm::dvec2 centre(0.5 * out.drawing.width, 0.5 * out.drawing.height);
    double lo = 1e300, hi = 0.0;
    for (const auto& q : out.drawing.contours[0].loops[0].q) {
        lo = std::min(lo, glm::length(q - centre));
        hi = std::max(hi, glm::length(q - centre));
    }
    EXPECT_LT(hi - lo, 0.02 * hi);
}

TEST(Degenerate, LightAtTheEyeCastsItsShadowOnTheSilhouette) {
    // A point light at a perspective eye: N.(L - p) is N.(E - p), so the
    // shadow boundary is the silhouette itself. Every shadow snaxel lies on
    // the visual contour (within an edge of a visual snaxel).
    const Scene s = scene_of(make_procedural("torus:8000"));
    const glm::dvec3 eye(0.5, 2.5, 3.0);
    Light light;
    light.point = true;
    light.pos = eye;
    const StillOutput out =
        draw(s, perspective(eye, {0.0, 0.0, 0.0}), light, {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}});
    expect_finite_drawing(out);
    const SnaxelEngine engine(s.topology);
    ASSERT_GT(snaxel_count(out.results[0]), 0u);
    double edge = 0.0;
    for (FaceId f(0); f < FaceId(50); ++f)
        edge = std::max(edge, glm::length(s.topology.positions()[s.topology.face_vertices()[f][0]] -
                                          s.topology.positions()[s.topology.face_vertices()[f][1]]));
    for (const auto& sh : out.results[1].fronts.snaxels) {
        const glm::dvec3 p = engine.position(sh);
        double nearest = 1e300;
        for (const auto& v : out.results[0].fronts.snaxels) nearest = std::min(nearest, glm::length(engine.position(v) - p));
        ASSERT_LT(nearest, edge) << "a shadow point off the silhouette";
    }
}

TEST(Degenerate, PointLightOnTheSurfaceLightsOnlyItsSpot) {
    // A point light on the unit sphere lights no part of it but the point
    // itself ((p - c).(L - p) = (p - c).(L - c) - 1 <= 0): shadow, isophote
    // and gleam contours draw, and whatever shadow boundary the facets leave
    // lies next to the light.
    const Scene s = scene_of(make_procedural("sphere:8000"));
    Light light;
    light.point = true;
    light.pos = s.topology.positions()[VertexId(0)];
    Camera c;
    c.view_dir = -glm::normalize(light.pos + glm::dvec3(0.3, 0.2, 0.0));
    const StillOutput out = draw(s, c, light,
                                 {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0},
                                  ContourSpec{ContourKind::Isophote, 0.5}, ContourSpec{ContourKind::Gleam, 0.9}},
                                 toon());
    expect_finite_drawing(out);
    const SnaxelEngine engine(s.topology);
    for (const auto& sh : out.results[1].fronts.snaxels) EXPECT_LT(glm::length(engine.position(sh) - light.pos), 0.1);
    EXPECT_EQ(out.results[0].fronts.loops.size(), 1u);
}

TEST(Degenerate, FarFromTheOriginOrTinyDrawsAsAtHome) {
    // Embree works in float; the ray scene re-centres, so a torus 1e7 away or
    // a millionth the size classifies its hidden lines as the one at home.
    const TriangleSoup home = make_procedural("torus:8000");
    Camera c;
    c.view_dir = glm::normalize(glm::dvec3(0.0, -1.0, -0.4)); // nearly edge-on: the ring hides its far side
    const Light light = directional({0.3, 0.6, 0.7});
    const std::vector<ContourSpec> kinds{ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}};
    const StillOutput base = draw(scene_of(home), c, light, kinds);
    auto hidden = [](const StillOutput& o, std::size_t k) {
        std::size_t n = 0, all = 0;
        for (const auto& lv : o.visibility[k].loops)
            for (const int qi : lv.snaxel_qi) {
                n += qi > 0;
                ++all;
            }
        return std::pair{n, all};
    };
    ASSERT_GT(hidden(base, 0).first, 50u); // the far side of the ring is hidden
    for (const auto& [scale, offset] : {std::pair{1.0, glm::dvec3(1e7, -2e7, 3e7)}, std::pair{1e-6, glm::dvec3(0.0)},
                                         std::pair{1e-6, glm::dvec3(5.0, 5.0, 5.0)}}) {
        const StillOutput out = draw(scene_of(moved(home, scale, offset)), c, light, kinds);
        expect_finite_drawing(out);
        for (std::size_t k = 0; k < kinds.size(); ++k) {
            const auto [n0, all0] = hidden(base, k);
            const auto [n, all] = hidden(out, k);
            EXPECT_EQ(all, all0) << "scale " << scale << " offset " << offset.x;
            EXPECT_NEAR(double(n), double(n0), 0.01 * double(all0) + 2) << "scale " << scale << " offset " << offset.x;
        }
        // The picture is the same picture (the canvas fits the mesh): every
        // drawn point within a hundredth of a pixel of one drawn at home.
        std::vector<glm::dvec2> at_home;
        for (const auto& loop : base.drawing.contours[0].loops) at_home.insert(at_home.end(), loop.q.begin(), loop.q.end());
        std::size_t points = 0;
        for (const auto& loop : out.drawing.contours[0].loops)
            for (const auto& q : loop.q) {
                double nearest = 1e300;
                for (const auto& h : at_home) nearest = std::min(nearest, glm::length(q - h));
                EXPECT_LT(nearest, 0.01) << "scale " << scale << " offset " << offset.x;
                ++points;
            }
        EXPECT_EQ(points, at_home.size());
    }
}

TEST(Degenerate, SingleTriangleDraws) {
    TriangleSoup soup;
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    soup.triangles = {{0, 1, 2}};
    const Scene s = scene_of(soup);
    for (const glm::dvec3 dir : {glm::dvec3(0, 0, -1), glm::dvec3(0, 0, 1), glm::dvec3(1, 0, 0)}) {
        Camera c;
        c.view_dir = dir;
        const StillOutput out = draw(s, c, directional({0.2, 0.3, 1.0}),
                                     {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}}, toon());
        expect_finite_drawing(out);
        // One flat face has one normal: N.V never changes sign across it.
        EXPECT_EQ(out.results[0].fronts.loops.size(), 0u);
    }
}

TEST(Degenerate, DuplicateAndCoincidentFacesDraw) {
    // A closed box, one face repeated, one repeated with its winding flipped,
    // and a second box lying exactly on the first.
    TriangleSoup box = make_procedural("sphere:600");
    TriangleSoup soup = box;
    soup.triangles.push_back(box.triangles[0]);
    soup.triangles.push_back({box.triangles[5][0], box.triangles[5][2], box.triangles[5][1]});
    const auto base = std::uint32_t(soup.positions.size());
    soup.positions.insert(soup.positions.end(), box.positions.begin(), box.positions.end());
    for (const auto& t : box.triangles) soup.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    const Scene s = scene_of(soup);
    EXPECT_GT(s.mesh.report.split_vertices + s.mesh.report.dropped_faces, 0u);
    Camera c;
    c.view_dir = glm::normalize(glm::dvec3(0.3, -0.2, -1.0));
    const StillOutput out = draw(s, c, directional({0.3, 0.6, 0.7}),
                                 {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}}, toon());
    expect_finite_drawing(out);
    EXPECT_GE(out.results[0].fronts.loops.size(), 1u);
}

TEST(Degenerate, AThousandOneTriangleComponentsDraw) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    TriangleSoup soup;
    for (std::uint32_t k = 0; k < 1000; ++k) {
        const glm::dvec3 at(u(rng) * 10, u(rng) * 10, u(rng) * 10);
        for (int i = 0; i < 3; ++i) soup.positions.push_back(at + 0.3 * glm::dvec3(u(rng), u(rng), u(rng)));
        soup.triangles.push_back({3 * k, 3 * k + 1, 3 * k + 2});
    }
    const Scene s = scene_of(soup);
    EXPECT_EQ(s.mesh.report.components, 1000u);
    const StillOutput out =
        draw(s, Camera{}, directional({0.3, 0.6, 0.7}), {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0}}, toon());
    expect_finite_drawing(out);
    EXPECT_EQ(out.results[0].fronts.loops.size(), 0u); // flat faces, no silhouette across any
}

TEST(Degenerate, NeedleAndCapTrianglesDraw) {
    // A sphere with every seventh face split at an inner point a billionth
    // from a corner (two needles and a full face) and every other seventh
    // at an inner point a billionth from an edge's midpoint (a cap, its
    // angle a hair under 180 degrees): the mesh stays closed, the welded
    // mesh keeps them, and the engine's invariants hold on it.
    TriangleSoup soup = make_procedural("sphere:3000");
    const std::size_t n = soup.triangles.size();
    for (std::size_t f = 0; f < n; f += 7) {
        const auto t = soup.triangles[f];
        const glm::dvec3 a = soup.positions[t[0]], b = soup.positions[t[1]], c = soup.positions[t[2]];
        const glm::dvec3 inner = (f / 7) % 2 == 0 ? a + 1e-9 * (b - a) + 1e-9 * (c - a)
                                                  : 0.5 * (b + c) + 1e-9 * (a - 0.5 * (b + c));
        const auto p = std::uint32_t(soup.positions.size());
        soup.positions.push_back(inner);
        soup.triangles[f] = {t[0], t[1], p};
        soup.triangles.push_back({t[1], t[2], p});
        soup.triangles.push_back({t[2], t[0], p});
    }
    const Scene s = scene_of(soup);
    for (const glm::dvec3 dir : {glm::dvec3(0, 0, 1), glm::dvec3(0.4, -0.3, -0.8)}) {
        Camera c;
        c.view_dir = glm::normalize(dir);
        const StillOutput out = draw(s, c, directional({0.3, 0.6, 0.7}),
                                     {ContourSpec{}, ContourSpec{ContourKind::Shadow, 0.0},
                                      ContourSpec{ContourKind::Isophote, 0.5}},
                                     toon());
        expect_finite_drawing(out);
        EXPECT_EQ(out.results[0].fronts.loops.size(), 1u);
    }
}

TEST(Degenerate, MoreFacesThanTheMachineCanDrawAreRefusedFirst) {
    // SNAXELS_MEMORY_MB stands in for the machine: 200,000 faces at the
    // estimate need more than 64 MB.
    const TriangleSoup soup = make_procedural("sphere:200000");
    ::setenv("SNAXELS_MEMORY_MB", "64", 1);
    std::string message;
    try {
        build_mesh(soup, "big");
    } catch (const Error& e) {
        message = e.what();
    }
    ::unsetenv("SNAXELS_MEMORY_MB");
    EXPECT_NE(message.find("faces need an estimated"), std::string::npos) << message;
    EXPECT_NE(message.find("more than this machine's 64 MB"), std::string::npos) << message;
    EXPECT_NO_THROW(build_mesh(soup, "big"));
}
