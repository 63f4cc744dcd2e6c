#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <optional>
#include <random>

#include "snaxels/mesh/import.h"
#include "snaxels/mesh/procedural.h"
#include "snaxels/planarmap/planar_map.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/mesh/sharp_edges.h"
#include "tests/support/assets.h"
#include "tests/support/map_raster.h"
#include "tests/support/reference_raster.h"
#include "tests/support/scene_reader.h"

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

/// The sphere a view frames: the centre and half the diagonal of the box
/// round @p positions.
std::pair<glm::dvec3, double> framing(const std::vector<glm::dvec3>& positions) {
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    return {0.5 * (lo + hi), 0.5 * glm::length(hi - lo)};
}

/// @p v looking along its direction at the sphere (@p centre, @p radius),
/// orthographic or in perspective from 2.5 radii away, at 512 x 512.
void frame_view(ref::View& v, bool orthographic, const glm::dvec3& centre, double radius) {
    v.orthographic = orthographic;
    v.centre = centre, v.radius = radius, v.width = v.height = 512, v.margin = 16.0;
    v.target = centre;
    v.eye = centre - 2.5 * radius * v.dir;
}

/// The product's camera for the reference's view.
Camera camera_of(const ref::View& v) {
    Camera cam;
    cam.projection = v.orthographic ? Camera::Projection::Orthographic : Camera::Projection::Perspective;
    cam.view_dir = v.dir, cam.eye = v.eye, cam.target = v.target, cam.fov_deg = v.fov_deg, cam.up = v.up;
    return cam;
}

/// The product's side of one view: its camera, the light toward @p to_light,
/// and the contours a map of the classes shadow, lit and band k needs.
struct ProductView {
    Camera cam;
    Light light;
    ImageProjection proj;
    ContourResult visual, shadow, iso;
    ProductView(const SnaxelEngine& engine, const ref::View& v, const glm::dvec3& to_light, double k)
        : cam(camera_of(v)), light(light_toward(to_light)), proj(cam, v.centre, v.radius, v.width, v.height, v.margin),
          visual(engine.compute({}, cam, light)), shadow(engine.compute({ContourKind::Shadow, 0.0}, cam, light)),
          iso(engine.compute({ContourKind::Isophote, k}, cam, light)) {}
    PlanarMap map(PlanarMapKind kind, const SnaxelEngine& engine, const RayScene& rays) const {
        return build_planar_map(kind, engine, {&visual, &shadow, &iso}, &rays, proj, cam, light);
    }

  private:
    static Light light_toward(const glm::dvec3& dir) {
        Light l;
        l.dir = dir;
        return l;
    }
};

/// Random views of a scene in turn, orthographic and perspective
/// alternately, each lit from near the viewer: directions from a seeded
/// generator, kept to those @p accept takes.
struct ViewSeries {
    std::mt19937 rng;
    std::normal_distribution<double> normal;
    glm::dvec3 centre;
    double radius;
    ViewSeries(unsigned seed, const std::pair<glm::dvec3, double>& framed)
        : rng(seed), centre(framed.first), radius(framed.second) {}
    template <class Accept> std::pair<ref::View, glm::dvec3> next(int view, Accept&& accept) {
        ref::View v;
        do v.dir = glm::normalize(draw());
        while (!accept(v.dir));
        frame_view(v, view % 2 == 0, centre, radius);
        const glm::dvec3 to_light = glm::normalize(-v.dir + draw());
        return {v, to_light};
    }
    /// Three draws, z first (the order GCC gave the arguments of a
    /// constructor call these views were first drawn with; the order of
    /// such arguments is unspecified, and Clang's drew other views).
    glm::dvec3 draw() {
        const double z = normal(rng);
        const double y = normal(rng);
        const double x = normal(rng);
        return {x, y, z};
    }
};

