#include "snaxels/snaxel/feature_edges.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/glm.hpp>

namespace snaxels {

namespace {

/// The unit normal of face @p f's plane, or zero for a face of no area.
glm::dvec3 face_normal(const MeshTopology& topo, FaceId f) {
    const auto& fv = topo.face_vertices()[f];
    const auto P = topo.positions();
    const glm::dvec3 a = P[fv[0]];
    const glm::dvec3 n = glm::cross(P[fv[1]] - a, P[fv[2]] - a);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

/// Where edge @p e lies along a split sharp edge (one of its faces has an
/// area, the other is the strip's): the face with an area on the strip's
/// far side, along the same line, or kNone. Found by walking the strip's
/// zero-area faces (a few; more where refinement divided them).
FaceId face_across_strip(const MeshTopology& topo, EdgeId e, FaceId near, FaceId strip) {
    const auto P = topo.positions();
    const glm::dvec3 a = P[topo.edge_vertices()[e][0]], b = P[topo.edge_vertices()[e][1]];
    const double tol = 1e-9 * glm::length(b - a);
    auto coincides = [&](EdgeId c) {
        const glm::dvec3 p = P[topo.edge_vertices()[c][0]], q = P[topo.edge_vertices()[c][1]];
        return (glm::length(p - a) <= tol && glm::length(q - b) <= tol) ||
               (glm::length(p - b) <= tol && glm::length(q - a) <= tol);
    };
    constexpr std::size_t kMostFaces = 256;
    std::vector<FaceId> walk{strip};
    for (std::size_t i = 0; i < walk.size() && walk.size() < kMostFaces; ++i)
        for (const EdgeId c : topo.face_edges()[walk[i]])
            for (const FaceId g : topo.edge_faces()[c]) {
                if (g == MeshTopology::kNone || g == near || std::find(walk.begin(), walk.end(), g) != walk.end()) continue;
                if (!face_has_area(topo, g)) walk.push_back(g);
                else if (c != e && coincides(c)) return g;
            }
    return MeshTopology::kNone;
}

/// The two faces with an area that meet at edge @p e: its own, or where it
/// is one side of a split sharp edge, the face beside it and the one across
/// the strip (only the side whose face comes first has them, so the edge is
/// taken once). False for a border, an edge inside a strip, or the second
/// side of a split edge.
bool faces_meeting(const MeshTopology& topo, EdgeId e, std::array<FaceId, 2>& faces) {
    if (topo.is_boundary_edge(e)) return false;
    faces = topo.edge_faces()[e];
    const bool strips = topo.has_strips();
    const bool has_area[2] = {!strips || face_has_area(topo, faces[0]), !strips || face_has_area(topo, faces[1])};
    if (has_area[0] != has_area[1]) {
        // One side of a split sharp edge: its faces meet across the strip.
        // Both sides find each other; the side whose face comes first has them.
        const FaceId near = has_area[0] ? faces[0] : faces[1];
        const FaceId across = face_across_strip(topo, e, near, has_area[0] ? faces[1] : faces[0]);
        if (across == MeshTopology::kNone || across < near) return false;
        faces = {near, across};
        return true;
    }
    return has_area[0]; // both without an area: inside a strip
}

/// The edges whose meeting faces (faces_meeting) pass @p differ, ascending.
template <class Differ> std::vector<EdgeId> edges_between(const MeshTopology& topo, Differ&& differ) {
    std::vector<EdgeId> out;
    std::array<FaceId, 2> faces;
    for (const EdgeId e : topo.edges())
        if (faces_meeting(topo, e, faces) && differ(faces[0], faces[1])) out.push_back(e);
    return out;
}

} // namespace

std::array<FaceId, 2> faces_beside(const MeshTopology& topo, EdgeId e) {
    std::array<FaceId, 2> faces = topo.edge_faces()[e];
    if (!topo.has_strips() || topo.is_boundary_edge(e)) return faces;
    const bool has_area[2] = {face_has_area(topo, faces[0]), face_has_area(topo, faces[1])};
    if (has_area[0] == has_area[1]) return faces;
    const FaceId near = has_area[0] ? faces[0] : faces[1];
    const FaceId across = face_across_strip(topo, e, near, has_area[0] ? faces[1] : faces[0]);
    return across == MeshTopology::kNone ? faces : std::array<FaceId, 2>{near, across};
}

std::vector<EdgeId> crease_edges(const MeshTopology& topo, double degrees) {
    const double limit = std::cos(glm::radians(std::clamp(degrees, 0.0, 180.0)));
    return edges_between(topo, [&](FaceId f, FaceId g) {
        const glm::dvec3 a = face_normal(topo, f), b = face_normal(topo, g);
        return glm::dot(a, a) != 0.0 && glm::dot(b, b) != 0.0 && glm::dot(a, b) < limit;
    });
}

std::vector<EdgeId> material_edges(const MeshTopology& topo) {
    const FaceParts* parts = topo.parts();
    if (!parts) return {};
    return edges_between(topo, [&](FaceId f, FaceId g) { return parts->material[f] != parts->material[g]; });
}

std::vector<EdgeId> object_edges(const MeshTopology& topo) {
    const FaceParts* parts = topo.parts();
    if (!parts) return {};
    return edges_between(topo, [&](FaceId f, FaceId g) { return parts->object[f] != parts->object[g]; });
}

std::vector<EdgeId> border_edges(const MeshTopology& topo) {
    std::vector<EdgeId> out;
    for (const EdgeId e : topo.edges())
        if (topo.is_boundary_edge(e)) out.push_back(e);
    return out;
}

std::vector<EdgeChain> chain_edges(const MeshTopology& topo, const std::vector<EdgeId>& edges) {
    EdgeData<std::uint8_t> chosen(topo.n_edges(), 0), used(topo.n_edges(), 0);
    for (const EdgeId e : edges) chosen[e] = 1;
    std::vector<EdgeId> order = edges;
    std::sort(order.begin(), order.end());
    order.erase(std::unique(order.begin(), order.end()), order.end());
    VertexData<std::int32_t> degree(topo.n_vertices(), 0);
    for (const EdgeId e : order)
        for (const VertexId v : topo.edge_vertices()[e]) ++degree[v];
    // The next chosen, unused edge at v.
    auto next_edge = [&](VertexId v) -> EdgeId {
        for (const EdgeId e : topo.vertex_edges(v))
            if (chosen[e] && !used[e]) return e;
        return MeshTopology::kNone;
    };
    // The other chosen edge at a vertex where two meet.
    auto other_edge = [&](VertexId v, EdgeId e) {
        for (const EdgeId c : topo.vertex_edges(v))
            if (c != e && chosen[c]) return c;
        return e;
    };
    std::vector<EdgeChain> chains;
    for (const EdgeId first : order) {
        if (used[first]) continue;
        // Back from the edge to where its chain ends (or, round a loop, to the edge again).
        VertexId v = topo.edge_vertices()[first][0];
        EdgeId e = first;
        while (degree[v] == 2) {
            const EdgeId other = other_edge(v, e);
            if (other == first) break;
            e = other;
            v = topo.opposite(other, v);
        }
        // Then forward along it, through every vertex where two meet.
        EdgeChain chain;
        chain.vertices.push_back(v);
        while (e != MeshTopology::kNone) {
            used[e] = 1;
            chain.edges.push_back(e);
            v = topo.opposite(e, v);
            chain.vertices.push_back(v);
            e = degree[v] == 2 ? next_edge(v) : EdgeId();
        }
        chain.closed = chain.edges.size() > 2 && chain.vertices.front() == chain.vertices.back();
        if (!chain.closed && chain.vertices.back() < chain.vertices.front()) {
            std::reverse(chain.vertices.begin(), chain.vertices.end());
            std::reverse(chain.edges.begin(), chain.edges.end());
        }
        chains.push_back(std::move(chain));
    }
    return chains;
}

std::vector<EdgeChain> chains_at_least(const MeshTopology& topo, std::vector<EdgeChain> chains, double length) {
    if (length <= 0.0) return chains;
    const auto P = topo.positions();
    std::erase_if(chains, [&](const EdgeChain& c) {
        double sum = 0.0;
        for (std::size_t i = 0; i + 1 < c.vertices.size(); ++i) sum += glm::length(P[c.vertices[i + 1]] - P[c.vertices[i]]);
        return sum < length;
    });
    return chains;
}

Fronts chain_fronts(const MeshTopology& topo, const std::vector<EdgeChain>& chains) {
    Fronts fronts;
    fronts.edge_snaxel.assign(topo.n_edges(), kNoSnaxel);
    std::vector<EdgeId> edges;
    std::vector<double> t;
    for (const EdgeChain& chain : chains) {
        if (chain.edges.empty()) continue;
        // A snaxel at each vertex of the chain (a closed chain's last vertex
        // is its first: one snaxel for both), on the edge leaving it along
        // the chain; at an open chain's end, on the edge arriving.
        const std::size_t n = chain.closed ? chain.edges.size() : chain.vertices.size();
        edges.clear();
        t.clear();
        for (std::size_t k = 0; k < n; ++k) {
            edges.push_back(chain.edges[std::min(k, chain.edges.size() - 1)]);
            t.push_back(chain.vertices[k] == topo.edge_vertices()[edges.back()][0] ? 0.0 : 1.0);
        }
        append_edge_loop(topo, edges, t, chain.closed, fronts);
    }
    return fronts;
}

Fronts feature_fronts(const MeshTopology& topo, const ContourSpec& spec) {
    const auto lines = contour_kind_info(spec.kind).edges;
    const std::vector<EdgeId> edges = lines ? lines(topo, spec) : border_edges(topo);
    const double min_length = spec.min_length > 0.0 ? spec.min_length * 2.0 * bounding_radius(topo) : 0.0;
    return chain_fronts(topo, chains_at_least(topo, chain_edges(topo, edges), min_length));
}

} // namespace snaxels
