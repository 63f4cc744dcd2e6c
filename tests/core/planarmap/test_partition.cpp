#include <gtest/gtest.h>

#include <random>

#include "snaxels/animation/pipeline.h"
#include "snaxels/animation/still.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/refine.h"
#include "snaxels/style/style.h"
#include "tests/support/assets.h"
#include "tests/support/coverage.h"
#include "tests/support/views.h"

using namespace snaxels;

namespace {

// Every class a map can hold, unstroked and uneroded, so the fills are the
// map's regions as they are.
const char* kStyle = R"(<style version="1">
  <canvas width="512" height="512" margin="16" background="#ffffff"/>
  <region class="shadow" fill="#203040"/>
  <region class="lit" fill="#a0b0c0"/>
  <region class="band" k="0.5" fill="#d0d8e0"/>
  <region class="highlight" k="0.9" fill="#ffffff"/>
  <contour kind="visual"><visible stroke="#000000" width="1"/><hidden draw="false"/></contour>
</style>)";

} // namespace

// Both planar maps are partitions in what the product writes: the regions
// (contours JSON writes them as they are) and the static SVG's fills (their
// outlines simplified and rounded to 0.01 px). Over 10 random views of every
// bundled mesh and the procedural torus and nose, each orthographic and in
// perspective, the samples (4 x 4 per pixel at 512 x 512) inside two or
// more regions are under 0.01% of those inside any.
TEST(PlanarMaps, RegionsArePartitionsInEveryView) {
    const Style style = parse_style(kStyle, "test", nullptr);
    const int views = getenv("SNAXELS_PARTITION_VIEWS") ? std::atoi(getenv("SNAXELS_PARTITION_VIEWS")) : 10;
    std::vector<std::string> files;
    for (const auto& m : test::asset_meshes()) files.push_back(m.file);
    files.push_back("proc:torus:20000");
    files.push_back("proc:nose:20000");
    double worst[2][2] = {{0, 0}, {0, 0}}; // [map][json, svg]
    for (const std::string& file : files) {
        const LoadedMesh mesh = file.rfind("proc:", 0) == 0 ? load_mesh(file) : import_mesh(test::asset(file));
        const MeshTopology topo = engine_topology(mesh.mesh);
        const RayScene rays(topo);
        const glm::dvec3 centre = 0.5 * (mesh.report.bbox_min + mesh.report.bbox_max);
        const double radius = 0.5 * glm::length(mesh.report.bbox_max - mesh.report.bbox_min);
        std::mt19937 rng(101);
        for (int view = 0; view < views; ++view) {
            const Camera ortho = test::random_orthographic_camera(rng);
            Camera persp = ortho;
            persp.projection = Camera::Projection::Perspective;
            persp.target = centre;
            persp.eye = centre - 2.5 * radius * ortho.view_dir;
            for (const Camera& cam : {ortho, persp}) {
                StillJob job = make_still_job(style, cam, std::nullopt);
                job.scene.visibility = false;
                for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
                    job.scene.map_kind = kind;
                    const StillOutput out = render_still(mesh, topo, &rays, job);
                    std::vector<test::Loops> regions;
                    for (const MapRegion& r : out.regions) regions.push_back(r.polygons);
                    const test::Coverage json = test::coverage(regions, 512, 512, 4);
                    const test::Coverage svg = test::coverage(test::svg_region_paths(out.svg), 512, 512, 4);
                    const int k = kind == PlanarMapKind::Snaxel ? 0 : 1;
                    worst[k][0] = std::max(worst[k][0], json.overlap_fraction());
                    worst[k][1] = std::max(worst[k][1], svg.overlap_fraction());
                    const std::string what = file + " view " + std::to_string(view) + (cam.orthographic() ? " ortho " : " persp ") +
                                             planar_map_kind_name(kind);
                    EXPECT_GT(json.covered, 0u) << what;
                    EXPECT_LT(json.overlap_fraction(), 1e-4) << what << ": " << json.multiple << " of " << json.covered;
                    EXPECT_LT(svg.overlap_fraction(), 1e-4) << what << " (SVG): " << svg.multiple << " of " << svg.covered;
                }
            }
        }
    }
    std::printf("largest overlap, %% of covered samples: snaxel map %.4f (SVG %.4f), post map %.4f (SVG %.4f)\n",
                100 * worst[0][0], 100 * worst[0][1], 100 * worst[1][0], 100 * worst[1][1]);
}

// The animated SVG's fills at every frame, evaluated from the SVG text as a
// SMIL player would (tests/support/coverage.h: display discrete, path data
// linear between key times), for both maps on a 24-frame turntable of spot
// and of the horse. Each frame's regions are a partition before export;
// the export reduces each path's keys and vertices on its own (0.25 px)
// and rounds to 0.1 px, so neighbouring paths overlap along shared
// outlines in slivers under half a pixel wide. Overlap wider than that
// (every sample within 0.5 px inside two paths) stays under 0.01% of the
// covered samples; the slivers are reported.
TEST(PlanarMaps, AnimatedFillsArePartitionsAtEveryFrame) {
    const Style style = parse_style(kStyle, "test", nullptr);
    double worst[2] = {0.0, 0.0}, worst_wide[2] = {0.0, 0.0};
    for (const std::string file : {"spot.obj", "horse.ply"}) {
        const LoadedMesh mesh = import_mesh(test::asset(file));
        for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
            AnimationSpec spec;
            spec.kind = AnimationSpec::Kind::Turntable;
            spec.degrees_per_frame = 4.0;
            spec.frames = 24;
            Camera cam;
            cam.view_dir = glm::normalize(glm::dvec3(0.6, -0.3, 1.0));
            AnimationJob job = make_animation_job(style, spec, cam, std::nullopt);
            job.scene.map_kind = kind;
            job.scene.visibility = false;
            const AnimationOutput out = run_animation(mesh, test::asset(file), job);
            for (int f = 0; f < spec.frames; ++f) {
                const test::Coverage c = test::coverage(test::smil_regions_at(out.document, (f + 0.01) / spec.frames), 512, 512, 4, 2);
                const int k = kind == PlanarMapKind::Snaxel ? 0 : 1;
                worst[k] = std::max(worst[k], c.overlap_fraction());
                worst_wide[k] = std::max(worst_wide[k], c.wide_fraction());
                EXPECT_GT(c.covered, 0u);
                EXPECT_LT(c.wide_fraction(), 1e-4) << file << " " << planar_map_kind_name(kind) << " frame " << f << ": "
                                                   << c.wide << " of " << c.covered;
            }
        }
    }
    std::printf("animated SVG at its frames, %% of covered samples: overlap wider than 0.5 px: snaxel map %.4f, post map %.4f; "
                "with slivers: %.4f, %.4f\n",
                100 * worst_wide[0], 100 * worst_wide[1], 100 * worst[0], 100 * worst[1]);
}
