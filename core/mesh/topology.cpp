#include "snaxels/mesh/topology.h"

#include <algorithm>
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

MeshTopology build_topology(const Mesh& mesh, std::shared_ptr<const MeshRefinement> refinement,
                            std::shared_ptr<const FaceParts> parts) {
    auto c = std::make_shared<MeshConnectivity>();
    c->refinement = std::move(refinement);
    c->parts = std::move(parts);
    auto pose = std::make_shared<MeshPose>();
    MeshConnectivity& t = *c;
    const auto nv = mesh.n_vertices(), ne = mesh.n_edges(), nf = mesh.n_faces();
    pose->positions.resize(nv);
    pose->normals.resize(nv);
    for (const auto vh : mesh.vertices()) {
        pose->positions[VertexId(vh.idx())] = to_glm(mesh.point(vh));
        pose->normals[VertexId(vh.idx())] = to_glm(mesh.normal(vh));
    }
    t.edge_vertices.resize(ne);
    t.edge_faces.resize(ne);
    double total = 0.0;
    std::size_t counted = 0;
    for (const auto eh : mesh.edges()) {
        const auto h0 = mesh.halfedge_handle(eh, 0), h1 = mesh.halfedge_handle(eh, 1);
        const VertexId a(mesh.from_vertex_handle(h0).idx()), b(mesh.to_vertex_handle(h0).idx());
        const EdgeId e(eh.idx());
        t.edge_vertices[e] = {a, b};
        t.edge_faces[e] = {FaceId(mesh.face_handle(h0).idx()), FaceId(mesh.face_handle(h1).idx())};
        // The zero-length edges of a split sharp edge (core/mesh/sharp_edges.h)
        // are no measure of the mesh's scale.
        const double length = glm::length(pose->positions[a] - pose->positions[b]);
        total += length;
        counted += length > 0.0;
    }
    t.mean_edge_length = counted ? total / double(counted) : 0.0;
    t.face_vertices.resize(nf);
    t.face_edges.resize(nf);
    for (const auto fh : mesh.faces()) {
        auto h = mesh.halfedge_handle(fh);
        for (int k = 0; k < 3; ++k) {
            t.face_vertices[FaceId(fh.idx())][k] = VertexId(mesh.from_vertex_handle(h).idx());
            t.face_edges[FaceId(fh.idx())][k] = EdgeId(mesh.edge_handle(h).idx());
            h = mesh.next_halfedge_handle(h);
        }
    }
    t.ring_start.assign(nv + 1, 0);
    t.ring.reserve(2 * ne);
    t.ring_edge.reserve(2 * ne);
    for (const auto vh : mesh.vertices()) {
        t.ring_start[vh.idx()] = static_cast<std::int32_t>(t.ring.size());
        for (const auto heh : mesh.voh_range(vh)) {
            t.ring.push_back(VertexId(mesh.to_vertex_handle(heh).idx()));
            t.ring_edge.push_back(EdgeId(mesh.edge_handle(heh).idx()));
        }
    }
    t.ring_start[nv] = static_cast<std::int32_t>(t.ring.size());
    MeshTopology out(c, std::move(pose));
    const auto faces = out.faces();
    t.has_strips = std::any_of(faces.begin(), faces.end(), [&](FaceId f) { return !face_has_area(out, f); });
    if (t.has_strips) {
        // Copies are joined by edges of zero length: each takes the lowest
        // vertex it reaches over them.
        t.point_of.resize(nv);
        for (const VertexId v : out.vertices()) t.point_of[v] = v;
        auto root = [&](VertexId v) {
            while (t.point_of[v] != v) v = t.point_of[v] = t.point_of[t.point_of[v]];
            return v;
        };
        for (const EdgeId e : out.edges()) {
            const auto [a, b] = t.edge_vertices[e];
            if (out.positions()[a] != out.positions()[b]) continue;
            const VertexId ra = root(a), rb = root(b);
            if (ra < rb) t.point_of[rb] = ra;
            else if (rb < ra) t.point_of[ra] = rb;
        }
        for (const VertexId v : out.vertices()) t.point_of[v] = root(v);
    }
    return out;
}

bool face_has_area(const MeshTopology& topo, FaceId f) {
    const auto& fv = topo.face_vertices()[f];
    const auto P = topo.positions();
    const glm::dvec3 e0 = P[fv[1]] - P[fv[0]], e1 = P[fv[2]] - P[fv[0]], e2 = P[fv[2]] - P[fv[1]];
    const double longest = std::max({glm::dot(e0, e0), glm::dot(e1, e1), glm::dot(e2, e2)});
    // Relative, as import's test for degenerate faces: refined points of a
    // strip lie on its line up to rounding.
    return glm::length(glm::cross(e0, e1)) > 1e-12 * longest;
}

bool edge_in_strip(const MeshTopology& topo, EdgeId e) {
    for (const FaceId f : topo.edge_faces()[e])
        if (f != MeshTopology::kNone && face_has_area(topo, f)) return false;
    return true;
}

double bounding_radius(const MeshTopology& topo) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const glm::dvec3& p : topo.positions()) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return topo.positions().empty() ? 0.0 : 0.5 * glm::length(hi - lo);
}

std::size_t MeshConnectivity::n_base_vertices() const { return refinement ? refinement->base_vertices : n_vertices(); }

namespace {

/// Sums each face's area vector into its corners' normals and makes them unit.
void face_normals_into(VertexData<glm::dvec3>& normals, const VertexData<glm::dvec3>& positions,
                       const std::vector<std::array<VertexId, 3>>& faces, std::size_t count) {
    for (const auto& f : faces) {
        const glm::dvec3 a = positions[f[0]];
        const glm::dvec3 n = glm::cross(positions[f[1]] - a, positions[f[2]] - a);
        for (const VertexId v : f) normals[v] += n;
    }
    for (VertexId v(0); v.index() < std::int32_t(count); ++v) {
        const double len = glm::length(normals[v]);
        normals[v] = len > 0.0 ? normals[v] / len : glm::dvec3(0.0, 0.0, 1.0);
    }
}

} // namespace

MeshPose make_pose(const MeshConnectivity& c, std::vector<glm::dvec3> positions) {
    MeshPose t;
    if (positions.size() < c.n_base_vertices())
        throw InternalError("make_pose: " + std::to_string(positions.size()) + " positions for " +
                                    std::to_string(c.n_base_vertices()) + " vertices");
    positions.resize(c.n_vertices());
    t.positions = VertexData<glm::dvec3>(std::move(positions));
    t.normals.assign(c.n_vertices(), glm::dvec3(0.0));
    if (!c.refinement) {
        face_normals_into(t.normals, t.positions, c.face_vertices.values(), c.n_vertices());
        return t;
    }
    const MeshRefinement& r = *c.refinement;
    face_normals_into(t.normals, t.positions, r.base_faces.values(), r.base_vertices);
    VertexId added(r.base_vertices);
    for (std::size_t i = 0; i < r.from.size(); ++i, ++added) {
        const auto& from = r.from[i];
        const glm::dvec3& w = r.weights[i];
        t.positions[added] = w.x * t.positions[from[0]] + w.y * t.positions[from[1]] + w.z * t.positions[from[2]];
        const glm::dvec3 n = w.x * t.normals[from[0]] + w.y * t.normals[from[1]] + w.z * t.normals[from[2]];
        const double len = glm::length(n);
        t.normals[added] = len > 0.0 ? n / len : t.normals[from[0]];
    }
    return t;
}

} // namespace snaxels
