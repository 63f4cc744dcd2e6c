// snaxels-import: reads one mesh file for snaxels and snaxels-cli, in a
// process of its own, so that a file which crashes the reader or exhausts
// memory costs this process only. Not meant to be run by hand:
//   snaxels-import --memory BYTES (--soup | --clips) -- PATH
// writes the reply (see core/mesh/isolated_import.h) to stdout.

#include <cstdlib>
#include <iostream>
#include <string>

#include <sys/resource.h>

#include "snaxels/mesh/isolated_import.h"

#if defined(__SANITIZE_ADDRESS__)
#define SNAXELS_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SNAXELS_ASAN 1
#endif
#endif

#ifdef SNAXELS_ASAN
// In a sanitizer build the reader's crash on a damaged file is this helper's
// expected end, reported to its parent by the signal, as in a normal build:
// AddressSanitizer leaves SIGSEGV and SIGBUS alone here.
extern "C" const char* __asan_default_options() { return "handle_segv=0:handle_sigbus=0"; }
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif

namespace {

int usage() {
    std::cerr << "usage: snaxels-import --memory BYTES (--soup | --clips) -- PATH\n"
                 "(a helper of snaxels and snaxels-cli; it writes a binary reply to stdout)\n";
    return 2;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 6 || std::string(argv[1]) != "--memory" || std::string(argv[4]) != "--") return usage();
    const std::string mode = argv[3];
    if (mode != "--soup" && mode != "--clips") return usage();
    char* end = nullptr;
    const unsigned long long memory = std::strtoull(argv[2], &end, 10);
    if (!end || *end != '\0' || memory == 0) return usage();
    // No core files from a crash in the reader, and no more memory than the
    // limit (AddressSanitizer reserves terabytes of address space up front,
    // so a sanitizer build keeps only the time limit).
    const rlimit no_core{0, 0};
    setrlimit(RLIMIT_CORE, &no_core);
    if (!kAddressSanitizer) {
        const rlimit as{rlim_t(memory), rlim_t(memory)};
        setrlimit(RLIMIT_AS, &as);
    }
    using snaxels::detail::ImportRequest;
    return snaxels::detail::serve_import(mode == "--soup" ? ImportRequest::Soup : ImportRequest::Clips, argv[5], 1);
}
