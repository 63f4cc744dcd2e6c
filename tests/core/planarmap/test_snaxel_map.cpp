#include <gtest/gtest.h>

#include <map>
#include <random>

#include "snaxels/mesh/import.h"
#include "snaxels/planarmap/snaxel_map.h"
#include "snaxels/mesh/refine.h"
#include "tests/support/assets.h"
#include "tests/support/map_raster.h"
#include "tests/support/views.h"

using namespace snaxels;

namespace {

struct Scene {
    LoadedMesh mesh;
    MeshTopology topo;
    glm::dvec3 centre;
    double radius;
    explicit Scene(const std::string& file) : mesh(import_mesh(test::asset(file))), topo(build_topology(mesh.mesh)) {
        centre = 0.5 * (mesh.report.bbox_min + mesh.report.bbox_max);
        radius = 0.5 * glm::length(mesh.report.bbox_max - mesh.report.bbox_min);
    }
};

struct Maps {
    ContourResult visual, shadow, iso;
    SnaxelMap snaxel;
    std::vector<MapRegion> post;
};

Maps build_maps(const Scene& s, const SnaxelEngine& engine, const RayScene& rays, const Camera& cam,
                const Light& light, const ImageProjection& proj, double k) {
    Maps m;
    m.visual = engine.compute({}, cam, light);
    m.shadow = engine.compute({ContourKind::Shadow, 0.0}, cam, light);
    m.iso = engine.compute({ContourKind::Isophote, k}, cam, light);
    SnaxelMapInput in;
    in.visual = &m.visual;
    in.shadow = &m.shadow;
    in.isophotes = {&m.iso};
    m.snaxel = build_snaxel_map(engine, in, rays, proj, cam, light);
    PostMapInput post{&m.visual, &m.shadow, {&m.iso}, {}};
    m.post = build_post_map(engine, post, rays, proj, cam, light);
    (void)s;
    return m;
}

Camera random_camera(std::mt19937& rng) { return test::random_orthographic_camera(rng); }

Light random_light(std::mt19937& rng, const Camera& cam) {
    std::normal_distribution<double> n;
    Light light = default_light(cam);
    light.dir = glm::normalize(light.dir + 0.5 * glm::dvec3(n(rng), n(rng), n(rng)));
    return light;
}

} // namespace

// The snaxel map cannot make regions thinner than the tessellation: it has
// fewer tiny regions (under 4 square pixels) than the post-processed map.
TEST(SnaxelMap, FewerTinyRegionsThanThePostProcessedMap) {
    for (const std::string file : {"stanford-bunny.obj", "horse.ply"}) {
        const Scene s(file);
        const SnaxelEngine engine(s.topo);
        const RayScene rays(s.topo);
        std::mt19937 rng(3);
        std::size_t tiny_snaxel = 0, tiny_post = 0;
        for (int view = 0; view < 4; ++view) {
            const Camera cam = random_camera(rng);
            const Light light = random_light(rng, cam);
            const ImageProjection proj(cam, s.centre, s.radius, 800, 800);
            const Maps m = build_maps(s, engine, rays, cam, light, proj, 0.5);
            for (const MapRegion& r : m.snaxel.regions) tiny_snaxel += r.area < 4.0;
            if (getenv("SNAXELS_DEBUG_MAP")) {
                std::map<int, int> by_vertices;
                std::vector<int> count(m.snaxel.regions.size(), 0);
                for (auto r : m.snaxel.vertex_region) if (r >= 0) count[std::size_t(r)]++;
                for (std::size_t r = 0; r < m.snaxel.regions.size(); ++r)
                    if (m.snaxel.regions[r].area < 4.0) { by_vertices[std::min(count[r], 10)]++;
                        if (count[r] >= 4) std::printf("    tiny: %d vertices, class %s, area %.2f, depth %d\n", count[r], region_class_name(m.snaxel.regions[r].cls), m.snaxel.regions[r].area, m.snaxel.regions[r].depth); }
                for (auto [n, c] : by_vertices) std::printf("  tiny regions with %d vertices: %d\n", n, c);
            }
            for (const MapRegion& r : m.post) tiny_post += r.area < 4.0;
        }
        std::printf("%s, 4 views: regions under 4 px2: snaxel map %zu, post-processed map %zu\n", file.c_str(), tiny_snaxel,
                    tiny_post);
        EXPECT_LT(tiny_snaxel, tiny_post) << file;
    }
}

