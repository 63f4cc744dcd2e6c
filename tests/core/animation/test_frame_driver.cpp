#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

#include "snaxels/error.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/mesh/procedural.h"
#include "snaxels/animation/frame_driver.h"
#include "snaxels/animation/scene_settings.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/style/style.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/snaxel/tracker.h"
#include "tests/support/assets.h"
#include "tests/support/plain_mesh.h"
#include "tests/support/oracle_setup.h"

using namespace snaxels;

namespace {

// Tracks the visual contour of a mesh animation and checks every frame
// against the oracle on the posed mesh; returns how far the mesh moved.
double track_clip(const std::string& path, const std::string& clip, int frames, double fps) {
    const LoadedMesh mesh = import_mesh(path);
    const MeshTopology rest_topo = build_topology(mesh.mesh);
    const std::span<const glm::dvec3> rest = rest_topo.positions();
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Clip;
    spec.clip = clip;
    spec.frames = frames;
    spec.fps = fps;
    Camera camera;
    camera.view_dir = glm::normalize(glm::dvec3(0.2, -0.1, -1.0));
    FrameDriver driver(spec, mesh, rest_topo, camera, default_light(camera), glm::dvec3(0.0), path);
    EXPECT_TRUE(driver.mesh_moves());
    ContourTracker tracker(rest_topo, ContourSpec{});
    double moved = 0.0;
    for (int k = 0; k < frames; ++k) {
        const FramePose pose = driver.pose(k);
        const MeshTopology& topo = pose.mesh;
        const Camera& cam = pose.camera;
        const Light& light = pose.light;
        EXPECT_TRUE(topo.same_connectivity(rest_topo)); // one connectivity, shared
        for (std::size_t v = 0; v < topo.n_vertices(); ++v) moved = std::max(moved, glm::length(topo.positions().values()[v] - rest[v]));
        const TrackedFrame& tf = tracker.step(topo, cam, light);
        // A moving mesh's normals are what its animation makes them.
        const auto oracle = test::marching_triangles(topo.positions(), test::plain_faces(topo), test::oracle_setup({}, cam, light), 1,
                                                     topo.normals());
        EXPECT_EQ(tf.contour.fronts.snaxels.size(), oracle.crossing.size()) << path << " frame " << k;
        EXPECT_EQ(tf.contour.fronts.loops.size(), oracle.loops) << path << " frame " << k;
        for (const auto& loop : tf.contour.fronts.loops) EXPECT_TRUE(loop.closed);
    }
    return moved;
}

} // namespace

// Done-when 4: a skinned mesh animates (its upper half bends 60 degrees)
// and its contours track.
TEST(MeshAnimation, SkinnedBarBendsAndTracks) {
    const std::string path = test::asset("anim/skinned-bar.gltf");
    const MeshAnimation anim(path, "bend");
    EXPECT_NEAR(anim.duration(), 1.0, 1e-9);
    std::vector<glm::dvec3> pose;
    anim.pose(1.0 - 1e-9, pose);
    // The top corner (0.2, 2, 0.2) turns 60 degrees about Z around (0, 1, 0).
    double best = 1e9;
    const double c = std::cos(M_PI / 3), s = std::sin(M_PI / 3);
    const glm::dvec3 expected(0.2 * c - 1.0 * s, 1.0 + 0.2 * s + 1.0 * c, 0.2);
    for (const auto& p : pose) best = std::min(best, glm::length(p - expected));
    EXPECT_LT(best, 1e-3);
    EXPECT_GT(track_clip(path, "bend", 25, 24.0), 0.5);
}

// Done-when 4: a morph-target mesh animates (stretched 1.6 times along X).
TEST(MeshAnimation, MorphBallStretchesAndTracks) {
    const std::string path = test::asset("anim/morph-ball.gltf");
    const MeshAnimation anim(path, "");
    EXPECT_EQ(anim.clip(), "stretch");
    std::vector<glm::dvec3> pose;
    anim.pose(1.0 - 1e-9, pose);
    double max_x = 0.0;
    for (const auto& p : pose) max_x = std::max(max_x, p.x);
    EXPECT_NEAR(max_x, 1.6, 1e-3);
    EXPECT_GT(track_clip(path, "stretch", 25, 24.0), 0.5);
}

