// Memory for pixel buffers (see pixel_memory.hpp).
#include "core/pixel_memory.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace casteljau::platform {

#if defined(__linux__)
namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
std::size_t mapped_size(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }
}  // namespace
#endif

void* allocate(std::size_t bytes, bool zeroed) noexcept {
#if defined(__linux__)
    if (bytes >= kHugeBlock) {
        // Map one huge page more than needed, then unmap the parts before the first 2 MiB
        // boundary and after the block, so that the block starts on a huge page.
        const std::size_t size = mapped_size(bytes);
        void* raw = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        if (raw == MAP_FAILED) return nullptr;
        const auto start = reinterpret_cast<std::uintptr_t>(raw);
        const std::uintptr_t aligned = (start + kHugePage - 1) / kHugePage * kHugePage;
        if (aligned > start) munmap(raw, aligned - start);
        const std::size_t tail = (start + size + kHugePage) - (aligned + size);
        if (tail > 0) munmap(reinterpret_cast<void*>(aligned + size), tail);
        void* p = reinterpret_cast<void*>(aligned);
        // A hint: without huge pages the block still works. A last part of less than half a huge
        // page is left to small pages, whose faults cost less than zeroing the whole huge page.
        const std::size_t tail_bytes = bytes % kHugePage;
        (void)madvise(p, tail_bytes && tail_bytes < kHugePage / 2 ? size - kHugePage : size, MADV_HUGEPAGE);
        return p;
    }
#endif
    if (zeroed) return std::calloc(bytes == 0 ? 1 : bytes, 1);
    constexpr std::size_t kAlign = 64;
    return std::aligned_alloc(kAlign, (std::max<std::size_t>(bytes, 1) + kAlign - 1) / kAlign * kAlign);
}

void* allocate_sparse(std::size_t bytes) noexcept {
#if defined(__linux__)
    if (bytes >= kSparseBlock) {
        void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        return p == MAP_FAILED ? nullptr : p;
    }
#endif
    return std::malloc(bytes == 0 ? 1 : bytes);
}

void release_sparse(void* p, std::size_t bytes) noexcept {
    if (!p) return;
#if defined(__linux__)
    if (bytes >= kSparseBlock) {
        munmap(p, bytes);
        return;
    }
#endif
    std::free(p);
}

void release(void* p, std::size_t bytes) noexcept {
    if (!p) return;
#if defined(__linux__)
    if (bytes >= kHugeBlock) {
        munmap(p, mapped_size(bytes));
        return;
    }
#endif
    std::free(p);
}

}  // namespace casteljau::platform
