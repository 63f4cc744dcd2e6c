#pragma once
/// The contour kinds, in one table: each kind's name, where its line comes
/// from, the value it takes, the style attributes it reads, its colours,
/// and its own function (f at a point, the vertices' values, or the mesh
/// edges it runs along). Everything that needs to know about a kind reads
/// it here: the command line's --kind, the style's <contour kind>, the
/// engine, the drawing's defaults and the application's 3-D view. Adding a
/// kind is one entry of the table and its function (register_contour_kind
/// adds one at run time).

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "snaxels/mesh/elements.h"

namespace snaxels {

struct Camera;
class MeshTopology;
struct ContourSpec;

/// The built-in kinds, in the table's order. A kind registered at run time
/// takes the next value.
enum class ContourKind {
    Visual, Shadow, Isophote, Gleam, Parabolic, Crease, Border, Suggestive, Material, Object, Intersection
};

/// Where a kind's line comes from.
enum class ContourOrigin : std::uint8_t {
    /// The zero set of min(g, N.V), g a function of the unit normal, the
    /// unit vectors toward the viewer and the light, and the spec's k
    /// (ContourKindInfo::g): tracked by snaxels from any view.
    View,
    /// The zero set of a function of the vertices (the pose's curvature and
    /// the view: ContourKindInfo::vertices), linear along an edge.
    Vertices,
    /// Whole mesh edges (ContourKindInfo::edges), chained: fixed on the
    /// surface while the mesh keeps its pose.
    Edges,
    /// Another line fixed on the surface, found by its own search (the
    /// parabolic curves from visual events, intersection lines where
    /// surfaces pass through each other).
    Surface,
};

/// The value a kind takes: on the command line after a colon, in a style as
/// attributes.
enum class ContourValue : std::uint8_t {
    None,       ///< no value ("visual")
    Cosine,     ///< k, a cosine in -1 .. 1, required ("isophote:0.5"; k="0.5")
    Angle,      ///< degrees above 0 and below 180, 30 unless given ("crease:45"; angle="45")
    Suggestive, ///< a suggestive contour's test and its thresholds (ContourSpec::parse says which)
};

/// The terms of f along a slerped edge seen by an orthographic camera under
/// a directional light, at arc angle x: N.V = pv cos x + qv sin x and N.L =
/// pl cos x + ql sin x; lv is L.V and w the arc's angle.
struct ArcTerms {
    double pv = 0.0, qv = 0.0, pl = 0.0, ql = 0.0, lv = 0.0, w = 0.0;
};

struct ContourKindInfo {
    ContourKind kind = ContourKind::Visual;
    const char* name = "";
    ContourOrigin origin = ContourOrigin::View;
    ContourValue value = ContourValue::None;
    /// How --kind writes it, for the list an unknown kind gets ("isophote:K").
    const char* usage = "";
    /// The <contour> attributes this kind takes beyond those of every kind
    /// (kind, object, material; k and angle are the value's).
    std::vector<const char*> attributes;
    /// The stroke a style draws it with when it names none, and its colour
    /// in the application's 3-D view.
    const char* stroke = "#111111";
    const char* view_colour = "#ffffff";
    /// View kinds: g, of the unit normal @p n and the unit vectors toward
    /// the viewer @p v and the light @p l, and the spec's k (f is min(g, N.V)).
    double (*g)(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double k) = nullptr;
    /// View kinds that use the light (else @p l is not computed for g).
    bool lit = false;
    /// View kinds, optional: g's first downward zero along a slerped edge
    /// in closed form (arc angle, +inf when none); without it the engine
    /// brackets the root numerically.
    double (*arc_zero)(const ArcTerms& terms, double k) = nullptr;
    /// Vertices kinds: f at every vertex of the topology's pose.
    void (*vertices)(const MeshTopology& topology, const Camera& camera, VertexData<double>& out) = nullptr;
    /// Edges kinds: the edges the line runs along.
    std::vector<EdgeId> (*edges)(const MeshTopology& topology, const ContourSpec& spec) = nullptr;
};

/// The entry of @p kind (the visual contour's for a value no entry has).
const ContourKindInfo& contour_kind_info(ContourKind kind);
/// The entry named @p name, or null.
const ContourKindInfo* find_contour_kind(const std::string& name);
/// Every kind, in the table's order (the built-ins, then those registered).
std::vector<const ContourKindInfo*> contour_kinds();
/// Every kind as --kind writes it ("isophote:K"), joined by ", " and, before
/// the last, by @p last (" or ").
std::string contour_kind_usages(const std::string& last);
/// Adds @p info to the table as a new kind (its `kind` is set to the value
/// returned). Throws snaxels::Error when the name is taken or the table is
/// full. Kinds are registered before they are used; lookups on other
/// threads may run meanwhile.
ContourKind register_contour_kind(ContourKindInfo info);

} // namespace snaxels
