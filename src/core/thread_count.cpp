// Core stage: the public size of the process-wide pool (include/casteljau/threads.hpp).
#include "casteljau/threads.hpp"

#include "core/for_each_index.hpp"

namespace casteljau {

void set_thread_count(int threads) { parallel::set_thread_count(threads); }

int thread_count() { return parallel::thread_count(); }

}  // namespace casteljau
