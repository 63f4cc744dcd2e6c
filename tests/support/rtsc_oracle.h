#pragma once
// DeCarlo et al.'s suggestive contours, drawn as their program rtsc draws
// them, written for the tests alone: it shares no code with the engine.
//
// - Curvature (Rusinkiewicz 2004): each face's second fundamental form is
//   fitted by least squares to the change of the vertex normals along its
//   edges; a vertex takes the mean of its faces' forms weighted by its
//   share of each face (rtsc's Voronoi corner areas), each form held as a 3x3 tensor and
//   rotated from the face's plane into the vertex's (the smallest rotation
//   between the normals). Optional smoothing passes replace each vertex's
//   form by the area-weighted mean of its own and its neighbours', rotated
//   the same way. Principal curvatures from the 2x2 form's eigenvalues.
// - The derivative of curvature (Rusinkiewicz 2004, as trimesh2 computes
//   it): each face's symmetric 2x2x2 tensor C is fitted by least squares to
//   the change of the vertex forms (rotated into the face's plane) along
//   its edges, then averaged at the vertices like the forms.
// - Per view (a perspective eye, as rtsc): kr = kappa_r sin^2(theta); the
//   test's numerator sin(theta) C(w,w,w) - 2 cos(theta) tau_r^2 less the
//   threshold over feature size squared times its denominator cos(theta)
//   (rtsc's sctest_num and sctest_den), the feature size the median edge
//   length.
// - Per face where kr changes sign, the segment between its zeros on two
//   edges (linear in kr), kept where the numerator and the denominator,
//   each linear along it, are both positive: the zeros on the side seen
//   where the test passes.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "tests/support/segment_distance.h"

