// Paint stage: gradient colours of a run of parameters (gradient_span.hpp), one parameter per
// SIMD lane: spreading in double, finding the stops around the parameter by comparing it with
// every stop's offset (gradients have few stops), interpolating and premultiplying in float.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "paint/gradient_span.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>

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

// The conical equation a t^2 - 2 b t + k = 0, a = |c - f|^2 - dr^2, b = (p - f).(c - f) + r0 dr,
// k = |p - f|^2 - r0^2, one pixel per lane: which root applies is decided per lane, the degenerate
// equation (a close to 0: a linear one) per row.
void RadialParametersImpl(const RadialGradient& g, Point origin, Point step, double x0, int n, double* HWY_RESTRICT t) {
    const hn::ScalableTag<double> d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    const double cdx = g.centre.x - g.focal.x, cdy = g.centre.y - g.focal.y, dr = g.r1 - g.r0;
    const double a = cdx * cdx + cdy * cdy - dr * dr;
    const double scale = cdx * cdx + cdy * cdy + dr * dr + g.r0 * g.r0 + 1e-300;
    const bool linear = std::fabs(a) <= 1e-9 * scale;
    const auto vcdx = hn::Set(d, cdx), vcdy = hn::Set(d, cdy), vr0 = hn::Set(d, g.r0), vdr = hn::Set(d, dr);
    const auto r0dr = hn::Set(d, g.r0 * dr), r0sq = hn::Set(d, g.r0 * g.r0), va = hn::Set(d, a);
    const auto zero = hn::Zero(d), nan = hn::Set(d, NAN);
    for (int i = 0; i < n; i += lanes) {
        const auto X = hn::Iota(d, x0 + i);
        const auto px = hn::Add(hn::Set(d, origin.x), hn::Mul(X, hn::Set(d, step.x)));
        const auto py = hn::Add(hn::Set(d, origin.y), hn::Mul(X, hn::Set(d, step.y)));
        const auto pdx = hn::Sub(px, hn::Set(d, g.focal.x)), pdy = hn::Sub(py, hn::Set(d, g.focal.y));
        const auto b = hn::Add(hn::Add(hn::Mul(pdx, vcdx), hn::Mul(pdy, vcdy)), r0dr);
        const auto k = hn::Sub(hn::Add(hn::Mul(pdx, pdx), hn::Mul(pdy, pdy)), r0sq);
        auto radius_ok = [&](hn::Vec<decltype(d)> u) { return hn::Ge(hn::Add(vr0, hn::Mul(u, vdr)), zero); };
        hn::Vec<decltype(d)> out;
        if (linear) {
            // Concentric circles of one radius: inside them takes the first stop.
            const auto flat = hn::Eq(b, zero);
            const auto u = hn::Div(k, hn::Mul(hn::Set(d, 2.0), b));
            out =
                hn::IfThenElse(flat, hn::IfThenElse(hn::Le(k, zero), zero, nan), hn::IfThenElse(radius_ok(u), u, nan));
        } else {
            const auto disc = hn::Sub(hn::Mul(b, b), hn::Mul(va, k));
            const auto sq = hn::Sqrt(hn::Max(disc, zero));
            const auto t1 = hn::Div(hn::Add(b, sq), va), t2 = hn::Div(hn::Sub(b, sq), va);
            const auto hi = hn::Max(t1, t2), lo = hn::Min(t1, t2);
            out = hn::IfThenElse(radius_ok(hi), hi, hn::IfThenElse(radius_ok(lo), lo, nan));
            out = hn::IfThenElse(hn::Lt(disc, zero), nan, out);
        }
        hn::StoreU(out, d, t + i);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::paint_simd
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::paint_simd {

CASTELJAU_SIMD_EXPORT(GradientColorsImpl);
CASTELJAU_SIMD_EXPORT(RadialParametersImpl);

void radial_parameters(const RadialGradient& g, Point origin, Point step, double x0, int n, double* t) {
    CASTELJAU_SIMD_DISPATCH(RadialParametersImpl)(g, origin, step, x0, n, t);
}

void gradient_colors(const double* t, int n, const GradientTable& table, SpreadMethod spread, bool constant,
                     float opacity, std::uint8_t* out) {
    CASTELJAU_SIMD_DISPATCH(GradientColorsImpl)(t, n, table, spread, constant, opacity, out);
}

}  // namespace casteljau::paint_simd
#endif
