#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <unordered_map>

#include "core/mesh/import.h"
#include "core/parabolic/parabolic.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

constexpr double kPi = 3.141592653589793;

LoadedMesh load(const std::string& spec) {
    return load_mesh(spec.rfind("proc:", 0) == 0 ? spec : test::asset(spec));
}

// ---------------------------------------------------------------------------
// The oracle: where the sign of the Gaussian curvature changes, from the
// face list alone (nothing of core/ but the mesh's positions and faces).
// Angle defect per interior vertex, averaged over its one ring, and the
// zero crossing of that average on every edge whose ends differ in sign.

struct SignChanges {
    std::vector<glm::dvec3> places;
    double mean_edge = 0.0;
};

SignChanges gaussian_sign_changes(const std::vector<glm::dvec3>& positions,
                                  const std::vector<std::array<std::int32_t, 3>>& faces) {
    const std::size_t nv = positions.size();
    std::vector<double> angle_sum(nv, 0.0);
    std::map<std::pair<std::int32_t, std::int32_t>, int> edge_uses;
    for (const auto& f : faces)
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = f[std::size_t(k)], b = f[std::size_t((k + 1) % 3)], c = f[std::size_t((k + 2) % 3)];
            const glm::dvec3 u = glm::normalize(positions[std::size_t(b)] - positions[std::size_t(a)]);
            const glm::dvec3 w = glm::normalize(positions[std::size_t(c)] - positions[std::size_t(a)]);
            angle_sum[std::size_t(a)] += std::acos(std::clamp(glm::dot(u, w), -1.0, 1.0));
            ++edge_uses[{std::min(a, b), std::max(a, b)}];
        }
    std::vector<std::vector<std::int32_t>> ring(nv);
    std::vector<bool> border(nv, false);
    SignChanges out;
    for (const auto& [e, uses] : edge_uses) {
        ring[std::size_t(e.first)].push_back(e.second);
        ring[std::size_t(e.second)].push_back(e.first);
        if (uses != 2) border[std::size_t(e.first)] = border[std::size_t(e.second)] = true;
        out.mean_edge += glm::length(positions[std::size_t(e.first)] - positions[std::size_t(e.second)]);
    }
    out.mean_edge /= double(edge_uses.size());
    std::vector<double> defect(nv, 0.0), smooth(nv, 0.0);
    for (std::size_t v = 0; v < nv; ++v) defect[v] = border[v] ? 0.0 : 2.0 * kPi - angle_sum[v];
    for (std::size_t v = 0; v < nv; ++v) {
        double sum = defect[v];
        for (const std::int32_t w : ring[v]) sum += defect[std::size_t(w)];
        smooth[v] = sum / double(1 + ring[v].size());
    }
    for (const auto& [e, uses] : edge_uses) {
        const double ka = smooth[std::size_t(e.first)], kb = smooth[std::size_t(e.second)];
        if (border[std::size_t(e.first)] || border[std::size_t(e.second)] || !(ka * kb < 0.0)) continue;
        const double t = ka / (ka - kb);
        out.places.push_back((1.0 - t) * positions[std::size_t(e.first)] + t * positions[std::size_t(e.second)]);
    }
    return out;
}

/// Share of @p points within @p radius of one of @p places (a hashed grid).
double share_near(const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& places, double radius) {
    auto key = [&](const glm::dvec3& p) {
        const glm::dvec3 c = glm::floor(p / radius);
        return std::make_tuple(std::int64_t(c.x), std::int64_t(c.y), std::int64_t(c.z));
    };
    std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t>, std::vector<glm::dvec3>> grid;
    for (const glm::dvec3& p : places) grid[key(p)].push_back(p);
    std::size_t near = 0;
    for (const glm::dvec3& p : points) {
        const auto [x, y, z] = key(p);
        bool found = false;
        for (int dx = -1; dx <= 1 && !found; ++dx)
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dz = -1; dz <= 1 && !found; ++dz) {
                    const auto it = grid.find({x + dx, y + dy, z + dz});
                    if (it == grid.end()) continue;
                    for (const glm::dvec3& q : it->second)
                        if (glm::length(q - p) <= radius) {
                            found = true;
                            break;
                        }
                }
        near += found;
    }
    return points.empty() ? 0.0 : double(near) / double(points.size());
}

double total_length(const ParabolicResult& r) {
    double l = 0.0;
    for (const ParabolicCurve& c : r.curves) {
        for (std::size_t k = 1; k < c.points.size(); ++k) l += glm::length(c.points[k] - c.points[k - 1]);
        if (c.closed) l += glm::length(c.points.front() - c.points.back());
    }
    return l;
}

} // namespace

