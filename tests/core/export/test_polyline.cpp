#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "snaxels/export/detail/polyline.h"

using namespace snaxels;

namespace {

double distance_to(const std::vector<glm::dvec2>& poly, bool closed, const glm::dvec2& p) {
    double best = 1e300;
    const std::size_t segments = closed ? poly.size() : poly.size() - 1;
    for (std::size_t i = 0; i < segments; ++i) best = std::min(best, point_segment(p, poly[i], poly[(i + 1) % poly.size()]));
    return best;
}

} // namespace

// Points on straight stretches go; every point left out lies within the
// tolerance of what is kept; the ends of an open line and the first point
// of a ring stay.
TEST(SimplifyPolyline, DropsOnlyWhatStaysWithinTolerance) {
    // A square outline sampled every 0.3 px along its sides.
    std::vector<glm::dvec2> square;
    for (int side = 0; side < 4; ++side)
        for (int k = 0; k < 100; ++k) {
            const double t = 30.0 * k / 100.0;
            const glm::dvec2 p = side == 0 ? glm::dvec2(t, 0) : side == 1 ? glm::dvec2(30, t) : side == 2 ? glm::dvec2(30 - t, 30) : glm::dvec2(0, 30 - t);
            square.push_back(p + glm::dvec2(10.0, 10.0));
        }
    const std::vector<glm::dvec2> kept = simplify_polyline(square, true, 0.01);
    EXPECT_LE(kept.size(), 6u); // the corners, the first point and the one half way round
    EXPECT_EQ(kept.front(), square.front());
    for (const glm::dvec2& p : square) EXPECT_LE(distance_to(kept, true, p), 0.01);

    // A circle of radius 100 sampled every ~0.6 px: a curve keeps its bends.
    std::vector<glm::dvec2> circle;
    for (int k = 0; k < 1000; ++k) circle.push_back(100.0 * glm::dvec2(std::cos(2 * M_PI * k / 1000), std::sin(2 * M_PI * k / 1000)));
    const std::vector<glm::dvec2> round = simplify_polyline(circle, true, 0.01);
    EXPECT_LT(round.size(), circle.size());
    EXPECT_GT(round.size(), 100u);
    for (const glm::dvec2& p : circle) EXPECT_LE(distance_to(round, true, p), 0.01 + 1e-12);

    // An open zigzag with noise: ends kept, nothing strays.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    std::vector<glm::dvec2> zigzag;
    for (int k = 0; k < 200; ++k) zigzag.push_back({double(k), (k % 20 < 10 ? k % 20 : 20 - k % 20) + u(rng)});
    const std::vector<glm::dvec2> line = simplify_polyline(zigzag, false, 0.25);
    EXPECT_EQ(line.front(), zigzag.front());
    EXPECT_EQ(line.back(), zigzag.back());
    for (const glm::dvec2& p : zigzag) EXPECT_LE(distance_to(line, false, p), 0.25 + 1e-12);

    // Too few points to leave any out.
    const std::vector<glm::dvec2> tri{{0, 0}, {1, 0}, {0, 1}};
    EXPECT_EQ(simplify_polyline(tri, true, 10.0).size(), 3u);
}
