#include "snaxels/snaxel/tracker.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <stdexcept>

#include "snaxels/error.h"
#include "snaxels/snaxel/intersections.h"
#include "snaxels/util/detail/float_mode.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {
namespace {

constexpr std::int32_t kNone = kNoSnaxel;

glm::dvec3 loop_centroid(const Fronts& fronts, const FrontLoop& loop,
                         const std::vector<glm::dvec3>& positions) {
    glm::dvec3 sum(0.0);
    fronts.for_each_in_loop(loop, [&](std::int32_t s) { sum += positions[s]; });
    return loop.size ? sum / double(loop.size) : sum;
}

// Midpoint of the closest pair of points of two loops (subsampled for long
// loops: every k-th point, at most about 200 of each): of the pairs at the
// least distance, the first in a's order, then b's. The samples of b are
// sorted by x, and each point of a looks only at those within the best
// distance so far in x.
glm::dvec3 closest_between(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
    if (a.empty() || b.empty()) return glm::dvec3(0.0);
    const std::size_t sa = std::max<std::size_t>(1, a.size() / 200), sb = std::max<std::size_t>(1, b.size() / 200);
    std::vector<std::size_t> bx;
    for (std::size_t j = 0; j < b.size(); j += sb) bx.push_back(j);
    std::sort(bx.begin(), bx.end(), [&](std::size_t p, std::size_t q) { return b[p].x < b[q].x || (b[p].x == b[q].x && p < q); });
    double best = std::numeric_limits<double>::infinity();
    std::size_t bi = 0, bj = 0;
    auto consider = [&](std::size_t i, std::size_t j) {
        const glm::dvec3 gap = a[i] - b[j];
        const double d = glm::dot(gap, gap); // (squared: the same order, no root)
        if (d < best || (d == best && (i < bi || (i == bi && j < bj)))) {
            best = d;
            bi = i;
            bj = j;
        }
    };
    for (std::size_t i = 0; i < a.size(); i += sa) {
        const auto at = std::lower_bound(bx.begin(), bx.end(), a[i].x, [&](std::size_t j, double x) { return b[j].x < x; });
        // Outward from a[i]'s x, while the gap in x alone is no more than the best distance.
        for (auto it = at; it != bx.end(); ++it) {
            const double dx = b[*it].x - a[i].x;
            if (dx * dx > best) break;
            consider(i, *it);
        }
        for (auto it = at; it != bx.begin();) {
            --it;
            const double dx = a[i].x - b[*it].x;
            if (dx * dx > best) break;
            consider(i, *it);
        }
    }
    return 0.5 * (a[bi] + b[bj]);
}

} // namespace

const char* event_name(EventKind kind) {
    switch (kind) {
    case EventKind::Creation: return "creation";
    case EventKind::Annihilation: return "annihilation";
    case EventKind::Split: return "split";
    case EventKind::Merge: return "merge";
    }
    return "creation";
}

ContourTracker::ContourTracker(const MeshTopology& topology, const ContourSpec& spec,
                               const EngineOptions& options)
    : topo_(topology), spec_(spec), options_(options) {}

const TrackedFrame& ContourTracker::step(const MeshTopology& pose, const Camera& camera, const Light& light) {
    if (!pose.same_connectivity(topo_))
        throw InternalError("ContourTracker::step: a pose of another mesh (its connectivity differs)");
    topo_ = pose;
    return step(camera, light);
}

const TrackedFrame& ContourTracker::step(const Camera& camera, const Light& light) {
    const FloatModeGuard mode; // one answer whichever thread steps it (float_mode.h)
    ++frame_number_;
    if (fault_injected("tracker-step", frame_number_))
        throw InternalError("fault injected in the tracker at frame " + std::to_string(frame_number_) + " (SNAXELS_FAULT)");
    if (frame_number_ == 0) {
        start(camera, light);
    } else if (spec_.kind == ContourKind::Intersection && require_intersections(topo_) != curves_) {
        track_intersections(); // the surfaces moved: where they meet moved too
    } else if (spec_.on_surface()) {
        // The mesh's own lines: the same snaxels on the same edges every
        // frame (they move with a moving mesh), no events.
        frame_.frame = frame_number_;
        frame_.events.clear();
        std::fill(frame_.born_from.begin(), frame_.born_from.end(), 0);
        frame_.fanouts = frame_.retreats = 0;
        frame_.contour.stats = ContourStats{};
    } else {
        track(camera, light);
    }
    return frame_;
}

