#pragma once
// The subcommands of snaxels-cli. Each takes the arguments after its name
// and returns the process exit code: 0 success, 1 bad input, 2 bad usage.

#include <string>
#include <vector>

namespace snaxels::cli {

struct Command {
    const char* name;
    const char* summary;
    int (*run)(const std::vector<std::string>& args);
};

/// Every command, in the order --help lists them.
const std::vector<Command>& commands();

int run_info(const std::vector<std::string>& args);
int run_contours(const std::vector<std::string>& args);
int run_bench(const std::vector<std::string>& args);
int run_animate(const std::vector<std::string>& args);
int run_render(const std::vector<std::string>& args);
int run_parabolic(const std::vector<std::string>& args);

/// The sentence every command's help uses to say what MESH may be.
extern const char* const kMeshArgumentHelp;

} // namespace snaxels::cli
