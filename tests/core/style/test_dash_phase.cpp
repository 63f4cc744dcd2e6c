#include <gtest/gtest.h>

#include <cmath>

#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/export/dash_phase.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/tracker.h"

using namespace snaxels;

namespace {

struct DriftResult {
    double mean = 0.0, median = 0.0;
    std::size_t ends = 0;
};

// Done-when 3: a 120-frame sphere turntable seen from above, so the surface
// slides along the silhouette. For every dash end of frame k, the surface
// point under it is carried to frame k+1 (projected with that frame's
// camera onto its contour); the drift is how far the nearest dash end of
// frame k+1 is from there, along the contour.
DriftResult measure_drift(bool on_surface) {
    const LoadedMesh m = load_mesh("proc:sphere:20000");
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    ContourTracker tracker(topo, ContourSpec{});
    const double period = 12.0; // dash 8, gap 4
    SurfaceDashPhase dashes(period);
    struct Frame {
        std::vector<glm::dvec2> q;
        std::vector<glm::dvec3> p;
        double phase = 0.0;
        ImageProjection projection;
    };
    std::vector<Frame> frames;
    for (int k = 0; k < 120; ++k) {
        Camera cam;
        cam.view_dir = glm::rotate(glm::normalize(glm::dvec3(0.0, -0.6, 1.0)), glm::radians(3.0 * k), glm::dvec3(0, 1, 0));
        const TrackedFrame& tf = tracker.step(cam, Light{});
        const ImageProjection proj(cam, glm::dvec3(0.0), 1.0, 800, 800);
        EXPECT_EQ(tf.contour.fronts.loops.size(), 1u);
        PhaseLoop loop;
        Frame f{{}, {}, 0.0, proj};
        tf.contour.fronts.for_each_in_loop(tf.contour.fronts.loops[0], [&](std::int32_t s) {
            const Snaxel& sn = tf.contour.fronts.snaxels[s];
            f.p.push_back(engine.position(sn));
            f.q.push_back(proj.project(f.p.back()));
            loop.surface.push_back({sn.inside, sn.outside, sn.t});
        });
        loop.q = f.q;
        const auto phases = dashes.step({loop}, [&](const SurfacePoint& sp) {
            return proj.project((1.0 - sp.t) * topo.positions()[sp.a] + sp.t * topo.positions()[sp.b]);
        });
        f.phase = on_surface ? phases[0] : 0.0; // screen dashes start at the loop's first point
        frames.push_back(std::move(f));
    }
    std::vector<double> drifts;
    for (std::size_t k = 0; k + 1 < frames.size(); ++k) {
        const Frame& a = frames[k];
        const Frame& b = frames[k + 1];
        const auto arc_a = arc_lengths(a.q), arc_b = arc_lengths(b.q);
        const double length_a = arc_a.back() + glm::length(a.q.front() - a.q.back());
        // Dash starts of frame k: arc s with (phase + s) a multiple of the period.
        for (double s = std::fmod(period - a.phase, period); s < length_a; s += period) {
            std::size_t i = 0;
            while (i + 1 < a.q.size() && arc_a[i + 1] < s) ++i;
            const std::size_t j = (i + 1) % a.q.size();
            const double seg = glm::length(a.q[j] - a.q[i]);
            const double t = seg > 0 ? std::clamp((s - arc_a[i]) / seg, 0.0, 1.0) : 0.0;
            const glm::dvec3 surface = (1.0 - t) * a.p[i] + t * a.p[j];
            const glm::dvec2 carried = b.projection.project(surface);
            // Where it lands on frame k+1's contour.
            double best = 1e300, s_b = 0.0;
            for (std::size_t u = 0; u < b.q.size(); ++u) {
                const glm::dvec2 p0 = b.q[u], p1 = b.q[(u + 1) % b.q.size()], d = p1 - p0;
                const double l2 = glm::dot(d, d);
                const double f = l2 > 0 ? std::clamp(glm::dot(carried - p0, d) / l2, 0.0, 1.0) : 0.0;
                const double dist = glm::length(carried - (p0 + f * d));
                if (dist < best) best = dist, s_b = (u < arc_b.size() ? arc_b[u] : 0.0) + f * std::sqrt(l2);
            }
            if (best > 2.0) continue;
            const double r = std::fmod(b.phase + s_b, period);
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
