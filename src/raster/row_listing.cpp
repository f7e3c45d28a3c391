// Raster stage, row listing: the row vectors' pieces of a polyline's edges (list_row_pieces in
// engine.hpp), a SIMD vector of edges at a time.
//
// At text sizes most edges lie inside one pixel row and most others cross one row boundary, in an
// order that follows the outline, so listing them one at a time branches unpredictably (one row or
// more, up or down: callgrind's branch model counts a miss for every third edge of a CFF glyph at
// 12 px). Here every lane computes an edge's first piece and, for an edge over two rows, its
// second; the pieces go out lane by lane, the pointer advanced by each edge's piece count, with no
// branch. Edges over three rows or more are listed again, one by one, over the pieces they were
// given. The arithmetic is list_edge_pieces()'s, operation for operation (this file is compiled
// without fused multiply-adds), so the pieces are the same bits.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/row_listing.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "core/simd_dispatch.hpp"
#include "raster/engine.hpp"

HWY_BEFORE_NAMESPACE();
namespace casteljau::raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The vector listing needs four double lanes and 256-bit float vectors: x86 with AVX2 or better.
#undef CASTELJAU_ROW_LISTING_SIMD  // set by the previous target's pass
#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2
#define CASTELJAU_ROW_LISTING_SIMD 1

// std::min(a, b) and std::max(a, b), lane by lane, with their choice on ties (so signed zeros
// come out as they do).
template <class V>
HWY_INLINE V StdMin(V a, V b) {
    return hn::IfThenElse(hn::Lt(b, a), b, a);
}
template <class V>
HWY_INLINE V StdMax(V a, V b) {
    return hn::IfThenElse(hn::Lt(a, b), b, a);
}

// Pieces {xl, xr, dy, r} of the lanes of dd as four-float vectors: piece j is 128-bit block j / 4
// of out[j % 4].
template <class DD, class V = hn::Vec<DD>>
HWY_INLINE void Transpose(DD, V xl, V xr, V dy, V r, hn::Vec<hn::Rebind<float, DD>>* out) {
    const hn::Rebind<float, DD> df;
    const hn::Rebind<std::int32_t, DD> di;
    const auto fxl = hn::DemoteTo(df, xl), fxr = hn::DemoteTo(df, xr), fdy = hn::DemoteTo(df, dy);
    const auto fr = hn::BitCast(df, hn::DemoteTo(di, r));
    const auto a = hn::InterleaveLower(df, fxl, fdy), b = hn::InterleaveLower(df, fxr, fr);
    const auto c = hn::InterleaveUpper(df, fxl, fdy), e = hn::InterleaveUpper(df, fxr, fr);
    out[0] = hn::InterleaveLower(df, a, b);
    out[1] = hn::InterleaveUpper(df, a, b);
    out[2] = hn::InterleaveLower(df, c, e);
    out[3] = hn::InterleaveUpper(df, c, e);
}

// Stores piece j of Transpose's output at p.
template <int kLanes, class VF>
HWY_INLINE void StorePiece(const VF* v, int j, RowPiece* p) {
    float* f = reinterpret_cast<float*>(p);
    if constexpr (kLanes == 4) {
        hn::StoreU(v[j], hn::Full128<float>(), f);
    } else {
        const hn::Full128<float> dh;
        if (j < 4)
            hn::StoreU(hn::LowerHalf(dh, v[j]), dh, f);
        else
            hn::StoreU(hn::UpperHalf(dh, v[j - 4]), dh, f);
    }
}

