#include "snaxels/snaxel/intersections.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <tuple>

#include "snaxels/error.h"
#include "snaxels/mesh/quantities.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/util/detail/embree_device.h"
#include "snaxels/util/detail/float_mode.h"
#include "snaxels/util/detail/parallel.h"
#include "snaxels/util/detail/predicates.h"

namespace snaxels {
namespace {

/// What Embree's callbacks read: the faces (primitive i is faces[i]) and
/// the pairs found.
struct CollideContext {
    const MeshTopology* topo = nullptr;
    std::vector<std::array<VertexId, 3>> corners; ///< primitive i's triangle
    std::vector<FaceId> faces;                     ///< primitive i's face (of the mesh as refined, or as loaded)
    glm::dvec3 origin{0.0};
    std::mutex mutex;
    std::vector<std::pair<FaceId, FaceId>> pairs;
};

bool share_point(const MeshTopology& topo, const std::array<VertexId, 3>& f, const std::array<VertexId, 3>& g) {
    for (const VertexId v : f)
        for (const VertexId w : g)
            if (topo.same_point(v, w)) return true;
    return false;
}

void face_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* c = static_cast<const CollideContext*>(args->geometryUserPtr);
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const VertexId v : c->corners[args->primID]) {
        lo = glm::min(lo, c->topo->positions()[v] - c->origin);
        hi = glm::max(hi, c->topo->positions()[v] - c->origin);
    }
    // Rounded outward to float, and a little more: boxes that touch in
    // double must overlap in float (a face lying on another's plane).
    const glm::dvec3 pad = 1e-6 * (glm::abs(lo) + glm::abs(hi)) + 1e-30;
    lo -= pad, hi += pad;
    RTCBounds& b = *args->bounds_o;
    b.lower_x = std::nextafter(float(lo.x), -INFINITY), b.lower_y = std::nextafter(float(lo.y), -INFINITY);
    b.lower_z = std::nextafter(float(lo.z), -INFINITY);
    b.upper_x = std::nextafter(float(hi.x), INFINITY), b.upper_y = std::nextafter(float(hi.y), INFINITY);
    b.upper_z = std::nextafter(float(hi.z), INFINITY);
}

void collide(void* user, RTCCollision* collisions, unsigned count) {
    auto* c = static_cast<CollideContext*>(user);
    std::vector<std::pair<FaceId, FaceId>> found;
    for (unsigned i = 0; i < count; ++i) {
        const FaceId f = c->faces[collisions[i].primID0], g = c->faces[collisions[i].primID1];
        if (!(f < g) || share_point(*c->topo, c->corners[collisions[i].primID0], c->corners[collisions[i].primID1])) continue;
        found.emplace_back(f, g);
    }
    if (found.empty()) return;
    const std::lock_guard lock(c->mutex);
    c->pairs.insert(c->pairs.end(), found.begin(), found.end());
}

/// Which side of face @p g's plane vertex @p v lies on: +1 or -1, a vertex
/// on the plane counting as in front (so a surface that only touches
/// another never crosses it).
int side(const MeshTopology& topo, VertexId v, FaceId g) {
    const auto& gv = topo.face_vertices()[g];
    const auto p = topo.positions();
    return detail::orient3d(p[gv[0]], p[gv[1]], p[gv[2]], p[v]) >= 0 ? 1 : -1;
}

