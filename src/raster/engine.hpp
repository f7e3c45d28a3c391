// Internal: the raster stage's engine (see engine.cpp). The per-edge cell walk is here, in the
// header, so that it inlines into the flattener's loop in rasterizer.cpp.
#pragma once

#include <algorithm>
#include <cassert>
#include <span>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "core/large_buffer.hpp"
#include "raster/inside_cells.hpp"
#include "raster/raster_internal.hpp"

namespace casteljau::raster {

// The engine (engine.cpp): one dense buffer of w x h cells, the whole shape's box or one band of
// it (rasterizer.cpp chooses). Edges are accumulated as they arrive, in contour order, and the
// overlap check works on "visits" (maximal runs of consecutive edges of one contour inside one
// cell). See the comment at the top of engine.cpp.
class Engine {
public:
    // Starts a shape of w x h cells. `track`: record visits for the exact overlap check (the cell
    // walk in double); without it narrow shapes take the float row vectors.
    void begin(int w, int h, bool track);
    // One straight edge in cell coordinates, inside [0, w] x [0, h] up to rounding (y is held at h).
    inline void push(double x0, double y0, double x1, double y1);
    // The edges between n consecutive points (x and y interleaved), as push() for each.
    void push_polyline(const double* xy, std::size_t n);
    // The edges of a chain, n points monotone in y (the winding sweep's), in the opposite
    // direction when `reverse` (from point n - 1 to point 0).
    void push_chain(const double* xy, std::size_t n, bool reverse);
    // The current contour is complete (its closing edge was pushed).
    void contour_end();
    // Whether the edges pushed so far only wait in a list until finish() (the row vectors), so
    // that restart() is cheap.
    bool defers_accumulation() const { return vec_; }
    // Drops every edge pushed since begin(), as if begun again on the same box; only while
    // defers_accumulation().
    void restart() {
        assert(vec_);
        pieces_.clear();
        chains_ = false;
        count_ = 0;
    }
    // Restricts the overlap check to the cells that meet `boxes` (moved by (dx, dy) into cell
    // coordinates), grown by one cell for rounding: FillOptions::overlap_boxes. Boxes that would
    // mark more cells in all than the shape has are ignored (the check looks everywhere), so
    // marking costs at most the shape's cells. After begin(), before the first edge.
    void set_region(std::span<const Rect> boxes, double dx, double dy);
    // Resolves the marked cells and hands the rows to the sink, at pixel offset (ox, oy). Marked
    // cells wholly inside one of `inside` (pixel space) are full under the nonzero rule; cells of
    // pixels in `hidden` keep their accumulated coverage (FillOptions::hidden).
    void finish(FillRule rule, int ox, int oy, SpanSink& sink, RasterStats& stats,
                std::span<const CutCapsule> inside = {}, const PixelSet* hidden = nullptr);
    // Frees the per-edge and per-visit lists that hold room for more than `records` entries (the
    // dense buffers stay: a strip bounds them). Between shapes only.
    void trim(std::size_t records);

private:
    struct Visit {
        std::uint32_t cell;    // row * stride + col
        std::int32_t next;     // the cell's previous visit (-1: none)
        std::uint32_t s0, s1;  // first and last edge of the visit (indices into segs_)
        std::int32_t pre;      // merged visit holding the part of this run before the contour start
        std::uint8_t dirs;     // +x, -x, +y, -y seen along the run
        bool merged_away;      // this record is the first part of another visit (`pre` of it)
    };

