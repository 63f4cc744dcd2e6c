// snaxels-quality: every independent check of the test suite, run on one
// asset of the quality corpus (scripts/quality.sh, docs/quality.md), its
// figures written as one JSON object per view so that the report can name
// the worst asset and view of each check.
//
//   snaxels-quality ASSET [--views N] [--frames N] [--motion-frames N] [--pictures DIR] [--no-export]
//
// The checks, each against an oracle that shares no code with the product:
//   outline     the visible visual contour against the faceted mesh's visible
//               silhouette edges (tests/support/silhouette_oracle.h): the share
//               of the silhouette drawn within 2 px (coverage) and of the drawing
//               within 2 px of it (precision), per orthographic view;
//   qi          the visual contour's QI against the same z-buffer, where clear;
//   suggestive  the drawn suggestive contours (the default test) against
//               DeCarlo et al.'s test computed by tests/support/rtsc_oracle.h,
//               both ways within 0.5% of the diagonal, per perspective view;
//   maps        the snaxel and post planar maps against a z-buffer of the
//               triangles: per object, the share of its pixels in a region
//               of its own material and of the shading class the pixel sees
//               (the file's corner normals, else faces smoothed within 30
//               degrees), per orthographic view; the worst object;
//   motion      the export seeked half way between frames (and at them)
//               against the export at half the step at that moment, read
//               from both SVGs as a player reads them (tests/support/
//               svg_player.h); persistence of the strokes' paths;
//   export      a turntable (or the file's first clip) exported as
//               `snaxels-cli animate` does, with hidden lines and the default
//               style: its time per frame against brute-force marching
//               triangles of the visual contour on the same frames, its bytes.
// The oracles read the triangles the product imported (Assimp): no
// independent reader exists for the corpus's forty formats; the bundled
// OBJ, PLY, glTF and Collada files are also read independently by the
// test suite's own checks.

#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <filesystem>
#include <limits>
#include <map>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pugixml.hpp>

#include "bench/brute_force_contour.h"
#include "snaxels/animation/frame_driver.h"
#include "snaxels/animation/pipeline.h"
#include "snaxels/animation/scene_settings.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/mesh/sharp_edges.h"
#include "snaxels/planarmap/planar_map.h"
#include "tests/support/map_raster.h"
#include "tests/support/reference_raster.h"
#include "tests/support/rtsc_compare.h"
#include "tests/support/silhouette_oracle.h"
#include "tests/support/svg_player.h"

using namespace snaxels;
using nlohmann::json;

