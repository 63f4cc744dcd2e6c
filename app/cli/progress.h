#pragma once
// A frame counter on standard error for long runs (only on a terminal).

#include <unistd.h>

#include <cstdio>

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
