// Work done on several threads, results taken in order (`sphdeck check --jobs N`): the report reads
// as if the decks had been checked one after the other, whatever order they finish in.
#pragma once

#include <algorithm>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace sphdeck::cli {

// Runs make(i) for every i in [0, n) on `jobs` threads and hands each result to take(i, result) on
// the calling thread, in the order of i. A thread starts item i only while fewer than 2 * jobs
// items wait to be taken, so the results held at once stay bounded (a checked deck of a million
// particles holds hundreds of MB). make() must not throw; with one job it all runs on this thread.
template <typename Result>
void run_in_order(std::size_t n, unsigned jobs, const std::function<Result(std::size_t)>& make,
                  const std::function<void(std::size_t, Result&)>& take) {
    jobs = static_cast<unsigned>(std::min<std::size_t>(std::max(jobs, 1u), std::max<std::size_t>(n, 1)));
    if (jobs == 1) {
        for (std::size_t i = 0; i < n; ++i) {
            Result r = make(i);
            take(i, r);
        }
        return;
    }
    std::mutex mutex;
    std::condition_variable changed;
    std::vector<std::optional<Result>> done(n);
    std::size_t next = 0, taken = 0;
    const std::size_t window = 2 * static_cast<std::size_t>(jobs);
    auto work = [&] {
        for (;;) {
            std::size_t i;
            {
                std::unique_lock lock(mutex);
                changed.wait(lock, [&] { return next >= n || next < taken + window; });
                if (next >= n) return;
                i = next++;
            }
            Result r = make(i);
            std::lock_guard lock(mutex);
            done[i] = std::move(r);
            changed.notify_all();
        }
    };
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < jobs; ++t) threads.emplace_back(work);
    for (std::size_t i = 0; i < n; ++i) {
        Result r;
        {
            std::unique_lock lock(mutex);
            changed.wait(lock, [&] { return done[i].has_value(); });
            r = std::move(*done[i]);
            done[i].reset();
        }
        take(i, r);
        std::lock_guard lock(mutex);
        ++taken;
        changed.notify_all();
    }
    for (std::thread& t : threads) t.join();
}

}  // namespace sphdeck::cli