/// The product's side of a scene file: the mesh as loaded and split along
/// its sharp edges (as @p surface says), the engine's topology with the
/// file's parts, the engine and the ray scene.
struct ProductScene {
    LoadedMesh loaded;
    std::optional<LoadedMesh> split;
    MeshTopology topo;
    SnaxelEngine engine;
    RayScene rays;
    ProductScene(const std::string& file, const SurfaceOptions& surface)
        : loaded(import_mesh(file)), topo(engine_topology(with_sharp_edges(loaded, surface, split))), engine(topo),
          rays(topo) {}
};

/// How many of the mesh's pixels (@p truth >= 0) the map gives the same class.
Agreement agreement(const PlanarMap& map, const std::vector<int>& image, const std::vector<int>& truth, double k) {
    Agreement a;
    for (std::size_t at = 0; at < truth.size(); ++at) {
        if (truth[at] < 0) continue;
        ++a.mesh_pixels;
        const int r = image[at];
        a.agree += r >= 0 && test::region_class_index(map.regions[std::size_t(r)], {k}) == truth[at];
    }
    return a;
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
        const auto [centre, radius] = framing(reference.positions);
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
            frame_view(v, view % 2 == 0, centre, radius);
            glm::dvec3 to_light = glm::normalize(-v.dir + glm::dvec3(normal(rng), normal(rng), normal(rng)));
            const std::vector<int> truth = ref::class_image(reference, v, to_light, {k});

            const ProductView product(engine, v, to_light, k);
            for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
                const PlanarMap map = product.map(kind, engine, rays);
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

// Hard surfaces (#35, done-when 2; the meshes without normals #56's done-when
// 4): on meshes split along their sharp edges
// both maps agree with the reference rasterizer shading with the same
// corner normals (the file's own, or the reference's own auto-smooth by
// angle) on at least 97% of the mesh's pixels, in the classes of the toon
// and clip-art presets' fills (shadow, lit, a band at k = 0.75), where a
// flat face takes one tone.
TEST(PlanarMaps, AgreeOnHardSurfaces) {
    constexpr int kSize = 512;
    const double k = 0.75;
    struct Model {
        std::string file;
        double sharp_angle;     // kFileNormals: the file's own corner normals (a file without: by angle)
        double reference_angle; // the reference's auto-smooth angle; negative: the file's normals
    };
    // The meshes without normals (#56, done-when 4) are split at 30 degrees
    // by default: the reference smooths them by that angle itself.
    for (const Model& model : {Model{"hard/CesiumMilkTruck.gltf", kFileNormals, -1.0}, Model{"hard/regr01-house.dae", kFileNormals, -1.0},
                               Model{"fandisk.obj", 40.0, 40.0}, Model{"hard/no-normals/cube.obj", kFileNormals, 30.0},
                               Model{"hard/no-normals/cylinder.obj", kFileNormals, 30.0},
                               Model{"hard/no-normals/part.obj", kFileNormals, 30.0},
                               Model{"hard/no-normals/cage.obj", kFileNormals, 30.0}}) {
        const std::string file = test::asset(model.file);
        const bool obj = model.file.find(".obj") != std::string::npos;
        ref::SceneMesh scene;
        if (obj) {
            const ref::Mesh read = ref::read_mesh(file);
            scene.positions = read.positions;
            scene.faces = read.faces;
        } else {
            scene = model.file.find(".dae") != std::string::npos ? ref::read_collada(file) : ref::read_gltf1(file);
        }
        if (model.reference_angle >= 0.0) scene.normals = ref::auto_smooth_normals(scene.positions, scene.faces, model.reference_angle);
        ref::Mesh reference;
        reference.positions = scene.positions;
        reference.faces = scene.faces;
        reference.normals.assign(scene.positions.size(), glm::dvec3(0, 0, 1)); // unused: corner normals shade

        SurfaceOptions surface;
        surface.sharp_angle = model.sharp_angle;
        const ProductScene product_scene(file, surface);
        ASSERT_TRUE(product_scene.split.has_value()) << file;
        const SnaxelEngine& engine = product_scene.engine;
        const RayScene& rays = product_scene.rays;
        ViewSeries views(11, framing(reference.positions));
        double least[2] = {1.0, 1.0};
        for (int view = 0; view < 6; ++view) {
            const auto [v, to_light] = views.next(view, [](const glm::dvec3&) { return true; });
            const std::vector<int> truth = ref::class_image(reference, v, to_light, {k}, &scene.normals);
            const ProductView product(engine, v, to_light, k);
            for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
                const PlanarMap map = product.map(kind, engine, rays);
                const Agreement a = agreement(map, test::rasterize_regions(map.regions, kSize, kSize), truth, k);
                const int which = kind == PlanarMapKind::Snaxel ? 0 : 1;
                least[which] = std::min(least[which], a.fraction());
                EXPECT_GE(a.fraction(), 0.97)
                    << model.file << " view " << view << " " << planar_map_kind_name(kind);
            }
        }
        std::printf("%s: least agreement over 6 views: snaxel map %.2f%%, post map %.2f%%\n", model.file.c_str(),
                    100 * least[0], 100 * least[1]);
    }
}

