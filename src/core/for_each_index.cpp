// Core stage: the process-wide pool behind for_each_index (see for_each_index.hpp).
//
// Pool threads wait for jobs on one queue. A job stays queued while it has worker ids and indices
// left; a pool thread that takes it claims an id, counts itself in the job's `active` (under the
// pool's lock, so a caller that has dequeued its job sees every helper that joined) and runs
// indices until none are left. The caller runs its own job too, then dequeues it and waits for
// `active` to drop to zero before the job (on its stack) goes away.
#include "core/for_each_index.hpp"

#include <unistd.h>

#include <deque>
#include <new>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "casteljau/error.hpp"

namespace casteljau::parallel {

namespace {

class Pool {
public:
    ~Pool() { stop_threads(); }

    int size() {
        const std::lock_guard<std::mutex> lock(mu_);
        return size_;
    }

    void resize(int n) {
        stop_threads();
        const std::lock_guard<std::mutex> lock(mu_);
        size_ = n;
    }

    // Queues `job` for helpers; false when there are none (a pool of one, a forked child, or no
    // thread could be started).
    bool offer(Job& job) {
        {
            std::unique_lock<std::mutex> lock(mu_);
            if (threads_.empty() && size_ > 1 && !started_) start(lock);
            if (threads_.empty() || owner_ != getpid()) return false;
            queue_.push_back(&job);
        }
        wake_.notify_all();
        return true;
    }

    void withdraw(Job& job) {
        const std::lock_guard<std::mutex> lock(mu_);
        for (auto it = queue_.begin(); it != queue_.end(); ++it)
            if (*it == &job) {
                queue_.erase(it);
                break;
            }
    }

private:
    std::mutex mu_;
    std::condition_variable wake_;
    std::deque<Job*> queue_;
    std::vector<std::thread> threads_;
    int size_ = hardware_threads();
    bool stop_ = false;
    bool started_ = false;  // start() ran for this size (it may have started fewer threads)
    pid_t owner_ = 0;

    void start(std::unique_lock<std::mutex>&) {
        started_ = true;
        owner_ = getpid();
        try {
            for (int i = 1; i < size_; ++i) threads_.emplace_back([this] { serve(); });
        } catch (const std::system_error&) {
            // Resource limits: the threads started so far serve; callers always work too.
        }
    }

    void stop_threads() {
        std::vector<std::thread> old;
        {
            const std::lock_guard<std::mutex> lock(mu_);
            stop_ = true;
            old.swap(threads_);
        }
        wake_.notify_all();
        // In a forked child the threads do not exist: leave the handles unjoined and unreleased.
        if (owner_ != 0 && owner_ != getpid()) {
            for (std::thread& t : old) new (&t) std::thread();  // forget the parent's handles
        } else {
            for (std::thread& t : old) t.join();
        }
        const std::lock_guard<std::mutex> lock(mu_);
        stop_ = false;
        started_ = false;
    }

    void serve() {
        std::unique_lock<std::mutex> lock(mu_);
        while (true) {
            wake_.wait(lock, [&] { return stop_ || !queue_.empty(); });
            if (stop_) return;
            Job* job = queue_.front();
            const int id = job->slots.fetch_add(1);
            if (id >= job->workers || job->next.load() >= job->n) {
                queue_.pop_front();  // full or finished: nothing for helpers
                continue;
            }
            if (id + 1 >= job->workers) queue_.pop_front();
            job->active.fetch_add(1);
            lock.unlock();
            job->run(id);
            {
                const std::lock_guard<std::mutex> jl(job->mu);
                if (job->active.fetch_sub(1) == 1) job->left.notify_all();
            }
            lock.lock();
        }
    }
};

Pool& pool() {
    static Pool p;
    return p;
}

}  // namespace

int hardware_threads() { return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 256u)); }

int thread_count() { return pool().size(); }

void set_thread_count(int n) {
    if (n < 0 || n > 256)
        throw Error(ErrorKind::InvalidArgument, "thread count must be 0 (all cores) to 256, got " + std::to_string(n));
    pool().resize(n == 0 ? hardware_threads() : n);
}

void run_job(Job& job) {
    Pool& p = pool();
    const bool shared = p.offer(job);
    job.run(0);
    if (shared) {
        p.withdraw(job);
        std::unique_lock<std::mutex> lock(job.mu);
        job.left.wait(lock, [&] { return job.active.load() == 0; });
    }
    if (job.error) std::rethrow_exception(job.error);
}

}  // namespace casteljau::parallel
