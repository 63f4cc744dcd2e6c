#include "snaxels/snaxel/curvature.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "snaxels/snaxel/detail/corner_areas.h"
#include "snaxels/util/detail/lanes.h"
#include "snaxels/util/detail/parallel.h"

namespace snaxels {

namespace {

/// A face's second fundamental form in its own frame (t, b): the symmetric
/// matrix [ku kuv; kuv kv], with the face's share of each corner's area.
struct FaceForm {
    glm::dvec3 t{0.0}, b{0.0};
    glm::dvec3 n{0.0}; ///< t x b (the face's unit normal, which a vertex frame is turned toward)
    double ku = 0.0, kuv = 0.0, kv = 0.0;
    std::array<double, 3> corner{0.0, 0.0, 0.0}; ///< 0 for a face of no area: it then counts nowhere
};

/// A vertex's unit tangent frame (u, v) and u x v (its normal, the axis
/// the frame is turned about).
struct TangentFrame {
    glm::dvec3 u, v, n;
};

// The curvature passes compute several forms, vertices or faces at once,
// each a lane of a vector (snaxels/util/detail/lanes.h: each lane's result
// is the scalar formula's to the bit, in the two-lane and the AVX2 builds).
namespace lanes {
using namespace simd;

/// The projected forms, a lane per form: [k0 k1; k1 k2] in the frame.
struct Projected {
    alignas(32) double k0[kMaxWidth], k1[kMaxWidth], k2[kMaxWidth];
};

/// The forms of @p source numbered @p at, turned into @p frame, a lane
/// each. source.t(i), b(i), n(i), ku(i), kuv(i), kv(i) give form i: the
/// form [ku kuv; kuv kv] in the frame (t, b) of normal n. The vertex frame
/// (u, v) is first turned about o = u x v onto the form's plane (the
/// smallest rotation taking o to n: u - d (u.p) with p = n - (n.o) o and
/// d = (o + n) / (1 + n.o); negated when n = -o), then the turned axes'
/// coordinates in (t, b) give the form in (u, v).
template <std::size_t W, class Source>
[[gnu::always_inline]] inline void project(const Source& source, const std::size_t* at, const TangentFrame& frame,
                                           Projected& out) {
    using D = Doubles<W>;
    const D tx = gather<W>([&](std::size_t l) { return source.t(at[l]).x; });
    const D ty = gather<W>([&](std::size_t l) { return source.t(at[l]).y; });
    const D tz = gather<W>([&](std::size_t l) { return source.t(at[l]).z; });
    const D bx = gather<W>([&](std::size_t l) { return source.b(at[l]).x; });
    const D by = gather<W>([&](std::size_t l) { return source.b(at[l]).y; });
    const D bz = gather<W>([&](std::size_t l) { return source.b(at[l]).z; });
    const D nx = gather<W>([&](std::size_t l) { return source.n(at[l]).x; });
    const D ny = gather<W>([&](std::size_t l) { return source.n(at[l]).y; });
    const D nz = gather<W>([&](std::size_t l) { return source.n(at[l]).z; });
    const D ux = splat<W>(frame.u.x), uy = splat<W>(frame.u.y), uz = splat<W>(frame.u.z);
    const D vx = splat<W>(frame.v.x), vy = splat<W>(frame.v.y), vz = splat<W>(frame.v.z);
    const D ox = splat<W>(frame.n.x), oy = splat<W>(frame.n.y), oz = splat<W>(frame.n.z);
    // The frame turned onto each form's plane.
    const D ndot = dot<W>(ox, oy, oz, nx, ny, nz);
    const Mask<W> flip = ndot <= splat<W>(-1.0);
    const D px = nx - ndot * ox, py = ny - ndot * oy, pz = nz - ndot * oz;
    const D denominator = splat<W>(1.0) + ndot;
    const D dx = (ox + nx) / denominator, dy = (oy + ny) / denominator, dz = (oz + nz) / denominator;
    const D du = dot<W>(ux, uy, uz, px, py, pz), dv = dot<W>(vx, vy, vz, px, py, pz);
    const D rux = select<W>(flip, -ux, ux - dx * du), ruy = select<W>(flip, -uy, uy - dy * du),
            ruz = select<W>(flip, -uz, uz - dz * du);
    const D rvx = select<W>(flip, -vx, vx - dx * dv), rvy = select<W>(flip, -vy, vy - dy * dv),
            rvz = select<W>(flip, -vz, vz - dz * dv);
    // Each form in the turned frame.
    const D u1 = dot<W>(rux, ruy, ruz, tx, ty, tz), v1 = dot<W>(rux, ruy, ruz, bx, by, bz);
    const D u2 = dot<W>(rvx, rvy, rvz, tx, ty, tz), v2 = dot<W>(rvx, rvy, rvz, bx, by, bz);
    const D ku = gather<W>([&](std::size_t l) { return source.ku(at[l]); });
    const D kuv = gather<W>([&](std::size_t l) { return source.kuv(at[l]); });
    const D kv = gather<W>([&](std::size_t l) { return source.kv(at[l]); });
    const D two = splat<W>(2.0);
    store<W>(out.k0, ku * u1 * u1 + kuv * (two * u1 * v1) + kv * v1 * v1);
    store<W>(out.k1, ku * u1 * u2 + kuv * (u1 * v2 + u2 * v1) + kv * v1 * v2);
    store<W>(out.k2, ku * u2 * u2 + kuv * (two * u2 * v2) + kv * v2 * v2);
}

/// A vertex's weighted sum of the forms of a Source (as project reads it)
/// turned into its frame, W at a time: add() each (its number and weight,
/// in order), then finish().
template <std::size_t W, class Source> struct FormSum {
    FormSum(const Source& s, const TangentFrame& f) : source(s), frame(f) {}
    const Source& source;
    const TangentFrame& frame;
    Projected k;
    std::size_t at[kMaxWidth]{};
    double weight[kMaxWidth]{};
    std::size_t filled = 0;
    double total = 0.0, ku = 0.0, kuv = 0.0, kv = 0.0;

    [[gnu::always_inline]] void add(std::size_t i, double w) {
        at[filled] = i;
        weight[filled++] = w;
        if (filled == W) flush();
    }
    [[gnu::always_inline]] void finish() {
        if (filled == 0) return;
        for (std::size_t lane = filled; lane < W; ++lane) at[lane] = at[0]; // computed, never summed
        flush();
    }
    [[gnu::always_inline]] void flush() {
        project<W>(source, at, frame, k);
        for (std::size_t lane = 0; lane < filled; ++lane) {
            total += weight[lane];
            ku += weight[lane] * k.k0[lane];
            kuv += weight[lane] * k.k1[lane];
            kv += weight[lane] * k.k2[lane];
        }
        filled = 0;
    }
};

} // namespace lanes

/// A unit tangent frame (u, v) at vertex @p v, u toward its first neighbour.
TangentFrame vertex_frame(const MeshTopology& topo, VertexId v) {
    const glm::dvec3 n = topo.normals()[v];
    glm::dvec3 u(0.0);
    if (const auto ring = topo.neighbours(v); !ring.empty()) {
        const glm::dvec3 d = topo.positions()[ring.front()] - topo.positions()[v];
        u = d - glm::dot(d, n) * n;
    }
    if (!(glm::length(u) > 0.0)) { // no neighbour, or one along the normal: any tangent
        u = glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0));
    }
    u = glm::normalize(u);
    const glm::dvec3 w = glm::cross(n, u);
    return {u, w, glm::cross(u, w)};
}

