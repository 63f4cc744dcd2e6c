#pragma once
/// Reading mesh files in a separate process. Assimp's readers can abort
/// (ai_assert), fault or allocate without bound on a damaged file; run in
/// the helper program snaxels-import, such a file costs that process only,
/// and the caller gets a one-line message naming the file and the cause.
///
/// The helper reads the file exactly as the in-process reader does and
/// sends the triangle soup (or the animation clip list) back through a pipe.
/// It runs under a memory limit (setrlimit) and a wall-clock limit, both
/// scaled with the file's size and overridable with SNAXELS_IMPORT_SECONDS
/// and SNAXELS_IMPORT_MEMORY_MB.

#include <cstdint>
#include <string>
#include <vector>

#include "snaxels/mesh/mesh_animation.h"
#include "snaxels/mesh/triangle_soup.h"

namespace snaxels {

/// Where mesh files are read: empty (the default, and what a library user
/// gets) reads them in this process; a path names the snaxels-import helper
/// that reads each file in its own process. The CLI and the application set
/// it at start-up.
void set_mesh_importer(std::string helper_path);
std::string mesh_importer();

/// The snaxels-import helper installed beside the running program (or in
/// ../libexec/snaxels/ of it). When there is none, the path beside the
/// program, so that reading a file names what is missing.
std::string importer_beside_executable();

struct ImportLimits {
    double seconds = 0.0;           ///< wall clock, from start to the last byte
    std::uint64_t memory_bytes = 0; ///< the helper's address space
};

/// The limits for a file of @p file_size bytes: 8 s plus 1 s per 4 MB, and
/// 2 GiB or 64 times the file's size (at most three quarters of the
/// machine's memory); SNAXELS_IMPORT_SECONDS and SNAXELS_IMPORT_MEMORY_MB
/// replace them.
ImportLimits import_limits(std::uintmax_t file_size);

namespace detail {

/// What the helper reads: the soup (read_triangle_soup) or the clip list
/// (animation_clips, which reads the whole scene too).
enum class ImportRequest : char { Soup = 's', Clips = 'c' };

/// Runs @p helper on @p path; throws snaxels::Error "PATH: cause" when it
/// reports an error, crashes, overruns a limit or cannot be started.
TriangleSoup read_soup_isolated(const std::string& helper, const std::string& path);
std::vector<AnimationClipInfo> read_clips_isolated(const std::string& helper, const std::string& path);

/// The helper's side: reads @p path in this process and writes the reply
/// for @p request to file descriptor @p fd. Returns the exit status.
int serve_import(ImportRequest request, const std::string& path, int fd);

/// In-process readers (what the helper runs).
TriangleSoup read_triangle_soup_here(const std::string& path);
std::vector<AnimationClipInfo> animation_clips_here(const std::string& path);

} // namespace detail
} // namespace snaxels
