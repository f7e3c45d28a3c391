// Internal types of the raster stage, shared by its files:
//   rasterizer.cpp  clip edges to the target, bucket them into strips, drive the stages below
//   accumulate.cpp  walk each edge through the cells of a strip: cover/area into a dense buffer,
//                   and mark the cells where plain accumulation may be inexact
//   exact_cell.cpp  exact coverage of a marked cell from the edges inside it
//   coverage.cpp    per-row prefix sum + fill rule -> 8-bit coverage (Highway, runtime dispatch)
#pragma once

#include <cstdint>
#include <vector>

#include "casteljau/raster.hpp"

namespace casteljau::raster {

// An edge after clipping, in coordinates local to the shape's pixel bounds (double precision).
// prev/next link edges that share an end point along a contour (-1: none). An edge never has
// y0 == y1 (horizontal edges carry no coverage and are dropped).
struct Edge {
    double x0, y0, x1, y1;
    std::int32_t prev, next;
};

// Tag word per cell: which edge touched it last, how many chained edges touch it, and whether it
// is already marked for exact recomputation.
inline constexpr std::uint32_t kTagIdMask = (1u << 29) - 1;
inline constexpr std::uint32_t kTagCountShift = 29;
inline constexpr std::uint32_t kTagCountMask = 3u << kTagCountShift;
inline constexpr std::uint32_t kTagMarked = 1u << 31;

// One strip of rows [y0, y0 + rows) of the shape's bounds, `width` cells wide (plus 2 spill cells).
struct Strip {
    int y0 = 0;
    int rows = 0;
    int width = 0;
    std::size_t stride = 0;          // cells per row in acc/tags (width + 2)
    float* acc = nullptr;            // cover/area accumulation
    std::uint32_t* tags = nullptr;   // nullptr when exact overlaps are off
    int* row_min = nullptr;          // first touched cell per row (INT_MAX when untouched)
    int* row_max = nullptr;          // last touched cell per row (-1 when untouched)
    std::vector<std::uint32_t>* marked = nullptr;  // cell indices (row * stride + col) to recompute
};

// Walks edge `e` (index `id`) through the strip's rows and cells.
void accumulate_edge(const Edge& e, std::uint32_t id, Strip& s);

// A piece of an edge inside one row, y0 < y1, dir = +1 for edges going down (y increasing).
struct RowPiece {
    double x0, y0, x1, y1;
    int dir;
};

// Exact coverage in [0, 1] of cell [cx, cx + 1] x [ry, ry + 1] under `rule`, given every piece of
// the row's edges (only those reaching left of cx + 1 matter). `scratch` is reused storage.
struct ExactScratch {
    std::vector<double> breaks;
    struct Part { double ya, yb, xa, xb; int dir; };
    std::vector<Part> left, inside;
    struct Cross { double x0, x1, xm; int dir; };
    std::vector<Cross> active;
};
double exact_cell_coverage(const std::vector<RowPiece>& pieces, double cx, double ry, FillRule rule,
                           ExactScratch& scratch);

// 8-bit coverage of an accumulated signed area under the fill rule: nonzero min(|a|, 1), even-odd
// the distance of |a| to the nearest even integer; rounded to nearest.
inline std::uint8_t coverage_u8(float a, FillRule rule) {
    float v = a < 0 ? -a : a;
    if (rule == FillRule::NonZero) {
        v = v < 1.0f ? v : 1.0f;
    } else {
        v = v - 2.0f * static_cast<float>(static_cast<int>(v * 0.5f));
        v = v > 1.0f ? 2.0f - v : v;
    }
    return static_cast<std::uint8_t>(v * 255.0f + 0.5f);
}

// Prefix sum over acc[from, to) starting from `start`, mapped through the fill rule into 8-bit
// coverage cov[from, to). Returns the running sum after `to`. Clears acc[from, to).
float accumulate_row(float* acc, std::uint8_t* cov, int from, int to, float start, FillRule rule);

}  // namespace casteljau::raster
