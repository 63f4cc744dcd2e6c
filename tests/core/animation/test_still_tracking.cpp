// The application's view tracks its contours from one still frame to the
// next (StillTracking): what it draws must be what a computation from
// scratch draws, at every step, through orbits of a perspective camera,
// light turns, a far jump, kinds added and dropped; small steps are
// tracked and far ones start anew.

#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/animation/still.h"
#include "snaxels/mesh/import.h"
#include "snaxels/scene/orbit.h"
#include "snaxels/visibility/ray_scene.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

// The snaxels of @p r as (edge, inside vertex, t), sorted: fronts compared
// independently of their order in memory.
std::vector<std::tuple<EdgeId, VertexId, double>> crossings(const ContourResult& r) {
    std::vector<std::tuple<EdgeId, VertexId, double>> out;
    for (const Snaxel& s : r.fronts.snaxels) out.emplace_back(s.edge, s.inside, s.t);
    std::sort(out.begin(), out.end());
    return out;
}

// The points a contour draws, each with its quantitative invisibility,
// sorted: the drawing independently of where its loops start.
std::vector<std::tuple<double, double, int>> drawn(const DrawnContour& c) {
    std::vector<std::tuple<double, double, int>> out;
    for (const DrawnLoop& loop : c.loops)
        for (std::size_t i = 0; i < loop.q.size(); ++i)
            out.emplace_back(loop.q[i].x, loop.q[i].y, loop.qi.empty() ? -1 : loop.qi[i]);
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

TEST(StillTracking, TrackedStillsEqualStillsFromScratch) {
    const LoadedMesh mesh = load_mesh(test::asset("spot.obj"));
    const MeshTopology topo = build_topology(mesh.mesh);
    const RayScene rays(topo);
    const Style shading = load_style(std::string(SNAXELS_STYLES_DIR) + "/shading-lines.xml", nullptr);
    const Style toon = load_style(std::string(SNAXELS_STYLES_DIR) + "/toon.xml", nullptr);
    const glm::dvec3 centre = 0.5 * (mesh.report.bbox_min + mesh.report.bbox_max);
    OrbitView view = framing_view(centre, 0.5 * glm::length(mesh.report.bbox_max - mesh.report.bbox_min));
    StillTracking tracking;
    glm::dvec3 light_dir(-1.0, 1.0, 1.0);
    std::size_t compared = 0;
    for (int step = 0; step < 40; ++step) {
        // Orbit a degree a step, turn the light from step 10, jump at 20,
        // draw the toon preset (its fills track visual and shadow) from 30.
        view.yaw += glm::radians(step == 20 ? 90.0 : 1.0);
        if (step >= 10) light_dir = glm::rotate(light_dir, glm::radians(2.0), glm::dvec3(0.0, 1.0, 0.0));
        Light light;
        light.dir = light_dir;
        const StillJob job = make_still_job(step < 30 ? shading : toon, orbit_camera(view), light);
        const StillOutput tracked = render_still(mesh, topo, &rays, job, &tracking);
        const StillOutput fresh = render_still(mesh, topo, &rays, job);
        ASSERT_EQ(tracked.results.size(), fresh.results.size());
        for (std::size_t c = 0; c < fresh.results.size(); ++c) {
            const auto a = crossings(tracked.results[c]), b = crossings(fresh.results[c]);
            ASSERT_EQ(a.size(), b.size()) << "step " << step << " " << fresh.results[c].spec.label();
            for (std::size_t i = 0; i < a.size(); ++i) {
                ASSERT_EQ(std::get<0>(a[i]), std::get<0>(b[i])) << "step " << step;
                ASSERT_EQ(std::get<1>(a[i]), std::get<1>(b[i])) << "step " << step;
                ASSERT_NEAR(std::get<2>(a[i]), std::get<2>(b[i]), 1e-9) << "step " << step;
            }
            ++compared;
        }
        // The drawing: the same points with the same visibility, and the
        // same SVG (loops in the same order from the same snaxels).
        for (std::size_t c = 0; c < fresh.drawing.contours.size(); ++c)
            EXPECT_EQ(drawn(tracked.drawing.contours[c]), drawn(fresh.drawing.contours[c])) << "step " << step;
        EXPECT_TRUE(tracked.svg == fresh.svg) << "step " << step;
        // The fills: the same regions, class by class, of the same area.
        ASSERT_EQ(tracked.regions.size(), fresh.regions.size()) << "step " << step;
        std::map<std::pair<int, double>, double> area_a, area_b;
        for (const MapRegion& r : tracked.regions) area_a[{int(r.cls), r.k}] += r.area;
        for (const MapRegion& r : fresh.regions) area_b[{int(r.cls), r.k}] += r.area;
        ASSERT_EQ(area_a.size(), area_b.size());
        for (const auto& [key, area] : area_b) EXPECT_NEAR(area_a[key], area, 1e-6 * area + 1e-9) << "step " << step;
    }
    EXPECT_EQ(compared, 30u * 5u + 10u * 1u);
    // Five kinds start at step 0 and again after the 90-degree jump; the
    // toon preset's visual contour and the shadow its fills need go on.
    EXPECT_EQ(tracking.restarts(), 10u);
    EXPECT_EQ(tracking.tracked_steps(), 19u * 5u + 9u * 5u + 10u * 2u);
}
