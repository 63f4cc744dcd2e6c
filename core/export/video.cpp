#include "snaxels/export/video.h"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "snaxels/error.h"
#include "snaxels/util/atomic_file.h"

extern char** environ;

namespace snaxels {

namespace {

bool executable(const std::string& path) { return ::access(path.c_str(), X_OK) == 0 && !std::filesystem::is_directory(path); }

std::string format_number(double v) {
    std::ostringstream s;
    s.precision(12);
    s << v;
    return s.str();
}

/// The last lines of ffmpeg's messages, for an error.
std::string tail_of(int fd) {
    std::string text;
    if (::lseek(fd, 0, SEEK_SET) == 0) {
        char buffer[4096];
        for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    }
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
    if (text.size() > 600) text = "..." + text.substr(text.size() - 600);
    for (char& c : text)
        if (c == '\n' || c == '\r') c = ' ';
    return text;
}

} // namespace

std::string require_ffmpeg() {
    if (const char* v = std::getenv("SNAXELS_FFMPEG"); v && *v) {
        if (executable(v)) return v;
        throw Error(std::string("cannot encode video: SNAXELS_FFMPEG names ") + v + ", which is not a program");
    }
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && executable(dir + "/ffmpeg")) return dir + "/ffmpeg";
    throw Error("cannot encode video: the ffmpeg program was not found (install FFmpeg: apt install ffmpeg)");
}

struct VideoEncoder::Impl {
    std::string path;
    AtomicFile file;
    pid_t pid = -1;
    int in = -1;  ///< the pipe to ffmpeg's standard input
    int log = -1; ///< ffmpeg's messages
    int width, height;
    bool finished = false;

    Impl(const std::string& p, OutputKind kind, int w, int h, double fps, int crf) : path(p), file(p), width(w), height(h) {
        const std::string program = require_ffmpeg();
        std::vector<std::string> args{program, "-hide_banner", "-loglevel", "error", "-y",
                                      "-f", "rawvideo", "-pix_fmt", "rgba",
                                      "-s", std::to_string(w) + "x" + std::to_string(h),
                                      "-framerate", format_number(fps), "-i", "pipe:0"};
        switch (kind) {
        case OutputKind::Mp4:
            args.insert(args.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2:color=white", "-c:v", "libx264", "-pix_fmt",
                                     "yuv420p", "-crf", std::to_string(crf >= 0 ? crf : kDefaultMp4Crf), "-preset", "medium", "-movflags", "+faststart", "-f", "mp4"});
            break;
        case OutputKind::Webm:
            args.insert(args.end(), {"-c:v", "libvpx-vp9", "-pix_fmt", "yuv420p", "-crf", std::to_string(crf >= 0 ? crf : kDefaultWebmCrf), "-b:v", "0",
                                     "-deadline", "good", "-cpu-used", "4", "-row-mt", "1", "-f", "webm"});
            break;
        case OutputKind::Gif:
            // A palette per frame (made and used as the frames come: no
            // frame waits for the whole clip), no dithering: lines stay crisp.
            args.insert(args.end(), {"-filter_complex",
                                     "[0:v]split[a][b];[a]palettegen=stats_mode=single:reserve_transparent=0[p];"
                                     "[b][p]paletteuse=new=1:dither=none",
                                     "-loop", "0", "-f", "gif"});
            break;
        default: throw Error("cannot encode " + p + ": not a video format");
        }
        args.push_back(file.temp_path());

        char log_name[] = "/tmp/snaxels-ffmpeg-XXXXXX";
        log = ::mkstemp(log_name);
        if (log < 0) throw Error("cannot encode " + p + ": cannot make a log file: " + std::strerror(errno));
        ::unlink(log_name);
        int fds[2];
        if (::pipe2(fds, O_CLOEXEC) != 0) throw Error("cannot encode " + p + ": " + std::strerror(errno));
        in = fds[1];
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
        posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
        posix_spawn_file_actions_adddup2(&actions, log, 2);
        std::vector<char*> argv;
        for (std::string& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        const int rc = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
        posix_spawn_file_actions_destroy(&actions);
        ::close(fds[0]);
        if (rc != 0) {
            pid = -1;
            throw Error("cannot encode " + p + ": cannot run " + program + ": " + std::strerror(rc));
        }
    }

    ~Impl() {
        if (in >= 0) ::close(in);
        if (pid > 0) {
            if (!finished) ::kill(pid, SIGTERM);
            int status = 0;
            while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
            }
        }
        if (log >= 0) ::close(log);
    }

    /// Waits for ffmpeg; its failure as an Error.
    void wait_for_ffmpeg() {
        int status = 0;
        while (::waitpid(pid, &status, 0) < 0) {
            if (errno != EINTR) throw Error("cannot encode " + path + ": " + std::strerror(errno));
        }
        pid = -1;
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
            const std::string said = tail_of(log);
            throw Error("cannot encode " + path + ": ffmpeg failed" + (said.empty() ? "" : ": " + said));
        }
    }

    void write_all(const std::uint8_t* data, std::size_t size) {
        // A write to a pipe whose reader died raises SIGPIPE, which would
        // end the whole program: blocked on this thread while writing, and
        // a pending one taken back, so the failure is ffmpeg's message.
        sigset_t pipe_signal, old;
        sigemptyset(&pipe_signal);
        sigaddset(&pipe_signal, SIGPIPE);
        pthread_sigmask(SIG_BLOCK, &pipe_signal, &old);
        int error = 0;
        while (size > 0) {
            const ssize_t n = ::write(in, data, size);
            if (n < 0) {
                if (errno == EINTR) continue;
                error = errno;
                break;
            }
            data += n;
            size -= static_cast<std::size_t>(n);
        }
        if (error == EPIPE) {
            const timespec zero{0, 0};
            while (sigtimedwait(&pipe_signal, nullptr, &zero) == SIGPIPE) {
            }
        }
        pthread_sigmask(SIG_SETMASK, &old, nullptr);
        if (error != 0) {
            ::close(in);
            in = -1;
            wait_for_ffmpeg(); // throws ffmpeg's own message
            throw Error("cannot encode " + path + ": " + std::strerror(error));
        }
    }
};

VideoEncoder::VideoEncoder(const std::string& path, OutputKind kind, int width, int height, double fps, int crf)
    : impl_(std::make_unique<Impl>(path, kind, width, height, fps, crf)) {}

VideoEncoder::~VideoEncoder() = default;

void VideoEncoder::add(const RgbaImage& frame) {
    if (frame.width != impl_->width || frame.height != impl_->height)
        throw InternalError("a video frame of " + std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                            " in a video of " + std::to_string(impl_->width) + "x" + std::to_string(impl_->height));
    impl_->write_all(frame.rgba.data(), frame.rgba.size());
}

void VideoEncoder::finish() {
    ::close(impl_->in);
    impl_->in = -1;
    impl_->wait_for_ffmpeg();
    impl_->finished = true;
    impl_->file.commit();
}

} // namespace snaxels
