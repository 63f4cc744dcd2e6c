#include "snaxels/snaxel/topology.h"

#include <glm/glm.hpp>

#include "snaxels/snaxel/refine.h"

namespace snaxels {

MeshTopology build_topology(const Mesh& mesh) {
    MeshTopology t;
    const auto nv = mesh.n_vertices(), ne = mesh.n_edges(), nf = mesh.n_faces();
    t.positions.resize(nv);
    t.normals.resize(nv);
    for (const auto vh : mesh.vertices()) {
        t.positions[vh.idx()] = to_glm(mesh.point(vh));
        t.normals[vh.idx()] = to_glm(mesh.normal(vh));
    }
    t.edge_vertices.resize(ne);
    t.edge_faces.resize(ne);
    double total = 0.0;
    for (const auto eh : mesh.edges()) {
        const auto h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
        const int a = mesh.from_vertex_handle(h0).idx(), b = mesh.to_vertex_handle(h0).idx();
        t.edge_vertices[eh.idx()] = {a, b};
        t.edge_faces[eh.idx()] = {mesh.face_handle(h0).idx(), mesh.face_handle(h1).idx()};
        total += glm::length(t.positions[a] - t.positions[b]);
    }
    t.mean_edge_length = ne ? total / double(ne) : 0.0;
    t.face_vertices.resize(nf);
    t.face_edges.resize(nf);
    for (const auto fh : mesh.faces()) {
        auto h = mesh.halfedge_handle(fh);
        for (int k = 0; k < 3; ++k) {
            t.face_vertices[fh.idx()][k] = mesh.from_vertex_handle(h).idx();
            t.face_edges[fh.idx()][k] = mesh.edge_handle(h).idx();
            h = mesh.next_halfedge_handle(h);
        }
    }
    t.ring_start.assign(nv + 1, 0);
    t.ring.reserve(2 * ne);
    t.ring_edge.reserve(2 * ne);
    for (const auto vh : mesh.vertices()) {
        t.ring_start[vh.idx()] = static_cast<std::int32_t>(t.ring.size());
        for (const auto heh : mesh.voh_range(vh)) {
            t.ring.push_back(mesh.to_vertex_handle(heh).idx());
            t.ring_edge.push_back(mesh.edge_handle(heh).idx());
        }
    }
    t.ring_start[nv] = static_cast<std::int32_t>(t.ring.size());
    return t;
}

} // namespace snaxels

namespace snaxels {

std::size_t MeshTopology::n_base_vertices() const { return refinement ? refinement->base_vertices : n_vertices(); }

void recompute_normals(MeshTopology& t) {
    if (t.refinement) {
        const MeshRefinement& r = *t.refinement;
        const std::size_t base = r.base_vertices;
        std::fill(t.normals.begin(), t.normals.begin() + std::ptrdiff_t(base), glm::dvec3(0.0));
        for (const auto& f : r.base_faces) {
            const glm::dvec3 a = t.positions[std::size_t(f[0])];
            const glm::dvec3 n = glm::cross(t.positions[std::size_t(f[1])] - a, t.positions[std::size_t(f[2])] - a);
            for (const auto v : f) t.normals[std::size_t(v)] += n;
        }
        for (std::size_t v = 0; v < base; ++v) {
            const double len = glm::length(t.normals[v]);
            t.normals[v] = len > 0.0 ? t.normals[v] / len : glm::dvec3(0.0, 0.0, 1.0);
        }
        for (std::size_t i = 0; i < r.from.size(); ++i) {
            const auto& from = r.from[i];
            const glm::dvec3& w = r.weights[i];
            t.positions[base + i] = w.x * t.positions[std::size_t(from[0])] + w.y * t.positions[std::size_t(from[1])] +
                                    w.z * t.positions[std::size_t(from[2])];
            const glm::dvec3 n = w.x * t.normals[std::size_t(from[0])] + w.y * t.normals[std::size_t(from[1])] +
                                 w.z * t.normals[std::size_t(from[2])];
            const double len = glm::length(n);
            t.normals[base + i] = len > 0.0 ? n / len : t.normals[std::size_t(from[0])];
        }
        return;
    }
    std::fill(t.normals.begin(), t.normals.end(), glm::dvec3(0.0));
    for (const auto& f : t.face_vertices) {
        const glm::dvec3 a = t.positions[f[0]];
        const glm::dvec3 n = glm::cross(t.positions[f[1]] - a, t.positions[f[2]] - a);
        for (const auto v : f) t.normals[v] += n;
    }
    for (auto& n : t.normals) {
        const double len = glm::length(n);
        n = len > 0.0 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
    }
}

} // namespace snaxels