/// Which side of the line through edge @p e (from its first vertex p to
/// its second q) the directed edge (a, b) of a face passes: the sign of
/// orient3d(p, q, a, b). A zero is broken as the vertex-on-plane rule of
/// side() perturbs the points: where a and b lie in the plane of a face
/// of e (a ball's equator lying in a tabletop that an edge of the top
/// crosses), they count as lifted off it along that face's normal, which
/// gives the sign of det[q - p, n, b - a]; otherwise by the vertices'
/// numbers. Either way the sign is antisymmetric in (a, b), so a segment
/// through an edge of a face goes through exactly one of the two faces
/// beside it.
int line_side(const MeshTopology& topo, EdgeId e, VertexId a, VertexId b) {
    const auto pos = topo.positions();
    const auto [p, q] = topo.edge_vertices()[e];
    const int s = detail::orient3d(pos[p], pos[q], pos[a], pos[b]);
    if (s != 0) return s;
    for (const FaceId f : topo.edge_faces()[e]) {
        if (!f.valid() || !face_has_area(topo, f)) continue;
        const auto& fv = topo.face_vertices()[f];
        if (detail::orient3d(pos[fv[0]], pos[fv[1]], pos[fv[2]], pos[a]) != 0 ||
            detail::orient3d(pos[fv[0]], pos[fv[1]], pos[fv[2]], pos[b]) != 0)
            continue;
        const glm::dvec3 n = glm::cross(pos[fv[1]] - pos[fv[0]], pos[fv[2]] - pos[fv[0]]);
        const double d = glm::dot(pos[q] - pos[p], glm::cross(n, pos[b] - pos[a]));
        if (d != 0.0) return d > 0.0 ? 1 : -1;
    }
    return (p < q ? 1 : -1) * (a < b ? 1 : -1);
}

/// Whether edge @p e, whose ends lie on both sides of face @p g's plane,
/// passes through g.
bool pierces(const MeshTopology& topo, EdgeId e, FaceId g) {
    const auto& gv = topo.face_vertices()[g];
    const int s0 = line_side(topo, e, gv[0], gv[1]);
    return line_side(topo, e, gv[1], gv[2]) == s0 && line_side(topo, e, gv[2], gv[0]) == s0;
}

/// Where edge @p e crosses face @p g's plane, as t from its first vertex.
double crossing_t(const MeshTopology& topo, EdgeId e, FaceId g) {
    const auto& gv = topo.face_vertices()[g];
    const auto p = topo.positions();
    const glm::dvec3 n = glm::cross(p[gv[1]] - p[gv[0]], p[gv[2]] - p[gv[0]]);
    const auto [a, b] = topo.edge_vertices()[e];
    const double da = glm::dot(p[a] - p[gv[0]], n), db = glm::dot(p[b] - p[gv[0]], n);
    return da != db ? std::clamp(da / (da - db), 0.0, 1.0) : 0.5;
}

using PointKey = std::pair<EdgeId, FaceId>; ///< an edge and the face it pierces

/// The points of face pair (f, g)'s segment: each edge of one that pierces
/// the other. Two for faces that cross; none for faces that do not (or
/// only touch).
std::vector<PointKey> segment_of(const MeshTopology& topo, FaceId f, FaceId g) {
    std::vector<PointKey> out;
    auto edges_through = [&](FaceId a, FaceId b) {
        const auto& av = topo.face_vertices()[a];
        std::array<int, 3> s{};
        for (int k = 0; k < 3; ++k) s[k] = side(topo, av[k], b);
        if (s[0] == s[1] && s[1] == s[2]) return false;
        for (int k = 0; k < 3; ++k) {
            if (s[k] == s[(k + 1) % 3]) continue;
            const EdgeId e = topo.face_edges()[a][k];
            if (pierces(topo, e, b)) out.emplace_back(e, b);
        }
        return true;
    };
    if (!edges_through(f, g)) return {};
    const std::size_t from_f = out.size();
    if (!edges_through(g, f)) return {};
    (void)from_f;
    return out;
}

} // namespace

