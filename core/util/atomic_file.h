#pragma once
/// Writing output files so that a failure never leaves a half-written file.

#include <string>

namespace snaxels {

/// Writes @p content to a temporary file beside @p path and renames it over
/// @p path. Throws snaxels::Error "cannot write PATH: reason" on failure, in
/// which case @p path is untouched and no temporary file remains.
void write_file_atomically(const std::string& path, const std::string& content);

} // namespace snaxels
