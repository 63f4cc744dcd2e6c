#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include <polyclipping/clipper.hpp>

#include "snaxels/mesh/import.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/mesh/refine.h"
#include "tests/support/assets.h"
#include "tests/support/views.h"

using namespace snaxels;

namespace {

ClipperLib::Paths to_paths(const std::vector<std::vector<glm::dvec2>>& polys) {
    ClipperLib::Paths out;
    for (const auto& poly : polys) {
        ClipperLib::Path p;
        for (const auto& q : poly) p.push_back({ClipperLib::cInt(std::llround(q.x * 1024)), ClipperLib::cInt(std::llround(q.y * 1024))});
        out.push_back(p);
    }
    return out;
}

double area(const ClipperLib::Paths& paths) {
    double a = 0.0;
    for (const auto& p : paths) a += ClipperLib::Area(p);
    return std::abs(a) / (1024.0 * 1024.0);
}

ClipperLib::Paths op(const ClipperLib::Paths& a, const ClipperLib::Paths& b, ClipperLib::ClipType type) {
    ClipperLib::Clipper c;
    c.AddPaths(a, ClipperLib::ptSubject, true);
    c.AddPaths(b, ClipperLib::ptClip, true);
    ClipperLib::Paths out;
    c.Execute(type, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
    return out;
}

} // namespace

// The post-processed map's regions, as the product builds them, do not overlap (pairwise intersection
// under 1e-6 of the total), and together they cover the projected
// silhouette of the mesh's own triangles within 0.5%, creased fandisk too
// (the map built on the topology the engine works on, coarse meshes
// refined; the silhouette from the mesh as loaded).
TEST(PostMap, RegionsPartitionTheSilhouette) {
    for (const std::string file : {"spot.obj", "horse.ply", "fandisk.obj"}) {
        const LoadedMesh m = import_mesh(test::asset(file));
        const MeshTopology topo = build_topology(m.mesh);     // the mesh as loaded: the reference
        const MeshTopology refined = engine_topology(m.mesh); // what the engine works on
        const SnaxelEngine engine(refined);
        std::mt19937 rng(5);
        for (int view = 0; view < 4; ++view) {
            const Camera cam = test::random_orthographic_camera(rng);
            const Light light = default_light(cam);
            const ContourResult visual = engine.compute({}, cam, light);
            const ContourResult shadow = engine.compute({ContourKind::Shadow, 0.0}, cam, light);
            const ContourResult iso = engine.compute({ContourKind::Isophote, 0.6}, cam, light);
            const ContourResult gleam = engine.compute({ContourKind::Gleam, 0.9}, cam, light);
            const glm::dvec3 centre = 0.5 * (m.report.bbox_min + m.report.bbox_max);
            const ImageProjection proj(cam, centre, 0.5 * glm::length(m.report.bbox_max - m.report.bbox_min), 800, 800);
            const RayScene rays(engine.topology());
            const std::vector<MapRegion> regions =
                build_planar_map(PlanarMapKind::Post, engine, {&visual, &shadow, &iso, &gleam}, &rays, proj, cam, light).regions;
            ASSERT_FALSE(regions.empty());
            double total = 0.0;
            ClipperLib::Paths all;
            for (std::size_t i = 0; i < regions.size(); ++i) {
                total += regions[i].area;
                all = op(all, to_paths(regions[i].polygons), ClipperLib::ctUnion);
            }
            // Pairwise overlap: the sum of the areas equals the area of the union.
            const double united = area(all);
            EXPECT_NEAR(total, united, 1e-6 * united + 1e-3) << file << " view " << view;
            for (std::size_t i = 0; i < regions.size(); ++i)
                for (std::size_t j = i + 1; j < regions.size(); ++j) {
                    const double overlap = area(op(to_paths(regions[i].polygons), to_paths(regions[j].polygons), ClipperLib::ctIntersection));
                    ASSERT_LE(overlap, 1e-6 * united) << file << " regions " << i << ", " << j;
                }
            // Against the projection of every triangle of the mesh.
            ClipperLib::Paths triangles;
            for (const auto& f : topo.face_vertices()) {
                std::vector<glm::dvec2> tri;
                for (const auto v : f) tri.push_back(proj.project(topo.positions()[v]));
                triangles.push_back(to_paths({tri})[0]);
            }
            // Triangles of either winding: orient them all the same way first.
            for (auto& t : triangles)
                if (!ClipperLib::Orientation(t)) std::reverse(t.begin(), t.end());
            ClipperLib::Paths silhouette;
            ClipperLib::Clipper c;
            c.AddPaths(triangles, ClipperLib::ptSubject, true);
            c.Execute(ClipperLib::ctUnion, silhouette, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
            const double reference = area(silhouette);
            std::printf("%s view %d: %zu regions, union %.1f px2, triangles' silhouette %.1f px2 (%.3f%%)\n", file.c_str(), view,
                        regions.size(), united, reference, 100.0 * (united - reference) / reference);
            EXPECT_NEAR(united, reference, 0.005 * reference) << file << " view " << view;
        }
    }
}
