#pragma once
/// The snaxel engine on a still mesh: seeds fronts at the local extrema of a
/// contour function, sweeps them over the vertices until they stop where f
/// changes sign (fan-out past each vertex, merging where fronts meet), labels
/// the regions they sweep, and polishes every snaxel to the root of f on its
/// edge. A front is the boundary of the vertices it has swept
/// (docs/engine.md, "Fronts as region boundaries").

#include <cstdint>
#include <vector>

#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/snaxel/fronts.h"
#include "snaxels/mesh/topology.h"

namespace snaxels {

struct EngineOptions {
    /// Run check_fronts after every sweep iteration and after convergence;
    /// throws snaxels::Error on a violation. On in debug builds.
#ifdef NDEBUG
    bool check_invariants = false;
#else
    bool check_invariants = true;
#endif
    /// Snaxels are polished until their bracket on the edge is this small (in t).
    double polish_tolerance = 1e-12;
    /// Where f can cross zero more than once on an edge (every kind but the
    /// visual contour), the edge is sampled at this many points and the
    /// crossing nearest the inside vertex is polished.
    int polish_scan_samples = 8;
};

struct ContourStats {
    std::size_t seeds = 0;      ///< fronts created at local extrema
    std::size_t iterations = 0; ///< sweep rounds: every front advances one ring per round
    std::size_t fanouts = 0;    ///< vertices passed (each replaces a snaxel by a fan)
    std::size_t merges = 0;     ///< two fronts meeting on an edge and joining
    std::size_t splits = 0;     ///< a front meeting itself (splitting, or closing round a handle)
    double ms = 0.0;            ///< wall time of compute()
};

/// One region swept by one (merged) front: f >= 0 (sign +1) or f < 0 (-1).
struct Region {
    int sign = 1;
    VertexId seed; ///< vertex of the extremum it grew from
    std::size_t vertices = 0;
};

struct ContourResult {
    ContourSpec spec;
    Fronts fronts;                      ///< the converged f = 0 contour, R = {f >= 0}
    VertexData<double> vertex_f;             ///< f at every vertex
    VertexData<std::int32_t> vertex_region; ///< index into regions, for every vertex
    std::vector<Region> regions;
    /// Per snaxel, for a kind whose drawing leaves parts of its loops out
    /// (suggestive contours: suggestive_margins): >= 0 where drawn. Empty
    /// for the other kinds: every snaxel is drawn.
    std::vector<double> snaxel_margin;
    /// Per snaxel of an intersection line: the face of the other surface
    /// its edge pierces (IntersectionCurves::pierced). Empty for the other
    /// kinds.
    std::vector<FaceId> snaxel_pierced;
    ContourStats stats;
};

/// @p result as its lines need it (hidden lines, the drawing, the stroke
/// parameter): its spec, snaxels, loops, margins and stats, without what
/// it holds per vertex and per edge (vertex_f, vertex_region, regions,
/// fronts.edge_snaxel), which only the planar map reads. A tracker's frame
/// is copied every frame: this copy is a tenth of the whole on the horse.
ContourResult lines_of(const ContourResult& result);

/// Puts every snaxel of @p result.fronts at the root of @p f on its edge
/// (polish_root, from @p result.vertex_f, the frame's f; in parallel), and
/// with @p positions where each snaxel then is (SnaxelEngine::position).
/// With @p arcs (one per snaxel) the arcs known there are used and the
/// others are set where a root needs them (polish_root).
void polish_snaxels(const MeshTopology& topology, const ContourFunction& f, const EngineOptions& options,
                    ContourResult& result, std::vector<glm::dvec3>* positions = nullptr,
                    std::vector<NormalArc>* arcs = nullptr);

/// Fills @p result.snaxel_margin for its fronts, as its kind needs (see
/// ContourResult::snaxel_margin; @p result.vertex_f must be the frame's f).
void set_snaxel_margins(const MeshTopology& topology, const Camera& camera, ContourResult& result);

class SnaxelEngine {
  public:
    explicit SnaxelEngine(const MeshTopology& topology) : topo_(topology) {}

    ContourResult compute(const ContourSpec& spec, const Camera& camera, const Light& light,
                          const EngineOptions& options = {}) const;

    /// 3-D position and slerped normal of a snaxel.
    glm::dvec3 position(const Snaxel& s) const {
        return (1.0 - s.t) * topo_.positions()[s.inside] + s.t * topo_.positions()[s.outside];
    }
    glm::dvec3 normal(const Snaxel& s) const {
        return slerp_normal(topo_.normals()[s.inside], topo_.normals()[s.outside], s.t);
    }
    const MeshTopology& topology() const { return topo_; }

  private:
    const MeshTopology& topo_;
};

/// The root of f along edge (inside -> outside) given f(inside) >= 0 >
/// f(outside): the first sign change among @p scan_samples equal steps from
/// the inside end, polished by the Illinois variant of regula falsi with the
/// slerped normal until its bracket is below @p tolerance in t.
/// @p arc, where given and known, is the arc between the edge's normals
/// (normal_arc) and saves working it out; where given and not known, it
/// is set to that arc when the root needs it.
double polish_root(const MeshTopology& topology, const ContourFunction& f, VertexId inside,
                   VertexId outside, double f_inside, double f_outside, double tolerance,
                   int scan_samples, NormalArc* arc = nullptr);

} // namespace snaxels
