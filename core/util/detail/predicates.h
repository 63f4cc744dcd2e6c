#pragma once
/// The sign of the orientation of four points, exact: a filter in double
/// arithmetic decides when its result is far enough from zero, and
/// otherwise the 4 x 4 determinant is summed without rounding as an
/// expansion (a sum of doubles whose parts do not overlap, after Shewchuk,
/// "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
/// Predicates", 1997). Intersection curves decide from these signs which
/// edges pierce which faces, so two faces that share an edge agree on it.

#include <array>
#include <cmath>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels::detail {

/// a + b = x + y exactly, x the rounded sum.
inline void two_sum(double a, double b, double& x, double& y) {
    x = a + b;
    const double bv = x - a, av = x - bv;
    y = (a - av) + (b - bv);
}

/// a * b = x + y exactly (fused multiply-add gives the rounding error).
inline void two_product(double a, double b, double& x, double& y) {
    x = a * b;
    y = std::fma(a, b, -x);
}

/// An expansion: doubles whose exact sum is the value, in increasing
/// magnitude, none overlapping; zeros left out.
class Expansion {
  public:
    /// Adds @p b exactly (Shewchuk's Grow-Expansion with zero elimination).
    void add(double b) {
        std::size_t out = 0;
        double q = b;
        for (const double e : parts_) {
            double sum, err;
            two_sum(q, e, sum, err);
            q = sum;
            if (err != 0.0) parts_[out++] = err;
        }
        parts_.resize(out);
        if (q != 0.0) parts_.push_back(q);
    }
    /// Adds the product a * b * c exactly (as four doubles) times @p sign.
    void add_product(double a, double b, double c, double sign) {
        double p, pe;
        two_product(a, b, p, pe);
        double x, xe, y, ye;
        two_product(p, c, x, xe);
        two_product(pe, c, y, ye);
        add(sign * ye);
        add(sign * y);
        add(sign * xe);
        add(sign * x);
    }
    /// -1, 0 or 1: the sign of the largest part.
    int sign() const { return parts_.empty() ? 0 : parts_.back() > 0.0 ? 1 : -1; }

  private:
    std::vector<double> parts_;
};

/// The sign of det[b - a, c - a, d - a] computed exactly from the rows
/// (x, y, z, 1) of the four points: positive when d lies on the side of
/// the plane (a, b, c) its normal (b - a) x (c - a) points to.
inline int orient3d_exact(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    // det of the rows (p, 1) for p = a, b, c, d equals -det[b-a, c-a, d-a];
    // its 24 permutation terms each hold one column-4 entry (1) and three
    // coordinates.
    const std::array<const glm::dvec3*, 4> row{&a, &b, &c, &d};
    Expansion sum;
    // Every permutation of the columns, its parity counted by inversions.
    for (int p0 = 0; p0 < 4; ++p0)
        for (int p1 = 0; p1 < 4; ++p1)
            for (int p2 = 0; p2 < 4; ++p2) {
                const int p3 = 6 - p0 - p1 - p2;
                if (p0 == p1 || p0 == p2 || p1 == p2 || p3 < 0 || p3 > 3 || p3 == p0 || p3 == p1 || p3 == p2) continue;
                const std::array<int, 4> perm{p0, p1, p2, p3};
                int inversions = 0;
                for (int i = 0; i < 4; ++i)
                    for (int j = i + 1; j < 4; ++j) inversions += perm[i] > perm[j];
                const double s = inversions % 2 ? -1.0 : 1.0;
                // Row i takes column perm[i]; the row taking column 3 gives 1.
                double f[3];
                int n = 0;
                for (int i = 0; i < 4; ++i)
                    if (perm[i] != 3) f[n++] = (*row[i])[perm[i]];
                sum.add_product(f[0], f[1], f[2], -s);
            }
    return sum.sign();
}

/// The same sign, filtered: the double determinant when its error bound
/// (a multiple of the permanent) shows its sign is right, else exact.
inline int orient3d(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
    const glm::dvec3 u = b - a, v = c - a, w = d - a;
    const double det = u.x * (v.y * w.z - v.z * w.y) + u.y * (v.z * w.x - v.x * w.z) + u.z * (v.x * w.y - v.y * w.x);
    const double permanent = std::abs(u.x) * (std::abs(v.y * w.z) + std::abs(v.z * w.y)) +
                             std::abs(u.y) * (std::abs(v.z * w.x) + std::abs(v.x * w.z)) +
                             std::abs(u.z) * (std::abs(v.x * w.y) + std::abs(v.y * w.x));
    // Shewchuk's first bound is about 7.8e-16 of the permanent for
    // differences taken exactly; ours are rounded too, so a wider margin.
    const double bound = 1e-14 * permanent;
    if (det > bound) return 1;
    if (det < -bound) return -1;
    return orient3d_exact(a, b, c, d);
}

} // namespace snaxels::detail