    // The cell walk. T: the cells' type (float for the float cells, else double).
    template <bool kTrack, class T = double>
    inline void row_piece(int r, double xa, double ya, double xb, double yb, std::uint32_t sid, std::uint8_t bits);
    template <bool kTrack, class T = double>
    inline void walk(double x0, double y0, double x1, double y1);
    template <class T>
    T* cells();
    // The row vectors' walk: lists the edge's pieces.
    inline void list_pieces(double x0, double y0, double x1, double y1);
    // The row vectors' push of the edges between n consecutive points (reversed: from the last);
    // `rows`: at least the sum of the edges' heights.
    template <bool kReverse>
    void push_rows(const double* xy, std::size_t n, double rows);
    inline bool admit(double x0, double& y0, double x1, double& y1);
    inline void touch(std::uint32_t cell, std::uint32_t sid, std::uint8_t bits);
    // Whether edge `sid`, entering `cell` whose only visit so far is `before`, makes a pair that
    // classify() would find harmless by harmless_two's closed form for a contour that leaves the
    // cell and comes back one vertex later: both single edges passing through, consecutive, their
    // shared vertex outside the cell. Such a cell needs no candidate unless its runs change later
    // (a third visit, or this visit's run growing: touch() makes it one then).
    bool returns_harmlessly(std::int32_t before, std::uint32_t sid, std::uint32_t cell) const;
    bool harmless_two(const Visit& a, const Visit& b, int col, int row);
    bool run_ends(const Visit& v, int col, int row, double& t0, double& t1) const;
    void gather(const Visit& v, int col, int row, std::vector<ExactScratch::Piece>& out) const;
    // Lists the cells to compute exactly; returns how many candidates `hidden` left out.
    std::size_t classify(int ox, int oy, const PixelSet* hidden);
    bool simple_run(const Visit& v) const;
    // Whether a run with these directions (Visit::dirs) is monotone in x or in y, so that it
    // cannot cross itself (a run of one edge always is).
    static bool monotone(std::uint8_t dirs) { return (dirs & 3) != 3 || (dirs & 12) != 12; }
    bool closed_run(const Visit& v) const;
    // Longer runs are not checked for simplicity: exact. The pairwise check of 32 edges costs less
    // than an exact cell of as many (a map's coasts at small sizes wind through one pixel in 17 to
    // 32 edges; countries-land-10km at 256 px: 575 exact cells at 16, 399 at 32, 363 at 64).
    static constexpr int kMaxRunEdges = 32;
    static constexpr int kMaxRuns = 6;  // cells with more runs are computed exactly
    int run_edges(const Visit& v, std::uint32_t* out) const;
    bool harmless_many(const Visit* const* runs, int n, int col, int row) const;
    struct ManyRuns;  // harmless_many's steps (engine.cpp)

