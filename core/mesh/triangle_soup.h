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
    /// The file's own normal at each position (parallel to positions), or
    /// empty when the file has none. A file that shades a hard edge gives
    /// the corners on either side their own vertices with their own normals;
    /// build_mesh welds the positions and keeps these per corner.
    std::vector<glm::dvec3> normals;
};

} // namespace snaxels
