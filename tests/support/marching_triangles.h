#pragma once
// The engine's oracle, written from the paper's formulas with nothing of
// the engine's: its own vertex normals (area-weighted face normals from the
// face list), slerp along edges, contour functions, V and L, and edges and
// loops from the face list. Brute-force marching triangles: every edge
// whose end values of f differ in sign (f >= 0 counts as positive) holds
// one crossing, the one nearest the positive end (a fine scan, then
// bisection); crossings are joined through the faces they share and counted
// into loops with a union-find.
//   visual   N.V
//   shadow   min(N.L, N.V)
//   isophote min(N.L - k, N.V)
//   gleam    min(V.R - k, N.V), R = 2(N.L)N - L

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numeric>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace snaxels::test {

/// A view, a light and a contour kind as plain numbers.
struct OracleSetup {
    enum Kind { Visual, Shadow, Isophote, Gleam } kind = Visual;
    double k = 0.0;
    bool orthographic = true;
    glm::dvec3 view_dir{0, 0, 1}, eye{0, 0, 5}; ///< orthographic: where the camera looks; perspective: the eye
    bool point_light = false;
    glm::dvec3 light_dir{0, 0, 1}, light_pos{0.0}; ///< toward the light; or where it is
    /// When above 0: a vertex's f within this of zero counts as outside (a
    /// face seen edge-on on a mesh with sharp edges, as the product defines it).
    double edge_on = 0.0;
};

struct OracleContour {
    std::map<std::pair<std::int32_t, std::int32_t>, glm::dvec3> crossing; ///< (lower, higher vertex) -> point
    std::size_t edges = 0;
    std::size_t loops = 0;
    std::size_t open_loops = 0;
};

/// Area-weighted vertex normals of a triangle list.
inline std::vector<glm::dvec3> oracle_normals(std::span<const glm::dvec3> positions,
                                              std::span<const std::array<std::int32_t, 3>> faces) {
    std::vector<glm::dvec3> n(positions.size(), glm::dvec3(0.0));
    for (const auto& f : faces) {
        const glm::dvec3 c = glm::cross(positions[std::size_t(f[1])] - positions[std::size_t(f[0])],
                                        positions[std::size_t(f[2])] - positions[std::size_t(f[0])]);
        for (const auto v : f) n[std::size_t(v)] += c;
    }
    for (glm::dvec3& v : n) {
        const double len = glm::length(v);
        v = len > 0.0 ? v / len : glm::dvec3(0, 0, 1);
    }
    return n;
}

inline double oracle_f(const OracleSetup& s, const glm::dvec3& p, const glm::dvec3& n) {
    const glm::dvec3 V = s.orthographic ? -glm::normalize(s.view_dir) : glm::normalize(s.eye - p);
    const glm::dvec3 L = s.point_light ? glm::normalize(s.light_pos - p) : glm::normalize(s.light_dir);
    const double nv = glm::dot(n, V), nl = glm::dot(n, L);
    switch (s.kind) {
    case OracleSetup::Visual: return nv;
    case OracleSetup::Shadow: return std::min(nl, nv);
    case OracleSetup::Isophote: return std::min(nl - s.k, nv);
    case OracleSetup::Gleam: return std::min(glm::dot(V, 2.0 * nl * n - L) - s.k, nv);
    }
    return nv;
}

inline glm::dvec3 oracle_slerp(const glm::dvec3& a, const glm::dvec3& b, double t) {
    const double angle = std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0));
    if (angle < 1e-12) return a;
    return (std::sin((1.0 - t) * angle) * a + std::sin(t * angle) * b) / std::sin(angle);
}

/// With @p normals given (a mesh whose animation defines its normals), else
/// the oracle's own.
inline OracleContour marching_triangles(std::span<const glm::dvec3> positions,
                                        std::span<const std::array<std::int32_t, 3>> faces, const OracleSetup& setup,
                                        int scan = 256, std::span<const glm::dvec3> normals = {}) {
    const std::vector<glm::dvec3> normal =
        !normals.empty() ? std::vector<glm::dvec3>(normals.begin(), normals.end()) : oracle_normals(positions, faces);
    std::vector<double> fv(positions.size());
    for (std::size_t v = 0; v < fv.size(); ++v) {
        fv[v] = oracle_f(setup, positions[v], normal[v]);
        if (std::abs(fv[v]) < setup.edge_on) fv[v] = -1e-300;
    }
    OracleContour out;
    std::map<std::pair<std::int32_t, std::int32_t>, std::int32_t> index; // edge -> crossing number, or -1
    for (const auto& f : faces)
        for (int k = 0; k < 3; ++k) {
            const std::int32_t u = f[std::size_t(k)], w = f[std::size_t((k + 1) % 3)];
            index.emplace(std::make_pair(std::min(u, w), std::max(u, w)), -1);
        }
    out.edges = index.size();
    std::int32_t points = 0;
    for (auto& [e, id] : index) {
        std::int32_t a = e.first, b = e.second;
        if ((fv[std::size_t(a)] >= 0.0) == (fv[std::size_t(b)] >= 0.0)) continue;
        if (fv[std::size_t(a)] < 0.0) std::swap(a, b); // a positive, b negative
        auto g = [&](double t) {
            const glm::dvec3 p = (1.0 - t) * positions[std::size_t(a)] + t * positions[std::size_t(b)];
            return oracle_f(setup, p, oracle_slerp(normal[std::size_t(a)], normal[std::size_t(b)], t));
        };
        double lo = 0.0, hi = 1.0;
        for (int i = 1; i < scan; ++i) {
            if (g(double(i) / scan) < 0.0) {
                hi = double(i) / scan;
                break;
            }
            lo = double(i) / scan;
        }
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (lo + hi);
            (g(mid) >= 0.0 ? lo : hi) = mid;
        }
        const double t = 0.5 * (lo + hi);
        out.crossing[e] = (1.0 - t) * positions[std::size_t(a)] + t * positions[std::size_t(b)];
        id = points++;
    }
    std::vector<std::int32_t> parent(static_cast<std::size_t>(points));
    std::iota(parent.begin(), parent.end(), 0);
    auto find = [&](std::int32_t x) {
        while (parent[std::size_t(x)] != x) x = parent[std::size_t(x)] = parent[std::size_t(parent[std::size_t(x)])];
        return x;
    };
    std::vector<int> links(static_cast<std::size_t>(points), 0);
    for (const auto& f : faces) {
        std::int32_t found[3], n = 0;
        for (int k = 0; k < 3; ++k) {
            const std::int32_t u = f[std::size_t(k)], w = f[std::size_t((k + 1) % 3)];
            const std::int32_t id = index.at({std::min(u, w), std::max(u, w)});
            if (id >= 0) found[n++] = id;
        }
        if (n != 2) continue; // a triangle is crossed on zero or two edges
        parent[std::size_t(find(found[0]))] = find(found[1]);
        ++links[std::size_t(found[0])];
        ++links[std::size_t(found[1])];
    }
    std::vector<std::uint8_t> open(static_cast<std::size_t>(points), 0);
    for (std::int32_t i = 0; i < points; ++i)
        if (links[std::size_t(i)] < 2) open[std::size_t(find(i))] = 1;
    for (std::int32_t i = 0; i < points; ++i)
        if (find(i) == i) {
            ++out.loops;
            out.open_loops += open[std::size_t(i)];
        }
    return out;
}

} // namespace snaxels::test
