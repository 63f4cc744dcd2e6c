#include "snaxels/snaxel/parabolic.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <list>
#include <mutex>
#include <queue>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>

#include <glm/glm.hpp>

#include "snaxels/snaxel/detail/parabolic_chains.h"
#include "snaxels/snaxel/detail/point_grid.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {
namespace {

constexpr double kPi = 3.141592653589793;
constexpr NoElement kNone = MeshTopology::kNone;
/// Hilbert index of cell (x, y) of an n x n grid (n a power of two).
std::uint64_t hilbert_index(std::uint32_t n, std::uint32_t x, std::uint32_t y) {
    std::uint64_t d = 0;
    for (std::uint32_t s = n / 2; s > 0; s /= 2) {
        const std::uint32_t rx = (x & s) ? 1 : 0, ry = (y & s) ? 1 : 0;
        d += std::uint64_t(s) * s * ((3 * rx) ^ ry);
        if (ry == 0) {
            if (rx == 1) x = n - 1 - x, y = n - 1 - y;
            std::swap(x, y);
        }
    }
    return d;
}

/// A vertex whose crossing of the visual contour, somewhere in a step,
/// changes the contour's topology.
struct CriticalCrossing {
    VertexId vertex;
    bool saddle = false;     ///< a split or merge (else a loop born or gone)
    glm::dvec3 dir{0.0};     ///< the view direction at which N.V passes zero there
};

/// Every vertex whose N.d changes sign on the great-circle arc from @p d0 to
/// @p d1 and which, at the direction where it is zero, is a critical point
/// of the contour's vertex signs: around it the signs of N.d change other
/// than twice (none: a loop is born or gone; four or more: loops split or
/// merge). These are exactly the places where the front set R = {N.V >= 0}
/// changes topology as the view turns. Vertices on a mesh boundary are left out.
void critical_crossings(const MeshTopology& topo, const VertexData<std::uint8_t>& boundary, const glm::dvec3& d0,
                        const glm::dvec3& d1, std::vector<CriticalCrossing>& out) {
    out.clear();
    const double omega = std::acos(std::clamp(glm::dot(d0, d1), -1.0, 1.0));
    if (omega <= 0.0) return;
    const double so = std::sin(omega), co = std::cos(omega);
    const auto N = topo.normals();
    for (const VertexId v : topo.vertices()) {
        const double a = glm::dot(N[v], d0), b = glm::dot(N[v], d1);
        if ((a >= 0.0) == (b >= 0.0) || boundary[v]) continue;
        // a sin((1-t)w) + b sin(tw) = 0 on the slerp d0 -> d1.
        const double s = a >= 0.0 ? 1.0 : -1.0;
        const double tw = std::atan2(s * a * so, s * (a * co - b));
        const glm::dvec3 dir = glm::normalize(std::sin(omega - tw) * d0 + std::sin(tw) * d1);
        const std::span<const VertexId> ring = topo.neighbours(v);
        if (ring.size() < 3) continue;
        int changes = 0;
        bool last = glm::dot(N[ring.back()], dir) >= 0.0;
        for (const VertexId w : ring) {
            const bool sign = glm::dot(N[w], dir) >= 0.0;
            changes += sign != last;
            last = sign;
        }
        if (changes != 2) out.push_back({v, changes > 2, dir});
    }
}

/// The vertices on a mesh boundary or on a split sharp edge (a corner of a
/// zero-area strip face: the normals jump there, and the contour's events
/// at them are the edge's, not the smooth surface's parabolic curves).
VertexData<std::uint8_t> boundary_vertices(const MeshTopology& topo) {
    VertexData<std::uint8_t> boundary(topo.n_vertices(), 0);
    for (const EdgeId e : topo.edges())
        if (topo.is_boundary_edge(e))
            for (const VertexId v : topo.edge_vertices()[e]) boundary[v] = 1;
    for (const FaceId f : topo.faces())
        if (topo.has_strips() && !face_has_area(topo, f))
            for (const VertexId v : topo.face_vertices()[f]) boundary[v] = 1;
    return boundary;
}

/// Passes of one-ring normal averaging that smooth over about @p scale:
/// each pass spreads a normal by about 0.65 edge lengths (variance 3/7 of
/// an edge length squared on a regular grid), at most 400 passes.
int smoothing_passes(double scale, double edge) {
    if (scale <= 0.0) return 0;
    const double r = scale / edge;
    return int(std::min(400.0, std::ceil(r * r * 7.0 / 3.0)));
}

/// @p topo with its normals smoothed by @p passes of one-ring averaging.
MeshTopology smooth_normals(const MeshTopology& topo, int passes) {
    if (passes <= 0) return topo;
    auto pose = std::make_shared<MeshPose>(*topo.pose());
    VertexData<glm::dvec3>& normals = pose->normals;
    VertexData<glm::dvec3> next(topo.n_vertices());
    for (int pass = 0; pass < passes; ++pass) {
        parallel_for(topo.vertices(), [&](VertexId v) {
            glm::dvec3 sum = normals[v];
            for (const VertexId w : topo.neighbours(v)) sum += normals[w];
            const double l = glm::length(sum);
            next[v] = l > 0.0 ? sum / l : normals[v];
        }, 4096);
        std::swap(normals, next);
    }
    return topo.posed(std::move(pose));
}

} // namespace

