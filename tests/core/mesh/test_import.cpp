#include <gtest/gtest.h>

#include "core/error.h"
#include "core/mesh/import.h"
#include "tests/support/assets.h"

using namespace snaxels;
using snaxels::test::asset;

class AssetImport : public ::testing::TestWithParam<test::AssetMesh> {};

TEST_P(AssetImport, CountsMatchTheDataReadme) {
    const auto& want = GetParam();
    const auto m = import_mesh(asset(want.file));
    EXPECT_EQ(m.report.vertices, want.vertices);
    EXPECT_EQ(m.report.faces, want.faces);
    EXPECT_EQ(m.report.edges, want.edges);
    EXPECT_EQ(m.report.boundary_edges, want.boundary_edges);
    EXPECT_EQ(m.report.nonmanifold_edges, want.nonmanifold_edges);
    EXPECT_EQ(m.mesh.n_vertices(), m.report.vertices + m.report.split_vertices);
    EXPECT_EQ(m.mesh.n_faces(), m.report.faces);
    for (const auto vh : m.mesh.vertices()) {
        EXPECT_TRUE(m.mesh.is_manifold(vh));
        EXPECT_NEAR(m.mesh.normal(vh).norm(), 1.0, 1e-9);
    }
}

INSTANTIATE_TEST_SUITE_P(Data, AssetImport, ::testing::ValuesIn(test::asset_meshes()),
                         [](const auto& p) { return test::test_name(p.param.file); });

TEST(Import, AppliesEveryNodeTransform) {
    // One triangle instanced twice under a parent scaled by 2, one instance
    // moved by (10, 0, 0).
    const auto m = import_mesh(asset("instanced.gltf"));
    EXPECT_EQ(m.report.faces, 2u);
    EXPECT_EQ(m.report.components, 2u);
    EXPECT_DOUBLE_EQ(m.report.bbox_min.x, 0.0);
    EXPECT_DOUBLE_EQ(m.report.bbox_max.x, 22.0);
    EXPECT_DOUBLE_EQ(m.report.bbox_max.y, 2.0);
}

TEST(Import, ClosedMeshesHaveOneComponent) {
    EXPECT_EQ(import_mesh(asset("spot.obj")).report.components, 1u);
    EXPECT_EQ(import_mesh(asset("horse.ply")).report.components, 1u);
}

TEST(Import, LoadMeshAcceptsProceduralSpecs) {
    const auto m = load_mesh("proc:sphere:1200");
    EXPECT_EQ(m.report.boundary_edges, 0u);
    EXPECT_THROW(load_mesh("proc:cube"), Error);
}

TEST(Import, ErrorsNameTheFile) {
    try {
        import_mesh(asset("bad/truncated.ply"));
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("truncated.ply: the binary PLY file is truncated"),
                  std::string::npos)
            << e.what();
    }
}

TEST(Import, HorseFacesAreTurnedOutward) {
    // horse.ply is wound inward; the engine needs outward normals.
    const auto m = import_mesh(asset("horse.ply"));
    EXPECT_EQ(m.report.flipped_components, 1u);
    double volume = 0.0;
    for (const auto fh : m.mesh.faces()) {
        auto it = m.mesh.cfv_iter(fh);
        const auto a = m.mesh.point(*it), b = m.mesh.point(*++it), c = m.mesh.point(*++it);
        volume += OpenMesh::dot(a, OpenMesh::cross(b, c)) / 6.0;
    }
    EXPECT_GT(volume, 0.0);
    EXPECT_EQ(import_mesh(asset("spot.obj")).report.flipped_components, 0u);
}