/// Every vertex's tangent frame (vertex_frame), found once per pose for
/// the passes that turn forms into it.
VertexData<TangentFrame> vertex_frames(const MeshTopology& topo) {
    VertexData<TangentFrame> frames(topo.n_vertices());
    parallel_for(topo.vertices(), [&](VertexId v) { frames[v] = vertex_frame(topo, v); }, 4096);
    return frames;
}

/// A face's area and its corners' gradients (corner_gradients).
struct FaceGradients {
    double area = 0.0;
    std::array<glm::dvec3, 3> g;
};

namespace lanes {

/// A vertex waiting for its principal curvatures: its mean form in its frame.
struct Pending {
    VertexId v;
    double ku, kuv, kv;
};

/// The principal curvatures and directions of @p count pending vertices
/// (at most W), a lane each, from each one's second fundamental form
/// [ku kuv; kuv kv] in its tangent frame (u, w): the Jacobi rotation that
/// diagonalizes it, |k1| >= |k2|, and dir2 = n x dir1.
template <std::size_t W>
[[gnu::always_inline]] inline void principal(const Pending* pending, std::size_t count, const VertexData<TangentFrame>& frames,
                                             ElementSpan<VertexTag, const glm::dvec3> normals, CurvatureField& out) {
    using D = Doubles<W>;
    auto lane = [&](std::size_t l) -> const Pending& { return pending[l < count ? l : 0]; };
    const D ku = gather<W>([&](std::size_t l) { return lane(l).ku; });
    const D kuv = gather<W>([&](std::size_t l) { return lane(l).kuv; });
    const D kv = gather<W>([&](std::size_t l) { return lane(l).kv; });
    // The Jacobi rotation, where kuv != 0 (else none).
    const Mask<W> rotate = kuv != splat<W>(0.0);
    const D h = splat<W>(0.5) * (kv - ku) / kuv;
    const D root = sqrt<W>(splat<W>(1.0) + h * h);
    const D t_rotate = splat<W>(1.0) / select<W>(h < splat<W>(0.0), h - root, h + root);
    const D c_rotate = splat<W>(1.0) / sqrt<W>(splat<W>(1.0) + t_rotate * t_rotate);
    const D tt = select<W>(rotate, t_rotate, splat<W>(0.0));
    const D c = select<W>(rotate, c_rotate, splat<W>(1.0));
    const D s = select<W>(rotate, t_rotate * c_rotate, splat<W>(0.0));
    const D k1 = ku - tt * kuv, k2 = kv + tt * kuv;
    const Mask<W> swap = abs<W>(k1) < abs<W>(k2);
    auto frame_of = [&](std::size_t l) -> const TangentFrame& { return frames[lane(l).v]; };
    const D ux = gather<W>([&](std::size_t l) { return frame_of(l).u.x; });
    const D uy = gather<W>([&](std::size_t l) { return frame_of(l).u.y; });
    const D uz = gather<W>([&](std::size_t l) { return frame_of(l).u.z; });
    const D wx = gather<W>([&](std::size_t l) { return frame_of(l).v.x; });
    const D wy = gather<W>([&](std::size_t l) { return frame_of(l).v.y; });
    const D wz = gather<W>([&](std::size_t l) { return frame_of(l).v.z; });
    const D d1x = select<W>(swap, s * ux + c * wx, c * ux - s * wx);
    const D d1y = select<W>(swap, s * uy + c * wy, c * uy - s * wy);
    const D d1z = select<W>(swap, s * uz + c * wz, c * uz - s * wz);
    const D nx = gather<W>([&](std::size_t l) { return normals[lane(l).v].x; });
    const D ny = gather<W>([&](std::size_t l) { return normals[lane(l).v].y; });
    const D nz = gather<W>([&](std::size_t l) { return normals[lane(l).v].z; });
    // glm::cross(n, d1)'s order.
    const D d2x = ny * d1z - d1y * nz, d2y = nz * d1x - d1z * nx, d2z = nx * d1y - d1x * ny;
    const D first = select<W>(swap, k2, k1), second = select<W>(swap, k1, k2);
    for (std::size_t l = 0; l < count; ++l) {
        const VertexId v = pending[l].v;
        out.k1[v] = first[l];
        out.k2[v] = second[l];
        out.dir1[v] = glm::dvec3(d1x[l], d1y[l], d1z[l]);
        out.dir2[v] = glm::dvec3(d2x[l], d2y[l], d2z[l]);
    }
}

/// principal over all of @p pending, W at a time.
template <std::size_t W>
[[gnu::always_inline]] inline void principals(const Pending* pending, std::size_t count,
                                              const VertexData<TangentFrame>& frames, ElementSpan<VertexTag, const glm::dvec3> normals,
                                              CurvatureField& out) {
    for (std::size_t at = 0; at < count; at += W) principal<W>(pending + at, std::min(W, count - at), frames, normals, out);
}

/// The vertex values @p values (positions or normals) at each corner of the
/// @p count (at most W) faces from @p first, a face per lane (the lanes
/// past count repeat the first face).
template <std::size_t W>
[[gnu::always_inline]] inline std::array<Vec3<W>, 3> at_corners(const MeshTopology& topo, std::size_t first, std::size_t count,
                                                                ElementSpan<VertexTag, const glm::dvec3> values) {
    const auto fv = topo.face_vertices();
    auto corner = [&](std::size_t l, std::size_t k) -> const glm::dvec3& {
        return values[fv[FaceId(first + (l < count ? l : 0))][k]];
    };
    return {gather3<W>([&](std::size_t l) -> const glm::dvec3& { return corner(l, 0); }),
            gather3<W>([&](std::size_t l) -> const glm::dvec3& { return corner(l, 1); }),
            gather3<W>([&](std::size_t l) -> const glm::dvec3& { return corner(l, 2); })};
}

/// The second fundamental forms of the @p count (at most W) faces from
/// @p first, a lane each, written to @p out: each fitted to the change of
/// the vertex normals along the face's edges (least squares over the three
/// edges, in the face's frame t along its first edge, b = n x t), with each
/// corner's share of the face's area. A face of no area gets a zero form
/// and no area; one whose normal equations are singular keeps its frame
/// and gets no area.
template <std::size_t W>
[[gnu::always_inline]] inline void face_forms(const MeshTopology& topo, std::size_t first, std::size_t count, FaceForm* out) {
    using D = Doubles<W>;
    const auto [p0, p1, p2] = at_corners<W>(topo, first, count, topo.positions());
    const std::array<Vec3<W>, 3> normal = at_corners<W>(topo, first, count, topo.normals());
    const std::array<Vec3<W>, 3> e{p2 - p1, p0 - p2, p1 - p0};
    const Vec3<W> cr = cross<W>(e[0], e[1]);
    const D twice_area = sqrt<W>(dot<W>(cr, cr));
    const D e0 = sqrt<W>(dot<W>(e[0], e[0]));
    const Vec3<W> n = cr / twice_area;
    const Vec3<W> t = e[0] / e0;
    const Vec3<W> b = cross<W>(n, t);
    D w00 = splat<W>(0.0), w01 = splat<W>(0.0), w22 = splat<W>(0.0), m0 = splat<W>(0.0), m1 = splat<W>(0.0),
      m2 = splat<W>(0.0);
    for (std::size_t j = 0; j < 3; ++j) {
        const D u = dot<W>(e[j], t), v = dot<W>(e[j], b);
        w00 = w00 + u * u;
        w01 = w01 + u * v;
        w22 = w22 + v * v;
        const Vec3<W> dn = normal[(j + 2) % 3] - normal[(j + 1) % 3];
        const D dnu = dot<W>(dn, t), dnv = dot<W>(dn, b);
        m0 = m0 + dnu * u;
        m1 = m1 + (dnu * v + dnv * u);
        m2 = m2 + dnv * v;
    }
    // glm::determinant and glm::inverse of the symmetric [w00 w01 0; w01 w00+w22 w01; 0 w01 w22] (m[column][row]).
    const D zero = splat<W>(0.0);
    const D a00 = w00, a01 = w01, a02 = zero, a10 = w01, a11 = w00 + w22, a12 = w01, a20 = zero, a21 = w01, a22 = w22;
    const D det = a00 * (a11 * a22 - a21 * a12) - a10 * (a01 * a22 - a21 * a02) + a20 * (a01 * a12 - a11 * a02);
    const D scale = w00 + w22;
    const Mask<W> solvable = abs<W>(det) > splat<W>(1e-30) * (scale * scale * scale);
    const D ood = splat<W>(1.0) / det;
    const D i00 = (a11 * a22 - a21 * a12) * ood, i10 = -(a10 * a22 - a20 * a12) * ood, i20 = (a10 * a21 - a20 * a11) * ood;
    const D i01 = -(a01 * a22 - a21 * a02) * ood, i11 = (a00 * a22 - a20 * a02) * ood, i21 = -(a00 * a21 - a20 * a01) * ood;
    const D i02 = (a01 * a12 - a11 * a02) * ood, i12 = -(a00 * a12 - a10 * a02) * ood, i22 = (a00 * a11 - a10 * a01) * ood;
    const D ku = i00 * m0 + i10 * m1 + i20 * m2;
    const D kuv = i01 * m0 + i11 * m1 + i21 * m2;
    const D kv = i02 * m0 + i12 * m1 + i22 * m2;
    const Vec3<W> tb = cross<W>(t, b);
    for (std::size_t l = 0; l < count; ++l) {
        FaceForm& form = out[l];
        form = FaceForm{};
        if (!(twice_area[l] > 0.0) || !(e0[l] > 0.0)) continue;
        form.t = t.lane(l);
        form.b = b.lane(l);
        if (!solvable[l]) continue;
        form.ku = ku[l];
        form.kuv = kuv[l];
        form.kv = kv[l];
        form.n = tb.lane(l);
        form.corner = detail::corner_areas({e[0].lane(l), e[1].lane(l), e[2].lane(l)}, 0.5 * twice_area[l]);
    }
}

/// The gradients of the corners' barycentric coordinates of the @p count
/// (at most W) faces from @p first (corner_gradients, a lane each, with the
/// same operations in the same order), and their areas.
template <std::size_t W>
[[gnu::always_inline]] inline void face_gradients(const MeshTopology& topo, std::size_t first, std::size_t count,
                                                  FaceGradients* out) {
    using D = Doubles<W>;
    const auto [a, b, c] = at_corners<W>(topo, first, count, topo.positions());
    const Vec3<W> normal = cross<W>(b - a, c - a);
    const D twice_area2 = dot<W>(normal, normal);
    const D area = splat<W>(0.5) * sqrt<W>(twice_area2);
    const std::array<Vec3<W>, 3> g{cross<W>(normal, c - b) / twice_area2, cross<W>(normal, a - c) / twice_area2,
                                   cross<W>(normal, b - a) / twice_area2};
    for (std::size_t l = 0; l < count; ++l) {
        out[l].area = area[l];
        for (std::size_t k = 0; k < 3; ++k) out[l].g[k] = twice_area2[l] > 0.0 ? g[k].lane(l) : glm::dvec3(0.0);
    }
}

} // namespace lanes

