#pragma once
// A frame counter on standard error for long runs (only on a terminal).

#include <cstdio>

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

} // namespace snaxels::cli
