#pragma once
// A frame counter on standard error for long runs (only on a terminal),
// and the output files of the commands that write animations.

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/args.h"

#include "snaxels/animation/pipeline.h"
#include "snaxels/snaxel/parabolic.h"

namespace snaxels::cli {

class Progress {
  public:
    Progress(int total, bool enabled, const char* unit = "frames") : total_(total), enabled_(enabled), unit_(unit) {}
    void set_total(int total) { total_ = total; }
    void update(int done) {
        if (!enabled_) return;
        const int width = 40, filled = total_ ? width * done / total_ : width;
        std::fprintf(stderr, "\r[%.*s%*s] %d/%d %s", filled,
                     "########################################", width - filled, "", done, total_, unit_);
        std::fflush(stderr);
    }
    void finish() {
        if (enabled_) std::fprintf(stderr, "\n");
    }

  private:
    int total_;
    bool enabled_;
    const char* unit_;
};

/// Finds @p topology's parabolic curves (when @p kinds draw them) with a
/// counter of view steps on standard error (when it is a terminal), and
/// keeps them in the topology's pose for the engine (require_parabolic).
inline void find_parabolic_with_progress(const MeshTopology& topology, const std::vector<ContourSpec>& kinds) {
    if (std::none_of(kinds.begin(), kinds.end(), [](const ContourSpec& k) { return k.kind == ContourKind::Parabolic; }))
        return;
    Progress progress(0, ::isatty(2), "view steps (parabolic curves)");
    ParabolicOptions options;
    bool shown = false; // no bar when the curves are kept already
    options.progress = [&](int done, int total) {
        shown = true;
        progress.set_total(total);
        progress.update(done);
    };
    require_parabolic(topology, options);
    if (shown) progress.finish();
}

/// Checks, before any work, that @p output (-o) names a file the command
/// can write (its extension one of output_extensions()) and that --format,
/// when given, agrees with it (svg for .svg and .svgz, lottie for .json and
/// .lottie); throws UsageError naming what it can write otherwise.
inline void check_output(const std::optional<std::string>& format, const std::string& output) {
    const std::optional<OutputKind> kind = output_kind_for(output);
    if (!kind)
        throw UsageError("cannot write '" + output + "': the output's extension must be one of " + output_extensions());
    if (!format) return;
    if (*format != "svg" && *format != "lottie") throw UsageError("--format must be svg or lottie, not '" + *format + "'");
    if (is_video(*kind) || (*format == "lottie") != (document_format(*kind) == AnimationFormat::Lottie))
        throw UsageError("--format " + *format + " does not fit '" + output + "' (.svg and .svgz are SVG; .json and .lottie are Lottie)");
}

/// Runs @p job with a frame counter on standard error (when it is a terminal).
inline AnimationOutput run_animation_with_progress(const LoadedMesh& mesh, const std::string& mesh_path, AnimationJob job) {
    Progress progress(0, ::isatty(2));
    Progress parabolic(0, ::isatty(2), "view steps (parabolic curves)");
    job.parabolic_progress = [&](int done, int total) {
        parabolic.set_total(total);
        parabolic.update(done);
        if (done == total) parabolic.finish();
    };
    job.progress = [&](int done, int total) {
        progress.set_total(total);
        progress.update(done);
    };
    AnimationOutput result = run_animation(mesh, mesh_path, job);
    progress.finish();
    return result;
}

} // namespace snaxels::cli
