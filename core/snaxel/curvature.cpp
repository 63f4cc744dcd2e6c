#include "snaxels/snaxel/curvature.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "snaxels/util/detail/parallel.h"

namespace snaxels {

namespace {

/// A face's second fundamental form in its own frame (t, b): the symmetric
/// matrix [ku kuv; kuv kv], with the face's share of each corner's area.
struct FaceForm {
    glm::dvec3 t{0.0}, b{0.0};
    glm::dvec3 n{0.0}; ///< t x b (the face's unit normal, as project_form turns toward it)
    double ku = 0.0, kuv = 0.0, kv = 0.0;
    std::array<double, 3> corner{0.0, 0.0, 0.0}; ///< 0 for a face of no area: it then counts nowhere
};

/// The parts of a triangle's area nearest each corner (Meyer et al. 2003's
/// mixed Voronoi areas: a corner's Voronoi cell, or for an obtuse triangle
/// half the area at the obtuse corner and a quarter at the others).
std::array<double, 3> corner_areas(const std::array<glm::dvec3, 3>& e, double area) {
    const std::array<double, 3> l2{glm::dot(e[0], e[0]), glm::dot(e[1], e[1]), glm::dot(e[2], e[2])};
    // Barycentric weights of the circumcentre (times a common factor).
    const std::array<double, 3> bcw{l2[0] * (l2[1] + l2[2] - l2[0]), l2[1] * (l2[2] + l2[0] - l2[1]),
                                    l2[2] * (l2[0] + l2[1] - l2[2])};
    std::array<double, 3> c{};
    for (std::size_t a = 0; a < 3; ++a) {
        if (bcw[a] > 0.0) continue;
        // Obtuse at corner a: the circumcentre lies outside, past the edge opposite a.
        const std::size_t n = (a + 1) % 3, p = (a + 2) % 3;
        c[n] = -0.25 * l2[p] * area / glm::dot(e[a], e[p]);
        c[p] = -0.25 * l2[n] * area / glm::dot(e[a], e[n]);
        c[a] = area - c[n] - c[p];
        return c;
    }
    const double scale = 0.5 * area / (bcw[0] + bcw[1] + bcw[2]);
    for (std::size_t j = 0; j < 3; ++j) c[j] = scale * (bcw[(j + 1) % 3] + bcw[(j + 2) % 3]);
    return c;
}

/// Fits face @p f's second fundamental form to the change of the vertex
/// normals along its edges (least squares over the three edges).
FaceForm face_form(const MeshTopology& topo, FaceId f) {
    FaceForm form;
    const auto& fv = topo.face_vertices()[f];
    const auto P = topo.positions();
    const auto N = topo.normals();
    // Edge j is opposite corner j, running from corner j+1 to corner j+2.
    const std::array<glm::dvec3, 3> e{P[fv[2]] - P[fv[1]], P[fv[0]] - P[fv[2]], P[fv[1]] - P[fv[0]]};
    const glm::dvec3 cross = glm::cross(e[0], e[1]);
    const double twice_area = glm::length(cross);
    const double e0 = glm::length(e[0]);
    if (!(twice_area > 0.0) || !(e0 > 0.0)) return form;
    const glm::dvec3 n = cross / twice_area;
    form.t = e[0] / e0;
    form.b = glm::cross(n, form.t);
    // Normal equations of [u v 0; 0 u v] (ku kuv kv) = (dn.t dn.b) over the edges.
    double w00 = 0.0, w01 = 0.0, w22 = 0.0, m0 = 0.0, m1 = 0.0, m2 = 0.0;
    for (std::size_t j = 0; j < 3; ++j) {
        const double u = glm::dot(e[j], form.t), v = glm::dot(e[j], form.b);
        w00 += u * u;
        w01 += u * v;
        w22 += v * v;
        const glm::dvec3 dn = N[fv[(j + 2) % 3]] - N[fv[(j + 1) % 3]];
        const double dnu = glm::dot(dn, form.t), dnv = glm::dot(dn, form.b);
        m0 += dnu * u;
        m1 += dnu * v + dnv * u;
        m2 += dnv * v;
    }
    const glm::dmat3 w(w00, w01, 0.0, w01, w00 + w22, w01, 0.0, w01, w22); // symmetric
    const double det = glm::determinant(w);
    const double scale = w00 + w22;
    if (!(std::abs(det) > 1e-30 * (scale * scale * scale))) return form;
    const glm::dvec3 k = glm::inverse(w) * glm::dvec3(m0, m1, m2);
    form.ku = k.x;
    form.kuv = k.y;
    form.kv = k.z;
    form.n = glm::cross(form.t, form.b);
    form.corner = corner_areas(e, 0.5 * twice_area);
    return form;
}

/// A vertex's unit tangent frame (u, v) and u x v (its normal, as
/// turn_frame turns it).
struct TangentFrame {
    glm::dvec3 u, v, n;
};

/// The frame (u, v) turned about u x v onto the plane of normal @p n: the
/// smallest rotation taking u x v to n.
std::pair<glm::dvec3, glm::dvec3> turn_frame(const TangentFrame& frame, const glm::dvec3& n) {
    const glm::dvec3& u = frame.u;
    const glm::dvec3& v = frame.v;
    const glm::dvec3& old_n = frame.n;
    const double ndot = glm::dot(old_n, n);
    if (ndot <= -1.0) return {-u, -v};
    const glm::dvec3 perp = n - ndot * old_n;
    const glm::dvec3 dperp = (old_n + n) / (1.0 + ndot);
    return {u - dperp * glm::dot(u, perp), v - dperp * glm::dot(v, perp)};
}

/// @p form, a form in the frame (form.t, form.b), as a form in @p frame.
std::array<double, 3> project_form(const FaceForm& form, const TangentFrame& frame) {
    const auto [ru, rv] = turn_frame(frame, form.n);
    const double u1 = glm::dot(ru, form.t), v1 = glm::dot(ru, form.b);
    const double u2 = glm::dot(rv, form.t), v2 = glm::dot(rv, form.b);
    return {form.ku * u1 * u1 + form.kuv * (2.0 * u1 * v1) + form.kv * v1 * v1,
            form.ku * u1 * u2 + form.kuv * (u1 * v2 + u2 * v1) + form.kv * v1 * v2,
            form.ku * u2 * u2 + form.kuv * (2.0 * u2 * v2) + form.kv * v2 * v2};
}

/// A unit tangent frame (u, v) at vertex @p v, u toward its first neighbour.
TangentFrame vertex_frame(const MeshTopology& topo, VertexId v) {
    const glm::dvec3 n = topo.normals()[v];
    glm::dvec3 u(0.0);
    if (const auto ring = topo.neighbours(v); !ring.empty()) {
        const glm::dvec3 d = topo.positions()[ring.front()] - topo.positions()[v];
        u = d - glm::dot(d, n) * n;
    }
    if (!(glm::length(u) > 0.0)) { // no neighbour, or one along the normal: any tangent
        u = glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0));
    }
    u = glm::normalize(u);
    const glm::dvec3 w = glm::cross(n, u);
    return {u, w, glm::cross(u, w)};
}