namespace {

struct Options {
    std::string asset;
    int views = 6;       ///< orthographic views of the outline and QI checks
    int sugg_views = 4;  ///< perspective views of the suggestive check
    int frames = 24;     ///< frames of the export check
    int motion_frames = 12; ///< frames of the motion check's coarse export
    std::string pictures; ///< folder for each outline view's picture
    bool do_export = true;
};

double ms_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// The imported triangles as the oracle's plain mesh.
ref::SceneMesh oracle_mesh(const LoadedMesh& loaded) {
    ref::SceneMesh m;
    for (const auto vh : loaded.mesh.vertices()) {
        const auto p = loaded.mesh.point(vh);
        m.positions.push_back({p[0], p[1], p[2]});
    }
    for (const auto fh : loaded.mesh.faces()) {
        std::array<int, 3> f{};
        int k = 0;
        for (const auto vh : loaded.mesh.fv_range(fh))
            if (k < 3) f[std::size_t(k++)] = vh.idx();
        m.faces.push_back(f);
    }
    return m;
}


void write_ppm(const std::string& path, const std::vector<std::uint8_t>& rgb, int size) {
    std::ofstream out(path, std::ios::binary);
    out << "P6 " << size << ' ' << size << " 255\n";
    out.write(reinterpret_cast<const char*>(rgb.data()), std::streamsize(rgb.size()));
}

json outline_and_qi(const Options& o, const ref::SceneMesh& oracle, const MeshTopology& topo) {
    const RayScene rays(topo);
    json views = json::array();
    int i = 0;
    for (const glm::dvec3& dir : test::silhouette::fibonacci_directions(o.views)) {
        std::vector<std::uint8_t> picture;
        const test::silhouette::Score s = test::silhouette::score_view(oracle, topo, rays, dir, o.pictures.empty() ? nullptr : &picture);
        if (!o.pictures.empty()) write_ppm(o.pictures + "/outline-" + std::to_string(i) + ".ppm", picture, test::silhouette::kSize);
        views.push_back({{"view", i++},
                         {"dir", {dir.x, dir.y, dir.z}},
                         {"silhouette_samples", s.silhouette},
                         {"drawn_samples", s.drawn},
                         {"coverage", s.coverage()},
                         {"precision", s.precision()},
                         {"qi_snaxels", s.snaxels},
                         {"qi_agreement", s.agreement()}});
    }
    return views;
}


/// Per face corner, the normal the z-buffer shades with. Where the file
/// gives normals: the file's, unless it leans out of its wedge (the faces at
/// the vertex with the same file normal) by more than 20 degrees beyond the
/// widest of them (as docs/engine.md says the product treats an
/// exporter's normals averaged across a hard edge), then the wedge's
/// area-weighted normal. Without: the mean of the area-weighted normals of
/// the faces at the vertex that turn less than 30 degrees from the face.
std::vector<std::array<glm::dvec3, 3>> oracle_corner_normals(const LoadedMesh& loaded, const ref::SceneMesh& m) {
    std::vector<glm::dvec3> area_normal(m.faces.size());
    std::vector<std::vector<std::pair<int, int>>> at_vertex(m.positions.size()); // face, corner
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const auto& t = m.faces[f];
        area_normal[f] = glm::cross(m.positions[std::size_t(t[1])] - m.positions[std::size_t(t[0])],
                                    m.positions[std::size_t(t[2])] - m.positions[std::size_t(t[0])]);
        for (int k = 0; k < 3; ++k) at_vertex[std::size_t(t[std::size_t(k)])].push_back({int(f), k});
    }
    const bool file = !loaded.corner_normals.empty();
    auto file_normal = [&](int f, int k) { return loaded.corner_normals[std::size_t(f)][std::size_t(k)]; };
    const double cos30 = std::cos(30.0 * M_PI / 180.0);
    std::vector<std::array<glm::dvec3, 3>> out(m.faces.size());
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        const double lf = glm::length(area_normal[f]);
        for (std::size_t k = 0; k < 3; ++k) {
            const glm::dvec3 n = file ? file_normal(int(f), int(k)) : glm::dvec3(0.0);
            const bool given = glm::length(n) > 0.0;
            glm::dvec3 sum(0.0);
            std::vector<glm::dvec3> wedge;
            for (const auto& [g, c] : at_vertex[std::size_t(m.faces[f][k])]) {
                const glm::dvec3& ng = area_normal[std::size_t(g)];
                const double lg = glm::length(ng);
                if (!(lf > 0.0 && lg > 0.0)) continue;
                const bool with = given ? glm::length(file_normal(g, c) - n) < 1e-6
                                        : glm::dot(area_normal[f], ng) >= cos30 * lf * lg;
                if (!with) continue;
                sum += ng;
                wedge.push_back(ng / lg);
            }
            const glm::dvec3 own = glm::length(sum) > 0.0 ? glm::normalize(sum) : glm::dvec3(0, 0, 1);
            out[f][k] = own;
            if (!given) continue;
            double spread = 0.0;
            for (const glm::dvec3& w : wedge) spread = std::max(spread, std::acos(std::clamp(glm::dot(w, own), -1.0, 1.0)));
            const glm::dvec3 un = glm::normalize(n);
            if (wedge.empty() || std::acos(std::clamp(glm::dot(un, own), -1.0, 1.0)) <= spread + 20.0 * M_PI / 180.0)
                out[f][k] = un;
        }
    }
    return out;
}

