#include "core/util/atomic_file.h"

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

#include "core/error.h"

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

void write_file_atomically(const std::string& path, const std::string& content) {
    namespace fs = std::filesystem;
    auto fail = [&](const std::string& why) { throw Error("cannot write " + path + ": " + why); };
    std::error_code ec;
    if (fs::is_directory(path, ec)) fail("it is a directory");
    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec)) fail("the folder " + dir.string() + " does not exist");
    remove_stale_temporaries(dir, target);

    std::string tmp = (dir / (temp_prefix(target, long(::getpid())) + "XXXXXX")).string();
    const int fd = ::mkstemp(tmp.data());
    if (fd < 0) fail(std::strerror(errno));
    const char* data = content.data();
    std::size_t left = content.size();
    while (left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int err = errno;
            ::close(fd);
            ::unlink(tmp.c_str());
            fail(std::strerror(err));
        }
        data += n;
        left -= std::size_t(n);
    }
    // mkstemp creates 0600; give the file the usual permissions.
    const mode_t mask = ::umask(0);
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    // The data reaches the disk before the name points at it, and the
    // rename itself is made durable by syncing the folder: after a crash or
    // a power cut the file is the old one or the new one, whole.
    if (::fsync(fd) != 0 || ::close(fd) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail(std::strerror(err));
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        const int err = errno;
        ::unlink(tmp.c_str());
        fail(std::strerror(err));
    }
    if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY); dfd >= 0) {
        ::fsync(dfd); // best effort: some file systems refuse to sync a folder
        ::close(dfd);
    }
}

} // namespace snaxels
