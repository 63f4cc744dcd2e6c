#pragma once
/// Unconnected triangles as read from a file or made by a generator, before
/// welding and repair turn them into a Mesh.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace snaxels {

/// A part of a scene: a node that holds meshes.
struct SceneObject {
    std::string name; ///< the node's name
    std::string path; ///< the names from the scene's top node down to it, joined by '/'

    bool operator==(const SceneObject&) const = default;
};

/// A material of a scene, as the file gives it.
struct SceneMaterial {
    std::string name;
    /// Base colour (PBR) or else diffuse colour, linear RGB as the file
    /// stores it, with the opacity as alpha.
    glm::dvec4 colour{0.8, 0.8, 0.8, 1.0};

    bool operator==(const SceneMaterial&) const = default;
};

struct TriangleSoup {
    std::vector<glm::dvec3> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles; ///< indices into positions
    /// The file's own normal at each position (parallel to positions), or
    /// empty when the file has none. A file that shades a hard edge gives
    /// the corners on either side their own vertices with their own normals;
    /// build_mesh welds the positions and keeps these per corner.
    std::vector<glm::dvec3> normals;
    /// The scene's parts and materials, and per triangle (parallel to
    /// triangles) the index of each; all empty for a soup without parts
    /// (a procedural mesh).
    std::vector<SceneObject> objects;
    std::vector<SceneMaterial> materials;
    std::vector<std::uint32_t> triangle_object, triangle_material;
};

} // namespace snaxels