/// Every vertex's tangent frame (vertex_frame), found once per pose for
/// the passes that turn forms into it.
VertexData<TangentFrame> vertex_frames(const MeshTopology& topo) {
    VertexData<TangentFrame> frames(topo.n_vertices());
    parallel_for(topo.vertices(), [&](VertexId v) { frames[v] = vertex_frame(topo, v); }, 4096);
    return frames;
}

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

/// Vertex @p v's principal curvatures and directions from its second
/// fundamental form [ku kuv; kuv kv] in the tangent frame (u, w): the
/// Jacobi rotation that diagonalizes it, |k1| >= |k2|.
void set_principal(CurvatureField& out, VertexId v, const glm::dvec3& n, const glm::dvec3& u, const glm::dvec3& w,
                   double ku, double kuv, double kv) {
    double c = 1.0, s = 0.0, tt = 0.0;
    if (kuv != 0.0) {
        const double h = 0.5 * (kv - ku) / kuv;
        tt = h < 0.0 ? 1.0 / (h - std::sqrt(1.0 + h * h)) : 1.0 / (h + std::sqrt(1.0 + h * h));
        c = 1.0 / std::sqrt(1.0 + tt * tt);
        s = tt * c;
    }
    double k1 = ku - tt * kuv, k2 = kv + tt * kuv;
    glm::dvec3 d1 = c * u - s * w;
    if (std::abs(k1) < std::abs(k2)) {
        std::swap(k1, k2);
        d1 = s * u + c * w;
    }
    out.k1[v] = k1;
    out.k2[v] = k2;
    out.dir1[v] = d1;
    out.dir2[v] = glm::cross(n, d1);
}

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

