#include "snaxels/mesh/isolated_import.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <new>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "snaxels/error.h"
#include "snaxels/util/memory.h"

extern char** environ;

namespace snaxels {
namespace {

namespace fs = std::filesystem;

std::mutex importer_mutex;
std::string importer_path;

// The reply: a status byte, then either a message or the payload.
constexpr unsigned char kOk = 0, kFailed = 1;

class Writer {
  public:
    explicit Writer(int fd) : fd_(fd) {}
    ~Writer() { flush(); }
    void bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const char*>(data);
        if (buffer_.size() + n > kChunk) flush();
        if (n >= kChunk) return raw(p, n);
        buffer_.append(p, n);
    }
    template <class T> void value(const T& v) { bytes(&v, sizeof v); }
    void text(const std::string& s) {
        value(static_cast<std::uint32_t>(s.size()));
        bytes(s.data(), s.size());
    }
    void flush() {
        raw(buffer_.data(), buffer_.size());
        buffer_.clear();
    }

  private:
    static constexpr std::size_t kChunk = 1 << 16;
    void raw(const char* p, std::size_t n) {
        while (n > 0) {
            const ssize_t w = ::write(fd_, p, n);
            if (w < 0 && errno == EINTR) continue;
            if (w <= 0) std::_Exit(4); // the reader is gone; nothing to tell
            p += w;
            n -= std::size_t(w);
        }
    }
    int fd_;
    std::string buffer_;
};

class Reader {
  public:
    Reader(const std::string& data, const std::string& path) : data_(data), path_(path) {}
    template <class T> T value() {
        T v{};
        bytes(&v, sizeof v);
        return v;
    }
    void bytes(void* out, std::size_t n) {
        if (n > data_.size() - at_) throw Error(path_ + ": the importer's reply is cut short");
        if (n == 0) return;  // an empty vector's data() may be null, which memcpy must not see
        std::memcpy(out, data_.data() + at_, n);
        at_ += n;
    }
    std::string text() {
        const auto n = value<std::uint32_t>();
        std::string s(std::min<std::size_t>(n, data_.size() - at_), '\0');
        bytes(s.data(), n);
        return s;
    }
    std::size_t left() const { return data_.size() - at_; }

  private:
    const std::string& data_;
    const std::string& path_;
    std::size_t at_ = 0;
};

double env_number(const char* name) {
    const char* v = std::getenv(name);
    if (!v || !*v) return 0.0;
    char* end = nullptr;
    const double x = std::strtod(v, &end);
    return (end && *end == '\0' && std::isfinite(x) && x > 0) ? x : 0.0;
}

std::string describe_seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g s", s);
    return buf;
}

// The last non-empty line the helper wrote to stderr (Assimp's assertion
// text, say), trimmed to something a message can carry.
std::string last_line(std::string err) {
    while (!err.empty() && (err.back() == '\n' || err.back() == '\r' || err.back() == ' ')) err.pop_back();
    const auto nl = err.find_last_of('\n');
    std::string line = nl == std::string::npos ? err : err.substr(nl + 1);
    if (line.size() > 200) line = line.substr(0, 200) + "...";
    return line;
}

struct HelperRun {
    std::string out, err;
    int status = 0;
    bool timed_out = false;
    long max_rss_kb = 0;
};