/// Per pixel of the orthographic view @p v (as ref::class_image projects
/// it): whether a face of another object or material lies within a
/// ten-thousandth of the view's radius of the nearest one's depth, so that
/// which of them shows is a tie (a slab resting on a floor, seen from
/// below): the z-buffer cannot say, and the pixel is not judged.
std::vector<std::uint8_t> tied_pixels(const LoadedMesh& loaded, const ref::Mesh& m, const ref::View& v,
                                      const std::vector<int>& nearest) {
    const glm::dvec3 fwd = glm::normalize(v.dir);
    glm::dvec3 up = glm::normalize(v.up);
    if (std::abs(glm::dot(fwd, up)) > 0.999) up = std::abs(fwd.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(fwd, up)), sup = glm::cross(right, fwd);
    const double scale = (0.5 * std::min(v.width, v.height) - v.margin) / v.radius;
    std::vector<glm::dvec3> pv(m.positions.size()); // pixel x, y, depth
    for (std::size_t i = 0; i < pv.size(); ++i) {
        const glm::dvec3 d = m.positions[i] - v.centre;
        pv[i] = {0.5 * v.width + scale * glm::dot(d, right), 0.5 * v.height - scale * glm::dot(d, sup), glm::dot(d, fwd)};
    }
    const std::size_t n = std::size_t(v.width) * std::size_t(v.height);
    std::vector<double> depth(n, std::numeric_limits<double>::infinity());
    auto each = [&](auto&& fn) {
        for (std::size_t f = 0; f < m.faces.size(); ++f) {
            const glm::dvec3 &a = pv[std::size_t(m.faces[f][0])], &b = pv[std::size_t(m.faces[f][1])], &c = pv[std::size_t(m.faces[f][2])];
            ref::for_each_pixel_in({a.x, a.y}, {b.x, b.y}, {c.x, c.y}, v.width, v.height, [&](int x, int y, double wa, double wb, double wc) {
                fn(f, std::size_t(y) * std::size_t(v.width) + std::size_t(x), wa * a.z + wb * b.z + wc * c.z);
            });
        }
    };
    each([&](std::size_t, std::size_t at, double z) { depth[at] = std::min(depth[at], z); });
    const bool parts = !loaded.face_material.empty();
    std::vector<std::uint8_t> tied(n, 0);
    const double tolerance = 1e-4 * v.radius;
    each([&](std::size_t f, std::size_t at, double z) {
        if (nearest[at] < 0 || z > depth[at] + tolerance || !parts) return;
        const std::size_t g = std::size_t(nearest[at]);
        if (loaded.face_object[f] != loaded.face_object[g] || loaded.face_material[f] != loaded.face_material[g]) tied[at] = 1;
    });
    return tied;
}

