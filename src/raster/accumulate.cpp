// Raster stage, accumulation: walks one clipped edge through the cells of a strip.
//
// For every row the edge crosses, the piece of the edge inside that row has a signed height d
// (positive going down) and runs from xa to xb. Cell k receives in acc[k] the area between the
// piece and the cell's right side (weighted by d), and acc[k + 1] the rest of the piece's height
// in that cell; a prefix sum along the row then yields, for every pixel, the signed area of the
// shape inside it (the winding-weighted coverage). This is the cover/area scheme of FreeType's
// gray rasterizer and font-rs, written for a dense per-strip buffer.
//
// Tagging (exact_overlaps): each touched cell remembers the last edge that touched it. A second
// edge in the same cell is harmless only when the two are consecutive edges of one contour that
// meet inside the cell (the vertex is in the cell's closure) and at most two such edges share it:
// then the edges form one simple polyline through the cell and the winding numbers inside it lie
// in one unit interval, where accumulation is exact. Every other multi-edge cell is marked and
// later recomputed exactly (exact_cell.cpp). The test is independent of the order edges arrive in.
#include <algorithm>
#include <cmath>

#include "raster/raster_internal.hpp"

namespace casteljau::raster {

namespace {

// Cell (row, col) holding an end point (px, py) of an edge, seen from the edge heading to (qx, qy):
// the same cell the walk below attributes that end of the edge to.
inline void end_cell(double px, double py, double qx, double qy, int& row, int& col) {
    row = qy > py ? static_cast<int>(std::floor(py)) : static_cast<int>(std::ceil(py)) - 1;
    col = qx < px ? static_cast<int>(std::ceil(px)) - 1 : static_cast<int>(std::floor(px));
}

}  // namespace

// Checks and updates the tag of cell k in a row for edge `me` (id + 1).
inline void tag_cell(std::uint32_t* tags, int k, std::uint32_t me, bool chained_if_prev, bool chained_if_next,
                     const Edge& e, std::size_t index, std::vector<std::uint32_t>& marked_cells) {
    const std::uint32_t t = tags[k];
    if (t == 0) {
        tags[k] = me | (1u << kTagCountShift);
        return;
    }
    const std::uint32_t other = (t & kTagIdMask) - 1;
    const std::uint32_t count = (t & kTagCountMask) >> kTagCountShift;
    const bool chained = (chained_if_prev && e.prev >= 0 && other == static_cast<std::uint32_t>(e.prev)) ||
                         (chained_if_next && e.next >= 0 && other == static_cast<std::uint32_t>(e.next));
    std::uint32_t marked = t & kTagMarked;
    if ((!chained || count >= 2) && !marked) {
        marked = kTagMarked;
        marked_cells.push_back(static_cast<std::uint32_t>(index));
    }
    tags[k] = marked | (std::min(count + 1, 3u) << kTagCountShift) | me;
}

void accumulate_edge(const Edge& e, std::uint32_t id, Strip& s) {
    double x0 = e.x0, y0 = e.y0, x1 = e.x1, y1 = e.y1;
    int start_row = -1, start_col = -1, end_row = -1, end_col = -1;
    if (s.tags) {
        if (y0 == y1) {
            // Horizontal edge: tags only, and only when it lies inside a row (on a row boundary it
            // separates two rows, not two regions of one cell).
            const double fy = std::floor(y0);
            if (fy == y0 || y0 < s.y0 || y0 >= s.y0 + s.rows) return;
            const int local = static_cast<int>(fy) - s.y0;
            const double xl = std::min(x0, x1), xr = std::max(x0, x1);
            const int i0 = static_cast<int>(xl);
            const int i1 = std::max(i0, static_cast<int>(std::ceil(xr)) - 1);
            const int c0 = x1 > x0 ? i0 : i1, c1 = x1 > x0 ? i1 : i0;  // start and end cells
            std::uint32_t* tags = s.tags + static_cast<std::size_t>(local) * s.stride;
            const std::size_t base = static_cast<std::size_t>(local) * s.stride;
            for (int k = i0; k <= i1; ++k) tag_cell(tags, k, id + 1, k == c0, k == c1, e, base + k, *s.marked);
            s.row_min[local] = std::min(s.row_min[local], i0);
            s.row_max[local] = std::max(s.row_max[local], i1);
            return;
        }
        end_cell(x0, y0, x1, y1, start_row, start_col);
        end_cell(x1, y1, x0, y0, end_row, end_col);
    } else if (y0 == y1) {
        return;
    }
    double dir = 1;
    if (y0 > y1) {
        std::swap(x0, x1);
        std::swap(y0, y1);
        dir = -1;
    }
    const double top = s.y0, bottom = s.y0 + s.rows;
    if (y1 <= top || y0 >= bottom) return;
    const double xlo = std::min(x0, x1), xhi = std::max(x0, x1);
    const double dxdy = (x1 - x0) / (y1 - y0);
    const double ya = std::max(y0, top), yb = std::min(y1, bottom);
    const int r_end = static_cast<int>(std::ceil(yb));
    const std::uint32_t me = id + 1;
    for (int r = static_cast<int>(std::floor(ya)); r < r_end; ++r) {
        const double ry0 = std::max(ya, static_cast<double>(r));
        const double ry1 = std::min(yb, r + 1.0);
        if (!(ry1 > ry0)) continue;
        const double xa = std::clamp(x0 + (ry0 - y0) * dxdy, xlo, xhi);
        const double xb = std::clamp(x0 + (ry1 - y0) * dxdy, xlo, xhi);
        const double d = dir * (ry1 - ry0);
        const double xl = std::min(xa, xb), xr = std::max(xa, xb);
        const int i0 = static_cast<int>(xl);  // xl >= 0, so truncation is floor
        int i1 = xr > xl ? static_cast<int>(std::ceil(xr)) - 1 : i0;
        if (i1 < i0) i1 = i0;
        const int local = r - s.y0;
        float* acc = s.acc + static_cast<std::size_t>(local) * s.stride;
        if (i0 == i1) {
            const double a = d * ((i0 + 1) - 0.5 * (xl + xr));
            acc[i0] += static_cast<float>(a);
            acc[i0 + 1] += static_cast<float>(d - a);
        } else {
            const double hpx = d / (xr - xl);  // height of the piece per unit of x
            double len = (i0 + 1) - xl;
            double h = hpx * len;
            double a = h * 0.5 * len;
            acc[i0] += static_cast<float>(a);
            acc[i0 + 1] += static_cast<float>(h - a);
            const float half = static_cast<float>(hpx * 0.5);
            for (int k = i0 + 1; k < i1; ++k) {
                acc[k] += half;
                acc[k + 1] += half;
            }
            len = xr - i1;
            h = hpx * len;
            a = h * (1 - 0.5 * len);
            acc[i1] += static_cast<float>(a);
            acc[i1 + 1] += static_cast<float>(h - a);
        }
        s.row_min[local] = std::min(s.row_min[local], i0);
        s.row_max[local] = std::max(s.row_max[local], i1 + 1);

        if (!s.tags) continue;
        std::uint32_t* tags = s.tags + static_cast<std::size_t>(local) * s.stride;
        const std::size_t base = static_cast<std::size_t>(local) * s.stride;
        for (int k = i0; k <= i1; ++k)
            tag_cell(tags, k, me, r == start_row && k == start_col, r == end_row && k == end_col, e, base + k, *s.marked);
    }
}

}  // namespace casteljau::raster