namespace snaxels {
namespace {

// Objects and materials (#36, done-when 1): on the milk truck (glTF 1.0),
// a Blender scene of four objects and five materials as Collada and as a
// multi-material OBJ, and three teapots of three materials saved by 3ds
// Max's Collada exporter (Assimp's test model: <polygons>, decimal commas,
// Z up, centimetres, the file's own smooth normals), every region of both maps
// shows one material, and per pixel the region's material and shading
// class (shadow, lit, a band at k = 0.75: what fill="material" colours in
// the toon and clip-art presets) are the reference rasterizer's (its own
// reading of the file's faces, materials and corner normals, its own
// z-buffer) on at least 97% of the mesh's pixels, in 10 views.
TEST(PlanarMaps, RegionsShowOneMaterialEach) {
    constexpr int kSize = 512;
    const double k = 0.75;
    for (const std::string name : {"hard/CesiumMilkTruck.gltf", "parts/parts.dae", "parts/parts.obj", "hard/teapots.dae"}) {
        const std::string file = test::asset(name);
        const ref::SceneMesh scene = name.find(".dae") != std::string::npos   ? ref::read_collada(file)
                                     : name.find(".obj") != std::string::npos ? ref::read_obj_parts(file)
                                                                              : ref::read_gltf1(file);
        ref::Mesh reference;
        reference.positions = scene.positions;
        reference.faces = scene.faces;
        reference.normals.assign(scene.positions.size(), glm::dvec3(0, 0, 1)); // unused: corner normals shade

        const ProductScene product_scene(file, SurfaceOptions{});
        const MeshTopology& topo = product_scene.topo;
        ASSERT_TRUE(topo.parts() && topo.parts()->several()) << name;
        const SnaxelEngine& engine = product_scene.engine;
        const RayScene& rays = product_scene.rays;
        ViewSeries views(36, framing(reference.positions));
        double least[2] = {1.0, 1.0};
        for (int view = 0; view < 10; ++view) {
            // From above the ground, as a scene is seen: looking down, so
            // the eye is above the framing centre and the ground (y = 0).
            const auto [v, to_light] = views.next(view, [](const glm::dvec3& dir) { return dir.y < 0.0; });
            std::vector<int> faces;
            const std::vector<int> truth = ref::class_image(reference, v, to_light, {k}, &scene.normals, &faces);
            const ProductView product(engine, v, to_light, k);
            for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
                const PlanarMap map = product.map(kind, engine, rays);
                for (const MapRegion& r : map.regions) ASSERT_GE(r.material, 0) << "a region of no material, area " << r.area << " class " << int(r.cls) << " " << planar_map_kind_name(kind) << " view " << view;
                const std::vector<int> image = test::rasterize_regions(map.regions, kSize, kSize);
                std::size_t mesh_pixels = 0, agree = 0, class_off = 0, material_off = 0;
                // With SNAXELS_DEBUG_MAP_DIR: an image of the misses (red no
                // region, blue another class, green another material).
                std::vector<unsigned char> debug(std::size_t(kSize) * kSize * 3, 255);
                for (std::size_t at = 0; at < truth.size(); ++at) {
                    if (truth[at] < 0) continue;
                    ++mesh_pixels;
                    const int r = image[at];
                    unsigned char* px = &debug[at * 3];
                    px[0] = 255, px[1] = px[2] = 0;
                    if (r < 0) continue;
                    const MapRegion& region = map.regions[std::size_t(r)];
                    const std::string& material = topo.parts()->materials[std::size_t(region.material)].name;
                    const bool same_class = test::region_class_index(region, {k}) == truth[at];
                    const bool same_material = material == scene.face_material[std::size_t(faces[at])];
                    agree += same_class && same_material;
                    class_off += !same_class;
                    material_off += !same_material;
                    if (same_class && same_material) px[0] = px[1] = px[2] = (unsigned char)(60 + 60 * truth[at]);
                    else if (!same_material) px[0] = px[2] = 0, px[1] = 200;
                    else px[0] = px[1] = 0, px[2] = 255;
                }
                if (const char* dir = getenv("SNAXELS_DEBUG_MAP_DIR")) {
                    const std::string out_path = std::string(dir) + "/" + test::test_name(name) + "-" + std::to_string(view) + "-" +
                                                 planar_map_kind_name(kind) + ".ppm";
                    if (FILE* out = std::fopen(out_path.c_str(), "wb")) {
                        std::fprintf(out, "P6 %d %d 255\n", kSize, kSize);
                        std::fwrite(debug.data(), 1, debug.size(), out);
                        std::fclose(out);
                    }
                }
                const double fraction = mesh_pixels ? double(agree) / double(mesh_pixels) : 0.0;
                std::printf("%s view %d, %s map: %zu mesh pixels, %zu of another class, %zu of another material: %.2f%%\n",
                            name.c_str(), view, planar_map_kind_name(kind), mesh_pixels, class_off, material_off, 100 * fraction);
                const int which = kind == PlanarMapKind::Snaxel ? 0 : 1;
                least[which] = std::min(least[which], fraction);
                EXPECT_GE(fraction, 0.97) << name << " view " << view << " " << planar_map_kind_name(kind);
            }
        }
        std::printf("%s: least agreement of material and class over 10 views: snaxel map %.2f%%, post map %.2f%%\n",
                    name.c_str(), 100 * least[0], 100 * least[1]);
    }
}

} // namespace
} // namespace snaxels

