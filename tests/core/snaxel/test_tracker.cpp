#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include <glm/gtx/rotate_vector.hpp>

#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/tracker.h"
#include "tests/support/assets.h"
#include "tests/support/plain_mesh.h"
#include "tests/support/fronts_oracle.h"
#include "tests/support/oracle_setup.h"

using namespace snaxels;

namespace {

Camera turntable_camera(int frame, double degrees_per_frame) {
    Camera cam;
    const glm::dvec3 start = glm::normalize(glm::dvec3(0.3, -0.35, 1.0));
    cam.view_dir = glm::rotate(start, glm::radians(degrees_per_frame * frame), glm::dvec3(0, 1, 0));
    return cam;
}

LoadedMesh load(const std::string& spec) {
    return load_mesh(spec.rfind("proc:", 0) == 0 ? spec : test::asset(spec));
}

} // namespace

class TurntableTracking : public ::testing::TestWithParam<std::string> {};

// Done-when 1: at every frame of a 360-frame turntable the tracked snaxels
// are exactly the brute-force oracle's crossings of that frame.
TEST_P(TurntableTracking, EqualsRecomputationAtEveryFrame) {
    const LoadedMesh m = load(GetParam());
    const MeshTopology topo = build_topology(m.mesh);
    const SnaxelEngine engine(topo);
    EngineOptions options;
    options.check_invariants = false;
    ContourTracker tracker(topo, ContourSpec{}, options);
    const Light light;
    std::size_t total_fanouts = 0;
    for (int frame = 0; frame < 360; ++frame) {
        const Camera cam = turntable_camera(frame, 1.0);
        const TrackedFrame& tf = tracker.step(cam, light);
        // Visual contours have one crossing per edge: no scan needed.
        ASSERT_TRUE(test::fronts_match_oracle(topo, engine, tf.contour.fronts, cam, light)) << "frame " << frame;
        // Identities are unique within a frame.
        std::set<std::uint64_t> ids(tf.snaxel_id.begin(), tf.snaxel_id.end());
        ASSERT_EQ(ids.size(), tf.snaxel_id.size()) << "frame " << frame;
        total_fanouts += tf.fanouts + tf.retreats;
    }
    EXPECT_GT(total_fanouts, 0u);
}

INSTANTIATE_TEST_SUITE_P(Meshes, TurntableTracking,
                         ::testing::Values("horse.ply", "spot.obj", "fandisk.obj", "proc:bumpy:40000"),
                         [](const auto& p) { return test::test_name(p.param); });

// Done-when 2: events of every kind occur, and every frame balances:
// loops(t+1) = loops(t) + creations + splits - merges - annihilations.
TEST(Tracking, EventsBalanceTheLoopCount) {
    std::map<EventKind, std::size_t> seen;
    for (const std::string spec : {"proc:torus:20000", "proc:nose:40000"}) {
        const LoadedMesh m = load(spec);
        const MeshTopology topo = build_topology(m.mesh);
        EngineOptions options;
        options.check_invariants = true; // tracked fronts checked every frame too
        ContourTracker tracker(topo, ContourSpec{}, options);
        std::size_t loops = 0;
        for (int frame = 0; frame < 180; ++frame) {
            // Orbit around an axis tilted off the torus's, so its silhouette
            // passes through every kind of change.
            Camera cam;
            cam.view_dir = glm::rotate(glm::dvec3(0, 0, 1), glm::radians(2.0 * frame),
                                       glm::normalize(glm::dvec3(1.0, 0.35, 0.0)));
            const TrackedFrame& tf = tracker.step(cam, Light{});
            std::map<EventKind, long> count;
            for (const VisualEvent& e : tf.events) {
                ++count[e.kind];
                ++seen[e.kind];
                EXPECT_EQ(e.frame, frame);
            }
            if (frame > 0) {
                const long expected = long(loops) + count[EventKind::Creation] + count[EventKind::Split] -
                                      count[EventKind::Merge] - count[EventKind::Annihilation];
                ASSERT_EQ(long(tf.contour.fronts.loops.size()), expected) << spec << " frame " << frame;
            }
            loops = tf.contour.fronts.loops.size();
        }
    }
    for (const EventKind kind : {EventKind::Creation, EventKind::Annihilation, EventKind::Split, EventKind::Merge})
        EXPECT_GT(seen[kind], 0u) << event_name(kind);
}

