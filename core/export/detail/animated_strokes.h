#pragma once
// Internal to core/export: the animated strokes of one contour kind
// (stroke_paths in animated_paths.h). One visible and one hidden path per
// contour sequence, each shown for the sequence's whole life; its
// visibility runs are the path's subpaths, which grow from and shrink to
// points as runs appear and vanish. Styles with surface-fastened dashes give each run its own path
// instead (a path has one dash offset; SVG restarts dashes at every subpath).

#include <array>
#include <utility>
#include <vector>

#include "snaxels/visibility/visibility.h"

namespace snaxels {

/// The class a stretch of a line is drawn in: visible, hidden (behind a
/// surface: QI above 0), or left out (a part its contour does not draw).
enum class StrokeClass { Visible, Hidden, LeftOut };
/// The classes that are drawn, in the order their paths are made.
inline constexpr std::array<StrokeClass, 2> kDrawnClasses{StrokeClass::Visible, StrokeClass::Hidden};
/// The class of a stretch of QI @p qi: kNotDrawn, the QI of what a contour
/// leaves out, is the one "not drawn" there is.
constexpr StrokeClass stroke_class(int qi) {
    return qi == kNotDrawn ? StrokeClass::LeftOut : qi > 0 ? StrokeClass::Hidden : StrokeClass::Visible;
}
/// One @p T per class, indexed by the class.
template <class T>
struct ByClass {
    std::array<T, 3> values{};
    T& operator[](StrokeClass c) { return values[static_cast<unsigned>(c)]; }
    const T& operator[](StrokeClass c) const { return values[static_cast<unsigned>(c)]; }
};

/// A stretch of a loop's arc-length parameter u of one class: [u0, u1] (u1
/// may pass 1 on closed loops), or the whole closed loop.
struct ClassSpan {
    StrokeClass cls = StrokeClass::Visible;
    bool whole = false;
    double u0 = 0.0, u1 = 1.0;
};

/// The class spans of one loop from its visibility changes (u, class after
/// it; sorted), @p cls0 holding at u = 0. Stretches shorter than
/// @p min_u (QI flicker at T-junctions) take their longer neighbour's class.
std::vector<ClassSpan> class_spans(const std::vector<std::pair<double, StrokeClass>>& changes, StrokeClass cls0, bool closed,
                                   double min_u);

} // namespace snaxels