namespace snaxels::test {

struct RtscMesh {
    std::vector<glm::dvec3> p, n; ///< positions and unit vertex normals
    std::vector<std::array<std::int32_t, 3>> f;
};

struct RtscCurvature {
    std::vector<glm::dvec3> u, v;        ///< each vertex's tangent frame (u, v, its normal right-handed)
    std::vector<std::array<double, 3>> ii; ///< the second fundamental form [a b; b c] in (u, v)
    std::vector<std::array<double, 4>> c;  ///< the curvature derivative C(uuu), C(uuv), C(uvv), C(vvv)
    std::vector<double> area;              ///< Voronoi area (rtsc's corner shares)
};

namespace rtsc_detail {

using Tensor = std::array<std::array<double, 3>, 3>;

inline Tensor outer_sym(const glm::dvec3& a, const glm::dvec3& b) { // a b^T + b a^T
    Tensor t{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) t[i][j] = a[i] * b[j] + b[i] * a[j];
    return t;
}

inline glm::dvec3 apply(const Tensor& t, const glm::dvec3& x) {
    return {t[0][0] * x[0] + t[0][1] * x[1] + t[0][2] * x[2], t[1][0] * x[0] + t[1][1] * x[1] + t[1][2] * x[2],
            t[2][0] * x[0] + t[2][1] * x[1] + t[2][2] * x[2]};
}

/// The form (a, b, c) in the frame (x, y) as a 3x3 tensor.
inline Tensor tensor_of(const std::array<double, 3>& form, const glm::dvec3& x, const glm::dvec3& y) {
    Tensor t{};
    const Tensor xx = outer_sym(x, x), xy = outer_sym(x, y), yy = outer_sym(y, y);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) t[i][j] = 0.5 * form[0] * xx[i][j] + form[1] * xy[i][j] + 0.5 * form[2] * yy[i][j];
    return t;
}

/// Rodrigues' rotation taking unit @p from to unit @p to (the smallest),
/// applied to @p x.
inline glm::dvec3 rotate_between(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& x) {
    const glm::dvec3 axis = glm::cross(from, to);
    const double s = glm::length(axis), c = glm::dot(from, to);
    if (s < 1e-15) return c >= 0.0 ? x : -x;
    const glm::dvec3 k = axis / s;
    return x * c + glm::cross(k, x) * s + k * glm::dot(k, x) * (1.0 - c);
}

/// The form of tensor @p t (on the plane of normal @p from) seen in the
/// frame (x, y) of the plane of normal @p to, after rotating the plane.
inline std::array<double, 3> form_in(const Tensor& t, const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& x,
                                     const glm::dvec3& y) {
    // Rotating the tensor forward equals reading it along the frame rotated back.
    const glm::dvec3 xb = rotate_between(to, from, x), yb = rotate_between(to, from, y);
    return {glm::dot(xb, apply(t, xb)), glm::dot(xb, apply(t, yb)), glm::dot(yb, apply(t, yb))};
}

/// Solves the symmetric positive system @p a x = @p b (Gaussian elimination
/// with partial pivoting); false when singular.
template <std::size_t N> bool solve(std::array<std::array<double, N>, N> a, std::array<double, N> b, std::array<double, N>& x) {
    for (std::size_t col = 0; col < N; ++col) {
        std::size_t pivot = col;
        for (std::size_t r = col + 1; r < N; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        if (!(std::abs(a[pivot][col]) > 1e-300)) return false;
        std::swap(a[col], a[pivot]);
        std::swap(b[col], b[pivot]);
        for (std::size_t r = col + 1; r < N; ++r) {
            const double f = a[r][col] / a[col][col];
            for (std::size_t k = col; k < N; ++k) a[r][k] -= f * a[col][k];
            b[r] -= f * b[col];
        }
    }
    for (std::size_t r = N; r-- > 0;) {
        double s = b[r];
        for (std::size_t k = r + 1; k < N; ++k) s -= a[r][k] * x[k];
        x[r] = s / a[r][r];
    }
    return true;
}

/// Each corner's share of a triangle's area, as rtsc (trimesh2's point
/// areas) shares it: the Voronoi cells of the corners where no angle is
/// obtuse; where one is, each of the other two corners gets the right
/// triangle between it, the middle of its edge to the obtuse corner and
/// where that edge's perpendicular bisector meets the long edge (the
/// square of the edge's length times the tangent of the corner's angle,
/// over 8), and the obtuse corner the rest. (Not Meyer et al.'s halves and
/// quarters: on a CAD file's slivers the two differ by a factor of six.)
inline std::array<double, 3> voronoi(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2) {
    const std::array<glm::dvec3, 3> p{p0, p1, p2};
    const double area = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
    std::array<double, 3> out{};
    if (!(area > 0.0)) return out;
    auto angle_at = [&](int i) {
        const glm::dvec3 a = p[(i + 1) % 3] - p[i], b = p[(i + 2) % 3] - p[i];
        return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
    };
    for (int i = 0; i < 3; ++i) {
        if (!(angle_at(i) >= 0.5 * 3.14159265358979323846)) continue; // obtuse (or right) at i
        double rest = area;
        for (const int j : {(i + 1) % 3, (i + 2) % 3}) {
            const double l = glm::length(p[j] - p[i]);
            out[j] = l * l * std::tan(angle_at(j)) / 8.0;
            rest -= out[j];
        }
        out[i] = rest;
        return out;
    }
    auto cot = [](const glm::dvec3& a, const glm::dvec3& b) { return glm::dot(a, b) / glm::length(glm::cross(a, b)); };
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        const double cot_k = cot(p[i] - p[k], p[j] - p[k]), cot_j = cot(p[i] - p[j], p[k] - p[j]);
        out[i] = (glm::dot(p[j] - p[i], p[j] - p[i]) * cot_k + glm::dot(p[k] - p[i], p[k] - p[i]) * cot_j) / 8.0;
    }
    return out;
}

} // namespace rtsc_detail

