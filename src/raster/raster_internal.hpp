// Internal types of the raster stage, shared by its files:
//   rasterizer.cpp    the driver: exactness verdict, the shape's box, dense buffer or bands
//   edge_builder.hpp  flattened points -> edges local to the box, clipped to it when needed
//   topology.cpp      classify_topology: may plain accumulation render this path exactly?
//   engine.hpp/.cpp   the engine: the cell walk (cover/area accumulation), the overlap check by
//                     visits, and, without the check for narrow shapes, row-vector accumulation
//   exact_cell.cpp    exact coverage of one cell from the edges inside it, and the cell geometry
//                     (clip of an edge to a cell, segment meeting test) the overlap check uses
//   coverage.cpp      per-row prefix sum + fill rule -> 8-bit coverage, row-vector kernels
//                     (Highway, runtime dispatch)
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "casteljau/raster.hpp"

namespace casteljau::raster {

// An edge in coordinates local to the shape's pixel bounds (double precision). prev/next link
// edges that share an end point along a contour (-1: none). Horizontal edges (y0 == y1) carry no
// coverage but are kept: they separate winding regions inside the cells they cross.
struct Edge {
    double x0, y0, x1, y1;
    std::int32_t prev, next;
};

// The part of `e` inside the closed cell [cx, cx + 1] x [ry, ry + 1]; false when there is none.
bool cell_portion(const Edge& e, double cx, double ry, double& ax, double& ay, double& bx, double& by);

struct ExactScratch {
    struct Piece {
        double ax, ay, bx, by;
    };  // in the edge's direction
    std::vector<Piece> pieces;
    std::vector<std::uint32_t> ids;
    std::vector<double> breaks;
    struct Part {
        double ya, yb, xa, xb;
        double k;  // dx / dy, once per piece rather than per slab and per pair
        int dir;
    };
    std::vector<Part> inside;
    struct Cross {
        double x0, x1, xm;
        int dir;
    };
    std::vector<Cross> active;
    struct Region {
        int b;
        double area;
    };
    std::vector<Region> regions;
    std::vector<std::uint32_t> order, live;  // the pieces by top end, and the active ones
    struct Ranked {
        Cross c;
        std::uint32_t id;
    };
    std::vector<Ranked> ranked;  // active pieces re-sorted whole (see sort_active)
    struct VCross {
        double y;
        int d;
    };  // a piece crossing the vertical through r
    std::vector<VCross> vcross;
    // The work the exact cells of the current fill may spend, in piece visits (see
    // exact_cell.cpp), and what they spent; the engine sets both before each fill's exact cells.
    double budget = 0;
    double work = 0;
    std::size_t dense_cells = 0;  // cells given the dense method
};

// Exact coverage in [0, 1] of cell [cx, cx + 1] x [ry, ry + 1] under `rule`. `ids` lists every edge
// that passes through the open cell (more are harmless); `integral` is the accumulated signed area of the cell
// (the integral of the winding number over it), which fixes the winding number's unknown offset.
double exact_cell_coverage(const Edge* edges, const std::vector<std::uint32_t>& ids, double cx, double ry,
                           double integral, FillRule rule, ExactScratch& scratch);

// floor and ceil to int for cell coordinates (in range by construction), cheaper than std::floor.
inline int ifloor(double v) {
    const int i = static_cast<int>(v);
    return i > v ? i - 1 : i;
}
inline int iceil(double v) {
    const int i = static_cast<int>(v);
    return i < v ? i + 1 : i;
}

// Twice the signed area of triangle (a, b, c): > 0 when c lies to the left of a -> b (y up).
inline double orient(double ax, double ay, double bx, double by, double cx, double cy) {
    return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

// Do the closed segments ab and cd share a point? (exact_cell.cpp)
bool segments_meet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy);

// Coverage c in [0, 1] becomes the 8-bit level c x 255 + kRoundUp, truncated: rounded to nearest,
// and a coverage half-way between two levels rounds up. The bias above 0.5 is for half-way values
// computed a little below themselves from exactly representable positions: a rational one (a
// diagonal's area) lands within about 1e-12 of a level of it in double, within about 1e-4 in float
// (the row vectors). A value that far below half-way rounds up too, one level from its correctly
// rounded value.
inline constexpr double kRoundUp = 0.5 + 1.0 / (1 << 20);
inline constexpr double kRoundUpFloat = 0.5 + 1.0 / 4096;

// 8-bit coverage of an exact area in [0, 1], rounded to nearest.
inline std::uint8_t area_to_u8(double c) { return static_cast<std::uint8_t>(c * 255.0 + kRoundUp); }

// exact_cell_coverage as 8-bit coverage; sorts `ids` and drops repeats first.
std::uint8_t exact_cell_u8(const Edge* edges, std::vector<std::uint32_t>& ids, double cx, double ry, double integral,
                           FillRule rule, ExactScratch& scratch);

// 8-bit coverage of an accumulated signed area under the fill rule: nonzero min(|a|, 1), even-odd
// the distance of |a| to the nearest even integer; rounded to nearest, with the bias of a's type
// (kRoundUp for double, kRoundUpFloat for float sums).
template <class T>
inline std::uint8_t coverage_u8(T a, FillRule rule) {
    T v = a < 0 ? -a : a;
    if (rule == FillRule::NonZero) {
        v = v < T(1) ? v : T(1);
    } else {
        v = v - T(2) * static_cast<T>(static_cast<long long>(v * T(0.5)));
        v = v > T(1) ? T(2) - v : v;
    }
    constexpr T kBias = static_cast<T>(sizeof(T) == sizeof(double) ? kRoundUp : kRoundUpFloat);
    return static_cast<std::uint8_t>(v * T(255) + kBias);
}

// The rows of a box (w x h at ox, oy) that a sink's direct target holds whole: row r's pixels
// go to at(r), or through the sink's row() when at(r) is null.
struct DirectRows {
    std::uint8_t* first = nullptr;  // row r0's first pixel in the target
    std::ptrdiff_t stride = 0;
    int r0 = 0, r1 = 0;  // the box's rows inside the target
    std::uint8_t* at(int r) const { return r >= r0 && r < r1 ? first + (r - r0) * stride : nullptr; }
};
DirectRows direct_rows(const CoverageTarget& t, int ox, int oy, int w, int h);

// The rows of the engine's dense buffer. Per row, bit b of its `words` 64-bit words of `blocks` says cells
// [b << kScanBlockShift, (b + 1) << kScanBlockShift) were touched. Touched blocks are
// prefix-summed into cov and cleared in acc; the gaps between them get the constant coverage of the
// running sum. Cells at or past `w` (spill cells, up to `stride`) are cleared, never delivered.
// The exact cells' coverage (patches: cell index row * stride + col and value, sorted) is written
// over the scanned row, and each row with a touched block goes to the sink at (ox, oy), or is
// scanned straight into the sink's target (direct) where it holds the row. One call
// (one SIMD dispatch) per shape. Float cells (facc instead of acc) come in rows of whole blocks
// (stride a multiple of 8) and have no patches.
inline constexpr int kScanBlockShift = 3;
struct ScanRows {
    double* acc;
    float* facc;
    std::uint8_t* cov;  // stride bytes of scratch
    const std::uint64_t* blocks;
    int words, w, h, stride;
    FillRule rule;
    const std::pair<std::uint32_t, std::uint8_t>* patches;
    std::size_t npatches;
    int ox, oy;
    DirectRows direct;
};
void scan_rows(const ScanRows& rows, SpanSink& sink);

// Row-vector accumulation (the engine's accumulation for narrow shapes without the overlap check:
// proven simple, or exactness off). A piece of an edge inside pixel row
// r, spanning [xl, xr] (xr > xl) with signed height dy, adds to pixel c of the row the integral
// over its height of clamp(c + 1 - x, 0, 1): its part inside [c, c + 1] contributes its height
// times the distance of that part's middle to the pixel's right side, its part left of the pixel
// its whole height. With u0 = max(xl, c), u1 = min(xr, c + 1) and k = dy / (xr - xl):
//     k * (max(u1 - u0, 0) * (c + 1 - (u0 + u1) / 2) + max(min(xr, c) - xl, 0)).
// Every pixel of the row at once, in SIMD vectors: no per-cell loop and no prefix sum, since the
// sum is the integral of the winding number over the pixel itself.
struct RowPiece {
    float xl, xr, k;
    std::int32_t r;
};
// A vertical piece at x (xl == xr, k = dy) adds dy times clamp(c + 1 - x, 0, 1) to pixel c, the
// limit of the formula above.
// The piece of row r spanning [xl, xr] with signed height dy. One narrower than 1e-4 px is taken as
// vertical at its middle: the area it adds to a pixel changes by at most |dy| x 1e-4 / 8, and an
// exactly vertical one (a stem) keeps its exact area, so that coverage lying exactly half-way
// between two 8-bit levels still rounds as the double accumulation rounds it.
inline RowPiece make_row_piece(int r, float xl, float xr, float dy) {
    if (xr - xl < 1e-4f) {
        const float m = 0.5f * (xl + xr);  // xl itself when xl == xr
        return {m, m, dy, r};
    }
    return {xl, xr, dy / (xr - xl), r};
}
// The kernel that adds a piece to its row is AddRowPiece in row_vector-inl.h.
// Floats per SIMD vector of the best target this CPU runs.
int row_vector_lanes();
// Rows are whole granules: at most kRowGranule floats, at most one vector (8 with AVX2 and AVX-512,
// so that a shape at most 8 px wide takes a half-width vector under AVX-512; 4 with SSE4).
constexpr int kRowGranule = 8;
int row_vector_granule();
// Adds every piece to acc (`stride` floats per row, a multiple of row_vector_granule()). The pieces
// come as the walk lists them, {xl, xr, dy, r} (k holding dy), and are first turned into
// make_row_piece's form in place, a SIMD vector of pieces at a time: the division and the test for
// vertical pieces cost a few cycles and a mispredicted branch each when done one piece at a time.
// `outline_order`: the pieces were listed along the outline (not chain by chain, as the winding
// sweep hands them on), so consecutive ones often share a row, and they are added in an order that
// separates them.
void row_vector_accumulate(RowPiece* pieces, std::size_t n, bool outline_order, float* acc, int stride);
// Maps rows [0, h) of acc through the fill rule to 8-bit coverage and clears them; rows with
// from[r] == INT_MAX (no piece) are skipped (they are zero). Each row goes to the sink from column
// from[r] to w, at (ox, oy). `cov`: stride bytes of scratch. (Rows this narrow fit a vector or
// two: writing them into the sink's target saved nothing measurable, so they are not.)
struct RowVectorRows {
    float* acc;
    int stride, w, h;
    FillRule rule;
    std::uint8_t* cov;
    int ox, oy;
};
void row_vector_emit(const RowVectorRows& rows, SpanSink& sink);

// An append-only list (the engine's per-cell and per-edge records, the winding sweep's points):
// the append is a compare and a store inline, growth (doubling) out of line. Cleared lists keep
// their memory.
template <class T>
class AppendList {
public:
    [[gnu::always_inline]] void push(const T& v) {
        if (n_ == buf_.size()) [[unlikely]]
            grow();
        buf_[n_++] = v;
    }
    void clear() { n_ = 0; }
    // Room for n more records: write them from the returned end, then pass the new end to commit().
    T* room(std::size_t n) {
        while (buf_.size() - n_ < n) grow();
        return buf_.data() + n_;
    }
    void commit(const T* end) { n_ = static_cast<std::size_t>(end - buf_.data()); }
    // Frees the memory when it holds room for more than `n` records (the list is then empty).
    void release_above(std::size_t n) {
        if (buf_.size() > n) {
            std::vector<T>().swap(buf_);
            n_ = 0;
        }
    }
    std::size_t size() const { return n_; }
    std::size_t capacity() const { return buf_.size(); }
    T& operator[](std::size_t i) { return buf_[i]; }
    const T& operator[](std::size_t i) const { return buf_[i]; }
    T* data() { return buf_.data(); }
    const T* data() const { return buf_.data(); }
    const T* begin() const { return buf_.data(); }
    const T* end() const { return buf_.data() + n_; }

private:
    [[gnu::noinline]] void grow() { buf_.resize(std::max<std::size_t>(256, 2 * buf_.size())); }
    std::vector<T> buf_;
    std::size_t n_ = 0;
};

}  // namespace casteljau::raster
