#include "snaxels/util/memory.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <unistd.h>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace snaxels {

std::uint64_t machine_memory_bytes() {
    if (const char* v = std::getenv("SNAXELS_MEMORY_MB"); v && *v) {
        char* end = nullptr;
        const double mb = std::strtod(v, &end);
        if (end && *end == '\0' && std::isfinite(mb) && mb > 0) return std::uint64_t(mb * 1024 * 1024);
    }
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return UINT64_MAX;
    return std::uint64_t(pages) * std::uint64_t(page);
}

void tune_allocator() {
#if defined(__GLIBC__)
    // Fixing the thresholds also turns off glibc's own adjustment of them.
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 128 * 1024 * 1024);
#endif
}

std::string describe_bytes(std::uint64_t bytes) {
    char buf[32];
    const double mb = double(bytes) / (1024.0 * 1024.0);
    if (mb < 1024.0) std::snprintf(buf, sizeof buf, "%.0f MB", mb);
    else std::snprintf(buf, sizeof buf, "%.1f GB", mb / 1024.0);
    return buf;
}

} // namespace snaxels
