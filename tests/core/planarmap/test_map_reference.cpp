#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <random>

#include "snaxels/mesh/import.h"
#include "snaxels/mesh/procedural.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/mesh/refine.h"
#include "tests/support/assets.h"
#include "tests/support/map_raster.h"
#include "tests/support/reference_raster.h"

using namespace snaxels;

namespace {

struct Agreement {
    std::size_t mesh_pixels = 0, agree = 0;
    double fraction() const { return mesh_pixels ? double(agree) / double(mesh_pixels) : 0.0; }
};

// The file both sides read: an asset, or a procedural mesh written as OBJ.
std::string mesh_file(const std::string& name) {
    if (name.rfind("proc:", 0) != 0) return test::asset(name);
    const TriangleSoup soup = make_procedural(name.substr(5));
    const std::string path = (std::filesystem::temp_directory_path() / (test::test_name(name) + "-reference.obj")).string();
    ref::write_obj(path, soup.positions, soup.triangles);
    return path;
}

} // namespace

// Both planar maps agree with an independent reference (a z-buffer
// rasterizer written in the tests from the mesh file alone:
// tests/support/reference_raster.h) on at least 97% of the pixels the mesh
// covers at 512 x 512: the class of the nearest triangle's Phong-interpolated
// N.L (shadow, lit, a band at k = 0.55). Over 10 random views and lights of
// every bundled mesh and the procedural nose and torus (views 55-80 degrees
// off its axis, where the tube hides itself), alternately orthographic and
// in perspective. The maps are built on the topology the product uses
// (coarse meshes refined).
TEST(PlanarMaps, AgreeWithAnIndependentZBuffer) {
    constexpr int kSize = 512;
    const double k = 0.55;
    const int views = getenv("SNAXELS_MAP_VIEWS") ? std::atoi(getenv("SNAXELS_MAP_VIEWS")) : 10;
    std::vector<std::string> names;
    for (const auto& m : test::asset_meshes()) names.push_back(m.file);
    names.push_back("proc:torus:20000");
    names.push_back("proc:nose:20000");
    for (const std::string& name : names) {
        const std::string file = mesh_file(name);
        const ref::Mesh reference = ref::read_mesh(file);
        const LoadedMesh mesh = import_mesh(file);
        const MeshTopology topo = engine_topology(mesh.mesh);
        const SnaxelEngine engine(topo);
        const RayScene rays(topo);
        // The framing sphere, from the reference's own reading of the file.
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const glm::dvec3& p : reference.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
        const glm::dvec3 centre = 0.5 * (lo + hi);
        const double radius = 0.5 * glm::length(hi - lo);
        std::mt19937 rng(7);
        std::normal_distribution<double> normal;
        std::uniform_real_distribution<double> uniform(0.0, 1.0);
        double least[2] = {1.0, 1.0};
        for (int view = 0; view < views; ++view) {
            ref::View v;
            v.dir = glm::normalize(glm::dvec3(normal(rng), normal(rng), normal(rng)));
            if (name.find("torus") != std::string::npos) { // oblique to the axis (+Z)
                const double off = glm::radians(55.0 + 25.0 * uniform(rng)), turn = 6.283185307179586 * uniform(rng);
                v.dir = {std::sin(off) * std::cos(turn), std::sin(off) * std::sin(turn), (uniform(rng) < 0.5 ? 1 : -1) * std::cos(off)};
            }
            v.orthographic = view % 2 == 0;
            v.centre = centre, v.radius = radius, v.width = v.height = kSize, v.margin = 16.0;
            v.target = centre;
            v.eye = centre - 2.5 * radius * v.dir;
            glm::dvec3 to_light = glm::normalize(-v.dir + glm::dvec3(normal(rng), normal(rng), normal(rng)));
            const std::vector<int> truth = ref::class_image(reference, v, to_light, {k});

            Camera cam;
            cam.projection = v.orthographic ? Camera::Projection::Orthographic : Camera::Projection::Perspective;
            cam.view_dir = v.dir, cam.eye = v.eye, cam.target = v.target, cam.fov_deg = v.fov_deg, cam.up = v.up;
            Light light;
            light.dir = to_light;
            const ImageProjection proj(cam, centre, radius, kSize, kSize, v.margin);
            const ContourResult visual = engine.compute({}, cam, light);
            const ContourResult shadow = engine.compute({ContourKind::Shadow, 0.0}, cam, light);
            const ContourResult iso = engine.compute({ContourKind::Isophote, k}, cam, light);
            for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
                const PlanarMap map = build_planar_map(kind, engine, {&visual, &shadow, &iso}, &rays, proj, cam, light);
                const std::vector<int> image = test::rasterize_regions(map.regions, kSize, kSize);
                Agreement a;
                std::map<std::pair<int, int>, int> confusion;
                std::vector<unsigned char> debug(std::size_t(kSize) * kSize * 3, 255);
                for (std::size_t at = 0; at < truth.size(); ++at) {
                    if (truth[at] < 0) continue;
                    ++a.mesh_pixels;
                    const int r = image[at];
                    const bool same = r >= 0 && test::region_class_index(map.regions[std::size_t(r)], {k}) == truth[at];
                    a.agree += same;
                    unsigned char* px = &debug[at * 3];
                    if (same) px[0] = px[1] = px[2] = (unsigned char)(60 + 60 * truth[at]);
                    else if (r < 0) px[0] = 255, px[1] = px[2] = 0;
                    else px[0] = px[1] = 0, px[2] = 255;
                    if (!same && r >= 0 && getenv("SNAXELS_DEBUG_MAP_DIR"))
                        ++confusion[{truth[at], test::region_class_index(map.regions[std::size_t(r)], {k})}];
                }
                if (getenv("SNAXELS_DEBUG_MAP_DIR"))
                    for (const auto& [pair, count] : confusion)
                        std::printf("  %s view %d %s: truth %d, map %d: %d px\n", name.c_str(), view, planar_map_kind_name(kind), pair.first, pair.second, count);
                const int which = kind == PlanarMapKind::Snaxel ? 0 : 1;
                least[which] = std::min(least[which], a.fraction());
                EXPECT_GE(a.fraction(), 0.97) << name << " view " << view << " " << planar_map_kind_name(kind)
                                              << (v.orthographic ? " orthographic" : " perspective");
                if (const char* dir = getenv("SNAXELS_DEBUG_MAP_DIR")) {
                    const std::string out_path = std::string(dir) + "/" + test::test_name(name) + "-" + std::to_string(view) + "-" +
                                                 planar_map_kind_name(kind) + ".ppm";
                    FILE* out = std::fopen(out_path.c_str(), "wb");
                    std::fprintf(out, "P6 %d %d 255\n", kSize, kSize);
                    std::fwrite(debug.data(), 1, debug.size(), out);
                    std::fclose(out);
                }
            }
        }
        std::printf("%s (%zu faces, engine %zu): least agreement over %d views: snaxel map %.2f%%, post map %.2f%%\n",
                    name.c_str(), reference.faces.size(), topo.n_faces(), views, 100 * least[0], 100 * least[1]);
    }
}
