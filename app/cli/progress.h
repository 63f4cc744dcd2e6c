#pragma once
// A frame counter on standard error for long runs (only on a terminal),
// and the output format of the commands that write animations.

#include <unistd.h>

#include <cstdio>
#include <optional>
#include <string>

#include "app/cli/args.h"

#include "core/animation/pipeline.h"

namespace snaxels::cli {

class Progress {
  public:
    Progress(int total, bool enabled) : total_(total), enabled_(enabled) {}
    void set_total(int total) { total_ = total; }
    void update(int done) {
        if (!enabled_) return;
        const int width = 40, filled = total_ ? width * done / total_ : width;
        std::fprintf(stderr, "\r[%.*s%*s] %d/%d frames", filled,
                     "########################################", width - filled, "", done, total_);
        std::fflush(stderr);
    }
    void finish() {
        if (enabled_) std::fprintf(stderr, "\n");
    }

  private:
    int total_;
    bool enabled_;
};

/// The format of the animation written to @p output: --format (svg or
/// lottie) when given, else by the file's extension (.json: Lottie).
inline AnimationFormat parse_animation_format(const std::optional<std::string>& format, const std::string& output) {
    if (!format) return animation_format_for(output);
    if (*format == "svg") return AnimationFormat::Svg;
    if (*format == "lottie") return AnimationFormat::Lottie;
    throw UsageError("--format must be svg or lottie, not '" + *format + "'");
}

/// Runs @p job with a frame counter on standard error (when it is a terminal).
inline AnimationOutput run_animation_with_progress(const LoadedMesh& mesh, const std::string& mesh_path, AnimationJob job) {
    Progress progress(0, ::isatty(2));
    job.progress = [&](int done, int total) {
        progress.set_total(total);
        progress.update(done);
    };
    AnimationOutput result = run_animation(mesh, mesh_path, job);
    progress.finish();
    return result;
}

} // namespace snaxels::cli
