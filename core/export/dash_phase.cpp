#include "snaxels/export/dash_phase.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace snaxels {
namespace {

constexpr double kTwoPi = 6.283185307179586;
// How far (pixels) a carried dash may land from the new loop and still count.
constexpr double kCapture = 2.0;
// At most this many carried samples vote per loop (spread along the old loops).
constexpr std::size_t kSamplesPerLoop = 256;

// Nearest point on a polyline, found through a uniform grid of its segments.
class SegmentGrid {
  public:
    SegmentGrid(const std::vector<glm::dvec2>& q, bool closed, double cell) : q_(q), cell_(cell) {
        const std::size_t segments = closed ? q.size() : q.size() - 1;
        for (std::size_t s = 0; s < segments; ++s) {
            const glm::dvec2 a = q[s], b = q[(s + 1) % q.size()];
            const auto x0 = key(std::min(a.x, b.x)), x1 = key(std::max(a.x, b.x));
            const auto y0 = key(std::min(a.y, b.y)), y1 = key(std::max(a.y, b.y));
            for (auto x = x0; x <= x1; ++x)
                for (auto y = y0; y <= y1; ++y) cells_[pack(x, y)].push_back(s);
        }
    }
    /// (distance, segment, fraction along it) of the nearest point within kCapture.
    bool nearest(const glm::dvec2& p, std::size_t& segment, double& fraction, double& distance) const {
        distance = kCapture;
        bool found = false;
        for (auto x = key(p.x - kCapture); x <= key(p.x + kCapture); ++x)
            for (auto y = key(p.y - kCapture); y <= key(p.y + kCapture); ++y) {
                const auto it = cells_.find(pack(x, y));
                if (it == cells_.end()) continue;
                for (const std::size_t s : it->second) {
                    const glm::dvec2 a = q_[s], b = q_[(s + 1) % q_.size()], ab = b - a;
                    const double l2 = glm::dot(ab, ab);
                    const double t = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
                    const double d = glm::length(p - (a + t * ab));
                    if (d <= distance) distance = d, segment = s, fraction = t, found = true;
                }
            }
        return found;
    }

  private:
    std::int64_t key(double v) const { return std::int64_t(std::floor(v / cell_)); }
    static std::int64_t pack(std::int64_t x, std::int64_t y) { return (x << 32) ^ (y & 0xffffffff); }
    const std::vector<glm::dvec2>& q_;
    double cell_;
    std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

} // namespace

std::vector<double> arc_lengths(const std::vector<glm::dvec2>& q) {
    std::vector<double> arc(q.size(), 0.0);
    for (std::size_t i = 1; i < q.size(); ++i) arc[i] = arc[i - 1] + glm::length(q[i] - q[i - 1]);
    return arc;
}

std::vector<double> SurfaceDashPhase::step(const std::vector<PhaseLoop>& loops,
                                           const std::function<glm::dvec2(const SurfacePoint&)>& project) {
    std::vector<double> phase(loops.size(), 0.0);
    // Carry the previous frame's dashes: where its samples land now.
    std::vector<glm::dvec2> landed(previous_.size());
    for (std::size_t i = 0; i < previous_.size(); ++i) landed[i] = project(previous_[i].where);
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const PhaseLoop& loop = loops[l];
        if (loop.q.size() < 2 || previous_.empty()) continue;
        const std::vector<double> arc = arc_lengths(loop.q);
        const SegmentGrid grid(loop.q, loop.closed, 4.0);
        double sx = 0.0, sy = 0.0;
        std::size_t votes = 0;
        for (std::size_t i = 0; i < previous_.size(); ++i) {
            std::size_t segment = 0;
            double fraction = 0.0, distance = 0.0;
            if (!grid.nearest(landed[i], segment, fraction, distance)) continue;
            const glm::dvec2 a = loop.q[segment], b = loop.q[(segment + 1) % loop.q.size()];
            const double s = arc[segment] + fraction * glm::length(b - a);
            // The pattern's phase at this loop's first vertex, as this sample says.
            const double angle = kTwoPi * (previous_[i].phase - s) / period_;
            sx += std::cos(angle);
            sy += std::sin(angle);
            ++votes;
        }
        if (votes && std::hypot(sx, sy) > 1e-9) {
            double p = std::atan2(sy, sx) / kTwoPi * period_;
            phase[l] = p < 0.0 ? p + period_ : p;
        }
    }
    // Remember samples of this frame's loops with their phases.
    previous_.clear();
    for (std::size_t l = 0; l < loops.size(); ++l) {
        const PhaseLoop& loop = loops[l];
        if (loop.q.empty()) continue;
        const std::vector<double> arc = arc_lengths(loop.q);
        const std::size_t stride = std::max<std::size_t>(1, loop.q.size() / kSamplesPerLoop);
        for (std::size_t i = 0; i < loop.q.size(); i += stride)
            previous_.push_back({loop.surface[i], std::fmod(phase[l] + arc[i], period_)});
    }
    return phase;
}

} // namespace snaxels
