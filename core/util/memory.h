#pragma once
/// The machine's memory, for refusing work that cannot fit before it starts.

#include <cstdint>
#include <string>

namespace snaxels {

/// Physical memory in bytes; SNAXELS_MEMORY_MB (a positive number) stands in
/// for it, so the refusals can be tried on any machine.
std::uint64_t machine_memory_bytes();

/// Sets the process's allocator for the engine's frames, once at the start
/// of a program (the command line, the application, the benchmarks): glibc
/// serves a block of a few megabytes by mapping fresh pages and gives the
/// freed top of its heap back to the system, so a moving mesh's frame,
/// whose temporaries (curvature's per-face forms, the tangent frames) are
/// tens of megabytes allocated and freed each frame, paid a page fault for
/// every page of them every frame: a fifth of the curvature update of a
/// walking 30K-vertex mesh. Blocks under 32 MB now come from the heap and
/// up to 128 MB of its freed top is kept for the next frame. Does nothing
/// where the C library is not glibc.
void tune_allocator();

/// "850 MB", "1.2 GB".
std::string describe_bytes(std::uint64_t bytes);

} // namespace snaxels