double ParabolicCurve::length() const {
    double l = 0.0;
    for (std::size_t k = 1; k < points.size(); ++k) l += glm::length(points[k] - points[k - 1]);
    if (closed && points.size() > 2) l += glm::length(points.front() - points.back());
    return l;
}

std::vector<glm::dvec3> parabolic_directions(int samples, int order) {
    samples = std::max(samples, 24);
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    // Order k > 0 follows the Hilbert curve of the map turned by k radians
    // about an oblique axis: another path through the same neighbours.
    const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -0.5, 0.81));
    const double angle = double(order), ca = std::cos(angle), sa = std::sin(angle);
    auto turn = [&](const glm::dvec3& v) { // Rodrigues' rotation
        return v * ca + glm::cross(axis, v) * sa + axis * glm::dot(axis, v) * (1.0 - ca);
    };
    constexpr std::uint32_t kGrid = 1u << 12;
    std::vector<std::pair<std::uint64_t, glm::dvec3>> keyed;
    for (int i = 0; i < samples; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / samples, r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const glm::dvec3 d(r * std::cos(golden * i), r * std::sin(golden * i), z);
        // Octahedral map of the sphere onto [-1, 1]^2, the lower half folded out.
        const glm::dvec3 t = turn(d);
        const glm::dvec3 o = t / (std::abs(t.x) + std::abs(t.y) + std::abs(t.z));
        glm::dvec2 uv(o.x, o.y);
        if (o.z < 0.0)
            uv = glm::dvec2((1.0 - std::abs(o.y)) * (o.x >= 0.0 ? 1.0 : -1.0), (1.0 - std::abs(o.x)) * (o.y >= 0.0 ? 1.0 : -1.0));
        auto cell = [&](double c) { return std::uint32_t(std::clamp((c + 1.0) * 0.5 * kGrid, 0.0, double(kGrid - 1))); };
        keyed.push_back({hilbert_index(kGrid, cell(uv.x), cell(uv.y)), d});
    }
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<glm::dvec3> dirs;
    for (const auto& [key, d] : keyed) dirs.push_back(d);
    return dirs;
}

std::vector<std::vector<glm::dvec3>> parabolic_walks(int samples, int orders) {
    std::vector<std::vector<glm::dvec3>> out;
    for (int order = 0; order < std::max(orders, 1); ++order) {
        const std::vector<glm::dvec3> dirs = parabolic_directions(samples, order);
        // About sqrt(N)/4 walks per order: enough to keep every core busy,
        // few enough that the fresh start of each (a full contour search) costs little.
        const std::size_t walks = std::clamp<std::size_t>(std::size_t(std::lround(std::sqrt(double(dirs.size())) / 4.0)), 1,
                                                          dirs.size() / 8 + 1);
        for (std::size_t w = 0; w < walks; ++w) {
            const std::size_t begin = dirs.size() * w / walks, end = std::min(dirs.size(), dirs.size() * (w + 1) / walks + 1);
            out.emplace_back(dirs.begin() + std::ptrdiff_t(begin), dirs.begin() + std::ptrdiff_t(end));
        }
    }
    return out;
}

