#pragma once
// Internal to core/export: the animated strokes of one contour kind
// (stroke_paths in animated_paths.h). One visible and one hidden path per
// contour sequence, each shown for the sequence's whole life; its
// visibility runs are the path's subpaths, which grow from and shrink to
// points as runs appear and vanish. Styles with surface-fastened dashes give each run its own path
// instead (a path has one dash offset; SVG restarts dashes at every subpath).

#include <utility>
#include <vector>

namespace snaxels {

/// A stretch of a loop's arc-length parameter u of one visibility class
/// (0 visible, 1 hidden, kLeftOut: a part its contour leaves out): [u0, u1] (u1 may pass 1 on closed loops), or the
/// whole closed loop.
/// The class of the stretches of a loop that are not drawn (kNotDrawn).
constexpr int kLeftOut = 2;

struct ClassSpan {
    int cls = 0;
    bool whole = false;
    double u0 = 0.0, u1 = 1.0;
};

/// The class spans of one loop from its visibility changes (u, class after
/// it; sorted), @p cls0 holding at u = 0. Stretches shorter than
/// @p min_u (QI flicker at T-junctions) take their longer neighbour's class.
std::vector<ClassSpan> class_spans(const std::vector<std::pair<double, int>>& changes, int cls0, bool closed,
                                   double min_u);

} // namespace snaxels
