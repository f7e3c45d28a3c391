// Raster stage, coverage: per-row prefix sum of the (double) accumulation buffer mapped through the fill
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

double AccumulateRowImpl(double* acc, std::uint8_t* cov, int from, int to, double start, FillRule rule) {
    double sum = start;
    int i = from;
#if HWY_TARGET != HWY_SCALAR
    // Two doubles per 128-bit vector: one shift-and-add scan step, then the running carry. Double
    // precision keeps rows crossing hundreds of stacked edges exact to far below 1/255.
    const hn::FixedTag<double, 2> dd;
    const hn::FixedTag<std::int32_t, 2> di;
    const hn::FixedTag<std::uint8_t, 2> du8;
    if (to - i >= 2) {
        const auto one = hn::Set(dd, 1.0);
        const auto two = hn::Set(dd, 2.0);
        const auto half = hn::Set(dd, 0.5);
        const auto scale = hn::Set(dd, 255.0);
        const auto zero = hn::Zero(dd);
        auto carry = hn::Set(dd, sum);
        for (; i + 2 <= to; i += 2) {
            auto v = hn::LoadU(dd, acc + i);
            hn::StoreU(zero, dd, acc + i);
            v = hn::Add(v, hn::ShiftLeftLanes<1>(dd, v));
            v = hn::Add(v, carry);
            carry = hn::Broadcast<1>(v);
            auto a = hn::Abs(v);
            if (rule == FillRule::NonZero) {
                a = hn::Min(a, one);
            } else {
                a = hn::NegMulAdd(hn::Floor(hn::Mul(a, half)), two, a);  // |v| mod 2, in [0, 2)
                a = hn::Min(a, hn::Sub(two, a));                          // distance to an even integer
            }
            const auto c = hn::DemoteTo(di, hn::MulAdd(a, scale, half));
            hn::StoreU(hn::DemoteTo(du8, c), du8, cov + i);
        }
        sum = hn::GetLane(carry);
    }
#endif
    for (; i < to; ++i) {
        sum += acc[i];
        acc[i] = 0.0;
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

double accumulate_row(double* acc, std::uint8_t* cov, int from, int to, double start, FillRule rule) {
    return HWY_DYNAMIC_DISPATCH(AccumulateRowImpl)(acc, cov, from, to, start, rule);
}
}  // namespace casteljau::raster
#endif
