#pragma once
/// The one triangle mesh type of the project: an OpenMesh array-kernel
/// triangle mesh with double-precision points and per-vertex normals.

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <glm/vec3.hpp>

namespace snaxels {

struct MeshTraits : public OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
    using Normal = OpenMesh::Vec3d;
    VertexAttributes(OpenMesh::Attributes::Normal | OpenMesh::Attributes::Status);
    FaceAttributes(OpenMesh::Attributes::Status);
    EdgeAttributes(OpenMesh::Attributes::Status);
    HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
};

using Mesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

inline glm::dvec3 to_glm(const OpenMesh::Vec3d& p) { return {p[0], p[1], p[2]}; }
/// The index of an OpenMesh element's handle in arrays kept beside the mesh.
inline std::size_t slot(OpenMesh::BaseHandle h) { return std::size_t(h.idx()); }
inline OpenMesh::Vec3d to_om(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

} // namespace snaxels
