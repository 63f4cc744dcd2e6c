#include "snaxels/visibility/visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "snaxels/snaxel/feature_edges.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {

FaceId common_face(const MeshTopology& topo, const Snaxel& a, const Snaxel& b) {
    for (const FaceId f : topo.edge_faces()[a.edge])
        if (f != MeshTopology::kNone &&
            (f == topo.edge_faces()[b.edge][0] || f == topo.edge_faces()[b.edge][1]))
            return f;
    // Snaxels at the two ends of an edge (a crease or border chain's step):
    // a face of the edge they share.
    auto vertex = [](const Snaxel& s) { return s.t == 0.0 ? s.inside : s.t == 1.0 ? s.outside : VertexId(); };
    const VertexId va = vertex(a), vb = vertex(b);
    if (va == MeshTopology::kNone || vb == MeshTopology::kNone || va == vb) return MeshTopology::kNone;
    for (const EdgeId e : {a.edge, b.edge}) {
        const auto& ends = topo.edge_vertices()[e];
        if ((ends[0] == va && ends[1] == vb) || (ends[0] == vb && ends[1] == va))
            for (const FaceId f : topo.edge_faces()[e])
                if (f != MeshTopology::kNone) return f;
    }
    return MeshTopology::kNone;
}

std::vector<std::uint8_t> selected_stretches(const MeshTopology& topo, const ContourResult& contour) {
    const PartMatcher matcher(contour.spec.parts, topo.parts());
    if (matcher.all()) return {};
    const Fronts& fronts = contour.fronts;
    std::vector<std::uint8_t> out(fronts.snaxels.size(), 1);
    const bool along_edges = contour.spec.along_edges();
    const bool meeting = contour.spec.kind == ContourKind::Intersection;
    auto on_edge = [&](const Snaxel& s) {
        const auto faces = along_edges ? faces_beside(topo, s.edge) : topo.edge_faces()[s.edge];
        return matcher.face(faces[0]) || matcher.face(faces[1]);
    };
    std::vector<std::int32_t> order;
    for (const FrontLoop& loop : fronts.loops) {
        order.clear();
        fronts.for_each_in_loop(loop, [&](std::int32_t s) { order.push_back(s); });
        const std::size_t n = order.size();
        for (std::size_t k = 0; k < n; ++k) {
            const Snaxel& s = fronts.snaxels[order[k]];
            if (along_edges || n == 1) {
                // A chain's snaxel lies on the edge of its stretch (chain_fronts).
                out[order[k]] = on_edge(s);
                continue;
            }
            if (meeting) {
                // Where two surfaces meet: on both (its edge's and the face it pierces).
                const std::int32_t at = order[k];
                const FaceId pierced = at < std::int32_t(contour.snaxel_pierced.size()) ? contour.snaxel_pierced[at] : FaceId();
                out[order[k]] = on_edge(s) || (pierced.valid() && matcher.face(pierced));
                continue;
            }
            const bool last = k + 1 == n && !loop.closed;
            const Snaxel& a = last ? fronts.snaxels[order[k - 1]] : s;
            const Snaxel& b = last ? s : fronts.snaxels[order[(k + 1) % n]];
            const FaceId face = common_face(topo, a, b);
            out[order[k]] = face != MeshTopology::kNone ? matcher.face(face) : on_edge(s);
        }
    }
    return out;
}

VisibilitySampler::VisibilitySampler(const RayScene& scene, const Camera& camera, VisibilityOptions options)
    : scene_(scene), camera_(camera), options_(options), near_(near_plane_of(camera, scene.topology())),
      forward_(camera.forward()) {}

double VisibilitySampler::past_near(const glm::dvec3& p) const {
    if (camera_.orthographic()) return std::numeric_limits<double>::infinity();
    return glm::dot(p - camera_.eye, forward_) - near_;
}