// The L edges (L: lanes of dd) between the L + 1 points from xy: from the first point to the last,
// or reversed, from the last to the first.
template <bool kReverse, class DD>
HWY_INLINE RowPiece* ListBlock(DD dd, const double* xy, double fh, RowPiece* out, std::size_t& edges) {
    constexpr int L = static_cast<int>(hn::MaxLanes(DD()));
    using V = hn::Vec<DD>;
    V x0, y0, x1, y1;
    // Lane j holds the edge between points j and j + 1, taken backwards when reversed (and then
    // listed last to first).
    if constexpr (kReverse) {
        hn::LoadInterleaved2(dd, xy + 2, x0, y0);
        hn::LoadInterleaved2(dd, xy, x1, y1);
    } else {
        hn::LoadInterleaved2(dd, xy, x0, y0);
        hn::LoadInterleaved2(dd, xy + 2, x1, y1);
    }
    const V fhv = hn::Set(dd, fh), one = hn::Set(dd, 1.0), zero = hn::Zero(dd);
    y0 = hn::IfThenElse(hn::Lt(y0, fhv), y0, fhv);
    y1 = hn::IfThenElse(hn::Lt(y1, fhv), y1, fhv);
    edges += hn::CountTrue(dd, hn::Or(hn::Ne(x0, x1), hn::Ne(y0, y1)));
    const auto down = hn::Gt(y1, y0), up = hn::Lt(y1, y0);
    // floor_nn and ceil_nn: truncation, and one more where the value lies above it.
    const V t0 = hn::Trunc(y0), t1 = hn::Trunc(y1);
    const V c0 = hn::Add(t0, hn::IfThenElseZero(hn::Lt(t0, y0), one));
    const V c1 = hn::Add(t1, hn::IfThenElseZero(hn::Lt(t1, y1), one));
    // for_each_row's first and last rows, and the rows between them.
    const V r0 = hn::IfThenElse(down, t0, hn::Sub(c0, one));
    const V rend = hn::IfThenElse(down, hn::Sub(c1, one), t1);
    const V span = hn::IfThenElse(down, hn::Sub(rend, r0), hn::Sub(r0, rend));
    const auto single = hn::Le(span, zero);
    const V count = hn::IfThenElseZero(hn::Or(down, up), hn::Add(one, hn::Max(span, zero)));
    // The first row boundary crossed, and where: x0 + (yb - y0) k held to the edge's x range.
    const V yb = hn::IfThenElse(down, hn::Add(r0, one), r0);
    const V k = hn::Div(hn::Sub(x1, x0), hn::Sub(y1, y0));
    const V xlo = StdMin(x0, x1), xhi = StdMax(x0, x1);
    V xb = hn::Add(x0, hn::Mul(hn::Sub(yb, y0), k));
    xb = hn::IfThenElse(hn::Lt(xb, xlo), xlo, hn::IfThenElse(hn::Lt(xhi, xb), xhi, xb));
    const V xe = hn::IfThenElse(single, x1, xb), ye = hn::IfThenElse(single, y1, yb);
    hn::Vec<hn::Rebind<float, DD>> first[4], second[4];
    Transpose(dd, StdMin(x0, xe), StdMax(x0, xe), hn::Sub(ye, y0), r0, first);
    Transpose(dd, StdMin(xb, x1), StdMax(xb, x1), hn::Sub(y1, yb), rend, second);
    alignas(64) std::int32_t counts[L];
    hn::Store(hn::DemoteTo(hn::Rebind<std::int32_t, DD>(), count), hn::Rebind<std::int32_t, DD>(), counts);
    RowPiece* at[L];
    for (int i = 0; i < L; ++i) {
        const int j = kReverse ? L - 1 - i : i;
        StorePiece<L>(first, j, out);
        StorePiece<L>(second, j, out + 1);
        at[j] = out;
        out += counts[j];
    }
    // Edges over three rows or more: listed again over their pieces.
    const auto longer = hn::Gt(span, one);
    if (!hn::AllFalse(dd, longer)) {
        alignas(64) double ex0[L], ey0[L], ex1[L], ey1[L];
        hn::Store(x0, dd, ex0);
        hn::Store(y0, dd, ey0);
        hn::Store(x1, dd, ex1);
        hn::Store(y1, dd, ey1);
        std::uint8_t mask_bits[8] = {};
        hn::StoreMaskBits(dd, longer, mask_bits);
        for (unsigned bits = mask_bits[0]; bits != 0; bits &= bits - 1) {
            const int j = __builtin_ctz(bits);
            list_edge_pieces(at[j], ex0[j], ey0[j], ex1[j], ey1[j]);
        }
    }
    return out;
}

#endif  // CASTELJAU_ROW_LISTING_SIMD

template <bool kReverse, class DD>
HWY_INLINE RowPiece* ListAll(DD dd, const double* xy, std::size_t n, double fh, RowPiece* out, std::size_t& edges) {
    std::size_t i = 0;  // edges listed so far
#ifdef CASTELJAU_ROW_LISTING_SIMD
    constexpr std::size_t L = hn::MaxLanes(DD());
    for (; i + L < n; i += L) out = ListBlock<kReverse>(dd, xy + 2 * (kReverse ? n - 1 - i - L : i), fh, out, edges);
#else
    (void)dd;
#endif
    // The last edges (fewer than a vector; all of them on targets without the vector listing).
    return list_polyline_pieces<kReverse>(kReverse ? xy : xy + 2 * i, n - i, fh, out, edges);
}

RowPiece* ListRowPiecesImpl(const double* xy, std::size_t n, bool reverse, double fh, RowPiece* out,
                            std::size_t& edges) {
    const hn::CappedTag<double, 8> dd;
    return reverse ? ListAll<true>(dd, xy, n, fh, out, edges) : ListAll<false>(dd, xy, n, fh, out, edges);
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::raster {
CASTELJAU_SIMD_EXPORT(ListRowPiecesImpl);

RowPiece* list_row_pieces(const double* xy, std::size_t n, bool reverse, double fh, RowPiece* out, std::size_t& edges) {
    return CASTELJAU_SIMD_DISPATCH(ListRowPiecesImpl)(xy, n, reverse, fh, out, edges);
}
}  // namespace casteljau::raster
#endif