// Every region's outline closes, on closed, open, creased and procedural
// meshes under random views, orthographic and perspective, with bands and a
// gleam; regions lie inside the image of the mesh.
TEST(SnaxelMap, OutlinesCloseOnEveryMesh) {
    for (const std::string file : {"spot.obj", "fandisk.obj", "teapot.obj", "suzanne.obj", "proc:torus:20000", "proc:nose:20000"}) {
        const LoadedMesh mesh = file.rfind("proc:", 0) == 0 ? load_mesh(file) : import_mesh(test::asset(file));
        const MeshTopology topo = build_topology(mesh.mesh);
        const SnaxelEngine engine(topo);
        const RayScene rays(topo);
        const glm::dvec3 centre = 0.5 * (mesh.report.bbox_min + mesh.report.bbox_max);
        const double radius = 0.5 * glm::length(mesh.report.bbox_max - mesh.report.bbox_min);
        std::mt19937 rng(29);
        for (int view = 0; view < 4; ++view) {
            Camera cam = random_camera(rng);
            if (view % 2) {
                cam.projection = Camera::Projection::Perspective;
                cam.target = centre;
                cam.eye = centre - 3.0 * radius * cam.view_dir;
            }
            const Light light = random_light(rng, cam);
            const ImageProjection proj(cam, centre, radius, 400, 400);
            const ContourResult visual = engine.compute({}, cam, light);
            const ContourResult shadow = engine.compute({ContourKind::Shadow, 0.0}, cam, light);
            const ContourResult iso1 = engine.compute({ContourKind::Isophote, 0.3}, cam, light);
            const ContourResult iso2 = engine.compute({ContourKind::Isophote, 0.7}, cam, light);
            const ContourResult gleam = engine.compute({ContourKind::Gleam, 0.9}, cam, light);
            SnaxelMapInput in;
            in.visual = &visual;
            in.shadow = &shadow;
            in.isophotes = {&iso1, &iso2};
            in.gleams = {&gleam};
            const SnaxelMap map = build_snaxel_map(engine, in, rays, proj, cam, light);
            EXPECT_EQ(map.stats.open_outlines, 0u) << file << " view " << view;
            EXPECT_FALSE(map.regions.empty()) << file << " view " << view;
            for (const MapRegion& r : map.regions)
                for (const auto& loop : r.polygons)
                    for (const glm::dvec2& p : loop) {
                        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << file;
                    }
        }
    }
}

// Several band and highlight levels all reach both maps: each level is a
// region class of its own, brighter levels inside dimmer ones. A sphere lit
// from the viewer's side: its shading is concentric rings.
TEST(PlanarMaps, EveryBandAndHighlightLevelFills) {
    const LoadedMesh mesh = load_mesh("proc:sphere:40000");
    const MeshTopology topo = build_topology(mesh.mesh);
    const SnaxelEngine engine(topo);
    const RayScene rays(topo);
    Camera cam;
    cam.view_dir = glm::dvec3(0, 0, -1);
    Light light = default_light(cam);
    light.dir = glm::normalize(glm::dvec3(0.2, 0.3, 1.0));
    const glm::dvec3 centre = 0.5 * (mesh.report.bbox_min + mesh.report.bbox_max);
    const double radius = 0.5 * glm::length(mesh.report.bbox_max - mesh.report.bbox_min);
    const ImageProjection proj(cam, centre, radius, 400, 400);
    const ContourResult visual = engine.compute({}, cam, light);
    const ContourResult shadow = engine.compute({ContourKind::Shadow, 0.0}, cam, light);
    const ContourResult iso1 = engine.compute({ContourKind::Isophote, 0.3}, cam, light);
    const ContourResult iso2 = engine.compute({ContourKind::Isophote, 0.6}, cam, light);
    const ContourResult gleam1 = engine.compute({ContourKind::Gleam, 0.8}, cam, light);
    const ContourResult gleam2 = engine.compute({ContourKind::Gleam, 0.95}, cam, light);
    SnaxelMapInput in;
    in.visual = &visual;
    in.shadow = &shadow;
    in.isophotes = {&iso1, &iso2};
    in.gleams = {&gleam1, &gleam2};
    const std::vector<MapRegion> snaxel = build_snaxel_map(engine, in, rays, proj, cam, light).regions;
    const std::vector<MapRegion> post = build_post_map(engine, {&visual, &shadow, {&iso1, &iso2}, {&gleam1, &gleam2}}, rays, proj, cam, light);
    for (const auto* regions : {&snaxel, &post}) {
        const char* which = regions == &snaxel ? "snaxel map" : "post-processed map";
        auto area = [&](RegionClass cls, double k) {
            double a = 0.0;
            for (const MapRegion& r : *regions)
                if (r.cls == cls && std::abs(r.k - k) < 1e-9) a += r.area;
            return a;
        };
        auto box = [&](RegionClass cls, double k) {
            glm::dvec2 lo(1e300), hi(-1e300);
            for (const MapRegion& r : *regions)
                if (r.cls == cls && std::abs(r.k - k) < 1e-9)
                    for (const auto& loop : r.polygons)
                        for (const glm::dvec2& p : loop) lo = glm::min(lo, p), hi = glm::max(hi, p);
            return std::pair{lo, hi};
        };
        EXPECT_GT(area(RegionClass::Band, 0.3), 100.0) << which;
        EXPECT_GT(area(RegionClass::Band, 0.6), 100.0) << which;
        EXPECT_GT(area(RegionClass::Highlight, 0.8), 20.0) << which;
        EXPECT_GT(area(RegionClass::Highlight, 0.95), 5.0) << which;
        // The stricter gleam's disc lies inside the other's ring.
        const auto [lo8, hi8] = box(RegionClass::Highlight, 0.8);
        const auto [lo95, hi95] = box(RegionClass::Highlight, 0.95);
        EXPECT_TRUE(lo95.x > lo8.x && lo95.y > lo8.y && hi95.x < hi8.x && hi95.y < hi8.y) << which;
    }
}