void VisibilitySampler::stop_at_near(VisibilityRay& ray) const {
    if (camera_.orthographic() || !(ray.tfar > 0.0)) return;
    // Depth falls linearly along the ray to 0 at the eye: the near plane
    // is reached at the fraction (depth - near) / depth of the way.
    const double depth = glm::dot(ray.origin - camera_.eye, forward_);
    ray.tfar = depth > near_ ? ray.tfar * (depth - near_) / depth : 0.0;
}

VisibilityRay VisibilitySampler::make_ray(const glm::dvec3& p, const glm::dvec3& n,
                                          double scale) const {
    VisibilityRay ray;
    ray.original_neighbourhood = options_.original_neighbourhood;
    ray.origin = p + options_.normal_offset * scale * n;
    if (camera_.orthographic()) {
        ray.dir = -glm::normalize(camera_.view_dir);
        ray.tfar = std::numeric_limits<double>::infinity();
    } else {
        const glm::dvec3 to_eye = camera_.eye - ray.origin;
        ray.tfar = glm::length(to_eye);
        ray.dir = ray.tfar > 0.0 ? to_eye / ray.tfar : glm::dvec3(0, 0, 1);
        stop_at_near(ray);
    }
    return ray;
}

namespace {

/// The offset of a point on a crease's own line (no facet to clear): a
/// tenth of the mean length of the edges round @p v. The start must still
/// leave the point: where another surface passes through it (a leg's rim
/// on the floor), contact_qi looks past it.
double crease_scale(const MeshTopology& topo, VertexId v) {
    double sum = 0.0;
    int n = 0;
    for (const VertexId w : topo.neighbours(v))
        if (const double l = glm::length(topo.positions()[w] - topo.positions()[v]); l > 0.0) sum += l, ++n;
    return 0.1 * (n > 0 ? sum / n : topo.mean_edge_length());
}

/// Whether edge @p e has length but only faces of no area beside it: a
/// diagonal of a split sharp edge's strip, from one side's copy of a
/// vertex to the other side's copy of the next, along the crease.
bool strip_diagonal(const MeshTopology& topo, EdgeId e) {
    if (!topo.has_strips()) return false;
    const auto [a, b] = topo.edge_vertices()[e];
    if (!(glm::length(topo.positions()[a] - topo.positions()[b]) > 0.0)) return false;
    for (const FaceId f : topo.edge_faces()[e])
        if (f.valid() && face_has_area(topo, f)) return false;
    return true;
}

/// The length across which the faces beside edge @p e leave the smooth
/// surface: the edge's length, but no more than twice the least height of
/// a face beside it (the long edges of a cylinder's side run where the
/// facets follow the surface; across them its faces are narrow), and no
/// less than a tenth of the edge (a sliver says little); a face with no
/// area (a split sharp edge's strip) says nothing.
double facet_scale(const MeshTopology& topo, EdgeId e) {
    const auto [a, b] = topo.edge_vertices()[e];
    const double len = glm::length(topo.positions()[a] - topo.positions()[b]);
    if (!(len > 0.0)) return crease_scale(topo, a); // a rung of a strip, between two copies of one vertex
    double across = len;
    for (const FaceId f : topo.edge_faces()[e]) {
        if (!f.valid() || !face_has_area(topo, f)) continue; // a sharp edge's strip
        const auto& fv = topo.face_vertices()[f];
        const glm::dvec3 p0 = topo.positions()[fv[0]], p1 = topo.positions()[fv[1]], p2 = topo.positions()[fv[2]];
        const double longest = std::sqrt(std::max({glm::dot(p1 - p0, p1 - p0), glm::dot(p2 - p1, p2 - p1), glm::dot(p0 - p2, p0 - p2)}));
        across = std::min(across, glm::length(glm::cross(p1 - p0, p2 - p0)) / longest); // its height
    }
    return std::clamp(2.0 * across, 0.1 * len, len);
}

} // namespace

