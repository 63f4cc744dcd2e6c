// libFuzzer target: mesh import, from the bytes of a file through the
// pre-validation (PLY, OFF, STL headers and bodies), Assimp's OBJ, PLY, STL
// and OFF readers and snaxels' welding and repair. The first byte picks the
// file's extension; the rest is the file. Any input gives a mesh or throws
// snaxels::Error; a mesh that builds holds the halfedge invariants.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include "snaxels/error.h"
#include "snaxels/mesh/build.h"
#include "snaxels/mesh/isolated_import.h"

// Assimp's internal checks (ai_assert) abort; in this process they throw
// instead, so that a failed check is an error of the file, as the
// snaxels-import helper's crash is for the application. (The definition here
// interposes the library's.)
namespace Assimp {
void aiAssertViolation(const char* expression, const char* file, int line) {
    throw std::runtime_error(std::string("ai_assert failure in ") + file + "(" + std::to_string(line) +
                             "): " + expression);
}
} // namespace Assimp

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size < 1) return 0;
    static const char* const extensions[] = {".obj", ".ply", ".stl", ".off"};
    const std::string path = "/tmp/snaxels-fuzz-" + std::to_string(::getpid()) + extensions[data[0] % 4];
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data + 1), std::streamsize(size - 1));
    }
    try {
        const snaxels::TriangleSoup soup = snaxels::detail::read_triangle_soup_here(path);
        const snaxels::LoadedMesh loaded = snaxels::build_mesh(soup, path);
        for (const auto vh : loaded.mesh.vertices())
            if (!loaded.mesh.is_manifold(vh)) {
                std::fprintf(stderr, "a built mesh has a non-manifold vertex\n");
                std::abort();
            }
        if (loaded.mesh.n_faces() != loaded.report.faces) {
            std::fprintf(stderr, "the report's face count differs from the mesh's\n");
            std::abort();
        }
    } catch (const snaxels::Error&) {
    } catch (const std::runtime_error& e) {
        // An ai_assert turned into an exception and passed through Assimp
        // (ReadFile normally catches it): as much an error of the file.
        if (std::string(e.what()).rfind("ai_assert failure", 0) != 0) throw;
    }
    return 0;
}
