#pragma once
/// The implicit contour functions of the paper's "NPR Contouring" section,
/// evaluated at a surface point with its (slerped) normal. f >= 0 is inside.

#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/scene/camera.h"
#include "snaxels/mesh/parts.h"
#include "snaxels/mesh/topology.h"
#include "snaxels/snaxel/contour_kind.h"

namespace snaxels {

/// On a mesh with split sharp edges, f within this of zero at a vertex is a
/// face seen edge-on (some 0.0006 degrees: ten times the rounding of a
/// file's single-precision normal), and counts as turned away: a box seen
/// square-on is outlined along its near edges, not the hidden ones behind
/// them that project to the same place (ContourFunction::evaluate_vertices).
constexpr double kEdgeOn = 1e-5;

/// Suggestive contours' defaults: the least scale-free derivative of the
/// radial curvature (ContourSpec::k) and the least angle, in degrees,
/// between the normal and the view (ContourSpec::min_angle).
constexpr double kDefaultSuggestiveDerivative = 4.0;
constexpr double kDefaultSuggestiveAngle = 15.0;

/// Which parts of kappa_r's zeros a suggestive contour draws.
enum class SuggestiveTest {
    /// Where the derivative of kappa_r along the view, over the square of
    /// the mesh's typical curvature, is at least k, and the surface is seen
    /// at more than min_angle from its normal.
    Derivative,
    /// DeCarlo et al. 2004's test, as their rtsc draws: where
    /// s = feature_size^2 tan(theta) D_w kappa_r exceeds k (theta the angle
    /// between the normal and the view, the feature size the median edge
    /// length of the surface). The tan(theta) carries a line that continues
    /// a silhouette on into the fold it makes.
    Rtsc,
};
/// The rtsc test's default threshold on s (rtsc's own).
constexpr double kDefaultRtscThreshold = 0.01;

/// Which contour: visual N.V; shadow min(N.L, N.V); diffuse isophote
/// min(N.L - k, N.V); specular gleam min(V.R - k, N.V) with R = 2(N.L)N - L.
/// Parabolic curves, creases, borders and part boundaries have no contour
/// function: they are lines of the mesh, the same from any view
/// (on_surface()). Parabolic curves are found from visual events over all
/// views (core/parabolic); creases are the edges whose faces meet at more
/// than k degrees, borders the edges with one face, material lines the
/// edges between faces of two materials, object lines the edges between
/// faces of two objects (core/snaxel/feature_edges.h). Intersection
/// lines are where two surfaces pass through each other (two objects, or
/// one object through itself: core/snaxel/intersections.h); they move with
/// the surfaces and change where the objects move apart. Suggestive
/// contours are the zeros of the radial curvature kappa_r (a function of
/// the vertices, from the pose's curvature: core/snaxel/curvature.h),
/// linear along an edge; the drawing keeps the parts where kappa_r grows
/// toward the viewer fast enough and the surface is seen at a slant
/// (suggestive_margins).
struct ContourSpec {
    ContourKind kind = ContourKind::Visual;
    double k = 0.0;
    /// Creases and borders: chains shorter than this fraction of the mesh's
    /// bounding-box diagonal are left out (the short, scattered creases of a
    /// scanned surface); 0 keeps every edge.
    double min_length = 0.0;
    /// Suggestive contours: parts where the angle between the normal and the
    /// view is below this many degrees are not drawn (k is then the least
    /// derivative of kappa_r along the view, times the squared bounding-box
    /// diagonal, that is drawn).
    double min_angle = 0.0;
    /// Suggestive contours: which test draws (k is then its threshold).
    /// parse() and styles take rtsc's unless the derivative test's values
    /// are given; a spec built in code says which.
    SuggestiveTest test = SuggestiveTest::Derivative;
    /// The parts of the scene whose stretches of the line are drawn (a line
    /// set of a style): the engine finds the whole line; the drawing leaves
    /// out what lies on other parts (core/visibility/visibility.h).
    PartSelector parts{};

    /// "visual", "shadow", "isophote", "gleam", "parabolic", "crease",
    /// "border", "suggestive", "material", "object" or "intersection".
    std::string kind_name() const;
    /// "visual", "shadow", "isophote:0.5", "gleam:0.9", "parabolic",
    /// "crease:30", "border", "suggestive:0.5:15" (the derivative test),
    /// "suggestive:rtsc:0.01" (rtsc's), "material", "object", "intersection":
    /// what parse() reads; followed by the part selector's text when it has
    /// one ("visual object=wheel*").
    std::string label() const;
    /// The line itself, whatever parts it is drawn on: the spec without its
    /// part selector (what the engine computes and trackers follow).
    ContourSpec line() const {
        ContourSpec out = *this;
        out.parts = {};
        return out;
    }
    /// A line of the mesh itself (parabolic, crease, border, material,
    /// object, intersection), not the zero set of a function of the view
    /// and light: fixed on the surface while the mesh keeps its pose,
    /// bounding no region of its own.
    bool on_surface() const {
        const ContourOrigin origin = contour_kind_info(kind).origin;
        return origin == ContourOrigin::Surface || origin == ContourOrigin::Edges;
    }
    /// A line made of whole mesh edges (crease, border, material, object):
    /// feature_fronts finds it.
    bool along_edges() const { return contour_kind_info(kind).origin == ContourOrigin::Edges; }
    /// Parses the CLI's --kind values; throws snaxels::Error when malformed.
    static ContourSpec parse(const std::string& text);
    /// The same contour (kind, test, and k, min_length and min_angle within
    /// 1e-9, and the same parts).
    bool same_as(const ContourSpec& other) const;
};

/// The arc between two unit normals, the part of a root on a slerped edge
/// that depends on the edge alone (so it is the same in every frame while
/// the mesh keeps its pose): its cosine (clamped to [-1, 1]), its angle w
/// and sin(w).
struct NormalArc {
    double c = 0.0, w = std::numeric_limits<double>::quiet_NaN(), s = 0.0;
    bool known() const { return !std::isnan(w); }
};
NormalArc normal_arc(const glm::dvec3& na, const glm::dvec3& nb);

/// f for one spec, camera and light.
class ContourFunction {
  public:
    ContourFunction(const ContourSpec& spec, const Camera& camera, const Light& light);

