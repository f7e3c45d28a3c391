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
    const hn::Rebind<std::int32_t, D> di;
    const hn::Rebind<std::uint8_t, D> du8;
    const double bias = sizeof(hn::TFromD<D>) == 8 ? kRoundUp : kRoundUpFloat;  // see kRoundUp
    const auto scaled = hn::MulAdd(a, hn::Set(d, 255.0), hn::Set(d, bias));
    if constexpr (sizeof(hn::TFromD<D>) == 8)
        hn::StoreU(hn::DemoteTo(du8, hn::DemoteTo(di, scaled)), du8, out);
    else
        hn::StoreU(hn::DemoteTo(du8, hn::ConvertTo(di, scaled)), du8, out);
}

// Scans acc[i, to) in whole vectors of tag d: `scan` makes a vector's inclusive prefix sum and
// `last` broadcasts its last lane. The carry chain is one add per vector; the in-register scans of
// successive vectors are independent of it. Clears what it reads; returns where it stopped.
template <class D, class Scan, class Last>
HWY_INLINE int ScanVectors(D d, double* HWY_RESTRICT acc, std::uint8_t* HWY_RESTRICT cov, int i, int to, double& sum,
                           FillRule rule, Scan scan, Last last) {
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

HWY_INLINE double ScanRange(double* HWY_RESTRICT acc, std::uint8_t* HWY_RESTRICT cov, int from, int to, double start,
                            FillRule rule) {
    double sum = start;
    int i = from;
    // Double precision keeps rows crossing hundreds of stacked edges exact to far below 1/255.
#if HWY_TARGET != HWY_SCALAR && HWY_MAX_BYTES >= 32
    // Four doubles per 256-bit vector: scan within each 128-bit half, then add the lower half's
    // total to the upper half.
    {
        const hn::FixedTag<double, 4> d4;
        i = ScanVectors(
            d4, acc, cov, i, to, sum, rule,
            [d4](auto v) {
                v = hn::Add(v, hn::ShiftLeftLanes<1>(d4, v));                                    // a, a+b, c, c+d
                return hn::Add(v, hn::ConcatLowerLower(d4, hn::Broadcast<1>(v), hn::Zero(d4)));  // + 0, 0, a+b, a+b
            },
            [d4](auto v) { return hn::Broadcast<1>(hn::ConcatUpperUpper(d4, v, v)); });
    }
#endif
#if HWY_TARGET != HWY_SCALAR
    // Two doubles per 128-bit vector (the whole row on SSE targets, the tail on wider ones).
    {
        const hn::FixedTag<double, 2> d2;
        i = ScanVectors(
            d2, acc, cov, i, to, sum, rule, [d2](auto v) { return hn::Add(v, hn::ShiftLeftLanes<1>(d2, v)); },
            [](auto v) { return hn::Broadcast<1>(v); });
    }
#endif
    for (; i < to; ++i) {
        sum += acc[i];
        acc[i] = 0.0;
        cov[i] = coverage_u8(sum, rule);
    }
    return sum;
}

// One row (see ScanRows in raster_internal.hpp); valid coverage is cov[from, end), from = end = 0
// when no block was touched.
struct ScanSpan {
    int from, end;
};

HWY_INLINE ScanSpan ScanBlocksImpl(double* acc, std::uint8_t* cov, const std::uint64_t* bm, int words, int w,
                                   int stride, FillRule rule) {
    const int nb = words * 64;
    auto bit = [&](int b) { return b < nb && ((bm[b >> 6] >> (b & 63)) & 1) != 0; };
    auto next_set = [&](int b) {
        while (b < nb) {
            const std::uint64_t v = bm[b >> 6] >> (b & 63);
            if (v) return b + __builtin_ctzll(v);
            b = (b | 63) + 1;
        }
        return nb;
    };
    const int first = next_set(0);
    if (first >= nb) return {0, 0};
    const int from = first << kScanBlockShift;
    double sum = 0;
    int pos = from;
    for (int b = first; b < nb;) {
        int e = b + 1;
        while (bit(e)) ++e;
        const int a0 = b << kScanBlockShift;
        const int a1 = std::min(e << kScanBlockShift, stride);
        if (a0 > pos && pos < w)
            std::memset(cov + pos, coverage_u8(sum, rule), static_cast<std::size_t>(std::min(a0, w) - pos));
        const int to = std::min(a1, w);
        if (to > a0) sum = ScanRange(acc, cov, a0, to, sum, rule);
        for (int k = std::max(a0, w); k < a1; ++k) acc[k] = 0.0;  // spill cells
        if (to > pos) pos = to;
        b = next_set(e);
    }
    if (pos < w) {  // beyond the last touched cell the coverage is constant
        const std::uint8_t tail = coverage_u8(sum, rule);
        if (tail != 0) {
            std::memset(cov + pos, tail, static_cast<std::size_t>(w - pos));
            pos = w;
        }
    }
    return {from, pos};
}

void ScanRowsImpl(const ScanRows& s, SpanSink& sink) {
    std::size_t pi = 0;
    for (int r = 0; r < s.h; ++r) {
        const std::size_t row_base = static_cast<std::size_t>(r) * static_cast<std::size_t>(s.stride);
        const ScanSpan span = ScanBlocksImpl(s.acc + row_base, s.cov, s.blocks + static_cast<std::size_t>(r) * s.words,
                                             s.words, s.w, s.stride, s.rule);
        const std::size_t row_end = row_base + static_cast<std::size_t>(s.stride);
        for (; pi < s.npatches && s.patches[pi].first < row_end; ++pi)
            if (span.end > span.from) s.cov[s.patches[pi].first - row_base] = s.patches[pi].second;
        if (span.end > span.from) sink.row(s.oy + r, s.ox + span.from, span.end - span.from, s.cov + span.from);
    }
}

int RowVectorLanesImpl() {
    const hn::ScalableTag<float> d;
    return static_cast<int>(hn::Lanes(d));
}

void RowVectorAccumulateImpl(const RowPiece* HWY_RESTRICT pieces, std::size_t n, float* HWY_RESTRICT acc, int stride) {
    const hn::ScalableTag<float> d;
    for (std::size_t k = 0; k < n; ++k)
        AddRowPiece(d, pieces[k], acc + static_cast<std::size_t>(pieces[k].r) * static_cast<std::size_t>(stride),
                    stride);
}

void RowVectorEmitImpl(const RowVectorRows& s, SpanSink& sink) {
    const hn::ScalableTag<float> d;
    const int N = static_cast<int>(hn::Lanes(d));
    const auto zero = hn::Zero(d);
    for (int r = 0; r < s.h; ++r) {
        const int from = s.from[r];
        if (from == INT_MAX) continue;
        float* HWY_RESTRICT row = s.acc + static_cast<std::size_t>(r) * static_cast<std::size_t>(s.stride);
        for (int i = 0; i < s.stride; i += N) {
            const auto v = ApplyRule(d, hn::LoadU(d, row + i), s.rule);
            hn::StoreU(zero, d, row + i);
            StoreCoverage(d, v, s.cov + i);
        }
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
CASTELJAU_SIMD_EXPORT(RowVectorAccumulateImpl);
CASTELJAU_SIMD_EXPORT(RowVectorEmitImpl);

void scan_rows(const ScanRows& rows, SpanSink& sink) { CASTELJAU_SIMD_DISPATCH(ScanRowsImpl)(rows, sink); }

// Not cached: tests switch targets, and the stride must be whole vectors of the kernels' target.
int row_vector_lanes() { return CASTELJAU_SIMD_DISPATCH(RowVectorLanesImpl)(); }
void row_vector_accumulate(const RowPiece* pieces, std::size_t n, float* acc, int stride) {
    CASTELJAU_SIMD_DISPATCH(RowVectorAccumulateImpl)(pieces, n, acc, stride);
}
void row_vector_emit(const RowVectorRows& rows, SpanSink& sink) {
    CASTELJAU_SIMD_DISPATCH(RowVectorEmitImpl)(rows, sink);
}

}  // namespace casteljau::raster
#endif