/// The median |k1| over the vertices with area (CurvatureField::typical).
double typical_curvature(const CurvatureField& field) {
    std::vector<double> magnitudes;
    magnitudes.reserve(field.size());
    for (const VertexId v : field.k1.ids())
        if (field.area[v] > 0.0) magnitudes.push_back(std::abs(field.k1[v]));
    if (magnitudes.empty()) return 0.0;
    const auto middle = magnitudes.begin() + std::ptrdiff_t(magnitudes.size() / 2);
    std::nth_element(magnitudes.begin(), middle, magnitudes.end());
    return *middle;
}

/// What the curvature passes read of the connectivity alone, found once per
/// mesh and shared by its poses: each vertex's faces (faces_around's order,
/// with the vertex's corner) and, for the gradient operator, where each of
/// a face's corners adds to the vertex's weights.
struct CurvaturePlan {
    /// CSR: the faces around v are around[around_start[v] .. around_start[v+1]).
    std::vector<std::size_t> around_start;
    std::vector<FaceCorner> around;
    /// Per entry of around, per corner k of its face: the place of corner
    /// k's vertex among v's gradient weights (0 for v, 1 + i for its i-th
    /// neighbour), or kNoPlace when it is none of them.
    std::vector<std::array<std::int32_t, 3>> place;
    static constexpr std::int32_t kNoPlace = -1;
    /// CurvatureField::gradient_start and gradient_vertex, the same in every pose.
    std::vector<std::int32_t> gradient_start;
    std::vector<VertexId> gradient_vertex;
};