/// The median |k1| over the vertices with area (CurvatureField::typical).
double typical_curvature(const CurvatureField& field) {
    std::vector<double> magnitudes;
    magnitudes.reserve(field.size());
    for (const VertexId v : field.k1.ids())
        if (field.area[v] > 0.0) magnitudes.push_back(std::abs(field.k1[v]));
    if (magnitudes.empty()) return 0.0;
    const auto middle = magnitudes.begin() + std::ptrdiff_t(magnitudes.size() / 2);
    std::nth_element(magnitudes.begin(), middle, magnitudes.end());
    return *middle;
}

/// What the curvature passes read of the connectivity alone, found once per
/// mesh and shared by its poses: each vertex's faces (faces_around's order,
/// with the vertex's corner) and, for the gradient operator, where each of
/// a face's corners adds to the vertex's weights.
struct CurvaturePlan {
    /// CSR: the faces around v are around[around_start[v] .. around_start[v+1]).
    std::vector<std::size_t> around_start;
    std::vector<FaceCorner> around;
    /// Per entry of around, per corner k of its face: the place of corner
    /// k's vertex among v's gradient weights (0 for v, 1 + i for its i-th
    /// neighbour), or kNoPlace when it is none of them.
    std::vector<std::array<std::int32_t, 3>> place;
    static constexpr std::int32_t kNoPlace = -1;
    /// CurvatureField::gradient_start and gradient_vertex, the same in every pose.
    std::vector<std::int32_t> gradient_start;
    std::vector<VertexId> gradient_vertex;
};

CurvaturePlan make_plan(const MeshTopology& topo) {
    CurvaturePlan plan;
    const std::size_t nv = topo.n_vertices();
    plan.around_start.assign(nv + 1, 0);
    plan.gradient_start.assign(nv + 1, 0);
    for (const VertexId v : topo.vertices()) {
        const auto i = v.index();
        for (const FaceCorner fc : topo.faces_around(v)) plan.around.push_back(fc);
        plan.around_start[i + 1] = plan.around.size();
        plan.gradient_start[i + 1] = plan.gradient_start[i] + 1 + topo.degree(v); // v itself, then its neighbours
    }
    plan.place.resize(plan.around.size());
    plan.gradient_vertex.resize(plan.gradient_start.back());
    parallel_for(topo.vertices(), [&](VertexId v) {
        const std::span<const VertexId> ring = topo.neighbours(v);
        const auto at = plan.gradient_vertex.begin() + plan.gradient_start[v.index()];
        *at = v;
        std::copy(ring.begin(), ring.end(), at + 1);
        for (std::size_t a = plan.around_start[v.index()]; a < plan.around_start[v.index() + 1]; ++a) {
            const auto& fv = topo.face_vertices()[plan.around[a].face];
            for (std::size_t k = 0; k < 3; ++k) {
                std::int32_t place = CurvaturePlan::kNoPlace;
                if (fv[k] == v) {
                    place = 0;
                } else if (const auto it = std::find(ring.begin(), ring.end(), fv[k]); it != ring.end()) {
                    place = std::int32_t(1 + (it - ring.begin()));
                }
                plan.place[a][k] = place;
            }
        }
    }, 4096);
    return plan;
}

/// The topology's plan, made on first use and kept with its connectivity.
std::shared_ptr<const CurvaturePlan> require_plan(const MeshTopology& topo) {
    return topo.connectivity()->quantities.require<CurvaturePlan>("curvature plan", [&] { return make_plan(topo); });
}

/// smoothed_curvatures with the pose's tangent frames given, without the
/// typical curvature (only the last pass's is read).
CurvatureField smoothed(const MeshTopology& topo, const CurvatureField& field, const VertexData<TangentFrame>& frames) {
    CurvatureField out = field;
    // Each vertex's principal frame as a form's frame, with its normal.
    VertexData<glm::dvec3> principal_normal(topo.n_vertices());
    parallel_for(topo.vertices(), [&](VertexId v) { principal_normal[v] = glm::cross(field.dir1[v], field.dir2[v]); }, 4096);
    parallel_for(topo.vertices(), [&](VertexId v) {
        if (!(field.area[v] > 0.0)) return;
        const TangentFrame& frame = frames[v];
        double total = 0.0, ku = 0.0, kuv = 0.0, kv = 0.0;
        auto add = [&](VertexId j) {
            FaceForm form; // vertex j's form in its principal frame
            form.t = field.dir1[j];
            form.b = field.dir2[j];
            form.n = principal_normal[j];
            form.ku = field.k1[j];
            form.kv = field.k2[j];
            const std::array<double, 3> k = project_form(form, frame);
            total += field.area[j];
            ku += field.area[j] * k[0];
            kuv += field.area[j] * k[1];
            kv += field.area[j] * k[2];
        };
        add(v);
        for (const VertexId n : topo.neighbours(v))
            if (field.area[n] > 0.0) add(n);
        set_principal(out, v, topo.normals()[v], frame.u, frame.v, ku / total, kuv / total, kv / total);
    }, 1024);
    return out;
}

