#include "snaxels/snaxel/snaxel_engine.h"

#include "snaxels/snaxel/suggestive.h"
#include "snaxels/snaxel/feature_edges.h"
#include "snaxels/snaxel/intersections.h"
#include "snaxels/snaxel/parabolic.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "snaxels/error.h"
#include "snaxels/util/detail/float_mode.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {
namespace {

/// A vertex no front has reached yet.
constexpr std::int32_t kNoRegion = -1;

struct RegionUnion {
    std::vector<std::int32_t> parent;
    std::int32_t add() {
        parent.push_back(static_cast<std::int32_t>(parent.size()));
        return parent.back();
    }
    std::int32_t find(std::int32_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
};

// Sweeps fronts of one sign from the local extrema (maxima of f for the
// f >= 0 side, minima for f < 0) until every vertex of that side is labelled.
class Sweep {
  public:
    Sweep(const MeshTopology& topo, const VertexData<double>& f, int sign,
          VertexData<std::int32_t>& label, RegionUnion& regions, std::vector<Region>& info,
          ContourStats& stats, const EngineOptions& options)
        : topo_(topo), f_(f), sign_(sign), label_(label), regions_(regions), info_(info),
          stats_(stats), options_(options) {}

    /// Edges where the fronts stopped (f changes sign), each once.
    const std::vector<EdgeId>& stopped_edges() const { return stopped_; }

    void run() {
        std::vector<VertexId> frontier, next;
        seed(frontier);
        while (!frontier.empty()) {
            ++stats_.iterations;
            next.clear();
            for (const VertexId u : frontier) advance(u, next);
            frontier.swap(next);
            if (options_.check_invariants) check();
        }
    }

  private:
    bool on_side(VertexId v) const { return (f_[v] >= 0.0) == (sign_ > 0); }

    // A front starts around every unvisited local extremum of this side.
    void seed(std::vector<VertexId>& frontier) {
        for (const VertexId v : topo_.vertices()) {
            if (!on_side(v) || label_[v] != kNoRegion) continue;
            bool extremum = true;
            for (const VertexId w : topo_.neighbours(v)) {
                extremum = sign_ > 0 ? f_[v] >= f_[w] : f_[v] <= f_[w];
                if (!extremum) break;
            }
            if (!extremum) continue;
            label_[v] = regions_.add();
            info_.push_back({sign_, v, 0});
            frontier.push_back(v);
            ++stats_.seeds;
        }
    }

    // The front of u's region fans out past every neighbour on this side.
    void advance(VertexId u, std::vector<VertexId>& next) {
        const std::int32_t mine = regions_.find(label_[u]);
        for (const auto [w, edge] : topo_.ring_of(u)) {
            if (!on_side(w)) { // the front stops on this edge: f changes sign
                stopped_.push_back(edge);
                continue;
            }
            if (label_[w] == kNoRegion) {
                stats_.splits += self_contacts(w, mine);
                label_[w] = mine;
                ++stats_.fanouts;
                next.push_back(w);
            } else if (const std::int32_t theirs = regions_.find(label_[w]); theirs != mine) {
                regions_.parent[theirs] = mine; // two fronts annihilate on edge (u, w)
                ++stats_.merges;
            }
        }
    }

    // Around w, the runs of neighbours already swept by `region`: a front
    // that reaches w from two or more sides meets itself there.
    std::size_t self_contacts(VertexId w, std::int32_t region) {
        const std::span<const VertexId> ring = topo_.neighbours(w);
        if (ring.size() < 2) return 0;
        auto in = [&](VertexId u) {
            const std::int32_t l = label_[u];
            return l != kNoRegion && regions_.find(l) == region;
        };
        std::size_t runs = 0;
        bool last = in(ring.back());
        for (const VertexId u : ring) {
            const bool now = in(u);
            runs += now && !last;
            last = now;
        }
        return runs > 1 ? runs - 1 : 0;
    }

    void check() const {
        VertexData<std::uint8_t> swept(topo_.n_vertices());
        for (const VertexId v : topo_.vertices()) swept[v] = label_[v] != kNoRegion && on_side(v);
        const Fronts fronts = extract_fronts(topo_, swept);
        if (const std::string problem = check_fronts(topo_, fronts, swept); !problem.empty())
            throw InternalError("snaxel invariant broken after iteration " +
                        std::to_string(stats_.iterations) + ": " + problem);
    }