/// The median edge length of @p m (edges of no length left out).
inline double rtsc_feature_size(const RtscMesh& m) {
    std::map<std::pair<std::int32_t, std::int32_t>, double> edges;
    for (const auto& f : m.f)
        for (int j = 0; j < 3; ++j) {
            const std::int32_t a = f[j], b = f[(j + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}] = glm::length(m.p[a] - m.p[b]);
        }
    std::vector<double> l;
    for (const auto& [e, len] : edges)
        if (len > 0.0) l.push_back(len);
    if (l.empty()) return 0.0;
    std::nth_element(l.begin(), l.begin() + std::ptrdiff_t(l.size() / 2), l.end());
    return l[l.size() / 2];
}

/// Curvature and its derivative of @p m, the forms smoothed @p smoothing times.
inline RtscCurvature rtsc_curvature(const RtscMesh& m, int smoothing) {
    using namespace rtsc_detail;
    const std::size_t nv = m.p.size(), nf = m.f.size();
    RtscCurvature out;
    out.u.resize(nv);
    out.v.resize(nv);
    out.ii.assign(nv, {0.0, 0.0, 0.0});
    out.c.assign(nv, {0.0, 0.0, 0.0, 0.0});
    out.area.assign(nv, 0.0);
    std::vector<std::vector<std::int32_t>> ring(nv);
    for (const auto& f : m.f)
        for (int j = 0; j < 3; ++j) {
            ring[f[j]].push_back(f[(j + 1) % 3]);
            ring[f[j]].push_back(f[(j + 2) % 3]);
        }
    for (std::size_t i = 0; i < nv; ++i) {
        std::sort(ring[i].begin(), ring[i].end());
        ring[i].erase(std::unique(ring[i].begin(), ring[i].end()), ring[i].end());
        const glm::dvec3 n = m.n[i];
        const glm::dvec3 any = std::abs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        out.u[i] = glm::normalize(any - glm::dot(any, n) * n);
        out.v[i] = glm::cross(n, out.u[i]);
    }
    // Faces: frame, form, corner areas.
    struct Face {
        glm::dvec3 n, t, b;
        std::array<double, 3> form{};
        std::array<double, 3> corner{};
        bool ok = false;
    };
    std::vector<Face> faces(nf);
    for (std::size_t fi = 0; fi < nf; ++fi) {
        const auto& f = m.f[fi];
        Face& face = faces[fi];
        const glm::dvec3 cr = glm::cross(m.p[f[1]] - m.p[f[0]], m.p[f[2]] - m.p[f[0]]);
        if (!(glm::length(cr) > 0.0)) continue;
        face.n = glm::normalize(cr);
        face.t = glm::normalize(m.p[f[1]] - m.p[f[0]]);
        face.b = glm::cross(face.n, face.t);
        std::array<std::array<double, 3>, 3> a{};
        std::array<double, 3> rhs{};
        for (int j = 0; j < 3; ++j) {
            const std::int32_t s = f[j], e = f[(j + 1) % 3];
            const glm::dvec3 d = m.p[e] - m.p[s], dn = m.n[e] - m.n[s];
            const double x = glm::dot(d, face.t), y = glm::dot(d, face.b);
            const double nx = glm::dot(dn, face.t), ny = glm::dot(dn, face.b);
            // [x y 0] . (ku kuv kv) = nx ; [0 x y] . (ku kuv kv) = ny
            const std::array<std::array<double, 3>, 2> rows{{{x, y, 0.0}, {0.0, x, y}}};
            const std::array<double, 2> r{nx, ny};
            for (int q = 0; q < 2; ++q)
                for (int i = 0; i < 3; ++i) {
                    rhs[i] += rows[q][i] * r[q];
                    for (int k = 0; k < 3; ++k) a[i][k] += rows[q][i] * rows[q][k];
                }
        }
        face.ok = solve<3>(a, rhs, face.form);
        if (face.ok) face.corner = voronoi(m.p[f[0]], m.p[f[1]], m.p[f[2]]);
    }
    for (std::size_t fi = 0; fi < nf; ++fi) {
        const Face& face = faces[fi];
        if (!face.ok) continue;
        const Tensor t = tensor_of(face.form, face.t, face.b);
        for (int j = 0; j < 3; ++j) {
            const std::int32_t i = m.f[fi][j];
            const double w = face.corner[j];
            if (!(w > 0.0)) continue;
            const auto k = form_in(t, face.n, m.n[i], out.u[i], out.v[i]);
            for (int q = 0; q < 3; ++q) out.ii[i][q] += w * k[q];
            out.area[i] += w;
        }
    }
    for (std::size_t i = 0; i < nv; ++i)
        if (out.area[i] > 0.0)
            for (double& x : out.ii[i]) x /= out.area[i];
    for (int pass = 0; pass < smoothing; ++pass) {
        std::vector<std::array<double, 3>> next = out.ii;
        for (std::size_t i = 0; i < nv; ++i) {
            if (!(out.area[i] > 0.0)) continue;
            std::array<double, 3> sum{};
            double total = 0.0;
            auto add = [&](std::size_t j) {
                if (!(out.area[j] > 0.0)) return;
                const Tensor t = tensor_of(out.ii[j], out.u[j], out.v[j]);
                const auto k = form_in(t, m.n[j], m.n[i], out.u[i], out.v[i]);
                for (int q = 0; q < 3; ++q) sum[q] += out.area[j] * k[q];
                total += out.area[j];
            };
            add(i);
            for (const std::int32_t j : ring[i]) add(std::size_t(j));
            for (int q = 0; q < 3; ++q) next[i][q] = sum[q] / total;
        }
        out.ii = std::move(next);
    }
    // The derivative of curvature: per face, C fitted to the change of the
    // vertex forms (in the face's frame) along its edges.
    for (std::size_t fi = 0; fi < nf; ++fi) {
        const Face& face = faces[fi];
        if (!face.ok) continue;
        const auto& f = m.f[fi];
        std::array<std::array<double, 3>, 3> form{};
        for (int j = 0; j < 3; ++j)
            form[j] = form_in(tensor_of(out.ii[f[j]], out.u[f[j]], out.v[f[j]]), m.n[f[j]], face.n, face.t, face.b);
        std::array<std::array<double, 4>, 4> a{};
        std::array<double, 4> rhs{};
        for (int j = 0; j < 3; ++j) {
            const int s = j, e = (j + 1) % 3;
            const glm::dvec3 d = m.p[f[e]] - m.p[f[s]];
            const double x = glm::dot(d, face.t), y = glm::dot(d, face.b);
            const std::array<std::array<double, 4>, 3> rows{{{x, y, 0, 0}, {0, x, y, 0}, {0, 0, x, y}}};
            for (int q = 0; q < 3; ++q) {
                const double r = form[e][q] - form[s][q];
                for (int i = 0; i < 4; ++i) {
                    rhs[i] += rows[q][i] * r;
                    for (int k = 0; k < 4; ++k) a[i][k] += rows[q][i] * rows[q][k];
                }
            }
        }
        std::array<double, 4> c{};
        if (!solve<4>(a, rhs, c)) continue;
        for (int j = 0; j < 3; ++j) {
            const std::int32_t i = f[j];
            const double w = face.corner[j];
            if (!(w > 0.0)) continue;
            // The vertex frame turned onto the face's plane, in (t, b).
            const glm::dvec3 ut = rotate_between(m.n[i], face.n, out.u[i]), vt = rotate_between(m.n[i], face.n, out.v[i]);
            const double p1 = glm::dot(ut, face.t), q1 = glm::dot(ut, face.b);
            const double p2 = glm::dot(vt, face.t), q2 = glm::dot(vt, face.b);
            auto trilinear = [&](double x1, double y1, double x2, double y2, double x3, double y3) {
                // C(a, b, c) for a symmetric C of components c0..c3 (C_ttt, C_ttb, C_tbb, C_bbb).
                return c[0] * x1 * x2 * x3 + c[1] * (x1 * x2 * y3 + x1 * y2 * x3 + y1 * x2 * x3) +
                       c[2] * (x1 * y2 * y3 + y1 * x2 * y3 + y1 * y2 * x3) + c[3] * y1 * y2 * y3;
            };
            out.c[i][0] += w * trilinear(p1, q1, p1, q1, p1, q1);
            out.c[i][1] += w * trilinear(p1, q1, p1, q1, p2, q2);
            out.c[i][2] += w * trilinear(p1, q1, p2, q2, p2, q2);
            out.c[i][3] += w * trilinear(p2, q2, p2, q2, p2, q2);
        }
    }
    for (std::size_t i = 0; i < nv; ++i)
        if (out.area[i] > 0.0)
            for (double& x : out.c[i]) x /= out.area[i];
    return out;
}