void ContourTracker::start(const Camera& camera, const Light& light) {
    const SnaxelEngine engine(topo_);
    frame_ = TrackedFrame{};
    frame_.frame = frame_number_;
    frame_.contour = engine.compute(spec_, camera, light, options_);
    if (spec_.kind == ContourKind::Intersection) curves_ = require_intersections(topo_);
    const Fronts& fronts = frame_.contour.fronts;
    inside_.assign(topo_.n_vertices(), 0);
    if (frame_.contour.vertex_f.size() == inside_.size()) // (parabolic curves bound no vertex set)
        for (const VertexId v : topo_.vertices()) inside_[v] = frame_.contour.vertex_f[v] >= 0.0;
    frame_.snaxel_id.resize(fronts.snaxels.size());
    frame_.born_from.assign(fronts.snaxels.size(), 0);
    snaxel_position_.resize(fronts.snaxels.size());
    snaxel_arc_.clear(); // worked out anew as the next frame's roots need them
    for (std::size_t s = 0; s < fronts.snaxels.size(); ++s) {
        frame_.snaxel_id[s] = next_id_++;
        snaxel_position_[s] = engine.position(fronts.snaxels[s]);
    }
    for (std::size_t l = 0; l < fronts.loops.size(); ++l) frame_.loop_sequence.push_back(next_sequence_++);
}

