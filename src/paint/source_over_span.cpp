// Paint stage, source-over of premultiplied pixels (source_over_span.hpp), with Highway's runtime
// dispatch (core/simd_dispatch.hpp): one 32-bit lane per pixel, the four channels taken out by
// shifts.
//
// Each channel is div65025(s sc + d keep + 32512) as in pixel::source_over, with sc = 255 c and
// keep = 65025 - Sa c. The numerator t is below 2^24, so it converts to float exactly, and
// trunc(t x float(1 / 65025)) equals floor(t / 65025) for every such t (the tests check all 2^24):
// the float product is exact to the integer. A vector where every Sa c is 0 is skipped, one where
// every Sa c is 255^2 (opaque sources at full coverage) is stored as the source.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "paint/source_over_span.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <bit>
#include <cstring>

#include "core/simd_dispatch.hpp"
#include "paint/pixel_math.hpp"
#include "paint/source_over_span.hpp"

HWY_BEFORE_NAMESPACE();
namespace casteljau::paint_simd {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// round(n / 65025) for every lane, n + 32512 < 2^24: the truncated float product (see the top of
// the file).
template <class D, class V>
HWY_INLINE V Div65025(D d, V n) {
    const hn::RebindToSigned<D> di;
    const hn::RebindToFloat<D> df;
    const auto t = hn::ConvertTo(df, hn::BitCast(di, hn::Add(n, hn::Set(d, 32512u))));
    return hn::BitCast(d, hn::ConvertTo(di, hn::Mul(t, hn::Set(df, kInv65025))));
}

// Byte 3 of a pixel in memory (alpha) as a bit position of its 32-bit lane.
constexpr int kAlphaShift = std::endian::native == std::endian::little ? 24 : 0;

// src_step 0: `src` is one pixel for the whole span; 4: one per pixel. coverage null: 255.
void SourceOverImpl(std::uint8_t* HWY_RESTRICT dst, int length, const std::uint8_t* HWY_RESTRICT coverage,
                    const std::uint8_t* HWY_RESTRICT src, int src_step) {
    const std::size_t step = static_cast<std::size_t>(src_step);
    int i = 0;
#if HWY_TARGET != HWY_SCALAR
    const hn::ScalableTag<std::uint32_t> d;
    const hn::Repartition<std::uint8_t, decltype(d)> dpx;  // the same pixels as bytes
    const hn::Rebind<std::uint8_t, decltype(d)> dcov;      // one coverage byte per pixel
    const int n = static_cast<int>(hn::Lanes(d));
    std::uint32_t word;
    std::memcpy(&word, src, 4);
    const auto solid = hn::Set(d, word);
    const auto mask = hn::Set(d, 0xffu);
    const auto full = hn::Set(d, 255u);
    for (; i + n <= length; i += n) {
        std::uint8_t* px = dst + 4 * static_cast<std::size_t>(i);
        const auto c = coverage ? hn::PromoteTo(d, hn::LoadU(dcov, coverage + i)) : full;
        const auto s = step ? hn::BitCast(d, hn::LoadU(dpx, src + step * static_cast<std::size_t>(i))) : solid;
        const auto sa = hn::And(hn::ShiftRight<kAlphaShift>(s), mask);
        const auto sac = hn::Mul(c, sa);  // 0: the pixel keeps its value; 65025: it becomes s
        if (hn::AllTrue(d, hn::Eq(sac, hn::Zero(d)))) continue;
        if (hn::AllTrue(d, hn::Eq(sac, hn::Set(d, 65025u)))) {
            hn::StoreU(hn::BitCast(dpx, s), dpx, px);
            continue;
        }
        const auto sc = hn::Mul(c, full);
        const auto keep = hn::Sub(hn::Set(d, 65025u), sac);
        const auto dv = hn::BitCast(d, hn::LoadU(dpx, px));
        auto out = hn::Zero(d);
        for (int k = 0; k < 4; ++k) {
            const auto dk = hn::And(hn::ShiftRightSame(dv, 8 * k), mask);
            const auto sk = hn::And(hn::ShiftRightSame(s, 8 * k), mask);
            const auto q = Div65025(d, hn::Add(hn::Mul(sk, sc), hn::Mul(dk, keep)));
            out = hn::Or(out, hn::ShiftLeftSame(q, 8 * k));
        }
        hn::StoreU(hn::BitCast(dpx, out), dpx, px);
    }
#endif
    // The tail shorter than a vector, and Highway's one-lane scalar target (which has no byte view
    // of a pixel lane): the scalar formula.
    for (; i < length; ++i) {
        const unsigned c = coverage ? coverage[i] : 255u;
        const std::uint8_t* sp = src + step * static_cast<std::size_t>(i);
        if (c == 0 || sp[3] == 0) continue;
        std::uint8_t* px = dst + 4 * static_cast<std::size_t>(i);
        if (c == 255 && sp[3] == 255)
            std::memcpy(px, sp, 4);
        else
            pixel::source_over(px, sp, c);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::paint_simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::paint_simd {
CASTELJAU_SIMD_EXPORT(SourceOverImpl);

void source_over_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src,
                      int src_step) {
    CASTELJAU_SIMD_DISPATCH(SourceOverImpl)(dst, length, coverage, src, src_step);
}
}  // namespace casteljau::paint_simd
#endif