struct RtscSegment {
    glm::dvec3 a, b;
    /// Whether the end is where the side seen ends (N.V = 0): on a contour.
    bool a_on_contour = false, b_on_contour = false;
};

/// The suggestive contours rtsc draws of @p m seen from @p eye at
/// @p threshold, on the side seen.
inline std::vector<RtscSegment> rtsc_suggestive(const RtscMesh& m, const RtscCurvature& k, const glm::dvec3& eye,
                                                double threshold) {
    const std::size_t nv = m.p.size();
    const double fs = rtsc_feature_size(m);
    const double thresh = threshold / (fs * fs);
    std::vector<double> kr(nv), num(nv), den(nv);
    for (std::size_t i = 0; i < nv; ++i) {
        const glm::dvec3 view = glm::normalize(eye - m.p[i]);
        const double ndotv = glm::dot(view, m.n[i]);
        const double x = glm::dot(view, k.u[i]), y = glm::dot(view, k.v[i]);
        const auto& f = k.ii[i];
        const auto& c = k.c[i];
        kr[i] = f[0] * x * x + 2.0 * f[1] * x * y + f[2] * y * y;
        const double s2 = x * x + y * y;
        double n = 0.0;
        if (s2 > 0.0) {
            n = (c[0] * x * x * x + 3.0 * c[1] * x * x * y + 3.0 * c[2] * x * y * y + c[3] * y * y * y) / s2;
            const double tau = ((f[2] - f[0]) * x * y + f[1] * (x * x - y * y)) / s2;
            n -= 2.0 * ndotv * tau * tau;
        }
        den[i] = ndotv;
        num[i] = n - thresh * ndotv;
    }
    std::vector<RtscSegment> out;
    for (const auto& f : m.f) {
        // A face where kr is positive somewhere and negative somewhere (as
        // rtsc asks: a zero exactly at vertices alone draws nothing), and
        // the corner whose kr has the sign the other two have not.
        const double k0 = kr[f[0]], k1 = kr[f[1]], k2 = kr[f[2]];
        if (!((k0 > 0.0 || k1 > 0.0 || k2 > 0.0) && (k0 < 0.0 || k1 < 0.0 || k2 < 0.0))) continue;
        int lone = -1;
        for (int j = 0; j < 3; ++j) {
            const double a = kr[f[j]], b = kr[f[(j + 1) % 3]], c = kr[f[(j + 2) % 3]];
            if ((a < 0.0 && b >= 0.0 && c >= 0.0) || (a > 0.0 && b <= 0.0 && c <= 0.0)) lone = j;
        }
        if (lone < 0) continue;
        const std::int32_t v0 = f[lone], v1 = f[(lone + 1) % 3], v2 = f[(lone + 2) % 3];
        if (!(glm::length(glm::cross(m.p[v1] - m.p[v0], m.p[v2] - m.p[v0])) > 0.0)) continue;
        const double w1 = kr[v0] / (kr[v0] - kr[v1]), w2 = kr[v0] / (kr[v0] - kr[v2]);
        const glm::dvec3 p1 = (1.0 - w1) * m.p[v0] + w1 * m.p[v1], p2 = (1.0 - w2) * m.p[v0] + w2 * m.p[v2];
        const double n1 = (1.0 - w1) * num[v0] + w1 * num[v1], n2 = (1.0 - w2) * num[v0] + w2 * num[v2];
        const double d1 = (1.0 - w1) * den[v0] + w1 * den[v1], d2 = (1.0 - w2) * den[v0] + w2 * den[v2];
        // Where both n(s) and d(s), linear from p1 (s = 0) to p2 (s = 1), are positive.
        double lo = 0.0, hi = 1.0;
        bool lo_contour = false, hi_contour = false;
        for (int which = 0; which < 2; ++which) {
            const double g1 = which ? d1 : n1, g2 = which ? d2 : n2;
            if (g1 <= 0.0 && g2 <= 0.0) {
                lo = 1.0, hi = 0.0;
                break;
            }
            if (g1 > 0.0 && g2 > 0.0) continue;
            const double z = g1 / (g1 - g2);
            if (g1 > 0.0 && z < hi) hi = z, hi_contour = which == 1;
            if (g1 <= 0.0 && z > lo) lo = z, lo_contour = which == 1;
        }
        if (hi > lo) out.push_back({(1.0 - lo) * p1 + lo * p2, (1.0 - hi) * p1 + hi * p2, lo_contour, hi_contour});
    }
    return out;
}

