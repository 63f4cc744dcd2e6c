#include <gtest/gtest.h>

#include <cmath>

#include <glm/glm.hpp>

#include "snaxels/error.h"
#include "snaxels/mesh/build.h"
#include "snaxels/mesh/procedural.h"

using namespace snaxels;

namespace {

long euler_characteristic(const LoadedMesh& m) {
    return long(m.mesh.n_vertices()) - long(m.mesh.n_edges()) + long(m.mesh.n_faces());
}

} // namespace

class ProceduralMesh : public ::testing::TestWithParam<std::string> {};

TEST_P(ProceduralMesh, IsClosedManifoldNearTheAskedFaceCount) {
    for (const std::size_t target : {200u, 5000u, 60000u}) {
        const auto m = build_mesh(make_procedural(GetParam() + ":" + std::to_string(target)), GetParam());
        SCOPED_TRACE(GetParam() + " " + std::to_string(target));
        EXPECT_EQ(m.report.boundary_edges, 0u);
        EXPECT_EQ(m.report.nonmanifold_edges, 0u);
        EXPECT_EQ(m.report.split_vertices, 0u);
        EXPECT_EQ(m.report.dropped_faces, 0u);
        EXPECT_EQ(m.report.components, 1u);
        EXPECT_EQ(euler_characteristic(m), GetParam() == "torus" ? 0 : 2);
        EXPECT_NEAR(double(m.report.faces), double(target), 0.12 * target);
        // Outward orientation: normals point away from the centre.
        std::size_t outward = 0;
        for (const auto vh : m.mesh.vertices())
            outward += glm::dot(to_glm(m.mesh.normal(vh)), to_glm(m.mesh.point(vh))) > 0.0;
        if (GetParam() != "torus") {
            EXPECT_EQ(outward, m.mesh.n_vertices());
        }
    }
}

INSTANTIATE_TEST_SUITE_P(All, ProceduralMesh, ::testing::ValuesIn(procedural_names()));

TEST(Procedural, SphereNormalsMatchPositions) {
    const auto m = build_mesh(make_sphere(20000), "sphere");
    for (const auto vh : m.mesh.vertices()) {
        const auto p = to_glm(m.mesh.point(vh));
        EXPECT_NEAR(glm::length(p), 1.0, 1e-12);
        EXPECT_GT(glm::dot(to_glm(m.mesh.normal(vh)), p), 0.999);
    }
}

TEST(Procedural, ReachesAMillionFaces) {
    const auto m = build_mesh(make_torus(1'000'000), "torus");
    EXPECT_GE(m.report.faces, 1'000'000u);
    EXPECT_EQ(m.report.boundary_edges, 0u);
}

TEST(Procedural, RejectsUnknownNamesAndBadCounts) {
    EXPECT_THROW(make_procedural("cube"), Error);
    EXPECT_THROW(make_procedural("torus:abc"), Error);
    EXPECT_THROW(make_procedural("torus:10"), Error);
    EXPECT_THROW(make_procedural("torus:"), Error);
}
