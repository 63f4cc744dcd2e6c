#pragma once
/// Unconnected triangles as read from a file or made by a generator, before
/// welding and repair turn them into a Mesh.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace snaxels {

struct TriangleSoup {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles; ///< indices into positions
};

} // namespace snaxels
