#pragma once
/// Reads any mesh file Assimp understands into one welded, repaired Mesh in
/// the file's own coordinates (every scene node with its transform applied).

#include <string>

#include "snaxels/mesh/build.h"

namespace snaxels {

/// Reads the triangles of every mesh instance in the scene of @p path, in
/// this process or, when set_mesh_importer named a helper, in the helper's
/// (isolated_import.h). Throws snaxels::Error "PATH: problem" for
/// unreadable or invalid input, and when the reader crashes or overruns.
TriangleSoup read_triangle_soup(const std::string& path);

/// read_triangle_soup followed by build_mesh; errors name @p path.
LoadedMesh import_mesh(const std::string& path);

/// Either a file path or a procedural description "proc:NAME[:FACES]"
/// (see procedural.h); the one entry point the CLI and the GUI use.
LoadedMesh load_mesh(const std::string& spec);

} // namespace snaxels
