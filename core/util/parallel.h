#pragma once
/// A minimal parallel loop over an index range on the machine's cores.

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace snaxels {

/// Calls fn(i) for every i in [0, n), split into contiguous chunks over the
/// hardware threads; runs inline when n is below @p grain.
template <class Fn> void parallel_for(std::size_t n, Fn&& fn, std::size_t grain = 512) {
    const std::size_t threads =
        std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), (n + grain - 1) / std::max<std::size_t>(grain, 1));
    if (threads <= 1) {
        for (std::size_t i = 0; i < n; ++i) fn(i);
        return;
    }
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    const std::size_t chunk = (n + threads - 1) / threads;
    for (std::size_t t = 1; t < threads; ++t)
        pool.emplace_back([&, t] {
            for (std::size_t i = t * chunk; i < std::min(n, (t + 1) * chunk); ++i) fn(i);
        });
    for (std::size_t i = 0; i < std::min(n, chunk); ++i) fn(i);
    for (auto& th : pool) th.join();
}

} // namespace snaxels
