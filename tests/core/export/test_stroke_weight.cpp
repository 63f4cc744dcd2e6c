#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/export/stroke_parameter.h"
#include "snaxels/export/stroke_shape.h"
#include "snaxels/export/stroke_weight.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/suggestive.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/style/style.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

Style parse(const std::string& visible) {
    return parse_style("<style version=\"1\"><contour kind=\"visual\"><visible " + visible + "/></contour></style>", "test", nullptr);
}

double polygon_area(const std::vector<glm::dvec2>& p) {
    double a = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const glm::dvec2 u = p[i], v = p[(i + 1) % p.size()];
        a += u.x * v.y - v.x * u.y;
    }
    return std::abs(a) / 2.0;
}

std::vector<StrokePoint> straight(double length, int points) {
    std::vector<StrokePoint> c;
    for (int i = 0; i < points; ++i) {
        const double s = length * i / (points - 1);
        c.push_back({{10.0 + s, 20.0}, s, 1.0});
    }
    return c;
}

} // namespace

TEST(LineWeight, StyleAttributes) {
    const StrokeStyle s = parse("width=\"2\" taper=\"12 25%\" width-by=\"depth\" width-min=\"1\" width-max=\"4\" "
                                "calligraphy=\"30 0.4\" wobble=\"1.5 40\" boil=\"8\"").contours[0].visible;
    EXPECT_DOUBLE_EQ(s.taper_start, 12.0);
    EXPECT_FALSE(s.taper_start_fraction);
    EXPECT_DOUBLE_EQ(s.taper_end, 0.25);
    EXPECT_TRUE(s.taper_end_fraction);
    EXPECT_EQ(s.width_by, StrokeStyle::WidthBy::Depth);
    EXPECT_DOUBLE_EQ(s.min_width(), 1.0);
    EXPECT_DOUBLE_EQ(s.max_width(), 4.0);
    EXPECT_DOUBLE_EQ(s.calligraphy_angle, 30.0);
    EXPECT_DOUBLE_EQ(s.calligraphy_ratio, 0.4);
    EXPECT_DOUBLE_EQ(s.wobble_amplitude, 1.5);
    EXPECT_DOUBLE_EQ(s.wobble_wavelength, 40.0);
    EXPECT_DOUBLE_EQ(s.boil_rate, 8.0);
    EXPECT_TRUE(s.variable_width());
    // One taper length serves both ends; wobble alone keeps a stroke.
    const StrokeStyle one = parse("taper=\"10%\"").contours[0].visible;
    EXPECT_DOUBLE_EQ(one.taper_end, 0.1);
    EXPECT_TRUE(one.taper_end_fraction);
    const StrokeStyle wobbly = parse("wobble=\"1 20\"").contours[0].visible;
    EXPECT_FALSE(wobbly.variable_width());
    EXPECT_TRUE(wobbly.needs_parameter());
    // Hidden lines' default dashes give way to line weight.
    const Style hidden = parse_style("<style version=\"1\"><contour kind=\"visual\"><hidden taper=\"5\"/></contour></style>", "test", nullptr);
    EXPECT_TRUE(hidden.contours[0].hidden.dash.empty());
    // Without the attributes nothing reads the parameter.
    EXPECT_FALSE(parse("width=\"2\"").contours[0].visible.needs_parameter());
    // Bad values are named.
    for (const char* bad : {"taper=\"x\"", "taper=\"1 2 3\"", "taper=\"150%\"", "width-by=\"speed\"",
                            "calligraphy=\"30\"", "calligraphy=\"30 0\"", "wobble=\"1\"", "wobble=\"1 0.5\"",
                            "width-min=\"3\" width-max=\"2\"", "boil=\"-1\"", "dash=\"4 3\" taper=\"5\"",
                            "dash=\"4 3\" wobble=\"1 20\""}) {
        try {
            parse(bad);
            ADD_FAILURE() << bad << " was accepted";
        } catch (const StyleError& e) {
            const std::string name = std::string(bad).substr(0, std::string(bad).find('='));
            EXPECT_NE(std::string(e.what()).find(name.substr(0, 5)), std::string::npos) << e.what();
        }
    }
}