CurvaturePlan make_plan(const MeshTopology& topo) {
    CurvaturePlan plan;
    const std::size_t nv = topo.n_vertices();
    plan.around_start.assign(nv + 1, 0);
    plan.gradient_start.assign(nv + 1, 0);
    for (const VertexId v : topo.vertices()) {
        const auto i = v.index();
        for (const FaceCorner fc : topo.faces_around(v)) plan.around.push_back(fc);
        plan.around_start[i + 1] = plan.around.size();
        plan.gradient_start[i + 1] = plan.gradient_start[i] + 1 + topo.degree(v); // v itself, then its neighbours
    }
    plan.place.resize(plan.around.size());
    plan.gradient_vertex.resize(plan.gradient_start.back());
    parallel_for(topo.vertices(), [&](VertexId v) {
        const std::span<const VertexId> ring = topo.neighbours(v);
        const auto at = plan.gradient_vertex.begin() + plan.gradient_start[v.index()];
        *at = v;
        std::copy(ring.begin(), ring.end(), at + 1);
        for (std::size_t a = plan.around_start[v.index()]; a < plan.around_start[v.index() + 1]; ++a) {
            const auto& fv = topo.face_vertices()[plan.around[a].face];
            for (std::size_t k = 0; k < 3; ++k) {
                std::int32_t place = CurvaturePlan::kNoPlace;
                if (fv[k] == v) {
                    place = 0;
                } else if (const auto it = std::find(ring.begin(), ring.end(), fv[k]); it != ring.end()) {
                    place = std::int32_t(1 + (it - ring.begin()));
                }
                plan.place[a][k] = place;
            }
        }
    }, 4096);
    return plan;
}

