// Paint stage: gradient colours of a run of parameters (gradient_span.hpp), one parameter per
// SIMD lane: spreading in double, finding the stops around the parameter by comparing it with
// every stop's offset (gradients have few stops), interpolating and premultiplying in float.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "paint/gradient_span.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>

#include "core/simd_dispatch.hpp"
#include "paint/gradient_span.hpp"

HWY_BEFORE_NAMESPACE();
namespace casteljau::paint_simd {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The spread parameter u of t: pad clamps to [0, 1], repeat keeps the fraction, reflect folds
// |t| mod 2 (|t| - 2 floor(|t| / 2) is exact, as fmod is) back into [0, 1].
template <class D, class V>
HWY_INLINE V Spread(D d, V t, SpreadMethod m) {
    const auto zero = hn::Zero(d), one = hn::Set(d, 1.0), two = hn::Set(d, 2.0);
    switch (m) {
        case SpreadMethod::Pad: return hn::Min(hn::Max(t, zero), one);
        case SpreadMethod::Repeat: return hn::Sub(t, hn::Floor(t));
        case SpreadMethod::Reflect: {
            const auto a = hn::Abs(t);
            const auto u = hn::Sub(a, hn::Mul(two, hn::Floor(hn::Mul(a, hn::Set(d, 0.5)))));
            return hn::IfThenElse(hn::Gt(u, one), hn::Sub(two, u), u);
        }
    }
    return t;
}

// A mask of double lanes as a mask of the float lanes they demote to.
template <class DF, class D, class M>
HWY_INLINE auto Narrow(DF df, D d, M m) {
    return hn::Gt(hn::DemoteTo(df, hn::IfThenElseZero(m, hn::Set(d, 1.0))), hn::Zero(df));
}

void GradientColorsImpl(const double* HWY_RESTRICT t, int n, const GradientTable& g, SpreadMethod spread, bool constant,
                        float opacity, std::uint8_t* HWY_RESTRICT out) {
    const hn::ScalableTag<double> d;
    const hn::Rebind<float, decltype(d)> df;
    const hn::Rebind<std::int32_t, decltype(d)> di;
    constexpr std::size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
    const int lanes = static_cast<int>(hn::Lanes(d));
    const std::size_t last = g.stops - 1;
    HWY_ALIGN std::int32_t ch[4][kMaxLanes];
    for (int i = 0; i < n; i += lanes) {
        const auto tv = hn::LoadU(d, t + i);
        const auto valid = hn::Eq(tv, tv);
        const auto u = constant ? hn::Set(d, 1.0) : Spread(d, tv, spread);
        // Between stops s and s + 1 for the last s with offset <= u.
        hn::Vec<decltype(df)> c[4];
        for (int k = 0; k < 4; ++k) c[k] = hn::Set(df, g.rgba[4 * last + k]);
        for (std::size_t s = 0; s < last; ++s) {
            const auto off = hn::Set(d, g.offset[s]);
            const auto at = Narrow(df, d, hn::Le(off, u));
            const auto w = g.inv_span[s] > 0 ? hn::DemoteTo(df, hn::Mul(hn::Sub(u, off), hn::Set(d, g.inv_span[s])))
                                             : hn::Set(df, 1.0f);
            for (int k = 0; k < 4; ++k) {
                const auto c0 = hn::Set(df, g.rgba[4 * s + k]), c1 = hn::Set(df, g.rgba[4 * (s + 1) + k]);
                c[k] = hn::IfThenElse(at, hn::Add(c0, hn::Mul(hn::Sub(c1, c0), w)), c[k]);
            }
        }
        // Past the last offset, the last stop; at or before the first, the first stop.
        const auto after = Narrow(df, d, hn::Ge(u, hn::Set(d, g.offset[last])));
        const auto before = Narrow(df, d, hn::Le(u, hn::Set(d, g.offset[0])));
        for (int k = 0; k < 4; ++k) {
            c[k] = hn::IfThenElse(after, hn::Set(df, g.rgba[4 * last + k]), c[k]);
            c[k] = hn::IfThenElse(before, hn::Set(df, g.rgba[k]), c[k]);
        }
        const auto alpha = hn::Mul(c[3], hn::Set(df, opacity));
        const auto scale = hn::Mul(alpha, hn::Set(df, 1.0f / 255.0f));
        const auto half = hn::Set(df, 0.5f);
        const auto keep = hn::RebindMask(di, Narrow(df, d, valid));
        for (int k = 0; k < 3; ++k)
            hn::Store(hn::IfThenElseZero(keep, hn::ConvertTo(di, hn::Add(hn::Mul(c[k], scale), half))), di, ch[k]);
        hn::Store(hn::IfThenElseZero(keep, hn::ConvertTo(di, hn::Add(alpha, half))), di, ch[3]);
        const int count = std::min(lanes, n - i);
        for (int j = 0; j < count; ++j) {
            std::uint8_t* o = out + 4 * static_cast<std::size_t>(i + j);
            for (int k = 0; k < 4; ++k) o[k] = static_cast<std::uint8_t>(ch[k][j]);
        }
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::paint_simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::paint_simd {

CASTELJAU_SIMD_EXPORT(GradientColorsImpl);

void gradient_colors(const double* t, int n, const GradientTable& table, SpreadMethod spread, bool constant,
                     float opacity, std::uint8_t* out) {
    CASTELJAU_SIMD_DISPATCH(GradientColorsImpl)(t, n, table, spread, constant, opacity, out);
}

}  // namespace casteljau::paint_simd
#endif
