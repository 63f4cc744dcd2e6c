// snaxels-cli: every engine feature without a display.

#include <csignal>
#include <exception>

#include <unistd.h>
#include <iostream>
#include <new>

#include "app/cli/args.h"
#include "app/cli/commands.h"
#include "snaxels/error.h"
#include "snaxels/mesh/isolated_import.h"
#include "snaxels/util/memory.h"
#include "snaxels/version.h"

namespace snaxels::cli {

const char* const kMeshArgumentHelp =
    "MESH is a mesh file in any format Assimp reads (OBJ, PLY, STL, OFF, glTF/GLB,\n"
    "FBX, DAE, 3DS, X, BLEND, ...) or a procedural mesh proc:NAME[:FACES], NAME one\n"
    "of torus, sphere, bumpy, nose, scan and FACES the approximate face count (default\n"
    "20000), for example proc:torus:100000.";

const std::vector<Command>& commands() {
    static const std::vector<Command> all = {
        {"info", "print a report on a mesh (counts, repairs, bounding box)", run_info},
        {"contours", "find visual, shadow, isophote and gleam contours; JSON and SVG", run_contours},
        {"animate", "track contours through an animation; animated SVG whose paths move", run_animate},
        {"render", "render a project saved by the application (animated or one frame)", run_render},
        {"parabolic", "find parabolic points and curves from visual events over the view sphere", run_parabolic},
        {"bench", "time import, topology and contour extraction on a mesh", run_bench},
    };
    return all;
}

namespace {

void print_help() {
    std::cout << "usage: snaxels-cli COMMAND [OPTIONS]\n\n"
                 "Turns 3-D meshes into contour line art with snaxels (Karsch and Hart 2011).\n\n"
                 "commands:\n";
    for (const auto& c : commands()) {
        std::string name = "  " + std::string(c.name);
        name.resize(14, ' ');
        std::cout << name << c.summary << '\n';
    }
    std::cout << "\n'snaxels-cli COMMAND --help' describes a command's options.\n";
}

} // namespace
} // namespace snaxels::cli

namespace {

// A fault inside a third-party reader (or a bug of ours) still ends with a
// one-line message and a distinct exit code rather than a core dump.
extern "C" void on_fatal_signal(int sig) {
    static const char message[] = "snaxels-cli: internal error (a fatal signal while processing the input); "
                                  "please report it with the input file\n";
    const ssize_t ignored = ::write(2, message, sizeof message - 1);
    (void)ignored;
    (void)sig;
    ::_exit(3);
}

} // namespace

int main(int argc, char** argv) {
    using namespace snaxels::cli;
    std::ios::sync_with_stdio(false);
    snaxels::tune_allocator();
    for (const int sig : {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL}) std::signal(sig, on_fatal_signal);
    if (argc < 2) {
        print_help();
        return 2;
    }
    const std::string name = argv[1];
    if (name == "--help" || name == "-h" || name == "help") {
        print_help();
        return 0;
    }
    if (name == "--version") {
        std::cout << "snaxels-cli " << snaxels::version << '\n';
        return 0;
    }
    // Mesh files are read by the snaxels-import helper in a process of its
    // own, under time and memory limits.
    snaxels::set_mesh_importer(snaxels::importer_beside_executable());
    const std::vector<std::string> rest(argv + 2, argv + argc);
    for (const auto& c : commands()) {
        if (name != c.name) continue;
        try {
            return c.run(rest);
        } catch (const UsageError& e) {
            std::cerr << "snaxels-cli " << name << ": " << e.what() << " (see 'snaxels-cli "
                      << name << " --help')\n";
            return 2;
        } catch (const snaxels::InternalError& e) {
            std::cerr << "snaxels-cli: internal error: " << e.what() << "; please report it with the input\n";
            return 3;
        } catch (const snaxels::Error& e) {
            std::cerr << "snaxels-cli: " << e.what() << '\n';
            return 1;
        } catch (const std::bad_alloc&) {
            std::cerr << "snaxels-cli: out of memory\n";
            return 1;
        } catch (const std::exception& e) {
            std::cerr << "snaxels-cli: " << e.what() << '\n';
            return 1;
        }
    }
    std::cerr << "snaxels-cli: unknown command '" << name << "' (see 'snaxels-cli --help')\n";
    return 2;
}