void ContourTracker::track(const Camera& camera, const Light& light) {
    const auto t0 = std::chrono::steady_clock::now();
    const ContourFunction f(spec_, camera, light);
    TrackedFrame prev = std::move(frame_);
    const Fronts& old = prev.contour.fronts;
    const std::vector<glm::dvec3> old_position = std::move(snaxel_position_);
    const std::vector<NormalArc> old_arc = std::move(snaxel_arc_);
    frame_ = TrackedFrame{};
    frame_.frame = frame_number_;
    ContourResult& result = frame_.contour;
    result.spec = spec_;

    // 1. f everywhere (new regions may appear anywhere) and what changed side,
    // written over the frame before's (every vertex is written).
    result.vertex_f = std::move(prev.contour.vertex_f);
    f.evaluate_vertices(topo_, result.vertex_f);
    const std::vector<VertexId> changed = flip_changed_vertices();
    sweep_parents(old, changed);
    result.fronts = extract_fronts(topo_, inside_, crossing_edges(old, changed), std::move(spare_edge_snaxel_));
    place_snaxels(f, old, old_arc);
    set_snaxel_margins(topo_, camera, result);
    if (options_.check_invariants) {
        if (const std::string problem = check_fronts(topo_, result.fronts, inside_); !problem.empty())
            throw InternalError("tracked fronts broken at frame " + std::to_string(frame_number_) + ": " + problem);
    }
    match_loops(prev, old_position, assign_identities(prev, old_position));
    // The frame before's edge lookup, cleared where its snaxels were, serves the next frame.
    spare_edge_snaxel_ = std::move(prev.contour.fronts.edge_snaxel);
    if (spare_edge_snaxel_.size() == topo_.n_edges())
        for (const Snaxel& s : old.snaxels) spare_edge_snaxel_[s.edge] = kNoSnaxel;
    result.stats.fanouts = frame_.fanouts;
    result.stats.iterations = 1;
    for (const VisualEvent& e : frame_.events) {
        if (e.kind == EventKind::Merge) ++result.stats.merges;
        if (e.kind == EventKind::Split) ++result.stats.splits;
        if (e.kind == EventKind::Creation) ++result.stats.seeds;
    }
    result.stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

void ContourTracker::track_intersections() {
    const auto t0 = std::chrono::steady_clock::now();
    curves_ = require_intersections(topo_);
    TrackedFrame prev = std::move(frame_);
    const Fronts& old = prev.contour.fronts;
    const std::vector<glm::dvec3> old_position = std::move(snaxel_position_);
    frame_ = TrackedFrame{};
    frame_.frame = frame_number_;
    frame_.contour.spec = spec_;
    frame_.contour.fronts = curves_->fronts;
    frame_.contour.snaxel_pierced = curves_->pierced;
    const Fronts& fronts = frame_.contour.fronts;
    const SnaxelEngine engine(topo_);
    const std::size_t n = fronts.snaxels.size();
    snaxel_position_.resize(n);
    for (std::size_t s = 0; s < n; ++s) snaxel_position_[s] = engine.position(fronts.snaxels[s]);

    // The old snaxels by (edge, pierced face), and in cells of a grid for
    // the nearest one.
    std::map<std::pair<EdgeId, FaceId>, std::int32_t> by_key;
    for (std::size_t o = 0; o < old.snaxels.size(); ++o)
        by_key.emplace(std::pair{old.snaxels[o].edge, prev.contour.snaxel_pierced[o]}, std::int32_t(o));
    const double reach = 4.0 * topo_.mean_edge_length();
    auto cell = [&](const glm::dvec3& p) {
        return std::array<std::int64_t, 3>{std::int64_t(std::floor(p.x / reach)), std::int64_t(std::floor(p.y / reach)),
                                           std::int64_t(std::floor(p.z / reach))};
    };
    std::map<std::array<std::int64_t, 3>, std::vector<std::int32_t>> grid;
    for (std::size_t o = 0; o < old.snaxels.size(); ++o) grid[cell(old_position[o])].push_back(std::int32_t(o));
    auto nearest_old = [&](const glm::dvec3& p) {
        std::int32_t best = kNone;
        double best_d = reach * reach;
        const auto c = cell(p);
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == grid.end()) continue;
                    for (const std::int32_t o : it->second) {
                        const glm::dvec3 gap = old_position[o] - p;
                        const double d = glm::dot(gap, gap);
                        if (d < best_d || (d == best_d && o < best)) best_d = d, best = o;
                    }
                }
        return best;
    };
    frame_.snaxel_id.assign(n, 0);
    frame_.born_from.assign(n, 0);
    std::vector<std::int32_t> source(n, kNone);
    std::vector<std::uint8_t> continued(old.snaxels.size(), 0);
    for (std::size_t s = 0; s < n; ++s) {
        const auto it = by_key.find({fronts.snaxels[s].edge, frame_.contour.snaxel_pierced[s]});
        if (it == by_key.end()) continue;
        source[s] = it->second;
        frame_.snaxel_id[s] = prev.snaxel_id[it->second];
        continued[it->second] = 1;
    }
    // The rest: the nearest old snaxel's nearest new one takes its identity
    // on where no snaxel continued it; the others are born from it.
    std::vector<std::int32_t> best_child(old.snaxels.size(), kNone);
    for (std::size_t s = 0; s < n; ++s) {
        if (source[s] != kNone) continue;
        source[s] = nearest_old(snaxel_position_[s]);
        if (source[s] == kNone || continued[source[s]]) continue;
        std::int32_t& best = best_child[source[s]];
        const glm::dvec3 at = old_position[source[s]];
        if (best == kNone || glm::length(snaxel_position_[s] - at) < glm::length(snaxel_position_[best] - at))
            best = std::int32_t(s);
    }
    for (std::size_t s = 0; s < n; ++s) {
        if (frame_.snaxel_id[s]) continue;
        const std::int32_t parent = source[s];
        if (parent != kNone && best_child[parent] == std::int32_t(s)) {
            frame_.snaxel_id[s] = prev.snaxel_id[parent];
        } else {
            frame_.snaxel_id[s] = next_id_++;
            if (parent != kNone) frame_.born_from[s] = prev.snaxel_id[parent];
        }
    }
    match_loops(prev, old_position, source);
    frame_.contour.stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

