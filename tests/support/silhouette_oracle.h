#pragma once
// An oracle for outlines and hidden lines: the faceted mesh's visible
// silhouette edges (a face turned to the viewer beside one turned away,
// visible by the oracle's own z-buffer), against which the product's
// visible visual contour is scored (within 2 px both ways, on a 512-pixel
// orthographic view fitted to the mesh), and the product's QI against the
// same z-buffer where it is clear. The oracle works on plain triangles
// (tests/support/scene_reader.h's SceneMesh) and shares nothing with the
// product but the view direction; score_view runs the product's side.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "snaxels/snaxel/snaxel_engine.h"
#include "snaxels/visibility/ray_scene.h"
#include "snaxels/visibility/visibility.h"
#include "tests/support/reference_raster.h"
#include "tests/support/scene_reader.h"

namespace snaxels::test::silhouette {

inline constexpr int kSize = 512;
inline constexpr double kMargin = 32.0;

/// An orthographic view fitted to the oracle mesh's bounding sphere.
struct OracleView {
    glm::dvec3 fwd, right, sup, centre;
    double scale = 1.0;
    double px_world = 1.0; ///< world length of a pixel

    OracleView(const glm::dvec3& dir, const ref::SceneMesh& m) {
        glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
        for (const glm::dvec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        centre = 0.5 * (lo + hi);
        const double radius = 0.5 * glm::length(hi - lo);
        fwd = glm::normalize(dir);
        const glm::dvec3 up = std::abs(fwd.y) > 0.95 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
        right = glm::normalize(glm::cross(fwd, up));
        sup = glm::cross(right, fwd);
        scale = (0.5 * kSize - kMargin) / radius;
        px_world = 1.0 / scale;
    }
    glm::dvec3 project(const glm::dvec3& p) const {
        const glm::dvec3 d = p - centre;
        return {0.5 * kSize + scale * glm::dot(d, right), 0.5 * kSize - scale * glm::dot(d, sup), glm::dot(d, fwd)};
    }
};

struct Raster {
    std::vector<double> depth = std::vector<double>(kSize * kSize, std::numeric_limits<double>::infinity());
    double at(int x, int y) const {
        return x < 0 || y < 0 || x >= kSize || y >= kSize ? std::numeric_limits<double>::infinity()
                                                          : depth[std::size_t(y * kSize + x)];
    }
};

inline Raster zbuffer(const ref::SceneMesh& m, const OracleView& view) {
    Raster r;
    std::vector<glm::dvec3> q(m.positions.size());
    for (std::size_t i = 0; i < q.size(); ++i) q[i] = view.project(m.positions[i]);
    for (const auto& f : m.faces) {
        const glm::dvec3 a = q[std::size_t(f[0])], b = q[std::size_t(f[1])], c = q[std::size_t(f[2])];
        ref::for_each_pixel_in({a.x, a.y}, {b.x, b.y}, {c.x, c.y}, kSize, kSize, [&](int x, int y, double wa, double wb, double wc) {
            double& d = r.depth[std::size_t(y * kSize + x)];
            d = std::min(d, wa * a.z + wb * b.z + wc * c.z);
        });
    }
    return r;
}

/// 1 where a visible point (x, y, depth) is not behind the z-buffer in its
/// 3 x 3 pixels (within @p tol), 0 where it is behind all of them, -1 where
/// the pixels disagree (an occluding outline passes within a pixel).
inline int seen(const Raster& r, const glm::dvec3& p, double tol) {
    const int cx = int(std::floor(p.x)), cy = int(std::floor(p.y));
    int pass = 0, fail = 0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) (r.at(cx + dx, cy + dy) >= p.z - tol ? pass : fail)++;
    return fail == 0 ? 1 : pass == 0 ? 0 : -1;
}

struct Bitmap {
    std::vector<std::uint8_t> on = std::vector<std::uint8_t>(kSize * kSize, 0);
    void set(const glm::dvec3& p) {
        const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
        if (x >= 0 && y >= 0 && x < kSize && y < kSize) on[std::size_t(y * kSize + x)] = 1;
    }
    bool near(const glm::dvec3& p, double reach) const {
        const int cx = int(std::floor(p.x)), cy = int(std::floor(p.y)), r = int(std::ceil(reach));
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
                const int x = cx + dx, y = cy + dy;
                if (x < 0 || y < 0 || x >= kSize || y >= kSize || !on[std::size_t(y * kSize + x)]) continue;
                if (std::hypot(x + 0.5 - p.x, y + 0.5 - p.y) <= reach + 0.5) return true;
            }
        return false;
    }
};

/// Points every half pixel along the image of segment a-b.
template <class Fn> inline void along(const glm::dvec3& a, const glm::dvec3& b, Fn&& fn) {
    const int n = std::max(1, int(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / 0.5)));
    for (int i = 0; i < n; ++i) fn(a + (b - a) * ((i + 0.5) / n));
}

struct Score {
    std::size_t silhouette = 0, covered = 0; ///< visible faceted-silhouette samples, and those drawn within 2 px
    std::size_t drawn = 0, on_silhouette = 0; ///< drawn visible samples, and those within 2 px of the silhouette
    std::size_t snaxels = 0, agree = 0;       ///< snaxels the z-buffer judges, and those whose QI agrees
    double coverage() const { return silhouette ? double(covered) / double(silhouette) : 0.0; }
    double precision() const { return drawn ? double(on_silhouette) / double(drawn) : 0.0; }
    double agreement() const { return snaxels ? double(agree) / double(snaxels) : 0.0; }
    void add(const Score& o) {
        silhouette += o.silhouette, covered += o.covered, drawn += o.drawn, on_silhouette += o.on_silhouette;
        snaxels += o.snaxels, agree += o.agree;
    }
};

