#pragma once
/// Parallel loops over an index range, and calls made at once, on oneTBB's
/// thread pool. An exception thrown by an iteration reaches the caller (the
/// first one; the rest of the loop is cancelled), as it would from a plain
/// loop. Every block and call runs in IEEE floating-point mode
/// (float_mode.h), whichever thread runs it.

#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include "snaxels/util/detail/float_mode.h"

namespace snaxels {

/// Calls fn(i) for every i in [0, n), in blocks of about @p grain indices
/// handed out to the pool's threads as they come free (so a thread whose
/// indices are cheap takes more of them); runs inline when n is below
/// @p grain.
template <class Fn> void parallel_for(std::size_t n, Fn&& fn, std::size_t grain = 512) {
    grain = std::max<std::size_t>(grain, 1);
    if (n <= grain) {
        const FloatModeGuard mode;
        for (std::size_t i = 0; i < n; ++i) fn(i);
        return;
    }
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain), [&](const tbb::blocked_range<std::size_t>& r) {
        const FloatModeGuard mode;
        for (std::size_t i = r.begin(); i < r.end(); ++i) fn(i);
    });
}

/// Calls fn(id) for every id of @p ids, a range of ids numbered from 0
/// (a mesh's vertices, edges, ...: ElementRange), as parallel_for above.
template <class Ids, class Fn>
    requires requires(const Ids& ids) {
        ids.size();
        typename Ids::Id;
    }
void parallel_for(const Ids& ids, Fn&& fn, std::size_t grain = 512) {
    parallel_for(ids.size(), [&](std::size_t i) { fn(typename Ids::Id(i)); }, grain);
}

/// Calls each of @p fns at once, on the pool's threads, each in IEEE
/// floating-point mode; returns when all have returned.
template <class... Fns> void parallel_invoke(Fns&&... fns) {
    tbb::parallel_invoke([&fns] {
        const FloatModeGuard mode;
        fns();
    }...);
}

} // namespace snaxels