/// The vertices whose side of the contour differs from inside_ (ascending),
/// flipped there.
std::vector<VertexId> ContourTracker::flip_changed_vertices() {
    const VertexData<double>& vertex_f = frame_.contour.vertex_f;
    std::vector<VertexId> changed;
    for (const VertexId v : topo_.vertices())
        if (std::uint8_t(vertex_f[v] >= 0.0) != inside_[v]) changed.push_back(v);
    for (const VertexId v : changed) inside_[v] ^= 1;
    return changed;
}

/// 2. Fronts move on: every changed vertex next to an old snaxel's edge is
/// passed by that snaxel (fan-out when it joins R, retreat when it leaves),
/// and the sweep carries the same parent on across connected changed
/// vertices of the same kind.
void ContourTracker::sweep_parents(const Fronts& old, const std::vector<VertexId>& changed) {
    // Cleared where the frame before set it (a pass over the mesh costs more).
    if (vertex_parent_.size() != topo_.n_vertices()) vertex_parent_.assign(topo_.n_vertices(), kNone);
    for (const VertexId v : parented_) vertex_parent_[v] = kNone;
    std::vector<VertexId>& queue = parented_;
    queue.clear();
    for (std::size_t s = 0; s < old.snaxels.size(); ++s) {
        for (const VertexId v : {old.snaxels[s].outside, old.snaxels[s].inside}) {
            const bool joined = v == old.snaxels[s].outside && inside_[v];
            const bool left = v == old.snaxels[s].inside && !inside_[v];
            if ((joined || left) && vertex_parent_[v] == kNone) {
                vertex_parent_[v] = std::int32_t(s);
                queue.push_back(v);
            }
        }
    }
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const VertexId v = queue[q];
        (inside_[v] ? frame_.fanouts : frame_.retreats) += 1;
        for (const VertexId w : topo_.neighbours(v)) {
            if (vertex_parent_[w] != kNone || inside_[w] != inside_[v]) continue;
            if (std::binary_search(changed.begin(), changed.end(), w)) { // changed the same way
                vertex_parent_[w] = vertex_parent_[v];
                queue.push_back(w);
            }
        }
    }
}

/// 3. The edges the fronts now cross: old front edges that still cross, and
/// the edges around every vertex that changed side; ascending, as a scan
/// would give them.
std::vector<EdgeId> ContourTracker::crossing_edges(const Fronts& old, const std::vector<VertexId>& changed) {
    edge_mark_.resize(topo_.n_edges(), 0);
    std::vector<EdgeId> kept, fresh;
    kept.reserve(old.snaxels.size());
    auto consider = [&](EdgeId e, std::vector<EdgeId>& into) {
        if (edge_mark_[e]) return;
        edge_mark_[e] = 1;
        const auto [a, b] = topo_.edge_vertices()[e];
        if (inside_[a] != inside_[b]) into.push_back(e);
    };
    for (const Snaxel& s : old.snaxels) consider(s.edge, kept);
    for (const VertexId v : changed)
        for (const EdgeId e : topo_.vertex_edges(v)) consider(e, fresh);
    for (const Snaxel& s : old.snaxels) edge_mark_[s.edge] = 0;
    for (const VertexId v : changed)
        for (const EdgeId e : topo_.vertex_edges(v)) edge_mark_[e] = 0;
    // The old snaxels come ascending by edge from the frame before (a
    // from-scratch frame may not): only the few new edges need sorting.
    if (!std::is_sorted(kept.begin(), kept.end())) std::sort(kept.begin(), kept.end());
    std::sort(fresh.begin(), fresh.end());
    std::vector<EdgeId> crossing(kept.size() + fresh.size());
    std::merge(kept.begin(), kept.end(), fresh.begin(), fresh.end(), crossing.begin());
    return crossing;
}

