#pragma once
// Hand-built animation frames for the export tests: circles of snaxels with
// identities and visibility, one contour kind, 400 x 400 pixels.

#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/export/animated_svg.h"

namespace snaxels::test {

/// A circle of @p n snaxels; QI from @p hidden(angle).
inline DrawnLoop circle_loop(glm::dvec2 centre, double radius, int n, const std::function<bool(double)>& hidden) {
    DrawnLoop dl;
    dl.closed = true;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * M_PI * k / n;
        dl.q.push_back(centre + radius * glm::dvec2(std::cos(a), std::sin(a)));
        dl.qi.push_back(hidden(a) ? 1 : 0);
    }
    for (int k = 0; k < n; ++k) dl.change_before.push_back(0.5 * (dl.q[k] + dl.q[(k + n - 1) % n]));
    return dl;
}

/// Snaxel identities base .. base + n - 1 of contour sequence @p sequence.
inline AnimatedLoop ids(std::uint64_t sequence, std::uint64_t base, int n) {
    AnimatedLoop al;
    al.sequence = sequence;
    for (int k = 0; k < n; ++k) al.ids.push_back(base + std::uint64_t(k));
    return al;
}

/// A frame of one contour kind with these loops.
inline AnimationFrame frame_with(std::vector<std::pair<DrawnLoop, AnimatedLoop>> loops) {
    AnimationFrame f;
    f.drawing.width = f.drawing.height = 400;
    f.drawing.contours.resize(1);
    f.loops.resize(1);
    for (auto& [dl, al] : loops) {
        f.drawing.contours[0].loops.push_back(std::move(dl));
        f.loops[0].push_back(std::move(al));
    }
    return f;
}

} // namespace snaxels::test
