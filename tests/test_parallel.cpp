// parallel::for_each_index (src/parallel/): every index runs exactly once whatever the number of
// workers, worker ids stay in range, and the first exception reaches the caller after all joined.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "parallel/for_each_index.hpp"

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