/// Every new snaxel at its function's root on its edge, and where that is.
void ContourTracker::place_snaxels(const ContourFunction& f, const Fronts& old, const std::vector<NormalArc>& old_arc) {
    snaxel_arc_.clear();
    if (f.linear_in_normal() || f.closed_form()) {
        // The roots' closed forms start from the arc of the edge's normals;
        // in the same pose a snaxel on the same edge has it already.
        const std::vector<Snaxel>& snaxels = frame_.contour.fronts.snaxels;
        snaxel_arc_.resize(snaxels.size());
        const bool same_pose = !arc_pose_.owner_before(topo_.pose()) && !topo_.pose().owner_before(arc_pose_);
        if (same_pose && old_arc.size() == old.snaxels.size() && old.edge_snaxel.size() == topo_.n_edges())
            for (std::size_t i = 0; i < snaxels.size(); ++i)
                if (const std::int32_t o = old.edge_snaxel[snaxels[i].edge]; o != kNoSnaxel) snaxel_arc_[i] = old_arc[std::size_t(o)];
        arc_pose_ = topo_.pose();
    }
    polish_snaxels(topo_, f, options_, frame_.contour, &snaxel_position_, snaxel_arc_.empty() ? nullptr : &snaxel_arc_);
}

/// 4. Identities. Returns per new snaxel the old snaxel it continues or was
/// born from (its source), or kNone.
std::vector<std::int32_t> ContourTracker::assign_identities(const TrackedFrame& prev,
                                                            const std::vector<glm::dvec3>& old_position) {
    const Fronts& old = prev.contour.fronts;
    const Fronts& fronts = frame_.contour.fronts;
    const std::size_t n = fronts.snaxels.size();
    frame_.snaxel_id.assign(n, 0);
    frame_.born_from.assign(n, 0);
    std::vector<std::int32_t> source(n, kNone);
    std::vector<std::int32_t> best_child(old.snaxels.size(), kNone);
    for (std::size_t s = 0; s < n; ++s) {
        const Snaxel& sn = fronts.snaxels[s];
        const std::int32_t o = old.edge_snaxel[sn.edge];
        if (o != kNone && old.snaxels[o].inside == sn.inside) {
            frame_.snaxel_id[s] = prev.snaxel_id[o]; // moved along its edge
            source[s] = o;
            continue;
        }
        std::int32_t parent = vertex_parent_[sn.inside];
        if (parent == kNone) parent = vertex_parent_[sn.outside];
        source[s] = parent;
        if (parent == kNone) continue; // born in a region that appeared from nothing
        std::int32_t& best = best_child[parent];
        if (best == kNone || glm::length(snaxel_position_[s] - old_position[parent]) <
                                 glm::length(snaxel_position_[best] - old_position[parent]))
            best = std::int32_t(s);
    }
    for (std::size_t s = 0; s < n; ++s) {
        if (frame_.snaxel_id[s]) continue;
        const std::int32_t parent = source[s];
        if (parent != kNone && best_child[parent] == std::int32_t(s)) {
            frame_.snaxel_id[s] = prev.snaxel_id[parent]; // the fan's nearest child goes on
        } else {
            frame_.snaxel_id[s] = next_id_++;
            if (parent != kNone) frame_.born_from[s] = prev.snaxel_id[parent];
        }
    }
    return source;
}

