#pragma once
/// A BVH of a triangle mesh (Embree) that counts every surface crossing of
/// a ray segment, front- and back-facing apart, ignoring the faces that
/// touch chosen vertices (the sample's own neighbourhood).

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/mesh/topology.h"

namespace snaxels {

/// A ray segment and the vertices whose incident faces it must not count.
struct VisibilityRay {
    glm::dvec3 origin{0.0};
    glm::dvec3 dir{0.0, 0.0, 1.0}; ///< unit, toward the viewer
    double tfar = 0.0;              ///< where the viewer is (infinity: orthographic)
    std::array<VertexId, 3> ignore{};
    /// On a refined mesh (core/mesh/refine.h): ignore the faces the mesh
    /// as loaded has around the original vertices the ignored ones lie
    /// between, not only the refined faces around them.
    bool original_neighbourhood = false;
};

/// The nearest surface a ray meets: its face, barycentric coordinates
/// (point = (1-u-v) a + u b + v c over the face's corners) and distance.
struct RayHit {
    FaceId face;
    double u = 0.0, v = 0.0, t = 0.0;
    bool hit() const { return face != MeshTopology::kNone; }
};

/// Crossings of a ray with faces facing along it (front: the face's normal
/// points toward the viewer) and against it, and the nearest of them (the
/// one RayScene::nearest finds).
struct Crossings {
    int front = 0;
    int back = 0;
    RayHit nearest;
};

struct CountContext;

class RayScene {
  public:
    /// Builds the BVH of @p topology's faces in its pose (the scene keeps
    /// the topology, a shared value).
    explicit RayScene(MeshTopology topology);
    ~RayScene();
    RayScene(const RayScene&) = delete;
    RayScene& operator=(const RayScene&) = delete;

    /// Refits the BVH to @p pose, another pose of the same connectivity (else
    /// InternalError), for meshes that move between frames.
    void refit(const MeshTopology& pose);

    /// Every crossing of the ray segment, each face once.
    Crossings count(const VisibilityRay& ray) const;
    /// Whether anything blocks the ray segment (faster than count()).
    bool occluded(const VisibilityRay& ray) const;
    /// The nearest crossing of the ray segment (the ignored faces skipped).
    RayHit nearest(const VisibilityRay& ray) const;

    const MeshTopology& topology() const { return topo_; }

    /// On a scene of several objects, whether @p p lies within @p reach of
    /// the box of an object other than @p object (in this pose): a ray
    /// segment from p no longer than reach can meet no other object
    /// otherwise. True on a mesh of one object.
    bool near_other_object(const glm::dvec3& p, std::int64_t object, double reach) const;
    /// On a scene of several objects (else empty), per face in this pose:
    /// cross(b - a, c - a) over its corners a, b, c, and a. Which way a face
    /// turns is asked of every face each frame; these lie in one array.
    struct FacePlane {
        glm::dvec3 normal, corner;
    };
    const FaceData<FacePlane>& face_planes() const { return face_planes_; }

  private:
    void upload_positions();
    void measure_object_boxes();
    void init_context(CountContext& context, const VisibilityRay& ray, bool counting) const;

    MeshTopology topo_;
    /// Embree works in float: vertices and rays are taken relative to the
    /// mesh's centre (in double), so a mesh far from the origin (1e7 away)
    /// keeps its detail.
    glm::dvec3 origin_{0.0};
    void* scene_ = nullptr;  // RTCScene
    void* geometry_ = nullptr; // RTCGeometry
    float* vertices_ = nullptr; // Embree-owned vertex buffer
    /// Per object of a scene of several (else empty): its box in this pose.
    std::vector<std::pair<glm::dvec3, glm::dvec3>> object_boxes_;
    double box_slack_ = 0.0; ///< how far Embree's single precision may place a hit
    FaceData<FacePlane> face_planes_;
};

} // namespace snaxels
