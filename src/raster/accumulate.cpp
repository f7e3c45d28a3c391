// Raster stage, accumulation: walks one edge through the cells of a strip.
//
// For every row the edge crosses, the piece of the edge inside that row has a signed height d
// (positive going down) and runs from xa to xb. Cell k receives in acc[k] the area between the
// piece and the cell's right side (weighted by d), and acc[k + 1] the rest of the piece's height
// in that cell; a prefix sum along the row then yields, for every pixel, the integral of the
// winding number over it (the cover/area scheme of FreeType's gray rasterizer and font-rs, on a
// dense per-strip buffer).
//
// Marking (exact_overlaps). Plain accumulation is exact in a cell whose winding numbers lie in one
// unit interval. Each cell remembers the last two edges that touched it and decides, when a
// second edge arrives, whether the pair is harmless:
//   - consecutive edges of one contour meeting at a vertex inside the cell (a polyline bend), or
//   - two edge pieces that do not meet inside the cell and cross it such that the regions on the
//     far sides of both have the same winding number (a stem: one edge up, one down). Seen from
//     inside, the side of a directed edge where the cross product with the edge is negative has a
//     winding number one higher; the middle region is on the other piece's side of each piece, so
//     the outer regions agree exactly when each piece's midpoint lies on the same-signed side of
//     the other piece.
// Further pieces continuing such a polyline are accepted while the polyline stays monotone in x or
// in y (then it cannot cross itself; a third piece is also accepted when it misses the first), and
// a two-piece bend plus one unrelated piece when they do not meet and the outer regions agree.
// Anything more, or any other pair, marks the cell; every edge touching a marked cell is logged
// for the exact recomputation (exact_cell.cpp). A piece that ends inside a cell always brings its
// neighbour along the contour into the cell too, so a provisional "harmless" verdict on a pair
// whose piece ends inside is always revisited by that third edge. The verdicts do not depend on
// the order in which edges arrive.
#include <algorithm>
#include <cmath>

#include "raster/raster_internal.hpp"