// Spawns the helper on @p path and collects both of its streams until it
// exits or the time limit passes (then it is killed).
HelperRun run_helper(const std::string& helper, detail::ImportRequest request, const std::string& path,
                     const ImportLimits& limits) {
    if (::access(helper.c_str(), X_OK) != 0)
        throw Error(path + ": cannot start the mesh importer " + helper + " (" + std::strerror(errno) +
                    "); the installation is incomplete");
    int out[2], err[2];
    if (::pipe2(out, O_CLOEXEC) != 0) throw Error(path + ": cannot start the mesh importer (" + std::strerror(errno) + ")");
    if (::pipe2(err, O_CLOEXEC) != 0) {
        ::close(out[0]);
        ::close(out[1]);
        throw Error(path + ": cannot start the mesh importer (" + std::strerror(errno) + ")");
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, out[1], 1);
    posix_spawn_file_actions_adddup2(&actions, err[1], 2);
    const std::string memory = std::to_string(limits.memory_bytes);
    const std::string mode = request == detail::ImportRequest::Soup ? "--soup" : "--clips";
    std::vector<char*> argv = {const_cast<char*>(helper.c_str()), const_cast<char*>("--memory"),
                               const_cast<char*>(memory.c_str()), const_cast<char*>(mode.c_str()),
                               const_cast<char*>("--"), const_cast<char*>(path.c_str()), nullptr};
    pid_t pid = -1;
    const int spawned = ::posix_spawn(&pid, helper.c_str(), &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(out[1]);
    ::close(err[1]);
    if (spawned != 0) {
        ::close(out[0]);
        ::close(err[0]);
        throw Error(path + ": cannot start the mesh importer " + helper + " (" + std::strerror(spawned) + ")");
    }

    HelperRun run;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(limits.seconds);
    pollfd fds[2] = {{out[0], POLLIN, 0}, {err[0], POLLIN, 0}};
    std::string* sinks[2] = {&run.out, &run.err};
    int open = 2;
    char buf[1 << 16];
    while (open > 0) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) {
            run.timed_out = true;
            break;
        }
        const int ready = ::poll(fds, 2, int(std::min<long long>(left.count(), 1000)));
        if (ready < 0 && errno != EINTR) break;
        for (int i = 0; i < 2; ++i) {
            if (fds[i].fd < 0 || !(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            const ssize_t n = ::read(fds[i].fd, buf, sizeof buf);
            if (n > 0) {
                // stderr is only for the cause of a crash: keep its tail.
                sinks[i]->append(buf, std::size_t(n));
                if (i == 1 && run.err.size() > 8192) run.err.erase(0, run.err.size() - 4096);
            } else if (n == 0 || errno != EINTR) {
                ::close(fds[i].fd);
                fds[i].fd = -1;
                --open;
            }
        }
    }
    for (auto& f : fds)
        if (f.fd >= 0) ::close(f.fd);
    if (run.timed_out) ::kill(pid, SIGKILL);
    rusage usage{};
    while (::wait4(pid, &run.status, 0, &usage) < 0 && errno == EINTR) {
    }
    run.max_rss_kb = usage.ru_maxrss;
    return run;
}

std::string signal_name(int sig) {
    switch (sig) {
    case SIGABRT: return "SIGABRT";
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGKILL: return "SIGKILL";
    case SIGXCPU: return "SIGXCPU";
    default: return "signal " + std::to_string(sig);
    }
}

// Runs the helper and returns its payload, or throws what went wrong.
std::string import_reply(const std::string& helper, detail::ImportRequest request, const std::string& path) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(path, ec);
    const ImportLimits limits = import_limits(ec ? 0 : size);
    const HelperRun run = run_helper(helper, request, path, limits);
    if (run.timed_out)
        throw Error(path + ": reading the file took longer than " + describe_seconds(limits.seconds) +
                    " and was stopped (it may declare far more data than it holds; SNAXELS_IMPORT_SECONDS "
                    "raises the limit)");
    if (WIFSIGNALED(run.status)) {
        const std::string cause = last_line(run.err);
        throw Error(path + ": the mesh reader crashed on this file (" + signal_name(WTERMSIG(run.status)) +
                    (cause.empty() ? "" : ": " + cause) +
                    "); the file is damaged or uses a feature the reader mishandles");
    }
    if (!run.out.empty()) {
        Reader reply(run.out, path);
        const auto status = reply.value<unsigned char>();
        if (status == kFailed) throw Error(reply.text());
        if (status == kOk && WIFEXITED(run.status) && WEXITSTATUS(run.status) == 0) return run.out.substr(1);
    }
    if (WIFEXITED(run.status) && WEXITSTATUS(run.status) == 5)
        throw Error(path + ": reading the file needs more than " + describe_bytes(limits.memory_bytes) +
                    " of memory and was stopped (SNAXELS_IMPORT_MEMORY_MB raises the limit)");
    const std::string cause = last_line(run.err);
    throw Error(path + ": the mesh reader failed (exit " +
                std::to_string(WIFEXITED(run.status) ? WEXITSTATUS(run.status) : -1) + ")" +
                (cause.empty() ? "" : ": " + cause));
}

} // namespace

void set_mesh_importer(std::string helper_path) {
    const std::lock_guard lock(importer_mutex);
    importer_path = std::move(helper_path);
}

std::string mesh_importer() {
    const std::lock_guard lock(importer_mutex);
    return importer_path;
}

std::string importer_beside_executable() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) return "snaxels-import";
    const fs::path beside = self.parent_path() / "snaxels-import";
    for (const fs::path& candidate : {beside, self.parent_path().parent_path() / "libexec/snaxels/snaxels-import"})
        if (::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    return beside.string();
}

ImportLimits import_limits(std::uintmax_t file_size) {
    ImportLimits limits;
    limits.seconds = 8.0 + double(file_size) / (4.0 * 1024 * 1024);
    const std::uint64_t gib = 1ull << 30;
    limits.memory_bytes = std::max<std::uint64_t>(2 * gib, std::uint64_t(file_size) * 64);
    limits.memory_bytes = std::min<std::uint64_t>(limits.memory_bytes, machine_memory_bytes() / 4 * 3);
    if (const double s = env_number("SNAXELS_IMPORT_SECONDS"); s > 0) limits.seconds = s;
    if (const double mb = env_number("SNAXELS_IMPORT_MEMORY_MB"); mb > 0)
        limits.memory_bytes = std::uint64_t(mb * 1024 * 1024);
    return limits;
}

