#include "snaxels/visibility/ray_scene.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include <embree3/rtcore.h>

#include "snaxels/error.h"
#include "snaxels/mesh/refine.h"

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
    std::array<std::int32_t, 9> ignore_base{};
    int n_ignore_base = 0;
    Crossings crossings;
    // A primitive can be reported more than once; remember what was counted.
    std::vector<std::uint32_t> seen;
};

namespace {

bool ignored(const CountContext& c, std::uint32_t prim) {
    if (c.refinement) {
        const auto& corners = c.refinement->base_faces[std::size_t(c.refinement->face_origin[prim])];
        for (const std::int32_t v : corners)
            for (int i = 0; i < c.n_ignore_base; ++i)
                if (v == c.ignore_base[std::size_t(i)]) return true;
        return false;
    }
    for (const std::int32_t v : c.topo->face_vertices()[prim])
        for (const std::int32_t w : c.ray->ignore)
            if (v == w) return true;
    return false;
}

void count_filter(const RTCFilterFunctionNArguments* args) {
    auto* c = reinterpret_cast<CountContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        args->valid[i] = 0; // reject: keep traversing to find every crossing
        const std::uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
        if (ignored(*c, prim)) continue;
        if (std::find(c->seen.begin(), c->seen.end(), prim) != c->seen.end()) continue;
        c->seen.push_back(prim);
        const auto& fv = c->topo->face_vertices()[prim];
        const glm::dvec3 a = c->topo->positions()[fv[0]];
        const glm::dvec3 normal = glm::cross(c->topo->positions()[fv[1]] - a, c->topo->positions()[fv[2]] - a);
        if (glm::dot(normal, c->ray->dir) > 0.0) ++c->crossings.front;
        else ++c->crossings.back;
    }
}

void occlusion_filter(const RTCFilterFunctionNArguments* args) {
    auto* c = reinterpret_cast<CountContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i)
        if (args->valid[i] == -1 && ignored(*c, RTCHitN_primID(args->hit, args->N, i)))
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

namespace {

// One Embree device for the process: creating one starts a thread pool.
RTCDevice shared_device() {
    static const RTCDevice device = rtcNewDevice(nullptr);
    if (!device) throw Error("cannot start the ray tracer (Embree device)");
    return device;
}

} // namespace

RayScene::RayScene(MeshTopology topology) : topo_(std::move(topology)) {
    if (!topo_.positions().empty()) {
        glm::dvec3 lo = topo_.positions()[0], hi = lo;
        for (const glm::dvec3& p : topo_.positions()) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        origin_ = 0.5 * (lo + hi);
    }
    RTCDevice device = shared_device();
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
    for (std::size_t f = 0; f < topo_.n_faces(); ++f)
        for (int k = 0; k < 3; ++k) index[3 * f + k] = std::uint32_t(topo_.face_vertices()[f][k]);
    upload_positions();
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcCommitScene(scene);
}

RayScene::~RayScene() {
    if (geometry_) rtcReleaseGeometry(static_cast<RTCGeometry>(geometry_));
    if (scene_) rtcReleaseScene(static_cast<RTCScene>(scene_));
}

void RayScene::upload_positions() {
    for (std::size_t v = 0; v < topo_.n_vertices(); ++v)
        for (int k = 0; k < 3; ++k) vertices_[3 * v + k] = float(topo_.positions()[v][k] - origin_[k]);
}

void RayScene::refit(const MeshTopology& pose) {
    if (!pose.same_connectivity(topo_))
        throw InternalError("RayScene::refit: a pose of another mesh (its connectivity differs)");
    topo_ = pose;
    auto geom = static_cast<RTCGeometry>(geometry_);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_REFIT);
    upload_positions();
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
        auto add = [&](std::int32_t v) {
            for (int i = 0; i < c.n_ignore_base; ++i)
                if (c.ignore_base[std::size_t(i)] == v) return;
            c.ignore_base[std::size_t(c.n_ignore_base++)] = v;
        };
        for (const std::int32_t v : r.ignore) {
            if (v == MeshTopology::kNone) continue;
            if (std::size_t(v) < refinement.base_vertices) {
                add(v);
                continue;
            }
            const std::size_t i = std::size_t(v) - refinement.base_vertices;
            for (int k = 0; k < 3; ++k)
                if (refinement.weights[i][k] > 0.0) add(refinement.from[i][std::size_t(k)]);
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
    hit.face = std::int32_t(rayhit.hit.primID);
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
