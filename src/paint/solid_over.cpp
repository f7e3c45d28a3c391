// Paint stage, source-over of a solid colour (solid_over.hpp), with Highway's runtime dispatch
// (core/simd_dispatch.hpp): one 32-bit lane per pixel, the four channels taken out by shifts.
//
// Each channel is div65025(s sc + d keep + 32512) as in pixel::source_over, with sc = 255 c and
// keep = 65025 - Sa c. The numerator t is below 2^24, so it converts to float exactly, and
// trunc(t x float(1 / 65025)) equals floor(t / 65025) for every such t (the tests check all 2^24):
// the float product is exact to the integer. A vector whose coverage is all zero is skipped, one all 255 under an opaque
// colour is stored as the colour; the tail shorter than a vector, and Highway's one-lane scalar target, take the
// scalar formula.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "paint/solid_over.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cstring>

#include "core/simd_dispatch.hpp"
#include "paint/pixel_math.hpp"
#include "paint/solid_over.hpp"

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

void SolidOverImpl(std::uint8_t* HWY_RESTRICT dst, int length, const std::uint8_t* HWY_RESTRICT coverage,
                   const std::uint8_t* HWY_RESTRICT solid) {
#if HWY_TARGET == HWY_SCALAR
    // One lane: the scalar formula (Highway's scalar target has no byte view of a pixel lane).
    for (int i = 0; i < length; ++i)
        if (coverage[i] != 0) pixel::source_over(dst + 4 * static_cast<std::size_t>(i), solid, coverage[i]);
#else
    const hn::ScalableTag<std::uint32_t> d;
    const hn::Repartition<std::uint8_t, decltype(d)> dpx;  // the same pixels as bytes
    const hn::Rebind<std::uint8_t, decltype(d)> dcov;      // one coverage byte per pixel
    const int n = static_cast<int>(hn::Lanes(d));
    std::uint32_t word;
    std::memcpy(&word, solid, 4);
    const auto colour = hn::Set(d, word);
    const auto sa_vec = hn::Set(d, solid[3]);
    const auto mask = hn::Set(d, 0xffu);
    const bool opaque = solid[3] == 255;
    int i = 0;
    for (; i + n <= length; i += n) {
        const auto cov8 = hn::LoadU(dcov, coverage + i);
        if (hn::AllTrue(dcov, hn::Eq(cov8, hn::Zero(dcov)))) continue;
        std::uint8_t* px = dst + 4 * static_cast<std::size_t>(i);
        if (opaque && hn::AllTrue(dcov, hn::Eq(cov8, hn::Set(dcov, 255)))) {
            hn::StoreU(hn::BitCast(dpx, colour), dpx, px);
            continue;
        }
        const auto c = hn::PromoteTo(d, cov8);
        const auto sc = hn::Mul(c, hn::Set(d, 255u));
        const auto keep = hn::Sub(hn::Set(d, 65025u), hn::Mul(c, sa_vec));
        const auto dv = hn::BitCast(d, hn::LoadU(dpx, px));
        auto out = hn::Zero(d);
        for (int k = 0; k < 4; ++k) {
            const auto dk = hn::And(hn::ShiftRightSame(dv, 8 * k), mask);
            const auto sk = hn::Set(d, solid[k]);
            const auto q = Div65025(d, hn::Add(hn::Mul(sk, sc), hn::Mul(dk, keep)));
            out = hn::Or(out, hn::ShiftLeftSame(q, 8 * k));
        }
        hn::StoreU(hn::BitCast(dpx, out), dpx, px);
    }
    for (; i < length; ++i)
        if (coverage[i] != 0) pixel::source_over(dst + 4 * static_cast<std::size_t>(i), solid, coverage[i]);
#endif
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::paint_simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::paint_simd {
CASTELJAU_SIMD_EXPORT(SolidOverImpl);

void solid_over_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* solid) {
    CASTELJAU_SIMD_DISPATCH(SolidOverImpl)(dst, length, coverage, solid);
}
}  // namespace casteljau::paint_simd
#endif