/// The topology's plan, made on first use and kept with its connectivity.
std::shared_ptr<const CurvaturePlan> require_plan(const MeshTopology& topo) {
    return topo.connectivity()->quantities.require(Quantity<CurvaturePlan>{"curvature plan"}, [&] { return make_plan(topo); });
}

/// The passes that turn forms into vertex frames, over the vertices
/// [begin, end), built twice (below): for the baseline x86-64 and for AVX2.
/// The vertices or faces a pass runs over at a time.
constexpr std::size_t kBlock = 256;

/// The smoothing pass: each vertex's form becomes the mean of its own and
/// its neighbours' forms (each in its principal frame) weighted by area.
struct SmoothPass {
    const MeshTopology& topo;
    bool strips; ///< topo.has_strips(), asked once
    const CurvatureField& field;
    const VertexData<TangentFrame>& frames;
    const VertexData<glm::dvec3>& principal_normal;
    CurvatureField& out;

    // Vertex j's form, as lanes::project reads it.
    const glm::dvec3& t(std::size_t j) const { return field.dir1.data()[j]; }
    const glm::dvec3& b(std::size_t j) const { return field.dir2.data()[j]; }
    const glm::dvec3& n(std::size_t j) const { return principal_normal.data()[j]; }
    double ku(std::size_t j) const { return field.k1.data()[j]; }
    double kuv(std::size_t) const { return 0.0; }
    double kv(std::size_t j) const { return field.k2.data()[j]; }