namespace {

/// Pairs of the triangles @p c holds (by their faces, f < g) whose boxes
/// overlap and which share no point, by Embree's BVH collision.
std::vector<std::pair<FaceId, FaceId>> colliding(CollideContext& c) {
    if (c.faces.size() < 2) return {};
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const auto& corners : c.corners)
        for (const VertexId v : corners) lo = glm::min(lo, c.topo->positions()[v]), hi = glm::max(hi, c.topo->positions()[v]);
    c.origin = 0.5 * (lo + hi);
    RTCDevice device = detail::embree_device();
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geom, unsigned(c.faces.size()));
    rtcSetGeometryUserData(geom, &c);
    rtcSetGeometryBoundsFunction(geom, face_bounds, &c);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    rtcCommitScene(scene);
    rtcCollide(scene, scene, collide, &c);
    rtcReleaseScene(scene);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
        throw Error("the ray tracer could not compare the scene's faces (out of memory?)");
    std::sort(c.pairs.begin(), c.pairs.end());
    c.pairs.erase(std::unique(c.pairs.begin(), c.pairs.end()), c.pairs.end());
    return std::move(c.pairs);
}

/// Whether triangle @p a's corners lie on both sides of @p b's plane, a
/// corner on the plane counting as in front (as side() counts it).
bool straddles(const MeshTopology& topo, const std::array<VertexId, 3>& a, const std::array<VertexId, 3>& b) {
    const auto p = topo.positions();
    int above = 0, below = 0;
    for (const VertexId v : a) {
        const int s = detail::orient3d(p[b[0]], p[b[1]], p[b[2]], p[v]);
        above += s >= 0, below += s < 0;
    }
    return above && below;
}

bool has_area(const MeshTopology& topo, const std::array<VertexId, 3>& t) {
    const auto p = topo.positions();
    return glm::length(glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]])) > 0.0;
}

} // namespace

std::vector<std::pair<FaceId, FaceId>> overlapping_face_pairs(const MeshTopology& topo) {
    CollideContext c;
    c.topo = &topo;
    const MeshRefinement* refinement = topo.refinement().get();
    if (!refinement) {
        for (const FaceId f : topo.faces())
            if (face_has_area(topo, f)) c.faces.push_back(f), c.corners.push_back(topo.face_vertices()[f]);
        return colliding(c);
    }
    // A refined mesh: its faces lie in the faces as loaded, so the pairs of
    // those come first (a sixty-fourth of the work at three levels), then
    // the refined faces of each pair that crosses, as far as their boxes
    // tell. Faces as loaded that only touch (in one plane, or meeting at a
    // corner from in front) give none, whatever the rounding of the points
    // added inside them.
    for (const FaceId f : refinement->base_faces.ids())
        if (has_area(topo, refinement->base_faces[f])) c.faces.push_back(f), c.corners.push_back(refinement->base_faces[f]);
    const std::vector<std::pair<FaceId, FaceId>> coarse = colliding(c);
    FaceData<std::vector<FaceId>> children(refinement->base_faces.size());
    for (const FaceId f : topo.faces())
        if (face_has_area(topo, f)) children[refinement->face_origin[f]].push_back(f);
    std::vector<std::vector<std::pair<FaceId, FaceId>>> found(coarse.size());
    auto box = [&](FaceId f) {
        std::array<glm::dvec3, 2> b{glm::dvec3(std::numeric_limits<double>::infinity()), glm::dvec3(-std::numeric_limits<double>::infinity())};
        for (const VertexId v : topo.face_vertices()[f]) b[0] = glm::min(b[0], topo.positions()[v]), b[1] = glm::max(b[1], topo.positions()[v]);
        return b;
    };
    parallel_for(coarse.size(), [&](std::size_t i) {
        const auto [bf, bg] = coarse[i];
        const auto& fc = refinement->base_faces[bf];
        const auto& gc = refinement->base_faces[bg];
        if (!straddles(topo, fc, gc) || !straddles(topo, gc, fc)) return;
        for (const FaceId f : children[bf]) {
            const auto a = box(f);
            for (const FaceId g : children[bg]) {
                const auto b = box(g);
                if (glm::any(glm::lessThan(a[1], b[0])) || glm::any(glm::lessThan(b[1], a[0]))) continue;
                found[i].emplace_back(std::min(f, g), std::max(f, g));
            }
        }
    }, 16);
    std::vector<std::pair<FaceId, FaceId>> out;
    for (const auto& pairs : found) out.insert(out.end(), pairs.begin(), pairs.end());
    std::sort(out.begin(), out.end());
    return out;
}

