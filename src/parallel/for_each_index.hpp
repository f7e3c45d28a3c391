// Parallel stage (below every other): the one way casteljau fans work out over threads.
//
// for_each_index(workers, n, task) calls task(worker, i) once for every i in [0, n), on up to
// `workers` threads; worker 0 is the calling thread and the others are started for the call and
// joined before it returns (no pool outlives a call, so nothing is left running when a library
// call returns and no thread is shared between callers). Indices are handed out one at a time in
// increasing order, so uneven tasks balance themselves; results must not depend on which worker
// ran an index (callers keep per-index outputs, or per-worker scratch only).
//
// The first exception a task throws is rethrown in the caller after every worker has joined; no
// index is started after it (tasks already running finish). Thread-safe: each call is independent.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace casteljau::parallel {

// The hardware threads (std::thread::hardware_concurrency), at least 1 and at most 256.
int hardware_threads();

template <class Task>
void for_each_index(int workers, std::size_t n, Task&& task) {
    workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(workers, 1)), n));
    if (workers <= 1) {
        for (std::size_t i = 0; i < n; ++i) task(0, i);
        return;
    }
    std::atomic<std::size_t> next{0};
    std::mutex mu;
    std::exception_ptr error;
    auto loop = [&](int w) {
        try {
            for (std::size_t i; (i = next.fetch_add(1)) < n;) task(w, i);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(mu);
            if (!error) error = std::current_exception();
            next.store(n);
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(static_cast<std::size_t>(workers - 1));
    try {
        for (int w = 1; w < workers; ++w) threads.emplace_back(loop, w);
    } catch (...) {
        // No thread could be started (resource limits): the ones running and this one do the work.
    }
    loop(0);
    for (std::thread& t : threads) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace casteljau::parallel