VisibilityRay VisibilitySampler::snaxel_ray(const Snaxel& s, const glm::dvec3& p,
                                            const glm::dvec3& n) const {
    const MeshTopology& topo = scene_.topology();
    VisibilityRay ray = make_ray(p, n, facet_scale(topo, s.edge));
    ray.ignore = {s.inside, s.outside, VertexId()};
    const FaceParts* parts = topo.parts();
    if (parts && parts->objects.size() > 1 && parts->object.size() == topo.n_faces() && strip_diagonal(topo, s.edge)) {
        // On a crease's own line, along a strip's diagonal: the ray starts
        // a fifth of the diagonal off the surface (of a box's side), so it
        // runs well beside the line of sight. Where it meets another object
        // standing apart from the point (not one the crease rests against,
        // a slab under a wall, which the ray is meant to clear), the line of
        // sight itself decides: off the crease by a crease's offset, from
        // as far along it as the ray started off the surface. (A pillar in
        // front of an arch's post, 8 px clear of the post's edge in the
        // picture, hid that edge.)
        const RayHit hit = scene_.nearest(ray);
        const FaceId own = topo.edge_faces()[s.edge][0];
        const double len = glm::length(topo.positions()[s.inside] - topo.positions()[s.outside]);
        const double reach = options_.normal_offset * len; // how far off the surface the ray started
        const bool apart = hit.hit() && glm::length(ray.origin + ray.dir * hit.t - p) > 0.5 * reach;
        if (apart && own.valid() && parts->object[hit.face] != parts->object[own]) {
            VisibilityRay sight = make_ray(p, n, crease_scale(topo, s.inside));
            const double skip = std::isinf(sight.tfar) ? reach : std::min(reach, 0.5 * sight.tfar);
            sight.origin += skip * sight.dir;
            if (!std::isinf(sight.tfar)) sight.tfar -= skip;
            sight.ignore = ray.ignore;
            return sight;
        }
    }
    return ray;
}

VisibilityRay VisibilitySampler::face_ray(FaceId face, const glm::dvec3& p,
                                          const glm::dvec3& n) const {
    const MeshTopology& topo = scene_.topology();
    const auto& fv = topo.face_vertices()[face];
    const double len = (glm::length(topo.positions()[fv[0]] - topo.positions()[fv[1]]) +
                        glm::length(topo.positions()[fv[1]] - topo.positions()[fv[2]]) +
                        glm::length(topo.positions()[fv[2]] - topo.positions()[fv[0]])) / 3.0;
    VisibilityRay ray = make_ray(p, n, len);
    ray.ignore = {fv[0], fv[1], fv[2]};
    return ray;
}

VisibilityRay VisibilitySampler::vertex_ray(VertexId v, bool back_side) const {
    const MeshTopology& topo = scene_.topology();
    double len = 0.0;
    const std::span<const VertexId> ring = topo.neighbours(v);
    for (const VertexId w : ring) len += glm::length(topo.positions()[w] - topo.positions()[v]);
    len = !ring.empty() ? len / double(ring.size()) : topo.mean_edge_length();
    VisibilityRay ray = make_ray(topo.positions()[v], back_side ? -topo.normals()[v] : topo.normals()[v], len);
    ray.ignore = {v, VertexId(), VertexId()};
    return ray;
}

VisibilityRay VisibilitySampler::edge_ray(EdgeId e, double t) const {
    const MeshTopology& topo = scene_.topology();
    const auto [a, b] = topo.edge_vertices()[e];
    const glm::dvec3 p = glm::mix(topo.positions()[a], topo.positions()[b], t);
    const glm::dvec3 n = slerp_normal(topo.normals()[a], topo.normals()[b], t);
    VisibilityRay ray = make_ray(p, n, glm::length(topo.positions()[a] - topo.positions()[b]));
    ray.ignore = {a, b, VertexId()};
    return ray;
}

