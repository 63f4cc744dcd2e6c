#pragma once
// Rasterizing planar-map regions and classifying pixels directly (a ray
// cast and the shading at the hit), for checking maps pixel by pixel.

#include <algorithm>
#include <cmath>
#include <vector>

#include "snaxels/planarmap/post_map.h"
#include "snaxels/visibility/ray_scene.h"

namespace snaxels::test {

/// Per pixel of a width x height image: the index of the region covering
/// its centre (non-zero winding within a region, as SVG fills them; where
/// regions overlap, the nearer one by depth order), or -1.
inline std::vector<int> rasterize_regions(const std::vector<MapRegion>& regions, int width, int height) {
    std::vector<int> image(std::size_t(width) * std::size_t(height), -1);
    std::vector<std::size_t> order(regions.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    // Farthest first, so nearer regions paint over.
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return regions[a].depth > regions[b].depth; });
    std::vector<std::pair<double, int>> xs; // crossing, winding direction
    for (const std::size_t r : order)
        for (int y = 0; y < height; ++y) {
            const double cy = y + 0.5;
            xs.clear();
            for (const auto& poly : regions[r].polygons)
                for (std::size_t i = 0; i < poly.size(); ++i) {
                    const glm::dvec2& a = poly[i];
                    const glm::dvec2& b = poly[(i + 1) % poly.size()];
                    if ((a.y <= cy) == (b.y <= cy)) continue;
                    xs.push_back({a.x + (cy - a.y) / (b.y - a.y) * (b.x - a.x), b.y > a.y ? 1 : -1});
                }
            std::sort(xs.begin(), xs.end());
            int winding = 0;
            for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
                winding += xs[i].second;
                if (winding == 0) continue;
                const int x0 = std::max(0, int(std::ceil(xs[i].first - 0.5)));
                const int x1 = std::min(width - 1, int(std::floor(xs[i + 1].first - 0.5)));
                for (int x = x0; x <= x1; ++x) image[std::size_t(y) * std::size_t(width) + std::size_t(x)] = int(r);
            }
        }
    return image;
}

/// The map class at the surface point a pixel's ray hits: 0 shadow, 1 lit,
/// 2 + i isophote band i (ascending @p bands), -1 background. Shading uses
/// the interpolated normal, as the contours do.
inline int direct_class(const RayScene& rays, const ImageProjection& projection, const Camera& camera,
                        const Light& light, const std::vector<double>& bands, double radius, int x, int y) {
    VisibilityRay ray;
    projection.pixel_ray({x + 0.5, y + 0.5}, 4.0 * radius, ray.origin, ray.dir);
    ray.tfar = std::numeric_limits<double>::infinity();
    const RayHit hit = rays.nearest(ray);
    if (!hit.hit()) return -1;
    const MeshTopology& topo = rays.topology();
    const auto& f = topo.face_vertices()[hit.face];
    const glm::dvec3 p = (1.0 - hit.u - hit.v) * topo.positions()[f[0]] + hit.u * topo.positions()[f[1]] + hit.v * topo.positions()[f[2]];
    const glm::dvec3 n = glm::normalize((1.0 - hit.u - hit.v) * topo.normals()[f[0]] + hit.u * topo.normals()[f[1]] + hit.v * topo.normals()[f[2]]);
    (void)camera;
    const double nl = glm::dot(n, light.to_light(p));
    int cls = nl < 0.0 ? 0 : 1;
    for (std::size_t i = 0; i < bands.size(); ++i)
        if (cls != 0 && nl >= bands[i]) cls = 2 + int(i);
    return cls;
}

/// The class index of a region in direct_class's numbering.
inline int region_class_index(const MapRegion& r, const std::vector<double>& bands) {
    if (r.cls == RegionClass::Shadow) return 0;
    if (r.cls == RegionClass::Lit) return 1;
    for (std::size_t i = 0; i < bands.size(); ++i)
        if (std::abs(bands[i] - r.k) < 1e-9) return 2 + int(i);
    return -2;
}

} // namespace snaxels::test
