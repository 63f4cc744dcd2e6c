// snaxels-quality: every independent check of the test suite, run on one
// asset of the quality corpus (scripts/quality.sh, docs/quality.md), its
// figures written as one JSON object per view so that the report can name
// the worst asset and view of each check.
//
//   snaxels-quality ASSET [--views N] [--frames N] [--pictures DIR] [--no-export]
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
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/brute_force_contour.h"
#include "snaxels/animation/frame_driver.h"
#include "snaxels/animation/pipeline.h"
#include "snaxels/animation/scene_settings.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/mesh/sharp_edges.h"
#include "tests/support/rtsc_compare.h"
#include "tests/support/silhouette_oracle.h"

using namespace snaxels;
using nlohmann::json;

namespace {

struct Options {
    std::string asset;
    int views = 6;       ///< orthographic views of the outline and QI checks
    int sugg_views = 4;  ///< perspective views of the suggestive check
    int frames = 24;     ///< frames of the export check
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

json export_cost(const Options& o, const LoadedMesh& loaded, const std::string& path) {
    AnimationJob job;
    job.scene = scene_settings(default_style(), Camera{}, {});
    job.scene.engine.check_invariants = false;
    std::vector<AnimationClipInfo> clips;
    if (!path.starts_with("proc:")) {
        try {
            clips = animation_clips(path);
        } catch (const std::exception&) {
        }
    }
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
    if (o.do_export) timed("export", [&] { return export_cost(o, loaded, o.asset); });
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
        else if (a == "--pictures") o.pictures = value();
        else if (a == "--no-export") o.do_export = false;
        else if (!a.empty() && a[0] == '-') {
            std::fprintf(stderr, "snaxels-quality: unknown option %s\n", a.c_str());
            return 2;
        } else o.asset = a;
    }
    if (o.asset.empty()) {
        std::fprintf(stderr, "usage: snaxels-quality ASSET [--views N] [--suggestive-views N] [--frames N] [--pictures DIR] [--no-export]\n");
        return 2;
    }
    try {
        return run(o);
    } catch (const std::exception& e) {
        std::printf("%s\n", json({{"asset", o.asset}, {"error", e.what()}}).dump().c_str());
        return 1;
    }
}