VisibilityRay VisibilitySampler::meeting_ray(const glm::dvec3& p, double scale) const {
    VisibilityRay ray = make_ray(p, glm::dvec3(0.0), scale);
    const double lift = 1e-3 * std::max(scale, scene_.topology().mean_edge_length());
    ray.origin += lift * ray.dir;
    if (!std::isinf(ray.tfar)) ray.tfar = std::max(0.0, ray.tfar - lift);
    return ray;
}

int VisibilitySampler::qi(const VisibilityRay& ray) const {
    if (!scene_.occluded(ray)) return 0; // most samples: an any-hit query suffices
    const Crossings c = scene_.count(ray);
    return std::max(c.front, c.back);
}

namespace {

/// Cuts every loop of @p contour into runs of equal class, given each
/// snaxel's class (@p snaxel_qi, indexed like the snaxels) and
/// change_point(a, b, from): where the class stops being `from` on the
/// segment from snaxel a to snaxel b. Loops are cut in parallel.
template <class ChangePoint>
ContourVisibility cut_runs(const SnaxelEngine& engine, const ContourResult& contour, const std::vector<int>& snaxel_qi,
                           ChangePoint&& change_point) {
    const Fronts& fronts = contour.fronts;
    ContourVisibility out;
    out.loops.resize(fronts.loops.size());
    parallel_for(fronts.loops.size(), [&](std::size_t loop_index) {
        const FrontLoop& loop = fronts.loops[loop_index];
        LoopVisibility& lv = out.loops[loop_index];
        std::vector<std::int32_t> order;
        order.reserve(loop.size);
        fronts.for_each_in_loop(loop, [&](std::int32_t s) { order.push_back(s); });
        const std::size_t n = order.size();
        for (const std::int32_t s : order) lv.snaxel_qi.push_back(snaxel_qi[s]);
        lv.change_before.assign(n, glm::dvec3(0.0));
        auto point = [&](std::size_t k) { return engine.position(fronts.snaxels[order[k % n]]); };

        std::size_t start = 0; // where the first run begins
        bool any_change = false;
        for (std::size_t k = 1; k < n + (loop.closed ? 1 : 0); ++k)
            if (lv.snaxel_qi[k % n] != lv.snaxel_qi[k - 1]) {
                any_change = true;
                start = k % n;
                break;
            }
        if (!any_change) {
            VisibilityRun run{lv.snaxel_qi.empty() ? 0 : lv.snaxel_qi[0], loop.closed, {}};
            for (std::size_t k = 0; k < n; ++k) run.points.push_back(point(k));
            lv.runs.push_back(std::move(run));
            return;
        }
        // Walk the loop once from the first change (closed) or its start (open).
        const std::size_t first = loop.closed ? start : 0;
        const std::size_t steps = loop.closed ? n : n - 1;
        VisibilityRun run{lv.snaxel_qi[first], false, {}, first, loop.closed};
        glm::dvec3 first_change{};
        if (loop.closed) {
            first_change = change_point(order[(first + n - 1) % n], order[first], lv.snaxel_qi[(first + n - 1) % n]);
            lv.change_before[first] = first_change;
            run.points.push_back(first_change);
        }
        run.points.push_back(point(first));
        for (std::size_t step = 0; step < steps; ++step) {
            const std::size_t k = (first + step) % n, next = (first + step + 1) % n;
            if (loop.closed && next == first) {
                run.points.push_back(first_change);
                break;
            }
            if (lv.snaxel_qi[next] != lv.snaxel_qi[k]) {
                const glm::dvec3 c = change_point(order[k], order[next], lv.snaxel_qi[k]);
                lv.change_before[next] = c;
                run.points.push_back(c);
                lv.runs.push_back(std::move(run));
                run = VisibilityRun{lv.snaxel_qi[next], false, {c}, next, true};
            }
            run.points.push_back(point(next));
        }
        lv.runs.push_back(std::move(run));
    }, 1);
    return out;
}

/// Where the margin of a contour that leaves parts out crosses zero between
/// snaxels a and b (linear in the margins).
glm::dvec3 margin_zero(const SnaxelEngine& engine, const ContourResult& contour, std::int32_t a, std::int32_t b) {
    const double ma = contour.snaxel_margin[a], mb = contour.snaxel_margin[b];
    const double u = ma != mb ? std::clamp(ma / (ma - mb), 0.0, 1.0) : 0.5;
    return (1.0 - u) * engine.position(contour.fronts.snaxels[a]) + u * engine.position(contour.fronts.snaxels[b]);
}

/// The object of face @p f on a scene of several objects, else -1.
std::int64_t object_of(const MeshTopology& topo, FaceId f) {
    const FaceParts* parts = topo.parts();
    if (!parts || parts->objects.size() < 2 || parts->object.size() != topo.n_faces() || !f.valid()) return -1;
    return std::int64_t(parts->object[f]);
}

/// The object of the faces beside snaxel @p s's edge (-1 as object_of).
std::int64_t snaxel_object(const MeshTopology& topo, const Snaxel& s) {
    std::int64_t o = -1;
    for (const FaceId f : topo.edge_faces()[s.edge])
        if (f.valid()) o = object_of(topo, f);
    return o;
}

} // namespace

