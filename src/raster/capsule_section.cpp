// Raster stage: sections of a capsule on a run of sample lines (capsule_section.hpp), one line per
// SIMD lane, in double or in float. A capsule is convex, so its section is the hull of the sections
// of its two end discs and of the band between them: each is computed for every lane and kept where
// the line meets it.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/capsule_section.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/simd_dispatch.hpp"
#include "raster/capsule_section.hpp"

HWY_BEFORE_NAMESPACE();
namespace casteljau::raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// A capsule's value in the lanes' type (its fields are double).
template <class D>
HWY_INLINE hn::Vec<D> Splat(D d, double v) {
    return hn::Set(d, static_cast<hn::TFromD<D>>(v));
}

// Widens [lo, hi] by the section of the disc of radius r (r2 = r * r) at (px, py) on lines c,
// given as their heights above the row's top, `row` (so is py, in double, before it is rounded).
template <class D, class V>
HWY_INLINE void AddDisc(D d, V c, int row, double px, double py, V r2, V& lo, V& hi) {
    const auto dy = hn::Sub(c, Splat(d, py - row));
    const auto s = hn::Sub(r2, hn::Mul(dy, dy));
    const auto hit = hn::Ge(s, hn::Zero(d));
    const auto w = hn::Sqrt(hn::Max(s, hn::Zero(d)));
    const auto x = Splat(d, px);
    lo = hn::IfThenElse(hit, hn::Min(lo, hn::Sub(x, w)), lo);
    hi = hn::IfThenElse(hit, hn::Max(hi, hn::Add(x, w)), hi);
}

// Widens [lo, hi] by the section of the capsule's band on lines c.
template <class D, class V>
HWY_INLINE void AddBand(D d, V c, int row, const SweptCapsule& k, double r, V& lo, V& hi) {
    const auto dy = hn::Sub(c, Splat(d, k.ay - row));
    const auto ax = Splat(d, k.ax);
    if (k.vertical) {
        const auto hit = hn::And(hn::Ge(dy, Splat(d, k.end_lo)), hn::Le(dy, Splat(d, k.end_hi)));
        lo = hn::IfThenElse(hit, hn::Min(lo, Splat(d, k.ax - r)), lo);
        hi = hn::IfThenElse(hit, hn::Max(hi, Splat(d, k.ax + r)), hi);
        return;
    }
    const auto base = hn::Sub(ax, hn::Mul(Splat(d, k.end_slope), dy));
    const auto mid = hn::Add(ax, hn::Mul(Splat(d, k.side_slope), dy));
    const auto half = Splat(d, k.side_half);
    const auto l = hn::Max(hn::Add(base, Splat(d, k.end_lo)), hn::Sub(mid, half));
    const auto h = hn::Min(hn::Add(base, Splat(d, k.end_hi)), hn::Add(mid, half));
    const auto hit = hn::Le(l, h);
    lo = hn::IfThenElse(hit, hn::Min(lo, l), lo);
    hi = hn::IfThenElse(hit, hn::Max(hi, h), hi);
}

// The bits of `m` (lanes i .. i + lanes - 1 of a run) into words[i / 64]: lanes are a power of
// two of at most 64 here, so one vector's bits stay in one word.
template <class D, class M>
HWY_INLINE void OrBits(D d, M m, int i, std::uint64_t* HWY_RESTRICT words) {
    std::uint8_t bytes[8] = {};
    hn::StoreMaskBits(d, m, bytes);
    std::uint64_t bits = 0;
    std::memcpy(&bits, bytes, sizeof bits);
    words[i / 64] |= bits << (i % 64);
}

