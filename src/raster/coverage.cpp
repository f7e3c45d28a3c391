// Raster stage, coverage: per-row prefix sum of the accumulation buffer mapped through the fill
// rule to 8-bit coverage. Vectorised with Highway (runtime dispatch to the best instruction set
// the CPU has): an in-register inclusive scan per vector plus a running carry.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/coverage.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/raster_internal.hpp"

HWY_BEFORE_NAMESPACE();
namespace casteljau::raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

float AccumulateRowImpl(float* acc, std::uint8_t* cov, int from, int to, float start, FillRule rule) {
    float sum = start;
    int i = from;
#if HWY_TARGET != HWY_SCALAR
    // 128-bit vectors on every target: the scan's carry chain, not the width, bounds the speed.
    const hn::FixedTag<float, 4> df;
    const hn::FixedTag<std::int32_t, 4> di;
    const hn::FixedTag<std::uint8_t, 4> du8;
    if (to - i >= 4) {
        const auto one = hn::Set(df, 1.0f);
        const auto two = hn::Set(df, 2.0f);
        const auto half = hn::Set(df, 0.5f);
        const auto scale = hn::Set(df, 255.0f);
        const auto zero = hn::Zero(df);
        auto carry = hn::Set(df, sum);
        for (; i + 4 <= to; i += 4) {
            auto v = hn::LoadU(df, acc + i);
            hn::StoreU(zero, df, acc + i);
            // Inclusive scan in the vector: two shift-and-add steps, then the running carry.
            v = hn::Add(v, hn::ShiftLeftLanes<1>(df, v));
            v = hn::Add(v, hn::ShiftLeftLanes<2>(df, v));
            v = hn::Add(v, carry);
            carry = hn::Broadcast<3>(v);
            auto a = hn::Abs(v);
            if (rule == FillRule::NonZero) {
                a = hn::Min(a, one);
            } else {
                a = hn::NegMulAdd(hn::Floor(hn::Mul(a, half)), two, a);  // |v| mod 2, in [0, 2)
                a = hn::Min(a, hn::Sub(two, a));                          // distance to an even integer
            }
            const auto c = hn::ConvertTo(di, hn::MulAdd(a, scale, half));
            hn::StoreU(hn::DemoteTo(du8, c), du8, cov + i);
        }
        sum = hn::GetLane(carry);
    }
#endif
    for (; i < to; ++i) {
        sum += acc[i];
        acc[i] = 0.0f;
        cov[i] = coverage_u8(sum, rule);
    }
    return sum;
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::raster {
HWY_EXPORT(AccumulateRowImpl);

float accumulate_row(float* acc, std::uint8_t* cov, int from, int to, float start, FillRule rule) {
    return HWY_DYNAMIC_DISPATCH(AccumulateRowImpl)(acc, cov, from, to, start, rule);
}
}  // namespace casteljau::raster
#endif