std::vector<std::uint8_t> VisibilitySampler::over_other_objects(const SnaxelEngine& engine,
                                                                const ContourResult& contour) const {
    const Fronts& fronts = contour.fronts;
    const MeshTopology& topo = scene_.topology();
    std::vector<std::uint8_t> out(fronts.snaxels.size(), 0);
    const double radius = bounding_radius(topo), step = kOverObjectsStep * radius, reach = 4.0 * radius + 1.0;
    parallel_for(fronts.snaxels.size(), [&](std::size_t i) {
        const Snaxel& s = fronts.snaxels[i];
        const std::int64_t own = snaxel_object(topo, s);
        if (own < 0) return; // one object, or no face beside the snaxel
        const glm::dvec3 p = engine.position(s);
        const glm::dvec3 v = camera_.to_viewer(p);
        // Across the contour in the image plane, away from the surface.
        glm::dvec3 across = engine.normal(s) - glm::dot(engine.normal(s), v) * v;
        const double len = glm::length(across);
        if (!(len > 0.0)) return;
        // The ray through that image point from in front of everything: a
        // surface just past the outline may lie nearer than the contour
        // (the floor in front of a box's bottom edge).
        const glm::dvec3 q = p + step * across / len;
        VisibilityRay ray;
        ray.dir = -camera_.to_viewer(q);
        // From in front of everything (perspective: from the near plane, past what it clips).
        ray.origin = camera_.orthographic() ? q + reach * camera_.to_viewer(q)
                                            : camera_.eye + ray.dir * (near_ / std::max(glm::dot(ray.dir, forward_), 1e-12));
        ray.tfar = std::numeric_limits<double>::infinity();
        const RayHit hit = scene_.nearest(ray);
        out[i] = hit.hit() && object_of(topo, hit.face) != own;
    }, 256);
    return out;
}

int VisibilitySampler::qi_from(const VisibilityRay& ray, const glm::dvec3& origin) const {
    VisibilityRay moved = ray;
    moved.origin = origin;
    if (!camera_.orthographic()) {
        moved.tfar = glm::length(camera_.eye - origin);
        moved.dir = moved.tfar > 0.0 ? (camera_.eye - origin) / moved.tfar : ray.dir;
        stop_at_near(moved);
    }
    return qi(moved);
}

int VisibilitySampler::enclosed_qi(const VisibilityRay& ray, const glm::dvec3& p, std::int64_t object) const {
    const double offset = glm::length(ray.origin - p);
    if (!(offset > 0.0)) return 0;
    // Nearly always no other object comes that near: no ray needed.
    if (!scene_.near_other_object(p, object, offset)) return 0;
    VisibilityRay along = ray;
    along.origin = p;
    along.dir = (ray.origin - p) / offset;
    along.tfar = offset;
    // Nearly always nothing lies between: the any-hit query says so cheaply.
    if (!scene_.occluded(along)) return 0;
    const RayHit hit = scene_.nearest(along);
    if (!hit.hit() || object_of(scene_.topology(), hit.face) == object || hit.t <= 0.05 * offset) return 0;
    return qi_from(ray, p + 0.5 * hit.t * along.dir);
}

