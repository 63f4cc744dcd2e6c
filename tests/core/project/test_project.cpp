#include <filesystem>
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "snaxels/error.h"
#include "snaxels/project/project.h"

namespace snaxels {
namespace {

namespace fs = std::filesystem;

class ProjectFile : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("snaxels-project-" + std::to_string(::getpid()) + "-" +
                                            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(dir_ / "sub");
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string write(const std::string& name, const std::string& text) {
        const fs::path p = dir_ / name;
        std::ofstream(p) << text;
        return p.string();
    }
    std::string error_of(const std::string& path) {
        try {
            read_project(path);
        } catch (const Error& e) {
            return e.what();
        }
        return "";
    }
    fs::path dir_;
};

TEST_F(ProjectFile, EveryNumberReadsBackExactly) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    for (int trial = 0; trial < 50; ++trial) {
        Project p;
        p.mesh = "meshes/spot.obj";
        p.view.yaw = u(rng);
        p.view.pitch = u(rng) / 10.0 * 1.5;
        p.view.distance = std::abs(u(rng)) + 1e-3;
        p.view.pan = {u(rng) * 1e-7, u(rng), u(rng) * 1e9};
        p.view.fov_deg = 20.0 + std::abs(u(rng));
        if (trial % 2) p.view.up = glm::normalize(glm::dvec3(u(rng), u(rng), u(rng)));
        p.view.orthographic = trial % 5 == 1;
        if (trial % 3) {
            Light l;
            l.point = trial % 3 == 2;
            l.dir = {u(rng), u(rng), u(rng)};
            if (l.point) l.pos = {u(rng), u(rng), u(rng)};
            else l.pos = {};
            p.light = l;
        }
        p.animation.kind = trial % 2 ? AnimationSpec::Kind::Turntable : AnimationSpec::Kind::LightOrbit;
        p.animation.degrees_per_frame = u(rng) * 3.0;
        p.animation.frames = 1 + trial;
        p.animation.start = trial % 4;
        p.animation.fps = 1.0 + std::abs(u(rng));
        p.frame = trial / 2;
        p.style = "<style>\n  <contour kind=\"visual\"/>\n</style>\n\"quoted\" \\ ünïcode";
        const std::string path = write("p.snaxels", project_text(p));
        const Project back = read_project(path);
        // A point light keeps its position only, a directional light its direction.
        if (p.light && p.light->point) p.light->dir = back.light->dir;
        EXPECT_EQ(back, p) << project_text(p);
        EXPECT_EQ(project_text(back), project_text(p));
    }
}

TEST_F(ProjectFile, ClipAndSequenceSourcesRoundTrip) {
    Project p;
    p.mesh = "anim.gltf";
    p.animation.kind = AnimationSpec::Kind::Clip;
    p.animation.clip = "Bend";
    p.animation.frames = 0; // the clip's own length
    EXPECT_EQ(read_project(write("c.snaxels", project_text(p))), p);
    p.animation = {};
    p.animation.kind = AnimationSpec::Kind::Sequence;
    p.animation.pattern = "frames/f####.obj";
    p.animation.first_file = 3;
    p.animation.frames = 10;
    EXPECT_EQ(read_project(write("s.snaxels", project_text(p))), p);
    // A file's camera: moving through its own clip, or looking at a turntable.
    p.animation = {};
    p.animation.kind = AnimationSpec::Kind::Camera;
    p.animation.camera = "ShotCam";
    p.animation.clip = "ShotCamAction";
    p.animation.frames = 0;
    EXPECT_EQ(read_project(write("cam.snaxels", project_text(p))), p);
    p.animation.kind = AnimationSpec::Kind::Turntable;
    p.animation.clip.clear();
    p.animation.frames = 90;
    EXPECT_EQ(read_project(write("cam-turn.snaxels", project_text(p))), p);
    // A camera animation without its camera is refused, naming the field.
    std::string text = project_text(p);
    text.replace(text.find("\"turntable\""), 11, "\"camera\"");
    text.replace(text.find("\"camera\": \"ShotCam\","), 21, "");
    try {
        read_project(write("cam-bad.snaxels", text));
        FAIL() << text;
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("\"animation.camera\" must name one of the file's cameras"), std::string::npos)
            << e.what();
    }
}

