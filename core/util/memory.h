#pragma once
/// The machine's memory, for refusing work that cannot fit before it starts.

#include <cstdint>
#include <string>

namespace snaxels {

/// Physical memory in bytes; SNAXELS_MEMORY_MB (a positive number) stands in
/// for it, so the refusals can be tried on any machine.
std::uint64_t machine_memory_bytes();

/// "850 MB", "1.2 GB".
std::string describe_bytes(std::uint64_t bytes);

} // namespace snaxels
