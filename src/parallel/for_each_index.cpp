// Parallel stage: the hardware thread count shared by every caller of for_each_index.
#include "parallel/for_each_index.hpp"

namespace casteljau::parallel {

int hardware_threads() { return static_cast<int>(std::clamp(std::thread::hardware_concurrency(), 1u, 256u)); }

}  // namespace casteljau::parallel
