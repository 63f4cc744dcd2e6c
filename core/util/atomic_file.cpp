#include "snaxels/util/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include "snaxels/error.h"

namespace snaxels {

namespace {

/// The temporary beside @p target of process @p pid: ".NAME.PID.XXXXXX".
std::string temp_prefix(const std::filesystem::path& target, long pid) {
    return "." + target.filename().string() + "." + std::to_string(pid) + ".";
}

/// Temporaries for @p target left by runs that were killed before they
/// could rename or remove them (their process is gone): removed.
void remove_stale_temporaries(const std::filesystem::path& dir, const std::filesystem::path& target) {
    namespace fs = std::filesystem;
    const std::string stem = "." + target.filename().string() + ".";
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= stem.size() + 7 || name.compare(0, stem.size(), stem) != 0) continue;
        // NAME.PID.XXXXXX: the writer's process id, then mkstemp's six characters.
        const std::string rest = name.substr(stem.size());
        const auto dot = rest.find('.');
        if (dot == std::string::npos || rest.size() - dot - 1 != 6 || dot == 0) continue;
        if (rest.find_first_not_of("0123456789") != dot) continue;
        const long pid = std::strtol(rest.substr(0, dot).c_str(), nullptr, 10);
        if (pid <= 0 || pid == long(::getpid())) continue;
        if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue; // its writer may still be at work
        std::error_code ignored;
        fs::remove(it->path(), ignored);
    }
}

} // namespace

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path_, ec)) fail("it is a directory");
    const fs::path target(path_);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec)) fail("the folder " + dir.string() + " does not exist");
    dir_ = dir.string();
    remove_stale_temporaries(dir, target);
    tmp_ = (dir / (temp_prefix(target, long(::getpid())) + "XXXXXX")).string();
    fd_ = ::mkstemp(tmp_.data());
    if (fd_ < 0) {
        tmp_.clear();
        fail(std::strerror(errno));
    }
}

AtomicFile::~AtomicFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!tmp_.empty()) ::unlink(tmp_.c_str());
}

void AtomicFile::fail(const std::string& why) {
    const std::string message = "cannot write " + path_ + ": " + why;
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
    if (!tmp_.empty()) ::unlink(tmp_.c_str());
    tmp_.clear();
    throw Error(message);
}

void AtomicFile::write(const char* data, std::size_t size) {
    if (fd_ < 0) throw Error("cannot write " + path_ + ": the file is closed");
    while (size > 0) {
        const ssize_t n = ::write(fd_, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            fail(std::strerror(errno));
        }
        data += n;
        size -= std::size_t(n);
    }
}

void AtomicFile::commit() {
    if (fd_ < 0) throw Error("cannot write " + path_ + ": the file is closed");
    // mkstemp creates 0600; give the file the usual permissions.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd_, 0666 & ~mask);
    // The data reaches the disk before the name points at it, and the
    // rename itself is made durable by syncing the folder: after a crash or
    // a power cut the file is the old one or the new one, whole.
    const int fd = fd_;
    fd_ = -1;
    if (::fsync(fd) != 0) {
        const int err = errno;
        ::close(fd);
        fail(std::strerror(err));
    }
    if (::close(fd) != 0) fail(std::strerror(errno));
    if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail(std::strerror(errno));
    tmp_.clear();
    if (const int dfd = ::open(dir_.c_str(), O_RDONLY | O_DIRECTORY); dfd >= 0) {
        ::fsync(dfd); // best effort: some file systems refuse to sync a folder
        ::close(dfd);
    }
}

void write_file_atomically(const std::string& path, const std::string& content) {
    AtomicFile file(path);
    file.write(content);
    file.commit();
}

} // namespace snaxels
