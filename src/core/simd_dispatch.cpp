// SIMD dispatch: CPU detection and the chosen Highway target (simd_dispatch.hpp).
//
// Each target needs a group of CPU features, as Highway defines them, and the operating system's
// support for the wider registers (XGETBV): SSSE3 = SSE, SSE2, SSE3, SSSE3; SSE4 = SSSE3 + SSE4.1,
// SSE4.2, CLMUL, AES; AVX2 = SSE4 + AVX, AVX2, BMI, BMI2, FMA, F16C, LZCNT with YMM state enabled;
// AVX3 = AVX2 + AVX-512 F, VL, DQ, BW, CD with ZMM and opmask state enabled; AVX3_DL = AVX3 + VNNI,
// VPCLMULQDQ, VBMI, VBMI2, VAES, VPOPCNTDQ, BITALG, GFNI. tests/raster/test_simd_dispatch.cpp checks the
// result against Highway's own detection.
#include "core/simd_dispatch.hpp"

#if HWY_ARCH_X86
#include <cpuid.h>
#endif

namespace casteljau::simd {

namespace {

#if HWY_ARCH_X86
bool bit(std::uint32_t word, int b) { return ((word >> b) & 1u) != 0; }

std::int64_t detect() {
    std::int64_t targets = 0;
    unsigned a = 0, b = 0, c = 0, d = 0;
    if (__get_cpuid(0, &a, &b, &c, &d) == 0) return 0;
    const unsigned max_leaf = a;
    __cpuid_count(1, 0, a, b, c, d);
    const std::uint32_t ecx1 = c, edx1 = d;
    std::uint32_t ebx7 = 0, ecx7 = 0;
    if (max_leaf >= 7) {
        __cpuid_count(7, 0, a, b, c, d);
        ebx7 = b;
        ecx7 = c;
    }
    std::uint32_t ecx_ext = 0;
    if (__get_cpuid(0x80000000u, &a, &b, &c, &d) != 0 && a >= 0x80000001u) {
        __cpuid_count(0x80000001u, 0, a, b, c, d);
        ecx_ext = c;
    }
    // Registers the operating system saves on a context switch (XCR0), when it says it uses XSAVE.
    std::uint64_t xcr0 = 0;
    if (bit(ecx1, 27)) {
        std::uint32_t lo = 0, hi = 0;
        __asm__ volatile("xgetbv" : "=a"(lo), "=d"(hi) : "c"(0));
        xcr0 = (static_cast<std::uint64_t>(hi) << 32) | lo;
    }
    const bool ssse3 = bit(edx1, 25) && bit(edx1, 26) && bit(ecx1, 0) && bit(ecx1, 9);
    const bool sse4 = ssse3 && bit(ecx1, 19) && bit(ecx1, 20) && bit(ecx1, 1) && bit(ecx1, 25);
    const bool ymm = (xcr0 & 0x6) == 0x6;
    const bool avx2 = sse4 && ymm && bit(ecx1, 28) && bit(ebx7, 5) && bit(ebx7, 3) && bit(ebx7, 8) && bit(ecx1, 12) &&
                      bit(ecx1, 29) && bit(ecx_ext, 5);
    const bool zmm = (xcr0 & 0xE6) == 0xE6;
    const bool avx3 = avx2 && zmm && bit(ebx7, 16) && bit(ebx7, 31) && bit(ebx7, 17) && bit(ebx7, 30) && bit(ebx7, 28);
    const bool avx3_dl = avx3 && bit(ecx7, 11) && bit(ecx7, 10) && bit(ecx7, 1) && bit(ecx7, 6) && bit(ecx7, 9) &&
                         bit(ecx7, 14) && bit(ecx7, 12) && bit(ecx7, 8);
    if (ssse3) targets |= HWY_SSSE3;
    if (sse4) targets |= HWY_SSE4;
    if (avx2) targets |= HWY_AVX2;
    if (avx3) targets |= HWY_AVX3;
    if (avx3_dl) targets |= HWY_AVX3_DL;
    return targets;
}
#else
std::int64_t detect() { return 0; }  // other architectures: the static target and the fallback
#endif

// The portable fallback every build has, and the target the whole file was compiled for.
constexpr std::int64_t kAlways = HWY_STATIC_TARGET | HWY_EMU128 | HWY_SCALAR;

hwy::ChosenTarget& storage() {
    static hwy::ChosenTarget target;
    return target;
}

}  // namespace

std::int64_t cpu_targets() {
    static const std::int64_t targets = detect() | kAlways;
    return targets;
}

const hwy::ChosenTarget& chosen() {
    static const bool initialized = [] {
        storage().Update(cpu_targets());
        return true;
    }();
    (void)initialized;
    return storage();
}

void restrict_targets(std::int64_t mask) {
    (void)chosen();
    storage().Update(mask == 0 ? cpu_targets() : (cpu_targets() & mask));
}

std::vector<std::int64_t> available_targets() {
    std::vector<std::int64_t> out;
    const std::int64_t runnable = cpu_targets() & HWY_TARGETS;
    for (int b = 0; b < 63; ++b)  // lower bits are better targets in Highway's numbering
        if ((runnable >> b) & 1) out.push_back(std::int64_t{1} << b);
    return out;
}

const char* target_name(std::int64_t target) {
    switch (target) {
        case HWY_AVX3_DL: return "AVX3_DL";
        case HWY_AVX3: return "AVX3";
        case HWY_AVX2: return "AVX2";
        case HWY_SSE4: return "SSE4";
        case HWY_SSSE3: return "SSSE3";
        case HWY_EMU128: return "EMU128";
        case HWY_SCALAR: return "SCALAR";
        default: return "other";
    }
}

}  // namespace casteljau::simd