int VisibilitySampler::contact_qi(const VisibilityRay& ray, const glm::dvec3& p, std::int64_t object) const {
    if (object < 0) return qi(ray);
    // As qi(), keeping the count's nearest crossing.
    if (!scene_.occluded(ray)) return enclosed_qi(ray, p, object);
    const Crossings c = scene_.count(ray);
    const int q = std::max(c.front, c.back);
    if (q == 0) return enclosed_qi(ray, p, object);
    const MeshTopology& topo = scene_.topology();
    const RayHit& hit = c.nearest;
    const double offset = glm::length(ray.origin - p);
    if (!hit.hit() || !(offset > 0.0) || object_of(topo, hit.face) == object) return q;
    const auto& fv = topo.face_vertices()[hit.face];
    const glm::dvec3 a = topo.positions()[fv[0]];
    glm::dvec3 normal = glm::cross(topo.positions()[fv[1]] - a, topo.positions()[fv[2]] - a);
    const double len = glm::length(normal);
    if (!(len > 0.0)) return q;
    normal /= len;
    const glm::dvec3 at = ray.origin + hit.t * ray.dir;
    // The crossing's surface passes through p, near p: a contact.
    if (std::abs(glm::dot(p - a, normal)) > 0.05 * offset || glm::length(at - p) > 10.0 * offset) return q;
    return qi_from(ray, p + offset * camera_.to_viewer(p));
}

bool VisibilitySampler::qi_is(const VisibilityRay& ray, const glm::dvec3& p, std::int64_t object, int q) const {
    if (object >= 0) return contact_qi(ray, p, object) == q;
    // One object: QI 0 is an any-hit query's answer alone.
    if (!scene_.occluded(ray)) return q == 0;
    if (q == 0) return false;
    const Crossings c = scene_.count(ray);
    return std::max(c.front, c.back) == q;
}

namespace {

/// A hidden snaxel whose level is not counted yet (HiddenLevels::WhereSeen).
constexpr int kUncounted = std::numeric_limits<int>::max();

} // namespace

void VisibilitySampler::count_where_seen(const SnaxelEngine& engine, const ContourResult& contour,
                                         std::vector<int>& snaxel_qi) const {
    const Fronts& fronts = contour.fronts;
    auto count = [&](std::int32_t s) {
        const Snaxel& sn = fronts.snaxels[s];
        const glm::dvec3 p = engine.position(sn);
        // Known hidden (the any-hit query said so): the count alone.
        const Crossings c = scene_.count(snaxel_ray(sn, p, engine.normal(sn)));
        snaxel_qi[s] = std::max(c.front, c.back);
    };
    parallel_for(fronts.loops.size(), [&](std::size_t l) {
        const FrontLoop& loop = fronts.loops[l];
        std::vector<std::int32_t> order;
        order.reserve(loop.size);
        fronts.for_each_in_loop(loop, [&](std::int32_t s) { order.push_back(s); });
        const std::size_t n = order.size();
        if (n == 0) return;
        auto seen = [&](std::size_t k) { return snaxel_qi[order[k % n]] == 0; };
        // Where the next snaxel is seen: the level a change to seen starts from.
        for (std::size_t k = 0; k + 1 < n + (loop.closed ? 1 : 0); ++k)
            if (snaxel_qi[order[k]] == kUncounted && seen(k + 1)) count(order[k]);
        // The rest take the level of their hidden stretch's end, walking
        // back from a snaxel already known (on an open loop, from its end).
        auto level_after = [&](std::size_t k) {
            if (k >= n) return 1; // an open loop's last snaxel
            const int q = snaxel_qi[order[k]];
            return q > 0 && q != kNotDrawn ? q : 1;
        };
        std::size_t known = n; // an open loop's walk starts past its end
        if (loop.closed) {
            known = 0;
            while (known < n && snaxel_qi[order[known]] == kUncounted) ++known;
            if (known == n) { // hidden all round, nowhere counted
                for (const std::int32_t s : order) snaxel_qi[s] = 1;
                return;
            }
        }
        for (std::size_t step = 1; step <= n; ++step) {
            const std::size_t k = (known + n - step) % n;
            if (snaxel_qi[order[k]] != kUncounted) continue;
            snaxel_qi[order[k]] = level_after(loop.closed ? (k + 1) % n : k + 1);
        }
    }, 1);
}

