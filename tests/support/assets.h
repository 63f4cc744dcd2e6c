#pragma once
// Where the test meshes are, and the shared list of them that fixtures run over.

#include <cctype>
#include <string>
#include <vector>

namespace snaxels::test {

inline std::string asset(const std::string& name) { return std::string(SNAXELS_TEST_ASSETS) + "/" + name; }

/// A GoogleTest parameter name made of a file name or mesh spec.
inline std::string test_name(std::string text) {
    for (auto& c : text)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return text;
}

/// One mesh of tests/assets with the counts of shared/data/README.md.
struct AssetMesh {
    std::string file;
    std::size_t vertices, faces, edges, boundary_edges, nonmanifold_edges;
};

inline const std::vector<AssetMesh>& asset_meshes() {
    static const std::vector<AssetMesh> all = {
        {"spot.obj", 2930, 5856, 8784, 0, 0},
        {"teapot.obj", 3241, 6320, 9560, 160, 0},
        {"fandisk.obj", 6475, 12946, 19419, 0, 0},
        {"suzanne.obj", 505, 968, 1472, 42, 1},
        {"stanford-bunny.obj", 34834, 69451, 104288, 223, 0},
        {"horse.ply", 48485, 96966, 145449, 0, 0},
    };
    return all;
}

} // namespace snaxels::test
