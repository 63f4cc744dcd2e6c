#include "snaxels/snaxel/suggestive.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/util/detail/parallel.h"

namespace snaxels {

namespace {

/// The normal curvature of vertex @p v along @p view (toward the viewer)
/// projected onto its tangent plane: kappa_r.
/// (The principal directions lie in the tangent plane, so the view's part
/// along the normal adds nothing to its components along them: no
/// projection is needed.)
double radial_at(const CurvatureField& field, VertexId v, const glm::dvec3& view) {
    return field.normal_curvature(v, view);
}

/// Camera::to_viewer with the orthographic camera's one direction found once.
struct ToViewer {
    explicit ToViewer(const Camera& camera)
        : camera_(camera), ortho_(camera.orthographic()), v_(ortho_ ? camera.to_viewer(glm::dvec3(0.0)) : glm::dvec3(0.0)) {}
    glm::dvec3 operator()(const glm::dvec3& p) const { return ortho_ ? v_ : camera_.to_viewer(p); }

  private:
    const Camera& camera_;
    bool ortho_;
    glm::dvec3 v_;
};

/// The gradients over face @p face of its corners' barycentric coordinates,
/// (n x opposite edge) / |n|^2, and the face's area through @p area (all 0
/// for a face of no area). A linear interpolant's gradient is the sum of
/// each corner's value times its vector.
std::array<glm::dvec3, 3> corner_gradients(const MeshTopology& topo, FaceId face, double& area) {
    const auto& fv = topo.face_vertices()[face];
    const auto P = topo.positions();
    const glm::dvec3 a = P[fv[0]], b = P[fv[1]], c = P[fv[2]];
    const glm::dvec3 normal = glm::cross(b - a, c - a);
    const double twice_area2 = glm::dot(normal, normal);
    area = 0.5 * std::sqrt(twice_area2);
    if (!(twice_area2 > 0.0)) return {glm::dvec3(0.0), glm::dvec3(0.0), glm::dvec3(0.0)};
    return {glm::cross(normal, c - b) / twice_area2, glm::cross(normal, a - c) / twice_area2,
            glm::cross(normal, b - a) / twice_area2};
}

} // namespace

double require_feature_size(const MeshTopology& topo) {
    return *topo.pose()->quantities.require(Quantity<double>{"feature size"}, [&] {
        std::vector<double> lengths;
        lengths.reserve(topo.n_edges());
        const auto P = topo.positions();
        // The edges of faces with an area: a split sharp edge's strip is no
        // part of the surface (its rungs have no length, its diagonals
        // repeat the sharp edge's), as rtsc reads a file split there.
        for (const EdgeId e : topo.edges()) {
            if (topo.has_strips() && edge_in_strip(topo, e)) continue;
            const auto [a, b] = topo.edge_vertices()[e];
            const double l = glm::length(P[b] - P[a]);
            if (l > 0.0) lengths.push_back(l);
        }
        if (lengths.empty()) return 0.0;
        const auto middle = lengths.begin() + std::ptrdiff_t(lengths.size() / 2);
        std::nth_element(lengths.begin(), middle, lengths.end());
        return *middle;
    });
}

VertexData<double> radial_curvature(const MeshTopology& topo, const CurvatureField& field, const Camera& camera) {
    VertexData<double> out(topo.n_vertices(), 0.0);
    const auto P = topo.positions();
    const ToViewer to_viewer(camera);
    parallel_for(topo.vertices(), [&](VertexId v) { out[v] = radial_at(field, v, to_viewer(P[v])); }, 4096);
    return out;
}

double suggestive_away_value(const CurvatureField& field) { return field.typical > 0.0 ? field.typical : 1.0; }

void suggestive_function(const MeshTopology& topo, const CurvatureField& field, const Camera& camera,
                         VertexData<double>& out) {
    out.resize(topo.n_vertices());
    const double away = suggestive_away_value(field);
    const auto P = topo.positions();
    const auto N = topo.normals();
    const ToViewer to_viewer(camera);
    VertexData<std::uint8_t> facing(topo.n_vertices());
    parallel_for(topo.vertices(), [&](VertexId v) { facing[v] = glm::dot(to_viewer(P[v]), N[v]) > 0.0; }, 4096);
    parallel_for(topo.vertices(), [&](VertexId v) {
        // kappa_r sin^2(theta) on the side seen and one ring past it (the
        // last ring of faces before the contour, where a suggestive contour
        // meets the silhouette it continues); the stand-in beyond.
        bool near = facing[v];
        for (const VertexId w : topo.neighbours(v)) near = near || facing[w];
        out[v] = near ? field.form(v, to_viewer(P[v])) : away;
    }, 4096);
}

namespace {

/// The derivative along the unit view direction projected onto vertex @p v's
/// tangent plane of the vertex values @p f (f(j) the value of vertex j),
/// from the pose's gradient operator (CurvatureField::gradient_*: the
/// area-weighted mean of the gradients of the faces around v, smoother than
/// one face's).
template <class Values>
double vertex_derivative_along_view(const MeshTopology& topo, const CurvatureField& field, Values&& f, VertexId v,
                                    const ToViewer& to_viewer) {
    glm::dvec3 gradient(0.0);
    for (std::int32_t k = field.gradient_start[v.index()]; k < field.gradient_start[v.index() + 1]; ++k)
        gradient += f(field.gradient_vertex[k]) * field.gradient_weight[k];
    const glm::dvec3 n = topo.normals()[v];
    const glm::dvec3 view = to_viewer(topo.positions()[v]);
    const glm::dvec3 w = view - glm::dot(view, n) * n;
    const double len = glm::length(w);
    return len > 0.0 ? glm::dot(gradient, w) / len : 0.0;
}

/// "No slot yet" in suggestive_margins' vertex slots.
constexpr std::size_t kNoSlot = ~std::size_t(0);

/// The strength of a suggestive contour's test (suggestive_strength) at the
/// snaxels of @p fronts where @p wanted says, -infinity at the others.
std::vector<double> strength_where(const MeshTopology& topo, const CurvatureField& field, const Fronts& fronts,
                                   const Camera& camera, const ContourSpec& spec, const std::vector<std::uint8_t>& wanted) {
    const std::size_t n = fronts.snaxels.size();
    const ToViewer to_viewer(camera);
    const auto P = topo.positions();
    const auto N = topo.normals();
    // The derivative at each end vertex of the snaxels wanted, once per vertex.
    VertexData<std::size_t> slot(topo.n_vertices(), kNoSlot);
    std::vector<VertexId> ends;
    for (std::size_t i = 0; i < n; ++i) {
        if (!wanted[i]) continue;
        for (const VertexId v : {fronts.snaxels[i].inside, fronts.snaxels[i].outside})
            if (slot[v] == kNoSlot) {
                slot[v] = ends.size();
                ends.push_back(v);
            }
    }
    std::vector<double> out(n, -std::numeric_limits<double>::infinity());
    if (spec.test == SuggestiveTest::Derivative) {
        // The derivative along the view, from kappa_r at the vertex's neighbours.
        std::vector<double> derivative(ends.size());
        parallel_for(ends.size(), [&](std::size_t k) {
            // kappa_r itself at every vertex (suggestive_function holds a
            // stand-in past the last ring; it is recomputed there, and a true
            // kappa_r of the stand-in's value is recomputed to itself).
            auto radial = [&](VertexId j) { return radial_at(field, j, to_viewer(P[j])); };
            derivative[k] = vertex_derivative_along_view(topo, field, radial, ends[k], to_viewer);
        }, 1024);
        const double typical = field.typical, scale = typical > 0.0 ? 1.0 / (typical * typical) : 0.0;
        for (std::size_t i = 0; i < n; ++i) {
            if (!wanted[i]) continue;
            const Snaxel& s = fronts.snaxels[i];
            const double d = (1.0 - s.t) * derivative[slot[s.inside]] + s.t * derivative[slot[s.outside]];
            out[i] = d * scale - spec.k;
        }
        return out;
    }
    // rtsc's test: feature_size^2 sin(theta) D_w kappa_r and cos(theta) at
    // each end, interpolated apart along the edge, their ratio against k;
    // D_w kappa_r from the derivative of curvature, as rtsc computes it.
    const double fs = require_feature_size(topo), fs2 = fs * fs;
    const std::shared_ptr<const CurvatureDerivative> dc = require_curvature_derivative(topo, field);
    std::vector<double> num(ends.size()), den(ends.size());
    parallel_for(ends.size(), [&](std::size_t k) {
        const VertexId v = ends[k];
        const glm::dvec3 view = to_viewer(P[v]);
        den[k] = glm::dot(view, N[v]);
        num[k] = fs2 * radial_derivative_term(field, *dc, v, N[v], view);
    }, 4096);
    for (std::size_t i = 0; i < n; ++i) {
        if (!wanted[i]) continue;
        const Snaxel& s = fronts.snaxels[i];
        const std::size_t a = slot[s.inside], b = slot[s.outside];
        const double nu = (1.0 - s.t) * num[a] + s.t * num[b], de = (1.0 - s.t) * den[a] + s.t * den[b];
        if (de > 0.0) out[i] = nu / de - spec.k;
    }
    return out;
}

} // namespace

std::vector<double> suggestive_strength(const MeshTopology& topo, const CurvatureField& field, const Fronts& fronts,
                                        const Camera& camera, const ContourSpec& spec) {
    return strength_where(topo, field, fronts, camera, spec, std::vector<std::uint8_t>(fronts.snaxels.size(), 1));
}

std::vector<double> suggestive_margins(const MeshTopology& topo, const CurvatureField& field, const VertexData<double>& kr,
                                       const Fronts& fronts, const Camera& camera, const ContourSpec& spec) {
    const std::size_t n = fronts.snaxels.size();
    const double away = suggestive_away_value(field);
    const ToViewer to_viewer(camera);
    std::vector<double> margin(n);
    const bool rtsc = spec.test == SuggestiveTest::Rtsc;
    const double most_facing = std::cos(glm::radians(spec.min_angle));
    const auto P = topo.positions();
    const auto N = topo.normals();
    // A snaxel at a vertex where kappa_r is exactly 0 (a flat patch, whose
    // curvature vanishes) lies on a sign change only beside one that is not:
    // rtsc draws a zero where one corner of a face has kappa_r positive and
    // another negative, so the run along a flat patch's rim, from one such
    // vertex to the next, is no suggestive contour, while the step from a
    // true crossing to the flat vertex in the same face is.
    std::vector<std::uint8_t> flat(n, 0), beside_crossing(n, 0);
    for (std::size_t i = 0; i < n; ++i)
        flat[i] = kr[fronts.snaxels[i].inside] == 0.0 || kr[fronts.snaxels[i].outside] == 0.0;
    for (const FrontLoop& loop : fronts.loops) {
        std::vector<std::int32_t> order;
        fronts.for_each_in_loop(loop, [&](std::int32_t i) { order.push_back(i); });
        for (std::size_t k = 0; k < order.size(); ++k) {
            if (!flat[order[k]]) continue;
            const bool has_prev = k > 0 || loop.closed, has_next = k + 1 < order.size() || loop.closed;
            const std::int32_t prev = order[(k + order.size() - 1) % order.size()], next = order[(k + 1) % order.size()];
            beside_crossing[order[k]] = (has_prev && !flat[prev]) || (has_next && !flat[next]);
        }
    }
    // The view terms first: where they already leave a snaxel out (about
    // half of them face away), its margin is theirs and the test's
    // strength is not needed.
    parallel_for(n, [&](std::size_t i) {
        const Snaxel& s = fronts.snaxels[i];
        const glm::dvec3 p = (1.0 - s.t) * P[s.inside] + s.t * P[s.outside];
        // (The normalized mean of the end normals: the slerp's direction
        // within a hair, at a fraction of its cost.)
        const glm::dvec3 mixed = (1.0 - s.t) * N[s.inside] + s.t * N[s.outside];
        const double len = glm::length(mixed);
        const double nv = len > 0.0 ? glm::dot(mixed, to_viewer(p)) / len : 0.0;
        // A snaxel on an edge from a vertex holding suggestive_function's
        // stand-in (its inside end) lies on the rim of the stand-in, a zero
        // of suggestive_function only: never drawn.
        const bool rim = kr[s.inside] == away;
        // Inside a sharp edge's strip kappa_r jumps from one side's to the
        // other's: a zero there is no suggestive contour (they are drawn on
        // smooth patches only).
        // (The rtsc test has no least angle: its tan(theta) falls to 0 where
        // the surface faces the viewer.)
        margin[i] = rim || (flat[i] && !beside_crossing[i]) || (topo.has_strips() && edge_in_strip(topo, s.edge)) ? -1.0
                    : rtsc                                                   ? nv
                                                                             : std::min(most_facing - nv, nv);
    }, 4096);
    std::vector<std::uint8_t> open(n);
    for (std::size_t i = 0; i < n; ++i) open[i] = margin[i] >= 0.0;
    const std::vector<double> strength = strength_where(topo, field, fronts, camera, spec, open);
    for (std::size_t i = 0; i < n; ++i)
        if (open[i]) margin[i] = std::isfinite(strength[i]) ? std::min(margin[i], strength[i]) : -1.0;
    return margin;
}

double derivative_along_view(const MeshTopology& topo, const VertexData<double>& f, FaceId face,
                             const glm::dvec3& p, const Camera& camera) {
    double area = 0.0;
    const std::array<glm::dvec3, 3> g = corner_gradients(topo, face, area);
    if (!(area > 0.0)) return 0.0;
    const auto& fv = topo.face_vertices()[face];
    const glm::dvec3 gradient = f[fv[0]] * g[0] + f[fv[1]] * g[1] + f[fv[2]] * g[2];
    const auto P = topo.positions();
    const glm::dvec3 n = glm::normalize(glm::cross(P[fv[1]] - P[fv[0]], P[fv[2]] - P[fv[0]]));
    const glm::dvec3 view = camera.to_viewer(p);
    const glm::dvec3 w = view - glm::dot(view, n) * n;
    const double len = glm::length(w);
    return len > 0.0 ? glm::dot(gradient, w) / len : 0.0;
}

} // namespace snaxels