TEST_F(ProjectFile, MeshPathsAreRelativeToTheProject) {
    const std::string project = (dir_ / "sub" / "p.snaxels").string();
    const std::string mesh = (dir_ / "meshes" / "horse.ply").string();
    EXPECT_EQ(project_mesh_reference(project, mesh), "../meshes/horse.ply");
    EXPECT_EQ(resolve_project_mesh(project, "../meshes/horse.ply"), fs::path(mesh).lexically_normal().string());
    EXPECT_EQ(project_mesh_reference(project, (dir_ / "sub" / "a.obj").string()), "a.obj");
    EXPECT_EQ(project_mesh_reference(project, "proc:torus:2000"), "proc:torus:2000");
    EXPECT_EQ(resolve_project_mesh(project, "proc:torus:2000"), "proc:torus:2000");
    EXPECT_EQ(resolve_project_mesh(project, "/abs/x.obj"), "/abs/x.obj");
}

TEST_F(ProjectFile, TheUpAxisRoundTripsAndOldProjectsStandOnY) {
    Project p;
    p.mesh = "scan.ply";
    p.view.up = {0.0, 0.0, 1.0};
    const std::string text = project_text(p);
    EXPECT_EQ(read_project(write("z.snaxels", text)).view.up, glm::dvec3(0.0, 0.0, 1.0));
    // A version 1 project has no up axis: +Y, as it was drawn then.
    std::string old = text;
    old.replace(old.find("\"version\": 2"), 12, "\"version\": 1");
    const auto up = old.find("\"up\"");
    old.erase(up, old.find(']', up) + 2 - up);
    const Project back = read_project(write("old.snaxels", old));
    EXPECT_EQ(back.view.up, glm::dvec3(0.0, 1.0, 0.0));
    EXPECT_EQ(back.view.yaw, p.view.yaw);
}

TEST_F(ProjectFile, AnOrthographicViewRoundTripsAndAPerspectiveOneReadsAsBefore) {
    Project p;
    p.mesh = "truck.glb";
    const std::string perspective = project_text(p);
    EXPECT_EQ(perspective.find("projection"), std::string::npos); // a perspective project's text is unchanged
    EXPECT_FALSE(read_project(write("p.snaxels", perspective)).view.orthographic);
    p.view.orthographic = true;
    const std::string ortho = project_text(p);
    EXPECT_NE(ortho.find("\"projection\": \"orthographic\""), std::string::npos);
    EXPECT_TRUE(read_project(write("o.snaxels", ortho)).view.orthographic);
    std::string bad = ortho;
    bad.replace(bad.find("\"orthographic\""), 14, "\"isometric\"");
    EXPECT_NE(error_of(write("bad.snaxels", bad)).find("\"view.projection\" must be orthographic or perspective"),
              std::string::npos);
}

TEST_F(ProjectFile, BadFilesNameTheProblem) {
    Project p;
    p.mesh = "m.obj";
    p.view.yaw = 3.8;
    const std::string good = project_text(p);
    EXPECT_NE(error_of(write("empty.snaxels", "")).find("not a snaxels project"), std::string::npos);
    EXPECT_NE(error_of(write("trunc.snaxels", good.substr(0, good.size() / 2))).find("parse error"), std::string::npos);
    EXPECT_NE(error_of(write("array.snaxels", "[1,2]")).find("not a JSON object"), std::string::npos);
    EXPECT_NE(error_of(write("other.snaxels", "{\"format\": \"x\"}")).find("not a snaxels project"), std::string::npos);
    auto edit = [&](const std::string& from, const std::string& to) {
        std::string text = good;
        const auto at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        text.replace(at, from.size(), to);
        return error_of(write("edited.snaxels", text));
    };
    EXPECT_NE(edit("\"version\": 2", "\"version\": 9").find("newer snaxels"), std::string::npos);
    EXPECT_NE(edit("\"mesh\": \"m.obj\",", "").find("\"mesh\" is missing"), std::string::npos);
    EXPECT_NE(edit("\"yaw\": 3.8", "\"yaw\": \"left\"").find("\"view.yaw\" must be a finite number"), std::string::npos);
    EXPECT_NE(edit("\"source\": \"still\"", "\"source\": \"spin\"").find("\"animation.source\" must be one of"), std::string::npos);
    EXPECT_NE(edit("\"frames\": 1", "\"frames\": -4").find("\"animation.frames\""), std::string::npos);
    EXPECT_NE(edit("\"distance\": 3.0", "\"distance\": 0").find("\"view.distance\" must be positive"), std::string::npos);
    EXPECT_NE(edit("\"up\": [\n      0.0,\n      1.0,", "\"up\": [\n      0.0,\n      0.0,").find("\"view.up\" must be a direction"),
              std::string::npos);
    EXPECT_NE(error_of((dir_ / "missing.snaxels").string()).find("cannot open"), std::string::npos);
    EXPECT_NE(error_of(dir_.string()).find("is a directory"), std::string::npos);
    // The message names the file.
    EXPECT_EQ(error_of(write("other.snaxels", "{}")).rfind((dir_ / "other.snaxels").string(), 0), 0u);
}

} // namespace
} // namespace snaxels
