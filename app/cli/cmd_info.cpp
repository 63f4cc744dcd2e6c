#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "snaxels/mesh/import.h"
#include "snaxels/mesh/refine.h"

namespace snaxels::cli {

int run_info(const std::vector<std::string>& argv) {
    Args args("info", "info MESH [--json]",
              std::string("Reads MESH, welds and repairs it as the engine sees it, and prints a "
                          "report:\nvertices, faces, edges, boundary and non-manifold edges of the "
                          "input, vertices\nsplit and faces dropped by the repair, connected "
                          "components and bounding box,\nand how far the engine refines it (--refine auto).\n\n") +
                  kMeshArgumentHelp,
              {{"json", "", "print one JSON object instead of text"}}, {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    const LoadedMesh loaded = load_mesh(args.positional()[0]);
    // What the engine works on by default (--refine auto): docs/engine.md.
    const int levels = refine_levels(loaded.report.faces, kAutoRefine);
    const std::size_t engine_faces = loaded.report.faces * (std::size_t(1) << (2 * levels));
    if (args.flag("json")) {
        nlohmann::json doc = to_json(loaded.report);
        doc["engine"] = {{"refine_levels", levels}, {"faces", engine_faces}};
        std::cout << doc.dump(2) << '\n';
    } else {
        std::cout << to_text(loaded.report);
        if (levels > 0)
            std::cout << "refined for contours: " << levels << (levels == 1 ? " level, " : " levels, ") << engine_faces
                      << " faces\n";
    }
    return 0;
}

} // namespace snaxels::cli
