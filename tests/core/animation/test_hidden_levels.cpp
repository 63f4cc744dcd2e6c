// A still whose hidden lines are not drawn counts the hidden snaxels'
// levels only where the parts seen need them (StillJob::all_hidden_levels
// off, VisibilitySampler::HiddenLevels::WhereSeen). It must draw exactly
// what counting every level draws: the same SVG, the same runs seen with
// the same ends, in the same order, on meshes with many layers (the
// horse's legs, the teapot's handle and spout), hard-surface parts and a
// scene of several objects, from views all round.

#include <gtest/gtest.h>

#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/animation/still.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/scene/orbit.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

/// The runs seen of every loop of @p v, in order, with their points.
std::vector<std::vector<glm::dvec3>> seen_runs(const ContourVisibility& v) {
    std::vector<std::vector<glm::dvec3>> out;
    for (const LoopVisibility& loop : v.loops)
        for (const VisibilityRun& run : loop.runs)
            if (run.qi == 0) out.push_back(run.points);
    return out;
}

std::size_t hidden_snaxels(const ContourVisibility& v) {
    std::size_t n = 0;
    for (const LoopVisibility& loop : v.loops)
        for (const int q : loop.snaxel_qi) n += q > 0 && q != kNotDrawn;
    return n;
}

} // namespace

TEST(HiddenLevels, CountedWhereSeenDrawsWhatCountingAllDraws) {
    const Style shading = load_style(std::string(SNAXELS_STYLES_DIR) + "/shading-lines.xml", nullptr);
    const Style toon = load_style(std::string(SNAXELS_STYLES_DIR) + "/toon.xml", nullptr);
    const Style pencil = load_style(std::string(SNAXELS_STYLES_DIR) + "/pencil-sketch.xml", nullptr);
    std::size_t compared = 0, runs = 0, hidden = 0, level_changes = 0;
    for (const char* name : {"horse.ply", "teapot.obj", "fandisk.obj", "spot.obj", "parts/parts.dae"}) {
        const LoadedMesh loaded = load_mesh(test::asset(name));
        const glm::dvec3 centre = loaded.report.centre();
        const double radius = 0.5 * glm::length(loaded.report.bbox_max - loaded.report.bbox_min);
        for (const Style* style : {&shading, &toon, &pencil}) {
            std::optional<LoadedMesh> split;
            const LoadedMesh& surface = scene_surface(loaded, *style, split);
            const MeshTopology topo = engine_topology(surface);
            OrbitView view = framing_view(centre, radius);
            for (int k = 0; k < 6; ++k) {
                view.yaw += glm::radians(61.0);
                view.pitch = glm::radians(k % 2 ? 25.0 : -15.0);
                SCOPED_TRACE(std::string(name) + " view " + std::to_string(k));
                StillJob some = make_still_job(*style, orbit_camera(view), std::nullopt);
                ASSERT_FALSE(some.all_hidden_levels);
                StillJob all = some;
                all.all_hidden_levels = true;
                const StillOutput a = render_still(surface, topo, nullptr, all);
                const StillOutput b = render_still(surface, topo, nullptr, some);
                EXPECT_EQ(a.svg, b.svg);
                ASSERT_EQ(a.visibility.size(), b.visibility.size());
                for (std::size_t c = 0; c < a.visibility.size(); ++c) {
                    const auto ra = seen_runs(a.visibility[c]), rb = seen_runs(b.visibility[c]);
                    ASSERT_EQ(ra.size(), rb.size()) << a.results[c].spec.label();
                    for (std::size_t r = 0; r < ra.size(); ++r) ASSERT_EQ(ra[r], rb[r]) << a.results[c].spec.label();
                    runs += ra.size();
                    // Hidden stays hidden (only levels inside hidden stretches may differ).
                    EXPECT_EQ(hidden_snaxels(a.visibility[c]), hidden_snaxels(b.visibility[c]));
                    hidden += hidden_snaxels(a.visibility[c]);
                    for (const LoopVisibility& loop : a.visibility[c].loops)
                        for (std::size_t i = 1; i < loop.snaxel_qi.size(); ++i)
                            level_changes += loop.snaxel_qi[i] > 0 && loop.snaxel_qi[i - 1] > 0 &&
                                             loop.snaxel_qi[i] != kNotDrawn && loop.snaxel_qi[i - 1] != kNotDrawn &&
                                             loop.snaxel_qi[i] != loop.snaxel_qi[i - 1];
                    ++compared;
                }
            }
        }
    }
    std::printf("%zu contours compared: %zu runs seen, %zu hidden snaxels, %zu changes between hidden levels\n",
                compared, runs, hidden, level_changes);
    // The views hide a good part of the lines, at several levels.
    EXPECT_GT(hidden, 10000u);
    EXPECT_GT(level_changes, 50u);
}