/// The planar maps (snaxel and post) against a z-buffer of the imported
/// triangles, per orthographic view lit from near the viewer: per object
/// (200 px or more), the share of its pixels whose region has the object's
/// own material, and the share whose region has the shading class (shadow,
/// lit, the band at N.L 0.75) of the surface the pixel sees. Pixels where
/// two objects or materials tie for the nearest are left out.
json maps(const Options& o, const LoadedMesh& loaded, const ref::SceneMesh& oracle, const MeshTopology& topo) {
    constexpr int kSize = 400;
    constexpr double kBand = 0.75;
    const SnaxelEngine engine(topo);
    const RayScene rays(topo);
    ref::Mesh reference;
    reference.positions = oracle.positions;
    reference.faces = oracle.faces;
    reference.normals.assign(oracle.positions.size(), glm::dvec3(0, 0, 1)); // unused: corner normals shade
    const std::vector<std::array<glm::dvec3, 3>> corners = oracle_corner_normals(loaded, oracle);
    glm::dvec3 lo(1e300), hi(-1e300);
    for (const glm::dvec3& p : oracle.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const bool parts = !loaded.face_material.empty() && topo.parts();
    json views = json::array();
    int i = 0;
    for (const glm::dvec3& dir : test::silhouette::fibonacci_directions(o.views)) {
        ref::View v;
        v.orthographic = true;
        v.dir = dir, v.centre = 0.5 * (lo + hi), v.radius = 0.5 * glm::length(hi - lo);
        v.width = v.height = kSize, v.margin = 16.0, v.target = v.centre, v.eye = v.centre - 2.5 * v.radius * dir;
        v.up = std::abs(dir.y) > 0.95 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
        const glm::dvec3 side = glm::normalize(glm::cross(dir, v.up));
        const glm::dvec3 to_light = glm::normalize(-dir + 0.6 * side + 0.4 * v.up);
        std::vector<int> faces;
        const std::vector<int> truth = ref::class_image(reference, v, to_light, {kBand}, &corners, &faces);
        const std::vector<std::uint8_t> tied = tied_pixels(loaded, reference, v, faces);
        Camera cam;
        cam.projection = Camera::Projection::Orthographic;
        cam.view_dir = v.dir, cam.eye = v.eye, cam.target = v.target, cam.up = v.up;
        Light light;
        light.dir = to_light;
        const ImageProjection proj(cam, v.centre, v.radius, kSize, kSize, v.margin);
        const ContourResult visual = engine.compute({}, cam, light), shadow = engine.compute({ContourKind::Shadow, 0.0}, cam, light),
                            iso = engine.compute({ContourKind::Isophote, kBand}, cam, light);
        json entry = {{"view", i++}, {"dir", {dir.x, dir.y, dir.z}}};
        for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
            const PlanarMap map = build_planar_map(kind, engine, {&visual, &shadow, &iso}, &rays, proj, cam, light);
            const std::vector<int> image = test::rasterize_regions(map.regions, kSize, kSize);
            struct Counts {
                std::size_t pixels = 0, material = 0, cls = 0;
            };
            std::map<std::uint32_t, Counts> per_object;
            // The picture: grey by the z-buffer's class where the map agrees,
            // red where its class differs, blue where its material does,
            // black where no region covers a pixel of the mesh.
            std::vector<std::uint8_t> picture(truth.size() * 3, 255);
            for (std::size_t at = 0; at < truth.size(); ++at) {
                if (truth[at] < 0 || tied[at]) continue;
                std::uint8_t* px = &picture[3 * at];
                px[0] = px[1] = px[2] = std::uint8_t(std::min(200, 90 + 50 * truth[at]));
                if (image[at] < 0) px[0] = px[1] = px[2] = 0;
                const std::size_t f = std::size_t(faces[at]);
                Counts& c = per_object[parts ? loaded.face_object[f] : 0];
                ++c.pixels;
                const int r = image[at];
                if (r < 0) continue;
                const MapRegion& region = map.regions[std::size_t(r)];
                const bool own = !parts || (region.material >= 0 && std::uint32_t(region.material) == loaded.face_material[f]);
                const bool cls = test::region_class_index(region, {kBand}) == truth[at];
                c.material += own;
                c.cls += cls;
                if (!cls) px[0] = 255, px[1] = px[2] = 0;
                if (!own) px[0] = px[1] = 0, px[2] = 255;
            }
            const std::string prefix = kind == PlanarMapKind::Snaxel ? "snaxel_" : "post_";
            if (!o.pictures.empty()) write_ppm(o.pictures + "/" + prefix + "map-" + std::to_string(i - 1) + ".ppm", picture, kSize);
            double worst_material = 1.0, worst_class = 1.0;
            std::string material_object, class_object;
            for (const auto& [object, c] : per_object) {
                if (c.pixels < 200) continue;
                const std::string name = parts && object < loaded.objects.size() ? loaded.objects[object].name : "";
                const double m = double(c.material) / double(c.pixels), k = double(c.cls) / double(c.pixels);
                if (m < worst_material) worst_material = m, material_object = name;
                if (k < worst_class) worst_class = k, class_object = name;
            }
            entry[prefix + "material"] = worst_material;
            entry[prefix + "material_object"] = material_object;
            entry[prefix + "class"] = worst_class;
            entry[prefix + "class_object"] = class_object;
        }
        views.push_back(entry);
    }
    return views;
}

