// The snaxels engine embedded in another program: load a mesh, find its
// visible and hidden contours, write them as SVG. Built against an installed
// snaxels with find_package(snaxels) (see CMakeLists.txt beside this file).
//   embed MESH OUT.svg
#include <cstdio>
#include <optional>

#include <snaxels/snaxels.h>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: embed MESH OUT.svg   (snaxels %s)\n", snaxels::version);
        return 2;
    }
    try {
        const snaxels::LoadedMesh mesh = snaxels::load_mesh(argv[1]); // a file, or proc:torus and the like
        snaxels::StillJob job; // the visual contour, hidden lines dashed
        // The surface as snaxels-cli draws it: split along its sharp edges
        // (where the file's normals part; without normals, past 30 degrees).
        std::optional<snaxels::LoadedMesh> storage;
        const snaxels::LoadedMesh& surface = snaxels::scene_surface(mesh, job.scene.style, storage);
        const snaxels::MeshTopology topology = snaxels::engine_topology(surface);
        // The model's front (+Z, for +Y up), three-quarter from a little above, as snaxels-cli draws it.
        job.scene.camera.view_dir = snaxels::default_view_dir(job.scene.camera.up);
        job.scene.light = snaxels::default_light(job.scene.camera);
        const snaxels::StillOutput still = snaxels::render_still(surface, topology, nullptr, job);
        snaxels::write_file_atomically(argv[2], still.svg);
        std::printf("%s: %zu contour loops\n", argv[2], still.results.front().fronts.loops.size());
    } catch (const snaxels::Error& e) {
        std::fprintf(stderr, "embed: %s\n", e.what());
        return 1;
    }
    return 0;
}
