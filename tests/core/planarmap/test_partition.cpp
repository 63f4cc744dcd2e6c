#include <gtest/gtest.h>

#include <random>

#include "core/animation/still.h"
#include "core/mesh/import.h"
#include "core/snaxel/refine.h"
#include "core/style/style.h"
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
                job.visibility = false;
                for (const PlanarMapKind kind : {PlanarMapKind::Snaxel, PlanarMapKind::Post}) {
                    job.map_kind = kind;
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