/// A picture of one suggestive view (PPM, kSize square): the oracle's lines
/// in blue, the product's in red, where they coincide black; the mesh's
/// bounding box fitted.
void write_suggestive_picture(const std::string& path, const Camera& cam, const glm::dvec3& centre, double diag,
                              const std::vector<test::RtscSegment>& oracle, const std::vector<test::RtscSegment>& product) {
    constexpr int kSize = test::silhouette::kSize;
    const glm::dvec3 fwd = glm::normalize(centre - cam.eye);
    const glm::dvec3 up = std::abs(fwd.y) > 0.95 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(fwd, up)), sup = glm::cross(right, fwd);
    const double depth = glm::dot(centre - cam.eye, fwd), scale = (0.5 * kSize - 16.0) * depth / (0.5 * diag);
    std::vector<std::uint8_t> rgb(std::size_t(kSize) * kSize * 3, 255);
    auto draw = [&](const std::vector<test::RtscSegment>& segments, int channel) {
        for (const test::RtscSegment& s : segments) {
            auto px = [&](const glm::dvec3& p) {
                const glm::dvec3 d = p - cam.eye;
                const double z = std::max(1e-9, glm::dot(d, fwd));
                return glm::dvec2(0.5 * kSize + scale * glm::dot(d, right) / z, 0.5 * kSize - scale * glm::dot(d, sup) / z);
            };
            const glm::dvec2 a = px(s.a), b = px(s.b);
            const int n = std::max(1, int(std::ceil(glm::length(b - a) * 2.0)));
            for (int i = 0; i <= n; ++i) {
                const glm::dvec2 q = a + (b - a) * (double(i) / n);
                const int x = int(q.x), y = int(q.y);
                if (x < 0 || y < 0 || x >= kSize || y >= kSize) continue;
                std::uint8_t* c = &rgb[std::size_t(3 * (y * kSize + x))];
                for (int k = 0; k < 3; ++k)
                    if (k != channel) c[k] = 0; // blue and red over each other: black
            }
        }
    };
    draw(oracle, 2);
    draw(product, 0);
    write_ppm(path, rgb, kSize);
}

json suggestive(const Options& o, const LoadedMesh& loaded, const MeshTopology& topo) {
    const SnaxelEngine engine(topo);
    const test::RtscMesh rm = test::rtsc_mesh_of(topo);
    const test::RtscCurvature k = test::rtsc_curvature(rm, 2);
    const glm::dvec3 centre = loaded.report.centre();
    const double diag = glm::length(loaded.report.bbox_max - loaded.report.bbox_min);
    const double reach = 0.005 * diag;
    const ContourSpec spec = ContourSpec::parse("suggestive");
    std::mt19937 rng(40);
    std::normal_distribution<double> gauss;
    json views = json::array();
    for (int i = 0; i < o.sugg_views; ++i) {
        Camera cam;
        cam.projection = Camera::Projection::Perspective;
        cam.target = centre;
        cam.eye = centre + 1.6 * diag * glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
        const std::vector<test::RtscSegment> oracle = test::rtsc_suggestive(rm, k, cam.eye, spec.k);
        const std::vector<test::RtscSegment> product = test::drawn_suggestive_segments(engine, engine.compute(spec, cam, Light{}));
        const test::SegmentIndex oracle_index(oracle, reach), product_index(product, reach);
        const auto [np, tp] = test::length_near(product, oracle_index, reach);
        const auto [no, to] = test::length_near(oracle, product_index, reach);
        if (!o.pictures.empty())
            write_suggestive_picture(o.pictures + "/suggestive-" + std::to_string(i) + ".ppm", cam, centre, diag, oracle, product);
        views.push_back({{"view", i},
                         {"eye", {cam.eye.x, cam.eye.y, cam.eye.z}},
                         {"product_length", tp / diag},
                         {"oracle_length", to / diag},
                         {"precision", tp > 0 ? np / tp : 1.0},
                         {"recall", to > 0 ? no / to : 1.0}});
    }
    return views;
}

