#pragma once
/// Writing output files so that a failure never leaves a half-written file.

#include <cstddef>
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

/// The same for a file written in pieces (a streamed export): the pieces go
/// to the temporary; commit() syncs it and renames it over the path. Until
/// then (and if the object is destroyed without commit, or the process
/// dies) the path keeps what it had. Errors throw as write_file_atomically's.
class AtomicFile {
  public:
    explicit AtomicFile(std::string path);
    ~AtomicFile();
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;

    void write(const char* data, std::size_t size);
    void write(const std::string& text) { write(text.data(), text.size()); }
    void commit();
    /// The temporary's path, for a program that writes the file itself
    /// (ffmpeg): it is committed, synced and renamed, the same way.
    const std::string& temp_path() const { return tmp_; }

  private:
    void fail(const std::string& why);
    std::string path_, tmp_, dir_;
    int fd_ = -1;
};

} // namespace snaxels
