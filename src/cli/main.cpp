// casteljau: command-line tool. A thin shell over the library (see run.cpp).
#include <csignal>
#include <cstdint>
#include <cstdlib>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#if defined(__linux__)
#include <sys/mman.h>
#endif
#include <iostream>

#include "cli/run.hpp"

// Whether AddressSanitizer replaces the allocator (GCC and clang spell it differently).
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CASTELJAU_CLI_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define CASTELJAU_CLI_ASAN 1
#endif

namespace {

// Grows the heap by 120 MB at once, marks it for transparent huge pages and hands it back to
// malloc, which keeps it (the trim threshold in main): the allocations that later fill it take a
// page fault per 2 MB instead of one per 4 KB, which on a virtual machine is a third of a small
// map's drawing time. Nothing is committed until it is touched. Two blocks of 60 MB, each under
// the mmap threshold set in main, so that both come from the heap. Not under AddressSanitizer,
// whose allocator replaces glibc's: there it would only poison 120 MB of shadow memory.
void advise_huge_page_heap() {
#if defined(__GLIBC__) && defined(__linux__) && !defined(CASTELJAU_CLI_ASAN)
    constexpr std::size_t kBlock = std::size_t(60) << 20, kHuge = std::size_t(2) << 20;
    void* blocks[2] = {std::malloc(kBlock), std::malloc(kBlock)};
    for (void* p : blocks) {
        if (!p) continue;
        const auto start = reinterpret_cast<std::uintptr_t>(p);
        const std::uintptr_t lo = (start + kHuge - 1) / kHuge * kHuge, hi = (start + kBlock) / kHuge * kHuge;
        if (hi > lo) (void)madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
    }
    for (void* p : blocks) std::free(p);
#endif
}

}  // namespace

int main(int argc, char** argv) {
    // Past a file-size limit (ulimit -f) the kernel sends SIGXFSZ, whose default action kills the
    // process without a word and leaves the temporary file behind; ignored, the write fails with
    // EFBIG and the writer reports it and removes its temporary file.
    std::signal(SIGXFSZ, SIG_IGN);
#ifdef __GLIBC__
    // The process lives for one job: memory it frees is kept for its next allocations instead of
    // being unmapped and mapped again, which costs a page fault per 4 KB touched (a small map's
    // drawing spends a fifth of its time there). Blocks of 64 MB and more still get their own
    // mapping, so freeing them returns them at once.
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
#endif
    advise_huge_page_heap();
    return casteljau::cli::run(argc, argv, true, std::cout, std::cerr);
}