ContourVisibility VisibilitySampler::classify(const SnaxelEngine& engine, const ContourResult& contour,
                                              HiddenLevels levels) const {
    const Fronts& fronts = contour.fronts;
    const MeshTopology& topo = scene_.topology();
    const bool margins = !contour.snaxel_margin.empty();
    std::vector<std::uint8_t> selected = selected_stretches(topo, contour);
    if (contour.spec.parts.over_objects) {
        const std::vector<std::uint8_t> over = over_other_objects(engine, contour);
        if (selected.empty()) selected.assign(over.size(), 1);
        for (std::size_t i = 0; i < over.size(); ++i) selected[i] = selected[i] && over[i];
    }
    std::vector<int> snaxel_qi(fronts.snaxels.size());
    const bool meeting = contour.spec.kind == ContourKind::Intersection;
    const bool where_seen = levels == HiddenLevels::WhereSeen && !meeting;
    auto edge_length = [&](const Snaxel& s) { return glm::length(topo.positions()[s.inside] - topo.positions()[s.outside]); };
    // Snaxels nearer the eye than the near plane are clipped: not drawn.
    std::vector<std::uint8_t> clipped(camera_.orthographic() ? 0 : fronts.snaxels.size());
    parallel_for(fronts.snaxels.size(), [&](std::size_t i) {
        const Snaxel& s = fronts.snaxels[i];
        const glm::dvec3 p = engine.position(s);
        if (!clipped.empty()) clipped[i] = past_near(p) < 0.0;
        if ((margins && contour.snaxel_margin[i] < 0.0) || (!selected.empty() && !selected[i]) ||
            (!clipped.empty() && clipped[i])) {
            snaxel_qi[i] = kNotDrawn;
            return;
        }
        if (meeting) {
            snaxel_qi[i] = qi(meeting_ray(p, edge_length(s)));
            return;
        }
        const VisibilityRay ray = snaxel_ray(s, p, engine.normal(s));
        const std::int64_t object = snaxel_object(topo, s);
        if (where_seen && object < 0) snaxel_qi[i] = scene_.occluded(ray) ? kUncounted : 0;
        else snaxel_qi[i] = contact_qi(ray, p, object);
    });
    if (where_seen) count_where_seen(engine, contour, snaxel_qi);

    // The point where QI stops being `from` between snaxels a and b.
    auto change_point = [&](std::int32_t ia, std::int32_t ib, int from) {
        // Across the near plane: where the segment meets it (depth is linear along it).
        if (!clipped.empty() && clipped[ia] != clipped[ib]) {
            const glm::dvec3 pa = engine.position(fronts.snaxels[ia]), pb = engine.position(fronts.snaxels[ib]);
            const double da = past_near(pa), db = past_near(pb);
            const double u = std::clamp(da / (da - db), 0.0, 1.0);
            return (1.0 - u) * pa + u * pb;
        }
        // From one part to another: at the snaxel on the edge between them.
        if (!selected.empty() && selected[ia] != selected[ib]) return engine.position(fronts.snaxels[ib]);
        if (margins && (snaxel_qi[ia] == kNotDrawn || snaxel_qi[ib] == kNotDrawn)) return margin_zero(engine, contour, ia, ib);
        const Snaxel& a = fronts.snaxels[ia];
        const Snaxel& b = fronts.snaxels[ib];
        const glm::dvec3 pa = engine.position(a), pb = engine.position(b);
        if (meeting) { // the segment lies on both surfaces
            const double scale = 0.5 * (edge_length(a) + edge_length(b));
            double lo = 0.0, hi = 1.0;
            for (int step = 0; step < options_.bisection_steps; ++step) {
                const double mid = 0.5 * (lo + hi);
                (qi(meeting_ray((1.0 - mid) * pa + mid * pb, scale)) == from ? lo : hi) = mid;
            }
            const double u = 0.5 * (lo + hi);
            return (1.0 - u) * pa + u * pb;
        }
        const glm::dvec3 na = engine.normal(a), nb = engine.normal(b);
        const FaceId face = common_face(topo, a, b);
        double lo = 0.0, hi = 1.0;
        for (int step = 0; step < options_.bisection_steps && face != MeshTopology::kNone; ++step) {
            const double mid = 0.5 * (lo + hi);
            // Opposite normals (a sheet seen from both sides) blend to
            // nothing half way: the nearer end's normal stands in.
            const glm::dvec3 blend = (1.0 - mid) * na + mid * nb;
            const double blend_length = glm::length(blend);
            const glm::dvec3 n = blend_length > 1e-9 ? blend / blend_length : (mid < 0.5 ? na : nb);
            const glm::dvec3 p = (1.0 - mid) * pa + mid * pb;
            if (qi_is(face_ray(face, p, n), p, object_of(topo, face), from)) lo = mid;
            else hi = mid;
        }
        const double u = 0.5 * (lo + hi);
        return (1.0 - u) * pa + u * pb;
    };
    return cut_runs(engine, contour, snaxel_qi, change_point);
}