    /// The vertices [begin, end), at most kBlock of them.
    template <std::size_t W> [[gnu::always_inline]] void run(std::size_t begin, std::size_t end) const {
        lanes::Pending pending[kBlock];
        std::size_t waiting = 0;
        for (std::size_t i = begin; i < end; ++i) {
            const VertexId v(i);
            if (!(field.area[v] > 0.0)) continue;
            const TangentFrame& frame = frames[v];
            lanes::FormSum<W, SmoothPass> sum(*this, frame);
            sum.add(i, field.area[v]);
            // Not across a split sharp edge: its strip joins two sides whose
            // curvatures have nothing to do with each other (a cylinder's
            // side and its flat cap).
            for (const auto [j, e] : topo.ring_of(v))
                if (field.area[j] > 0.0 && !(strips && edge_in_strip(topo, e))) sum.add(j.index(), field.area[j]);
            sum.finish();
            pending[waiting++] = {v, sum.ku / sum.total, sum.kuv / sum.total, sum.kv / sum.total};
        }
        lanes::principals<W>(pending, waiting, frames, topo.normals(), out);
    }
};

/// The pass over the faces: their forms (lanes::face_forms).
struct FormPass {
    const MeshTopology& topo;
    FaceData<FaceForm>& forms;
    template <std::size_t W> [[gnu::always_inline]] void run(std::size_t begin, std::size_t end) const {
        for (std::size_t f = begin; f < end; f += W) lanes::face_forms<W>(topo, f, std::min(W, end - f), forms.data() + f);
    }
};

/// The pass over the faces for the gradient operator (lanes::face_gradients).
struct GradientPass {
    const MeshTopology& topo;
    FaceData<FaceGradients>& faces;
    template <std::size_t W> [[gnu::always_inline]] void run(std::size_t begin, std::size_t end) const {
        for (std::size_t f = begin; f < end; f += W)
            lanes::face_gradients<W>(topo, f, std::min(W, end - f), faces.data() + f);
    }
};

/// The first pass over the vertices: each vertex's form is the mean of its faces' forms
/// weighted by the vertex's share of each face's area.
struct FacePass {
    const MeshTopology& topo;
    const CurvaturePlan& plan;
    const VertexData<TangentFrame>& frames;
    const FaceData<FaceForm>& forms;
    CurvatureField& out;