/// Stroke polylines of an animated SVG as a player draws them at normalized
/// time @p t, resampled at most a pixel apart.
std::vector<glm::dvec2> stroke_samples(const pugi::xml_document& doc, double t) {
    std::vector<std::vector<test::svg::Pt>> lines;
    test::svg::strokes_at(doc.child("svg"), t, lines);
    std::vector<glm::dvec2> out;
    for (const auto& line : lines)
        for (std::size_t k = 0; k < line.size(); ++k) {
            const glm::dvec2 b(line[k].x, line[k].y);
            if (k == 0) {
                out.push_back(b);
                continue;
            }
            const glm::dvec2 a(line[k - 1].x, line[k - 1].y);
            const int n = std::max(1, int(std::ceil(glm::length(b - a))));
            for (int j = 1; j <= n; ++j) out.push_back(a + (b - a) * (double(j) / n));
        }
    return out;
}

/// The share of @p samples within @p reach pixels of one of @p others.
double share_near(const std::vector<glm::dvec2>& samples, const std::vector<glm::dvec2>& others, double reach) {
    if (samples.empty()) return others.empty() ? 1.0 : 0.0;
    std::map<std::pair<long, long>, std::vector<glm::dvec2>> grid;
    auto cell = [&](const glm::dvec2& p) { return std::pair<long, long>(long(std::floor(p.x / reach)), long(std::floor(p.y / reach))); };
    for (const glm::dvec2& q : others) grid[cell(q)].push_back(q);
    std::size_t near = 0;
    for (const glm::dvec2& p : samples) {
        const auto [cx, cy] = cell(p);
        bool found = false;
        for (long dx = -1; dx <= 1 && !found; ++dx)
            for (long dy = -1; dy <= 1 && !found; ++dy) {
                const auto it = grid.find({cx + dx, cy + dy});
                if (it == grid.end()) continue;
                for (const glm::dvec2& q : it->second)
                    if (glm::length(q - p) <= reach) {
                        found = true;
                        break;
                    }
            }
        near += found;
    }
    return double(near) / double(samples.size());
}

/// Per stroke path of an animated SVG of @p frames frames: the frames it is
/// shown and its length over them.
std::vector<std::pair<int, double>> stroke_lives(pugi::xml_node node, int frames) {
    std::vector<std::pair<int, double>> out;
    test::svg::for_each_stroke_path(node, [&](pugi::xml_node path) {
        std::pair<int, double> life{0, 0.0};
        for (int f = 0; f < frames; ++f) {
            if (!test::svg::shown_at(path, (f + 0.5) / frames)) continue;
            ++life.first;
            life.second += test::svg::length_of(test::svg::flatten(test::svg::shape_at(path, (f + 0.01) / frames)));
        }
        if (life.first > 0) out.push_back(life);
    });
    return out;
}

