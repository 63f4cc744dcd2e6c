// The camera an export starts from (orbit_base_camera: the model's up as
// its up, for the turntable to turn about) must frame the picture as the
// orbit the application shows does, at every yaw and pitch the orbit
// allows, the top and bottom views included. The orbit's basis here is read
// off its view matrix (the rows of its rotation), not from Camera.

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/scene/camera.h"
#include "snaxels/scene/orbit.h"

using namespace snaxels;

namespace {

void expect_near(const glm::dvec3& a, const glm::dvec3& b, const char* what, double yaw, double pitch) {
    EXPECT_NEAR(glm::length(a - b), 0.0, 1e-9) << what << " at yaw " << yaw << ", pitch " << pitch << ": (" << a.x
                                                << ", " << a.y << ", " << a.z << ") against (" << b.x << ", " << b.y
                                                << ", " << b.z << ")";
}

TEST(OrbitCamera, TheExportCameraFramesThePictureAsTheOrbitDoesUpToThePoles) {
    for (const glm::dvec3 up : {glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)})
        for (const double pitch : {-kMaxPitch, -1.5, -0.4, 0.0, 0.3, 1.5, kMaxPitch})
            for (const double yaw : {0.0, 0.7, 2.5, -1.1536, -3.0}) {
                OrbitView view;
                view.up = up;
                view.yaw = yaw;
                view.pitch = pitch;
                view.distance = 4.0;
                view.centre = glm::dvec3(0.2, -0.1, 0.3);
                const glm::dmat4 m = orbit_view_matrix(view);
                // Row i of the rotation is the camera's axis i in world space.
                const glm::dvec3 right(m[0][0], m[1][0], m[2][0]), screen_up(m[0][1], m[1][1], m[2][1]);
                glm::dvec3 r, u;
                orbit_base_camera(view).screen_basis(r, u);
                expect_near(r, right, "right", yaw, pitch);
                expect_near(u, screen_up, "up", yaw, pitch);
                orbit_camera(view).screen_basis(r, u);
                expect_near(r, right, "right (the view's camera)", yaw, pitch);
                expect_near(u, screen_up, "up (the view's camera)", yaw, pitch);
            }
}

TEST(OrbitCamera, LookingStraightAlongUpStillHasABasis) {
    Camera c;
    c.eye = glm::dvec3(0, 5, 0);
    c.target = glm::dvec3(0, 0, 0);
    c.up = glm::dvec3(0, 1, 0);
    glm::dvec3 r, u;
    c.screen_basis(r, u);
    EXPECT_NEAR(glm::length(r), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(u), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(r, c.forward()), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(u, c.forward()), 0.0, 1e-12);
}

} // namespace

// The named orthographic views, measured as a drawing shows them: the
// model's three axes projected with the camera's screen basis. Isometric
// draws them equally long with the receding ones at 30 degrees; the 2:1
// dimetric draws its receding ones at atan(1/2) and two of them alike;
// trimetric draws all three differently. Expected values are the
// textbook ones, not computed by the code under test.
TEST(OrbitCamera, NamedViewsAreTheAxonometriesTheySayTheyAre) {
    auto view = [](const char* name, const glm::dvec3& up) {
        for (const NamedView& v : named_views())
            if (std::string(name) == v.name) return view_dir_at(up, v.yaw, v.pitch);
        ADD_FAILURE() << "no view " << name;
        return glm::dvec3(0.0);
    };
    const glm::dvec3 y(0.0, 1.0, 0.0), z(0.0, 0.0, 1.0);
    // Isometric from the front right above: along the cube's diagonal.
    const glm::dvec3 iso = view("iso", y);
    EXPECT_NEAR(glm::length(iso - glm::normalize(glm::dvec3(-1.0, -1.0, -1.0))), 0.0, 1e-12);
    // A Z-up model (front -Y, right +X): the same picture of it.
    EXPECT_NEAR(glm::length(view("iso", z) - glm::normalize(glm::dvec3(-1.0, 1.0, -1.0))), 0.0, 1e-12);
    auto projected = [](const glm::dvec3& dir, const glm::dvec3& up, const glm::dvec3& axis) {
        Camera c;
        c.view_dir = dir;
        c.up = up;
        glm::dvec3 right, screen_up;
        c.screen_basis(right, screen_up);
        return glm::dvec2(glm::dot(axis, right), glm::dot(axis, screen_up));
    };
    const glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    auto lengths = [&](const glm::dvec3& dir) {
        std::vector<double> l;
        for (const glm::dvec3& a : axes) l.push_back(glm::length(projected(dir, y, a)));
        return l;
    };
    auto slope_deg = [&](const glm::dvec3& dir, const glm::dvec3& axis) {
        const glm::dvec2 p = projected(dir, y, axis);
        return glm::degrees(std::atan(std::abs(p.y) / std::abs(p.x)));
    };
    const auto li = lengths(iso);
    EXPECT_NEAR(li[0], li[1], 1e-12);
    EXPECT_NEAR(li[1], li[2], 1e-12);
    EXPECT_NEAR(li[0], std::sqrt(2.0 / 3.0), 1e-12); // isometric's foreshortening
    EXPECT_NEAR(slope_deg(iso, axes[0]), 30.0, 1e-9);
    EXPECT_NEAR(slope_deg(iso, axes[2]), 30.0, 1e-9);
    const glm::dvec3 di = view("dimetric", y);
    EXPECT_NEAR(slope_deg(di, axes[0]), glm::degrees(std::atan(0.5)), 1e-9); // 2:1
    EXPECT_NEAR(slope_deg(di, axes[2]), glm::degrees(std::atan(0.5)), 1e-9);
    const auto ld = lengths(di);
    EXPECT_NEAR(ld[0], ld[2], 1e-12);
    EXPECT_GT(std::abs(ld[0] - ld[1]), 0.05);
    const auto lt = lengths(view("trimetric", y));
    EXPECT_GT(std::abs(lt[0] - lt[1]), 0.05);
    EXPECT_GT(std::abs(lt[1] - lt[2]), 0.05);
    EXPECT_GT(std::abs(lt[0] - lt[2]), 0.05);
    // Front looks straight at the front; the default view is still the three-quarter one.
    EXPECT_NEAR(glm::length(view("front", y) - glm::dvec3(0.0, 0.0, -1.0)), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(default_view_dir(y) - view_dir_at(y, kDefaultYaw, kDefaultPitch)), 0.0, 0.0);
}

