// The camera an export starts from (orbit_base_camera: the model's up as
// its up, for the turntable to turn about) must frame the picture as the
// orbit the application shows does, at every yaw and pitch the orbit
// allows, the top and bottom views included. The orbit's basis here is read
// off its view matrix (the rows of its rotation), not from Camera.

#include <gtest/gtest.h>

#include <cmath>

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
