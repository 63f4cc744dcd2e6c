// The derivative of curvature (Rusinkiewicz 2004, section 4): per face, the
// symmetric 2x2x2 tensor C fitted by least squares to how the vertices'
// second fundamental forms change along the face's three edges (each form
// turned into the face's plane); per vertex, the faces' tensors turned into
// the vertex's principal frame and averaged with the vertex's share of each
// face's area, as the forms themselves are (curvature.cpp).

#include "snaxels/snaxel/curvature.h"

#include <array>
#include <cmath>
#include <string>

#include <glm/glm.hpp>

#include "snaxels/snaxel/detail/corner_areas.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {
namespace {

/// Tangent vector @p x of a plane of unit normal @p from, turned by the
/// smallest rotation that takes @p from to unit @p to (x - d (x.p) with
/// p = to - (to.from) from and d = (from + to) / (1 + to.from); negated when
/// the normals are opposite).
glm::dvec3 turned(const glm::dvec3& x, const glm::dvec3& from, const glm::dvec3& to) {
    const double c = glm::dot(from, to);
    if (c <= -1.0) return -x;
    const glm::dvec3 p = to - c * from, d = (from + to) / (1.0 + c);
    return x - d * glm::dot(x, p);
}

/// C(a, b, c) of the symmetric tensor with components C111, C112, C122, C222
/// in a frame, for vectors given by their two coordinates there.
double trilinear(const std::array<double, 4>& t, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return t[0] * a.x * b.x * c.x + t[1] * (a.x * b.x * c.y + a.x * b.y * c.x + a.y * b.x * c.x) +
           t[2] * (a.x * b.y * c.y + a.y * b.x * c.y + a.y * b.y * c.x) + t[3] * a.y * b.y * c.y;
}

/// Solves the 4x4 system @p a x = @p r by elimination with partial
/// pivoting; false when it is singular.
bool solve4(std::array<std::array<double, 4>, 4> a, std::array<double, 4> r, std::array<double, 4>& x) {
    double scale = 0.0;
    for (const auto& row : a)
        for (const double v : row) scale = std::max(scale, std::abs(v));
    for (std::size_t col = 0; col < 4; ++col) {
        std::size_t pivot = col;
        for (std::size_t row = col + 1; row < 4; ++row)
            if (std::abs(a[row][col]) > std::abs(a[pivot][col])) pivot = row;
        if (!(std::abs(a[pivot][col]) > 1e-12 * scale)) return false;
        std::swap(a[pivot], a[col]);
        std::swap(r[pivot], r[col]);
        for (std::size_t row = col + 1; row < 4; ++row) {
            const double f = a[row][col] / a[col][col];
            for (std::size_t k = col; k < 4; ++k) a[row][k] -= f * a[col][k];
            r[row] -= f * r[col];
        }
    }
    for (std::size_t i = 4; i-- > 0;) {
        double s = r[i];
        for (std::size_t k = i + 1; k < 4; ++k) s -= a[i][k] * x[k];
        x[i] = s / a[i][i];
    }
    return true;
}

/// One face's tensor in its frame (t, b), and each corner's share of its area.
struct FaceDerivative {
    glm::dvec3 t{0.0}, b{0.0}, n{0.0};
    std::array<double, 4> c{};
    std::array<double, 3> corner{}; ///< 0: the face counts nowhere (no area, or a singular fit)
};

FaceDerivative face_derivative(const MeshTopology& topo, const CurvatureField& field, FaceId f) {
    FaceDerivative out;
    const auto& fv = topo.face_vertices()[f];
    const auto P = topo.positions();
    const auto N = topo.normals();
    const std::array<glm::dvec3, 3> e{P[fv[2]] - P[fv[1]], P[fv[0]] - P[fv[2]], P[fv[1]] - P[fv[0]]};
    const glm::dvec3 cr = glm::cross(e[0], e[1]);
    const double twice_area = glm::length(cr);
    if (!(twice_area > 0.0) || !face_has_area(topo, f)) return out;
    out.n = cr / twice_area;
    out.t = glm::normalize(e[2]);
    out.b = glm::cross(out.n, out.t);
    // Each vertex's form [a b; b c] in the face's frame.
    std::array<std::array<double, 3>, 3> form{};
    for (std::size_t j = 0; j < 3; ++j) {
        const VertexId v = fv[j];
        const glm::dvec3 d1 = turned(field.dir1[v], N[v], out.n), d2 = turned(field.dir2[v], N[v], out.n);
        const double t1 = glm::dot(d1, out.t), b1 = glm::dot(d1, out.b), t2 = glm::dot(d2, out.t), b2 = glm::dot(d2, out.b);
        form[j] = {field.k1[v] * t1 * t1 + field.k2[v] * t2 * t2, field.k1[v] * t1 * b1 + field.k2[v] * t2 * b2,
                   field.k1[v] * b1 * b1 + field.k2[v] * b2 * b2};
    }
    // Along edge s -> e (x, y in the face's frame) the form changes by
    // [C111 x + C112 y, C112 x + C122 y, C122 x + C222 y].
    std::array<std::array<double, 4>, 4> a{};
    std::array<double, 4> r{};
    for (std::size_t j = 0; j < 3; ++j) {
        const std::size_t s = j, to = (j + 1) % 3;
        const glm::dvec3 d = P[fv[to]] - P[fv[s]];
        const double x = glm::dot(d, out.t), y = glm::dot(d, out.b);
        const std::array<std::array<double, 4>, 3> rows{{{x, y, 0.0, 0.0}, {0.0, x, y, 0.0}, {0.0, 0.0, x, y}}};
        for (std::size_t q = 0; q < 3; ++q) {
            const double change = form[to][q] - form[s][q];
            for (std::size_t i = 0; i < 4; ++i) {
                r[i] += rows[q][i] * change;
                for (std::size_t k = 0; k < 4; ++k) a[i][k] += rows[q][i] * rows[q][k];
            }
        }
    }
    if (!solve4(a, r, out.c)) return out;
    out.corner = detail::corner_areas(e, 0.5 * twice_area);
    return out;
}

CurvatureDerivative compute_derivative(const MeshTopology& topo, const CurvatureField& field) {
    FaceData<FaceDerivative> faces(topo.n_faces());
    parallel_for(topo.faces(), [&](FaceId f) { faces[f] = face_derivative(topo, field, f); }, 1024);
    CurvatureDerivative out;
    out.c.assign(topo.n_vertices(), {0.0, 0.0, 0.0, 0.0});
    const auto N = topo.normals();
    parallel_for(topo.vertices(), [&](VertexId v) {
        std::array<double, 4> sum{};
        double total = 0.0;
        for (const FaceCorner fc : topo.faces_around(v)) {
            const FaceDerivative& fd = faces[fc.face];
            const double w = fd.corner[unsigned(fc.corner)];
            if (!(w > 0.0)) continue;
            // The vertex's principal frame turned onto the face's plane, in (t, b).
            const glm::dvec3 u = turned(field.dir1[v], N[v], fd.n), w2 = turned(field.dir2[v], N[v], fd.n);
            const glm::dvec2 a(glm::dot(u, fd.t), glm::dot(u, fd.b)), b(glm::dot(w2, fd.t), glm::dot(w2, fd.b));
            sum[0] += w * trilinear(fd.c, a, a, a);
            sum[1] += w * trilinear(fd.c, a, a, b);
            sum[2] += w * trilinear(fd.c, a, b, b);
            sum[3] += w * trilinear(fd.c, b, b, b);
            total += w;
        }
        if (total > 0.0)
            for (std::size_t k = 0; k < 4; ++k) out.c[v][k] = sum[k] / total;
    }, 1024);
    return out;
}

} // namespace

