#pragma once
/// Writing output files so that a failure never leaves a half-written file.

#include <string>

namespace snaxels {

/// Writes @p content to a temporary file beside @p path (".NAME.PID.XXXXXX"),
/// syncs it to disk, renames it over @p path and syncs the folder: killed or
/// crashed at any moment, @p path is the old file or the new one, whole.
/// Temporaries of @p path left by writers that were killed (their process
/// is gone) are removed first. Throws snaxels::Error "cannot write PATH:
/// reason" on failure, in which case @p path is untouched and no temporary
/// file remains.
void write_file_atomically(const std::string& path, const std::string& content);

} // namespace snaxels
