#pragma once
/// Parabolic points and curves from visual events over the view sphere (the
/// paper's "Mesh Parabolic Points"). The visual contour generator of a
/// smooth surface changes topology (lips, beak-to-beak) only where the view
/// direction is asymptotic at a parabolic point, where the Gaussian
/// curvature vanishes. So, without estimating curvature: sample orthographic
/// view directions evenly over the sphere, walk them in an order where each
/// step is small, track the visual contour from step to step, and mark where
/// it is created, annihilated, split or merged. Walks are independent and
/// run in parallel. The marked points are clustered and chained into curves
/// that run across the mesh's faces. Nothing here depends on a view: the
/// result is the mesh's (docs/parabolic.md).

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include <glm/vec3.hpp>

#include "snaxels/error.h"
#include "snaxels/snaxel/fronts.h"
#include "snaxels/mesh/topology.h"
#include "snaxels/snaxel/tracker.h"

namespace snaxels {

struct ParabolicOptions {
    int samples = 2000; ///< view directions over the whole sphere
    /// Paths through the directions (each steps between other neighbours):
    /// more marks along each curve, at a cost in proportion.
    int orders = 3;
    /// The scale, as a fraction of the mesh's bounding radius, over which
    /// vertex normals are averaged before the search (0: not at all). Mesh
    /// noise makes visual events everywhere; this keeps the surface's own.
    double smoothing = 0.02;
    /// Called as walks finish with (view directions done, in all); from
    /// worker threads, one call at a time.
    std::function<void(int, int)> progress;
    /// Asked between steps; true stops the search (ParabolicCancelled).
    std::function<bool()> cancelled;
};

struct ParabolicCancelled : Cancelled {
    ParabolicCancelled() : Cancelled("the parabolic search was cancelled") {}
};

/// One marked point: a visual event the tracker saw in one step, placed at
/// the vertex whose crossing of the contour changed the contour's topology
/// in that step (see docs/parabolic.md), with the view direction at which
/// it crossed, the step's two directions, a face around the vertex, and its
/// confidence: how many view transitions marked a point within two mean edge
/// lengths of it (itself included).
struct ParabolicPoint {
    EventKind kind = EventKind::Creation;
    glm::dvec3 where{0.0};
    VertexId vertex;
    FaceId face;
    glm::dvec3 dir{0.0}, from_dir{0.0}, to_dir{0.0};
    int confidence = 1;
};

/// A parabolic curve as a polyline across the mesh: each point lies on a
/// mesh edge (t from the edge's first vertex, edge_vertices[e][0]) and each
/// segment inside one face, faces[k] joining points k and k + 1 (and, when
/// closed, the last point and the first).
struct ParabolicCurve {
    std::vector<glm::dvec3> points;
    std::vector<EdgeId> edges;
    std::vector<double> t;
    std::vector<FaceId> faces;
    bool closed = false;
    double length() const;
};

struct ParabolicResult {
    std::vector<ParabolicPoint> points;
    std::vector<ParabolicCurve> curves;
    int samples = 0, walks = 0;
    int smoothing_passes = 0;   ///< one-ring normal averaging passes done first
    std::size_t events = 0;   ///< visual events the tracker reported
    std::size_t unplaced = 0; ///< events with no topology-changing vertex crossing near them
    double ms = 0.0;
    /// The edges of the mesh the curves were found on (their edge ids index it).
    std::size_t mesh_edges = 0;
};

/// @p samples directions of a spherical Fibonacci set, in the order of a
/// Hilbert curve over the sphere's octahedral map (turned by @p order
/// radians about a fixed oblique axis): neighbours in the order are
/// neighbours on the sphere, and each order steps between other neighbours.
std::vector<glm::dvec3> parabolic_directions(int samples, int order = 0);

/// The walks: parabolic_directions(samples, k) for @p orders orders, each
/// cut into independent stretches (each starts where the one before ends,
/// so every step is walked once).
std::vector<std::vector<glm::dvec3>> parabolic_walks(int samples, int orders);

/// Finds the parabolic points and curves of @p topology.
ParabolicResult find_parabolic(const MeshTopology& topology, const ParabolicOptions& options = {});

/// The same, kept in the pose's quantities (MeshPose::quantities) under
/// every option that changes the result (samples, orders, smoothing), and
/// carried to the poses made from it (MeshTopology::posed): the curves are
/// the mesh's, found once and carried by its edges as it moves. A pose
/// without them looks in a small cache across meshes in the process, keyed
/// by the mesh's content (positions and faces) and the same options, before
/// it searches, so reopening a mesh finds its curves at once. The options'
/// callbacks are used only when it searches.
std::shared_ptr<const ParabolicResult> require_parabolic(const MeshTopology& topology,
                                                         const ParabolicOptions& options = {});

/// The curves require_parabolic keeps for @p topology's pose and
/// @p options, or null when none are kept yet (nothing is searched).
std::shared_ptr<const ParabolicResult> kept_parabolic(const MeshTopology& topology, const ParabolicOptions& options = {});

/// Keeps @p result as @p topology's curves for @p options (as
/// require_parabolic would after finding them), for curves found elsewhere
/// (the application searches in the background on the loaded pose).
void keep_parabolic(const MeshTopology& topology, const ParabolicOptions& options,
                    std::shared_ptr<const ParabolicResult> result);

/// The curves as a snaxel front set: every curve point a snaxel on its edge
/// (inside = the edge's first vertex), every curve a loop, open or closed,
/// so that the drawing, hidden-line and export stages take them like any
/// contour. No vertex set bounds them: edge_snaxel holds each edge's first
/// snaxel only.
Fronts parabolic_fronts(const MeshTopology& topology, const ParabolicResult& result);

} // namespace snaxels
