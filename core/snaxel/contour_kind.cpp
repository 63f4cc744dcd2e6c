#include "snaxels/snaxel/contour_kind.h"

#include <array>
#include <atomic>
#include <mutex>

#include "snaxels/error.h"
#include "snaxels/scene/camera.h"
#include "snaxels/snaxel/contour_function.h"
#include "snaxels/snaxel/curvature.h"
#include "snaxels/snaxel/feature_edges.h"
#include "snaxels/snaxel/suggestive.h"

namespace snaxels {
namespace {

// ---- the kinds' own functions ----------------------------------------------

double visual_g(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3&, double) { return glm::dot(n, v); }
double shadow_g(const glm::dvec3& n, const glm::dvec3&, const glm::dvec3& l, double) { return glm::dot(n, l); }
double isophote_g(const glm::dvec3& n, const glm::dvec3&, const glm::dvec3& l, double k) { return glm::dot(n, l) - k; }
double gleam_g(const glm::dvec3& n, const glm::dvec3& v, const glm::dvec3& l, double k) {
    // V.R - k with R = 2(N.L)N - L, the light reflected about the normal.
    return glm::dot(v, 2.0 * glm::dot(n, l) * n - l) - k;
}

// N.V is f's other term, found beside these: the visual contour has no more.
double visual_arc(const ArcTerms&, double) { return std::numeric_limits<double>::infinity(); }
double shadow_arc(const ArcTerms& t, double) { return first_downward(0.0, t.pl, t.ql, t.w); }
double isophote_arc(const ArcTerms& t, double k) { return first_downward(-k, t.pl, t.ql, t.w); }
double gleam_arc(const ArcTerms& t, double k) {
    // V.R - k = 2 (N.L)(N.V) - L.V - k: a sinusoid in 2x.
    const double c0 = t.pl * t.pv + t.ql * t.qv - t.lv - k;
    return 0.5 * first_downward(c0, t.pl * t.pv - t.ql * t.qv, t.pl * t.qv + t.ql * t.pv, 2.0 * t.w);
}

void suggestive_vertices(const MeshTopology& topology, const Camera& camera, VertexData<double>& out) {
    // kappa_r sin^2(theta) is a curvature (its scale the mesh's), not a cosine: its
    // zeros are its own, and a flat patch's exact 0 is no sign change
    // (suggestive_margins).
    suggestive_function(topology, *require_curvature(topology), camera, out);
}

std::vector<EdgeId> crease_lines(const MeshTopology& topology, const ContourSpec& spec) {
    return crease_edges(topology, spec.k);
}
std::vector<EdgeId> border_lines(const MeshTopology& topology, const ContourSpec&) { return border_edges(topology); }
std::vector<EdgeId> material_lines(const MeshTopology& topology, const ContourSpec&) { return material_edges(topology); }
std::vector<EdgeId> object_lines(const MeshTopology& topology, const ContourSpec&) { return object_edges(topology); }

// ---- the table ---------------------------------------------------------------

std::vector<ContourKindInfo> built_in_kinds() {
    using O = ContourOrigin;
    using V = ContourValue;
    std::vector<ContourKindInfo> k(11);
    k[0] = {ContourKind::Visual, "visual", O::View, V::None, "visual", {"over"}, "#111111", "#e8402a", visual_g, false, visual_arc};
    k[1] = {ContourKind::Shadow, "shadow", O::View, V::None, "shadow", {}, "#2f5fa8", "#2f7fe0", shadow_g, true, shadow_arc};
    k[2] = {ContourKind::Isophote, "isophote", O::View, V::Cosine, "isophote:K", {}, "#8a4fb0", "#a05fd0", isophote_g,
            true, isophote_arc};
    k[3] = {ContourKind::Gleam, "gleam", O::View, V::Cosine, "gleam:K", {}, "#d98c00", "#ffc000", gleam_g, true, gleam_arc};
    k[4] = {ContourKind::Parabolic, "parabolic", O::Surface, V::None, "parabolic", {}, "#1f8a4c", "#3ddc84"};
    k[5] = {ContourKind::Crease, "crease", O::Edges, V::Angle, "crease[:DEG]", {"min-length"}, "#333333", "#f0f0f0"};
    k[5].edges = crease_lines;
    k[6] = {ContourKind::Border, "border", O::Edges, V::None, "border", {"min-length"}, "#111111", "#ff7ac8"};
    k[6].edges = border_lines;
    k[7] = {ContourKind::Suggestive, "suggestive", O::Vertices, V::Suggestive, "suggestive[:D[:DEG]], suggestive:rtsc[:T]",
            {"test", "min-derivative", "min-angle", "threshold", "fade"}, "#5a4632", "#ff9a3c"};
    k[7].vertices = suggestive_vertices;
    k[8] = {ContourKind::Material, "material", O::Edges, V::None, "material", {"min-length"}, "#333333", "#7ad7ff"};
    k[8].edges = material_lines;
    k[9] = {ContourKind::Object, "object", O::Edges, V::None, "object", {"min-length"}, "#111111", "#ffe45c"};
    k[9].edges = object_lines;
    k[10] = {ContourKind::Intersection, "intersection", O::Surface, V::None, "intersection", {}, "#111111", "#ff5c8a"};
    return k;
}

/// The table: the built-ins, then the kinds registered, in slots that never
/// move (a lookup reads the count, then its slot).
struct Table {
    static constexpr std::size_t kCapacity = 64;
    std::array<ContourKindInfo, kCapacity> slots;
    std::atomic<std::size_t> count{0};
    std::mutex adding;
    Table() {
        for (ContourKindInfo& info : built_in_kinds()) slots[count.fetch_add(1)] = std::move(info);
    }
};

Table& table() {
    static Table t;
    return t;
}

} // namespace

const ContourKindInfo& contour_kind_info(ContourKind kind) {
    const Table& t = table();
    const auto i = static_cast<int>(kind); // the kinds number the table's slots
    const auto n = static_cast<int>(t.count.load(std::memory_order_acquire));
    return i >= 0 && i < n ? t.slots[static_cast<unsigned>(i)] : t.slots[0];
}

const ContourKindInfo* find_contour_kind(const std::string& name) {
    const Table& t = table();
    const std::size_t n = t.count.load(std::memory_order_acquire);
    for (std::size_t i = 0; i < n; ++i)
        if (name == t.slots[i].name) return &t.slots[i];
    return nullptr;
}

std::vector<const ContourKindInfo*> contour_kinds() {
    const Table& t = table();
    const std::size_t n = t.count.load(std::memory_order_acquire);
    std::vector<const ContourKindInfo*> out;
    for (std::size_t i = 0; i < n; ++i) out.push_back(&t.slots[i]);
    return out;
}

std::string contour_kind_usages(const std::string& last) {
    const std::vector<const ContourKindInfo*> kinds = contour_kinds();
    std::string out;
    for (std::size_t i = 0; i < kinds.size(); ++i)
        out += (i ? i + 1 == kinds.size() ? last : std::string(", ") : std::string()) + kinds[i]->usage;
    return out;
}

ContourKind register_contour_kind(ContourKindInfo info) {
    Table& t = table();
    const std::lock_guard lock(t.adding);
    const bool complete = info.origin == ContourOrigin::View       ? info.g != nullptr
                          : info.origin == ContourOrigin::Vertices ? info.vertices != nullptr
                          : info.origin == ContourOrigin::Edges    ? info.edges != nullptr
                                                                   : false; // a surface line needs a search of its own
    if (!complete) throw Error(std::string("contour kind '") + info.name + "' has no function for its origin");
    if (find_contour_kind(info.name)) throw Error(std::string("a contour kind named '") + info.name + "' exists already");
    const std::size_t i = t.count.load();
    if (i == Table::kCapacity) throw Error("the table of contour kinds is full");
    info.kind = ContourKind(i);
    t.slots[i] = std::move(info);
    t.count.store(i + 1, std::memory_order_release);
    return ContourKind(i);
}

} // namespace snaxels
