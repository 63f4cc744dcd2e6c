#pragma once
/// Per-vertex curvature of a posed mesh, estimated as Rusinkiewicz does
/// ("Estimating Curvatures and Their Derivatives on Triangle Meshes",
/// 3DPVT 2004): each face's second fundamental form is fitted, by least
/// squares, to how the vertex normals change along its three edges; each
/// vertex averages the forms of its faces, turned into its own tangent
/// plane and weighted by the face's share of the vertex's (mixed Voronoi)
/// area; the average's eigenvectors are the principal directions.
///
/// Curvature is positive where the surface bends away from its normal, as
/// on a sphere with outward normals (1/radius there).

#include <array>
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/snaxel/fronts.h"
#include "snaxels/mesh/topology.h"

namespace snaxels {

/// The principal curvatures and directions of every vertex of one pose.
struct CurvatureField {
    VertexData<double> k1, k2;           ///< principal curvatures, |k1| >= |k2|
    VertexData<glm::dvec3> dir1, dir2;   ///< unit principal directions in the tangent plane
    VertexData<double> area;             ///< the vertex's mixed Voronoi area
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

/// The radial curvature of every vertex of @p topology seen from @p camera
/// (DeCarlo et al. 2003): the normal curvature in the direction w of the
/// view vector (toward the viewer) projected onto the tangent plane. Its
/// zeros where it grows along w are the suggestive contours. 0 where the
/// view is along the normal (w vanishes).
VertexData<double> radial_curvature(const MeshTopology& topology, const CurvatureField& field, const Camera& camera);

/// The function whose zeros the suggestive kind tracks: kappa_r sin^2(theta)
/// (radial_curvature times the squared sine of the view's angle to the
/// normal, CurvatureField::form of the unit view; theta's sine is positive,
/// so its zeros and sign are kappa_r's, and it is what rtsc interpolates
/// along an edge: where theta differs much between an edge's ends, the zero
/// lies where rtsc finds it, not where kappa_r's own interpolation would put
/// it) at the vertices facing the viewer and at those facing
/// away next to one (the last ring of faces before the contour, where a
/// suggestive contour runs on to meet the silhouette), and a positive value
/// (the typical curvature) at the others. Suggestive contours lie on the
/// side seen; the zeros of kappa_r beyond it (half of a noisy mesh's) are
/// then not tracked. Its zeros also run along the rim of the stand-in where
/// kappa_r < 0 next to it: suggestive_margins leaves those out. Written
/// into @p out, resized to the vertex count.
void suggestive_function(const MeshTopology& topology, const CurvatureField& field, const Camera& camera,
                         VertexData<double>& out);
/// The value suggestive_function gives a vertex facing away.
double suggestive_away_value(const CurvatureField& field);

/// The derivative along w (unit) of the piecewise-linear field @p f of
/// vertex values, in face @p face, seen from @p camera at point @p p of the
/// face: the face's gradient of f dotted with the unit projection of the
/// view vector at p onto the face's plane (0 when the view is along its
/// normal or the face has no area).
double derivative_along_view(const MeshTopology& topology, const VertexData<double>& f, FaceId face,
                             const glm::dvec3& p, const Camera& camera);

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

/// The feature size of @p topology's pose: its median edge length (rtsc's
/// measure), which makes the rtsc test's threshold free of the mesh's scale.
/// Kept with the pose.
double require_feature_size(const MeshTopology& topology);

/// How far each snaxel of @p fronts (a suggestive contour of @p spec, on
/// @p topology's pose of curvature @p field, seen from @p camera) passes
/// its test: the test's value less its threshold spec.k (the derivative
/// test's scale-free derivative, or rtsc's s; see suggestive_margins),
/// -infinity where the test has no value (rtsc's where the surface turns
/// away). What a stroke with width-by="strength" follows.
std::vector<double> suggestive_strength(const MeshTopology& topology, const CurvatureField& field, const Fronts& fronts,
                                        const Camera& camera, const ContourSpec& spec);

/// Where a suggestive contour is drawn (DeCarlo et al. 2003's pruning). Per
/// snaxel of @p fronts, zeros of @p kr (suggestive_function's values from
/// @p field, the pose's curvature with its gradient operator: require_curvature,
/// seen from @p camera): the least of three
/// margins, >= 0 where the snaxel is drawn, each free of the mesh's scale:
///   - the derivative of kappa_r along the view (at the edge's two ends from
///     the area-weighted mean gradient of their faces, interpolated), over
///     the square of the mesh's typical curvature (CurvatureField::typical),
///     less spec.k: only zeros where kappa_r grows toward the viewer are
///     suggestive contours, and weak ones are noise;
///   - cos(spec.min_angle) - N.V: where the surface faces the viewer, w
///     (and so kappa_r) turns unstable;
///   - N.V: suggestive contours lie on the side seen from the camera; a
///     snaxel on an edge from a vertex holding suggestive_function's
///     stand-in gets -1.
/// That is spec.test Derivative's. With SuggestiveTest::Rtsc the margin is
/// the least of N.V and s - spec.k, with s = feature_size^2 tan(theta)
/// D_w kappa_r (DeCarlo et al. 2004, as rtsc computes it: the numerator
/// feature_size^2 sin(theta) D_w kappa_r and the denominator cos(theta)
/// interpolated apart along the edge from its ends, D_w kappa_r as above,
/// the feature size require_feature_size's).
/// The drawing cuts a loop where the margin changes sign, between two
/// snaxels where it interpolates to zero. (Where the view terms are already
/// negative the derivative is not computed and the margin is theirs.)
std::vector<double> suggestive_margins(const MeshTopology& topology, const CurvatureField& field, const VertexData<double>& kr,
                                       const Fronts& fronts, const Camera& camera, const ContourSpec& spec);

} // namespace snaxels
