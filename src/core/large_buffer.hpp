// Core stage, internal: std::vector for large dense buffers (a rasterizer's accumulators, a
// compositor's layer), whose memory comes from platform::allocate (pixel_memory.hpp): blocks of
// kHugeBlock bytes and more are mapped on 2 MiB pages where the kernel allows, so that zeroing a
// fresh buffer takes a page fault per 2 MiB instead of one per 4 KiB.
// Thread-safety: as std::vector.
#pragma once

#include <cstddef>
#include <limits>
#include <new>
#include <vector>

#include "core/pixel_memory.hpp"

namespace casteljau::platform {

template <class T>
struct LargeBufferAllocator {
    using value_type = T;

    LargeBufferAllocator() = default;
    template <class U>
    LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}

    T* allocate(std::size_t n) {
        if (n > std::numeric_limits<std::size_t>::max() / sizeof(T)) throw std::bad_array_new_length();
        void* p = platform::allocate(n * sizeof(T), false);
        if (!p) throw std::bad_alloc();
        return static_cast<T*>(p);
    }
    void deallocate(T* p, std::size_t n) noexcept { platform::release(p, n * sizeof(T)); }

    friend bool operator==(const LargeBufferAllocator&, const LargeBufferAllocator&) noexcept { return true; }
};

template <class T>
using LargeVector = std::vector<T, LargeBufferAllocator<T>>;

}  // namespace casteljau::platform
