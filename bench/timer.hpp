// bench/timer.hpp: the clock the side-by-side programs time with.
//
// The benchmark machine is shared (2 cores, often 5-10 runnable processes): wall-clock time there
// mostly measures how long the scheduler left us waiting. The CPU time of the calling thread
// (CLOCK_THREAD_CPUTIME_ID) counts only the time the thread actually ran, so it is what we report;
// neighbours still disturb caches, which is why every figure is also a best of several rounds.
#pragma once

#include <time.h>

namespace bench {

inline double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

}  // namespace bench
