// The cameras of one Blender scene written by three exporters (glTF, FBX,
// Collada; tests/assets/cameras/make_blender_cameras.py): each reads as the
// scene made them, in the mesh's coordinates. Blender's axes (x, y, z) are
// the mesh's (x, z, -y) once upright; the FBX is in centimetres (x 100), as
// its mesh is.
#include <cmath>

#include <gtest/gtest.h>

#include "snaxels/error.h"
#include "snaxels/mesh/file_cameras.h"
#include "snaxels/mesh/import.h"
#include "tests/support/assets.h"

using namespace snaxels;
using snaxels::test::asset;

namespace {

/// Blender's point or direction in the mesh's upright axes.
glm::dvec3 upright(double x, double y, double z) { return {x, z, -y}; }

glm::dvec3 blender_forward(double rx_deg, double rz_deg) {
    // A Blender camera looks down its local -Z; rotation_euler XYZ.
    const double rx = rx_deg * M_PI / 180.0, rz = rz_deg * M_PI / 180.0;
    const glm::dvec3 v(0.0, std::sin(rx), -std::cos(rx)); // Rx * (0, 0, -1)
    return upright(std::cos(rz) * v.x - std::sin(rz) * v.y, std::sin(rz) * v.x + std::cos(rz) * v.y, v.z);
}

class BlenderCameras : public ::testing::TestWithParam<const char*> {};

TEST_P(BlenderCameras, ReadAsTheSceneMadeThem) {
    const std::string path = asset(std::string("cameras/blender-shot.") + GetParam());
    const double unit = std::string(GetParam()) == "fbx" ? 100.0 : 1.0;
    const std::vector<FileCamera> cameras = file_cameras(path);
    ASSERT_EQ(cameras.size(), 2u);
    const FileCamera* shot = cameras[0].name == "ShotCam" ? &cameras[0] : &cameras[1];
    ASSERT_EQ(shot->name, "ShotCam");
    // 50 degrees across a 16:9 frame.
    const double vertical = 2.0 * std::atan(std::tan(25.0 * M_PI / 180.0) * 9.0 / 16.0) * 180.0 / M_PI;
    EXPECT_FALSE(shot->orthographic);
    EXPECT_NEAR(shot->fov_deg, vertical, 1e-3);
    EXPECT_NEAR(shot->aspect, 16.0 / 9.0, 1e-5);
    EXPECT_TRUE(shot->animated());
    EXPECT_NEAR(shot->clip_seconds, 47.0 / 24.0, 1.0 / 24.0 + 1e-6); // frames 1-48 (glTF and Collada count from 0 s)

    const CameraTrack track(path, "ShotCam");
    const Camera first = track.at(0.0), last = track.at(shot->clip_seconds);
    EXPECT_TRUE(first.own_frame);
    // Blender's default clip start, 0.1 m, in the mesh's units: where the picture is cut.
    EXPECT_NEAR(first.near_clip, 0.1 * unit, 1e-6 * unit) << GetParam();
    EXPECT_NEAR(glm::length(first.eye / unit - upright(0.0, -6.0, 1.5)), 0.0, 1e-4);
    EXPECT_NEAR(glm::length(first.forward() - blender_forward(80.0, 0.0)), 0.0, 1e-4);
    EXPECT_NEAR(glm::length(last.eye / unit - upright(6.0, 0.0, 1.5)), 0.0, 1e-4);
    EXPECT_NEAR(glm::length(last.forward() - blender_forward(80.0, 90.0)), 0.0, 1e-4);
    // Half way, the camera is between its keys (Blender's Bezier easing: not the chord's midpoint).
    const Camera middle = track.at(0.5 * shot->clip_seconds);
    EXPECT_GT(middle.eye.x / unit, 0.5);
    EXPECT_LT(middle.eye.x / unit, 5.5);

    const FileCamera* top = &cameras[0] == shot ? &cameras[1] : &cameras[0];
    EXPECT_EQ(top->name, "TopOrtho");
    EXPECT_FALSE(top->animated());
    const Camera plan = CameraTrack(path, "TopOrtho").at(0.0);
    EXPECT_NEAR(glm::length(plan.eye / unit - upright(0.0, 0.0, 8.0)), 0.0, 1e-4);
    EXPECT_NEAR(glm::length(plan.forward() - upright(0.0, 0.0, -1.0)), 0.0, 1e-4);
    if (std::string(GetParam()) == "fbx") return; // Assimp 5.2 reads an FBX orthographic camera as perspective
    EXPECT_TRUE(top->orthographic);
    EXPECT_NEAR(top->ortho_height, 4.0 * 9.0 / 16.0, 1e-5); // 4 units across a 16:9 frame
    EXPECT_TRUE(plan.orthographic());
}

INSTANTIATE_TEST_SUITE_P(Formats, BlenderCameras, ::testing::Values("gltf", "fbx", "dae"));

TEST(FileCameras, UnknownNamesListWhatTheFileHas) {
    const std::string path = asset("cameras/blender-shot.gltf");
    try {
        CameraTrack(path, "Nope");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no camera 'Nope' (it has: ShotCam, TopOrtho)"), std::string::npos) << e.what();
    }
    try {
        CameraTrack(asset("spot.obj"), "Any");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("has no cameras"), std::string::npos) << e.what();
    }
    try {
        CameraTrack(path, "ShotCam", "Nope");
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("no animation clip 'Nope' (it has: ShotCamAction)"), std::string::npos) << e.what();
    }
    EXPECT_EQ(CameraTrack(path, "1").info().name, "TopOrtho"); // by index
    EXPECT_FALSE(CameraTrack(path, "TopOrtho", "0").info().animated()); // a clip that does not move it
    EXPECT_TRUE(file_cameras(asset("spot.obj")).empty());
    EXPECT_FALSE(may_hold_cameras(asset("spot.obj")));
    EXPECT_TRUE(may_hold_cameras(path));
}

TEST(FileCameras, TheCanvasFollowsTheAspect) {
    FileCamera wide;
    wide.aspect = 16.0 / 9.0;
    EXPECT_EQ(canvas_height_for(wide, 800, 800), 450);
    EXPECT_EQ(canvas_height_for(FileCamera{}, 800, 640), 640); // unknown: the style's
}

} // namespace
