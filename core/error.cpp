#include "snaxels/error.h"

#include <cstdlib>
#include <cstring>
#include <string>

namespace snaxels {

bool fault_injected(const char* site, long count) {
    const char* v = std::getenv("SNAXELS_FAULT"); // read each time: tests set it as they go
    if (!v || !*v) return false;
    const std::string spec = v;
    const std::size_t colon = spec.rfind(':');
    if (colon == std::string::npos || spec.compare(0, colon, site) != 0) return false;
    return std::strtol(spec.c_str() + colon + 1, nullptr, 10) == count;
}

} // namespace snaxels
