// Core stage, internal: memory for pixel buffers, large ones on huge pages.
//
// Small blocks come from calloc. Blocks of kHugeBlock bytes and more (a 724 x 724 RGBA image) are
// mapped directly, rounded up to whole 2 MiB pages, aligned to 2 MiB and marked MADV_HUGEPAGE on
// Linux, so that the kernel backs them with 2 MiB pages where it can: a 4096 x 2048 image then
// takes 16 page faults on first touch instead of 8,192, and is unmapped as fast. Faults are costly
// (on a virtual machine a 4 KiB fault can cost more than zeroing its page), and a block of at
// least one huge page wastes at most half of what it commits. Either way the memory reads as zero and
// is committed page by page on first touch. release() must get the size allocate() got.
// Thread-safety: both functions may be called from any thread.
#pragma once

#include <cstddef>

namespace casteljau::platform {

inline constexpr std::size_t kHugeBlock = std::size_t(2) << 20;

// `bytes` of memory reading as zero (`zeroed`), or of any content (large blocks are zero anyway);
// null when the memory is not available.
void* allocate(std::size_t bytes, bool zeroed) noexcept;
void release(void* p, std::size_t bytes) noexcept;

}  // namespace casteljau::platform