    // Face f's form, as lanes::project reads it.
    const glm::dvec3& t(std::size_t f) const { return forms.data()[f].t; }
    const glm::dvec3& b(std::size_t f) const { return forms.data()[f].b; }
    const glm::dvec3& n(std::size_t f) const { return forms.data()[f].n; }
    double ku(std::size_t f) const { return forms.data()[f].ku; }
    double kuv(std::size_t f) const { return forms.data()[f].kuv; }
    double kv(std::size_t f) const { return forms.data()[f].kv; }

    /// The vertices [begin, end), at most kBlock of them.
    template <std::size_t W> [[gnu::always_inline]] void run(std::size_t begin, std::size_t end) const {
        lanes::Pending pending[kBlock];
        std::size_t waiting = 0;
        for (std::size_t i = begin; i < end; ++i) {
            const VertexId v(i);
            const TangentFrame& frame = frames[v];
            lanes::FormSum<W, FacePass> sum(*this, frame);
            for (std::size_t a = plan.around_start[i]; a < plan.around_start[i + 1]; ++a) {
                const auto [face, corner] = plan.around[a];
                const double w = forms[face].corner[corner];
                if (w > 0.0) sum.add(face.index(), w);
            }
            sum.finish();
            out.area[v] = sum.total;
            if (!(sum.total > 0.0)) {
                out.dir1[v] = frame.u;
                out.dir2[v] = frame.v;
                continue;
            }
            pending[waiting++] = {v, sum.ku / sum.total, sum.kuv / sum.total, sum.kv / sum.total};
        }
        lanes::principals<W>(pending, waiting, frames, topo.normals(), out);
    }
};


/// Whether the passes take their AVX2 build.
std::atomic<bool> wide_lanes{simd::wide_lanes_available()};

/// Runs @p pass over [0, @p n) (vertices or faces), in blocks, in parallel.
template <class Pass> void run_blocks(std::size_t n, const Pass& pass) {
    const bool wide = wide_lanes.load(std::memory_order_relaxed);
    parallel_for((n + kBlock - 1) / kBlock, [&](std::size_t b) {
        const std::size_t begin = b * kBlock, end = std::min(n, begin + kBlock);
#if defined(__x86_64__)
        if (wide) return simd::run_pass_avx2(pass, begin, end);
#endif
        simd::run_pass(pass, begin, end);
    }, 4);
}

/// smoothed_curvatures with the pose's tangent frames given, without the
/// typical curvature (only the last pass's is read).
CurvatureField smoothed(const MeshTopology& topo, const CurvatureField& field, const VertexData<TangentFrame>& frames) {
    CurvatureField out = field;
    // Each vertex's principal frame as a form's frame, with its normal.
    VertexData<glm::dvec3> principal_normal(topo.n_vertices());
    parallel_for(topo.vertices(), [&](VertexId v) { principal_normal[v] = glm::cross(field.dir1[v], field.dir2[v]); }, 4096);
    run_blocks(topo.n_vertices(), SmoothPass{topo, topo.has_strips(), field, frames, principal_normal, out});
    return out;
}

/// vertex_curvatures with the plan and the pose's tangent frames given,
/// without the typical curvature.
CurvatureField unsmoothed(const MeshTopology& topo, const CurvaturePlan& plan, const VertexData<TangentFrame>& frames) {
    const std::size_t nv = topo.n_vertices(), nf = topo.n_faces();
    FaceData<FaceForm> forms(nf);
    run_blocks(nf, FormPass{topo, forms});

    CurvatureField out;
    out.k1.assign(nv, 0.0);
    out.k2.assign(nv, 0.0);
    out.dir1.assign(nv, glm::dvec3(0.0));
    out.dir2.assign(nv, glm::dvec3(0.0));
    out.area.assign(nv, 0.0);
    run_blocks(topo.n_vertices(), FacePass{topo, plan, frames, forms, out});
    return out;
}

