#pragma once
/// Turns a triangle soup into the project's Mesh: welds vertices by exact
/// position, drops unreferenced vertices and zero-area faces, splits vertices
/// where fans of faces meet only at them (bow ties) or a face cannot be added
/// to a manifold halfedge mesh, and computes
/// area-weighted vertex normals.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "snaxels/mesh/mesh.h"
#include "snaxels/mesh/report.h"
#include "snaxels/mesh/triangle_soup.h"

namespace snaxels {

/// A mesh ready for the engine together with what was done to it.
struct LoadedMesh {
    Mesh mesh;
    MeshReport report;
    /// Per mesh vertex: an input (soup) vertex at its place. Posing the soup
    /// (animation) and reading these gives the mesh's posed positions.
    std::vector<std::uint32_t> vertex_source;
    /// Per face, the file's normal at each corner in the order of the face's
    /// vertices (fv_range), or empty when the file has no normals. A zero
    /// vector is a corner the file gave no usable normal. Where corners at
    /// one vertex disagree across an edge, the file shades the edge hard
    /// (split_sharp_edges).
    std::vector<std::array<glm::dvec3, 3>> corner_normals;
    /// The scene's parts and materials, and per face the index of each
    /// (empty for a mesh without parts).
    std::vector<SceneObject> objects;
    std::vector<SceneMaterial> materials;
    std::vector<std::uint32_t> face_object, face_material;
};

/// Memory a mesh needs per face to be drawn, estimated from the peaks of
/// toon drawings and exports of meshes of 0.1 to 1 million faces, with room.
inline constexpr std::uint64_t kBytesPerFace = 600;

/// Builds a Mesh from @p soup. @p source names the input in the report.
/// Throws snaxels::Error (message without the source) when the soup has a
/// non-finite coordinate, an out-of-range index or no usable face, or when
/// its faces need more memory than the machine has (kBytesPerFace each),
/// before allocating for them.
LoadedMesh build_mesh(const TriangleSoup& soup, const std::string& source);

/// Recomputes every vertex normal as the normalized sum of its faces'
/// area-weighted normals (isolated vertices get +Z).
void compute_vertex_normals(Mesh& mesh);

} // namespace snaxels
