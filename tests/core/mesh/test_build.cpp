#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "snaxels/error.h"
#include "snaxels/mesh/build.h"

using namespace snaxels;

namespace {

TriangleSoup two_triangles_with_seam() {
    // A quad whose two triangles repeat the diagonal's positions, as OBJ
    // seams do; -0.0 and 0.0 must weld.
    TriangleSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-0.0, 0, 0}, {1, 1, 0}, {0, 1, -0.0}};
    s.triangles = {{0, 1, 2}, {3, 4, 5}};
    return s;
}

} // namespace

TEST(BuildMesh, WeldsByExactPositionIncludingNegativeZero) {
    const auto m = build_mesh(two_triangles_with_seam(), "seam");
    EXPECT_EQ(m.report.vertices, 4u);
    EXPECT_EQ(m.mesh.n_vertices(), 4u);
    EXPECT_EQ(m.report.faces, 2u);
    EXPECT_EQ(m.report.edges, 5u);
    EXPECT_EQ(m.report.boundary_edges, 4u);
    EXPECT_EQ(m.report.components, 1u);
}

TEST(BuildMesh, DropsDegenerateFacesAndUnreferencedVertices) {
    TriangleSoup s = two_triangles_with_seam();
    s.positions.push_back({5, 5, 5});        // referenced by nothing
    s.positions.push_back({2, 0, 0});        // collinear with 0 and 1
    s.triangles.push_back({0, 1, 7});        // zero area
    s.triangles.push_back({0, 3, 1});        // repeated corner after welding
    const auto m = build_mesh(s, "degenerate");
    EXPECT_EQ(m.report.dropped_faces, 2u);
    EXPECT_EQ(m.report.faces, 2u);
    EXPECT_EQ(m.report.vertices, 4u);
    EXPECT_EQ(m.report.bbox_max.x, 1.0);
}

TEST(BuildMesh, SplitsVerticesOfAFinEdgeAndKeepsEveryFace) {
    // Three triangles on one edge (0,1): a non-manifold "fin".
    TriangleSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
    s.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const auto m = build_mesh(s, "fin");
    EXPECT_EQ(m.report.nonmanifold_edges, 1u);
    EXPECT_EQ(m.report.faces, 3u);
    EXPECT_EQ(m.mesh.n_faces(), 3u);
    EXPECT_GE(m.report.split_vertices, 1u);
    EXPECT_EQ(m.mesh.n_vertices(), m.report.vertices + m.report.split_vertices);
}

TEST(BuildMesh, SplitsAComplexVertex) {
    // Two closed fans (tetrahedra) sharing their apex: the second fan's faces
    // meet a vertex that is no longer on a boundary.
    TriangleSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
    s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},
                   {0, 4, 5}, {0, 6, 4}, {0, 5, 6}, {4, 6, 5}};
    const auto m = build_mesh(s, "two tetrahedra");
    EXPECT_EQ(m.mesh.n_faces(), 8u);
    EXPECT_EQ(m.report.split_vertices, 1u);
    EXPECT_EQ(m.report.components, 2u);
    for (const auto vh : m.mesh.vertices()) EXPECT_TRUE(m.mesh.is_manifold(vh));
    for (const auto eh : m.mesh.edges()) EXPECT_FALSE(m.mesh.is_boundary(eh));
}

TEST(BuildMesh, SplitsABowTie) {
    // Two open fans touching at one vertex: OpenMesh accepts the second face
    // and leaves the vertex with two gaps in its ring (fuzz_mesh found a PLY
    // cube, most of its faces degenerate, that did this). Each fan gets its
    // own copy of the vertex.
    TriangleSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {0, -1, 0}};
    s.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 4, 5}, {0, 5, 6}};
    const auto m = build_mesh(s, "bow tie");
    EXPECT_EQ(m.mesh.n_faces(), 4u);
    EXPECT_EQ(m.report.split_vertices, 1u);
    EXPECT_EQ(m.report.vertices, 7u);
    EXPECT_EQ(m.mesh.n_vertices(), 8u);
    EXPECT_EQ(m.report.components, 2u);
    for (const auto vh : m.mesh.vertices()) EXPECT_TRUE(m.mesh.is_manifold(vh));
    // The copy stands for the same input vertex.
    std::size_t at_origin = 0;
    for (const auto vh : m.mesh.vertices())
        if (m.mesh.point(vh).norm() == 0.0) {
            ++at_origin;
            EXPECT_EQ(m.vertex_source[std::size_t(vh.idx())], 0u);
        }
    EXPECT_EQ(at_origin, 2u);
}

TEST(BuildMesh, RejectsNonFiniteCoordinatesAndBadIndices) {
    TriangleSoup s = two_triangles_with_seam();
    s.positions[2].y = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(build_mesh(s, "nan"), Error);
    s = two_triangles_with_seam();
    s.positions[2].z = std::numeric_limits<double>::infinity();
    EXPECT_THROW(build_mesh(s, "inf"), Error);
    s = two_triangles_with_seam();
    s.triangles[1][2] = 99;
    EXPECT_THROW(build_mesh(s, "index"), Error);
    s.triangles.clear();
    try {
        build_mesh(s, "empty");
        FAIL();
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "the mesh has no faces");
    }
}

TEST(BuildMesh, AreaWeightedNormals) {
    // An L-shaped vertex: a large face in z=0 and a small one in x=0. The
    // normal of the shared vertices leans toward the large face's normal.
    TriangleSoup s;
    s.positions = {{0, 0, 0}, {0, 1, 0}, {4, 0, 0}, {0, 0, 0.25}};
    s.triangles = {{0, 2, 1}, {0, 1, 3}};
    const auto m = build_mesh(s, "L");
    const auto n = to_glm(m.mesh.normal(Mesh::VertexHandle(0)));
    EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
    // Face normals are -Z (area 2) and -X (area 0.125): weights 16 : 1.
    EXPECT_NEAR(n.z / n.x, 16.0, 1e-9);
}

TEST(BuildMesh, TurnsInwardFacingClosedComponentsOutward) {
    // Two tetrahedra: one wound outward, one inward; and an open triangle,
    // which has no inside and is left as it is.
    TriangleSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                   {5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1},
                   {9, 0, 0}, {10, 0, 0}, {9, 1, 0}};
    s.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3},  // outward
                   {4, 5, 6}, {4, 7, 5}, {4, 6, 7}, {5, 7, 6},  // inward
                   {8, 10, 9}};
    const auto m = build_mesh(s, "tetrahedra");
    EXPECT_EQ(m.report.flipped_components, 1u);
    EXPECT_EQ(m.report.components, 3u);
    // Every closed tetrahedron's vertex normals now point away from its centroid.
    for (const auto vh : m.mesh.vertices()) {
        const glm::dvec3 p = to_glm(m.mesh.point(vh));
        if (p.x > 8) {
            EXPECT_LT(to_glm(m.mesh.normal(vh)).z, 0.0); // the open triangle keeps its winding
            continue;
        }
        const glm::dvec3 centre = p.x >= 5 ? glm::dvec3(5.25, 0.25, 0.25) : glm::dvec3(0.25);
        EXPECT_GT(glm::dot(to_glm(m.mesh.normal(vh)), p - centre), 0.0);
    }
}