/// vertex_curvatures with the plan and the pose's tangent frames given,
/// without the typical curvature.
CurvatureField unsmoothed(const MeshTopology& topo, const CurvaturePlan& plan, const VertexData<TangentFrame>& frames) {
    const std::size_t nv = topo.n_vertices(), nf = topo.n_faces();
    FaceData<FaceForm> forms(nf);
    parallel_for(topo.faces(), [&](FaceId f) { forms[f] = face_form(topo, f); }, 2048);

    CurvatureField out;
    out.k1.assign(nv, 0.0);
    out.k2.assign(nv, 0.0);
    out.dir1.assign(nv, glm::dvec3(0.0));
    out.dir2.assign(nv, glm::dvec3(0.0));
    out.area.assign(nv, 0.0);
    parallel_for(topo.vertices(), [&](VertexId v) {
        const TangentFrame& frame = frames[v];
        double area = 0.0, ku = 0.0, kuv = 0.0, kv = 0.0;
        for (std::size_t a = plan.around_start[v.index()]; a < plan.around_start[v.index() + 1]; ++a) {
            const auto [face, corner] = plan.around[a];
            const FaceForm& form = forms[face];
            const double weight = form.corner[corner];
            if (!(weight > 0.0)) continue;
            const std::array<double, 3> k = project_form(form, frame);
            area += weight;
            ku += weight * k[0];
            kuv += weight * k[1];
            kv += weight * k[2];
        }
        out.area[v] = area;
        if (!(area > 0.0)) {
            out.dir1[v] = frame.u;
            out.dir2[v] = frame.v;
            return;
        }
        set_principal(out, v, topo.normals()[v], frame.u, frame.v, ku / area, kuv / area, kv / area);
    }, 1024);
    return out;
}

/// add_gradient_operator with the plan given.
void gradient_operator(const MeshTopology& topo, const CurvaturePlan& plan, CurvatureField& field) {
    field.gradient_start = plan.gradient_start;
    field.gradient_vertex = plan.gradient_vertex;
    field.gradient_weight.assign(plan.gradient_vertex.size(), glm::dvec3(0.0));
    // Each face's corner gradients once (a face is around three vertices).
    struct FaceGradients {
        double area = 0.0;
        std::array<glm::dvec3, 3> g;
    };
    FaceData<FaceGradients> faces(topo.n_faces());
    parallel_for(topo.faces(), [&](FaceId f) { faces[f].g = corner_gradients(topo, f, faces[f].area); }, 4096);
    parallel_for(topo.vertices(), [&](VertexId v) {
        const auto begin = field.gradient_weight.begin() + plan.gradient_start[v.index()];
        const auto end = field.gradient_weight.begin() + plan.gradient_start[v.index() + 1];
        double total = 0.0;
        for (std::size_t a = plan.around_start[v.index()]; a < plan.around_start[v.index() + 1]; ++a) {
            const FaceGradients& face = faces[plan.around[a].face];
            const auto& place = plan.place[a];
            for (std::size_t k = 0; k < 3; ++k)
                if (place[k] != CurvaturePlan::kNoPlace) begin[place[k]] += face.area * face.g[k];
            total += face.area;
        }
        if (total > 0.0)
            for (auto w = begin; w != end; ++w) *w /= total;
    }, 1024);
}

} // namespace

CurvatureField smoothed_curvatures(const MeshTopology& topo, const CurvatureField& field) {
    CurvatureField out = smoothed(topo, field, vertex_frames(topo));
    out.typical = typical_curvature(out);
    return out;
}

CurvatureField vertex_curvatures(const MeshTopology& topo) {
    CurvatureField out = unsmoothed(topo, *require_plan(topo), vertex_frames(topo));
    out.typical = typical_curvature(out);
    return out;
}

void add_gradient_operator(const MeshTopology& topo, CurvatureField& field) {
    gradient_operator(topo, *require_plan(topo), field);
}