// Done-when 1: the torus's parabolic circles (distance 1 from the axis,
// height +-0.4): the marks lie on them and the curves go all round each.
TEST(Parabolic, TorusMarksLieOnTheParabolicCirclesAndCurvesCoverThem) {
    const LoadedMesh m = load("proc:torus:100000");
    const MeshTopology topo = build_topology(m.mesh);
    const ParabolicResult r = find_parabolic(topo);
    auto off_circle = [](const glm::dvec3& p) {
        const double rho = std::hypot(p.x, p.y);
        return std::min(std::hypot(rho - 1.0, p.z - 0.4), std::hypot(rho - 1.0, p.z + 0.4));
    };
    ASSERT_GT(r.points.size(), 100u);
    std::size_t on = 0;
    for (const ParabolicPoint& p : r.points) on += off_circle(p.where) <= 0.02;
    const double share = double(on) / double(r.points.size());
    // Coverage: the angle each circle's curve segments span, in 0.1-degree bins.
    std::vector<std::vector<bool>> covered(2, std::vector<bool>(3600, false));
    for (const ParabolicCurve& c : r.curves) {
        const std::size_t n = c.points.size(), segments = c.closed ? n : n - 1;
        for (std::size_t k = 0; k < segments; ++k) {
            const glm::dvec3 a = c.points[k], b = c.points[(k + 1) % n];
            if (off_circle(a) > 0.05 || off_circle(b) > 0.05 || a.z * b.z <= 0.0) continue;
            const double ta = std::atan2(a.y, a.x) * 180.0 / kPi;
            const double dt = std::remainder(std::atan2(b.y, b.x) * 180.0 / kPi - ta, 360.0);
            if (std::abs(dt) > 10.0) continue; // not a step along the circle
            const int lo = int(std::floor(std::min(ta, ta + dt) * 10.0)), hi = int(std::ceil(std::max(ta, ta + dt) * 10.0));
            for (int bin = lo; bin < hi; ++bin) covered[a.z > 0.0 ? 0 : 1][std::size_t(((bin % 3600) + 3600) % 3600)] = true;
        }
    }
    double coverage[2];
    for (int c = 0; c < 2; ++c)
        coverage[c] = double(std::count(covered[std::size_t(c)].begin(), covered[std::size_t(c)].end(), true)) / 3600.0;
    std::printf("torus 100K: %zu marks, %.1f%% within 0.02 of the circles; %zu curves, %.3f long (circles 12.566); "
                "coverage %.1f%% (z = 0.4), %.1f%% (z = -0.4); %d directions in %d walks, %.0f ms\n",
                r.points.size(), 100.0 * share, r.curves.size(), total_length(r), 100.0 * coverage[0], 100.0 * coverage[1],
                r.samples, r.walks, r.ms);
    EXPECT_GE(share, 0.95);
    EXPECT_GE(coverage[0], 0.90);
    EXPECT_GE(coverage[1], 0.90);
}

// Done-when 2: marks lie where the sign of the Gaussian curvature changes,
// as the oracle above finds it, within two mean edge lengths.
class ParabolicOnSurfaces : public ::testing::TestWithParam<std::string> {};

TEST_P(ParabolicOnSurfaces, MarksLieWhereGaussianCurvatureChangesSign) {
    const LoadedMesh m = load(GetParam());
    const MeshTopology topo = build_topology(m.mesh);
    const ParabolicResult r = find_parabolic(topo);
    const SignChanges reference = gaussian_sign_changes(topo.positions, topo.face_vertices);
    std::vector<glm::dvec3> marks;
    for (const ParabolicPoint& p : r.points) marks.push_back(p.where);
    const double share = share_near(marks, reference.places, 2.0 * reference.mean_edge);
    std::printf("%s: %zu faces, %zu marks, %.1f%% within 2 mean edge lengths (%.4g) of a Gaussian curvature sign "
                "change (%zu edges change sign); %zu curves, %.4g long; %.0f ms\n",
                GetParam().c_str(), topo.n_faces(), marks.size(), 100.0 * share, 2.0 * reference.mean_edge,
                reference.places.size(), r.curves.size(), total_length(r), r.ms);
    ASSERT_GT(marks.size(), 20u);
    EXPECT_GE(share, 0.90);
    EXPECT_FALSE(r.curves.empty());
}

INSTANTIATE_TEST_SUITE_P(Meshes, ParabolicOnSurfaces,
                         ::testing::Values("proc:nose:40000", "proc:bumpy:40000", "stanford-bunny.obj"),
                         [](const auto& p) {
                             std::string name = p.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });
