// C API: the size of the process-wide thread pool (casteljau.h, casteljau_set_thread_count).
#include "capi/handles.hpp"
#include "casteljau/threads.hpp"

extern "C" {

casteljau_status casteljau_set_thread_count(int threads) {
    return casteljau::capi::guard([&] { casteljau::set_thread_count(threads); });
}

int casteljau_thread_count(void) { return casteljau::thread_count(); }

}  // extern "C"