/// Motion, read from the exported SVGs as a player reads them: the
/// animation exported at a coarse step (4 degrees a frame, or the file's
/// first clip at 24 fps) seeked half way between each two frames, against
/// the export at half the step (2 degrees, 48 fps) at that moment; both
/// ways, the share of stroke samples within 2 px of the other's, at 400 x
/// 400 px. At frame times the same. Persistence, of the fine export: the
/// share of stroke length x frames carried by paths shown at least half the
/// frames, and the share of stroke paths shown one frame only.
json motion(const Options& o, const LoadedMesh& loaded, const std::string& path, const std::vector<AnimationClipInfo>& clips) {
    const int coarse_frames = clips.empty() ? o.motion_frames
                                            : std::min(o.motion_frames, std::max(2, clip_frame_count(clips.front().duration, 24.0)));
    auto export_at = [&](int frames, double step, double fps) {
        AnimationJob job;
        job.scene = scene_settings(default_style(), Camera{}, {});
        job.scene.engine.check_invariants = false;
        job.scene.style.width = job.scene.style.height = 400;
        job.animation.kind = clips.empty() ? AnimationSpec::Kind::Turntable : AnimationSpec::Kind::Clip;
        job.animation.frames = frames;
        job.animation.degrees_per_frame = step;
        job.animation.fps = fps;
        const AnimationOutput out = run_animation(loaded, path, job);
        auto doc = std::make_unique<pugi::xml_document>();
        if (!doc->load_string(out.document.c_str())) throw std::runtime_error("the exported SVG is not readable XML");
        return doc;
    };
    const auto coarse = export_at(coarse_frames, 4.0, 24.0);
    const auto fine = export_at(2 * coarse_frames, 2.0, 48.0);
    const int fine_frames = 2 * coarse_frames;
    double worst_half = 1.0, worst_at = 1.0;
    int worst_half_frame = 0, worst_at_frame = 0;
    for (int f = 0; f + 1 < coarse_frames; ++f) {
        const std::vector<glm::dvec2> half = stroke_samples(*coarse, (f + 0.5) / coarse_frames),
                                      truth = stroke_samples(*fine, (2 * f + 1 + 0.01) / fine_frames);
        const double h = std::min(share_near(half, truth, 2.0), share_near(truth, half, 2.0));
        if (h < worst_half) worst_half = h, worst_half_frame = f;
        const std::vector<glm::dvec2> at = stroke_samples(*coarse, (f + 0.01) / coarse_frames),
                                      at_truth = stroke_samples(*fine, (2 * f + 0.01) / fine_frames);
        const double a = std::min(share_near(at, at_truth, 2.0), share_near(at_truth, at, 2.0));
        if (a < worst_at) worst_at = a, worst_at_frame = f;
    }
    double total = 0.0, carried = 0.0;
    std::size_t one_frame = 0;
    const auto lives = stroke_lives(fine->child("svg"), fine_frames);
    for (const auto& [shown, length] : lives) {
        total += length;
        if (2 * shown >= fine_frames) carried += length;
        one_frame += shown == 1;
    }
    return {{"source", clips.empty() ? "turntable" : "clip"},
            {"frames", coarse_frames},
            {"half_way", worst_half},
            {"half_way_frame", worst_half_frame},
            {"at_frames", worst_at},
            {"at_frames_frame", worst_at_frame},
            {"stroke_paths", lives.size()},
            {"carried", total > 0 ? carried / total : 1.0},
            {"one_frame", lives.empty() ? 0.0 : double(one_frame) / double(lives.size())}};
}

