// Intersection curves (#55) against curves known in closed form (a sphere
// through a plane, two spheres, a tilted cylinder through a plane), against
// a second method written here (every pair of triangles of the Blender
// scenes, read by the tests' own Collada reader, intersected in long double),
// and the cases where surfaces only touch.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/animation/frame_driver.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/mesh/sharp_edges.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/intersections.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/snaxel/tracker.h"
#include "snaxels/visibility/ray_scene.h"
#include "snaxels/visibility/visibility.h"
#include "tests/support/assets.h"
#include "tests/support/scene_reader.h"
#include "tests/support/segment_distance.h"

using namespace snaxels;

namespace {

// ---- Meshes written by the test, one object per `o` group ----

struct TestObject {
    std::string name;
    std::vector<glm::dvec3> positions;
    std::vector<std::array<int, 3>> faces; // counter-clockwise from outside
};

/// An icosphere of @p levels subdivisions.
TestObject icosphere(const std::string& name, glm::dvec3 centre, double r, int levels) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> p{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    std::vector<std::array<int, 3>> f{{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                      {3, 8, 9},  {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (auto& q : p) q = glm::normalize(q);
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto middle = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            const auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            p.push_back(glm::normalize(p[std::size_t(a)] + p[std::size_t(b)]));
            return mid[key] = int(p.size()) - 1;
        };
        std::vector<std::array<int, 3>> next;
        for (const auto& [a, b, c] : f) {
            const int ab = middle(a, b), bc = middle(b, c), ca = middle(c, a);
            next.insert(next.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
        }
        f = std::move(next);
    }
    for (auto& q : p) q = centre + r * q;
    return {name, p, f};
}

/// A square grid of n x n cells in the plane y = @p y, facing +y.
TestObject grid(const std::string& name, double half, int n, double y) {
    TestObject o{name, {}, {}};
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) o.positions.push_back({-half + 2 * half * i / n, y, -half + 2 * half * j / n});
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
            o.faces.push_back({a, b, d});
            o.faces.push_back({a, d, c});
        }
    return o;
}

/// A closed cylinder round @p axis (unit) through @p centre.
TestObject cylinder(const std::string& name, glm::dvec3 centre, glm::dvec3 axis, double r, double length, int segments, int rings) {
    TestObject o{name, {}, {}};
    const glm::dvec3 u = glm::normalize(glm::cross(axis, std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 v = glm::cross(axis, u);
    for (int k = 0; k <= rings; ++k)
        for (int s = 0; s < segments; ++s) {
            const double a = 2 * M_PI * s / segments;
            o.positions.push_back(centre + (-0.5 * length + length * k / rings) * axis + r * (std::cos(a) * u + std::sin(a) * v));
        }
    for (int k = 0; k < rings; ++k)
        for (int s = 0; s < segments; ++s) {
            const int a = k * segments + s, b = k * segments + (s + 1) % segments, c = a + segments, d = b + segments;
            o.faces.push_back({a, b, d});
            o.faces.push_back({a, d, c});
        }
    const int bottom = int(o.positions.size()), top = bottom + 1;
    o.positions.push_back(centre - 0.5 * length * axis);
    o.positions.push_back(centre + 0.5 * length * axis);
    for (int s = 0; s < segments; ++s) {
        o.faces.push_back({bottom, (s + 1) % segments, s});
        o.faces.push_back({top, rings * segments + s, rings * segments + (s + 1) % segments});
    }
    return o;
}

/// An axis-aligned box.
TestObject box(const std::string& name, glm::dvec3 lo, glm::dvec3 hi) {
    TestObject o{name, {}, {}};
    for (int i = 0; i < 8; ++i) o.positions.push_back({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
    o.faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
               {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return o;
}

std::string write_scene(const std::string& file, const std::vector<TestObject>& objects) {
    const std::string path = (std::filesystem::temp_directory_path() / file).string();
    std::FILE* out = std::fopen(path.c_str(), "w");
    int base = 1;
    for (const TestObject& o : objects) {
        std::fprintf(out, "o %s\n", o.name.c_str());
        for (const glm::dvec3& p : o.positions) std::fprintf(out, "v %.17g %.17g %.17g\n", p.x, p.y, p.z);
        for (const auto& f : o.faces) std::fprintf(out, "f %d %d %d\n", f[0] + base, f[1] + base, f[2] + base);
        base += int(o.positions.size());
    }
    std::fclose(out);
    return path;
}

/// The product's intersection lines of a file, as the engine draws them.
struct ProductLines {
    LoadedMesh loaded;
    std::optional<LoadedMesh> split;
    MeshTopology topo;
    SnaxelEngine engine;
    ContourResult lines;
    explicit ProductLines(const std::string& file, const SurfaceOptions& surface = {})
        : loaded(import_mesh(file)), topo(engine_topology(with_sharp_edges(loaded, surface, split))), engine(topo),
          lines(engine.compute({ContourKind::Intersection}, Camera{}, Light{})) {}
    /// Each loop's points in order (closed loops repeat their first).
    std::vector<std::vector<glm::dvec3>> polylines() const {
        std::vector<std::vector<glm::dvec3>> out;
        for (const FrontLoop& loop : lines.fronts.loops) {
            std::vector<glm::dvec3> pts;
            lines.fronts.for_each_in_loop(loop, [&](std::int32_t s) { pts.push_back(engine.position(lines.fronts.snaxels[std::size_t(s)])); });
            if (loop.closed) pts.push_back(pts.front());
            out.push_back(std::move(pts));
        }
        return out;
    }
};

struct CurveFit {
    double within = 0.0;  ///< share of the product's length within tolerance of the truth
    double covered = 0.0; ///< share of the truth's samples within tolerance of the product
};

/// How well polylines match a true curve given by its distance function
/// and samples along it.
CurveFit fit(const std::vector<std::vector<glm::dvec3>>& lines, const std::function<double(const glm::dvec3&)>& distance,
             const std::vector<glm::dvec3>& truth_samples, double tolerance) {
    double total = 0.0, near = 0.0;
    for (const auto& pl : lines)
        for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
            const double len = glm::length(pl[i + 1] - pl[i]);
            // The segment is near where its ends and middle are.
            const bool ok = distance(pl[i]) <= tolerance && distance(pl[i + 1]) <= tolerance &&
                            distance(0.5 * (pl[i] + pl[i + 1])) <= tolerance;
            total += len;
            near += ok ? len : 0.0;
        }
    std::size_t covered = 0;
    for (const glm::dvec3& q : truth_samples) {
        double best = 1e300;
        for (const auto& pl : lines)
            for (std::size_t i = 0; i + 1 < pl.size(); ++i) best = std::min(best, test::segment_distance(q, pl[i], pl[i + 1]));
        covered += best <= tolerance;
    }
    return {total > 0.0 ? near / total : 0.0, truth_samples.empty() ? 0.0 : double(covered) / double(truth_samples.size())};
}

double diagonal(const MeshTopology& topo) { return 2.0 * bounding_radius(topo); }

/// A circle's distance function and samples.
std::pair<std::function<double(const glm::dvec3&)>, std::vector<glm::dvec3>> circle(glm::dvec3 c, glm::dvec3 n, double rho) {
    n = glm::normalize(n);
    auto distance = [=](const glm::dvec3& p) {
        const double h = glm::dot(p - c, n);
        const double radial = glm::length((p - c) - h * n);
        return std::hypot(h, radial - rho);
    };
    const glm::dvec3 u = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
    const glm::dvec3 v = glm::cross(n, u);
    std::vector<glm::dvec3> samples;
    for (int k = 0; k < 720; ++k) {
        const double a = 2 * M_PI * k / 720;
        samples.push_back(c + rho * (std::cos(a) * u + std::sin(a) * v));
    }
    return {distance, samples};
}

void expect_fit(const CurveFit& f, const std::string& what) {
    std::printf("%s: %.2f%% of the lines' length within tolerance, %.2f%% of the true curve covered\n", what.c_str(),
                100 * f.within, 100 * f.covered);
    EXPECT_GE(f.within, 0.98) << what;
    EXPECT_GE(f.covered, 0.95) << what;
}

} // namespace

// Done-when 2: on closed-form pairs, 98% of the lines' length lies within
// 0.2% of the scene's diagonal of the true curve, covering 95% of it.
TEST(Intersections, SphereThroughAPlaneMeetsItInACircle) {
    const double h = 0.3;
    const ProductLines p(write_scene("meet-sphere-plane.obj", {icosphere("Ball", {0, h, 0}, 1.0, 5), grid("Floor", 2.0, 40, 0.0)}));
    const auto [distance, samples] = circle({0, 0, 0}, {0, 1, 0}, std::sqrt(1.0 - h * h));
    ASSERT_EQ(p.lines.fronts.loops.size(), 1u);
    EXPECT_TRUE(p.lines.fronts.loops[0].closed);
    expect_fit(fit(p.polylines(), distance, samples, 0.002 * diagonal(p.topo)), "sphere and plane");
}

TEST(Intersections, TwoSpheresMeetInACircle) {
    const double d = 1.2, r1 = 1.0, r2 = 0.8;
    const ProductLines p(write_scene("meet-two-spheres.obj", {icosphere("A", {0, 0, 0}, r1, 5), icosphere("B", {d, 0, 0}, r2, 5)}));
    const double x = (d * d + r1 * r1 - r2 * r2) / (2 * d);
    const auto [distance, samples] = circle({x, 0, 0}, {1, 0, 0}, std::sqrt(r1 * r1 - x * x));
    ASSERT_EQ(p.lines.fronts.loops.size(), 1u);
    EXPECT_TRUE(p.lines.fronts.loops[0].closed);
    expect_fit(fit(p.polylines(), distance, samples, 0.002 * diagonal(p.topo)), "two spheres");
}

TEST(Intersections, TiltedCylinderThroughAPlaneMeetsItInAnEllipse) {
    const glm::dvec3 axis = glm::normalize(glm::dvec3(std::sin(0.5), std::cos(0.5), 0.0)); // 29 degrees off the normal
    const double r = 0.4;
    const ProductLines p(write_scene("meet-cylinder-plane.obj", {cylinder("Post", {0.1, 0.2, 0.0}, axis, r, 2.0, 128, 24), grid("Floor", 2.0, 30, 0.0)}));
    // The true curve: where the plane y = 0 meets the exact cylinder.
    auto distance = [&](const glm::dvec3& q) {
        const glm::dvec3 rel = q - glm::dvec3(0.1, 0.2, 0.0);
        const double radial = glm::length(rel - glm::dot(rel, axis) * axis);
        return std::hypot(q.y, (radial - r) / 1.0);
    };
    std::vector<glm::dvec3> samples;
    const glm::dvec3 u = glm::dvec3(0, 0, 1), v = glm::cross(axis, u);
    for (int k = 0; k < 720; ++k) {
        const double a = 2 * M_PI * k / 720;
        const glm::dvec3 on = glm::dvec3(0.1, 0.2, 0.0) + r * (std::cos(a) * u + std::sin(a) * v);
        samples.push_back(on - (on.y / axis.y) * axis);
    }
    ASSERT_EQ(p.lines.fronts.loops.size(), 1u);
    expect_fit(fit(p.polylines(), distance, samples, 0.002 * diagonal(p.topo)), "tilted cylinder and plane");
}

// Surfaces that only touch meet in no line: a box standing on a floor (its
// bottom in the floor's plane, its sides' edges on it), a box whose corner
// touches a face, and two boxes side by side sharing a face's plane.
TEST(Intersections, SurfacesThatOnlyTouchMeetInNoLine) {
    const ProductLines standing(write_scene("meet-standing.obj", {box("Box", {-0.5, 0, -0.5}, {0.5, 1, 0.5}), grid("Floor", 2.0, 8, 0.0)}));
    EXPECT_EQ(standing.lines.fronts.snaxels.size(), 0u) << "a box standing on a floor";
    const ProductLines side(write_scene("meet-side.obj", {box("A", {0, 0, 0}, {1, 1, 1}), box("B", {1, 0.2, 0.2}, {2, 0.8, 0.8})}));
    EXPECT_EQ(side.lines.fronts.snaxels.size(), 0u) << "two boxes face to face";
    // An octahedron standing on its tip, which lies on a vertex of the
    // floor's grid, and one on a tip inside a floor face.
    for (const double x : {0.0, 0.13}) {
        TestObject tip{"Tip", {{x, 0, 0}, {x + 0.5, 0.5, 0}, {x, 0.5, 0.5}, {x - 0.5, 0.5, 0}, {x, 0.5, -0.5}, {x, 1, 0}}, {}};
        tip.faces = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3}, {0, 1, 4}, {5, 1, 2}, {5, 2, 3}, {5, 3, 4}, {5, 4, 1}};
        const ProductLines touching(write_scene("meet-tip.obj", {tip, grid("Floor", 2.0, 8, 0.0)}));
        EXPECT_EQ(touching.lines.fronts.snaxels.size(), 0u) << "a tip touching a floor at x = " << x;
    }
}

// A vertex exactly on the other surface, and edges lying in its plane: a
// sphere whose equator's vertices lie in a plane that cuts through it (the
// tests' UV sphere: rings of vertices at fixed heights, the middle one at
// the plane's height) still meets it in one closed loop.
TEST(Intersections, AnEquatorLyingInThePlaneStillClosesItsLoop) {
    TestObject ball{"Ball", {}, {}};
    const int seg = 48, rings = 24;
    ball.positions.push_back({0, 1, 0});
    for (int k = 1; k < rings; ++k)
        for (int s = 0; s < seg; ++s) {
            const double th = M_PI * k / rings, ph = 2 * M_PI * s / seg;
            ball.positions.push_back({std::sin(th) * std::cos(ph), std::cos(th), -std::sin(th) * std::sin(ph)});
        }
    ball.positions.push_back({0, -1, 0});
    const int south = int(ball.positions.size()) - 1;
    for (int s = 0; s < seg; ++s) ball.faces.push_back({0, 1 + s, 1 + (s + 1) % seg});
    for (int k = 1; k + 1 < rings; ++k)
        for (int s = 0; s < seg; ++s) {
            const int a = 1 + (k - 1) * seg + s, b = 1 + (k - 1) * seg + (s + 1) % seg, c = a + seg, d = b + seg;
            ball.faces.push_back({a, c, d});
            ball.faces.push_back({a, d, b});
        }
    for (int s = 0; s < seg; ++s) ball.faces.push_back({south, 1 + (rings - 2) * seg + (s + 1) % seg, 1 + (rings - 2) * seg + s});
    // The slab's top at y = 0: the equator (ring 12, at cos(pi/2)) lies in
    // it up to rounding; set it exactly there.
    for (glm::dvec3& q : ball.positions)
        if (std::abs(q.y) < 1e-9) q.y = 0.0;
    const ProductLines p(write_scene("meet-equator.obj", {ball, box("Slab", {-2, -1, -2}, {2, 0, 2})}));
    std::size_t closed = 0;
    for (const FrontLoop& loop : p.lines.fronts.loops) closed += loop.closed;
    EXPECT_EQ(p.lines.fronts.loops.size(), 1u);
    EXPECT_EQ(closed, p.lines.fronts.loops.size());
    for (const auto& pl : p.polylines()) {
        double lo = 1e9, hi = -1e9, len = 0;
        for (std::size_t i = 0; i < pl.size(); ++i) lo = std::min(lo, pl[i].y), hi = std::max(hi, pl[i].y), len += i ? glm::length(pl[i] - pl[i - 1]) : 0.0;
        std::printf("loop of %zu points, length %g, y %g to %g, ends %g %g %g and %g %g %g\n", pl.size(), len, lo, hi,
                    pl.front().x, pl.front().y, pl.front().z, pl.back().x, pl.back().y, pl.back().z);
    }
    const auto [distance, samples] = circle({0, 0, 0}, {0, 1, 0}, 1.0);
    expect_fit(fit(p.polylines(), distance, samples, 0.002 * diagonal(p.topo)), "equator in the plane");
}

// One object through itself: two boxes joined into one mesh, a bar through
// a cube's two opposite faces: two square loops. Shaded smooth (the bar's
// corners lie on the diagonals of the cube's faces: a degenerate meeting),
// and split along their edges, as a mesh without normals is by default
// (the bar off the diagonals).
TEST(Intersections, AnObjectThroughItselfMeetsItself) {
    struct Case {
        glm::dvec3 lo, hi;
        double sharp_angle;
    };
    for (const Case& c : {Case{{0.3, 0.3, -0.5}, {0.7, 0.7, 1.5}, 180.0}, Case{{0.3, 0.22, -0.5}, {0.71, 0.63, 1.5}, kFileNormals}}) {
        TestObject a = box("Cross", {0, 0, 0}, {1, 1, 1});
        const TestObject b = box("", c.lo, c.hi);
        const int base = int(a.positions.size());
        a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
        for (auto f : b.faces) a.faces.push_back({f[0] + base, f[1] + base, f[2] + base});
        SurfaceOptions surface;
        surface.sharp_angle = c.sharp_angle;
        const ProductLines p(write_scene("meet-self.obj", {a}), surface);
        EXPECT_EQ(p.split.has_value(), c.sharp_angle < 180.0);
        ASSERT_EQ(p.lines.fronts.loops.size(), 2u) << c.sharp_angle;
        for (const FrontLoop& loop : p.lines.fronts.loops) EXPECT_TRUE(loop.closed) << c.sharp_angle;
        for (const auto& pl : p.polylines())
            for (const glm::dvec3& q : pl) {
                EXPECT_TRUE(std::abs(q.z) < 1e-6 || std::abs(q.z - 1.0) < 1e-6) << q.z;
                EXPECT_TRUE(std::abs(q.x - c.lo.x) < 1e-6 || std::abs(q.x - c.hi.x) < 1e-6 || std::abs(q.y - c.lo.y) < 1e-6 ||
                            std::abs(q.y - c.hi.y) < 1e-6)
                    << q.x << " " << q.y << " " << q.z;
            }
    }
}

namespace {

/// The second method, sharing nothing with the product: every pair of
/// triangles of the file (the tests' own Collada reader) whose boxes
/// overlap, of two objects or of one object without a shared corner,
/// intersected in long double: each triangle's crossing of the other's
/// plane (where its corners lie strictly on both sides) as a segment on
/// the planes' common line, the two segments overlapped along it.
std::vector<std::array<glm::dvec3, 2>> reference_segments(const ref::SceneMesh& scene) {
    using LV = std::array<long double, 3>;
    auto lv = [](const glm::dvec3& p) { return LV{p.x, p.y, p.z}; };
    auto sub = [](const LV& a, const LV& b) { return LV{a[0] - b[0], a[1] - b[1], a[2] - b[2]}; };
    auto cross = [](const LV& a, const LV& b) { return LV{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; };
    auto dot = [](const LV& a, const LV& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    const std::size_t n = scene.faces.size();
    std::vector<std::array<glm::dvec3, 2>> box(n);
    for (std::size_t f = 0; f < n; ++f) {
        box[f] = {glm::dvec3(1e300), glm::dvec3(-1e300)};
        for (const int v : scene.faces[f]) {
            box[f][0] = glm::min(box[f][0], scene.positions[std::size_t(v)]);
            box[f][1] = glm::max(box[f][1], scene.positions[std::size_t(v)]);
        }
    }
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return box[a][0].x < box[b][0].x; });
    double scale = 0.0;
    for (const glm::dvec3& p : scene.positions) scale = std::max(scale, glm::length(p));
    const long double eps = 1e-12L * scale;
    // The piece of triangle a's plane crossing by triangle t: the two points
    // where t's edges cross plane (n, d0); false when t does not strictly
    // straddle it.
    auto crossing = [&](const std::array<int, 3>& t, const LV& normal, const LV& origin, std::array<LV, 2>& out) {
        std::array<long double, 3> d{};
        std::array<LV, 3> p{};
        for (int k = 0; k < 3; ++k) {
            p[std::size_t(k)] = lv(scene.positions[std::size_t(t[std::size_t(k)])]);
            d[std::size_t(k)] = dot(sub(p[std::size_t(k)], origin), normal);
        }
        const long double len = std::sqrt(dot(normal, normal));
        bool above = false, below = false;
        for (const long double v : d) above |= v > eps * len, below |= v < -eps * len;
        if (!above || !below) return false;
        int found = 0;
        for (int k = 0; k < 3 && found < 2; ++k) {
            const std::size_t i = std::size_t(k), j = std::size_t((k + 1) % 3);
            if ((d[i] > 0) == (d[j] > 0)) continue;
            const long double u = d[i] / (d[i] - d[j]);
            out[std::size_t(found++)] = {p[i][0] + u * (p[j][0] - p[i][0]), p[i][1] + u * (p[j][1] - p[i][1]), p[i][2] + u * (p[j][2] - p[i][2])};
        }
        return found == 2;
    };
    // An edge lying in the other triangle's plane is on the curve where the
    // surface passes through that plane there: its two faces' third
    // corners lie strictly on either side (a ball's equator in a tabletop
    // that its lower half sinks into). Its part inside the triangle counts.
    std::map<std::pair<int, int>, std::vector<int>> third; // edge -> the faces' third corners
    for (const auto& f : scene.faces)
        for (int k = 0; k < 3; ++k) {
            const int u = f[std::size_t(k)], w = f[std::size_t((k + 1) % 3)];
            third[{std::min(u, w), std::max(u, w)}].push_back(f[std::size_t((k + 2) % 3)]);
        }
    auto edge_in_plane = [&](const std::array<int, 3>& t, const std::array<int, 3>& other, const LV& normal, const LV& origin,
                             std::vector<std::array<glm::dvec3, 2>>& into) {
        const long double len = std::sqrt(dot(normal, normal));
        auto dist = [&](int v) { return dot(sub(lv(scene.positions[std::size_t(v)]), origin), normal) / len; };
        for (int k = 0; k < 3; ++k) {
            const int u = t[std::size_t(k)], w = t[std::size_t((k + 1) % 3)];
            if (std::abs(dist(u)) > eps || std::abs(dist(w)) > eps) continue;
            const auto& thirds = third[{std::min(u, w), std::max(u, w)}];
            if (thirds.size() != 2 || !((dist(thirds[0]) > eps && dist(thirds[1]) < -eps) || (dist(thirds[0]) < -eps && dist(thirds[1]) > eps)))
                continue;
            if (std::min(u, w) != u) continue; // each edge once (from the face where it runs up)
            // The edge clipped to the other triangle, in its plane.
            const LV p0 = lv(scene.positions[std::size_t(u)]), p1 = lv(scene.positions[std::size_t(w)]);
            long double lo = 0, hi = 1;
            for (int j = 0; j < 3 && lo < hi; ++j) {
                const LV a = lv(scene.positions[std::size_t(other[std::size_t(j)])]), b = lv(scene.positions[std::size_t(other[std::size_t((j + 1) % 3)])]);
                const LV inward = cross(normal, sub(b, a)); // toward the triangle's inside
                const long double s0 = dot(sub(p0, a), inward), s1 = dot(sub(p1, a), inward);
                if (s0 < 0 && s1 < 0) lo = 1, hi = 0;
                else if (s0 < 0) lo = std::max(lo, s0 / (s0 - s1));
                else if (s1 < 0) hi = std::min(hi, s0 / (s0 - s1));
            }
            if (lo >= hi) continue;
            auto at = [&](long double u2) { return glm::dvec3(double(p0[0] + u2 * (p1[0] - p0[0])), double(p0[1] + u2 * (p1[1] - p0[1])), double(p0[2] + u2 * (p1[2] - p0[2]))); };
            into.push_back({at(lo), at(hi)});
        }
    };
    std::vector<std::array<glm::dvec3, 2>> out;
    for (std::size_t ia = 0; ia < n; ++ia) {
        const std::size_t a = order[ia];
        for (std::size_t ib = ia + 1; ib < n && box[order[ib]][0].x <= box[a][1].x; ++ib) {
            const std::size_t b = order[ib];
            if (box[b][0].y > box[a][1].y || box[a][0].y > box[b][1].y || box[b][0].z > box[a][1].z || box[a][0].z > box[b][1].z) continue;
            bool shared = false;
            for (const int u : scene.faces[a])
                for (const int w : scene.faces[b]) shared |= u == w;
            if (shared) continue;
            const auto& fa = scene.faces[a];
            const auto& fb = scene.faces[b];
            const LV a0 = lv(scene.positions[std::size_t(fa[0])]), b0 = lv(scene.positions[std::size_t(fb[0])]);
            const LV na = cross(sub(lv(scene.positions[std::size_t(fa[1])]), a0), sub(lv(scene.positions[std::size_t(fa[2])]), a0));
            const LV nb = cross(sub(lv(scene.positions[std::size_t(fb[1])]), b0), sub(lv(scene.positions[std::size_t(fb[2])]), b0));
            edge_in_plane(fa, fb, nb, b0, out);
            edge_in_plane(fb, fa, na, a0, out);
            std::array<LV, 2> sa{}, sb{};
            if (!crossing(fb, na, a0, sb) || !crossing(fa, nb, b0, sa)) continue;
            const LV dir = cross(na, nb);
            long double a_lo = dot(sa[0], dir), a_hi = dot(sa[1], dir), b_lo = dot(sb[0], dir), b_hi = dot(sb[1], dir);
            if (a_lo > a_hi) std::swap(a_lo, a_hi), std::swap(sa[0], sa[1]);
            if (b_lo > b_hi) std::swap(b_lo, b_hi), std::swap(sb[0], sb[1]);
            const LV& from = a_lo > b_lo ? sa[0] : sb[0];
            const LV& to = a_hi < b_hi ? sa[1] : sb[1];
            if (std::max(a_lo, b_lo) >= std::min(a_hi, b_hi)) continue;
            out.push_back({glm::dvec3(double(from[0]), double(from[1]), double(from[2])), glm::dvec3(double(to[0]), double(to[1]), double(to[2]))});
        }
    }
    return out;
}

} // namespace

// Done-when 2 on general scenes: the Blender scenes' intersection lines
// against the second method above, the same figures as the closed forms.
TEST(Intersections, AgreeWithASecondMethodOnBlenderScenes) {
    for (const std::string name : {"meet/still-life.dae", "meet/sunk.dae", "meet/crossing.dae"}) {
        const std::string file = test::asset(name);
        const ref::SceneMesh scene = ref::read_collada(file);
        const std::vector<std::array<glm::dvec3, 2>> truth = reference_segments(scene);
        ASSERT_FALSE(truth.empty()) << name;
        const ProductLines p(file);
        const double tolerance = 0.002 * diagonal(p.topo);
        auto distance = [&](const glm::dvec3& q) {
            double best = 1e300;
            for (const auto& s : truth) best = std::min(best, test::segment_distance(q, s[0], s[1]));
            return best;
        };
        std::vector<glm::dvec3> samples; // along the reference's segments, every 1/10 of the tolerance
        for (const auto& s : truth) {
            const int steps = std::max(1, int(std::ceil(glm::length(s[1] - s[0]) / (0.1 * tolerance))));
            for (int k = 0; k < steps; ++k) samples.push_back(glm::mix(s[0], s[1], (k + 0.5) / steps));
        }
 for (const auto& pl : p.polylines()) {
            const CurveFit one = fit({pl}, distance, {}, tolerance);
            if (one.within < 0.98)
                std::printf("  a loop of %zu points at %.3f %.3f %.3f: %.1f%% within\n", pl.size(), pl[0].x, pl[0].y, pl[0].z, 100 * one.within);
        }
 const CurveFit tight = fit(p.polylines(), distance, samples, 1e-5 * diagonal(p.topo));
        std::printf("%s at 0.001%% of the diagonal: %.2f%% within, %.2f%% covered\n", name.c_str(), 100 * tight.within, 100 * tight.covered);
        expect_fit(fit(p.polylines(), distance, samples, tolerance), name + " against the second method (" + std::to_string(truth.size()) + " segments)");
    }
}

// Done-when 4: as objects pass through each other (a ball entering a box
// through its wall, running half sunk in its top, leaving through the far
// wall), the tracked intersection lines and visual contour equal those
// found from scratch in every frame's pose, and the intersection loop is
// born, carried and ends as one sequence while it lasts.
TEST(Intersections, TrackedThroughAClipAsFromScratch) {
    const std::string path = test::asset("meet/rolling.gltf");
    const LoadedMesh mesh = import_mesh(path);
    const MeshTopology rest = engine_topology(mesh);
    AnimationSpec spec;
    spec.kind = AnimationSpec::Kind::Clip;
    spec.frames = 97;
    spec.fps = 24.0;
    Camera camera;
    camera.view_dir = glm::normalize(glm::dvec3(0.4, -0.6, -1.0));
    FrameDriver driver(spec, mesh, rest, camera, default_light(camera), glm::dvec3(0.0), path);
    ASSERT_TRUE(driver.mesh_moves());
    EngineOptions options;
    options.check_invariants = false;
    ContourTracker meeting(rest, {ContourKind::Intersection}, options), visual(rest, ContourSpec{}, options);
    std::map<std::uint64_t, int> frames_of_sequence;
    std::size_t frames_with_lines = 0;
    for (int k = 0; k < spec.frames; ++k) {
        const FramePose pose = driver.pose(k);
        const SnaxelEngine engine(pose.mesh);
        for (ContourTracker* tracker : {&meeting, &visual}) {
            const TrackedFrame& tracked = tracker->step(pose.mesh, pose.camera, pose.light);
            const ContourResult fresh = engine.compute(tracked.contour.spec, pose.camera, pose.light, options);
            ASSERT_EQ(tracked.contour.fronts.snaxels.size(), fresh.fronts.snaxels.size()) << "frame " << k << " " << tracked.contour.spec.label();
            ASSERT_EQ(tracked.contour.fronts.loops.size(), fresh.fronts.loops.size()) << "frame " << k;
            for (std::size_t s = 0; s < fresh.fronts.snaxels.size(); ++s) {
                EXPECT_EQ(tracked.contour.fronts.snaxels[s].edge, fresh.fronts.snaxels[s].edge) << "frame " << k;
                EXPECT_NEAR(tracked.contour.fronts.snaxels[s].t, fresh.fronts.snaxels[s].t, 1e-9) << "frame " << k;
            }
        }
        frames_with_lines += !meeting.current().contour.fronts.loops.empty();
        for (const std::uint64_t sequence : meeting.current().loop_sequence) ++frames_of_sequence[sequence];
    }
    int longest = 0;
    for (const auto& [sequence, frames] : frames_of_sequence) longest = std::max(longest, frames);
    std::printf("rolling: intersection lines in %zu of %d frames, %zu loop sequences, the longest %d frames\n", frames_with_lines,
                spec.frames, frames_of_sequence.size(), longest);
    EXPECT_GT(frames_with_lines, 80u);
    EXPECT_GE(longest, 60);
}
