#pragma once
/// Per-vertex curvature of a posed mesh, estimated as Rusinkiewicz does
/// ("Estimating Curvatures and Their Derivatives on Triangle Meshes",
/// 3DPVT 2004): each face's second fundamental form is fitted, by least
/// squares, to how the vertex normals change along its three edges; each
/// vertex averages the forms of its faces, turned into its own tangent
/// plane and weighted by the face's share of the vertex's (Voronoi)
/// area; the average's eigenvectors are the principal directions.
///
/// Curvature is positive where the surface bends away from its normal, as
/// on a sphere with outward normals (1/radius there).

#include <array>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "snaxels/mesh/topology.h"

namespace snaxels {

/// The principal curvatures and directions of every vertex of one pose.
struct CurvatureField {
    VertexData<double> k1, k2;           ///< principal curvatures, |k1| >= |k2|
    VertexData<glm::dvec3> dir1, dir2;   ///< unit principal directions in the tangent plane
    VertexData<double> area;             ///< the vertex's Voronoi area (rtsc's corner shares)
    /// The median of |k1| over the vertices with area: the mesh's typical
    /// curvature, whose inverse (a typical radius) makes thresholds on
    /// curvature scale-free and suited to the mesh (0 for a flat mesh).
    double typical = 0.0;
    /// The mean gradient of a field of vertex values at each vertex, as
    /// weights: the area-weighted mean over v's faces of each face's
    /// gradient of the linear interpolant is the sum over k in
    /// [gradient_start[v], gradient_start[v+1]) of gradient_weight[k] times
    /// the value at vertex gradient_vertex[k] (v, then its neighbours).
    /// Filled by add_gradient_operator (require_curvature does); empty else.
    std::vector<std::int32_t> gradient_start;
    std::vector<VertexId> gradient_vertex;
    std::vector<glm::dvec3> gradient_weight;

    std::size_t size() const { return k1.size(); }
    /// The normal curvature of vertex @p v in the direction of @p w's
    /// projection onto the tangent plane (@p w need not be unit nor
    /// tangent; 0 where the projection vanishes): k1 cos^2 + k2 sin^2 of
    /// its angle to dir1. Inline: kappa_r calls it for every vertex seen,
    /// every frame.
    double normal_curvature(VertexId v, const glm::dvec3& w) const {
        const double c = glm::dot(w, dir1[v]), s = glm::dot(w, dir2[v]);
        const double len2 = c * c + s * s;
        return len2 > 0.0 ? (k1[v] * c * c + k2[v] * s * s) / len2 : 0.0;
    }
    /// The second fundamental form of vertex @p v on @p w's projection onto
    /// the tangent plane: normal_curvature times the projection's squared
    /// length, with no division (so it falls smoothly to 0 where the
    /// projection vanishes). For a unit view vector, kappa_r sin^2(theta).
    double form(VertexId v, const glm::dvec3& w) const {
        const double c = glm::dot(w, dir1[v]), s = glm::dot(w, dir2[v]);
        return k1[v] * c * c + k2[v] * s * s;
    }
};

/// The curvature of @p topology in its pose (positions and vertex normals),
/// computed in parallel. A vertex with no face of non-zero area gets zero
/// curvatures and an arbitrary tangent frame.
CurvatureField vertex_curvatures(const MeshTopology& topology);

/// @p field smoothed once: each vertex's second fundamental form becomes the
/// area-weighted mean of its own and its neighbours' forms, each turned into
/// the vertex's tangent plane (the remedy of rtsc and DeCarlo et al. 2004
/// for the noise a scanned mesh gives curvature, and so kappa_r).
CurvatureField smoothed_curvatures(const MeshTopology& topology, const CurvatureField& field);

/// Fills @p field's gradient operator (CurvatureField::gradient_*) for
/// @p topology's pose.
void add_gradient_operator(const MeshTopology& topology, CurvatureField& field);

/// What require_curvature computes: the options that change its value.
struct CurvatureOptions {
    /// One-ring smoothing passes over vertex_curvatures' tensors (on a
    /// scanned mesh two halve the noise loops of kappa_r's zeros, and so
    /// the work of tracking them, and leave smooth surfaces as they were).
    int smoothing = 2;
    /// Whether the gradient operator is added (suggestive_margins reads it).
    bool gradient = true;
};

namespace detail {
/// Whether the curvature passes may take their build for wider vector lanes
/// (AVX2), where the processor has them (the default); returns the setting
/// before. Both builds give the same bits: tests compare them.
bool allow_curvature_wide_lanes(bool allowed);
/// Whether this processor can run the wider lanes.
bool curvature_wide_lanes_available();
} // namespace detail

/// The curvature of @p topology's pose: vertex_curvatures smoothed
/// @p options.smoothing times, with its gradient operator when asked.
/// Computed once per pose and options (the first caller computes it; it is
/// kept in the pose's quantities, MeshPose::quantities) and shared by every
/// frame, thread and copy of the topology in that pose. The suggestive kind
/// reads it with the default options.
std::shared_ptr<const CurvatureField> require_curvature(const MeshTopology& topology, const CurvatureOptions& options = {});

/// The derivative of curvature at every vertex (Rusinkiewicz 2004): the
/// symmetric tensor C of how the second fundamental form changes across
/// the surface, in the vertex's principal frame (dir1, dir2): C111, C112,
/// C122, C222 (core/snaxel/curvature_derivative.cpp).
struct CurvatureDerivative {
    VertexData<std::array<double, 4>> c;
};

/// @p field's derivative, kept with the pose when @p field is its default
/// curvature (require_curvature's).
std::shared_ptr<const CurvatureDerivative> require_curvature_derivative(const MeshTopology& topology,
                                                                       const CurvatureField& field);

/// sin(theta) times the derivative of kappa_r along the view at vertex
/// @p v, as DeCarlo et al.'s rtsc computes it from C: C(w, w, w) / |w|^2
/// minus 2 cos(theta) tau_r^2, with w the unit @p view toward the viewer
/// projected onto the tangent plane (|w| = sin theta), theta its angle to
/// @p normal and tau_r the geodesic torsion along w.
double radial_derivative_term(const CurvatureField& field, const CurvatureDerivative& derivative, VertexId v,
                              const glm::dvec3& normal, const glm::dvec3& view);

} // namespace snaxels