namespace {

/// Marks where the visual events @p events of one step of a walk (the view
/// from @p from to @p to) happened, into @p found: each at the nearest
/// topology-changing crossing of the step (@p crossings) within
/// @p place_limit, one of the event's own type first, each vertex once a
/// step. Returns how many events found no crossing near enough.
std::size_t place_events(const MeshTopology& topo, const std::vector<VisualEvent>& events,
                         const std::vector<CriticalCrossing>& crossings, const glm::dvec3& from, const glm::dvec3& to,
                         double place_limit, std::vector<ParabolicPoint>& found) {
    std::size_t unplaced = 0;
    std::vector<VertexId> marked; // vertices marked in this step
    for (const VisualEvent& e : events) {
        const bool saddle = e.kind == EventKind::Split || e.kind == EventKind::Merge;
        const CriticalCrossing* best = nullptr;
        double best_d = std::numeric_limits<double>::max();
        for (int pass = 0; pass < 2 && !best; ++pass) // a crossing of the event's type first
            for (const CriticalCrossing& c : crossings) {
                if (pass == 0 && c.saddle != saddle) continue;
                const double d = glm::length(topo.positions()[c.vertex] - e.where);
                if (d < best_d && d <= place_limit) best_d = d, best = &c;
            }
        if (!best) {
            ++unplaced;
            continue;
        }
        if (std::find(marked.begin(), marked.end(), best->vertex) != marked.end()) continue;
        marked.push_back(best->vertex);
        ParabolicPoint p;
        p.kind = e.kind;
        p.vertex = best->vertex;
        p.where = topo.positions()[best->vertex];
        p.dir = best->dir;
        p.from_dir = from;
        p.to_dir = to;
        found.push_back(p);
    }
    return unplaced;
}

} // namespace