    double operator()(const glm::dvec3& p, const glm::dvec3& n) const;

    /// True when f is N.v for one vector v everywhere (the visual contour
    /// seen by an orthographic camera): f at a vertex is then one dot
    /// product, and its zero on a slerped edge has a closed form.
    bool linear_in_normal() const { return linear_; }
    /// True when f is a function of the vertices interpolated linearly
    /// along an edge (suggestive contours' kappa_r): its zero on an edge is
    /// then f_a / (f_a - f_b), and the vertex values come from the pose's
    /// curvature (suggestive_function in core/snaxel/curvature.h).
    bool linear_on_edge() const { return contour_kind_info(spec_.kind).origin == ContourOrigin::Vertices; }
    /// That v (the unit vector toward the viewer) when linear_in_normal().
    const glm::dvec3& normal_coefficient() const { return v_; }

    /// True when the camera is orthographic and the light directional: V and
    /// L are then the same at every point, so along a slerped edge every
    /// term of f is a sinusoid in the arc angle (N.V, N.L - k) or in twice
    /// it (the gleam's V.R - k), and f's first zero has a closed form.
    bool closed_form() const { return closed_; }
    /// With closed_form(): the first t in [0, 1] where f turns negative on
    /// the slerp from @p na (f >= 0) to @p nb (f < 0), exact to rounding.
    /// NaN when the arc is degenerate (normals opposite) or no term crosses
    /// (rounding): the caller then brackets the root numerically.
    double first_zero(const glm::dvec3& na, const glm::dvec3& nb, double f_a, double f_b) const;
    /// The same with the arc from @p na to @p nb given (normal_arc).
    double first_zero(const glm::dvec3& na, const glm::dvec3& nb, const NormalArc& arc, double f_a, double f_b) const;

    /// f at every vertex of @p topology's pose into @p out: evaluate_vertices
    /// below, or for suggestive contours suggestive_function (kappa_r on the
    /// side seen) from the pose's curvature.
    void evaluate_vertices(const MeshTopology& topology, VertexData<double>& out) const;
    /// f at every vertex into @p out (sized to the vertices).
    void evaluate_vertices(ElementSpan<VertexTag, const glm::dvec3> positions,
                           ElementSpan<VertexTag, const glm::dvec3> normals, VertexData<double>& out) const;

  private:
    double evaluate(const glm::dvec3& p, const glm::dvec3& n) const;

    ContourSpec spec_;
    const ContourKindInfo* kind_; ///< its entry in the table of kinds
    Camera camera_;
    Light light_;
    bool linear_ = false, closed_ = false;
    glm::dvec3 v_{0.0}; ///< to the viewer (orthographic)
    glm::dvec3 l_{0.0}; ///< to the light (directional)
};

/// The first y in [0, span] where c0 + a cos y + b sin y turns negative
/// (it is >= 0 at y = 0), or +inf when it does not: the zero of one
/// sinusoidal term of f along a slerped edge (ContourKindInfo::arc_zero).
double first_downward(double c0, double a, double b, double span);

/// The zero of N.v on the slerp from @p na (N.v = @p a >= 0) to @p nb
/// (N.v = @p b < 0), as t in [0, 1]: a sin((1-t)w) + b sin(tw) = 0 with w
/// the arc's angle, solved in closed form.
double slerp_dot_root(const glm::dvec3& na, const glm::dvec3& nb, double a, double b);
/// The same with the arc from @p na to @p nb given (normal_arc).
double slerp_dot_root(const NormalArc& arc, double a, double b);

/// Spherical linear interpolation of unit normals, the limit na as they align.
glm::dvec3 slerp_normal(const glm::dvec3& na, const glm::dvec3& nb, double t);

/// slerp_normal along one edge, its arc's angle found once: root polishing
/// evaluates many points of the same edge (the same values, fewer acos and
/// sin calls).
class SlerpArc {
  public:
    SlerpArc(const glm::dvec3& na, const glm::dvec3& nb);
    /// With the arc between them known (normal_arc(na, nb)).
    SlerpArc(const glm::dvec3& na, const glm::dvec3& nb, const NormalArc& arc) : na_(na), nb_(nb), arc_(arc) {}
    glm::dvec3 operator()(double t) const;

  private:
    glm::dvec3 na_, nb_;
    NormalArc arc_;
};

} // namespace snaxels
