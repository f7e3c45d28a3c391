// Encode stage: the Paeth filter of a PNG row and libpng's filter sums (png_paeth.hpp), with
// Highway's runtime dispatch.
//
// All in bytes, as the PNG specification's predictor is usually vectorized: with pa = |b - c| and
// pb = |a - c| (absolute differences of bytes), |a + b - 2c| is pa + pb when a and b lie on the same
// side of c and |pa - pb| otherwise; pa + pb saturated at 255 orders the same way against pa and
// pb (both at most 255), which is all the predictor compares it with.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "formats/png_paeth.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "core/simd_dispatch.hpp"
#include "formats/png_paeth.hpp"

HWY_BEFORE_NAMESPACE();
namespace casteljau::png_detail {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The scalar formula, for the first pixel, the tail and the scalar target.
inline unsigned magnitude(std::uint8_t v) { return v < 128 ? v : 256u - v; }

inline std::uint8_t paeth_byte(int x, int a, int b, int c) {
    const int p = b - c, q = a - c;
    const int pa = p < 0 ? -p : p, pb = q < 0 ? -q : q, pc = p + q < 0 ? -(p + q) : p + q;
    const int pred = (pa <= pb && pa <= pc) ? a : (pb <= pc) ? b : c;
    return static_cast<std::uint8_t>(x - pred);
}

RowSums PaethRowImpl(const std::uint8_t* HWY_RESTRICT row, const std::uint8_t* HWY_RESTRICT prev, std::size_t n,
                     std::size_t bpp, std::uint8_t* HWY_RESTRICT out) {
    RowSums sums;
    std::size_t i = 0;
    for (; i < bpp && i < n; ++i) {
        out[i] = static_cast<std::uint8_t>(row[i] - prev[i]);
        sums.none += magnitude(row[i]);
        sums.paeth += magnitude(out[i]);
    }
#if HWY_TARGET != HWY_SCALAR
    const hn::ScalableTag<std::uint8_t> d;
    const hn::Repartition<std::uint64_t, decltype(d)> d64;
    const std::size_t lanes = hn::Lanes(d);
    const auto zero = hn::Zero(d);
    auto none = hn::Zero(d64), paeth = hn::Zero(d64);
    for (; i + lanes <= n; i += lanes) {
        const auto x = hn::LoadU(d, row + i), a = hn::LoadU(d, row + i - bpp);
        const auto b = hn::LoadU(d, prev + i), c = hn::LoadU(d, prev + i - bpp);
        const auto pa = hn::Or(hn::SaturatedSub(b, c), hn::SaturatedSub(c, b));
        const auto pb = hn::Or(hn::SaturatedSub(a, c), hn::SaturatedSub(c, a));
        // b >= c and a >= c: c - b and c - a saturate to 0.
        const auto same_side =
            hn::Not(hn::Xor(hn::Eq(hn::SaturatedSub(c, b), zero), hn::Eq(hn::SaturatedSub(c, a), zero)));
        const auto pc = hn::IfThenElse(same_side, hn::SaturatedAdd(pa, pb),
                                       hn::Or(hn::SaturatedSub(pa, pb), hn::SaturatedSub(pb, pa)));
        const auto pa_first = hn::And(hn::Eq(hn::SaturatedSub(pa, pb), zero), hn::Eq(hn::SaturatedSub(pa, pc), zero));
        const auto pb_second = hn::Eq(hn::SaturatedSub(pb, pc), zero);
        const auto filtered = hn::Sub(x, hn::IfThenElse(pa_first, a, hn::IfThenElse(pb_second, b, c)));
        hn::StoreU(filtered, d, out + i);
        none = hn::Add(none, hn::SumsOf8(hn::Min(x, hn::Sub(zero, x))));
        paeth = hn::Add(paeth, hn::SumsOf8(hn::Min(filtered, hn::Sub(zero, filtered))));
    }
    sums.none += hn::GetLane(hn::SumOfLanes(d64, none));
    sums.paeth += hn::GetLane(hn::SumOfLanes(d64, paeth));
#endif
    for (; i < n; ++i) {
        out[i] = paeth_byte(row[i], row[i - bpp], prev[i], prev[i - bpp]);
        sums.none += magnitude(row[i]);
        sums.paeth += magnitude(out[i]);
    }
    return sums;
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::png_detail
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::png_detail {
CASTELJAU_SIMD_EXPORT(PaethRowImpl);

RowSums paeth_row(const std::uint8_t* row, const std::uint8_t* prev, std::size_t n, std::size_t bpp,
                  std::uint8_t* out) {
    return CASTELJAU_SIMD_DISPATCH(PaethRowImpl)(row, prev, n, bpp, out);
}
}  // namespace casteljau::png_detail
#endif
