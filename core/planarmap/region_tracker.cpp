#include "snaxels/planarmap/region_tracker.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>

namespace snaxels {

std::vector<std::uint64_t> RegionTracker::step(const PlanarMap& map) {
    std::vector<Summary> now;
    for (const MapRegion& r : map.regions) {
        glm::dvec2 c(0.0);
        std::size_t n = 0;
        for (const auto& loop : r.polygons)
            for (const glm::dvec2& p : loop) c += p, ++n;
        now.push_back({r.cls, r.k, r.material, r.polygons.size(), n ? c / double(n) : c, r.area});
    }
    auto compatible = [&](std::size_t r, std::size_t p) {
        return now[r].cls == prev_[p].cls && std::abs(now[r].k - prev_[p].k) < 1e-9 && now[r].material == prev_[p].material;
    };
    // Candidate continuations, best first: (score, region, previous region).
    std::vector<std::tuple<double, std::size_t, std::size_t>> candidates;
    if (!map.vertex_region.empty() && map.vertex_region.size() == prev_vertex_region_.size()) {
        std::unordered_map<std::uint64_t, std::size_t> shared;
        for (const VertexId v : map.vertex_region.ids()) {
            const std::int32_t r = map.vertex_region[v], p = prev_vertex_region_[v];
            if (r >= 0 && p >= 0) ++shared[(std::uint64_t(r) << 32) | std::uint32_t(p)];
        }
        for (const auto& [key, count] : shared) {
            const std::size_t r = std::size_t(key >> 32), p = std::size_t(key & 0xffffffffu);
            if (r < now.size() && p < prev_.size() && compatible(r, p)) candidates.emplace_back(-double(count), r, p);
        }
    }
    // Where regions merge, the oldest track goes on (the region that has
    // been followed longest keeps its path); a previous region counts for a
    // region when it gives it at least a quarter of the vertices its best
    // one does. Where a region splits, the part with most of it goes on.
    std::vector<double> best(now.size(), 0.0);
    for (const auto& [score, r, p] : candidates) best[r] = std::max(best[r], -score);
    std::vector<std::tuple<std::uint64_t, double, std::size_t, std::size_t>> merges; // (track, -count, r, p)
    for (const auto& [score, r, p] : candidates)
        if (-score >= 0.25 * best[r]) merges.emplace_back(prev_tracks_[p], score, r, p);
    std::sort(merges.begin(), merges.end());
    std::vector<std::uint64_t> tracks(now.size(), 0);
    std::vector<char> assigned(now.size(), 0), taken(prev_.size(), 0);
    for (const auto& [track, score, r, p] : merges) {
        if (assigned[r] || taken[p]) continue;
        tracks[r] = track;
        assigned[r] = taken[p] = 1;
    }
    // The rest (the post-processed map's regions, or regions that hold no
    // vertex) continue the nearest region of their class left over.
    candidates.clear();
    for (std::size_t r = 0; r < now.size(); ++r)
        for (std::size_t p = 0; p < prev_.size() && !assigned[r]; ++p) {
            if (taken[p] || !compatible(r, p)) continue;
            const double d = glm::length(now[r].centre - prev_[p].centre);
            // A region moves less than its own size between frames.
            if (d <= std::max(8.0, 0.5 * std::sqrt(std::max(now[r].area, prev_[p].area)))) candidates.emplace_back(d, r, p);
        }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [score, r, p] : candidates) {
        if (assigned[r] || taken[p]) continue;
        tracks[r] = prev_tracks_[p];
        assigned[r] = taken[p] = 1;
    }
    for (std::size_t r = 0; r < now.size(); ++r)
        if (!assigned[r]) tracks[r] = next_++;
    prev_vertex_region_ = map.vertex_region;
    prev_ = std::move(now);
    prev_tracks_ = tracks;
    return tracks;
}

} // namespace snaxels
