#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/export/stroke_dashes.h"
#include "snaxels/export/stroke_parameter.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/tracker.h"

using namespace snaxels;

namespace {

struct DriftResult {
    double mean = 0.0, median = 0.0;
    std::size_t ends = 0;
};

// A 120-frame sphere turntable seen from above, so the surface slides
// along the silhouette. For every dash start of frame k, the surface point
// under it is carried to frame k+1 (projected with that frame's camera onto
// its contour); the drift is how far the nearest dash start of frame k+1 is
// from there, in the dash measure. Surface dashes measure the stroke
// parameter carried by the snaxels (StrokeParameter), screen dashes arc
// length from the loop's first point.
DriftResult measure_drift(bool on_surface) {
    const LoadedMesh m = load_mesh("proc:sphere:20000");
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    ContourTracker tracker(topo, ContourSpec{});
    const double period = 12.0; // dash 8, gap 4
    StrokeParameter parameter;
    struct Frame {
        std::vector<glm::dvec2> q;
        std::vector<glm::dvec3> p;
        std::vector<double> u; ///< the dash measure at each point, unwrapped along the loop
        ImageProjection projection;
    };
    std::vector<Frame> frames;
    for (int k = 0; k < 120; ++k) {
        Camera cam;
        cam.view_dir = glm::rotate(glm::normalize(glm::dvec3(0.0, -0.6, 1.0)), glm::radians(3.0 * k), glm::dvec3(0, 1, 0));
        const TrackedFrame& tf = tracker.step(cam, Light{});
        const ImageProjection proj(cam, glm::dvec3(0.0), 1.0, 800, 800);
        EXPECT_EQ(tf.contour.fronts.loops.size(), 1u);
        Drawing d = make_drawing(engine, {tf.contour}, proj);
        AnimatedLoop al;
        tf.contour.fronts.for_each_in_loop(tf.contour.fronts.loops[0], [&](std::int32_t s) { al.ids.push_back(tf.snaxel_id[s]); });
        std::vector<std::vector<SurfacePoint>> surface(1);
        tf.contour.fronts.for_each_in_loop(tf.contour.fronts.loops[0], [&](std::int32_t s) {
            const Snaxel& sn = tf.contour.fronts.snaxels[s];
            surface[0].push_back({sn.inside, sn.outside, sn.t});
        });
        parameter.step(d.contours[0], {al}, &surface, [&](const SurfacePoint& sp) {
            return proj.project((1.0 - sp.t) * topo.positions()[sp.a] + sp.t * topo.positions()[sp.b]);
        });
        const DrawnLoop& loop = d.contours[0].loops[0];
        Frame f{loop.q, loop.p, {}, proj};
        // Screen dashes start at the loop's first point and measure arc
        // length; surface dashes measure the carried parameter.
        for (std::size_t i = 0; i < f.q.size(); ++i) {
            if (i == 0) {
                f.u.push_back(on_surface ? loop.u[0] : 0.0);
                continue;
            }
            double du = on_surface ? loop.u[i] - loop.u[i - 1] : glm::length(f.q[i] - f.q[i - 1]);
            if (on_surface && loop.u_period > 0.0) du -= loop.u_period * std::round(du / loop.u_period);
            f.u.push_back(f.u.back() + du);
        }
        frames.push_back(std::move(f));
    }
    std::vector<double> drifts;
    for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
        const Frame& a = frames[k];
        const Frame& b = frames[k + 1];
        // Dash starts of frame k: where its measure crosses a multiple of the period.
        for (std::size_t i = 0; i + 1 < a.q.size(); ++i) {
            const double m0 = a.u[i], m1 = a.u[i + 1];
            if (m1 <= m0 || std::floor(m1 / period) == std::floor(m0 / period)) continue;
            const double t = (std::floor(m1 / period) * period - m0) / (m1 - m0);
            const glm::dvec3 surface = (1.0 - t) * a.p[i] + t * a.p[i + 1];
            const glm::dvec2 carried = b.projection.project(surface);
            // Where it lands on frame k+1's contour, and the measure there.
            double best = 1e300, at = 0.0;
            for (std::size_t j = 0; j + 1 < b.q.size(); ++j) {
                const glm::dvec2 p0 = b.q[j], p1 = b.q[j + 1], d = p1 - p0;
                const double l2 = glm::dot(d, d);
                const double f = l2 > 0 ? std::clamp(glm::dot(carried - p0, d) / l2, 0.0, 1.0) : 0.0;
                const double dist = glm::length(carried - (p0 + f * d));
                if (dist < best) best = dist, at = (1.0 - f) * b.u[j] + f * b.u[j + 1];
            }
            if (best > 2.0) continue;
            const double r = std::fmod(std::fmod(at, period) + period, period);
            drifts.push_back(std::min(r, period - r));
        }
    }
    DriftResult out;
    out.ends = drifts.size();
    for (const double d : drifts) out.mean += d;
    out.mean /= std::max<std::size_t>(1, drifts.size());
    std::sort(drifts.begin(), drifts.end());
    out.median = drifts.empty() ? 0.0 : drifts[drifts.size() / 2];
    return out;
}

} // namespace

TEST(SurfaceDashes, FollowTheSurfaceWhileScreenDashesDoNot) {
    const DriftResult surface = measure_drift(true);
    const DriftResult screen = measure_drift(false);
    std::printf("dash-end drift per frame: surface mean %.3f px (median %.3f, %zu ends); screen mean %.3f px\n",
                surface.mean, surface.median, surface.ends, screen.mean);
    EXPECT_GT(surface.ends, 1000u);
    EXPECT_LT(surface.mean, 1.0);
    EXPECT_GT(screen.mean, 1.0);
}