    const MeshTopology& topo_;
    const VertexData<double>& f_;
    int sign_;
    VertexData<std::int32_t>& label_;
    RegionUnion& regions_;
    std::vector<Region>& info_;
    ContourStats& stats_;
    const EngineOptions& options_;
    std::vector<EdgeId> stopped_;
};

} // namespace

double polish_root(const MeshTopology& topo, const ContourFunction& f, VertexId inside,
                   VertexId outside, double f_inside, double f_outside, double tolerance,
                   int scan_samples, NormalArc* arc) {
    if (f.linear_on_edge()) // vertex values, linear along the edge
        return f_inside > 0.0 ? std::clamp(f_inside / (f_inside - f_outside), 0.0, 1.0) : 0.0;
    // (Each end's normal and position is read where it is needed: the
    // reads are most of the cost of the closed forms.)
    if (f.linear_in_normal() && f_inside <= 0.0) return 0.0;
    const glm::dvec3 na = topo.normals()[inside], nb = topo.normals()[outside];
    NormalArc own;
    if (!arc) arc = &own;
    if ((f.linear_in_normal() || f.closed_form()) && !arc->known()) *arc = normal_arc(na, nb);
    if (f.linear_in_normal()) // N.v on a slerp: one sinusoid, solved exactly
        return slerp_dot_root(*arc, f_inside, f_outside);
    if (f.closed_form()) // sinusoids: the first crossing, exactly (no scan needed)
        if (const double t = f.first_zero(na, nb, *arc, f_inside, f_outside); !std::isnan(t)) return t;
    const glm::dvec3 pa = topo.positions()[inside], pb = topo.positions()[outside];
    const SlerpArc slerp = arc->known() ? SlerpArc(na, nb, *arc) : SlerpArc(na, nb);
    auto g = [&](double t) { return f((1.0 - t) * pa + t * pb, slerp(t)); };
    double t0 = 0.0, t1 = 1.0, g0 = f_inside, g1 = f_outside;
    // f may cross zero more than once on an edge (isophotes and gleams are
    // minima of sinusoids): bracket the crossing nearest the inside end.
    for (int i = 1; i < scan_samples; ++i) {
        const double t = double(i) / scan_samples;
        const double gt = g(t);
        if (gt < 0.0) {
            t1 = t;
            g1 = gt;
            break;
        }
        t0 = t;
        g0 = gt;
    }
    int stale = 0; // which end stayed put last step (Illinois: halve its value)
    for (int it = 0; it < 200 && t1 - t0 > tolerance; ++it) {
        double t = (g0 == g1) ? 0.5 * (t0 + t1) : t0 + (t1 - t0) * g0 / (g0 - g1);
        if (!(t > t0 && t < t1)) t = 0.5 * (t0 + t1);
        const double gt = g(t);
        if (gt == 0.0) return t;
        if (gt > 0.0) {
            t0 = t;
            g0 = gt;
            if (stale == 1) g1 *= 0.5;
            stale = 1;
        } else {
            t1 = t;
            g1 = gt;
            if (stale == -1) g0 *= 0.5;
            stale = -1;
        }
    }
    return 0.5 * (t0 + t1);
}

void polish_snaxels(const MeshTopology& topology, const ContourFunction& f, const EngineOptions& options,
                    ContourResult& result, std::vector<glm::dvec3>* positions, std::vector<NormalArc>* arcs) {
    // N.V along a slerp is one sinusoid over less than half a period: a
    // single crossing, so only the other kinds need the bracketing scan.
    const int scan = result.spec.kind == ContourKind::Visual ? 1 : options.polish_scan_samples;
    std::vector<Snaxel>& snaxels = result.fronts.snaxels;
    if (positions) positions->resize(snaxels.size());
    if (arcs) arcs->resize(snaxels.size());
    const SnaxelEngine engine(topology);
    parallel_for(snaxels.size(), [&](std::size_t i) {
        Snaxel& s = snaxels[i];
        s.t = polish_root(topology, f, s.inside, s.outside, result.vertex_f[s.inside],
                          result.vertex_f[s.outside], options.polish_tolerance, scan, arcs ? &(*arcs)[i] : nullptr);
        if (positions) (*positions)[i] = engine.position(s);
    }, 1024);
}

void set_snaxel_margins(const MeshTopology& topology, const Camera& camera, ContourResult& result) {
    if (result.spec.kind != ContourKind::Suggestive) {
        result.snaxel_margin.clear();
        return;
    }
    result.snaxel_margin =
        suggestive_margins(topology, *require_curvature(topology), result.vertex_f, result.fronts, camera, result.spec);
}

ContourResult lines_of(const ContourResult& result) {
    ContourResult out;
    out.spec = result.spec;
    out.fronts.snaxels = result.fronts.snaxels;
    out.fronts.loops = result.fronts.loops;
    out.snaxel_margin = result.snaxel_margin;
    out.snaxel_pierced = result.snaxel_pierced;
    out.stats = result.stats;
    return out;
}

ContourResult SnaxelEngine::compute(const ContourSpec& spec, const Camera& camera,
                                    const Light& light, const EngineOptions& options) const {
    const FloatModeGuard mode; // one answer whichever thread computes it (float_mode.h)
    const auto start = std::chrono::steady_clock::now();
    ContourResult result;
    result.spec = spec;
    if (spec.on_surface()) {
        // Lines of the mesh: the same from every view (no f, no regions).
        if (spec.kind == ContourKind::Parabolic) {
            const std::shared_ptr<const ParabolicResult> curves = require_parabolic(topo_);
            result.fronts = parabolic_fronts(topo_, *curves);
        } else if (spec.kind == ContourKind::Intersection) {
            const std::shared_ptr<const IntersectionCurves> curves = require_intersections(topo_);
            result.fronts = curves->fronts;
            result.snaxel_pierced = curves->pierced;
        } else {
            result.fronts = feature_fronts(topo_, spec);
        }
        result.stats.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        return result;
    }
    const ContourFunction f(spec, camera, light);
    const std::size_t nv = topo_.n_vertices();

    f.evaluate_vertices(topo_, result.vertex_f);

    VertexData<std::int32_t> label(nv, kNoRegion);
    RegionUnion regions;
    std::vector<Region> info;
    Sweep positive(topo_, result.vertex_f, +1, label, regions, info, result.stats, options);
    positive.run();
    Sweep(topo_, result.vertex_f, -1, label, regions, info, result.stats, options).run();

    // Converged: compact the merged region labels.
    std::vector<std::int32_t> compact(info.size(), kNoRegion);
    result.vertex_region.resize(nv);
    for (const VertexId v : topo_.vertices()) {
        if (label[v] == kNoRegion)
            throw InternalError("snaxel sweep left vertex " + std::to_string(v.index()) + " unlabelled");
        const std::int32_t root = regions.find(label[v]);
        if (compact[root] == kNoRegion) {
            compact[root] = static_cast<std::int32_t>(result.regions.size());
            result.regions.push_back(info[root]);
        }
        result.vertex_region[v] = compact[root];
        ++result.regions[compact[root]].vertices;
    }

    VertexData<std::uint8_t> inside(nv);
    for (const VertexId v : topo_.vertices()) inside[v] = result.regions[result.vertex_region[v]].sign > 0;
    // In edge order, as a scan of the edges (and the tracker) gives them: a
    // tracked frame and the same frame computed anew have the same loops,
    // in the same order, from the same snaxels, so they draw the same SVG.
    std::vector<EdgeId> crossing = positive.stopped_edges();
    std::sort(crossing.begin(), crossing.end());
    result.fronts = extract_fronts(topo_, inside, crossing);
    polish_snaxels(topo_, f, options, result);
    set_snaxel_margins(topo_, camera, result);
    if (options.check_invariants) {
        if (const std::string problem = check_fronts(topo_, result.fronts, inside); !problem.empty())
            throw InternalError("snaxel invariant broken after convergence: " + problem);
        for (const VertexId v : topo_.vertices())
            if (bool(inside[v]) != (result.vertex_f[v] >= 0.0))
                throw InternalError("region label of vertex " + std::to_string(v.index()) + " disagrees with f");
    }
    result.stats.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace snaxels