TEST(MeshAnimation, NamesTheClipsWhenOneIsMissing) {
    try {
        MeshAnimation(test::asset("anim/skinned-bar.gltf"), "walk");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no animation clip 'walk' (it has: bend)"), std::string::npos) << e.what();
    }
    EXPECT_THROW(MeshAnimation(test::asset("spot.obj"), ""), Error);
}

// A numbered sequence of files with one connectivity drives the mesh.
TEST(FrameDriver, FileSequence) {
    const auto dir = std::filesystem::temp_directory_path() / "snaxels-sequence-test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const TriangleSoup base = make_procedural("sphere:2000");
    for (int k = 1; k <= 4; ++k) {
        std::ofstream out(dir / ("blob_" + std::string(k < 10 ? "000" : "00") + std::to_string(k) + ".obj"));
        for (const auto& p : base.positions)
            out << "v " << p.x * (1.0 + 0.2 * k) << ' ' << p.y << ' ' << p.z << '\n';
        for (const auto& t : base.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Sequence;
    spec.pattern = (dir / "blob_####.obj").string();
    spec.frames = 4;
    const LoadedMesh mesh = import_mesh((dir / "blob_0001.obj").string());
    const MeshTopology topo = build_topology(mesh.mesh);
    FrameDriver driver(spec, mesh, topo, Camera{}, Light{}, glm::dvec3(0.0), "");
    EXPECT_EQ(driver.sequence_path(2), (dir / "blob_0003.obj").string());
    double base_x = 0.0;
    for (const auto& p : base.positions) base_x = std::max(base_x, p.x);
    for (int k = 0; k < 4; ++k) {
        const FramePose pose = driver.pose(k);
        EXPECT_TRUE(pose.mesh.same_connectivity(topo));
        double max_x = 0.0;
        for (const auto& p : pose.mesh.positions()) max_x = std::max(max_x, p.x);
        EXPECT_NEAR(max_x, base_x * (1.0 + 0.2 * (k + 1)), 1e-5); // files hold 6 significant digits
    }
    // A file with other connectivity is refused by name.
    std::ofstream(dir / "blob_0003.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    try {
        driver.pose(2);
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("blob_0003.obj: has 3 vertices"), std::string::npos) << e.what();
    }
    std::filesystem::remove_all(dir);
}

// A series found from any one of its files: the last number in the name,
// padded or not, and the unbroken run of its neighbours.
TEST(FindSequence, FromAnyOfItsFiles) {
    const auto dir = std::filesystem::temp_directory_path() / "snaxels-find-sequence-test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir / "take2");
    for (const int k : {3, 4, 5, 6, 9}) std::ofstream(dir / "take2" / ("walk_" + std::string(k < 10 ? "000" : "00") + std::to_string(k) + ".obj")) << "x";
    for (const int k : {8, 9, 10, 11}) std::ofstream(dir / ("run" + std::to_string(k) + ".ply")) << "x";
    std::ofstream(dir / "plain.obj") << "x";

    const auto walk = find_sequence((dir / "take2" / "walk_0005.obj").string());
    ASSERT_TRUE(walk);
    EXPECT_EQ(walk->pattern, (dir / "take2" / "walk_####.obj").string()); // the 2 in take2 is not the frame
    EXPECT_EQ(walk->first_file, 3);
    EXPECT_EQ(walk->count, 4); // 3-6: 9 is past a gap
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Sequence;
    spec.pattern = walk->pattern;
    spec.first_file = walk->first_file;
    EXPECT_EQ(sequence_file(spec, 3), (dir / "take2" / "walk_0006.obj").string());

    const auto run = find_sequence((dir / "run10.ply").string());
    ASSERT_TRUE(run);
    EXPECT_EQ(run->pattern, (dir / "run%d.ply").string()); // not padded
    EXPECT_EQ(run->first_file, 8);
    EXPECT_EQ(run->count, 4);
    spec.pattern = run->pattern;
    spec.first_file = -1; // 0 or 1, whichever exists: neither, so 1
    EXPECT_EQ(sequence_file(spec, 9), (dir / "run10.ply").string());

    EXPECT_FALSE(find_sequence((dir / "plain.obj").string()));
    const auto lonely = find_sequence((dir / "take2" / "walk_0009.obj").string());
    ASSERT_TRUE(lonely);
    EXPECT_EQ(lonely->count, 1);
    std::filesystem::remove_all(dir);
}

TEST(FrameDriver, TurntableAndLightOrbit) {
    const LoadedMesh mesh = load_mesh("proc:sphere:500");
    MeshTopology topo = build_topology(mesh.mesh);
    Camera base;
    base.view_dir = {0, 0, 1};
    Light light0;
    light0.dir = {1, 0, 0};
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Turntable;
    spec.degrees_per_frame = 90.0;
    FrameDriver turn(spec, mesh, topo, base, light0, glm::dvec3(0.0), "");
    const FramePose turned = turn.pose(1);
    EXPECT_NEAR(turned.camera.view_dir.x, 1.0, 1e-12); // +Z turned 90 degrees about +Y
    EXPECT_EQ(turned.mesh.pose(), topo.pose());        // the mesh stays as loaded: the same pose, not a copy
    spec.kind = AnimationSpec::Kind::LightOrbit;
    FrameDriver orbit(spec, mesh, topo, base, light0, glm::dvec3(0.0), "");
    const FramePose orbited = orbit.pose(2);
    EXPECT_NEAR(orbited.light.dir.x, -1.0, 1e-12);
    EXPECT_NEAR(orbited.camera.view_dir.z, 1.0, 1e-12);
}

// An in point (spec.start) shifts the source: frame k of an animation
// starting at S is frame S + k of one starting at 0, for turntables and
// for the mesh's own clips.
TEST(FrameDriver, StartIsAnInPoint) {
    const LoadedMesh sphere = load_mesh("proc:sphere:500");
    MeshTopology topo = build_topology(sphere.mesh);
    Camera base;
    base.view_dir = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
    const Light light0 = default_light(base);
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Turntable;
    spec.degrees_per_frame = 7.0;
    FrameDriver from_zero(spec, sphere, topo, base, light0, glm::dvec3(0.0), "");
    spec.start = 10;
    FrameDriver from_ten(spec, sphere, topo, base, light0, glm::dvec3(0.0), "");
    EXPECT_EQ(from_zero.pose(13).camera.view_dir, from_ten.pose(3).camera.view_dir);
    EXPECT_EQ(from_zero.pose(13).light.dir, from_ten.pose(3).light.dir);

    const std::string path = test::asset("anim/skinned-bar.gltf");
    const LoadedMesh bar = import_mesh(path);
    const MeshTopology t0 = build_topology(bar.mesh), t1 = build_topology(bar.mesh);
    AnimationSpec clip;
    clip.kind = AnimationSpec::Kind::Clip;
    clip.fps = 24.0;
    FrameDriver clip_zero(clip, bar, t0, base, light0, glm::dvec3(0.0), path);
    clip.start = 6;
    FrameDriver clip_six(clip, bar, t1, base, light0, glm::dvec3(0.0), path);
    auto positions = [](const FramePose& p) {
        return std::vector<glm::dvec3>(p.mesh.positions().begin(), p.mesh.positions().end());
    };
    EXPECT_EQ(positions(clip_zero.pose(9)), positions(clip_six.pose(3)));
    EXPECT_NE(positions(clip_zero.pose(9)), positions(clip_six.pose(0)));
}

// A frame's mesh is a value: later frames, and the tracker stepping through
// them, leave an earlier pose and the loaded one as they were; every pose
// shares the loaded mesh's one connectivity.
TEST(FrameDriver, PosesAreValuesOfOneSharedConnectivity) {
    const std::string path = test::asset("anim/skinned-bar.gltf");
    const LoadedMesh bar = import_mesh(path);
    const MeshTopology rest = engine_topology(bar.mesh); // refined: the added vertices follow too
    ASSERT_TRUE(rest.refinement());
    const std::vector<glm::dvec3> loaded(rest.positions().begin(), rest.positions().end());
    AnimationSpec clip;
    clip.kind = AnimationSpec::Kind::Clip;
    clip.fps = 24.0;
    Camera camera;
    camera.view_dir = glm::normalize(glm::dvec3(0.2, -0.1, -1.0));
    FrameDriver driver(clip, bar, rest, camera, default_light(camera), glm::dvec3(0.0), path);
    const FramePose early = driver.pose(3);
    const std::vector<glm::dvec3> early_positions(early.mesh.positions().begin(), early.mesh.positions().end());
    ContourTracker tracker(rest, ContourSpec{});
    tracker.step(early.mesh, early.camera, early.light);
    const FramePose late = driver.pose(20);
    tracker.step(late.mesh, late.camera, late.light);

    EXPECT_EQ(early.mesh.connectivity(), rest.connectivity()); // shared, not copied
    EXPECT_EQ(late.mesh.connectivity(), rest.connectivity());
    EXPECT_EQ(std::vector<glm::dvec3>(early.mesh.positions().begin(), early.mesh.positions().end()), early_positions);
    EXPECT_EQ(std::vector<glm::dvec3>(rest.positions().begin(), rest.positions().end()), loaded);
    double moved = 0.0;
    for (std::size_t v = 0; v < early_positions.size(); ++v)
        moved = std::max(moved, glm::length(late.mesh.positions().values()[v] - early_positions[v]));
    EXPECT_GT(moved, 0.1); // the bar bent between the two frames

    // A pose of another mesh is refused, not tracked as if it were this one.
    const LoadedMesh sphere = load_mesh("proc:sphere:500");
    EXPECT_THROW(tracker.step(build_topology(sphere.mesh), late.camera, late.light), InternalError);
    // Neither is a pose with another vertex count.
    EXPECT_THROW(rest.posed(build_topology(sphere.mesh).pose()), InternalError);
}

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>

// Tracking gives one answer whatever floating-point mode the thread that
// steps it is in (float_mode.h). Frame 1 of Wuson's walk (split along its
// hard edges and refined as the export does, the light of the command line's view) has a vertex whose shadow
// function is a negative subnormal: read as zero under denormals-are-zero
// (which Embree leaves on threads, and oneTBB carries to others) it lay on
// the other side of the shadow's contour, and the export's document
// depended on the thread that tracked it.
TEST(ContourTracker, OneAnswerWhateverTheThreadsFloatMode) {
    const std::string path = test::asset("anim/Testwuson.X");
    const LoadedMesh loaded = import_mesh(path);
    std::optional<LoadedMesh> split;
    const LoadedMesh& mesh = scene_surface(loaded, Style{}, split); // split along its hard edges, as exported
    const MeshTopology rest = engine_topology(mesh);
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Clip;
    spec.frames = 2;
    // The view and light `snaxels-cli animate Testwuson.X --clip 0` frames it with.
    Camera camera;
    camera.view_dir = {-0x1.e921dd42f09b9p-2, -0x1.2e9cd95baba33p-2, -0x1.a799d9fb7e802p-1};
    Light light;
    light.dir = {-0x1.3cf4c34497592p-2, 0x1.71c1e5e94003fp-1, 0x1.3cb6f2770efdep-1};
    FrameDriver driver(spec, mesh, rest, camera, light, mesh.report.centre(), path);
    const FramePose first = driver.pose(0), second = driver.pose(1);
    const ContourSpec shadow{ContourKind::Shadow, 0.0};
    VertexData<double> f;
    ContourFunction(shadow, camera, light).evaluate_vertices(second.mesh, f);
    std::size_t subnormal = 0;
    for (const double value : f) subnormal += value < 0.0 && std::fpclassify(value) == FP_SUBNORMAL;
    ASSERT_GT(subnormal, 0u) << "the test's premise: a vertex of frame 1 whose shadow function is a negative subnormal";
    // The two frames tracked on this thread, with flush-to-zero and
    // denormals-are-zero on or off; the fronts of frame 1 compared.
    auto track = [&](bool flushing) {
        const unsigned saved = _mm_getcsr();
        if (flushing) _mm_setcsr(saved | 0x8040);
        ContourTracker tracker(rest, shadow);
        tracker.step(first.mesh, camera, light);
        const Fronts fronts = tracker.step(second.mesh, camera, light).contour.fronts;
        _mm_setcsr(saved);
        std::vector<std::array<std::int32_t, 3>> out;
        for (const Snaxel& s : fronts.snaxels) out.push_back({std::int32_t(s.edge.index()), std::int32_t(s.inside.index()), std::int32_t(s.outside.index())});
        return out;
    };
    const auto ieee = track(false), flushing = track(true);
    EXPECT_FALSE(ieee.empty());
    EXPECT_TRUE(ieee == flushing) << ieee.size() << " snaxels in IEEE mode, " << flushing.size() << " when flushing";
}
#endif