std::shared_ptr<const CurvatureDerivative> require_curvature_derivative(const MeshTopology& topo,
                                                                       const CurvatureField& field) {
    // Kept with the pose when the field is the pose's default curvature
    // (what every caller draws with); another field's is computed afresh.
    if (&field != require_curvature(topo).get())
        return std::make_shared<const CurvatureDerivative>(compute_derivative(topo, field));
    return topo.pose()->quantities.require(Quantity<CurvatureDerivative>{"curvature derivative"},
                                                                 [&] { return compute_derivative(topo, field); });
}

double radial_derivative_term(const CurvatureField& field, const CurvatureDerivative& derivative, VertexId v,
                              const glm::dvec3& normal, const glm::dvec3& view) {
    const double x = glm::dot(view, field.dir1[v]), y = glm::dot(view, field.dir2[v]);
    const double s2 = x * x + y * y;
    if (!(s2 > 0.0)) return 0.0;
    const std::array<double, 4>& c = derivative.c[v];
    const double cwww = c[0] * x * x * x + 3.0 * c[1] * x * x * y + 3.0 * c[2] * x * y * y + c[3] * y * y * y;
    const double torsion = (field.k2[v] - field.k1[v]) * x * y / s2;
    return cwww / s2 - 2.0 * glm::dot(view, normal) * torsion * torsion;
}

} // namespace snaxels