namespace detail {

TriangleSoup read_soup_isolated(const std::string& helper, const std::string& path) {
    const std::string payload = import_reply(helper, ImportRequest::Soup, path);
    Reader in(payload, path);
    const auto nv = in.value<std::uint64_t>(), nt = in.value<std::uint64_t>();
    if (nv > in.left() / sizeof(glm::dvec3) || nt > in.left() / (3 * sizeof(std::uint32_t)))
        throw Error(path + ": the importer's reply is cut short");
    TriangleSoup soup;
    soup.positions.resize(nv);
    soup.triangles.resize(nt);
    in.bytes(soup.positions.data(), nv * sizeof(glm::dvec3));
    in.bytes(soup.triangles.data(), nt * sizeof(soup.triangles[0]));
    const auto nn = in.value<std::uint64_t>();
    if (nn != 0 && nn != nv) throw Error(path + ": the importer's reply has normals for some vertices only");
    if (nn > in.left() / sizeof(glm::dvec3)) throw Error(path + ": the importer's reply is cut short");
    soup.normals.resize(nn);
    in.bytes(soup.normals.data(), nn * sizeof(glm::dvec3));
    // The parts: objects (name, path), materials (name, RGBA), then per
    // triangle an object and a material, or none.
    const auto no = in.value<std::uint32_t>();
    for (std::uint32_t i = 0; i < no && in.left() > 0; ++i) {
        SceneObject o;
        o.name = in.text();
        o.path = in.text();
        soup.objects.push_back(std::move(o));
    }
    const auto nm = in.value<std::uint32_t>();
    for (std::uint32_t i = 0; i < nm && in.left() > 0; ++i) {
        SceneMaterial m;
        m.name = in.text();
        for (int k = 0; k < 4; ++k) m.colour[k] = in.value<double>();
        soup.materials.push_back(std::move(m));
    }
    const auto np = in.value<std::uint64_t>();
    if (np != 0 && np != nt) throw Error(path + ": the importer's reply has parts for some triangles only");
    if (soup.objects.size() != no || soup.materials.size() != nm || np > in.left() / (2 * sizeof(std::uint32_t)))
        throw Error(path + ": the importer's reply is cut short");
    soup.triangle_object.resize(np);
    soup.triangle_material.resize(np);
    in.bytes(soup.triangle_object.data(), np * sizeof(std::uint32_t));
    in.bytes(soup.triangle_material.data(), np * sizeof(std::uint32_t));
    for (std::size_t t = 0; t < np; ++t)
        if (soup.triangle_object[t] >= no || soup.triangle_material[t] >= nm)
            throw Error(path + ": the importer's reply names a part the file does not have");
    return soup;
}

std::vector<AnimationClipInfo> read_clips_isolated(const std::string& helper, const std::string& path) {
    const std::string payload = import_reply(helper, ImportRequest::Clips, path);
    Reader in(payload, path);
    const auto n = in.value<std::uint32_t>();
    std::vector<AnimationClipInfo> clips;
    for (std::uint32_t i = 0; i < n; ++i) {
        AnimationClipInfo clip;
        clip.name = in.text();
        clip.duration = in.value<double>();
        clips.push_back(clip);
    }
    return clips;
}

int serve_import(ImportRequest request, const std::string& path, int fd) {
    Writer out(fd);
    try {
        if (request == ImportRequest::Soup) {
            const TriangleSoup soup = read_triangle_soup_here(path);
            out.value(kOk);
            out.value(std::uint64_t(soup.positions.size()));
            out.value(std::uint64_t(soup.triangles.size()));
            out.bytes(soup.positions.data(), soup.positions.size() * sizeof(glm::dvec3));
            out.bytes(soup.triangles.data(), soup.triangles.size() * sizeof(soup.triangles[0]));
            out.value(std::uint64_t(soup.normals.size()));
            out.bytes(soup.normals.data(), soup.normals.size() * sizeof(glm::dvec3));
            out.value(std::uint32_t(soup.objects.size()));
            for (const SceneObject& o : soup.objects) {
                out.text(o.name);
                out.text(o.path);
            }
            out.value(std::uint32_t(soup.materials.size()));
            for (const SceneMaterial& m : soup.materials) {
                out.text(m.name);
                for (int k = 0; k < 4; ++k) out.value(double(m.colour[k]));
            }
            out.value(std::uint64_t(soup.triangle_object.size()));
            out.bytes(soup.triangle_object.data(), soup.triangle_object.size() * sizeof(std::uint32_t));
            out.bytes(soup.triangle_material.data(), soup.triangle_material.size() * sizeof(std::uint32_t));
        } else {
            const auto clips = animation_clips_here(path);
            out.value(kOk);
            out.value(std::uint32_t(clips.size()));
            for (const auto& c : clips) {
                out.text(c.name);
                out.value(c.duration);
            }
        }
        return 0;
    } catch (const std::bad_alloc&) {
        return 5; // the parent names the memory limit
    } catch (const std::exception& e) {
        // Assimp turns a failed allocation into an error of its own.
        if (std::string(e.what()).find("bad_alloc") != std::string::npos) return 5;
        out.value(kFailed);
        out.text(e.what());
        return 1;
    }
}

} // namespace detail
} // namespace snaxels