/// 5. Loops matched through their snaxels' sources: events and sequences.
void ContourTracker::match_loops(const TrackedFrame& prev, const std::vector<glm::dvec3>& old_position,
                                 const std::vector<std::int32_t>& source) {
    const Fronts& old = prev.contour.fronts;
    const Fronts& fronts = frame_.contour.fronts;
    const std::size_t old_loops = old.loops.size(), new_loops = fronts.loops.size();
    // The snaxels linking each (old loop, new loop) pair, in (old, new)
    // order: the new loops of each old loop's snaxels, bucketed by old loop
    // (a counting sort: there are few loops and many snaxels), then sorted
    // within the bucket, where runs of one loop count its snaxels.
    std::vector<std::int32_t> bucket_start(old_loops + 1, 0);
    for (const std::int32_t o : source)
        if (o != kNone) ++bucket_start[std::size_t(old.snaxels[o].loop) + 1];
    for (std::size_t l = 0; l < old_loops; ++l) bucket_start[l + 1] += bucket_start[l];
    std::vector<std::int32_t> linked(static_cast<std::size_t>(bucket_start[old_loops]));
    std::vector<std::int32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (std::size_t s = 0; s < source.size(); ++s)
        if (source[s] != kNone) linked[fill[std::size_t(old.snaxels[source[s]].loop)]++] = fronts.snaxels[s].loop;
    std::vector<std::pair<std::pair<std::int32_t, std::int32_t>, std::size_t>> shared; // (old, new) -> snaxels
    for (std::size_t l = 0; l < old_loops; ++l) {
        const auto first = linked.begin() + bucket_start[l], last = linked.begin() + bucket_start[l + 1];
        if (!std::is_sorted(first, last)) std::sort(first, last); // (mostly one loop)
        for (auto it = first; it != last; ++it) {
            const std::pair<std::int32_t, std::int32_t> link{std::int32_t(l), *it};
            if (it == first || shared.back().first != link) shared.push_back({link, 0});
            ++shared.back().second;
        }
    }
    // Per loop, the loops on the other side, ascending.
    std::vector<std::vector<std::int32_t>> pred(new_loops), succ(old_loops);
    for (const auto& [link, count] : shared) {
        succ[link.first].push_back(link.second);
        pred[link.second].push_back(link.first);
    }
    // Through a split or merge the sequence goes on along the branch that
    // shares the most snaxels both ways; the other branches start anew.
    std::vector<std::int32_t> best_succ(old_loops, kNone), best_pred(new_loops, kNone);
    std::vector<std::size_t> best_succ_n(old_loops, 0), best_pred_n(new_loops, 0);
    for (const auto& [link, count] : shared) {
        const auto [ol, nl] = link;
        if (count > best_succ_n[ol]) best_succ_n[ol] = count, best_succ[ol] = nl;
        if (count > best_pred_n[nl]) best_pred_n[nl] = count, best_pred[nl] = ol;
    }
    auto loop_points = [](const Fronts& fr, const FrontLoop& loop, const std::vector<glm::dvec3>& pos) {
        std::vector<glm::dvec3> pts;
        fr.for_each_in_loop(loop, [&](std::int32_t s) { pts.push_back(pos[s]); });
        return pts;
    };
    frame_.loop_sequence.assign(new_loops, 0);
    for (std::size_t l = 0; l < new_loops; ++l) {
        if (pred[l].empty()) {
            frame_.events.push_back({EventKind::Creation, frame_number_, loop_centroid(fronts, fronts.loops[l], snaxel_position_)});
        } else if (pred[l].size() > 1) {
            const auto first = loop_points(old, old.loops[*pred[l].begin()], old_position);
            for (auto it = std::next(pred[l].begin()); it != pred[l].end(); ++it)
                frame_.events.push_back({EventKind::Merge, frame_number_,
                                         closest_between(first, loop_points(old, old.loops[*it], old_position))});
        }
        const std::int32_t p = best_pred[l];
        if (p != kNone && best_succ[p] == std::int32_t(l))
            frame_.loop_sequence[l] = prev.loop_sequence[p];
        else
            frame_.loop_sequence[l] = next_sequence_++;
    }
    for (std::size_t l = 0; l < old_loops; ++l) {
        if (succ[l].empty()) {
            frame_.events.push_back({EventKind::Annihilation, frame_number_, loop_centroid(old, old.loops[l], old_position)});
        } else if (succ[l].size() > 1) {
            const auto first = loop_points(fronts, fronts.loops[*succ[l].begin()], snaxel_position_);
            for (auto it = std::next(succ[l].begin()); it != succ[l].end(); ++it)
                frame_.events.push_back({EventKind::Split, frame_number_,
                                         closest_between(first, loop_points(fronts, fronts.loops[*it], snaxel_position_))});
        }
    }
}

} // namespace snaxels