// The vertices' rays cast beside the contours (see_vertices) make the map
// the map casts itself, on a closed mesh and on one with holes, in
// perspective and orthographic views; rays cast for another camera are not
// taken, and the map does take the given ones (all of them flipped, it
// comes out otherwise).
TEST(SnaxelMap, RaysCastBeforehandMakeTheSameMap) {
    auto same = [](const SnaxelMap& a, const SnaxelMap& b) {
        if (a.vertex_region.values() != b.vertex_region.values() || a.regions.size() != b.regions.size()) return false;
        for (std::size_t r = 0; r < a.regions.size(); ++r)
            if (a.regions[r].polygons != b.regions[r].polygons || a.regions[r].depth != b.regions[r].depth ||
                a.regions[r].cls != b.regions[r].cls)
                return false;
        return true;
    };
    for (const std::string file : {"spot.obj", "stanford-bunny.obj"}) {
        const Scene s(file);
        const SnaxelEngine engine(s.topo);
        const RayScene rays(s.topo);
        std::mt19937 rng(41);
        for (int view = 0; view < 4; ++view) {
            Camera cam = random_camera(rng);
            if (view % 2) {
                cam.projection = Camera::Projection::Perspective;
                cam.target = s.centre;
                cam.eye = s.centre - 3.0 * s.radius * cam.view_dir;
            }
            const Light light = random_light(rng, cam);
            const ImageProjection proj(cam, s.centre, s.radius, 400, 400);
            const ContourResult visual = engine.compute({}, cam, light);
            const ContourResult shadow = engine.compute({ContourKind::Shadow, 0.0}, cam, light);
            SnaxelMapInput in;
            in.visual = &visual;
            in.shadow = &shadow;
            const SnaxelMap cast_within = build_snaxel_map(engine, in, rays, proj, cam, light);

            const VertexSight sight = see_vertices(s.topo, rays, cam, light, ContourSpec{});
            in.sight = &sight;
            EXPECT_TRUE(same(build_snaxel_map(engine, in, rays, proj, cam, light), cast_within)) << file << " view " << view;

            Camera other = cam;
            other.view_dir = glm::normalize(cam.view_dir + glm::dvec3(0.3, -0.2, 0.1));
            if (other.projection == Camera::Projection::Perspective) other.eye = s.centre - 3.0 * s.radius * other.view_dir;
            const VertexSight elsewhere = see_vertices(s.topo, rays, other, light, ContourSpec{});
            in.sight = &elsewhere;
            EXPECT_TRUE(same(build_snaxel_map(engine, in, rays, proj, cam, light), cast_within)) << file << " view " << view;

            VertexSight flipped = sight;
            for (std::uint8_t& c : flipped.code)
                if (c & VertexSight::kCast) c ^= VertexSight::kBlocked;
            in.sight = &flipped;
            EXPECT_FALSE(same(build_snaxel_map(engine, in, rays, proj, cam, light), cast_within)) << file << " view " << view;
        }
    }
}
