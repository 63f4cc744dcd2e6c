#pragma once
// Internal to core/mesh: reading a file with Assimp the one way import and
// animation both rely on, and walking its mesh instances in a fixed order
// (so soup vertex indices mean the same in both).

#include <functional>
#include <string>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

namespace snaxels::detail {

/// Checks the path (exists, readable, not empty, not an image...) and reads
/// it; throws snaxels::Error "PATH: problem".
const aiScene* read_assimp_scene(Assimp::Importer& importer, const std::string& path);

/// Calls fn(node, mesh, global transform) for every triangle mesh instance,
/// depth first from the root, in node and mesh order.
void for_each_mesh_instance(const aiScene* scene,
                            const std::function<void(const aiNode*, const aiMesh*, const aiMatrix4x4&)>& fn);

} // namespace snaxels::detail
