// Mutated mesh files: every one must load or fail with snaxels::Error —
// never crash, hang or throw anything else — and whatever loads must run
// through the engine with its invariants intact.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

#include <unistd.h>

#include "snaxels/error.h"
#include "snaxels/mesh/import.h"
#include "snaxels/snaxel/snaxel_engine.h"
#include "tests/support/assets.h"

using namespace snaxels;

namespace {

std::string read_prefix(const std::string& path, std::size_t n) {
    std::ifstream in(path, std::ios::binary);
    std::string s(n, '\0');
    in.read(s.data(), std::streamsize(n));
    s.resize(std::size_t(in.gcount()));
    return s;
}

std::string binary_stl() {
    std::string s(80, '\0');
    const std::uint32_t n = 2;
    s.append(reinterpret_cast<const char*>(&n), 4);
    const float tri[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0};
    for (int k = 0; k < 2; ++k) {
        s.append(reinterpret_cast<const char*>(tri), sizeof tri);
        s.append(2, '\0');
    }
    return s;
}

std::string mutate(std::string b, std::mt19937& rng) {
    static const char* inserts[] = {"-1", "999999999", "nan", "inf", "\n", " ", "e308", "/", "#", "4294967295", "0", "{", "}"};
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int rounds = 1 + int(rng() % 3);
    for (int r = 0; r < rounds && !b.empty(); ++r) {
        const double kind = u(rng);
        if (kind < 0.25 && b.size() > 10) {
            b.resize(1 + rng() % (b.size() - 1));
        } else if (kind < 0.6) {
            for (int i = 0, n = 1 + int(rng() % 30); i < n; ++i) b[rng() % b.size()] = char(rng() % 256);
        } else {
            for (int i = 0, n = 1 + int(rng() % 5); i < n; ++i) b.insert(rng() % b.size(), inserts[rng() % 13]);
        }
    }
    return b;
}

} // namespace

TEST(Fuzz, MutatedFilesLoadOrFailCleanly) {
    const std::vector<std::pair<std::string, std::string>> seeds = {
        {"obj", read_prefix(test::asset("suzanne.obj"), 3000)},
        {"ply", read_prefix(test::asset("horse.ply"), 2000)},
        {"ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"
                "3 0 1 2\n3 1 3 2\n"},
        {"stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n"},
        {"stl", binary_stl()},
        {"off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n"},
        {"gltf", read_prefix(test::asset("instanced.gltf"), 100000)},
    };
    const auto dir = std::filesystem::temp_directory_path() / ("snaxels-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    std::mt19937 rng(20261121);
    std::size_t loaded = 0, refused = 0;
    for (const auto& [ext, seed] : seeds)
        for (int i = 0; i < 150; ++i) {
            const auto path = (dir / ("f" + std::to_string(i) + "." + ext)).string();
            std::ofstream(path, std::ios::binary) << mutate(seed, rng);
            try {
                const LoadedMesh m = load_mesh(path);
                const MeshTopology topo = build_topology(m.mesh);
                EngineOptions options;
                options.check_invariants = true;
                SnaxelEngine(topo).compute({}, Camera{}, Light{}, options);
                ++loaded;
            } catch (const Error&) {
                ++refused;
            } catch (const std::exception& e) {
                ADD_FAILURE() << path << ": unexpected " << e.what();
            }
        }
    std::filesystem::remove_all(dir);
    EXPECT_GT(loaded, 5u); // some mutations still parse; the point is that none crashes
    EXPECT_GT(refused, 100u);
}
