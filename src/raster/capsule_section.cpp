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

// One capsule on lines s0 .. s0 + n - 1 of the row (capsule_section.hpp): returns how many lines
// it left for the caller (a bit set in left_bits or closed_bits). T: the lanes' type.
template <class T>
HWY_INLINE int CapsuleSections(const SweptCapsule& k, double r, int row, double step, int s0, int n,
                               T* HWY_RESTRICT lo_out, T* HWY_RESTRICT hi_out, T* HWY_RESTRICT open_lo,
                               T* HWY_RESTRICT open_hi, T* HWY_RESTRICT closed_hi,
                               std::uint64_t* HWY_RESTRICT left_bits, std::uint64_t* HWY_RESTRICT closed_bits) {
    const hn::ScalableTag<T> d;
    const int lanes = static_cast<int>(hn::Lanes(d));
    static_assert(kMaxSectionLines % 64 == 0);
    for (int w = 0; w < (n + 63) / 64; ++w) left_bits[w] = closed_bits[w] = 0;
    // Heights above the row's top: small wherever a line meets the capsule, so that float keeps them
    // to its last place, however far down the image the row is.
    const auto r2 = Splat(d, r * r), y0 = Splat(d, k.y0 - row), y1 = Splat(d, k.y1 - row);
    const auto inf = Splat(d, INFINITY), neg_inf = Splat(d, -INFINITY);
    std::size_t handed = 0;
    for (int i = 0; i < n; i += lanes) {
        const auto s = hn::Iota(d, static_cast<T>(s0 + i));
        const auto c = hn::Mul(hn::Add(s, Splat(d, 0.5)), Splat(d, step));
        auto lo = inf, hi = neg_inf;
        if (k.start_disc) AddDisc(d, c, row, k.ax, k.ay, r2, lo, hi);
        AddDisc(d, c, row, k.bx, k.by, r2, lo, hi);
        if (k.band) AddBand(d, c, row, k, r, lo, hi);
        const auto hit = hn::And(hn::And(hn::Gt(c, y0), hn::Lt(c, y1)),
                                 hn::And(hn::Lt(lo, hi), hn::FirstN(d, static_cast<std::size_t>(n - i))));
        // Fold into the open intervals: take where there is none, merge where the section meets it
        // and stays right of the closed ones, advance where it lies right of it (the open interval
        // is closed and handed out, the section opens).
        auto olo = hn::LoadU(d, open_lo + i), ohi = hn::LoadU(d, open_hi + i);
        const auto take = hn::And(hit, hn::Gt(olo, ohi));
        const auto meets = hn::And(hn::Le(lo, ohi), hn::Ge(hi, olo));
        const auto merge = hn::And(hit, hn::And(meets, hn::Gt(lo, hn::LoadU(d, closed_hi + i))));
        const auto advance = hn::AndNot(take, hn::And(hit, hn::Gt(lo, ohi)));
        const auto left = hn::AndNot(hn::Or(hn::Or(take, merge), advance), hit);
        hn::StoreU(hn::IfThenElse(advance, ohi, hn::LoadU(d, closed_hi + i)), d, closed_hi + i);
        hn::StoreU(hn::IfThenElse(left, lo, olo), d, lo_out + i);
        hn::StoreU(hn::IfThenElse(left, hi, ohi), d, hi_out + i);
        const auto opens = hn::Or(take, advance);
        olo = hn::IfThenElse(opens, lo, hn::IfThenElse(merge, hn::Min(olo, lo), olo));
        ohi = hn::IfThenElse(opens, hi, hn::IfThenElse(merge, hn::Max(ohi, hi), ohi));
        hn::StoreU(olo, d, open_lo + i);
        hn::StoreU(ohi, d, open_hi + i);
        const std::size_t count = hn::CountTrue(d, hn::Or(left, advance));
        if (count != 0) {
            OrBits(d, left, i, left_bits);
            OrBits(d, advance, i, closed_bits);
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
HWY_INLINE int RowSections(const SweptCapsule* const* caps, int count, double r, int row, int lines, T* HWY_RESTRICT lo,
                           T* HWY_RESTRICT hi, T* HWY_RESTRICT open_lo, T* HWY_RESTRICT open_hi,
                           T* HWY_RESTRICT closed_hi, std::uint64_t* HWY_RESTRICT left_bits,
                           std::uint64_t* HWY_RESTRICT closed_bits, int* s0_out, int* n_out) {
    const double step = 1.0 / lines;
    for (int c = 0; c < count; ++c) {
        int s0, s1;
        SectionLines(*caps[c], row, lines, s0, s1);
        if (s1 < s0) continue;
        if (CapsuleSections(*caps[c], r, row, step, s0, s1 - s0 + 1, lo, hi, open_lo + s0, open_hi + s0, closed_hi + s0,
                            left_bits, closed_bits) != 0) {
            *s0_out = s0;
            *n_out = s1 - s0 + 1;
            return c;
        }
    }
    return count;
}

int CapsuleSectionsImpl(const SweptCapsule* const* caps, int count, double r, int row, int lines, double* lo,
                        double* hi, double* open_lo, double* open_hi, double* closed_hi, std::uint64_t* left_bits,
                        std::uint64_t* closed_bits, int* s0, int* n) {
    return RowSections(caps, count, r, row, lines, lo, hi, open_lo, open_hi, closed_hi, left_bits, closed_bits, s0, n);
}

int CapsuleSectionsFloatImpl(const SweptCapsule* const* caps, int count, double r, int row, int lines, float* lo,
                             float* hi, float* open_lo, float* open_hi, float* closed_hi, std::uint64_t* left_bits,
                             std::uint64_t* closed_bits, int* s0, int* n) {
    return RowSections(caps, count, r, row, lines, lo, hi, open_lo, open_hi, closed_hi, left_bits, closed_bits, s0, n);
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::raster {

CASTELJAU_SIMD_EXPORT(CapsuleSectionsImpl);
CASTELJAU_SIMD_EXPORT(CapsuleSectionsFloatImpl);

int capsule_sections(const SweptCapsule* const* caps, int count, double r, int row, int lines, double* lo, double* hi,
                     double* open_lo, double* open_hi, double* closed_hi, std::uint64_t* left_bits,
                     std::uint64_t* closed_bits, int* s0, int* n) {
    return CASTELJAU_SIMD_DISPATCH(CapsuleSectionsImpl)(caps, count, r, row, lines, lo, hi, open_lo, open_hi, closed_hi,
                                                        left_bits, closed_bits, s0, n);
}

int capsule_sections(const SweptCapsule* const* caps, int count, double r, int row, int lines, float* lo, float* hi,
                     float* open_lo, float* open_hi, float* closed_hi, std::uint64_t* left_bits,
                     std::uint64_t* closed_bits, int* s0, int* n) {
    return CASTELJAU_SIMD_DISPATCH(CapsuleSectionsFloatImpl)(caps, count, r, row, lines, lo, hi, open_lo, open_hi,
                                                             closed_hi, left_bits, closed_bits, s0, n);
}

}  // namespace casteljau::raster
#endif