ParabolicResult find_parabolic(const MeshTopology& mesh_topo, const ParabolicOptions& options) {
    const auto t0 = std::chrono::steady_clock::now();
    // The normals the contour is tracked with, smoothed at the asked scale
    // (mesh noise makes visual events everywhere; docs/parabolic.md).
    const double radius = bounding_radius(mesh_topo);
    const double edge = std::max(mesh_topo.mean_edge_length(), 1e-300);
    const int passes = smoothing_passes(options.smoothing * radius, edge);
    const MeshTopology topo = smooth_normals(mesh_topo, passes);
    ParabolicResult result;
    const std::vector<std::vector<glm::dvec3>> walks = parabolic_walks(options.samples, options.orders);
    result.walks = int(walks.size());
    result.samples = int(parabolic_directions(options.samples, 0).size());
    result.smoothing_passes = passes;
    const VertexData<std::uint8_t> boundary = boundary_vertices(topo);
    // An event farther than this from every topology-changing crossing of its
    // step is left unplaced: the contour moved that far in one step only on
    // a mesh too coarse for the sampling.
    const double place_limit = std::max(8.0 * edge, 0.1 * radius);

    std::vector<std::vector<ParabolicPoint>> found(walks.size());
    std::vector<std::size_t> events(walks.size(), 0), unplaced(walks.size(), 0);
    int total_steps = 0;
    for (const auto& w : walks) total_steps += int(w.size()) - 1;
    std::atomic<int> done{0};
    std::atomic<bool> stop{false};
    std::mutex progress_mutex;
    parallel_for(
        walks.size(),
        [&](std::size_t i) {
            const std::vector<glm::dvec3>& walk = walks[i];
            ContourTracker tracker(topo, ContourSpec{});
            std::vector<CriticalCrossing> crossings;
            for (std::size_t k = 0; k < walk.size(); ++k) {
                if (stop || (options.cancelled && options.cancelled())) {
                    stop = true;
                    return;
                }
                Camera camera;
                camera.view_dir = walk[k];
                camera.up = std::abs(walk[k].z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
                const TrackedFrame& frame = tracker.step(camera, default_light(camera));
                if (k == 0 || frame.events.empty()) continue;
                events[i] += frame.events.size();
                critical_crossings(topo, boundary, walk[k - 1], walk[k], crossings);
                unplaced[i] += place_events(topo, frame.events, crossings, walk[k - 1], walk[k], place_limit, found[i]);
            }
            const int now = done += int(walk.size()) - 1;
            if (options.progress) {
                const std::lock_guard<std::mutex> lock(progress_mutex);
                options.progress(std::min(now, total_steps), total_steps);
            }
        },
        1);
    if (stop) throw ParabolicCancelled();
    for (std::size_t i = 0; i < walks.size(); ++i) {
        result.points.insert(result.points.end(), found[i].begin(), found[i].end());
        result.events += events[i];
        result.unplaced += unplaced[i];
    }

    // Faces and confidence: marks from other view transitions nearby.
    std::vector<glm::dvec3> where;
    for (const ParabolicPoint& p : result.points) where.push_back(p.where);
    const detail::PointGrid grid(where, 2.0 * edge);
    parallel_for(where.size(), [&](std::size_t i) {
        ParabolicPoint& p = result.points[i];
        topo.for_each_face_beside_edges(p.vertex, [&](FaceId f) {
            if (p.face == kNone) p.face = f;
        });
        p.confidence = 0;
        grid.near(p.where, 2.0 * edge, [&](std::size_t) { ++p.confidence; });
    }, 256);

    // Marks along a parabolic curve lie where walks crossed the curve's
    // asymptotic directions on the view sphere, about pi^2 / L apart in
    // direction for a walked length L; link marks a few such gaps apart.
    double walked = 0.0;
    for (const auto& walk : walks)
        for (std::size_t k = 1; k < walk.size(); ++k) walked += std::acos(std::clamp(glm::dot(walk[k - 1], walk[k]), -1.0, 1.0));
    const double gap = kPi * kPi / std::max(walked, 1e-9);
    const double link = std::max(4.0 * edge, 1.5 * gap * radius);
    result.curves = detail::chain_curves(topo, result.points, link, 6.0 * link, 2);
    result.mesh_edges = topo.n_edges();
    result.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return result;
}

namespace {

/// The options that change a search's result, as a key.
Quantity<ParabolicResult> parabolic_key(const ParabolicOptions& options) {
    char key[96];
    std::snprintf(key, sizeof key, "parabolic samples=%d orders=%d smoothing=%.17g", options.samples, options.orders,
                  options.smoothing);
    return {key};
}

/// A hash of @p topology's positions and faces.
std::uint64_t content_hash(const MeshTopology& topo) {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a
    auto mix = [&](const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
    };
    mix(topo.positions().data(), topo.positions().size() * sizeof(glm::dvec3));
    mix(topo.face_vertices().data(), topo.face_vertices().size() * sizeof(std::array<VertexId, 3>));
    return h;
}

/// The few searches most recently done in the process, newest first.
struct ProcessCache {
    std::mutex mutex;
    std::list<std::pair<std::pair<std::uint64_t, std::string>, std::shared_ptr<const ParabolicResult>>> entries;
    static constexpr std::size_t kCapacity = 4;
};
ProcessCache& process_cache() {
    static ProcessCache cache;
    return cache;
}

} // namespace

std::shared_ptr<const ParabolicResult> require_parabolic(const MeshTopology& topo, const ParabolicOptions& options) {
    const Quantity<ParabolicResult> key = parabolic_key(options);
    if (auto kept = topo.pose()->quantities.find(key)) return kept;
    const std::pair<std::uint64_t, std::string> content{content_hash(topo), key.name};
    ProcessCache& cache = process_cache();
    std::shared_ptr<const ParabolicResult> result;
    {
        const std::lock_guard<std::mutex> lock(cache.mutex);
        for (auto it = cache.entries.begin(); it != cache.entries.end(); ++it)
            if (it->first == content) {
                cache.entries.splice(cache.entries.begin(), cache.entries, it);
                result = cache.entries.front().second;
                break;
            }
    }
    if (!result) {
        result = std::make_shared<const ParabolicResult>(find_parabolic(topo, options));
        const std::lock_guard<std::mutex> lock(cache.mutex);
        cache.entries.push_front({content, result});
        while (cache.entries.size() > ProcessCache::kCapacity) cache.entries.pop_back();
    }
    return topo.pose()->quantities.keep(key, std::move(result), PoseQuantities::Lifetime::CarriedToLaterPoses);
}

std::shared_ptr<const ParabolicResult> kept_parabolic(const MeshTopology& topo, const ParabolicOptions& options) {
    return topo.pose()->quantities.find(parabolic_key(options));
}

void keep_parabolic(const MeshTopology& topo, const ParabolicOptions& options, std::shared_ptr<const ParabolicResult> result) {
    if (result) topo.pose()->quantities.keep(parabolic_key(options), std::move(result), PoseQuantities::Lifetime::CarriedToLaterPoses);
}

Fronts parabolic_fronts(const MeshTopology& topo, const ParabolicResult& result) {
    Fronts fronts;
    fronts.edge_snaxel.assign(topo.n_edges(), kNoSnaxel);
    for (const ParabolicCurve& curve : result.curves)
        if (curve.points.size() >= 2) append_edge_loop(topo, curve.edges, curve.t, curve.closed, fronts);
    return fronts;
}

} // namespace snaxels
