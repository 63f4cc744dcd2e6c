#pragma once
// Internal to core/mesh: reading a file with Assimp the one way import and
// animation both rely on, and walking its mesh instances in a fixed order
// (so soup vertex indices mean the same in both).

#include <functional>
#include <map>
#include <string>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <nlohmann/json.hpp>

namespace snaxels::detail {

/// Checks the path (exists, readable, not empty, not an image...) and reads
/// it; throws snaxels::Error "PATH: problem".
const aiScene* read_assimp_scene(Assimp::Importer& importer, const std::string& path);

/// Calls fn(node, mesh, global transform) for every triangle mesh instance,
/// depth first from the root, in node and mesh order.
void for_each_mesh_instance(const aiScene* scene,
                            const std::function<void(const aiNode*, const aiMesh*, const aiMatrix4x4&)>& fn);

/// The JSON of a glTF file of any version (a .gltf, or a .glb's JSON),
/// or null for anything else.
nlohmann::json gltf_json(const std::string& path);

/// Every node's global transform (by name) at @p ticks into @p anim: the
/// node's channel where the animation has one, its own transform else
/// (@p anim null: the scene at rest).
std::map<std::string, aiMatrix4x4> node_transforms_at(const aiScene* scene, const aiAnimation* anim, double ticks);

/// The animation's ticks per second (25 where the file does not say).
double ticks_per_second(const aiAnimation* anim);

} // namespace snaxels::detail