// A snaxel that stays on its edge keeps its identity; sequences persist
// while a loop neither splits nor merges.
TEST(Tracking, SmallMotionKeepsIdentitiesAndSequences) {
    const LoadedMesh m = load("proc:sphere:20000");
    const MeshTopology topo = build_topology(m.mesh);
    ContourTracker tracker(topo, ContourSpec{});
    const TrackedFrame first = tracker.step(turntable_camera(0, 0.2), Light{});
    const TrackedFrame& second = tracker.step(turntable_camera(1, 0.2), Light{});
    ASSERT_EQ(second.contour.fronts.loops.size(), 1u);
    EXPECT_EQ(second.loop_sequence[0], first.loop_sequence[0]);
    EXPECT_TRUE(second.events.empty());
    std::set<std::uint64_t> before(first.snaxel_id.begin(), first.snaxel_id.end());
    std::size_t kept = 0;
    for (const auto id : second.snaxel_id) kept += before.count(id);
    EXPECT_GT(kept, second.snaxel_id.size() * 8 / 10);
}

// A tracked snaxel that stays on its edge takes on the arc between the
// edge's normals from the frame before (its root's closed form starts
// from it) while the mesh keeps its pose, and works it out again in a new
// pose. Either way every root is, to the bit, the one a computation from
// scratch finds: with an orthographic camera and a directional light, for
// each kind that has a closed form, through a turntable in one pose and
// then through poses whose normals differ.
TEST(ContourTracker, TrackedRootsAreTheRootsComputedFromScratchToTheBit) {
    const LoadedMesh m = load("spot.obj");
    const MeshTopology rest = build_topology(m.mesh);
    EngineOptions options;
    options.check_invariants = false;
    const std::vector<ContourSpec> kinds{ContourSpec{}, {ContourKind::Shadow, 0.0}, {ContourKind::Isophote, 0.5},
                                         {ContourKind::Gleam, 0.9}};
    std::vector<ContourTracker> trackers;
    for (const ContourSpec& k : kinds) trackers.emplace_back(rest, k, options);
    MeshTopology topo = rest;
    std::size_t compared = 0;
    for (int frame = 0; frame < 60; ++frame) {
        if (frame >= 40) { // a new pose every frame: the normals turn a little, differently per vertex
            auto pose = std::make_shared<MeshPose>(*rest.pose());
            for (const VertexId v : rest.vertices()) {
                const glm::dvec3 p = rest.positions()[v];
                const glm::dvec3 lean(0.02 * (frame - 39) * std::sin(7.0 * p.y), 0.0, 0.02 * std::cos(5.0 * p.x));
                pose->normals[v] = glm::normalize(rest.normals()[v] + lean);
            }
            topo = rest.posed(pose);
        }
        const Camera cam = turntable_camera(frame, 1.5);
        Light light;
        light.dir = glm::normalize(glm::dvec3(-0.4, 0.8, 0.6));
        const SnaxelEngine engine(topo);
        for (std::size_t k = 0; k < kinds.size(); ++k) {
            const TrackedFrame& tracked = frame >= 40 ? trackers[k].step(topo, cam, light) : trackers[k].step(cam, light);
            const ContourResult fresh = engine.compute(kinds[k], cam, light, options);
            std::map<std::int32_t, const Snaxel*> by_edge;
            for (const Snaxel& s : fresh.fronts.snaxels) by_edge[s.edge.index()] = &s;
            ASSERT_EQ(tracked.contour.fronts.snaxels.size(), fresh.fronts.snaxels.size()) << "frame " << frame << ", kind " << k;
            for (const Snaxel& s : tracked.contour.fronts.snaxels) {
                const auto it = by_edge.find(s.edge.index());
                ASSERT_NE(it, by_edge.end()) << "frame " << frame << ", kind " << k;
                ASSERT_EQ(s.inside, it->second->inside);
                ASSERT_EQ(s.t, it->second->t) << "frame " << frame << ", kind " << k << ", edge " << s.edge.index();
                ++compared;
            }
        }
    }
    EXPECT_GT(compared, 10000u);
}