TEST(LineWeight, OutlineFollowsTheWidth) {
    StrokeStyle s;
    s.width = 4.0;
    s.cap = "butt";
    s.taper_start = 10.0;
    s.taper_end = 10.0;
    std::vector<std::vector<glm::dvec2>> out;
    stroke_outline(s, straight(40.0, 81), false, out);
    ASSERT_EQ(out.size(), 1u);
    // Width w(x) = 4 E(x/10) E((40-x)/10), E(t) = t(2-t): its integral is
    // 4 (20 + 2 * 10 * 2/3) = 133.3.
    EXPECT_NEAR(polygon_area(out[0]), 4.0 * (20.0 + 2.0 * 10.0 * 2.0 / 3.0), 0.5);
    // Vertex counts depend only on the centre's: keys of an animation interpolate.
    std::vector<std::vector<glm::dvec2>> bent;
    std::vector<StrokePoint> c = straight(40.0, 81);
    for (std::size_t i = 0; i < c.size(); ++i) c[i].q.y += 5.0 * std::sin(0.2 * double(i));
    s.cap = "round";
    stroke_outline(s, c, false, bent);
    out.clear();
    stroke_outline(s, straight(3.0, 81), false, out);
    EXPECT_EQ(bent[0].size(), out[0].size());
    // A run of no length has no width: no dot where a run appears.
    out.clear();
    s.taper_start = s.taper_end = 0.0;
    stroke_outline(s, straight(0.0, 5), false, out);
    EXPECT_LT(polygon_area(out[0]), 1e-9);
    // A closed ring: an outer and an inner (reversed) ring, a band of the width.
    std::vector<StrokePoint> ring;
    for (int i = 0; i < 400; ++i) {
        const double a = 6.283185307179586 * i / 400;
        ring.push_back({{100.0 + 50.0 * std::cos(a), 100.0 + 50.0 * std::sin(a)}, 50.0 * a, 1.0});
    }
    out.clear();
    s.width = 3.0;
    stroke_outline(s, ring, true, out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_NEAR(polygon_area(out[0]) - polygon_area(out[1]), 6.283185307179586 * 50.0 * 3.0, 5.0);
}

// Done-when 2: the surface point under a fixed u moves with the surface.
// On a horse turntable, for every snaxel that goes on from one frame to the
// next, the point of the next frame's loop at the u the snaxel had is found
// (this test's own interpolation) and its distance to where the snaxel is
// now measured: how far the parameter slid along the line.
TEST(LineWeight, ParameterStaysOnTheSurface) {
    const LoadedMesh m = import_mesh(test::asset("horse.ply"));
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    ContourTracker tracker(topo, ContourSpec{});
    const glm::dvec3 centre = 0.5 * (m.report.bbox_min + m.report.bbox_max);
    const double radius = 0.5 * glm::length(m.report.bbox_max - m.report.bbox_min);
    const glm::dvec3 up(0.0, 0.0, 1.0), start = glm::normalize(glm::dvec3(1.0, 0.2, 0.3));
    StrokeParameter parameter;
    std::unordered_map<std::uint64_t, double> before; // id -> u last frame
    std::vector<double> slides;
    for (int k = 0; k < 120; ++k) {
        Camera cam;
        cam.view_dir = -glm::rotate(start, glm::radians(1.0 * k), up);
        cam.up = up;
        const TrackedFrame& tf = tracker.step(cam, default_light(cam));
        const ImageProjection proj(cam, centre, radius, 800, 800);
        Drawing d = make_drawing(engine, {tf.contour}, proj);
        std::vector<AnimatedLoop> loops;
        for (std::size_t l = 0; l < tf.contour.fronts.loops.size(); ++l) {
            AnimatedLoop al;
            tf.contour.fronts.for_each_in_loop(tf.contour.fronts.loops[l], [&](std::int32_t s) { al.ids.push_back(tf.snaxel_id[s]); });
            loops.push_back(std::move(al));
        }
        std::vector<std::vector<SurfacePoint>> surface(loops.size());
        for (std::size_t l = 0; l < loops.size(); ++l)
            tf.contour.fronts.for_each_in_loop(tf.contour.fronts.loops[l], [&](std::int32_t s) {
                const Snaxel& sn = tf.contour.fronts.snaxels[s];
                surface[l].push_back({sn.inside, sn.outside, sn.t});
            });
        parameter.step(d.contours[0], loops, &surface, [&](const SurfacePoint& sp) {
            return proj.project((1.0 - sp.t) * topo.positions()[sp.a] + sp.t * topo.positions()[sp.b]);
        });
        std::unordered_map<std::uint64_t, double> now;
        for (std::size_t l = 0; l < loops.size(); ++l) {
            const DrawnLoop& loop = d.contours[0].loops[l];
            const std::size_t n = loop.q.size();
            ASSERT_EQ(loop.u.size(), n);
            const double period = loop.u_period;
            for (std::size_t i = 0; i < n; ++i) now[loops[l].ids[i]] = loop.u[i];
            for (std::size_t i = 0; i < n; ++i) {
                const auto it = before.find(loops[l].ids[i]);
                if (it == before.end()) continue;
                const double u = it->second;
                // The segment of this loop whose u brackets u (unwrapped round a closed loop).
                double best = 1e300;
                const std::size_t segs = loop.closed ? n : n - 1;
                for (std::size_t j = 0; j < segs; ++j) {
                    double a = loop.u[j], b = loop.u[(j + 1) % n];
                    if (loop.closed && period > 0.0 && b < a - 0.5 * period) b += period;
                    double target = u;
                    if (loop.closed && period > 0.0) target = a + std::fmod(std::fmod(u - a, period) + period, period);
                    if (target < std::min(a, b) || target > std::max(a, b) || b == a) continue;
                    const double f = (target - a) / (b - a);
                    const glm::dvec2 at = (1.0 - f) * loop.q[j] + f * loop.q[(j + 1) % n];
                    best = std::min(best, glm::length(at - loop.q[i]));
                }
                if (best < 1e299) slides.push_back(best);
            }
        }
        before = std::move(now);
    }
    ASSERT_GT(slides.size(), 10000u);
    std::sort(slides.begin(), slides.end());
    const double median = slides[slides.size() / 2], p95 = slides[slides.size() * 95 / 100];
    std::printf("horse turntable, 1 degree a frame, 120 frames: %zu snaxels carried; the parameter slides "
                "%.3f px a frame (median), %.3f px (95th percentile) against the surface\n",
                slides.size(), median, p95);
    EXPECT_LE(median, 1.0);
    EXPECT_LE(p95, 3.0);
}

// A still's parameter is arc length from the first snaxel.
TEST(LineWeight, StillParameterIsArcLength) {
    DrawnContour c;
    DrawnLoop l;
    l.closed = true;
    l.q = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
    c.loops.push_back(l);
    parameterize_still(c);
    EXPECT_EQ(c.loops[0].u, (std::vector<double>{0, 10, 20, 30}));
    EXPECT_DOUBLE_EQ(c.loops[0].u_period, 40.0);
    const LoopAttributes at(c.loops[0]);
    EXPECT_DOUBLE_EQ(at.at(35.0).u, 35.0);
    EXPECT_NEAR(at.at(35.0).q.y, 5.0, 1e-12);
}

// width-by="strength" on a suggestive contour fades it as rtsc does: each
// drawn snaxel's weight is m / (fade + m), m how far it passes its test
// (read here from the engine's margins where the test, not the view, sets
// them), 0 where it is not drawn; the weights span the range.
TEST(LineWeight, StrengthFadesSuggestiveContours) {
    const LoadedMesh horse = load_mesh(test::asset("horse.ply"));
    const MeshTopology topo = build_topology(horse.mesh);
    const SnaxelEngine engine(topo);
    const Style style = parse_style(R"(<style version="1"><contour kind="suggestive" test="rtsc" fade="0.05">
        <visible width-by="strength" width-min="0" width-max="2"/></contour></style>)", "test", nullptr);
    Camera cam;
    cam.view_dir = glm::normalize(glm::dvec3(1.0, -0.3, -1.0));
    const ContourResult r = engine.compute(style.contours[0].spec, cam, Light{});
    const ImageProjection projection(cam, glm::dvec3(0.0), bounding_radius(topo), 800, 800, 32.0);
    Drawing drawing = make_drawing(engine, {r}, projection, nullptr);
    weigh_strokes(drawing, style, engine, {r}, cam, Light{}, glm::dvec3(0.0), bounding_radius(topo));
    ASSERT_EQ(drawing.contours.size(), 1u);
    std::size_t drawn = 0, checked = 0, faint = 0, strong = 0;
    const std::vector<double> strength = suggestive_strength(topo, *require_curvature(topo), r.fronts, cam, r.spec);
    for (std::size_t l = 0; l < r.fronts.loops.size(); ++l) {
        const DrawnLoop& loop = drawing.contours[0].loops[l];
        std::size_t k = 0;
        r.fronts.for_each_in_loop(r.fronts.loops[l], [&](std::int32_t s) {
            const float w = loop.weight[k++];
            const double margin = r.snaxel_margin[std::size_t(s)], m = strength[std::size_t(s)];
            ASSERT_GE(w, 0.0f);
            ASSERT_LT(w, 1.0f);
            EXPECT_FLOAT_EQ(w, m > 0.0 ? float(m / (0.05 + m)) : 0.0f);
            if (margin < 0.0) return;
            ++drawn;
            EXPECT_GT(w, 0.0f);
            // Where the margin is the test's, the weight is its fade.
            if (margin == strength[std::size_t(s)]) {
                EXPECT_FLOAT_EQ(w, float(margin / (0.05 + margin)));
                ++checked;
            }
            faint += w < 0.3f;
            strong += w > 0.7f;
        });
    }
    std::printf("horse: %zu drawn snaxels, %zu weights checked against the margins, %zu faint, %zu strong\n", drawn,
                checked, faint, strong);
    EXPECT_GT(checked, 200u);
    EXPECT_GT(faint, 20u);
    EXPECT_GT(strong, 20u);
}