// Adds the settling lanes' intervals [olo, ohi], cut to the row's pixels, to one SettledRun when
// they end within kSettledPixels pixels of each other; returns the lanes left to the caller (none,
// or all of them when they spread wider or the runs are full).
template <class D, class V, class M>
HWY_INLINE M SettleLanes(D d, M settle, V olo, V ohi, SectionRow<hn::TFromD<D>>& st) {
    const auto none = hn::FirstN(d, 0);
    const auto l = hn::Max(olo, Splat(d, st.clip_lo)), h = hn::Min(ohi, Splat(d, st.clip_hi));
    const auto valid = hn::And(settle, hn::Lt(l, h));
    if (hn::AllFalse(d, valid)) return none;  // nothing inside the row's pixels
    const double first =
        std::floor(static_cast<double>(hn::GetLane(hn::MinOfLanes(d, hn::IfThenElse(valid, l, Splat(d, INFINITY))))));
    const double last =
        std::floor(static_cast<double>(hn::GetLane(hn::MaxOfLanes(d, hn::IfThenElse(valid, h, Splat(d, -INFINITY))))));
    if (last - first >= kSettledPixels || st.n_runs == st.max_runs) return valid;
    // Lengths from the first pixel's left side (small values, exact differences), each rounded to
    // whole units of kSettledUnit: whole numbers, summed exactly in any order.
    const auto base = Splat(d, first);
    const auto u = hn::IfThenElseZero(valid, hn::Sub(l, base)), v = hn::IfThenElseZero(valid, hn::Sub(h, base));
    const auto units = Splat(d, 1.0 / kSettledUnit);
    SettledRun& run = st.runs[st.n_runs++];
    run.x = static_cast<int>(first);
    run.count = static_cast<int>(last - first) + 1;
    for (int k = 0; k < run.count; ++k) {
        const auto len =
            hn::Max(hn::Sub(hn::Min(v, Splat(d, k + 1.0)), hn::Max(u, Splat(d, static_cast<double>(k)))), hn::Zero(d));
        const auto q = hn::Round(hn::Mul(len, units));
        run.units[k] = static_cast<std::int32_t>(hn::GetLane(hn::SumOfLanes(d, q)));
    }
    return none;
}

// One capsule on lines s0 .. s0 + n - 1 of the row (capsule_section.hpp): returns how many lines
// it left for the caller (a bit set in left_bits or closed_bits). Intervals it closes that no
// later capsule can reach (ending left of settle_below, on lines still in order) are settled here.
template <class T>
HWY_INLINE int CapsuleSections(const SweptCapsule& k, double step, int s0, int n, double settle_below,
                               SectionRow<T>& st) {
    const hn::ScalableTag<T> d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    static_assert(kMaxSectionLines % 64 == 0);
    const int row = st.row;
    T* HWY_RESTRICT open_lo = st.open_lo + s0;
    T* HWY_RESTRICT open_hi = st.open_hi + s0;
    T* HWY_RESTRICT closed_hi = st.closed_hi + s0;
    const T* HWY_RESTRICT limit = st.settle_limit + s0;
    for (int w = 0; w < (n + 63) / 64; ++w) st.left_bits[w] = st.closed_bits[w] = 0;
    // Heights above the row's top: small wherever a line meets the capsule, so that float keeps them
    // to its last place, however far down the image the row is.
    const auto r2 = Splat(d, st.r * st.r), y0 = Splat(d, k.y0 - row), y1 = Splat(d, k.y1 - row);
    const auto inf = Splat(d, INFINITY), neg_inf = Splat(d, -INFINITY), below = Splat(d, settle_below);
    std::size_t handed = 0;
    for (int i = 0; i < n; i += lanes) {
        const auto s = hn::Iota(d, static_cast<T>(s0 + i));
        const auto c = hn::Mul(hn::Add(s, Splat(d, 0.5)), Splat(d, step));
        auto lo = inf, hi = neg_inf;
        if (k.start_disc) AddDisc(d, c, row, k.ax, k.ay, r2, lo, hi);
        AddDisc(d, c, row, k.bx, k.by, r2, lo, hi);
        if (k.band) AddBand(d, c, row, k, st.r, lo, hi);
        const auto hit = hn::And(hn::And(hn::Gt(c, y0), hn::Lt(c, y1)),
                                 hn::And(hn::Lt(lo, hi), hn::FirstN(d, static_cast<std::size_t>(n - i))));
        // Fold into the open intervals: take where there is none, merge where the section meets it
        // and stays right of the closed ones, advance where it lies right of it (the open interval
        // is closed, and settled or handed out; the section opens).
        auto olo = hn::LoadU(d, open_lo + i), ohi = hn::LoadU(d, open_hi + i);
        const auto take = hn::And(hit, hn::Gt(olo, ohi));
        const auto meets = hn::And(hn::Le(lo, ohi), hn::Ge(hi, olo));
        const auto merge = hn::And(hit, hn::And(meets, hn::Gt(lo, hn::LoadU(d, closed_hi + i))));
        const auto advance = hn::AndNot(take, hn::And(hit, hn::Gt(lo, ohi)));
        const auto left = hn::AndNot(hn::Or(hn::Or(take, merge), advance), hit);
        hn::StoreU(hn::IfThenElse(advance, ohi, hn::LoadU(d, closed_hi + i)), d, closed_hi + i);
        const auto settle = hn::And(advance, hn::And(hn::Lt(ohi, below), hn::Lt(ohi, hn::LoadU(d, limit + i))));
        auto closes = hn::AndNot(settle, advance);
        if (!hn::AllFalse(d, settle)) closes = hn::Or(closes, SettleLanes(d, settle, olo, ohi, st));
        hn::StoreU(hn::IfThenElse(left, lo, olo), d, st.lo + i);
        hn::StoreU(hn::IfThenElse(left, hi, ohi), d, st.hi + i);
        const auto opens = hn::Or(take, advance);
        olo = hn::IfThenElse(opens, lo, hn::IfThenElse(merge, hn::Min(olo, lo), olo));
        ohi = hn::IfThenElse(opens, hi, hn::IfThenElse(merge, hn::Max(ohi, hi), ohi));
        hn::StoreU(olo, d, open_lo + i);
        hn::StoreU(ohi, d, open_hi + i);
        const std::size_t count = hn::CountTrue(d, hn::Or(left, closes));
        if (count != 0) {
            OrBits(d, left, i, st.left_bits);
            OrBits(d, closes, i, st.closed_bits);
            handed += count;
        }
    }
    return static_cast<int>(handed);
}

