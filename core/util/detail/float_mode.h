#pragma once
/// The floating-point mode snaxels computes in: IEEE arithmetic, with
/// subnormal numbers kept (no flush-to-zero, no denormals-are-zero).
///
/// A thread's mode is a register that libraries change: Embree turns on
/// flush-to-zero and denormals-are-zero on the threads that build its BVH,
/// and oneTBB hands a mode captured from one thread to the tasks it runs on
/// others. Left alone, the same computation then gives another answer on
/// another thread (a vertex whose function value is the least negative
/// subnormal counts as 0, so on the other side of a contour, under
/// denormals-are-zero). Every parallel loop's body, and every stage of the
/// export's frame pipeline, runs under FloatModeGuard, so a result does not
/// depend on which thread made it, or after what.

#if defined(__SSE__) || defined(__x86_64__) || defined(_M_X64)
#include <xmmintrin.h>
#define SNAXELS_HAS_MXCSR 1
#endif

namespace snaxels {

/// Sets IEEE mode on this thread for its lifetime, then puts back what was.
class FloatModeGuard {
  public:
#ifdef SNAXELS_HAS_MXCSR
    FloatModeGuard() : saved_(_mm_getcsr()) {
        if (saved_ & kFlushBits) _mm_setcsr(saved_ & ~kFlushBits);
    }
    ~FloatModeGuard() {
        if (saved_ & kFlushBits) _mm_setcsr(saved_);
    }
#else
    FloatModeGuard() = default;
#endif
    FloatModeGuard(const FloatModeGuard&) = delete;
    FloatModeGuard& operator=(const FloatModeGuard&) = delete;

  private:
#ifdef SNAXELS_HAS_MXCSR
    static constexpr unsigned kFlushBits = 0x8040; ///< MXCSR's flush-to-zero (bit 15) and denormals-are-zero (bit 6)
    unsigned saved_;
#endif
};

} // namespace snaxels