    int w_ = 0, h_ = 0;
    double fh_ = 0;  // h_ as a double: admit() holds every edge's y at it without a conversion
    std::size_t stride_ = 0;
    bool track_ = false;
    // Narrow shapes (at most kRowVectorMax SIMD vectors and kRowVectorMaxPixels per row) without
    // the overlap check are accumulated by row vectors (see RowPiece in raster_internal.hpp): the
    // walk only lists the pieces of edges per row, and finish() adds each piece's exact area to its
    // whole row at once, in float. 11 to 20 % faster from 12 to 96 px than the double cell walk
    // without tracking; glyphs proven simple take it. A piece costs a pass over its whole row, so
    // wider shapes take the cell walk (float cells, below): DejaVu Sans at 256 px renders 5 %
    // faster with the limit at 64 px than at 128 px, and at 48 px 5 % slower with it at 32 px.
    // With the overlap check the cell walk stays: the visits need it anyway and it accumulates
    // nearly for free alongside (row vectors on top measured 5 % slower at 12 px, equal at 48 and
    // 96 px).
    bool vec_ = false;
    static constexpr int kRowVectorMax = 8;
    static constexpr int kRowVectorMaxPixels = 64;
    // Wider shapes without the overlap check, up to kFloatCellsMax cells wide, accumulate cover and
    // area in float cells (facc_, rows of stride_ cells, a multiple of 8): half the memory of double
    // cells and twice the lanes in the scan. Rounding in a row's prefix sum stays below
    // kFloatCellsMax x 2^-24 of the coverage (0.016/255 at most); wider shapes take double cells.
    bool fcells_ = false;
    static constexpr int kFloatCellsMax = 1024;
    int vstride_ = 0;                    // floats per row of facc_ (w rounded up to whole granules)
    platform::LargeVector<float> facc_;  // row vectors or float cells, all zero between shapes
    AppendList<RowPiece> pieces_;
    bool chains_ = false;                       // the pieces came chain by chain (push_chain), not along the outline
    bool dirty_ = false;                        // buffers may hold data from an interrupted shape
    platform::LargeVector<double> acc_;         // cover/area, (w + 2) x h, all zero between shapes
    platform::LargeVector<std::int32_t> head_;  // per cell: last visit + 1 (0: none), all zero between shapes
    platform::LargeVector<std::uint8_t> cand_;  // per cell: listed in cands_ (1) or not, all zero between shapes
    // set_region: per cell, 1 where the overlap check looks (only read while region_on_); the
    // rectangles of cells set, to clear them again.
    platform::LargeVector<std::uint8_t> region_;
    std::vector<IRect> region_rects_;
    std::size_t region_stride_ = 0;
    bool region_on_ = false;
    void mark_region(std::uint8_t value);  // region_ set to value in region_rects_
    void clear_region();
    // Touched cells, per row, in blocks of kBlock cells: bit b of the row's words is block b. The
    // scan only sums touched blocks; between them the coverage is constant.
    static constexpr int kBlockShift = kScanBlockShift;
    std::vector<std::uint64_t> blocks_;
    std::size_t words_ = 1;  // words per row
    inline void mark(int r, int c0, int c1);
    AppendList<Edge> segs_;      // the edges (kept when tracking: exact cells need them)
    std::size_t count_ = 0;      // edges pushed
    std::size_t max_edges_ = 0;  // Limits::flattened_segments, read by begin()
    double exact_base_ = 0;      // Limits::exact_work, read by begin()
    AppendList<Visit> visits_;
    std::vector<std::uint32_t> cands_;  // cells with two or more visits, or a run not monotone (each once)
    void add_cand(std::uint32_t cell) {
        if (!cand_[cell]) {
            cand_[cell] = 1;
            cands_.push_back(cell);
        }
    }
    std::vector<std::uint32_t> exact_;     // cells to compute exactly (sorted)
    std::vector<std::uint32_t> exact_at_;  // start of each exact cell's edges in exact_ids_
    std::vector<std::uint32_t> exact_ids_;
    std::vector<std::uint8_t> cov_;
    std::vector<std::pair<std::uint32_t, std::uint8_t>> patches_;
    std::vector<ExactScratch::Piece> pa_, pb_;
    ExactScratch scratch_;
    InsideCells inside_;
    // Walk state.
    static constexpr std::uint32_t kNoCell = 0xffffffffu;
    std::uint32_t cur_cell_ = kNoCell;
    std::int32_t cur_visit_ = -1;
    std::size_t contour_visit_ = 0;  // first visit of the current contour
    double px_ = 0, py_ = 0;         // end of the last edge
    double sx_ = 0, sy_ = 0;         // start of the contour's first edge
    std::uint32_t contour_seg_ = 0;  // the contour's first edge (index into segs_)
    bool contour_started_ = false;
};

[[gnu::always_inline]] inline void Engine::touch(std::uint32_t cell, std::uint32_t sid, std::uint8_t bits) {
    if (region_on_ && !region_[cell]) {
        cur_cell_ = kNoCell;  // accumulation is exact here: no visit
        return;
    }
    if (cell == cur_cell_) {
        Visit& v = visits_[static_cast<std::size_t>(cur_visit_)];
        v.s1 = sid;
        v.dirs |= bits;
        // A run that may cross itself, or one growing in a cell visited before (whose pair of
        // runs returns_harmlessly may have let pass): checked by classify().
        if (!monotone(v.dirs) || v.next >= 0) add_cand(cell);
        return;
    }
    cur_cell_ = cell;
    const std::int32_t h = head_[cell];
    cur_visit_ = static_cast<std::int32_t>(visits_.size());
    visits_.push({cell, h - 1, sid, sid, -1, bits, false});
    head_[cell] = cur_visit_ + 1;
    if (h != 0 && !returns_harmlessly(h - 1, sid, cell)) add_cand(cell);
}

// floor and ceil for the walk's coordinates, which lie in [0, w] x [0, h] up to rounding (push()):
// truncation is floor for v >= 0 (no compare-and-adjust on the floor side), and takes a rounding
// step below 0 to cell or row 0.
[[gnu::always_inline]] inline int floor_nn(double v) { return static_cast<int>(v); }
[[gnu::always_inline]] inline int ceil_nn(double v) {
    const int i = static_cast<int>(v);
    return i + (i < v);
}

// Marks cells [c0, c1] of row r as touched.
[[gnu::always_inline]] inline void Engine::mark(int r, int c0, int c1) {
    std::uint64_t* m = blocks_.data() + static_cast<std::size_t>(r) * words_;
    const unsigned b0 = static_cast<unsigned>(c0) >> kBlockShift, b1 = static_cast<unsigned>(c1) >> kBlockShift;
    if (b1 < 64) {
        // Bits b0..b1: 2^(b1 + 1) - 2^b0, where 2^64 wraps to 0 (unsigned) and the difference still holds.
        m[0] |= (std::uint64_t(2) << b1) - (std::uint64_t(1) << b0);
        return;
    }
    for (unsigned b = b0; b <= b1; ++b) m[b >> 6] |= std::uint64_t(1) << (b & 63);
}

// The cover/area step, the only one: a piece of signed height d spanning [u0, u1] inside cell c
// of a row adds d times the part of the cell right of it to acc[c], the rest of d to acc[c + 1].
template <class T>
[[gnu::always_inline]] inline void add_cell(T* acc, int c, double d, double u0, double u1) {
    const double a = d * ((c + 1) - 0.5 * (u0 + u1));
    acc[c] += static_cast<T>(a);
    acc[c + 1] += static_cast<T>(d - a);
}

template <>
inline double* Engine::cells<double>() {
    return acc_.data();
}
template <>
inline float* Engine::cells<float>() {
    return facc_.data();
}

template <bool kTrack, class T>
[[gnu::always_inline]] inline void Engine::row_piece(int r, double xa, double ya, double xb, double yb,
                                                     std::uint32_t sid, std::uint8_t bits) {
    const double dy = yb - ya;
    const double xl = xa < xb ? xa : xb, xr = xa < xb ? xb : xa;
    const int c0 = floor_nn(xl);
    const int c1 = ceil_nn(xr) - 1;
    T* acc = cells<T>() + static_cast<std::size_t>(r) * stride_;
    if (c1 <= c0) {
        add_cell(acc, c0, dy, xl, xr);
        mark(r, c0, c0 + 1);
        if constexpr (kTrack) {
            if (xl == xr && xl == c0)
                cur_cell_ = kNoCell;  // on the cell's left side: no visit
            else
                touch(
                    static_cast<std::uint32_t>(static_cast<std::size_t>(r) * stride_) + static_cast<std::uint32_t>(c0),
                    sid, bits);
        }
        return;
    }
    mark(r, c0, c1 + 1);
    const std::uint32_t base = static_cast<std::uint32_t>(static_cast<std::size_t>(r) * stride_);
    const double s = dy / (xr - xl);  // height per unit of x
    // Cells in travel order (the visits need it). The two directions are written out: sharing
    // the cell step as a lambda measured 5 % slower per 12 px glyph (GCC 12 inlines the walk
    // differently).
    if (xa < xb) {
        double u0 = xa;
        for (int c = c0; c <= c1; ++c) {
            const double u1 = c == c1 ? xb : c + 1.0;
            add_cell(acc, c, s * (u1 - u0), u0, u1);
            if constexpr (kTrack) touch(base + static_cast<std::uint32_t>(c), sid, bits);
            u0 = u1;
        }
    } else {
        double u1 = xa;
        for (int c = c1; c >= c0; --c) {
            const double u0 = c == c0 ? xb : static_cast<double>(c);
            add_cell(acc, c, s * (u1 - u0), u0, u1);
            if constexpr (kTrack) touch(base + static_cast<std::uint32_t>(c), sid, bits);
            u1 = u0;
        }
    }
}

// push()'s first steps: y held at h, a point-like edge dropped (false), the edge counted against
// the limit. Coordinates arrive inside [0, w] x [0, h] up to rounding: the edge builder clips
// them, or the shape's control points lie inside the box. One rounding step below 0 truncates to
// cell or row 0, and one past w lands in the row's spill cells, so only y is held at h, so that no
// piece falls in a row past the last. (v < h ? v : h compiles to one min instruction.)
[[gnu::always_inline]] inline bool Engine::admit(double x0, double& y0, double x1, double& y1) {
    y0 = y0 < fh_ ? y0 : fh_;
    y1 = y1 < fh_ ? y1 : fh_;
    if (x0 == x1 && y0 == y1) return false;
    if (++count_ > max_edges_)
        throw Error(ErrorKind::Limit, "path too complex: more than " + std::to_string(max_edges_) + " edges");
    return true;
}

inline void Engine::push(double x0, double y0, double x1, double y1) {
    if (!admit(x0, y0, x1, y1)) return;
    if (track_)
        walk<true>(x0, y0, x1, y1);
    else if (vec_)
        list_pieces(x0, y0, x1, y1);
    else if (fcells_)
        walk<false, float>(x0, y0, x1, y1);
    else
        walk<false>(x0, y0, x1, y1);
}

// Calls piece(r, xa, ya, xb, yb) for each pixel row r that the edge (y0 != y1) crosses, in travel
// order, with the part of the edge inside that row.
template <class F>
[[gnu::always_inline]] inline void for_each_row(double x0, double y0, double x1, double y1, F&& piece) {
    if (y1 > y0) {
        const int r0 = floor_nn(y0), rend = ceil_nn(y1) - 1;
        if (rend <= r0) return piece(r0, x0, y0, x1, y1);  // one row
        const double k = (x1 - x0) / (y1 - y0);
        const double xlo = std::min(x0, x1), xhi = std::max(x0, x1);
        double ya = y0, xa = x0;
        for (int r = r0; r < rend; ++r) {
            const double yb = r + 1.0;
            const double xb = std::clamp(x0 + (yb - y0) * k, xlo, xhi);
            piece(r, xa, ya, xb, yb);
            ya = yb;
            xa = xb;
        }
        piece(rend, xa, ya, x1, y1);
    } else {
        const int r0 = ceil_nn(y0) - 1, rend = floor_nn(y1);
        if (rend >= r0) return piece(r0, x0, y0, x1, y1);  // one row
        const double k = (x1 - x0) / (y1 - y0);
        const double xlo = std::min(x0, x1), xhi = std::max(x0, x1);
        double ya = y0, xa = x0;
        for (int r = r0; r > rend; --r) {
            const double yb = r;
            const double xb = std::clamp(x0 + (yb - y0) * k, xlo, xhi);
            piece(r, xa, ya, xb, yb);
            ya = yb;
            xa = xb;
        }
        piece(rend, xa, ya, x1, y1);
    }
}

// The row vectors' pieces {xl, xr, dy, r} of an edge with y0 != y1, one per row it crosses, written
// from `out` (room for floor(|y1 - y0|) + 2 pieces); returns the new end.
[[gnu::always_inline]] inline RowPiece* list_edge_pieces(RowPiece* out, double x0, double y0, double x1, double y1) {
    for_each_row(
        x0, y0, x1, y1, [&](int r, double xa, double ya, double xb, double yb) __attribute__((always_inline)) {
            // Selects, not branches: the order of xa and xb follows the outline, which a branch
            // predictor cannot.
            const double xl = std::min(xa, xb), xr = std::max(xa, xb);
            *out++ = {static_cast<float>(xl), static_cast<float>(xr), static_cast<float>(yb - ya), r};  // k: dy
        });
    return out;
}

// list_row_pieces() one edge at a time: its way for short polylines, and for the edges left over
// after its last whole vector.
template <bool kReverse>
[[gnu::always_inline]] inline RowPiece* list_polyline_pieces(const double* xy, std::size_t n, double fh, RowPiece* out,
                                                             std::size_t& edges) {
    if (n < 2) return out;
    auto x_at = [&](std::size_t i) { return xy[2 * (kReverse ? n - 1 - i : i)]; };
    auto y_at = [&](std::size_t i) {
        const double y = xy[2 * (kReverse ? n - 1 - i : i) + 1];
        return y < fh ? y : fh;
    };
    double x0 = x_at(0), y0 = y_at(0);
    for (std::size_t i = 1; i < n; ++i) {
        const double x1 = x_at(i), y1 = y_at(i);
        if (x0 != x1 || y0 != y1) {
            ++edges;
            if (y0 != y1) out = list_edge_pieces(out, x0, y0, x1, y1);  // a horizontal edge has no cover
        }
        x0 = x1;
        y0 = y1;
    }
    return out;
}

// The row pieces of the edges between n consecutive points xy (x, y pairs, y held at fh), taken
// from the first point to the last (or the reverse), in edge order, each edge's in travel order:
// the pieces list_edge_pieces() lists for each edge of positive height, bit for bit, a SIMD vector
// of edges at a time (row_listing.cpp). `out` has room for the edges' pieces plus two. Returns the
// new end; adds the edges of positive length to `edges`.
RowPiece* list_row_pieces(const double* xy, std::size_t n, bool reverse, double fh, RowPiece* out, std::size_t& edges);

template <bool kTrack, class T>
[[gnu::always_inline]] inline void Engine::walk(double x0, double y0, double x1, double y1) {
    std::uint32_t sid = 0;
    std::uint8_t bits = 0;
    if constexpr (kTrack) {
        if (x0 != px_ || y0 != py_) cur_cell_ = kNoCell;  // a gap (clipped away): a new run starts
        if (!contour_started_) {
            contour_started_ = true;
            sx_ = x0;
            sy_ = y0;
            contour_seg_ = static_cast<std::uint32_t>(segs_.size());
        }
        px_ = x1;
        py_ = y1;
        sid = static_cast<std::uint32_t>(segs_.size());
        segs_.push({x0, y0, x1, y1, -1, -1});
        bits = static_cast<std::uint8_t>((x1 > x0 ? 1 : 0) | (x1 < x0 ? 2 : 0) | (y1 > y0 ? 4 : 0) | (y1 < y0 ? 8 : 0));
    }
    if (y0 == y1) {
        // No cover; it still separates regions inside the cells it crosses.
        if constexpr (kTrack) {
            const int r = floor_nn(y0);
            if (r == y0 || r >= h_) {
                cur_cell_ = kNoCell;  // on a row boundary
                return;
            }
            const std::uint32_t base = static_cast<std::uint32_t>(static_cast<std::size_t>(r) * stride_);
            const int c0 = floor_nn(std::min(x0, x1));
            const int c1 = std::max(c0, ceil_nn(std::max(x0, x1)) - 1);
            if (x1 > x0)
                for (int c = c0; c <= c1; ++c) touch(base + static_cast<std::uint32_t>(c), sid, bits);
            else
                for (int c = c1; c >= c0; --c) touch(base + static_cast<std::uint32_t>(c), sid, bits);
        }
        return;
    }
    for_each_row(
        x0, y0, x1, y1, [&](int r, double xa, double ya, double xb, double yb) __attribute__((always_inline)) {
            row_piece<kTrack, T>(r, xa, ya, xb, yb, sid, bits);
        });
}

// Row vectors: the pieces of one edge, one per pixel row it crosses; their areas go in at
// finish(). Room for every row is made first, so the pieces go out through local pointers.
[[gnu::always_inline]] inline void Engine::list_pieces(double x0, double y0, double x1, double y1) {
    if (y0 == y1) return;  // no cover
    RowPiece* out = pieces_.room(static_cast<std::size_t>(std::abs(y1 - y0)) + 2);
    pieces_.commit(list_edge_pieces(out, x0, y0, x1, y1));
}

}  // namespace casteljau::raster