// The lines of row `row` (of `lines` lines) whose centres may lie inside the capsule's vertical
// extent (y0, y1), with a line to spare on each side (the sections decide exactly): s0 .. s1, none
// when s1 < s0.
HWY_INLINE void SectionLines(const SweptCapsule& k, int row, int lines, int& s0, int& s1) {
    s0 = std::max(0, static_cast<int>(std::floor((k.y0 - row) * lines)) - 1);
    s1 = std::min(lines - 1, static_cast<int>(std::ceil((k.y1 - row) * lines)));
}

// A row's capsules in order until one leaves something for the caller (capsule_section.hpp).
template <class T>
HWY_INLINE int RowSections(const SweptCapsule* const* caps, const double* x0, int count, SectionRow<T>& st, int* s0_out,
                           int* n_out) {
    const double step = 1.0 / st.lines;
    for (int c = 0; c < count; ++c) {
        int s0, s1;
        SectionLines(*caps[c], st.row, st.lines, s0, s1);
        if (s1 < s0) continue;
        if (CapsuleSections(*caps[c], step, s0, s1 - s0 + 1, settle_bound(x0[c], st.margin), st) != 0) {
            *s0_out = s0;
            *n_out = s1 - s0 + 1;
            return c;
        }
    }
    return count;
}

int CapsuleSectionsImpl(const SweptCapsule* const* caps, const double* x0, int count, SectionRow<double>& st, int* s0,
                        int* n) {
    return RowSections(caps, x0, count, st, s0, n);
}

int CapsuleSectionsFloatImpl(const SweptCapsule* const* caps, const double* x0, int count, SectionRow<float>& st,
                             int* s0, int* n) {
    return RowSections(caps, x0, count, st, s0, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::raster {

CASTELJAU_SIMD_EXPORT(CapsuleSectionsImpl);
CASTELJAU_SIMD_EXPORT(CapsuleSectionsFloatImpl);

int capsule_sections(const SweptCapsule* const* caps, const double* x0, int count, SectionRow<double>& row, int* s0,
                     int* n) {
    return CASTELJAU_SIMD_DISPATCH(CapsuleSectionsImpl)(caps, x0, count, row, s0, n);
}

int capsule_sections(const SweptCapsule* const* caps, const double* x0, int count, SectionRow<float>& row, int* s0,
                     int* n) {
    return CASTELJAU_SIMD_DISPATCH(CapsuleSectionsFloatImpl)(caps, x0, count, row, s0, n);
}

}  // namespace casteljau::raster
#endif
