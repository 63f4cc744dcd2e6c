#pragma once
/// Lines that lie on the mesh whatever the view: creases (edges where two
/// faces meet at a sharp angle), borders (edges with a face on one side
/// only) and the boundaries between the scene's materials and objects,
/// chained into polylines along the mesh's edges. They move with the
/// surface: only their projection and visibility change from frame to
/// frame.

#include <array>
#include <cstdint>
#include <vector>

#include "snaxels/snaxel/contour_function.h"
#include "snaxels/snaxel/fronts.h"
#include "snaxels/mesh/topology.h"

namespace snaxels {

/// The default crease angle (degrees) of a `kind="crease"` line.
constexpr double kDefaultCreaseDegrees = 30.0;

/// The edges whose two faces' normals (of the faces' planes, in the
/// topology's pose) differ by more than @p degrees, ascending. A border
/// edge is no crease; a face of no area makes none.
std::vector<EdgeId> crease_edges(const MeshTopology& topology, double degrees);

/// The edges between faces of two materials (of the topology's parts),
/// ascending; none without parts. A split sharp edge counts once, as a
/// crease does.
std::vector<EdgeId> material_edges(const MeshTopology& topology);

/// The edges between faces of two objects, ascending; none without parts.
std::vector<EdgeId> object_edges(const MeshTopology& topology);

/// The two faces on either side of edge @p e: its own, or where it is one
/// side of a split sharp edge, the face beside it and the one across the
/// strip (the faces the sharp edge parts). kNone on a border's open side.
std::array<FaceId, 2> faces_beside(const MeshTopology& topology, EdgeId e);

/// The edges with a face on one side only, ascending.
std::vector<EdgeId> border_edges(const MeshTopology& topology);

/// A polyline along mesh edges: vertices[i] and vertices[i + 1] are the
/// ends of edges[i]. A closed chain ends where it starts (its last vertex
/// is its first).
struct EdgeChain {
    std::vector<VertexId> vertices;
    std::vector<EdgeId> edges;
    bool closed = false;
};

/// @p edges chained: a chain goes on through every vertex where exactly two
/// of them meet, and ends at a vertex where one or three and more meet (an
/// end, a corner of a part, a junction); edges that meet only in twos make
/// closed chains. Each edge is in one chain once; chains come in the order
/// of their first edge, open ones from their lower-numbered end.
std::vector<EdgeChain> chain_edges(const MeshTopology& topology, const std::vector<EdgeId>& edges);

/// @p chains without those shorter than @p length (in the topology's pose).
std::vector<EdgeChain> chains_at_least(const MeshTopology& topology, std::vector<EdgeChain> chains, double length);

/// The chains as a snaxel front set, as parabolic_fronts makes of parabolic
/// curves: every chain vertex a snaxel at that vertex (t 0 or 1 on the
/// chain's edge there), every chain a loop, open or closed, so that the
/// drawing, hidden-line and export stages take them like any contour.
/// No vertex set bounds them: edge_snaxel holds each edge's first snaxel.
Fronts chain_fronts(const MeshTopology& topology, const std::vector<EdgeChain>& chains);

/// The fronts of a crease, border, material or object @p spec on
/// @p topology: its edges (crease_edges at spec.k degrees, border_edges,
/// material_edges, object_edges), chained, the chains
/// shorter than spec.min_length of the bounding-box diagonal left out.
Fronts feature_fronts(const MeshTopology& topology, const ContourSpec& spec);

} // namespace snaxels