ContourVisibility drawn_parts(const SnaxelEngine& engine, const ContourResult& contour, const Camera* camera) {
    std::vector<std::uint8_t> selected = selected_stretches(engine.topology(), contour);
    if (contour.spec.parts.over_objects) selected.assign(contour.fronts.snaxels.size(), 0); // needs the rays
    const bool margins = !contour.snaxel_margin.empty();
    // How far each snaxel lies past a perspective camera's near plane (clipped below 0).
    std::vector<double> past;
    if (camera && !camera->orthographic()) {
        const NearPlane near(*camera, engine.topology());
        past.resize(contour.fronts.snaxels.size());
        bool any = false;
        for (std::size_t i = 0; i < past.size(); ++i) {
            past[i] = near.past(engine.position(contour.fronts.snaxels[i]));
            any = any || past[i] < 0.0;
        }
        if (!any) past.clear(); // nothing clipped: as without a camera
    }
    if (!margins && selected.empty() && past.empty()) return {};
    std::vector<int> cls(contour.fronts.snaxels.size());
    for (std::size_t i = 0; i < cls.size(); ++i)
        cls[i] = (margins && contour.snaxel_margin[i] < 0.0) || (!selected.empty() && !selected[i]) ||
                         (!past.empty() && past[i] < 0.0)
                     ? kNotDrawn
                     : 0;
    return cut_runs(engine, contour, cls, [&](std::int32_t a, std::int32_t b, int) {
        if (!past.empty() && (past[a] < 0.0) != (past[b] < 0.0)) { // on the near plane
            const double u = std::clamp(past[a] / (past[a] - past[b]), 0.0, 1.0);
            return (1.0 - u) * engine.position(contour.fronts.snaxels[a]) + u * engine.position(contour.fronts.snaxels[b]);
        }
        if (!selected.empty() && selected[a] != selected[b]) return engine.position(contour.fronts.snaxels[b]);
        return margin_zero(engine, contour, a, b);
    });
}

} // namespace snaxels