namespace casteljau::raster {

bool segments_meet(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    if (std::max(ax, bx) < std::min(cx, dx) || std::max(cx, dx) < std::min(ax, bx) ||
        std::max(ay, by) < std::min(cy, dy) || std::max(cy, dy) < std::min(ay, by))
        return false;
    const double d1 = orient(cx, cy, dx, dy, ax, ay), d2 = orient(cx, cy, dx, dy, bx, by);
    const double d3 = orient(ax, ay, bx, by, cx, cy), d4 = orient(ax, ay, bx, by, dx, dy);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    auto on = [](double px, double py, double qx, double qy, double rx, double ry) {
        return std::min(px, qx) <= rx && rx <= std::max(px, qx) && std::min(py, qy) <= ry && ry <= std::max(py, qy);
    };
    return (d1 == 0 && on(cx, cy, dx, dy, ax, ay)) || (d2 == 0 && on(cx, cy, dx, dy, bx, by)) ||
           (d3 == 0 && on(ax, ay, bx, by, cx, cy)) || (d4 == 0 && on(ax, ay, bx, by, dx, dy));
}

namespace {

// Cell (row, col) holding the end point (px, py) of an edge that heads towards (qx, qy): the same
// cell the walk below attributes that end of the edge to.
inline void end_cell(double px, double py, double qx, double qy, int& row, int& col) {
    row = qy > py ? ifloor(py) : (qy < py ? iceil(py) - 1 : ifloor(py));
    col = qx < px ? iceil(px) - 1 : ifloor(px);
}

// Is the pair of edges a, b harmless in cell (col, row)? See the comment at the top of the file.
bool harmless_pair(const Edge& a, const Edge& b, int col, int row) {
    double ax, ay, bx, by, cx, cy, dx, dy;
    if (!cell_portion(a, col, row, ax, ay, bx, by)) return true;  // a only grazes the cell
    if (!cell_portion(b, col, row, cx, cy, dx, dy)) return true;
    if (segments_meet(ax, ay, bx, by, cx, cy, dx, dy)) return false;
    // Directions are those of the edges (cell_portion keeps them).
    const double s1 = orient(ax, ay, bx, by, 0.5 * (cx + dx), 0.5 * (cy + dy));
    const double s2 = orient(cx, cy, dx, dy, 0.5 * (ax + bx), 0.5 * (ay + by));
    return (s1 > 0 && s2 > 0) || (s1 < 0 && s2 < 0);
}

// Is the pair "polyline u -> w (consecutive edges meeting inside the cell) + piece q" harmless in
// cell (col, row)? The polyline crosses the cell once and splits it in two; seen from inside, its
// negative side (where w is one higher) is the intersection of the negative half-planes of u and w
// when the polyline turns towards that side, their union otherwise. Then the test is the chord
// pair's: q must not meet the polyline, and the far regions beyond the polyline and beyond q
// must agree.
bool harmless_bend_and_piece(const Edge& u, const Edge& w, const Edge& q, int col, int row) {
    double ux0, uy0, ux1, uy1, wx0, wy0, wx1, wy1, qx0, qy0, qx1, qy1;
    const bool hu = cell_portion(u, col, row, ux0, uy0, ux1, uy1);
    const bool hw = cell_portion(w, col, row, wx0, wy0, wx1, wy1);
    if (!cell_portion(q, col, row, qx0, qy0, qx1, qy1)) return true;
    if (!hu || !hw) return false;
    if (segments_meet(ux0, uy0, ux1, uy1, qx0, qy0, qx1, qy1) || segments_meet(wx0, wy0, wx1, wy1, qx0, qy0, qx1, qy1))
        return false;
    const double mx = 0.5 * (qx0 + qx1), my = 0.5 * (qy0 + qy1);
    const double su = orient(u.x0, u.y0, u.x1, u.y1, mx, my), sw = orient(w.x0, w.y0, w.x1, w.y1, mx, my);
    if (su == 0 || sw == 0) return false;
    const double turn = (u.x1 - u.x0) * (w.y1 - w.y0) - (u.y1 - u.y0) * (w.x1 - w.x0);
    const bool q_on_negative = turn < 0 ? (su < 0 && sw < 0) : (su < 0 || sw < 0);
    // A point of the polyline inside the cell (not on q's line): the middle of u's portion.
    const double so = orient(qx0, qy0, qx1, qy1, 0.5 * (ux0 + ux1), 0.5 * (uy0 + uy1));
    if (so == 0) return false;
    return q_on_negative == (so < 0);
}

// Direction bits of an edge for the monotonicity test: +x, -x, +y, -y.
inline std::uint64_t dir_bits(const Edge& e) {
    std::uint64_t b = 0;
    if (e.x1 > e.x0) b |= 1;
    if (e.x1 < e.x0) b |= 2;
    if (e.y1 > e.y0) b |= 4;
    if (e.y1 < e.y0) b |= 8;
    return b << kTagDirShift;
}
// A polyline whose pieces all go the same way in x, or all the same way in y, cannot cross itself.
inline bool monotone(std::uint64_t dirs) {
    const std::uint64_t d = dirs >> kTagDirShift;
    return (d & 3) != 3 || (d & 12) != 12;
}

inline void log_edge(Strip& s, std::size_t cell, std::uint64_t id_plus_one) {
    if (id_plus_one) s.log->push_back({static_cast<std::uint32_t>(cell), static_cast<std::uint32_t>(id_plus_one - 1)});
}

// Checks and updates the tag of cell k of a row for edge `id`.
inline void tag_cell(Strip& s, std::uint64_t* tags, std::size_t base, int k, int row, std::uint32_t id,
                     const Edge& e, bool first_cell, bool last_cell) {
    const std::uint64_t t = tags[k];
    const std::uint64_t me = id + 1;
    if (t == 0) {
        tags[k] = me | (std::uint64_t(1) << kTagCountShift);
        return;
    }
    if (t & kTagMarked) {
        log_edge(s, base + k, me);
        return;
    }
    const std::uint64_t last = t & kTagIdMask;
    const unsigned count = static_cast<unsigned>(t >> kTagCountShift) & 3u;
    const std::int64_t other = static_cast<std::int64_t>(last) - 1;
    const bool chained = (first_cell && e.prev == other) || (last_cell && e.next == other);
    if (count == 1) {
        if (chained) {
            const std::uint64_t dirs = dir_bits(s.edges[other]) | dir_bits(e);
            tags[k] = me | (last << kTagPrevShift) | (std::uint64_t(2) << kTagCountShift) | kTagChain | dirs;
            return;
        }
        if (harmless_pair(s.edges[other], e, k, row)) {
            tags[k] = me | (last << kTagPrevShift) | (std::uint64_t(2) << kTagCountShift);
            return;
        }
    } else if (chained && (t & kTagChain)) {
        // One more piece of the polyline through the cell: still one simple curve while it stays
        // monotone in x or y; with three pieces, also when the new one misses the first.
        const std::uint64_t dirs = (t & kTagDirMask) | dir_bits(e);
        bool ok = monotone(dirs);
        if (!ok && count == 2) {
            const std::uint64_t first = (t >> kTagPrevShift) & kTagIdMask;
            double ax, ay, bx, by, cx, cy, dx, dy;
            ok = !cell_portion(s.edges[first - 1], k, row, ax, ay, bx, by) || !cell_portion(e, k, row, cx, cy, dx, dy) ||
                 !segments_meet(ax, ay, bx, by, cx, cy, dx, dy);
        }
        if (ok) {
            tags[k] = me | (last << kTagPrevShift) | (std::uint64_t(3) << kTagCountShift) | kTagChain | dirs;
            return;
        }
    } else if (count == 2) {
        const std::uint64_t first = (t >> kTagPrevShift) & kTagIdMask;
        const Edge& f = s.edges[first - 1];
        const Edge& l = s.edges[other];
        bool ok = false;
        if (chained) {
            // The previous pair was {f, l} with l unrelated to f; e bends l into a polyline.
            ok = e.prev == other ? harmless_bend_and_piece(l, e, f, k, row) : harmless_bend_and_piece(e, l, f, k, row);
        } else if (t & kTagChain) {
            // A polyline {f, l} and an unrelated piece e.
            const bool f_then_l = f.next == other;
            ok = f_then_l ? harmless_bend_and_piece(f, l, e, k, row) : harmless_bend_and_piece(l, f, e, k, row);
        }
        if (ok) {
            // The tag holds two ids; keep the pair whose dropped member is a neighbour along the
            // contour of a kept one, so that marking can recover it (see below).
            const std::uint64_t keep = chained ? first : last;
            tags[k] = me | (keep << kTagPrevShift) | (std::uint64_t(3) << kTagCountShift);
            return;
        }
    }
    tags[k] = t | kTagMarked;
    s.marked->push_back(static_cast<std::uint32_t>(base + k));
    log_edge(s, base + k, last);
    log_edge(s, base + k, (t >> kTagPrevShift) & kTagIdMask);
    log_edge(s, base + k, me);
    if (count == 3) {
        // Pieces were dropped from the tag: each is connected to a kept one along its contour
        // through pieces that all touch this cell. Walk both ways from the kept ids.
        const double cx = k, cy = row;
        for (const std::uint64_t kept : {last, (t >> kTagPrevShift) & kTagIdMask}) {
            for (int way = 0; way < 2; ++way) {
                std::int32_t n = way == 0 ? s.edges[kept - 1].prev : s.edges[kept - 1].next;
                const std::int32_t start = static_cast<std::int32_t>(kept - 1);
                for (int steps = 0; n >= 0 && n != start && steps < 4096; ++steps) {  // a contour inside the cell is a cycle
                    double ax, ay, bx, by;
                    if (!cell_portion(s.edges[n], cx, cy, ax, ay, bx, by)) break;
                    log_edge(s, base + k, static_cast<std::uint64_t>(n) + 1);
                    n = way == 0 ? s.edges[n].prev : s.edges[n].next;
                }
            }
        }
    }
}

}  // namespace

bool cell_portion(const Edge& e, double cx, double ry, double& ax, double& ay, double& bx, double& by) {
    // Liang-Barsky clip of the segment to the closed square, keeping the edge's direction.
    double t0 = 0, t1 = 1;
    const double dx = e.x1 - e.x0, dy = e.y1 - e.y0;
    // One reciprocal per axis instead of a division per side (not for tiny steps, whose
    // reciprocal could overflow: 0 means "divide").
    const double ix = std::abs(dx) > 1e-200 ? 1.0 / dx : 0.0, iy = std::abs(dy) > 1e-200 ? 1.0 / dy : 0.0;
    auto clip = [&](double p, double q, double inv) {  // p t <= q; inv = 1 / p, or 0
        if (p == 0) return q >= 0;
        const double r = inv != 0 ? q * inv : q / p;
        if (p < 0) {
            if (r > t1) return false;
            if (r > t0) t0 = r;
        } else {
            if (r < t0) return false;
            if (r < t1) t1 = r;
        }
        return true;
    };
    const double qx0 = e.x0 - cx, qx1 = cx + 1 - e.x0, qy0 = e.y0 - ry, qy1 = ry + 1 - e.y0;
    if (!clip(-dx, qx0, -ix) || !clip(dx, qx1, ix) || !clip(-dy, qy0, -iy) || !clip(dy, qy1, iy))
        return false;
    ax = e.x0 + dx * t0;
    ay = e.y0 + dy * t0;
    bx = e.x0 + dx * t1;
    by = e.y0 + dy * t1;
    return t1 > t0 || (dx == 0 && dy == 0);
}

namespace {

// Adds a piece of height d (signed) running from xa to xb inside one row to the row's cells
// [i0, i1] (and the spill cell i1 + 1). Returns nothing; see the file comment for the scheme.
inline void deposit(double* acc, double xa, double xb, double d, int& i0_out, int& i1_out) {
    const double xl = xa < xb ? xa : xb, xr = xa < xb ? xb : xa;
    const int i0 = static_cast<int>(xl);  // xl >= 0: truncation is floor
    int i1 = static_cast<int>(xr);
    if (i1 > i0 && i1 == xr) --i1;        // xr on a cell boundary belongs to the cell on its left
    i0_out = i0;
    i1_out = i1;
    if (i0 == i1) {
        const double a = d * ((i0 + 1) - 0.5 * (xl + xr));
        acc[i0] += a;
        acc[i0 + 1] += d - a;
        return;
    }
    const double hpx = d / (xr - xl);  // height of the piece per unit of x
    double len = (i0 + 1) - xl;
    double h = hpx * len;
    double a = h * 0.5 * len;
    const float half = static_cast<float>(hpx * 0.5);
    acc[i0] += static_cast<float>(a);
    if (i1 == i0 + 1) {
        acc[i0 + 1] += static_cast<float>(h - a);
    } else {
        acc[i0 + 1] += static_cast<float>(h - a) + half;
        for (int k = i0 + 2; k < i1; ++k) acc[k] += 2 * half;
        acc[i1] += half;
    }
    len = xr - i1;
    h = hpx * len;
    a = h * (1 - 0.5 * len);
    acc[i1] += static_cast<float>(a);
    acc[i1 + 1] += static_cast<float>(h - a);
}

}  // namespace

void accumulate_edge(const Edge& e, std::uint32_t id, Strip& s) {
    double x0 = e.x0, y0 = e.y0, x1 = e.x1, y1 = e.y1;
    if (y0 == y1) {
        // Horizontal: tags only, and only inside a row (on a row boundary it separates two rows,
        // not two regions of one cell).
        if (!s.tags) return;
        const int fy = ifloor(y0);
        if (fy == y0 || y0 < s.y0 || y0 >= s.y0 + s.rows) return;
        const int local = fy - s.y0;
        const double xl = std::min(x0, x1), xr = std::max(x0, x1);
        const int i0 = ifloor(xl);
        const int i1 = std::max(i0, iceil(xr) - 1);
        const int c0 = x1 > x0 ? i0 : i1, c1 = x1 > x0 ? i1 : i0;
        std::uint64_t* tags = s.tags + static_cast<std::size_t>(local) * s.stride;
        const std::size_t base = static_cast<std::size_t>(local) * s.stride;
        for (int k = i0; k <= i1; ++k) tag_cell(s, tags, base, k, fy, id, e, k == c0, k == c1);
        s.row_min[local] = std::min(s.row_min[local], i0);
        s.row_max[local] = std::max(s.row_max[local], i1);
        return;
    }
    int start_row = -1, start_col = -1, end_row = -1, end_col = -1;
    if (s.tags) {
        end_cell(x0, y0, x1, y1, start_row, start_col);
        end_cell(x1, y1, x0, y0, end_row, end_col);
    }
    double dir = 1;
    if (y0 > y1) {
        std::swap(x0, x1);
        std::swap(y0, y1);
        dir = -1;
    }
    const double top = s.y0, bottom = s.y0 + s.rows;
    if (y1 <= top || y0 >= bottom) return;
    const double dxdy = (x1 - x0) / (y1 - y0);
    const double xlo = x0 < x1 ? x0 : x1, xhi = x0 < x1 ? x1 : x0;
    const double ya = y0 > top ? y0 : top, yb = y1 < bottom ? y1 : bottom;
    const int r_first = static_cast<int>(ya);  // ya >= 0
    int r_last = static_cast<int>(yb);
    if (r_last == yb) --r_last;
    double x = ya == y0 ? x0 : std::clamp(x0 + (ya - y0) * dxdy, xlo, xhi);
    double y = ya;
    for (int r = r_first; r <= r_last; ++r) {
        const double ynext = r == r_last ? yb : r + 1.0;
        const double xnext = ynext == y1 ? x1 : std::clamp(x0 + (ynext - y0) * dxdy, xlo, xhi);
        const int local = r - s.y0;
        const std::size_t base = static_cast<std::size_t>(local) * s.stride;
        int i0, i1;
        deposit(s.acc + base, x, xnext, dir * (ynext - y), i0, i1);
        if (i0 < s.row_min[local]) s.row_min[local] = i0;
        if (i1 + 1 > s.row_max[local]) s.row_max[local] = i1 + 1;
        if (s.tags) {
            std::uint64_t* tags = s.tags + base;
            for (int k = i0; k <= i1; ++k) {
                if (tags[k] == 0) {  // first touch: the common case
                    tags[k] = (id + 1) | (std::uint64_t(1) << kTagCountShift);
                    continue;
                }
                tag_cell(s, tags, base, k, r, id, e, r == start_row && k == start_col, r == end_row && k == end_col);
            }
        }
        x = xnext;
        y = ynext;
    }
}

}  // namespace casteljau::raster
