#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "snaxels/error.h"
#include "snaxels/util/detail/parallel.h"

using namespace snaxels;

// Every index is visited once, in blocks or inline.
TEST(ParallelFor, VisitsEveryIndexOnce) {
    for (const std::size_t n : {0u, 1u, 7u, 512u, 513u, 100000u}) {
        std::vector<std::atomic<int>> seen(n);
        parallel_for(n, [&](std::size_t i) { seen[i].fetch_add(1); }, 64);
        for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i].load(), 1) << "n " << n << " index " << i;
    }
}

// An exception thrown by an iteration on a worker thread reaches the
// caller, type and message intact, and the process goes on.
TEST(ParallelFor, PropagatesAnExceptionToTheCaller) {
    for (int round = 0; round < 20; ++round) {
        try {
            parallel_for(100000, [](std::size_t i) {
                if (i == 77777) throw InternalError("broken at 77777");
            }, 16);
            FAIL() << "no exception reached the caller";
        } catch (const InternalError& e) {
            EXPECT_STREQ(e.what(), "broken at 77777");
        }
    }
    // Grain 1 over a few items: each on its own task (as the contour kinds are tracked).
    EXPECT_THROW(parallel_for(3, [](std::size_t i) { if (i == 2) throw std::runtime_error("third"); }, 1),
                 std::runtime_error);
}

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>

// Every block computes in IEEE mode, whatever the caller's thread was left
// in: a subnormal stays itself (neither read as zero nor flushed to zero),
// inline and on the pool's threads. (Embree leaves flush-to-zero and
// denormals-are-zero on threads; oneTBB carries a captured mode to others.)
TEST(ParallelFor, ComputesInIeeeModeWhateverTheCallerFlushes) {
    const unsigned saved = _mm_getcsr();
    _mm_setcsr(saved | 0x8040); // flush-to-zero and denormals-are-zero on this thread
    volatile double tiny = -4.9406564584124654e-324; // the least negative subnormal
    for (const std::size_t n : {8u, 100000u}) {
        std::vector<char> below_zero(n, 0), kept(n, 0);
        parallel_for(n, [&](std::size_t i) {
            const double x = tiny;
            below_zero[i] = x < 0.0;   // false when read as zero (denormals-are-zero)
            kept[i] = x * 2.0 != 0.0;  // a subnormal product: zero when flushed (flush-to-zero)
        }, 64);
        for (std::size_t i = 0; i < n; ++i) {
            ASSERT_TRUE(below_zero[i]) << "n " << n << " index " << i;
            ASSERT_TRUE(kept[i]) << "n " << n << " index " << i;
        }
    }
    const unsigned after = _mm_getcsr();
    _mm_setcsr(saved);
    EXPECT_EQ(after & 0x8040u, 0x8040u) << "the caller's own mode is put back";
}
#endif
