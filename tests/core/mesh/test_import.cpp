#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <algorithm>
#include <gtest/gtest.h>

#include "snaxels/error.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/isolated_import.h"
#include "snaxels/mesh/mesh_animation.h"
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

// A file that records its axes (FBX's GlobalSettings: 3ds Max saves Z up,
// front -Y) loads upright, +Y up and its front toward +Z, as a glTF, OBJ or
// PLY does. The box stands three times as tall as it is wide on its own Z.
TEST(Import, FbxAxesAreTurnedUpright) {
    const auto m = import_mesh(asset("z-up-tall-box.fbx"));
    const glm::dvec3 size = m.report.bbox_max - m.report.bbox_min;
    EXPECT_NEAR(size.y, 3.0 * size.x, 1e-6 * size.y) << "the tall side is up";
    EXPECT_NEAR(size.z, size.x, 1e-6 * size.x);
    EXPECT_NEAR(m.report.bbox_min.y, 0.0, 1e-9) << "it stands on its base, not on its top";
}

// So does a Collada file whose up_axis is Z (Assimp turns it itself): the
// same box, 1 x 1 x 3 on its own axes, stands 3 tall along +Y.
TEST(Import, ColladaUpAxisIsTurnedUpright) {
    const auto m = import_mesh(asset("z-up-tall-box.dae"));
    const glm::dvec3 size = m.report.bbox_max - m.report.bbox_min;
    EXPECT_NEAR(size.y, 3.0, 1e-9);
    EXPECT_NEAR(size.x, 1.0, 1e-9);
    EXPECT_NEAR(size.z, 1.0, 1e-9);
    EXPECT_NEAR(m.report.bbox_min.y, 0.0, 1e-9);
    EXPECT_EQ(m.report.flipped_components, 0u); // still facing outward after the turn
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

// Each face knows its part of the scene and its material: the milk truck's
// faces per node and per material are what its glTF 1.0 JSON says (read
// here: each node's meshes' triangle lists, instances counted, down the
// scene's node tree), its materials' colours its diffuse values.
TEST(Import, KeepsTheScenesPartsAndMaterials) {
    const std::string path = asset("hard/CesiumMilkTruck.gltf");
    std::ifstream in(path);
    const nlohmann::json doc = nlohmann::json::parse(in);
    std::map<std::string, std::size_t> by_node, by_material;
    std::function<void(const std::string&)> walk = [&](const std::string& id) {
        const nlohmann::json& node = doc["nodes"][id];
        for (const auto& mesh : node.value("meshes", nlohmann::json::array()))
            for (const auto& prim : doc["meshes"][mesh.get<std::string>()]["primitives"]) {
                const std::size_t triangles = doc["accessors"][prim["indices"].get<std::string>()]["count"].get<std::size_t>() / 3;
                by_node[id] += triangles;
                by_material[prim["material"].get<std::string>()] += triangles;
            }
        for (const auto& child : node.value("children", nlohmann::json::array())) walk(child.get<std::string>());
    };
    for (const auto& id : doc["scenes"][doc["scene"].get<std::string>()]["nodes"]) walk(id.get<std::string>());

    const LoadedMesh m = import_mesh(path);
    ASSERT_EQ(m.face_object.size(), m.mesh.n_faces());
    ASSERT_EQ(m.face_material.size(), m.mesh.n_faces());
    EXPECT_EQ(m.report.dropped_faces, 0u);
    std::map<std::string, std::size_t> objects, materials;
    for (const auto o : m.face_object) ++objects[m.objects[o].name];
    for (const auto k : m.face_material) ++materials[m.materials[k].name];
    EXPECT_EQ(objects, by_node);
    EXPECT_EQ(materials, by_material);
    for (const SceneObject& o : m.objects) EXPECT_FALSE(o.path.empty());
    EXPECT_NE(std::find_if(m.objects.begin(), m.objects.end(),
                           [](const SceneObject& o) { return o.path == "Geometry-mesh002Node/meshInst962Node"; }),
              m.objects.end()); // a wheel instance under the body, by its path
    for (const SceneMaterial& mat : m.materials) {
        const nlohmann::json& diffuse = doc["materials"][mat.name]["values"]["diffuse"];
        if (!diffuse.is_array()) continue; // a texture: the colour is Assimp's default
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(mat.colour[k], diffuse[k].get<double>(), 1e-6) << mat.name;
    }
    // A procedural mesh has no parts.
    EXPECT_TRUE(load_mesh("proc:torus:2000").face_object.empty());
}

// The snaxels-import helper hands back exactly what this process reads, and
// its errors read as the in-process ones do.
TEST(IsolatedImport, HelperReadsWhatThisProcessReads) {
    for (const std::string file : {"horse.ply", "instanced.gltf", "anim/skinned-bar.gltf", "suzanne.obj",
                                   "hard/CesiumMilkTruck.gltf", "hard/regr01-house.dae"}) {
        const TriangleSoup here = detail::read_triangle_soup_here(asset(file));
        const TriangleSoup there = detail::read_soup_isolated(SNAXELS_IMPORTER, asset(file));
        EXPECT_EQ(there.normals, here.normals) << file;
        EXPECT_EQ(there.objects, here.objects) << file;
        EXPECT_EQ(there.materials, here.materials) << file;
        EXPECT_EQ(there.triangle_object, here.triangle_object) << file;
        EXPECT_EQ(there.triangle_material, here.triangle_material) << file;
        EXPECT_FALSE(here.objects.empty()) << file;
        ASSERT_EQ(there.positions.size(), here.positions.size()) << file;
        ASSERT_EQ(there.triangles.size(), here.triangles.size()) << file;
        for (std::size_t i = 0; i < here.positions.size(); ++i) ASSERT_EQ(there.positions[i], here.positions[i]) << file;
        EXPECT_EQ(there.triangles, here.triangles) << file;
    }
    const auto clips_here = animation_clips(asset("anim/skinned-bar.gltf"));
    const auto clips_there = detail::read_clips_isolated(SNAXELS_IMPORTER, asset("anim/skinned-bar.gltf"));
    ASSERT_EQ(clips_there.size(), clips_here.size());
    ASSERT_FALSE(clips_here.empty());
    for (std::size_t i = 0; i < clips_here.size(); ++i) {
        EXPECT_EQ(clips_there[i].name, clips_here[i].name);
        EXPECT_EQ(clips_there[i].duration, clips_here[i].duration);
    }
    for (const std::string bad : {"bad/truncated.ply", "bad/empty.obj", "bad/no-such-file.obj"}) {
        std::string here, there;
        try {
            read_triangle_soup(asset(bad));
        } catch (const Error& e) {
            here = e.what();
        }
        try {
            detail::read_soup_isolated(SNAXELS_IMPORTER, asset(bad));
        } catch (const Error& e) {
            there = e.what();
        }
        EXPECT_FALSE(here.empty()) << bad;
        EXPECT_EQ(there, here) << bad;
    }
}

// A file that kills Assimp kills only the helper: this process gets an
// Error naming the file and the signal.
TEST(IsolatedImport, ReaderCrashIsAnError) {
    set_mesh_importer(SNAXELS_IMPORTER);
    std::string message;
    try {
        import_mesh(asset("bad/importer/triangulate-assert-2.ply"));
    } catch (const Error& e) {
        message = e.what();
    }
    set_mesh_importer("");
    EXPECT_NE(message.find("triangulate-assert-2.ply: the mesh reader crashed on this file (SIGABRT"),
              std::string::npos)
        << message;
}