std::shared_ptr<const CurvatureField> require_curvature(const MeshTopology& topo, const CurvatureOptions& options) {
    const std::string key = "curvature smoothing=" + std::to_string(options.smoothing) +
                            " gradient=" + std::to_string(int(options.gradient));
    // Computed outside the store's lock: the computation runs parallel
    // loops, whose workers may be asked for the same pose's curvature.
    return topo.pose()->quantities.require<CurvatureField>(key, [&] {
        const std::shared_ptr<const CurvaturePlan> plan = require_plan(topo);
        const VertexData<TangentFrame> frames = vertex_frames(topo);
        CurvatureField field = unsmoothed(topo, *plan, frames);
        for (int pass = 0; pass < options.smoothing; ++pass) field = smoothed(topo, field, frames);
        field.typical = typical_curvature(field);
        if (options.gradient) gradient_operator(topo, *plan, field);
        return field;
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
    parallel_for(topo.vertices(), [&](VertexId v) {
        const glm::dvec3 view = to_viewer(P[v]);
        out[v] = glm::dot(view, N[v]) > 0.0 ? radial_at(field, v, view) : away;
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

} // namespace

std::vector<double> suggestive_margins(const MeshTopology& topo, const CurvatureField& field, const VertexData<double>& kr,
                                       const Fronts& fronts, const Camera& camera, const ContourSpec& spec) {
    const std::size_t n = fronts.snaxels.size();
    const double typical = field.typical, away = suggestive_away_value(field);
    const ToViewer to_viewer(camera);
    std::vector<double> margin(n);
    const double scale = typical > 0.0 ? 1.0 / (typical * typical) : 0.0, most_facing = std::cos(glm::radians(spec.min_angle));
    const auto P = topo.positions();
    const auto N = topo.normals();
    // The view terms first: where they already leave a snaxel out (about
    // half of them face away), its margin is theirs and kappa_r's derivative
    // is not needed.
    parallel_for(n, [&](std::size_t i) {
        const Snaxel& s = fronts.snaxels[i];
        const glm::dvec3 p = (1.0 - s.t) * P[s.inside] + s.t * P[s.outside];
        // (The normalized mean of the end normals: the slerp's direction
        // within a hair, at a fraction of its cost.)
        const glm::dvec3 mixed = (1.0 - s.t) * N[s.inside] + s.t * N[s.outside];
        const double len = glm::length(mixed);
        const double nv = len > 0.0 ? glm::dot(mixed, to_viewer(p)) / len : 0.0;
        // A snaxel on an edge from a vertex facing away (its inside end,
        // where suggestive_function holds its stand-in) lies on the rim of
        // the side seen, a zero of suggestive_function only: never drawn.
        const bool rim = kr[s.inside] == away;
        // Inside a sharp edge's strip kappa_r jumps from one side's to the
        // other's: a zero there is no suggestive contour (they are drawn on
        // smooth patches only).
        margin[i] = rim || (topo.has_strips() && edge_in_strip(topo, s.edge)) ? -1.0 : std::min(most_facing - nv, nv);
    }, 4096);
    // The derivative at each end vertex of the other snaxels, once per vertex.
    VertexData<std::size_t> slot(topo.n_vertices(), kNoSlot);
    std::vector<VertexId> ends;
    for (std::size_t i = 0; i < n; ++i) {
        if (margin[i] < 0.0) continue;
        for (const VertexId v : {fronts.snaxels[i].inside, fronts.snaxels[i].outside})
            if (slot[v] == kNoSlot) {
                slot[v] = ends.size();
                ends.push_back(v);
            }
    }
    std::vector<double> derivative(ends.size());
    parallel_for(ends.size(), [&](std::size_t k) {
        // kappa_r itself, also at the neighbours facing away (where @p kr
        // holds suggestive_function's stand-in; a true kappa_r of the same
        // value is recomputed, to itself).
        auto radial = [&](VertexId j) { return kr[j] != away ? kr[j] : radial_at(field, j, to_viewer(P[j])); };
        derivative[k] = vertex_derivative_along_view(topo, field, radial, ends[k], to_viewer);
    }, 1024);
    for (std::size_t i = 0; i < n; ++i) {
        if (margin[i] < 0.0) continue;
        const Snaxel& s = fronts.snaxels[i];
        const double d = (1.0 - s.t) * derivative[slot[s.inside]] + s.t * derivative[slot[s.outside]];
        margin[i] = std::min(margin[i], d * scale - spec.k);
    }
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
