// parallel::for_each_index (src/core/): every index runs exactly once whatever the number of
// workers, worker ids stay in range, the first exception reaches the caller after all helpers
// left; the helpers come from one process-wide pool of the size the caller sets
// (casteljau/threads.hpp), shared by concurrent and nested calls, and unused after fork().
#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/threads.hpp"
#include "core/for_each_index.hpp"

using casteljau::parallel::for_each_index;

TEST_CASE("parallel: every index runs once on 1 to 9 workers, with worker ids in range", "[parallel]") {
    for (int workers = 0; workers <= 9; ++workers)
        for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{3}, std::size_t{1000}}) {
            std::vector<std::atomic<int>> seen(n);
            std::atomic<int> bad_worker{0};
            for_each_index(workers, n, [&](int w, std::size_t i) {
                if (w < 0 || w >= std::max(workers, 1)) bad_worker.fetch_add(1);
                seen[i].fetch_add(1);
            });
            INFO(workers << " workers, " << n << " indices");
            CHECK(bad_worker.load() == 0);
            int wrong = 0;
            for (auto& s : seen) wrong += s.load() != 1;
            CHECK(wrong == 0);
        }
}

TEST_CASE("parallel: the first exception is rethrown in the caller after every worker joined", "[parallel]") {
    for (int workers : {1, 2, 4}) {
        std::atomic<int> ran{0};
        CHECK_THROWS_WITH(for_each_index(workers, 100000,
                                         [&](int, std::size_t i) {
                                             ran.fetch_add(1);
                                             if (i == 10) throw std::runtime_error("index 10 failed");
                                         }),
                          "index 10 failed");
        // Every worker has joined: nothing runs after the call returned.
        const int at_return = ran.load();
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        CHECK(ran.load() == at_return);
        // One worker takes the indices in order and stops at the failing one. (With more, how many
        // other indices start before the failure is seen depends on the scheduler.)
        if (workers == 1) CHECK(at_return == 11);
    }
}

namespace {

// Sets the pool's size for one test and restores the default.
struct PoolSize {
    explicit PoolSize(int n) { casteljau::set_thread_count(n); }
    ~PoolSize() { casteljau::set_thread_count(0); }
};

// The threads that ran the tasks of one for_each_index call (slow tasks, so helpers get a chance).
std::set<std::thread::id> threads_of_call(int workers, std::size_t n) {
    std::mutex mu;
    std::set<std::thread::id> ids;
    for_each_index(workers, n, [&](int, std::size_t) {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        const std::lock_guard<std::mutex> lock(mu);
        ids.insert(std::this_thread::get_id());
    });
    return ids;
}

}  // namespace

TEST_CASE("parallel: the pool's size is the caller's, and bad sizes are refused", "[parallel]") {
    CHECK(casteljau::thread_count() == casteljau::parallel::hardware_threads());
    CHECK_THROWS_AS(casteljau::set_thread_count(-1), casteljau::Error);
    CHECK_THROWS_AS(casteljau::set_thread_count(257), casteljau::Error);
    {
        PoolSize pool(3);
        CHECK(casteljau::thread_count() == 3);
        // A call asking for 8 workers runs on at most the pool's 3 threads, ids still below 8.
        const auto ids = threads_of_call(8, 60);
        CHECK(ids.size() <= 3);
        CHECK(ids.count(std::this_thread::get_id()) == 1);
    }
    {
        PoolSize pool(1);  // everything on the calling thread
        const auto ids = threads_of_call(4, 20);
        CHECK(ids == std::set<std::thread::id>{std::this_thread::get_id()});
    }
    CHECK(casteljau::thread_count() == casteljau::parallel::hardware_threads());
}

TEST_CASE("parallel: successive calls reuse the pool's threads instead of starting new ones", "[parallel]") {
    PoolSize pool(3);
    // Each thread counts the calls it helped with in a thread_local: a thread started per call
    // would never count past one (thread ids, unlike thread_locals, may be recycled).
    static thread_local int last_call = -1, helped = 0;
    std::atomic<int> most{0};
    const std::thread::id caller = std::this_thread::get_id();
    for (int call = 0; call < 6; ++call)
        for_each_index(3, 40, [&](int, std::size_t) {
            std::this_thread::sleep_for(std::chrono::microseconds(200));
            if (std::this_thread::get_id() == caller || last_call == call) return;
            last_call = call;
            ++helped;
            int m = most.load();
            while (helped > m && !most.compare_exchange_weak(m, helped)) {}
        });
    CHECK(most.load() >= 2);
}

TEST_CASE("parallel: nested and concurrent calls share the pool and all complete", "[parallel]") {
    PoolSize pool(2);
    std::atomic<int> ran{0};
    std::mutex mu;
    std::set<std::thread::id> ids;
    auto outer = [&] {
        for_each_index(4, 8, [&](int, std::size_t) {
            for_each_index(4, 50, [&](int w, std::size_t) {
                if (w < 0 || w >= 4) ran.fetch_add(1 << 20);
                ran.fetch_add(1);
                const std::lock_guard<std::mutex> lock(mu);
                ids.insert(std::this_thread::get_id());
            });
        });
    };
    std::vector<std::thread> callers;
    for (int c = 0; c < 4; ++c) callers.emplace_back(outer);
    for (std::thread& t : callers) t.join();
    CHECK(ran.load() == 4 * 8 * 50);
    CHECK(ids.size() <= 4 + 1);  // the four callers and the pool's one helper
}

TEST_CASE("parallel: after fork() the child runs every index on its calling thread", "[parallel]") {
    PoolSize pool(3);
    threads_of_call(3, 30);  // the pool's threads exist in the parent
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
        const auto ids = threads_of_call(3, 30);
        _exit(ids == std::set<std::thread::id>{std::this_thread::get_id()} ? 0 : 1);
    }
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 0);
}
