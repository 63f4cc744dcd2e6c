#pragma once
/// Refining a coarse mesh for the engine. Snaxels live on edges and a
/// contour crosses a face in a straight line, while the shading it follows
/// (N.L of the normalized interpolated normal) curves inside the face: on a
/// mesh whose faces span many pixels the contours, and the planar map's
/// regions, cut corners the shading does not. Each face is split into
/// 4^levels faces on its own plane (the surface and its outline do not
/// move), and every new vertex takes the normalized interpolation of its
/// face's vertex normals, so the refined mesh's contours follow the smooth
/// shading of the original. The original vertices keep their indices and
/// come first.

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "snaxels/mesh/build.h"
#include "snaxels/mesh/parts.h"
#include "snaxels/mesh/topology.h"

namespace snaxels {

/// Where the refined mesh's vertices come from: every vertex past the
/// original ones is a weighted sum of (up to) three original vertices.
struct MeshRefinement {
    int levels = 0;
    std::size_t base_vertices = 0;
    FaceData<std::array<VertexId, 3>> base_faces; ///< the original faces, for their normals
    FaceData<FaceId> face_origin;                    ///< per refined face: the original face it lies in
    std::vector<std::array<VertexId, 3>> from;       ///< per added vertex (past base_vertices): original vertices
    std::vector<glm::dvec3> weights;                     ///< per added vertex: their weights (sum 1)
};

/// Faces a mesh is refined to at least, by default: about a face per 4 px2
/// of a mesh filling a 512 x 512 view.
constexpr std::size_t kRefineTargetFaces = 20000;
constexpr int kMaxRefineLevels = 3;
/// No refinement makes more faces than this (levels asked for are lowered).
constexpr std::size_t kMaxRefinedFaces = 2000000;

/// The levels that bring @p faces to kRefineTargetFaces (0 for a mesh that
/// has them already; at most kMaxRefineLevels).
int auto_refine_levels(std::size_t faces);

/// @p topology with each face split into 4^@p levels (the same topology
/// when @p levels is 0); its `refinement` says how the added vertices
/// follow the original ones (recompute_normals keeps them on the surface
/// after the original vertices move).
MeshTopology refine_topology(const MeshTopology& topology, int levels);

/// The levels to refine @p faces by when asked for @p requested (a level
/// count, or kAutoRefine), capped so the mesh stays within reach: at most
/// kMaxRefineLevels, and no more than kMaxRefinedFaces faces.
constexpr int kAutoRefine = -1;
int refine_levels(std::size_t faces, int requested);

/// The topology the engine works on: @p mesh's, refined by @p levels
/// (kAutoRefine: auto_refine_levels of its faces with an area), with
/// @p parts (the scene's parts of the mesh's faces) when given.
MeshTopology engine_topology(const Mesh& mesh, int levels = kAutoRefine,
                             std::shared_ptr<const FaceParts> parts = nullptr);
/// engine_topology of a loaded mesh, with its parts (loaded_parts).
MeshTopology engine_topology(const LoadedMesh& mesh, int levels = kAutoRefine);

} // namespace snaxels