/// The faceted mesh's edges with a face turned to the viewer and one not.
inline std::vector<std::pair<int, int>> silhouette_edges(const ref::SceneMesh& m, const glm::dvec3& fwd) {
    std::map<std::pair<int, int>, std::pair<int, int>> sides; // edge -> (faces turned to, faces turned away)
    for (const auto& f : m.faces) {
        const glm::dvec3 n = glm::cross(m.positions[std::size_t(f[1])] - m.positions[std::size_t(f[0])],
                                        m.positions[std::size_t(f[2])] - m.positions[std::size_t(f[0])]);
        const double facing = -glm::dot(n, fwd);
        for (int k = 0; k < 3; ++k) {
            const int a = f[std::size_t(k)], b = f[std::size_t((k + 1) % 3)];
            auto& s = sides[{std::min(a, b), std::max(a, b)}];
            if (facing > 0.0) ++s.first;
            else ++s.second; // seen edge-on or from behind: not turned to the viewer
        }
    }
    std::vector<std::pair<int, int>> out;
    for (const auto& [e, s] : sides)
        if (s.first > 0 && s.second > 0) out.push_back(e);
    return out;
}

/// The visible visual contour of @p topo seen along @p dir (orthographic)
/// against the oracle's visible faceted silhouette, and its QI against the
/// oracle's z-buffer; @p picture, when given, receives the view's picture.
inline Score score_view(const ref::SceneMesh& oracle, const MeshTopology& topo, const RayScene& rays, const glm::dvec3& dir,
                        std::vector<std::uint8_t>* picture = nullptr) {
    const OracleView view(dir, oracle);
    const Raster z = zbuffer(oracle, view);
    const double tol = 1.5 * view.px_world;
    Score s;
    Bitmap silhouette;
    std::vector<glm::dvec3> samples;
    for (const auto& [a, b] : silhouette_edges(oracle, view.fwd))
        along(view.project(oracle.positions[std::size_t(a)]), view.project(oracle.positions[std::size_t(b)]),
              [&](const glm::dvec3& p) {
                  if (seen(z, p, tol) == 0) return;
                  samples.push_back(p);
                  silhouette.set(p);
              });

    Camera cam;
    cam.view_dir = view.fwd;
    cam.up = glm::cross(view.right, view.fwd);
    const SnaxelEngine engine(topo);
    const ContourResult visual = engine.compute(ContourSpec{}, cam, default_light(cam));
    const ContourVisibility vis = VisibilitySampler(rays, cam).classify(engine, visual);
    Bitmap drawn;
    std::vector<glm::dvec3> drawn_samples;
    for (const LoopVisibility& loop : vis.loops)
        for (const VisibilityRun& run : loop.runs) {
            if (run.qi != 0) continue;
            const std::size_t n = run.points.size();
            for (std::size_t i = 0; i + 1 < n + (run.closed ? 1 : 0); ++i)
                along(view.project(run.points[i]), view.project(run.points[(i + 1) % n]), [&](const glm::dvec3& p) {
                    drawn.set(p);
                    drawn_samples.push_back(p);
                });
        }
    for (const glm::dvec3& p : samples) {
        ++s.silhouette;
        s.covered += drawn.near(p, 2.0);
    }
    // The picture: the visible faceted silhouette in blue, what is drawn on
    // it in black, drawn off it in red (kSize x kSize, RGB).
    std::vector<std::uint8_t> none;
    std::vector<std::uint8_t>& debug = picture ? *picture : none;
    if (picture) debug.assign(kSize * kSize * 3, 255);
    auto paint = [&](const glm::dvec3& p, int r, int g, int b) {
        const int x = int(p.x), y = int(p.y);
        if (debug.empty() || x < 0 || y < 0 || x >= kSize || y >= kSize) return;
        std::uint8_t* px = &debug[std::size_t(3 * (y * kSize + x))];
        px[0] = std::uint8_t(r), px[1] = std::uint8_t(g), px[2] = std::uint8_t(b);
    };
    for (const glm::dvec3& p : samples) paint(p, 120, 160, 255);
    for (const glm::dvec3& p : drawn_samples) {
        ++s.drawn;
        const bool on = silhouette.near(p, 2.0);
        s.on_silhouette += on;
        paint(p, on ? 0 : 255, 0, 0);
    }
    // Quantitative invisibility against the z-buffer, where it is clear.
    for (std::size_t l = 0; l < visual.fronts.loops.size(); ++l) {
        std::size_t k = 0;
        visual.fronts.for_each_in_loop(visual.fronts.loops[l], [&](std::int32_t i) {
            const int qi = vis.loops[l].snaxel_qi[k++];
            if (qi < 0) return;
            const int oracle_seen = seen(z, view.project(engine.position(visual.fronts.snaxels[std::size_t(i)])), tol);
            if (oracle_seen < 0) return;
            ++s.snaxels;
            s.agree += (qi == 0) == (oracle_seen == 1);
        });
    }
    return s;
}

inline std::vector<glm::dvec3> fibonacci_directions(int n) {
    std::vector<glm::dvec3> out;
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double y = 1.0 - 2.0 * (i + 0.5) / n, r = std::sqrt(1.0 - y * y);
        out.push_back({r * std::cos(golden * i + 0.5), y, r * std::sin(golden * i + 0.5)});
    }
    return out;
}

} // namespace snaxels::test::silhouette
