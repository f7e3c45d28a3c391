// Core stage (below every other): the one way casteljau fans work out over threads.
//
// for_each_index(workers, n, task) calls task(worker, i) once for every i in [0, n), on up to
// `workers` threads at once; worker ids are in [0, workers) and each is used by one thread at a
// time (worker 0 is the calling thread). Indices are handed out one at a time in increasing order,
// so uneven tasks balance themselves; results must not depend on which worker ran an index
// (callers keep per-index outputs, or per-worker scratch only).
//
// The helpers come from one process-wide pool (thread_count() threads in all, the caller
// included; casteljau/threads.hpp): concurrent calls share it, and a call made from inside a task
// (nested) is served the same way. The calling thread always works on its own call, so a call
// completes even when every pool thread is busy elsewhere. Pool threads are started on first use
// and sleep between calls. In a child process after fork() the pool is not used (the caller runs
// every index).
//
// The first exception a task throws is rethrown in the caller after every helper has left the
// call; no index is started after it (tasks already running finish). Thread-safe.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
#include <memory>
#include <mutex>
#include <type_traits>

namespace casteljau::parallel {

// The hardware threads (std::thread::hardware_concurrency), at least 1 and at most 256.
int hardware_threads();

// The pool's size: threads that may run casteljau work at once, callers included (1..256).
int thread_count();
// Resizes the pool (0: hardware_threads()). Waits for the current pool threads to finish the
// calls they are helping with. Throws Error(InvalidArgument) outside 0..256.
void set_thread_count(int n);

// One call's shared state; helpers join it through the pool.
struct Job {
    std::size_t n = 0;
    int workers = 1;
    std::atomic<std::size_t> next{0};
    std::atomic<int> slots{1};   // worker ids handed out (0 is the caller's)
    std::atomic<int> active{0};  // helpers inside run()
    void (*call)(void* task, int worker, std::size_t i) = nullptr;
    void* task = nullptr;
    std::mutex mu;
    std::condition_variable left;  // signalled when the last helper leaves
    std::exception_ptr error;

    // Runs indices as `worker` until none are left or a task failed.
    void run(int worker) noexcept {
        try {
            for (std::size_t i; (i = next.fetch_add(1)) < n;) call(task, worker, i);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(mu);
            if (!error) error = std::current_exception();
            next.store(n);
        }
    }
};

// Offers `job` to idle pool threads (at most job.workers - 1 join), runs it as worker 0 on the
// calling thread, waits until every helper has left, and rethrows the first error.
void run_job(Job& job);

template <class Task>
void for_each_index(int workers, std::size_t n, Task&& task) {
    workers = static_cast<int>(std::min<std::size_t>(static_cast<std::size_t>(std::max(workers, 1)), n));
    if (workers <= 1) {
        for (std::size_t i = 0; i < n; ++i) task(0, i);
        return;
    }
    Job job;
    job.n = n;
    job.workers = workers;
    job.task = const_cast<void*>(static_cast<const void*>(std::addressof(task)));
    job.call = [](void* t, int w, std::size_t i) { (*static_cast<std::remove_reference_t<Task>*>(t))(w, i); };
    run_job(job);
}

}  // namespace casteljau::parallel
