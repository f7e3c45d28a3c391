// Raster stage, coverage: per-row prefix sum of the (double) accumulation buffer mapped through the fill
// rule to 8-bit coverage, and the row-vector accumulation of narrow shapes (RowPiece in
// raster_internal.hpp). Vectorised with Highway (runtime dispatch to the best instruction set the
// CPU has, simd_dispatch.hpp): the prefix sum is an in-register inclusive scan per vector plus a running carry.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "raster/coverage.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "raster/row_vector-inl.h"

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstring>

#include "raster/raster_internal.hpp"
#include "core/simd_dispatch.hpp"

HWY_BEFORE_NAMESPACE();
namespace casteljau::raster {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// Fill rule and 8-bit conversion of accumulated values (any lane count).
template <class D, class V>
HWY_INLINE V ApplyRule(D d, V v, FillRule rule) {
    auto a = hn::Abs(v);
    if (rule == FillRule::NonZero) return hn::Min(a, hn::Set(d, 1.0));
    const auto two = hn::Set(d, 2.0);
    a = hn::NegMulAdd(hn::Floor(hn::Mul(a, hn::Set(d, 0.5))), two, a);  // |v| mod 2, in [0, 2)
    return hn::Min(a, hn::Sub(two, a));                                 // distance to an even integer
}

// Coverage in [0, 1] (double or float lanes) to 8-bit, rounded to nearest, half-way up.
template <class D, class V>
HWY_INLINE void StoreCoverage(D d, V a, std::uint8_t* HWY_RESTRICT out) {
    const hn::Rebind<std::uint8_t, D> du8;
    if constexpr (sizeof(hn::TFromD<D>) == 8) {
        const hn::Rebind<std::int32_t, D> di;
        const auto scaled = hn::MulAdd(a, hn::Set(d, 255.0), hn::Set(d, kRoundUp));  // see kRoundUp
        hn::StoreU(hn::DemoteTo(du8, hn::DemoteTo(di, scaled)), du8, out);
    } else {
        // a x 255 + (kRoundUpFloat - 1/2) rounded to the nearest integer by adding 2^23, whose
        // float then holds that integer in its low mantissa bits: the level of kRoundUpFloat's
        // truncation (a tie, which would go to even, needs a x 255 exactly 2^-12 below a half level).
        const hn::RebindToUnsigned<D> du;
        const auto scaled = hn::MulAdd(a, hn::Set(d, 255.0f), hn::Set(d, static_cast<float>(kRoundUpFloat - 0.5)));
        const auto bits = hn::BitCast(du, hn::Add(scaled, hn::Set(d, 8388608.0f)));
        hn::StoreU(hn::TruncateTo(du8, bits), du8, out);
    }
}

// Scans acc[i, to) in whole vectors of tag d: `scan` makes a vector's inclusive prefix sum and
// `last` broadcasts its last lane. The carry chain is one add per vector; the in-register scans of
// successive vectors are independent of it. Clears what it reads; returns where it stopped.
template <class D, class Scan, class Last>
HWY_INLINE int ScanVectors(D d, hn::TFromD<D>* HWY_RESTRICT acc, std::uint8_t* HWY_RESTRICT cov, int i, int to,
                           hn::TFromD<D>& sum, FillRule rule, Scan scan, Last last) {
    const int n = static_cast<int>(hn::Lanes(d));
    if (to - i < n) return i;
    const auto zero = hn::Zero(d);
    auto carry = hn::Set(d, sum);
    for (; i + n <= to; i += n) {
        const auto v = scan(hn::LoadU(d, acc + i));
        hn::StoreU(zero, d, acc + i);
        const auto out = hn::Add(v, carry);
        carry = hn::Add(carry, last(v));
        StoreCoverage(d, ApplyRule(d, out, rule), cov + i);
    }
    sum = hn::GetLane(carry);
    return i;
}

// Scans acc[from, to) from the running sum `start`; returns the sum at `to`. Double cells keep
// rows crossing hundreds of stacked edges exact to far below 1/255; float cells (narrower shapes)
// have twice the lanes. Each 128-bit block is scanned in register (kBlock lanes), a 256-bit
// vector then adds its lower half's total to its upper half; the tail goes one cell at a time.
template <class T>
HWY_INLINE T ScanRange(T* HWY_RESTRICT acc, std::uint8_t* HWY_RESTRICT cov, int from, int to, T start, FillRule rule) {
    T sum = start;
    int i = from;
#if HWY_TARGET != HWY_SCALAR
    constexpr int kBlock = 16 / sizeof(T);
    auto scan_block = [](auto d, auto v) {
        v = hn::Add(v, hn::ShiftLeftLanes<1>(d, v));
        if constexpr (kBlock == 4) v = hn::Add(v, hn::ShiftLeftLanes<2>(d, v));
        return v;
    };
#endif
#if HWY_TARGET != HWY_SCALAR && HWY_MAX_BYTES >= 32
    {
        const hn::FixedTag<T, 2 * kBlock> dw;
        i = ScanVectors(
            dw, acc, cov, i, to, sum, rule,
            [dw, scan_block](auto v) {
                v = scan_block(dw, v);
                return hn::Add(v, hn::ConcatLowerLower(dw, hn::Broadcast<kBlock - 1>(v), hn::Zero(dw)));
            },
            [dw](auto v) { return hn::Broadcast<kBlock - 1>(hn::ConcatUpperUpper(dw, v, v)); });
    }
#endif
#if HWY_TARGET != HWY_SCALAR
    {
        const hn::FixedTag<T, kBlock> dn;
        i = ScanVectors(
            dn, acc, cov, i, to, sum, rule, [dn, scan_block](auto v) { return scan_block(dn, v); },
            [](auto v) { return hn::Broadcast<kBlock - 1>(v); });
    }
#endif
    for (; i < to; ++i) {
        sum += acc[i];
        acc[i] = T(0);
        cov[i] = coverage_u8(sum, rule);
    }
    return sum;
}

// One row (see ScanRows in raster_internal.hpp); valid coverage is cov[from, end), from = end = 0
// when no block was touched.
struct ScanSpan {
    int from, end;
};

// Touched blocks are taken one at a time, in order, from the row's bit words: a block inside the
// row is one fixed-length scan (whole vectors, no tail), the gap before it one fill of the running
// coverage. Its branches follow the count of touched blocks, not the lengths of their runs, which
// a branch predictor cannot learn.
template <class T>
HWY_INLINE ScanSpan ScanBlocksImpl(T* acc, std::uint8_t* cov, const std::uint64_t* bm, int words, int w, int stride,
                                   FillRule rule) {
    constexpr int kCells = 1 << kScanBlockShift;
    int from = -1, pos = 0;
    T sum = 0;
    for (int wi = 0; wi < words; ++wi) {
        for (std::uint64_t m = bm[wi]; m != 0; m &= m - 1) {
            const int a0 = ((wi << 6) + __builtin_ctzll(m)) << kScanBlockShift;
            if (from < 0) from = pos = a0;
            if (a0 > pos && pos < w)
                std::memset(cov + pos, coverage_u8(sum, rule), static_cast<std::size_t>(std::min(a0, w) - pos));
            if (a0 + kCells <= w) {
                sum = ScanRange(acc, cov, a0, a0 + kCells, sum, rule);
                pos = a0 + kCells;
                continue;
            }
            // The block holding w, or one past it: cells at or past w are spill cells, cleared only.
            const int to = std::min(a0 + kCells, w);
            if (to > a0) sum = ScanRange(acc, cov, a0, to, sum, rule);
            for (int k = std::max(a0, w); k < std::min(a0 + kCells, stride); ++k) acc[k] = T(0);
            pos = std::max(pos, to);
        }
    }
    if (from < 0) return {0, 0};
    if (pos < w) {  // beyond the last touched cell the coverage is constant
        const std::uint8_t tail = coverage_u8(sum, rule);
        if (tail != 0) {
            std::memset(cov + pos, tail, static_cast<std::size_t>(w - pos));
            pos = w;
        }
    }
    return {from, pos};
}

// Every row of cells `acc` (s.acc or s.facc) to the sink, with the exact cells' patches (double
// cells only; float cells have none).
template <class T>
HWY_INLINE void ScanRowsOf(const ScanRows& s, T* acc, SpanSink& sink) {
    std::size_t pi = 0;
    for (int r = 0; r < s.h; ++r) {
        const std::size_t row_base = static_cast<std::size_t>(r) * static_cast<std::size_t>(s.stride);
        std::uint8_t* const direct = s.direct.at(r);
        std::uint8_t* const cov = direct ? direct : s.cov;
        const ScanSpan span = ScanBlocksImpl(acc + row_base, cov, s.blocks + static_cast<std::size_t>(r) * s.words,
                                             s.words, s.w, s.stride, s.rule);
        const std::size_t row_end = row_base + static_cast<std::size_t>(s.stride);
        for (; pi < s.npatches && s.patches[pi].first < row_end; ++pi)
            if (span.end > span.from) cov[s.patches[pi].first - row_base] = s.patches[pi].second;
        if (span.end > span.from && !direct)
            sink.row(s.oy + r, s.ox + span.from, span.end - span.from, s.cov + span.from);
    }
}

void ScanRowsImpl(const ScanRows& s, SpanSink& sink) {
    if (s.facc)
        ScanRowsOf(s, s.facc, sink);
    else
        ScanRowsOf(s, s.acc, sink);
}

int RowVectorLanesImpl() {
    const hn::ScalableTag<float> d;
    return static_cast<int>(hn::Lanes(d));
}

int RowVectorGranuleImpl() { return GranuleLanes(); }

// Pieces listed in outline order: consecutive ones often lie in one row (a curve's short edges),
// and adding them one after the other would chain each row's additions through memory, every one
// waiting for the store of the one before. Taking the list's four quarters in turn puts pieces from
// distant parts of the outline next to each other. Each row still gets the same pieces; only the
// order of their float additions changes.
template <int kGranules, class D>
HWY_INLINE void AccumulateFixed(D d, const RowPiece* HWY_RESTRICT pieces, std::size_t n, bool outline_order,
                                float* HWY_RESTRICT acc) {
    const std::size_t stride = static_cast<std::size_t>(kGranules * GranuleLanes());
    auto add = [&](const RowPiece& p) {
        AddRowPieceFixed<kGranules>(d, p, acc + static_cast<std::size_t>(p.r) * stride);
    };
    const std::size_t q = outline_order ? n / 4 : 0;
    for (std::size_t k = 0; k < q; ++k) {
        add(pieces[k]);
        add(pieces[q + k]);
        add(pieces[2 * q + k]);
        add(pieces[3 * q + k]);
    }
    for (std::size_t k = 4 * q; k < n; ++k) add(pieces[k]);
}

// Listed pieces {xl, xr, dy, r} to make_row_piece's {xl, xr, k, r}, with the same arithmetic (so
// the same bits), whole vectors of pieces at a time; the rest one by one.
HWY_INLINE void PreparePieces(RowPiece* HWY_RESTRICT pieces, std::size_t n) {
    static_assert(sizeof(RowPiece) == 4 * sizeof(float) && offsetof(RowPiece, r) == 3 * sizeof(float),
                  "a piece is four 32-bit lanes");
    const hn::ScalableTag<float> d;
    const std::size_t N = hn::Lanes(d);
    // The r lanes travel through as float bits, untouched.
    float* HWY_RESTRICT f = reinterpret_cast<float*>(pieces);
    const auto narrow = hn::Set(d, 1e-4f), half = hn::Set(d, 0.5f);
    std::size_t i = 0;
    for (; i + N <= n; i += N) {
        hn::Vec<decltype(d)> xl, xr, dy, r;
        hn::LoadInterleaved4(d, f + 4 * i, xl, xr, dy, r);
        const auto width = hn::Sub(xr, xl);
        const auto vertical = hn::Lt(width, narrow);
        const auto mid = hn::Mul(half, hn::Add(xl, xr));
        const auto k = hn::IfThenElse(vertical, dy, hn::Div(dy, width));
        hn::StoreInterleaved4(hn::IfThenElse(vertical, mid, xl), hn::IfThenElse(vertical, mid, xr), k, r, d, f + 4 * i);
    }
    for (; i < n; ++i) pieces[i] = make_row_piece(pieces[i].r, pieces[i].xl, pieces[i].xr, pieces[i].k);
}

void RowVectorAccumulateImpl(RowPiece* HWY_RESTRICT pieces, std::size_t n, bool outline_order, float* HWY_RESTRICT acc,
                             int stride) {
    PreparePieces(pieces, n);
    const hn::ScalableTag<float> d;
    // Rows of up to eight granules (64 px): unrolled, in whole vectors and a granule.
    switch (stride / GranuleLanes()) {
        case 1: return AccumulateFixed<1>(d, pieces, n, outline_order, acc);
        case 2: return AccumulateFixed<2>(d, pieces, n, outline_order, acc);
        case 3: return AccumulateFixed<3>(d, pieces, n, outline_order, acc);
        case 4: return AccumulateFixed<4>(d, pieces, n, outline_order, acc);
        case 5: return AccumulateFixed<5>(d, pieces, n, outline_order, acc);
        case 6: return AccumulateFixed<6>(d, pieces, n, outline_order, acc);
        case 7: return AccumulateFixed<7>(d, pieces, n, outline_order, acc);
        case 8: return AccumulateFixed<8>(d, pieces, n, outline_order, acc);
        default: break;
    }
    for (std::size_t k = 0; k < n; ++k)
        AddRowPiece(d, pieces[k], acc + static_cast<std::size_t>(pieces[k].r) * static_cast<std::size_t>(stride),
                    stride);
}

void RowVectorEmitImpl(const RowVectorRows& s, SpanSink& sink) {
    const hn::ScalableTag<float> d;
    for (int r = 0; r < s.h; ++r) {
        float* HWY_RESTRICT row = s.acc + static_cast<std::size_t>(r) * static_cast<std::size_t>(s.stride);
        // Cells left of a row's first piece hold exactly zero (a piece adds nothing left of it):
        // the row goes out from its first non-zero cell, and not at all when it has none.
        int from = INT_MAX;
        ForRowVectors(d, 0, s.stride, [&](auto dv, int i) {
            const auto a = hn::LoadU(dv, row + i);
            if (from == INT_MAX) {
                const std::intptr_t k = hn::FindFirstTrue(dv, hn::Ne(a, hn::Zero(dv)));
                if (k >= 0) from = i + static_cast<int>(k);
            }
            hn::StoreU(hn::Zero(dv), dv, row + i);
            StoreCoverage(dv, ApplyRule(dv, a, s.rule), s.cov + i);
        });
        if (from < s.w) sink.row(s.oy + r, s.ox + from, s.w - from, s.cov + from);
    }
}

}  // namespace HWY_NAMESPACE
}  // namespace casteljau::raster
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace casteljau::raster {
CASTELJAU_SIMD_EXPORT(ScanRowsImpl);

CASTELJAU_SIMD_EXPORT(RowVectorLanesImpl);
CASTELJAU_SIMD_EXPORT(RowVectorGranuleImpl);
CASTELJAU_SIMD_EXPORT(RowVectorAccumulateImpl);
CASTELJAU_SIMD_EXPORT(RowVectorEmitImpl);

void scan_rows(const ScanRows& rows, SpanSink& sink) { CASTELJAU_SIMD_DISPATCH(ScanRowsImpl)(rows, sink); }

// Not cached: tests switch targets, and the stride must be whole granules of the kernels' target.
int row_vector_lanes() { return CASTELJAU_SIMD_DISPATCH(RowVectorLanesImpl)(); }
int row_vector_granule() { return CASTELJAU_SIMD_DISPATCH(RowVectorGranuleImpl)(); }
void row_vector_accumulate(RowPiece* pieces, std::size_t n, bool outline_order, float* acc, int stride) {
    CASTELJAU_SIMD_DISPATCH(RowVectorAccumulateImpl)(pieces, n, outline_order, acc, stride);
}
void row_vector_emit(const RowVectorRows& rows, SpanSink& sink) {
    CASTELJAU_SIMD_DISPATCH(RowVectorEmitImpl)(rows, sink);
}

}  // namespace casteljau::raster
#endif