/// add_gradient_operator with the plan given.
void gradient_operator(const MeshTopology& topo, const CurvaturePlan& plan, CurvatureField& field) {
    field.gradient_start = plan.gradient_start;
    field.gradient_vertex = plan.gradient_vertex;
    field.gradient_weight.assign(plan.gradient_vertex.size(), glm::dvec3(0.0));
    // Each face's corner gradients once (a face is around three vertices).
    FaceData<FaceGradients> faces(topo.n_faces());
    run_blocks(topo.n_faces(), GradientPass{topo, faces});
    parallel_for(topo.vertices(), [&](VertexId v) {
        const auto begin = field.gradient_weight.begin() + plan.gradient_start[v.index()];
        const auto end = field.gradient_weight.begin() + plan.gradient_start[v.index() + 1];
        double total = 0.0;
        for (std::size_t a = plan.around_start[v.index()]; a < plan.around_start[v.index() + 1]; ++a) {
            const FaceGradients& face = faces[plan.around[a].face];
            const auto& place = plan.place[a];
            for (std::size_t k = 0; k < 3; ++k)
                if (place[k] != CurvaturePlan::kNoPlace) begin[place[k]] += face.area * face.g[k];
            total += face.area;
        }
        if (total > 0.0)
            for (auto w = begin; w != end; ++w) *w /= total;
    }, 1024);
}

} // namespace

namespace detail {

bool allow_curvature_wide_lanes(bool allowed) { return wide_lanes.exchange(allowed && simd::wide_lanes_available()); }

bool curvature_wide_lanes_available() { return simd::wide_lanes_available(); }

} // namespace detail

CurvatureField smoothed_curvatures(const MeshTopology& topo, const CurvatureField& field) {
    CurvatureField out = smoothed(topo, field, vertex_frames(topo));
    out.typical = typical_curvature(out);
    return out;
}

CurvatureField vertex_curvatures(const MeshTopology& topo) {
    CurvatureField out = unsmoothed(topo, *require_plan(topo), vertex_frames(topo));
    out.typical = typical_curvature(out);
    return out;
}

void add_gradient_operator(const MeshTopology& topo, CurvatureField& field) {
    gradient_operator(topo, *require_plan(topo), field);
}

std::shared_ptr<const CurvatureField> require_curvature(const MeshTopology& topo, const CurvatureOptions& options) {
    const std::string key = "curvature smoothing=" + std::to_string(options.smoothing) +
                            " gradient=" + std::to_string(int(options.gradient));
    // Computed outside the store's lock: the computation runs parallel
    // loops, whose workers may be asked for the same pose's curvature.
    return topo.pose()->quantities.require(Quantity<CurvatureField>{key}, [&] {
        const std::shared_ptr<const CurvaturePlan> plan = require_plan(topo);
        const VertexData<TangentFrame> frames = vertex_frames(topo);
        CurvatureField field = unsmoothed(topo, *plan, frames);
        for (int pass = 0; pass < options.smoothing; ++pass) field = smoothed(topo, field, frames);
        field.typical = typical_curvature(field);
        if (options.gradient) gradient_operator(topo, *plan, field);
        return field;
    });
}

std::array<double, 3> detail::corner_areas(const std::array<glm::dvec3, 3>& e, double area) {
    const std::array<double, 3> l2{glm::dot(e[0], e[0]), glm::dot(e[1], e[1]), glm::dot(e[2], e[2])};
    // Barycentric weights of the circumcentre (times a common factor).
    const std::array<double, 3> bcw{l2[0] * (l2[1] + l2[2] - l2[0]), l2[1] * (l2[2] + l2[0] - l2[1]),
                                    l2[2] * (l2[0] + l2[1] - l2[2])};
    std::array<double, 3> c{};
    for (std::size_t a = 0; a < 3; ++a) {
        if (bcw[a] > 0.0) continue;
        // Obtuse at corner a: the circumcentre lies outside, past the edge opposite a.
        const std::size_t n = (a + 1) % 3, p = (a + 2) % 3;
        c[n] = -0.25 * l2[p] * area / glm::dot(e[a], e[p]);
        c[p] = -0.25 * l2[n] * area / glm::dot(e[a], e[n]);
        c[a] = area - c[n] - c[p];
        return c;
    }
    const double scale = 0.5 * area / (bcw[0] + bcw[1] + bcw[2]);
    for (std::size_t j = 0; j < 3; ++j) c[j] = scale * (bcw[(j + 1) % 3] + bcw[(j + 2) % 3]);
    return c;
}

} // namespace snaxels