// The application's orthographic orbit: parallel projection along the
// perspective view's line of sight, showing across the image's smaller side
// the height the perspective view shows at the orbited point, 2 d tan(fov/2),
// so a toggle keeps what stands at the orbited point the same size. The
// expected pixels are worked out here from the definition.
TEST(OrbitCamera, TheOrthographicOrbitShowsThePerspectivesHeightAtTheOrbitedPoint) {
    OrbitView view;
    view.centre = glm::dvec3(1.0, 2.0, -0.5);
    view.yaw = 0.4;
    view.pitch = 0.3;
    view.distance = 6.0;
    view.fov_deg = 40.0;
    const Camera perspective = orbit_camera(view);
    view.orthographic = true;
    const Camera ortho = orbit_camera(view);
    ASSERT_TRUE(ortho.orthographic());
    EXPECT_NEAR(glm::length(ortho.forward() - perspective.forward()), 0.0, 1e-12);
    const double height = 2.0 * 6.0 * std::tan(20.0 * M_PI / 180.0);
    EXPECT_NEAR(ortho.ortho_height, height, 1e-12);

    const int width = 1200, image_height = 800; // landscape: the height is the smaller side
    const ImageProjection p(ortho, glm::dvec3(0.0), 100.0, width, image_height);
    glm::dvec3 right, up;
    ortho.screen_basis(right, up);
    // The orbited point lands at the image's centre; a step of the shown
    // height along screen up spans the image's height, wherever along the
    // line of sight it stands (parallel projection).
    for (const double depth : {-50.0, 0.0, 3.0}) {
        const glm::dvec3 at = view.centre + depth * ortho.forward();
        const glm::dvec2 c = p.project(at);
        EXPECT_NEAR(c.x, 600.0, 1e-9);
        EXPECT_NEAR(c.y, 400.0, 1e-9);
        const glm::dvec2 top = p.project(at + 0.5 * height * up), rightmost = p.project(at + 0.25 * height * right);
        EXPECT_NEAR(top.y, 0.0, 1e-9);
        EXPECT_NEAR(rightmost.x, 600.0 + 200.0, 1e-9);
    }
    // The perspective camera shows a small step at the orbited point the same size.
    const ImageProjection q(perspective, glm::dvec3(0.0), 100.0, width, image_height);
    const double step = 0.01 * height;
    EXPECT_NEAR(glm::length(q.project(view.centre + step * up) - q.project(view.centre)), 8.0, 1e-3);
    EXPECT_NEAR(glm::length(p.project(view.centre + step * up) - p.project(view.centre)), 8.0, 1e-9);
}

// The View menu's axonometric presets look along the command line's named
// views and turn the orbit orthographic; the others keep its projection.
TEST(OrbitCamera, AxonometricPresetsTurnTheOrbitOrthographic) {
    for (const glm::dvec3 up : {glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)})
        for (const NamedView& named : named_views()) {
            OrbitView view;
            view.up = up;
            view.pan = glm::dvec3(0.3, -0.2, 0.0);
            const OrbitView turned = preset_view(view, named);
            EXPECT_EQ(turned.orthographic, named.axonometric) << named.name;
            EXPECT_NEAR(glm::length(orbit_camera(turned).forward() - view_dir_at(up, named.yaw, named.pitch)), 0.0, 1e-9)
                << named.name;
            EXPECT_EQ(turned.distance, view.distance);
            EXPECT_EQ(turned.pan, view.pan);
            view.orthographic = true;
            EXPECT_TRUE(preset_view(view, named).orthographic) << named.name << " keeps orthographic";
        }
    ASSERT_NE(find_named_view("iso"), nullptr);
    EXPECT_TRUE(find_named_view("iso")->axonometric);
    EXPECT_FALSE(find_named_view("front")->axonometric);
    EXPECT_EQ(find_named_view("isometric"), nullptr);
}