namespace {

/// Chains the segments (pairs of point indices) into polylines: open ones
/// from their ends first, in the order of the end's index, then closed ones
/// from their least point. A point met by more than two segments (a
/// degenerate meeting the exact signs could not resolve) ends chains.
std::vector<std::pair<std::vector<std::int32_t>, bool>> chain_segments(
    std::size_t n_points, const std::vector<std::array<std::int32_t, 2>>& segments) {
    std::vector<std::array<std::int32_t, 2>> next(n_points, {-1, -1});
    std::vector<std::uint8_t> degree(n_points, 0);
    for (const auto& [a, b] : segments) {
        if (degree[a] < 2 && degree[b] < 2) {
            next[a][degree[a]++] = b;
            next[b][degree[b]++] = a;
        }
    }
    std::vector<std::uint8_t> used(n_points, 0);
    std::vector<std::pair<std::vector<std::int32_t>, bool>> out;
    auto walk = [&](std::int32_t start, bool closed) {
        std::vector<std::int32_t> chain{start};
        used[start] = 1;
        std::int32_t prev = -1, at = start;
        for (;;) {
            std::int32_t go = -1;
            for (const std::int32_t w : next[at])
                if (w >= 0 && w != prev && !used[w]) go = w;
            if (go < 0) break;
            used[go] = 1;
            chain.push_back(go);
            prev = at, at = go;
        }
        out.emplace_back(std::move(chain), closed);
    };
    for (std::size_t p = 0; p < n_points; ++p)
        if (!used[p] && degree[p] < 2) walk(std::int32_t(p), false);
    for (std::size_t p = 0; p < n_points; ++p)
        if (!used[p]) walk(std::int32_t(p), true);
    return out;
}

/// Where a degenerate meeting left a curve in pieces (a vertex of one
/// surface on an edge or a vertex of the other, which no exact sign can
/// give one answer for every face around it), the pieces' ends lie on one
/// point: open chains whose ends lie within @p tolerance of each other are
/// joined, and a chain whose two ends meet is closed; so are ends that
/// @p gap says a missing segment parts (ends of a curve that does not run
/// off a border, a few edges apart). Chains of no length are left out.
void join_coincident_ends(std::vector<std::pair<std::vector<std::int32_t>, bool>>& chains,
                          const std::vector<glm::dvec3>& at, double tolerance,
                          const std::function<bool(std::int32_t, std::int32_t)>& gap) {
    auto near = [&](std::int32_t a, std::int32_t b) { return glm::length(at[a] - at[b]) <= tolerance; };
    auto joins = [&](std::int32_t a, std::int32_t b) { return near(a, b) || gap(a, b); };
    bool joined = true;
    while (joined) {
        joined = false;
        for (std::size_t i = 0; i < chains.size() && !joined; ++i) {
            auto& [a, a_closed] = chains[i];
            if (a_closed || a.empty()) continue;
            for (std::size_t j = 0; j < chains.size() && !joined; ++j) {
                auto& [b, b_closed] = chains[j];
                if (i == j || b_closed || b.empty()) continue;
                // Orient b to continue a's end.
                if (joins(a.back(), b.back())) std::reverse(b.begin(), b.end());
                else if (joins(a.front(), b.front())) std::reverse(a.begin(), a.end());
                else if (joins(a.front(), b.back())) std::swap(a, b);
                if (!joins(a.back(), b.front())) continue;
                // The shared point once; ends of one face pair's gap both.
                a.insert(a.end(), b.begin() + (near(a.back(), b.front()) ? 1 : 0), b.end());
                b.clear();
                joined = true;
            }
        }
    }
    // A curve of no length is a touch seen through the tie-breaking (a
    // vertex of one surface lying on the other from inside it): no line.
    std::erase_if(chains, [&](const auto& c) {
        return std::all_of(c.first.begin(), c.first.end(), [&](std::int32_t p) { return near(p, c.first.front()); });
    });
    for (auto& [chain, closed] : chains)
        if (!closed && chain.size() > 2 && joins(chain.front(), chain.back())) {
            if (near(chain.front(), chain.back())) chain.pop_back();
            closed = true;
        }
}

} // namespace

