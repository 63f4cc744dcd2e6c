#include "snaxels/visibility/ray_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>

#include <embree3/rtcore.h>

#include "snaxels/error.h"
#include "snaxels/mesh/parts.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/util/detail/embree_device.h"

namespace snaxels {

// What the filter needs: the context Embree passes through, plus ours.
struct CountContext {
    RTCIntersectContext embree;
    const MeshTopology* topo;
    const VisibilityRay* ray;
    // On a refined mesh, when the ray asks, the faces ignored are those of
    // the original mesh around the original vertices the ray's ignored
    // vertices lie between, as they would be on the mesh as loaded.
    const MeshRefinement* refinement = nullptr;
    std::array<VertexId, 9> ignore_base{};
    std::size_t n_ignore_base = 0;
    Crossings crossings;
    // A primitive can be reported more than once; remember what was counted
    // (a ray crosses a few faces: kept in place, past that in `more`).
    std::array<std::uint32_t, 16> seen{};
    std::size_t n_seen = 0;
    std::vector<std::uint32_t> more;
    /// Whether @p prim was seen before; it is seen from now on.
    bool seen_before(std::uint32_t prim) {
        const auto kept = std::span(seen).first(n_seen);
        if (std::find(kept.begin(), kept.end(), prim) != kept.end() ||
            std::find(more.begin(), more.end(), prim) != more.end())
            return true;
        if (n_seen < seen.size()) seen[n_seen++] = prim;
        else more.push_back(prim);
        return false;
    }
};

namespace {

/// The face Embree calls primitive @p prim (faces go in in id order).
FaceId face_of_primitive(std::uint32_t prim) { return FaceId(std::int32_t(prim)); }

bool ignored(const CountContext& c, FaceId face) {
    if (c.refinement) {
        const auto& corners = c.refinement->base_faces[c.refinement->face_origin[face]];
        const auto ignore = std::span(c.ignore_base).first(c.n_ignore_base);
        for (const VertexId v : corners)
            for (const VertexId w : ignore)
                if (c.topo->same_point(v, w)) return true;
        return false;
    }
    // The copies of a vertex along a split sharp edge are the same point:
    // the faces around all of them are the sample's own surface.
    for (const VertexId v : c.topo->face_vertices()[face])
        for (const VertexId w : c.ray->ignore)
            if (w != MeshTopology::kNone && c.topo->same_point(v, w)) return true;
    return false;
}

void count_filter(const RTCFilterFunctionNArguments* args) {
    auto* c = reinterpret_cast<CountContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        args->valid[i] = 0; // reject: keep traversing to find every crossing
        const std::uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
        const FaceId face = face_of_primitive(prim);
        if (ignored(*c, face)) continue;
        if (c->seen_before(prim)) continue;
        const auto& fv = c->topo->face_vertices()[face];
        const glm::dvec3 a = c->topo->positions()[fv[0]];
        const glm::dvec3 normal = glm::cross(c->topo->positions()[fv[1]] - a, c->topo->positions()[fv[2]] - a);
        if (glm::dot(normal, c->ray->dir) > 0.0) ++c->crossings.front;
        else ++c->crossings.back;
        RayHit& nearest = c->crossings.nearest;
        const float t = RTCRayN_tfar(args->ray, args->N, i);
        if (!nearest.hit() || t < nearest.t) {
            nearest.face = face;
            nearest.u = RTCHitN_u(args->hit, args->N, i);
            nearest.v = RTCHitN_v(args->hit, args->N, i);
            nearest.t = t;
        }
    }
}

void occlusion_filter(const RTCFilterFunctionNArguments* args) {
    auto* c = reinterpret_cast<CountContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] == -1 && ignored(*c, face_of_primitive(RTCHitN_primID(args->hit, args->N, i))))
            args->valid[i] = 0;
}

RTCRay make_ray(const VisibilityRay& r, const glm::dvec3& shift) {
    RTCRay ray{};
    ray.org_x = float(r.origin.x - shift.x);
    ray.org_y = float(r.origin.y - shift.y);
    ray.org_z = float(r.origin.z - shift.z);
    ray.dir_x = float(r.dir.x);
    ray.dir_y = float(r.dir.y);
    ray.dir_z = float(r.dir.z);
    ray.tnear = 0.0f;
    ray.tfar = std::isinf(r.tfar) ? std::numeric_limits<float>::infinity() : float(r.tfar);
    ray.mask = 0xFFFFFFFFu;
    ray.flags = 0;
    return ray;
}

} // namespace

RayScene::RayScene(MeshTopology topology) : topo_(std::move(topology)) {
    if (!topo_.positions().empty()) {
        glm::dvec3 lo = topo_.positions().values().front(), hi = lo;
        for (const glm::dvec3& p : topo_.positions()) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        origin_ = 0.5 * (lo + hi);
    }
    RTCDevice device = detail::embree_device();
    RTCScene scene = rtcNewScene(device);
    scene_ = scene;
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION | RTC_SCENE_FLAG_ROBUST |
                                RTC_SCENE_FLAG_DYNAMIC);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_LOW);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    geometry_ = geom;
    // The first build is the fast (Morton) one; refit() switches to refitting.
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_LOW);
    vertices_ = static_cast<float*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), topo_.n_vertices()));
    auto* index = static_cast<std::uint32_t*>(rtcSetNewGeometryBuffer(
        geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(std::uint32_t), topo_.n_faces()));
    if (!vertices_ || !index) throw Error("out of memory building the ray-tracing scene");
    // A split sharp edge's zero-area faces hide nothing; in float they can
    // keep a rounding-size area a ray could graze, so each is given one
    // corner three times, which Embree never hits.
    for (const FaceId f : topo_.faces()) {
        const auto& corners = topo_.face_vertices()[f];
        const bool strip = topo_.has_strips() && !face_has_area(topo_, f);
        for (const VertexId v : corners) *index++ = std::uint32_t((strip ? corners[0] : v).index());
    }
    upload_positions();
    measure_object_boxes();
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcCommitScene(scene);
}

