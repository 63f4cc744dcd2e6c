#pragma once
/// Vector lanes: a few doubles computed at once, each a lane of a vector
/// (GCC/Clang vector extensions), with the same operations in the same
/// order as the scalar formulas they stand for, so every lane's result is
/// the scalar one to the bit. A pass is built twice, two lanes for any
/// x86-64 and four for AVX2 (chosen at run time: run_pass and
/// run_pass_avx2); neither build fuses a product and a sum (AVX2 brings
/// no FMA), so both give the same bits. The curvature passes
/// (core/snaxel/curvature.cpp) are built on them.
///
/// The vectors are passed only between functions inlined into one build of
/// a pass, never across the ABI GCC and Clang warn about: the warning is
/// off from here to the end of the file that includes this.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <glm/vec3.hpp>

#if defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace snaxels::simd {

/// The most lanes any build uses (AVX2's four doubles).
constexpr std::size_t kMaxWidth = 4;

// (Spelled per width: GCC drops a vector attribute on an alias template.)
using Doubles2 = double __attribute__((vector_size(2 * sizeof(double))));
using Doubles4 = double __attribute__((vector_size(4 * sizeof(double))));
using Mask2 = std::int64_t __attribute__((vector_size(2 * sizeof(double))));
using Mask4 = std::int64_t __attribute__((vector_size(4 * sizeof(double))));
template <std::size_t W> struct Vectors;
template <> struct Vectors<2> {
    using Doubles = Doubles2;
    using Mask = Mask2;
};
template <> struct Vectors<4> {
    using Doubles = Doubles4;
    using Mask = Mask4;
};
template <std::size_t W> using Doubles = typename Vectors<W>::Doubles;
template <std::size_t W> using Mask = typename Vectors<W>::Mask;


template <std::size_t W> [[gnu::always_inline]] inline void store(double* p, Doubles<W> d) { std::memcpy(p, &d, sizeof d); }
/// The vector of value(lane) over the lanes (built in registers: lanes
/// written to memory one by one and read back as a vector would stall).
template <std::size_t W, class Value> [[gnu::always_inline]] inline Doubles<W> gather(Value&& value) {
    static_assert(W == 2 || W == 4);
    if constexpr (W == 2) return Doubles<W>{value(0), value(1)};
    else return Doubles<W>{value(0), value(1), value(2), value(3)};
}
/// @p x in every lane (exactly: adding it to zeros would turn -0 into +0).
template <std::size_t W> [[gnu::always_inline]] inline Doubles<W> splat(double x) {
    return gather<W>([x](std::size_t) { return x; });
}

/// @p a where @p m is set, else @p b.
template <std::size_t W> [[gnu::always_inline]] inline Doubles<W> select(Mask<W> m, Doubles<W> a, Doubles<W> b) {
    return Doubles<W>((Mask<W>(a) & m) | (Mask<W>(b) & ~m));
}
/// glm::dot's order: (x x' + y y') + z z'.
template <std::size_t W>
[[gnu::always_inline]] inline Doubles<W> dot(Doubles<W> ax, Doubles<W> ay, Doubles<W> az, Doubles<W> bx, Doubles<W> by,
                                             Doubles<W> bz) {
    return ax * bx + ay * by + az * bz;
}


/// |x| lane by lane (the sign bit cleared).
template <std::size_t W> [[gnu::always_inline]] inline Doubles<W> abs(Doubles<W> x) {
    return Doubles<W>(Mask<W>(x) & ~Mask<W>(splat<W>(-0.0)));
}
/// std::sqrt lane by lane (exact in every build).
template <std::size_t W> [[gnu::always_inline]] inline Doubles<W> sqrt(Doubles<W> x) {
    return gather<W>([&](std::size_t l) { return std::sqrt(x[l]); });
}


/// A vector of three coordinates, a point or direction per lane.
template <std::size_t W> struct Vec3 {
    Doubles<W> x, y, z;
    Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3 operator/(Doubles<W> d) const { return {x / d, y / d, z / d}; }
    glm::dvec3 lane(std::size_t l) const { return {x[l], y[l], z[l]}; }
};
/// glm::dot's order.
template <std::size_t W> [[gnu::always_inline]] inline Doubles<W> dot(const Vec3<W>& a, const Vec3<W>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
/// glm::cross's order.
template <std::size_t W> [[gnu::always_inline]] inline Vec3<W> cross(const Vec3<W>& a, const Vec3<W>& b) {
    return {a.y * b.z - b.y * a.z, a.z * b.x - b.z * a.x, a.x * b.y - b.x * a.y};
}
template <std::size_t W, class Point> [[gnu::always_inline]] inline Vec3<W> gather3(Point&& point) {
    return {gather<W>([&](std::size_t l) { return point(l).x; }), gather<W>([&](std::size_t l) { return point(l).y; }),
            gather<W>([&](std::size_t l) { return point(l).z; })};
}


// Each pass is built twice: two lanes for the baseline x86-64 (SSE2) and
// four for AVX2, chosen at run time by what the processor has. Neither
// build may fuse a product and a sum (AVX2 does not bring FMA), so both
// give the same bits.
template <class Pass> void run_pass(const Pass& pass, std::size_t begin, std::size_t end) {
    pass.template run<2>(begin, end);
}
#if defined(__x86_64__)
template <class Pass> __attribute__((target("avx2"))) void run_pass_avx2(const Pass& pass, std::size_t begin, std::size_t end) {
    pass.template run<4>(begin, end);
}
#endif

/// Whether this processor can run the four-lane (AVX2) builds.
inline bool wide_lanes_available() {
#if defined(__x86_64__)
    return __builtin_cpu_supports("avx2") != 0;
#else
    return false;
#endif
}

} // namespace snaxels::simd
