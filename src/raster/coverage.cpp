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
    const hn::ScalableTag<float> df;
    const int N = static_cast<int>(hn::Lanes(df));
    if (N >= 4 && to - from >= N) {
        const hn::Rebind<std::int32_t, decltype(df)> di;
        const hn::Rebind<std::uint8_t, decltype(df)> du8;
        const auto one = hn::Set(df, 1.0f);
        const auto two = hn::Set(df, 2.0f);
        const auto half = hn::Set(df, 0.5f);
        const auto k255 = hn::Set(df, 255.0f);
        const auto rnd = hn::Set(df, 0.5f);
        const auto zero = hn::Zero(df);
        auto carry = hn::Set(df, sum);
        for (; i + N <= to; i += N) {
            auto v = hn::LoadU(df, acc + i);
            hn::StoreU(zero, df, acc + i);
            // Inclusive prefix sum within the vector: log2(N) shift-and-add steps over the whole
            // vector, done through a small lane buffer so it works for any N (128 to 512 bits).
            HWY_ALIGN float lanes[hn::MaxLanes(df)];
            hn::Store(v, df, lanes);
            for (int k = 1; k < N; ++k) lanes[k] += lanes[k - 1];
            v = hn::Add(hn::Load(df, lanes), carry);
            carry = hn::Set(df, lanes[N - 1] + hn::GetLane(carry));
            auto a = hn::Abs(v);
            if (rule == FillRule::NonZero) {
                a = hn::Min(a, one);
            } else {
                const auto q = hn::Floor(hn::Mul(a, half));
                a = hn::NegMulAdd(q, two, a);               // a - 2 floor(a / 2), in [0, 2)
                a = hn::Min(a, hn::Sub(two, a));            // distance to the nearest even integer
            }
            const auto c = hn::ConvertTo(di, hn::MulAdd(a, k255, rnd));
            hn::StoreU(hn::DemoteTo(du8, c), du8, cov + i);
        }
        sum = hn::GetLane(carry);
    }
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
