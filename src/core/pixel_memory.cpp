// Memory for pixel buffers (see pixel_memory.hpp).
#include "core/pixel_memory.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace casteljau::platform {

#if defined(__linux__)
namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
std::size_t mapped_size(std::size_t bytes) { return (bytes + kHugePage - 1) / kHugePage * kHugePage; }

// Released mapped blocks waiting for an allocation of their mapped size (see pixel_memory.hpp).
// A fixed array: release() must not allocate.
struct Spares {
    std::mutex mu;
    std::array<std::pair<void*, std::size_t>, kMaxSpareBlocks> blocks{};  // start and mapped size
    std::size_t count = 0, bytes = 0;
};

Spares& spares() {
    static Spares* s = new Spares;  // never destroyed: buffers may be released during static destruction
    return *s;
}

// Unmaps every waiting block.
void release_spares() {
    std::array<std::pair<void*, std::size_t>, kMaxSpareBlocks> out;
    std::size_t n = 0;
    {
        Spares& s = spares();
        std::lock_guard<std::mutex> lock(s.mu);
        out = s.blocks;
        n = s.count;
        s.count = 0;
        s.bytes = 0;
    }
    for (std::size_t i = 0; i < n; ++i) munmap(out[i].first, out[i].second);
}

// A waiting block of exactly `size` mapped bytes, or null. When none fits, the waiting blocks are
// unmapped, so that they never add to the memory a process holds at its peak.
void* take_spare(std::size_t size) {
    {
        Spares& s = spares();
        std::lock_guard<std::mutex> lock(s.mu);
        for (std::size_t i = s.count; i-- > 0;)  // the last released first: its pages are the likeliest cached
            if (s.blocks[i].second == size) {
                void* found = s.blocks[i].first;
                s.blocks[i] = s.blocks[--s.count];
                s.bytes -= size;
                return found;
            }
        if (s.count == 0) return nullptr;
    }
    release_spares();
    return nullptr;
}

// Keeps a released block of `size` mapped bytes as a spare when there is room; false when not.
bool keep_spare(void* p, std::size_t size) {
    Spares& s = spares();
    auto room = [&] { return s.count < kMaxSpareBlocks && s.bytes + size <= kMaxSpareBytes; };
    {
        std::lock_guard<std::mutex> lock(s.mu);
        if (!room()) return false;
    }
    // Lazily freed: the kernel takes the pages back only when it needs memory (they then read as
    // zero); until then they stay mapped, and writing them again costs no fault. Marked before the
    // block is listed, where another thread may take it and write it.
    (void)madvise(p, size, MADV_FREE);
    std::lock_guard<std::mutex> lock(s.mu);
    if (!room()) return false;
    s.blocks[s.count++] = {p, size};
    s.bytes += size;
    return true;
}

// A block of kHugeBlock bytes or more: a waiting spare (`reused`: of any content) or a new
// mapping (reading as zero); null when the memory is not available.
void* huge_block(std::size_t bytes, bool& reused) noexcept {
    const std::size_t size = mapped_size(bytes);
    reused = false;
    if (void* spare = take_spare(size)) {
        reused = true;
        return spare;
    }
    // Map one huge page more than needed, then unmap the parts before the first 2 MiB boundary
    // and after the block, so that the block starts on a huge page.
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
}  // namespace
#endif

void* allocate(std::size_t bytes, bool zeroed) noexcept {
#if defined(__linux__)
    if (bytes >= kHugeBlock) {
        bool reused = false;
        void* p = huge_block(bytes, reused);
        if (p && reused && zeroed) std::memset(p, 0, bytes);
        return p;
    }
#endif
    if (zeroed) return std::calloc(bytes == 0 ? 1 : bytes, 1);
    constexpr std::size_t kAlign = 64;
    return std::aligned_alloc(kAlign, (std::max<std::size_t>(bytes, 1) + kAlign - 1) / kAlign * kAlign);
}

void* allocate_uncleared(std::size_t bytes, bool& zero) noexcept {
#if defined(__linux__)
    if (bytes >= kHugeBlock) {
        bool reused = false;
        void* p = huge_block(bytes, reused);
        zero = !reused;
        return p;
    }
#endif
    zero = true;
    return allocate(bytes, true);
}

void* allocate_sparse(std::size_t bytes) noexcept {
#if defined(__linux__)
    if (bytes >= kSparseBlock) {
        release_spares();
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
        if (!keep_spare(p, mapped_size(bytes))) munmap(p, mapped_size(bytes));
        return;
    }
#endif
    std::free(p);
}

}  // namespace casteljau::platform