json export_cost(const Options& o, const LoadedMesh& loaded, const std::string& path, const std::vector<AnimationClipInfo>& clips) {
    AnimationJob job;
    job.scene = scene_settings(default_style(), Camera{}, {});
    job.scene.engine.check_invariants = false;
    job.animation.frames = o.frames;
    if (!clips.empty()) {
        job.animation.kind = AnimationSpec::Kind::Clip;
        job.animation.frames = std::min(o.frames, std::max(2, clip_frame_count(clips.front().duration, 24.0)));
    } else {
        job.animation.kind = AnimationSpec::Kind::Turntable;
        job.animation.degrees_per_frame = 360.0 / o.frames;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const AnimationOutput out = run_animation(loaded, path, job);
    const double export_ms = ms_since(t0);
    json result = {{"kind", clips.empty() ? "turntable" : "clip"},
                   {"frames", job.animation.frames},
                   {"bytes", out.document.size()},
                   {"export_ms_per_frame", export_ms / job.animation.frames}};
    if (!clips.empty()) return result; // brute force has no posed meshes: the turntable's ratio only
    std::optional<LoadedMesh> split;
    const MeshTopology topo = engine_topology(scene_surface(loaded, job.scene.style, split));
    const glm::dvec3 centre = loaded.report.centre();
    double brute_ms = 0.0;
    for (int f = 0; f < job.animation.frames; ++f) {
        const Camera cam = camera_at_frame(job.animation, job.scene.camera, nullptr, f, centre);
        const auto t1 = std::chrono::steady_clock::now();
        const auto r = bench::marching_triangles(topo, ContourFunction({}, cam, default_light(cam)), 1);
        if (r.points.size() == std::size_t(-1)) std::puts(""); // keep the work
        brute_ms += ms_since(t1);
    }
    result["brute_ms_per_frame"] = brute_ms / job.animation.frames;
    result["ratio"] = brute_ms > 0 ? export_ms / brute_ms : 0.0;
    return result;
}

int run(const Options& o) {
    json report = {{"asset", o.asset}};
    const auto t0 = std::chrono::steady_clock::now();
    const LoadedMesh loaded = load_mesh(o.asset);
    report["load_ms"] = ms_since(t0);
    report["faces"] = loaded.report.faces;
    report["objects"] = loaded.objects.size();
    report["file_normals"] = !loaded.corner_normals.empty();
    SharpSplit sharp;
    const std::optional<LoadedMesh> split = split_sharp_edges(loaded, SurfaceOptions{}, &sharp);
    const LoadedMesh& surface = split ? *split : loaded;
    report["sharp_edges"] = sharp.sharp_edges;
    const MeshTopology topo = engine_topology(surface);
    report["engine_faces"] = topo.n_faces();
    const ref::SceneMesh oracle = oracle_mesh(loaded);
    auto timed = [&](const char* name, auto&& fn) {
        const auto t = std::chrono::steady_clock::now();
        report[name] = fn();
        report[std::string(name) + "_ms"] = ms_since(t);
    };
    timed("outline", [&] { return outline_and_qi(o, oracle, topo); });
    timed("suggestive", [&] { return suggestive(o, loaded, topo); });
    timed("maps", [&] { return maps(o, loaded, oracle, topo); });
    if (o.do_export) {
        std::vector<AnimationClipInfo> clips;
        if (!o.asset.starts_with("proc:")) {
            try {
                clips = animation_clips(o.asset);
            } catch (const std::exception&) {
            }
        }
        timed("export", [&] { return export_cost(o, loaded, o.asset, clips); });
        timed("motion", [&] { return motion(o, loaded, o.asset, clips); });
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    report["peak_rss_mb"] = double(usage.ru_maxrss) / 1024.0;
    std::printf("%s\n", report.dump().c_str());
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "snaxels-quality: %s needs a value\n", a.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (a == "--views") o.views = std::stoi(value());
        else if (a == "--suggestive-views") o.sugg_views = std::stoi(value());
        else if (a == "--frames") o.frames = std::max(2, std::stoi(value()));
        else if (a == "--motion-frames") o.motion_frames = std::max(2, std::stoi(value()));
        else if (a == "--pictures") o.pictures = value();
        else if (a == "--no-export") o.do_export = false;
        else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "snaxels-quality: unknown option %s\n", a.c_str());
            return 2;
        } else o.asset = a;
    }
    if (o.asset.empty()) {
        std::fprintf(stderr, "usage: snaxels-quality ASSET [--views N] [--suggestive-views N] [--frames N] [--motion-frames N] [--pictures DIR] [--no-export]\n");
        return 2;
    }
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::printf("%s\n", json({{"asset", o.asset}, {"error", e.what()}}).dump().c_str());
        return 1;
    }
}
