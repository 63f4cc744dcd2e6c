// libFuzzer target: the project reader (nlohmann-json and snaxels' reading
// of its fields). Any input reads or throws snaxels::Error, and a project
// that reads writes back to text that reads as the same project (the
// property saving and reopening rely on).

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

#include "snaxels/error.h"
#include "snaxels/project/project.h"

namespace {

std::string scratch(const char* name) {
    return "/tmp/snaxels-fuzz-" + std::to_string(::getpid()) + "-" + name;
}

void write(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << text;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string first = scratch("a.snaxels"), second = scratch("b.snaxels");
    write(first, std::string(reinterpret_cast<const char*>(data), size));
    snaxels::Project project;
    try {
        project = snaxels::read_project(first);
    } catch (const snaxels::Error&) {
        return 0;
    }
    write(second, snaxels::project_text(project));
    try {
        if (snaxels::read_project(second) == project) return 0;
        std::fprintf(stderr, "a project read back differs from the one written\n");
    } catch (const snaxels::Error& e) {
        std::fprintf(stderr, "a written project does not read back: %s\n", e.what());
    }
    std::abort();
}
