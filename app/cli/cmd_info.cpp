#include <iostream>

#include <nlohmann/json.hpp>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "core/mesh/import.h"

namespace snaxels::cli {

int run_info(const std::vector<std::string>& argv) {
    Args args("info", "info MESH [--json]",
              std::string("Reads MESH, welds and repairs it as the engine sees it, and prints a "
                          "report:\nvertices, faces, edges, boundary and non-manifold edges of the "
                          "input, vertices\nsplit and faces dropped by the repair, connected "
                          "components and bounding box.\n\n") +
                  kMeshArgumentHelp,
              {{"json", "", "print one JSON object instead of text"}}, {"MESH"});
    if (!args.parse(argv)) {
        std::cout << args.help();
        return 0;
    }
    const LoadedMesh loaded = load_mesh(args.positional()[0]);
    if (args.flag("json"))
        std::cout << to_json(loaded.report).dump(2) << '\n';
    else
        std::cout << to_text(loaded.report);
    return 0;
}

} // namespace snaxels::cli
