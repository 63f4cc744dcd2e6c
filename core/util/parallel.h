#pragma once
/// A minimal parallel loop over an index range on the machine's cores.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

namespace snaxels {

/// Calls fn(i) for every i in [0, n) on the hardware threads, which take
/// blocks of @p grain indices in turn (so a thread whose indices are cheap
/// takes more of them); runs inline when n is below @p grain.
template <class Fn> void parallel_for(std::size_t n, Fn&& fn, std::size_t grain = 512) {
    grain = std::max<std::size_t>(grain, 1);
    const std::size_t threads = std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), (n + grain - 1) / grain);
    if (threads <= 1) {
        for (std::size_t i = 0; i < n; ++i) fn(i);
        return;
    }
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t begin = next.fetch_add(grain); begin < n; begin = next.fetch_add(grain))
            for (std::size_t i = begin; i < std::min(n, begin + grain); ++i) fn(i);
    };
    std::vector<std::thread> pool;
    pool.reserve(threads - 1);
    for (std::size_t t = 1; t < threads; ++t) pool.emplace_back(work);
    work();
    for (auto& th : pool) th.join();
}

} // namespace snaxels
