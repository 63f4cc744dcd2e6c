#pragma once
// An oracle for drawings through a perspective camera that stands inside
// the scene: its own z-buffer of the file's triangles, cut at the camera's
// near plane (each face clipped to what lies past the plane, then
// rasterized with depth interpolated as 1/z is, linearly in the image), and
// the faceted mesh's visible silhouette edges (a face turned to the eye
// beside one turned away), cut at the plane too. A drawing's visible
// strokes are scored against them as the orthographic oracle scores
// (tests/support/silhouette_oracle.h): within 2 px both ways, on the
// canvas. It reads the scene with tests/support/scene_reader.h and shares
// nothing with the product.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "tests/support/reference_raster.h"
#include "tests/support/scene_reader.h"

namespace snaxels::test::perspective {

/// The camera's picture: @p width x @p height pixels, the file's vertical
/// field of view across the height, cut at distance @p near along the line
/// of sight.
struct View {
    glm::dvec3 eye, fwd, right, up;
    double scale = 1.0; ///< focal length in pixels
    double near = 0.0;
    int width = 0, height = 0;

    View(const ref::SceneCamera& c, int w, int h, double near_distance)
        : eye(c.eye), fwd(glm::normalize(c.forward)), near(near_distance), width(w), height(h) {
        right = glm::normalize(glm::cross(fwd, c.up));
        up = glm::cross(right, fwd);
        scale = 0.5 * h / std::tan(0.5 * c.yfov);
    }
    double depth(const glm::dvec3& p) const { return glm::dot(p - eye, fwd); }
    /// Image x, y (y down) and depth; only for points past the near plane.
    glm::dvec3 project(const glm::dvec3& p) const {
        const glm::dvec3 d = p - eye;
        const double z = glm::dot(d, fwd);
        return {0.5 * width + scale * glm::dot(d, right) / z, 0.5 * height - scale * glm::dot(d, up) / z, z};
    }
    /// The point where segment a-b meets the near plane.
    glm::dvec3 on_plane(const glm::dvec3& a, const glm::dvec3& b) const {
        const double da = depth(a) - near, db = depth(b) - near;
        return a + (b - a) * (da / (da - db));
    }
};

struct Raster {
    int width = 0, height = 0;
    std::vector<double> depth;
    double at(int x, int y) const {
        return x < 0 || y < 0 || x >= width || y >= height ? std::numeric_limits<double>::infinity()
                                                           : depth[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

/// Every face's part past the near plane, nearest depth per pixel.
inline Raster zbuffer(const ref::SceneMesh& m, const View& v) {
    Raster r{v.width, v.height, std::vector<double>(std::size_t(v.width) * std::size_t(v.height), std::numeric_limits<double>::infinity())};
    for (const auto& f : m.faces) {
        std::vector<glm::dvec3> poly;
        for (int k = 0; k < 3; ++k) {
            const glm::dvec3& a = m.positions[std::size_t(f[std::size_t(k)])];
            const glm::dvec3& b = m.positions[std::size_t(f[std::size_t((k + 1) % 3)])];
            const bool in_a = v.depth(a) >= v.near, in_b = v.depth(b) >= v.near;
            if (in_a) poly.push_back(a);
            if (in_a != in_b) poly.push_back(v.on_plane(a, b));
        }
        if (poly.size() < 3) continue;
        const glm::dvec3 p0 = v.project(poly[0]);
        for (std::size_t k = 1; k + 1 < poly.size(); ++k) {
            const glm::dvec3 p1 = v.project(poly[k]), p2 = v.project(poly[k + 1]);
            ref::for_each_pixel_in({p0.x, p0.y}, {p1.x, p1.y}, {p2.x, p2.y}, v.width, v.height,
                                   [&](int x, int y, double wa, double wb, double wc) {
                                       const double z = 1.0 / (wa / p0.z + wb / p1.z + wc / p2.z);
                                       double& d = r.depth[std::size_t(y) * std::size_t(v.width) + std::size_t(x)];
                                       d = std::min(d, z);
                                   });
        }
    }
    return r;
}

/// The faceted mesh's edges with a face turned to the eye and one not.
inline std::vector<std::pair<int, int>> silhouette_edges(const ref::SceneMesh& m, const glm::dvec3& eye) {
    std::map<std::pair<int, int>, std::pair<int, int>> sides; // edge -> (faces turned to, faces turned away)
    for (const auto& f : m.faces) {
        const glm::dvec3& a = m.positions[std::size_t(f[0])];
        const glm::dvec3 n = glm::cross(m.positions[std::size_t(f[1])] - a, m.positions[std::size_t(f[2])] - a);
        const bool facing = glm::dot(n, eye - a) > 0.0;
        for (int k = 0; k < 3; ++k) {
            const int p = f[std::size_t(k)], q = f[std::size_t((k + 1) % 3)];
            auto& s = sides[{std::min(p, q), std::max(p, q)}];
            (facing ? s.first : s.second)++;
        }
    }
    std::vector<std::pair<int, int>> out;
    for (const auto& [e, s] : sides)
        if (s.first > 0 && s.second > 0) out.push_back(e);
    return out;
}

struct Bitmap {
    int width = 0, height = 0;
    std::vector<std::uint8_t> on;
    Bitmap(int w, int h) : width(w), height(h), on(std::size_t(w) * std::size_t(h), 0) {}
    bool inside(const glm::dvec2& p) const { return p.x >= 0.0 && p.y >= 0.0 && p.x < width && p.y < height; }
    void set(const glm::dvec2& p) {
        if (inside(p)) on[std::size_t(int(p.y)) * std::size_t(width) + std::size_t(int(p.x))] = 1;
    }
    bool near(const glm::dvec2& p, double reach) const {
        const int cx = int(std::floor(p.x)), cy = int(std::floor(p.y)), r = int(std::ceil(reach));
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) {
                const int x = cx + dx, y = cy + dy;
                if (x < 0 || y < 0 || x >= width || y >= height || !on[std::size_t(y) * std::size_t(width) + std::size_t(x)]) continue;
                if (std::hypot(x + 0.5 - p.x, y + 0.5 - p.y) <= reach + 0.5) return true;
            }
        return false;
    }
};

/// The visible faceted silhouette on the canvas, as points every half
/// pixel: each silhouette edge cut at the near plane, sampled evenly in the
/// image, kept unless the z-buffer is nearer all round it (3 x 3 pixels,
/// by 1.5 pixels' width at its depth).
inline std::vector<glm::dvec2> visible_silhouette(const ref::SceneMesh& m, const View& v, const Raster& z) {
    std::vector<glm::dvec2> out;
    for (const auto& [i, j] : silhouette_edges(m, v.eye)) {
        glm::dvec3 a = m.positions[std::size_t(i)], b = m.positions[std::size_t(j)];
        const bool in_a = v.depth(a) >= v.near, in_b = v.depth(b) >= v.near;
        if (!in_a && !in_b) continue;
        if (!in_a) a = v.on_plane(a, b);
        if (!in_b) b = v.on_plane(a, b);
        const glm::dvec3 pa = v.project(a), pb = v.project(b);
        const int n = std::clamp(int(std::ceil(std::hypot(pb.x - pa.x, pb.y - pa.y) / 0.5)), 1, 1 << 20);
        for (int k = 0; k < n; ++k) {
            // Even in the image: the point's parameter along the edge in space
            // follows from 1/z being linear in the image.
            const double s = (k + 0.5) / n;
            const double t = s * pa.z / ((1.0 - s) * pb.z + s * pa.z);
            const glm::dvec3 p = v.project(a + (b - a) * t);
            if (p.x < 0.0 || p.y < 0.0 || p.x >= v.width || p.y >= v.height) continue;
            const double tol = 1.5 * p.z / v.scale;
            int fail = 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) fail += z.at(int(p.x) + dx, int(p.y) + dy) < p.z - tol;
            if (fail < 9) out.push_back({p.x, p.y});
        }
    }
    return out;
}

struct Score {
    std::size_t silhouette = 0, covered = 0; ///< visible silhouette samples, and those drawn within 2 px
    std::size_t drawn = 0, on_silhouette = 0; ///< drawn samples on the canvas, and those within 2 px of the silhouette
    double coverage() const { return silhouette ? double(covered) / double(silhouette) : 1.0; }
    double precision() const { return drawn ? double(on_silhouette) / double(drawn) : 1.0; }
};

/// @p strokes (polylines in pixels: a drawing's visible visual contour)
/// against the visible silhouette of @p m through @p v.
/// @p picture, when given, receives a picture of it (RGB, the view's size):
/// the visible silhouette in blue, what is drawn on it in black, drawn off
/// it in red.
inline Score score(const ref::SceneMesh& m, const View& v, const std::vector<std::vector<glm::dvec2>>& strokes,
                   std::vector<std::uint8_t>* picture = nullptr) {
    const Raster z = zbuffer(m, v);
    const std::vector<glm::dvec2> silhouette = visible_silhouette(m, v, z);
    Bitmap sil(v.width, v.height), drawn(v.width, v.height);
    for (const glm::dvec2& p : silhouette) sil.set(p);
    std::vector<glm::dvec2> drawn_points;
    for (const auto& line : strokes)
        for (std::size_t k = 0; k + 1 < line.size(); ++k) {
            const glm::dvec2 a = line[k], b = line[k + 1];
            const int n = std::clamp(int(std::ceil(glm::length(b - a) / 0.5)), 1, 1 << 20);
            for (int i = 0; i < n; ++i) {
                const glm::dvec2 p = a + (b - a) * ((i + 0.5) / n);
                if (!drawn.inside(p)) continue;
                drawn.set(p);
                drawn_points.push_back(p);
            }
        }
    Score s;
    for (const glm::dvec2& p : silhouette) ++s.silhouette, s.covered += drawn.near(p, 2.0);
    for (const glm::dvec2& p : drawn_points) ++s.drawn, s.on_silhouette += sil.near(p, 2.0);
    if (picture) {
        picture->assign(std::size_t(v.width) * std::size_t(v.height) * 3, 255);
        auto paint = [&](const glm::dvec2& p, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
            std::uint8_t* px = &(*picture)[3 * (std::size_t(int(p.y)) * std::size_t(v.width) + std::size_t(int(p.x)))];
            px[0] = r, px[1] = g, px[2] = b;
        };
        for (const glm::dvec2& p : silhouette) paint(p, 120, 160, 255);
        for (const glm::dvec2& p : drawn_points) sil.near(p, 2.0) ? paint(p, 0, 0, 0) : paint(p, 230, 0, 0);
    }
    return s;
}

} // namespace snaxels::test::perspective
