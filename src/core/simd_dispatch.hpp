// SIMD dispatch: picks the Highway target (instruction set) the raster and paint kernels run
// with, without Highway's runtime library.
//
// Highway's per-target code generation (foreach_target.h) and its dispatch tables are header-only;
// only the CPU detection lives in libhwy.so, and loading that library runs a static initializer that
// measures the timer resolution, which costs several milliseconds of every process's start-up
// (most of the time of a small `casteljau text` run). casteljau detects the CPU itself (CPUID and
// XGETBV, the same feature groups Highway requires for each target) and keeps the chosen target in
// a hwy::ChosenTarget of its own, so the library does not link libhwy at all.
//
// Use CASTELJAU_SIMD_EXPORT(Func) where Highway's HWY_EXPORT would go and
// CASTELJAU_SIMD_DISPATCH(Func)(args) for HWY_DYNAMIC_DISPATCH(Func)(args).
// Thread-safety: the target is chosen once, on first use (a function-local static); restrict_targets
// is for tests and benchmarks and must not run while other threads rasterize.
#pragma once

#include <hwy/highway.h>

#include <cstdint>
#include <vector>

namespace casteljau::simd {

// Highway target bits (HWY_SSSE3, HWY_SSE4, HWY_AVX2, HWY_AVX3, ...) this CPU and operating system
// can run, plus the portable fallback.
std::int64_t cpu_targets();
// The chosen target, initialized from cpu_targets() on first use.
const hwy::ChosenTarget& chosen();
// Limits the choice to the targets in `mask` that the CPU runs (0: every target it runs).
void restrict_targets(std::int64_t mask);
// Every target this build compiled that the CPU runs, best first (for tests that compare them).
std::vector<std::int64_t> available_targets();
// A short name for one target bit ("AVX3", "AVX2", "SSE4", "SSSE3", "SCALAR", ...).
const char* target_name(std::int64_t target);

}  // namespace casteljau::simd

// The dispatch table of a function compiled for every target: entry 0 (Highway's lazy initializer)
// is never used, because chosen() is initialized before any index is read.
#if (HWY_TARGETS & (HWY_TARGETS - 1)) == 0
#define CASTELJAU_SIMD_EXPORT(FUNC) HWY_EXPORT(FUNC)
#define CASTELJAU_SIMD_DISPATCH(FUNC) HWY_STATIC_DISPATCH(FUNC)
#else
#define CASTELJAU_SIMD_EXPORT(FUNC)                                                                             \
    static decltype(&HWY_STATIC_DISPATCH(FUNC)) const HWY_DISPATCH_TABLE(FUNC)[HWY_MAX_DYNAMIC_TARGETS + 2] = { \
        nullptr, HWY_CHOOSE_TARGET_LIST(FUNC), HWY_CHOOSE_FALLBACK(FUNC)}
#define CASTELJAU_SIMD_DISPATCH(FUNC) (*(HWY_DISPATCH_TABLE(FUNC)[::casteljau::simd::chosen().GetIndex()]))
#endif
