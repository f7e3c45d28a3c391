// Core stage, internal: memory for pixel buffers, large ones on huge pages, and for buffers of
// which only a part is written.
//
// Small blocks come from calloc when zeroed, else from aligned_alloc on 64-byte boundaries, so
// that rows of whole SIMD vectors (a rasterizer's float rows, up to 64 bytes per vector) never
// straddle cache lines: 12 px glyphs render about 15 % slower when they do. Blocks of kHugeBlock
// bytes and more (a 724 x 724 RGBA image) are mapped directly, rounded up to whole 2 MiB pages,
// aligned to 2 MiB and marked MADV_HUGEPAGE on Linux, so that the kernel backs them with 2 MiB
// pages where it can: a 4096 x 2048 image then takes 16 page faults on first touch instead of
// 8,192, and is unmapped as fast. Faults are costly
// (on a virtual machine a 4 KiB fault can cost more than zeroing its page: about 0.55 against
// 0.25 ms per 2 MiB here); a last part of less than half a huge page stays on small pages, so a
// block commits at most a quarter more than it needs. Either way the memory reads as zero and is
// committed page by page on first touch. release() must get the size allocate() got.
//
// Released blocks are kept for reuse: mapping a 4096 x 2048 image afresh faults in 32 MiB of
// pages, which costs about five times as long as clearing the same memory already mapped (2.4-3.1
// against 0.45-0.6 ms here), and on two threads the faults of a new image made render_map 1.24x as
// fast as one thread where drawing into a kept image made it 1.7x. So release() keeps up to
// kMaxSpareBlocks blocks (kMaxSpareBytes in all) mapped, marked MADV_FREE: the kernel reclaims
// their pages only under memory pressure. An allocation of a block's mapped size takes it (cleared
// first when `zeroed`); one of another size, or of allocate_sparse(), unmaps the waiting blocks
// first, so that they never add to what the process holds at its peak. Rendering one map or tile
// after another reuses the same blocks.
//
// allocate_sparse() is for a buffer sized for the worst case of which usually a small part is
// written (a compressor's output): from kSparseBlock bytes it is mapped with small pages on Linux,
// so only what is written is committed, and it is not carved from the heap, whose pages the
// process's huge-page advice may commit 2 MiB at a time. release_sparse() must get its size.
// Thread-safety: both functions may be called from any thread.
#pragma once

#include <cstddef>

namespace casteljau::platform {

inline constexpr std::size_t kHugeBlock = std::size_t(2) << 20;
inline constexpr std::size_t kSparseBlock = std::size_t(256) << 10;
inline constexpr std::size_t kMaxSpareBlocks = 4;
inline constexpr std::size_t kMaxSpareBytes = std::size_t(256) << 20;

// `bytes` of memory reading as zero (`zeroed`), or of any content, aligned to 64 bytes; null when
// the memory is not available.
void* allocate(std::size_t bytes, bool zeroed) noexcept;
// As allocate(bytes, false), and says in `zero` whether the memory reads as zero: true for a new
// block, false for a released one taken again (its content is then whatever it held), which the
// caller clears where and when it likes (render_map: band by band on its workers). release() takes
// it as any other block.
void* allocate_uncleared(std::size_t bytes, bool& zero) noexcept;
void release(void* p, std::size_t bytes) noexcept;
// `bytes` of memory of any content, null when not available.
void* allocate_sparse(std::size_t bytes) noexcept;
void release_sparse(void* p, std::size_t bytes) noexcept;

}  // namespace casteljau::platform