IntersectionCurves find_intersections(const MeshTopology& topo) {
    const FloatModeGuard mode;
    IntersectionCurves out;
    out.fronts.edge_snaxel.assign(topo.n_edges(), kNoSnaxel);
    const std::vector<std::pair<FaceId, FaceId>> pairs = overlapping_face_pairs(topo);
    std::vector<std::vector<PointKey>> found(pairs.size());
    parallel_for(pairs.size(), [&](std::size_t i) { found[i] = segment_of(topo, pairs[i].first, pairs[i].second); }, 256);

    // A point is named by the edge's two surface points and the face: the
    // copies of an edge along a split sharp edge (one each side of its
    // strip) pierce a face at one point, which the first copy met carries.
    auto point_of = [&](VertexId v) { return topo.has_strips() ? topo.connectivity()->point_of[v] : v; };
    using GeometricKey = std::tuple<VertexId, VertexId, FaceId>;
    std::map<GeometricKey, std::int32_t> index;
    std::vector<PointKey> points;
    std::vector<std::array<std::int32_t, 2>> segments;
    auto point = [&](const PointKey& key) {
        const auto [a, b] = topo.edge_vertices()[key.first];
        const VertexId pa = point_of(a), pb = point_of(b);
        const auto [it, fresh] = index.emplace(GeometricKey{std::min(pa, pb), std::max(pa, pb), key.second}, std::int32_t(points.size()));
        if (fresh) points.push_back(key);
        return it->second;
    };
    for (std::size_t i = 0; i < pairs.size(); ++i) {
        if (found[i].size() != 2) continue; // no crossing (or an unresolved degenerate)
        out.crossing_faces.push_back(pairs[i]);
        segments.push_back({point(found[i][0]), point(found[i][1])});
    }
    std::vector<glm::dvec3> at(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        const auto [a, b] = topo.edge_vertices()[points[i].first];
        at[i] = glm::mix(topo.positions()[a], topo.positions()[b], crossing_t(topo, points[i].first, points[i].second));
    }
    auto chains = chain_segments(points.size(), segments);
    // A curve ends where it runs off a surface's border; any other end is
    // a gap a degenerate meeting left, closed with the nearest such end
    // within a few edges.
    const double reach = 4.0 * topo.mean_edge_length();
    auto gap_between = [&](std::int32_t a, std::int32_t b) {
        return !topo.is_boundary_edge(points[a].first) && !topo.is_boundary_edge(points[b].first) &&
               glm::length(at[a] - at[b]) <= reach;
    };
    join_coincident_ends(chains, at, 1e-9 * (2.0 * bounding_radius(topo)) + 1e-300, gap_between);
    for (const auto& [chain, closed] : chains) {
        if (chain.size() < 2) continue;
        std::vector<EdgeId> edges;
        std::vector<double> t;
        for (const std::int32_t p : chain) {
            const auto& [e, g] = points[p];
            edges.push_back(e);
            t.push_back(crossing_t(topo, e, g));
            out.pierced.push_back(g);
        }
        append_edge_loop(topo, edges, t, closed && chain.size() > 2, out.fronts);
    }
    return out;
}

std::shared_ptr<const IntersectionCurves> require_intersections(const MeshTopology& topology) {
    return topology.pose()->quantities.require(Quantity<IntersectionCurves>{"intersections"},
                                                                   [&] { return find_intersections(topology); });
}

} // namespace snaxels
