#pragma once
/// Suggestive contours (DeCarlo et al. 2003, drawn as their program rtsc
/// draws them, DeCarlo et al. 2004): the function whose zeros the
/// suggestive kind tracks, from the pose's curvature (curvature.h), and the
/// tests that choose which of its zeros are drawn.

#include <vector>

#include <glm/vec3.hpp>

#include "snaxels/mesh/topology.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/snaxel/curvature.h"
#include "snaxels/snaxel/fronts.h"

namespace snaxels {

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