void RayScene::measure_object_boxes() {
    const FaceParts* parts = topo_.parts();
    if (!parts || parts->objects.size() < 2 || parts->object.size() != topo_.n_faces()) return;
    const double inf = std::numeric_limits<double>::infinity();
    object_boxes_.assign(parts->objects.size(), {glm::dvec3(inf), glm::dvec3(-inf)});
    face_planes_ = FaceData<FacePlane>(topo_.n_faces());
    for (const FaceId f : topo_.faces()) {
        auto& [lo, hi] = object_boxes_[parts->object[f]];
        const auto& fv = topo_.face_vertices()[f];
        for (const VertexId v : fv) {
            lo = glm::min(lo, topo_.positions()[v]);
            hi = glm::max(hi, topo_.positions()[v]);
        }
        const glm::dvec3 a = topo_.positions()[fv[0]];
        face_planes_[f] = {glm::cross(topo_.positions()[fv[1]] - a, topo_.positions()[fv[2]] - a), a};
    }
    box_slack_ = 1e-5 * bounding_radius(topo_); // well past float's rounding of a hit (6e-8 of the extent)
}

bool RayScene::near_other_object(const glm::dvec3& p, std::int64_t object, double reach) const {
    if (object_boxes_.empty()) return true;
    const double r = reach + box_slack_;
    for (std::size_t o = 0; o < object_boxes_.size(); ++o) {
        if (std::int64_t(o) == object) continue;
        const auto& [lo, hi] = object_boxes_[o];
        const glm::dvec3 gap = glm::max(glm::max(lo - p, p - hi), glm::dvec3(0.0));
        if (glm::dot(gap, gap) <= r * r) return true;
    }
    return false;
}

RayScene::~RayScene() {
    if (geometry_) rtcReleaseGeometry(static_cast<RTCGeometry>(geometry_));
    if (scene_) rtcReleaseScene(static_cast<RTCScene>(scene_));
}

void RayScene::upload_positions() {
    float* out = vertices_;
    for (const glm::dvec3& p : topo_.positions())
        for (int k = 0; k < 3; ++k) *out++ = float(p[k] - origin_[k]);
}

void RayScene::refit(const MeshTopology& pose) {
    if (!pose.same_connectivity(topo_))
        throw InternalError("RayScene::refit: a pose of another mesh (its connectivity differs)");
    topo_ = pose;
    auto geom = static_cast<RTCGeometry>(geometry_);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_REFIT);
    upload_positions();
    measure_object_boxes();
    rtcUpdateGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0);
    rtcCommitGeometry(geom);
    rtcCommitScene(static_cast<RTCScene>(scene_));
}

void RayScene::init_context(CountContext& c, const VisibilityRay& r, bool counting) const {
    rtcInitIntersectContext(&c.embree);
    c.embree.filter = counting ? count_filter : occlusion_filter;
    c.topo = &topo_;
    c.ray = &r;
    if (topo_.refinement() && r.original_neighbourhood) {
        const MeshRefinement& refinement = *topo_.refinement();
        c.refinement = &refinement;
        auto add = [&](VertexId v) {
            const auto kept = std::span(c.ignore_base).first(c.n_ignore_base);
            if (std::find(kept.begin(), kept.end(), v) == kept.end()) c.ignore_base[c.n_ignore_base++] = v;
        };
        const VertexId first_added(refinement.base_vertices);
        for (const VertexId v : r.ignore) {
            if (v == MeshTopology::kNone) continue;
            if (v < first_added) {
                add(v);
                continue;
            }
            const std::size_t i = std::size_t(v.index() - first_added.index());
            for (std::size_t k = 0; k < 3; ++k)
                if (refinement.weights[i][int(k)] > 0.0) add(refinement.from[i][k]);
        }
    }
}

Crossings RayScene::count(const VisibilityRay& r) const {
    CountContext c{};
    init_context(c, r, true);
    RTCRayHit rayhit{};
    rayhit.ray = make_ray(r, origin_);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(static_cast<RTCScene>(scene_), &c.embree, &rayhit);
    return c.crossings;
}

RayHit RayScene::nearest(const VisibilityRay& r) const {
    CountContext c{};
    init_context(c, r, false); // the occlusion filter skips ignored faces only
    RTCRayHit rayhit{};
    rayhit.ray = make_ray(r, origin_);
    rayhit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(static_cast<RTCScene>(scene_), &c.embree, &rayhit);
    RayHit hit;
    if (rayhit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return hit;
    hit.face = face_of_primitive(rayhit.hit.primID);
    hit.u = rayhit.hit.u;
    hit.v = rayhit.hit.v;
    hit.t = rayhit.ray.tfar;
    return hit;
}

bool RayScene::occluded(const VisibilityRay& r) const {
    CountContext c{};
    init_context(c, r, false);
    RTCRay ray = make_ray(r, origin_);
    rtcOccluded1(static_cast<RTCScene>(scene_), &c.embree, &ray);
    return ray.tfar < 0.0f; // Embree marks an occluded ray with tfar = -inf
}

} // namespace snaxels
