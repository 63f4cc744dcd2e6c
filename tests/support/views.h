#pragma once
// Random views for tests that sweep a mesh from many sides.

#include <random>

#include <glm/glm.hpp>

#include "snaxels/scene/camera.h"

namespace snaxels::test {

/// An orthographic camera looking along a direction drawn uniformly from
/// the sphere.
inline Camera random_orthographic_camera(std::mt19937& rng) {
    std::normal_distribution<double> n;
    Camera cam;
    cam.view_dir = glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
    return cam;
}

} // namespace snaxels::test
