// Internal: the row-vector area kernel (see RowPiece in raster_internal.hpp), for every SIMD target.
// Highway's per-target header: include it after <hwy/highway.h> in a file that foreach_target.h
// compiles once per target (coverage.cpp; bench/accumulation_floor.cpp measures its floor).

// Per-target include guard (toggled by foreach_target.h for each target).
#if defined(CASTELJAU_RASTER_ROW_VECTOR_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef CASTELJAU_RASTER_ROW_VECTOR_INL_H_
#undef CASTELJAU_RASTER_ROW_VECTOR_INL_H_
#else
#define CASTELJAU_RASTER_ROW_VECTOR_INL_H_
#endif

#include <hwy/highway.h>

#include "raster/raster_internal.hpp"

HWY_BEFORE_NAMESPACE();
namespace casteljau::raster {
namespace HWY_NAMESPACE {

// Adds piece p's area to the N pixels of row from pixel i (one vector of d): per pixel c, with
// u0 = max(xl, c) and u1 = min(xr, c + 1), k * (max(u1 - u0, 0) * (c + 1 - (u0 + u1) / 2) +
// max(min(xr, c) - xl, 0)); a vertical piece (xl == xr, k = dy) adds k * clamp(c + 1 - x, 0, 1).
// Both are zero for every pixel with c + 1 <= xl.
template <class D>
HWY_INLINE void AddPieceVector(D d, const RowPiece& p, int i, float* HWY_RESTRICT row) {
    namespace hn = hwy::HWY_NAMESPACE;
    const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const auto xl = hn::Set(d, p.xl), xr = hn::Set(d, p.xr), k = hn::Set(d, p.k);
    const auto cl = hn::Add(hn::Iota(d, 0.0f), hn::Set(d, static_cast<float>(i)));
    const auto cr = hn::Add(cl, one);
    if (p.xl == p.xr) {
        const auto part = hn::Min(hn::Max(hn::Sub(cr, xl), zero), one);
        hn::StoreU(hn::MulAdd(k, part, hn::LoadU(d, row + i)), d, row + i);
        return;
    }
    const auto u0 = hn::Max(xl, cl), u1 = hn::Min(xr, cr);
    const auto len = hn::Max(hn::Sub(u1, u0), zero);
    const auto mid = hn::NegMulAdd(hn::Add(u0, u1), hn::Set(d, 0.5f), cr);
    const auto left = hn::Max(hn::Sub(hn::Min(xr, cl), xl), zero);
    hn::StoreU(hn::MulAdd(k, hn::MulAdd(len, mid, left), hn::LoadU(d, row + i)), d, row + i);
}

// One granule of a row (kRowGranule floats, raster_internal.hpp) and its lane count.
using GranuleTag = hwy::HWY_NAMESPACE::CappedTag<float, kRowGranule>;
HWY_INLINE int GranuleLanes() { return static_cast<int>(hwy::HWY_NAMESPACE::Lanes(GranuleTag())); }

// Calls f(tag, i) for the vectors of a row of `stride` floats (whole granules) from float `from` (a
// multiple of d's lanes): whole vectors of d, then the row's last granule when the row does not end
// on a whole vector.
template <class D, class F>
HWY_INLINE void ForRowVectors(D d, int from, int stride, F&& f) {
    const int N = static_cast<int>(hwy::HWY_NAMESPACE::Lanes(d));
    int i = from;
    for (; i + N <= stride; i += N) f(d, i);
    if (i < stride) f(GranuleTag(), i);
}

// Adds piece p's area to row[0, stride) (stride: whole granules), from the vector holding pixel
// floor(xl) (xl >= 0: the walk's coordinates are clamped to the box).
template <class D>
HWY_INLINE void AddRowPiece(D d, const RowPiece& p, float* HWY_RESTRICT row, int stride) {
    const int N = static_cast<int>(hwy::HWY_NAMESPACE::Lanes(d));  // a power of two
    ForRowVectors(d, static_cast<int>(p.xl) & -N, stride, [&](auto dv, int i) { AddPieceVector(dv, p, i, row); });
}

// AddRowPiece for rows of exactly kGranules granules (a glyph's rows at text sizes): every vector
// of the row, unrolled, so there is no loop to set up per piece (the vectors left of xl add zero).
// A row that ends in half a vector takes a half-width vector there: where wide vectors run at half
// rate (AVX-512 on Zen 4), that halves the work of a row of one granule.
template <int kGranules, class D>
HWY_INLINE void AddRowPieceFixed(D d, const RowPiece& p, float* HWY_RESTRICT row) {
    namespace hn = hwy::HWY_NAMESPACE;
    constexpr int kPer = static_cast<int>(hn::MaxLanes(D()) / hn::MaxLanes(GranuleTag()));  // granules per vector
    constexpr int kWhole = kGranules / kPer;
    const int N = static_cast<int>(hn::Lanes(d));
    for (int v = 0; v < kWhole; ++v) AddPieceVector(d, p, v * N, row);
    for (int g = kWhole * kPer; g < kGranules; ++g) AddPieceVector(GranuleTag(), p, g * GranuleLanes(), row);
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::raster
HWY_AFTER_NAMESPACE();

#endif  // per-target include guard
