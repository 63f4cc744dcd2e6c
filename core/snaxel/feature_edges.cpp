#include "snaxels/snaxel/feature_edges.h"

#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

namespace snaxels {

namespace {

/// The unit normal of face @p f's plane, or zero for a face of no area.
glm::dvec3 face_normal(const MeshTopology& topo, std::int32_t f) {
    const auto& fv = topo.face_vertices()[std::size_t(f)];
    const auto P = topo.positions();
    const glm::dvec3 a = P[std::size_t(fv[0])];
    const glm::dvec3 n = glm::cross(P[std::size_t(fv[1])] - a, P[std::size_t(fv[2])] - a);
    const double len = glm::length(n);
    return len > 0.0 ? n / len : glm::dvec3(0.0);
}

} // namespace

std::vector<std::int32_t> crease_edges(const MeshTopology& topo, double degrees) {
    const double limit = std::cos(glm::radians(std::clamp(degrees, 0.0, 180.0)));
    std::vector<std::int32_t> out;
    for (std::int32_t e = 0; e < std::int32_t(topo.n_edges()); ++e) {
        if (topo.is_boundary_edge(e)) continue;
        const auto& faces = topo.edge_faces()[std::size_t(e)];
        const glm::dvec3 a = face_normal(topo, faces[0]), b = face_normal(topo, faces[1]);
        if (glm::dot(a, a) == 0.0 || glm::dot(b, b) == 0.0) continue;
        if (glm::dot(a, b) < limit) out.push_back(e);
    }
    return out;
}

std::vector<std::int32_t> border_edges(const MeshTopology& topo) {
    std::vector<std::int32_t> out;
    for (std::int32_t e = 0; e < std::int32_t(topo.n_edges()); ++e)
        if (topo.is_boundary_edge(e)) out.push_back(e);
    return out;
}

std::vector<EdgeChain> chain_edges(const MeshTopology& topo, const std::vector<std::int32_t>& edges) {
    std::vector<std::uint8_t> chosen(topo.n_edges(), 0), used(topo.n_edges(), 0);
    for (const std::int32_t e : edges) chosen[std::size_t(e)] = 1;
    std::vector<std::int32_t> degree(topo.n_vertices(), 0);
    for (std::size_t e = 0; e < chosen.size(); ++e)
        if (chosen[e])
            for (const std::int32_t v : topo.edge_vertices()[e]) ++degree[std::size_t(v)];
    // The next chosen, unused edge at v.
    auto next_edge = [&](std::int32_t v) {
        for (const std::int32_t e : topo.vertex_edges(v))
            if (chosen[std::size_t(e)] && !used[std::size_t(e)]) return e;
        return MeshTopology::kNone;
    };
    // The other chosen edge at a vertex where two meet.
    auto other_edge = [&](std::int32_t v, std::int32_t e) {
        for (const std::int32_t c : topo.vertex_edges(v))
            if (c != e && chosen[std::size_t(c)]) return c;
        return e;
    };
    std::vector<std::int32_t> order = edges;
    std::sort(order.begin(), order.end());
    order.erase(std::unique(order.begin(), order.end()), order.end());
    std::vector<EdgeChain> chains;
    for (const std::int32_t first : order) {
        if (used[std::size_t(first)]) continue;
        // Back from the edge to where its chain ends (or, round a loop, to the edge again).
        std::int32_t v = topo.edge_vertices()[std::size_t(first)][0], e = first;
        while (degree[std::size_t(v)] == 2) {
            const std::int32_t other = other_edge(v, e);
            if (other == first) break;
            e = other;
            v = topo.opposite(other, v);
        }
        // Then forward along it, through every vertex where two meet.
        EdgeChain chain;
        chain.vertices.push_back(v);
        while (e != MeshTopology::kNone) {
            used[std::size_t(e)] = 1;
            chain.edges.push_back(e);
            v = topo.opposite(e, v);
            chain.vertices.push_back(v);
            e = degree[std::size_t(v)] == 2 ? next_edge(v) : MeshTopology::kNone;
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
        for (std::size_t i = 0; i + 1 < c.vertices.size(); ++i)
            sum += glm::length(P[std::size_t(c.vertices[i + 1])] - P[std::size_t(c.vertices[i])]);
        return sum < length;
    });
    return chains;
}

Fronts chain_fronts(const MeshTopology& topo, const std::vector<EdgeChain>& chains) {
    Fronts fronts;
    fronts.edge_snaxel.assign(topo.n_edges(), MeshTopology::kNone);
    for (const EdgeChain& chain : chains) {
        if (chain.edges.empty()) continue;
        const std::int32_t loop = std::int32_t(fronts.loops.size()), first = std::int32_t(fronts.snaxels.size());
        // A closed chain's last vertex is its first: one snaxel for both.
        const std::int32_t n = std::int32_t(chain.closed ? chain.edges.size() : chain.vertices.size());
        for (std::int32_t k = 0; k < n; ++k) {
            Snaxel s;
            // The edge leaving the vertex along the chain; at an open chain's end, the edge arriving.
            s.edge = chain.edges[std::size_t(std::min<std::int32_t>(k, std::int32_t(chain.edges.size()) - 1))];
            const auto& ends = topo.edge_vertices()[std::size_t(s.edge)];
            s.inside = ends[0];
            s.outside = ends[1];
            s.t = chain.vertices[std::size_t(k)] == ends[0] ? 0.0 : 1.0;
            s.loop = loop;
            s.prev = k > 0 ? first + k - 1 : chain.closed ? first + n - 1 : MeshTopology::kNone;
            s.next = k + 1 < n ? first + k + 1 : chain.closed ? first : MeshTopology::kNone;
            if (fronts.edge_snaxel[std::size_t(s.edge)] == MeshTopology::kNone)
                fronts.edge_snaxel[std::size_t(s.edge)] = first + k;
            fronts.snaxels.push_back(s);
        }
        fronts.loops.push_back({first, n, chain.closed});
    }
    return fronts;
}

Fronts feature_fronts(const MeshTopology& topo, const ContourSpec& spec) {
    const std::vector<std::int32_t> edges =
        spec.kind == ContourKind::Crease ? crease_edges(topo, spec.k) : border_edges(topo);
    const double min_length = spec.min_length > 0.0 ? spec.min_length * 2.0 * bounding_radius(topo) : 0.0;
    return chain_fronts(topo, chains_at_least(topo, chain_edges(topo, edges), min_length));
}

} // namespace snaxels
