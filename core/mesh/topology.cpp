#include "snaxels/mesh/topology.h"

#include <limits>
#include <string>

#include <glm/glm.hpp>

#include "snaxels/error.h"
#include "snaxels/mesh/refine.h"

namespace snaxels {

MeshTopology::MeshTopology()
    : MeshTopology(std::make_shared<const MeshConnectivity>(), std::make_shared<const MeshPose>()) {}

MeshTopology::MeshTopology(std::shared_ptr<const MeshConnectivity> connectivity, std::shared_ptr<const MeshPose> pose)
    : connectivity_(std::move(connectivity)), pose_(std::move(pose)) {
    if (!connectivity_ || !pose_) throw InternalError("MeshTopology: no connectivity or no pose");
    if (pose_->positions.size() != connectivity_->n_vertices() || pose_->normals.size() != pose_->positions.size())
        throw InternalError("MeshTopology: a pose of " + std::to_string(pose_->positions.size()) +
                                    " vertices for a connectivity of " + std::to_string(connectivity_->n_vertices()));
    const MeshConnectivity& c = *connectivity_;
    positions_ = pose_->positions;
    normals_ = pose_->normals;
    edge_vertices_ = c.edge_vertices;
    edge_faces_ = c.edge_faces;
    face_vertices_ = c.face_vertices;
    face_edges_ = c.face_edges;
    ring_start_ = c.ring_start;
    ring_ = c.ring;
    ring_edge_ = c.ring_edge;
}

MeshTopology MeshTopology::posed(std::shared_ptr<const MeshPose> pose) const {
    MeshTopology out(connectivity_, std::move(pose));
    pose_->quantities.carry_to(out.pose_->quantities);
    return out;
}

MeshTopology build_topology(const Mesh& mesh, std::shared_ptr<const MeshRefinement> refinement) {
    auto c = std::make_shared<MeshConnectivity>();
    c->refinement = std::move(refinement);
    auto pose = std::make_shared<MeshPose>();
    MeshConnectivity& t = *c;
    const auto nv = mesh.n_vertices(), ne = mesh.n_edges(), nf = mesh.n_faces();
    pose->positions.resize(nv);
    pose->normals.resize(nv);
    for (const auto vh : mesh.vertices()) {
        pose->positions[vh.idx()] = to_glm(mesh.point(vh));
        pose->normals[vh.idx()] = to_glm(mesh.normal(vh));
    }
    t.edge_vertices.resize(ne);
    t.edge_faces.resize(ne);
    double total = 0.0;
    for (const auto eh : mesh.edges()) {
        const auto h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
        const int a = mesh.from_vertex_handle(h0).idx(), b = mesh.to_vertex_handle(h0).idx();
        t.edge_vertices[eh.idx()] = {a, b};
        t.edge_faces[eh.idx()] = {mesh.face_handle(h0).idx(), mesh.face_handle(h1).idx()};
        total += glm::length(pose->positions[a] - pose->positions[b]);
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
    return MeshTopology(std::move(c), std::move(pose));
}

double bounding_radius(const MeshTopology& topo) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::dvec3& p : topo.positions()) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return topo.positions().empty() ? 0.0 : 0.5 * glm::length(hi - lo);
}

std::size_t MeshConnectivity::n_base_vertices() const { return refinement ? refinement->base_vertices : n_vertices(); }

MeshPose make_pose(const MeshConnectivity& c, std::vector<glm::dvec3> positions) {
    MeshPose t;
    if (positions.size() < c.n_base_vertices())
        throw InternalError("make_pose: " + std::to_string(positions.size()) + " positions for " +
                                    std::to_string(c.n_base_vertices()) + " vertices");
    t.positions = std::move(positions);
    t.positions.resize(c.n_vertices());
    t.normals.assign(c.n_vertices(), glm::dvec3(0.0));
    if (c.refinement) {
        const MeshRefinement& r = *c.refinement;
        const std::size_t base = r.base_vertices;
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
        return t;
    }
    for (const auto& f : c.face_vertices) {
        const glm::dvec3 a = t.positions[std::size_t(f[0])];
        const glm::dvec3 n = glm::cross(t.positions[std::size_t(f[1])] - a, t.positions[std::size_t(f[2])] - a);
        for (const auto v : f) t.normals[std::size_t(v)] += n;
    }
    for (auto& n : t.normals) {
        const double len = glm::length(n);
        n = len > 0.0 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
    }
    return t;
}

} // namespace snaxels