/// Nearest-segment queries within a fixed reach, over a uniform grid.
class SegmentIndex {
  public:
    SegmentIndex(const std::vector<RtscSegment>& segments, double reach) : segments_(segments), cell_(reach) {
        for (std::size_t i = 0; i < segments.size(); ++i) {
            const glm::dvec3 lo = glm::min(segments[i].a, segments[i].b), hi = glm::max(segments[i].a, segments[i].b);
            const auto a = key(lo), b = key(hi);
            for (std::int64_t x = a[0]; x <= b[0]; ++x)
                for (std::int64_t y = a[1]; y <= b[1]; ++y)
                    for (std::int64_t z = a[2]; z <= b[2]; ++z) cells_[hash({x, y, z})].push_back(i);
        }
    }
    /// Whether a segment passes within the reach of @p p.
    bool near(const glm::dvec3& p) const {
        const auto k = key(p);
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find(hash({k[0] + dx, k[1] + dy, k[2] + dz}));
                    if (it == cells_.end()) continue;
                    for (const std::size_t i : it->second)
                        if (distance(p, segments_[i]) <= cell_) return true;
                }
        return false;
    }

  private:
    static double distance(const glm::dvec3& p, const RtscSegment& s) { return segment_distance(p, s.a, s.b); }
    std::array<std::int64_t, 3> key(const glm::dvec3& p) const {
        return {std::int64_t(std::floor(p.x / cell_)), std::int64_t(std::floor(p.y / cell_)), std::int64_t(std::floor(p.z / cell_))};
    }
    static std::uint64_t hash(const std::array<std::int64_t, 3>& k) {
        return std::uint64_t(k[0]) * 73856093u ^ std::uint64_t(k[1]) * 19349663u ^ std::uint64_t(k[2]) * 83492791u;
    }
    const std::vector<RtscSegment>& segments_;
    double cell_;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
};

/// The length of @p segments within @p reach of @p other's, and their
/// whole length (sampled every reach / 4).
inline std::pair<double, double> length_near(const std::vector<RtscSegment>& segments, const SegmentIndex& other,
                                             double reach) {
    double near = 0.0, total = 0.0;
    for (const RtscSegment& s : segments) {
        const double len = glm::length(s.b - s.a);
        const int steps = std::max(1, int(std::ceil(len / (0.25 * reach))));
        for (int i = 0; i < steps; ++i) {
            const glm::dvec3 p = s.a + (s.b - s.a) * ((i + 0.5) / steps);
            total += len / steps;
            if (other.near(p)) near += len / steps;
        }
    }
    return {near, total};
}

} // namespace snaxels::test