namespace snaxels {
namespace {

// Where objects meet (#55, done-when 1): on Blender scenes of objects
// resting on, sunk into and passing through each other (five to seven
// materials each), and one of objects apart (where the maps' own outlines
// alone part them), in 10 views from above of each of two series, in both
// maps, every object covering at least 200 pixels has at least 97% of its
// pixels in regions of its own material, by the reference rasterizer's
// z-buffer (its own Collada reader). The figure is per object, the worst
// first: an image's average hides a small object filled with its
// neighbour's colour. (Over 160 views of each scene from other series the
// worst object read 97.5%: a ring sunk into a slab, in the post map.)
TEST(PlanarMaps, EveryObjectShowsItsOwnMaterial) {
    constexpr int kSize = 512;
    const double k = 0.75;
    const int views = getenv("SNAXELS_MAP_VIEWS") ? std::atoi(getenv("SNAXELS_MAP_VIEWS")) : 10;
    for (const std::string name : {"meet/still-life.dae", "meet/sunk.dae", "meet/crossing.dae", "meet/apart.dae"}) {
        const std::string file = test::asset(name);
        const ref::SceneMesh scene = ref::read_collada(file);
        ref::Mesh reference;
        reference.positions = scene.positions;
        reference.faces = scene.faces;
        reference.normals.assign(scene.positions.size(), glm::dvec3(0, 0, 1)); // unused: corner normals shade
        const ProductScene product_scene(file, SurfaceOptions{});
        const MeshTopology& topo = product_scene.topo;
        ASSERT_TRUE(topo.parts() && topo.parts()->several()) << name;
        double worst[2] = {1.0, 1.0};
        std::string worst_what[2];
        for (const unsigned seed : {55u, 58u}) {
            ViewSeries series(seed, framing(reference.positions));
            for (int view = 0; view < views; ++view) {
                const auto [v, to_light] = series.next(view, [](const glm::dvec3& dir) { return dir.y < -0.2; });
                std::vector<int> faces;
                const std::vector<int> truth = ref::class_image(reference, v, to_light, {k}, &scene.normals, &faces);
                const ProductView product(product_scene.engine, v, to_light, k);
                for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
                    const PlanarMap map = product.map(kind, product_scene.engine, product_scene.rays);
                    const std::vector<int> image = test::rasterize_regions(map.regions, kSize, kSize);
                    std::map<std::string, std::pair<std::size_t, std::size_t>> per_object; // pixels, own material
                    // With SNAXELS_DEBUG_MAP_DIR: the misses in red (another
                    // material) and black (no region), the rest grey by class.
                    std::vector<unsigned char> debug(std::size_t(kSize) * kSize * 3, 255);
                    for (std::size_t at = 0; at < truth.size(); ++at) {
                        if (truth[at] < 0) continue;
                        debug[at * 3] = debug[at * 3 + 1] = debug[at * 3 + 2] = 0;
                        auto& [pixels, own] = per_object[scene.face_object[std::size_t(faces[at])]];
                        ++pixels;
                        const int r = image[at];
                        if (r < 0 || map.regions[std::size_t(r)].material < 0) continue;
                        const std::string& got = topo.parts()->materials[std::size_t(map.regions[std::size_t(r)].material)].name;
                        own += got == scene.face_material[std::size_t(faces[at])];
                        if (got == scene.face_material[std::size_t(faces[at])])
                            debug[at * 3] = debug[at * 3 + 1] = debug[at * 3 + 2] = (unsigned char)(90 + 50 * truth[at]);
                        else
                            debug[at * 3] = 255;
                    }
                    if (const char* dir = getenv("SNAXELS_DEBUG_MAP_DIR")) {
                        const std::string out_path = std::string(dir) + "/" + test::test_name(name) + "-objects-" +
                                                     std::to_string(seed) + "-" + std::to_string(view) + "-" +
                                                     planar_map_kind_name(kind) + ".ppm";
                        if (FILE* out = std::fopen(out_path.c_str(), "wb")) {
                            std::fprintf(out, "P6 %d %d 255\n", kSize, kSize);
                            std::fwrite(debug.data(), 1, debug.size(), out);
                            std::fclose(out);
                        }
                    }
                    const int which = kind == PlanarMapKind::Snaxel ? 0 : 1;
                    for (const auto& [object, counts] : per_object) {
                        if (counts.first < 200) continue;
                        const double share = double(counts.second) / double(counts.first);
                        if (share < worst[which]) {
                            worst[which] = share;
                            worst_what[which] = object + " in view " + std::to_string(seed) + "/" + std::to_string(view) +
                                                " (" + std::to_string(counts.first) + " px)";
                        }
                        EXPECT_GE(share, 0.97) << name << " " << object << " view " << seed << "/" << view << " "
                                               << planar_map_kind_name(kind) << ": " << counts.second << " of " << counts.first
                                               << " px";
                    }
                }
            }
        }
        std::printf("%s: the worst object, snaxel map %.2f%% (%s), post map %.2f%% (%s)\n", name.c_str(), 100 * worst[0],
                    worst_what[0].c_str(), 100 * worst[1], worst_what[1].c_str());
    }
}

} // namespace
} // namespace snaxels
