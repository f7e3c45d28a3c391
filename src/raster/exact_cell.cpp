// Raster stage, exact cells: the coverage of one marked pixel computed exactly.
//
// Accumulation yields f(integral of w) where the truth is the integral of f(w) (w: the winding
// number, f: the fill rule). For a marked cell we know the integral A of w over the cell (from the
// accumulation) and every edge that passes through the open cell (logged while accumulating).
//   1. Clip those edges to the cell and cut the cell into horizontal slabs at every y where the
//      picture changes (piece end points, crossings of pieces, horizontal pieces), so that inside a
//      slab the pieces do not cross and the regions between consecutive pieces are trapezoids.
//   2. Inside the open cell, w(p) = W0 + L(p), where L(p) counts the signed crossings of the
//      segment from a fixed interior reference point r to p by the cell's pieces (the segment
//      stays inside the cell, so no other edge can cross it), and W0 = w(r) is unknown. Crossing
//      a directed piece towards the side where the cross product with it is negative raises w by
//      one (y down).
//   3. A = W0 + sum(L x area) fixes W0 (an integer: rounded), and the coverage is
//      sum(f(W0 + L) x area).
// Only the cell's own edges are needed, never the rest of its row.
// Also here: the cell geometry the overlap check shares (cell_portion, segments_meet).
#include <algorithm>
#include <cmath>

#include "raster/raster_internal.hpp"

namespace casteljau::raster {

// Cell geometry shared with the overlap check (engine.cpp).

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

inline double fill_value(long w, FillRule rule) {
    return rule == FillRule::NonZero ? (w != 0 ? 1.0 : 0.0) : ((w & 1) ? 1.0 : 0.0);
}

// Reference points inside the unit cell, tried in order until one is in general position.
constexpr double kRef[4][2] = {{0.5012345, 0.4987654}, {0.3141593, 0.7182818}, {0.6931472, 0.2718282},
                               {0.1414214, 0.8660254}};

// For pathological pixels the slab decomposition (up to cubic in the pieces) gives way to
// kDenseRows horizontal lines through the cell, each integrated exactly in x: the result is then
// within about 1/(2 kDenseRows) of the pixel instead of exact, on such pixels only.
// The switch happens when slabs x pieces (the work of the exact method) would pass kMaxSlabWork
// (equal break points are merged first: stacked copies of one shape make few distinct slabs), or
// straight away beyond kMaxExactPieces pieces, where even finding the crossings costs too much.
// A 500-segment scribble inside one pixel (62,000 crossings) is still computed exactly.
constexpr std::size_t kMaxExactPieces = 4096;
constexpr double kMaxSlabWork = 6e7;
constexpr int kDenseRows = 1024;

}  // namespace

double exact_cell_coverage(const Edge* edges, const std::vector<std::uint32_t>& ids, double cx, double ry,
                           double integral, FillRule rule, ExactScratch& sc) {
    const double cr = cx + 1, rb = ry + 1;
    sc.inside.clear();
    sc.breaks.clear();
    sc.regions.clear();
    sc.breaks.push_back(ry);
    sc.breaks.push_back(rb);
    // Pieces inside the closed cell; `inside` keeps them as (ya, yb, xa, xb, dir) for the slabs
    // (top to bottom) and `pieces` in the edge's direction for the crossing counts.
    auto& pieces = sc.pieces;
    pieces.clear();
    for (std::uint32_t id : ids) {
        double ax, ay, bx, by;
        if (!cell_portion(edges[id], cx, ry, ax, ay, bx, by)) continue;
        if (ax == bx && ay == by) continue;
        pieces.push_back({ax, ay, bx, by});
        sc.breaks.push_back(ay);
        sc.breaks.push_back(by);
        if (ay == by) continue;  // horizontal: a slab boundary, no slab of its own
        if (ay < by) sc.inside.push_back({ay, by, ax, bx, 1});
        else sc.inside.push_back({by, ay, bx, ax, -1});
    }
    const std::size_t n = sc.inside.size();
    // Reference point in general position: on no piece's line through an end point.
    double rx = cx + kRef[0][0], ryy = ry + kRef[0][1];
    for (const auto& ref : kRef) {
        rx = cx + ref[0];
        ryy = ry + ref[1];
        bool ok = true;
        for (const ExactScratch::Piece& p : pieces)
            if (orient(p.ax, p.ay, p.bx, p.by, rx, ryy) == 0) { ok = false; break; }
        if (ok) break;
    }
    auto winding_offset = [&](double px, double py) {
        int l = 0;
        for (const ExactScratch::Piece& p : pieces) {
            const double o1 = orient(p.ax, p.ay, p.bx, p.by, rx, ryy);
            const double o2 = orient(p.ax, p.ay, p.bx, p.by, px, py);
            if ((o1 < 0) == (o2 < 0) || o2 == 0) continue;
            const double o3 = orient(rx, ryy, px, py, p.ax, p.ay);
            const double o4 = orient(rx, ryy, px, py, p.bx, p.by);
            if ((o3 < 0 && o4 < 0) || (o3 > 0 && o4 > 0)) continue;
            // The segment r -> p crosses the piece: into its negative side raises w.
            l += o2 < 0 ? 1 : -1;
        }
        return l;
    };

    bool dense = n > kMaxExactPieces;
    if (!dense) {
        // Pairwise crossings of the pieces cut the slabs too.
        for (std::size_t i = 0; i < n && !dense; ++i) {
            const auto& a = sc.inside[i];
            const double ka = (a.xb - a.xa) / (a.yb - a.ya);
            for (std::size_t j = i + 1; j < n; ++j) {
                const auto& b = sc.inside[j];
                const double lo = std::max(a.ya, b.ya), hi = std::min(a.yb, b.yb);
                if (!(hi > lo)) continue;
                const double kb = (b.xb - b.xa) / (b.yb - b.ya);
                if (ka == kb) continue;
                const double y = (b.xa - a.xa + a.ya * ka - b.ya * kb) / (ka - kb);
                if (y > lo && y < hi) sc.breaks.push_back(y);
            }
            if (static_cast<double>(sc.breaks.size()) * static_cast<double>(n) > 4 * kMaxSlabWork) dense = true;
        }
        std::sort(sc.breaks.begin(), sc.breaks.end());
        sc.breaks.erase(std::unique(sc.breaks.begin(), sc.breaks.end()), sc.breaks.end());
        if (static_cast<double>(sc.breaks.size()) * static_cast<double>(n) > kMaxSlabWork) dense = true;
    }
    double sum_l = 0;
    if (dense) {
        for (int k = 0; k < kDenseRows; ++k) {
            const double ym = ry + (k + 0.5) / kDenseRows;
            sc.active.clear();
            for (const auto& p : sc.inside) {
                if (!(p.ya <= ym && ym < p.yb)) continue;
                const double x = std::clamp(p.xa + (ym - p.ya) * (p.xb - p.xa) / (p.yb - p.ya), cx, cr);
                sc.active.push_back({x, x, x, p.dir});
            }
            std::sort(sc.active.begin(), sc.active.end(),
                      [](const ExactScratch::Cross& u, const ExactScratch::Cross& v) { return u.xm < v.xm; });
            double px = cx;
            int l = 0;
            bool known = false;
            const std::size_t na = sc.active.size();
            for (std::size_t i = 0; i <= na; ++i) {
                const double nx = i < na ? sc.active[i].xm : cr;
                if (nx > px) {
                    if (!known) {
                        l = winding_offset(0.5 * (px + nx), ym);
                        known = true;
                    }
                    const double area = (nx - px) / kDenseRows;
                    sc.regions.push_back({l, area});
                    sum_l += l * area;
                }
                if (i < na && known) l += sc.active[i].dir;
                px = nx;
            }
        }
    }
    for (std::size_t bi = 0; !dense && bi + 1 < sc.breaks.size(); ++bi) {
        const double y0 = std::max(sc.breaks[bi], ry), y1 = std::min(sc.breaks[bi + 1], rb);
        if (!(y1 > y0)) continue;
        const double ym = 0.5 * (y0 + y1), h = y1 - y0;
        sc.active.clear();
        for (const auto& p : sc.inside) {
            if (!(p.ya < ym && ym < p.yb)) continue;
            const double k = (p.xb - p.xa) / (p.yb - p.ya);
            sc.active.push_back({std::clamp(p.xa + (y0 - p.ya) * k, cx, cr), std::clamp(p.xa + (y1 - p.ya) * k, cx, cr),
                                 std::clamp(p.xa + (ym - p.ya) * k, cx, cr), p.dir});
        }
        std::sort(sc.active.begin(), sc.active.end(),
                  [](const ExactScratch::Cross& u, const ExactScratch::Cross& v) { return u.xm < v.xm; });
        // The leftmost region's offset by crossings from r; moving right across a piece changes
        // w by the piece's direction (down: +1), the accumulation's own convention.
        double px0 = cx, px1 = cx, pxm = cx;
        const std::size_t na = sc.active.size();
        int l = 0;
        bool known = false;  // l is computed by crossings at the first region with an area
        for (std::size_t i = 0; i <= na; ++i) {
            const double nx0 = i < na ? sc.active[i].x0 : cr, nx1 = i < na ? sc.active[i].x1 : cr;
            const double nxm = i < na ? sc.active[i].xm : cr;
            const double area = h * 0.5 * ((nx0 + nx1) - (px0 + px1));
            if (area > 0 && nxm > pxm) {
                if (!known) {
                    l = winding_offset(0.5 * (pxm + nxm), ym);
                    known = true;
                }
                sc.regions.push_back({l, area});
                sum_l += l * area;
            }
            if (i < na && known) l += sc.active[i].dir;
            px0 = nx0;
            px1 = nx1;
            pxm = nxm;
        }
    }
    const long w0 = std::lround(integral - sum_l);
    double coverage = 0;
    for (const auto& r : sc.regions) coverage += fill_value(w0 + r.b, rule) * r.area;
    return std::clamp(coverage, 0.0, 1.0);
}

std::uint8_t exact_cell_u8(const Edge* edges, std::vector<std::uint32_t>& ids, double cx, double ry, double integral,
                           FillRule rule, ExactScratch& scratch) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return area_to_u8(exact_cell_coverage(edges, ids, cx, ry, integral, rule, scratch));
}

}  // namespace casteljau::raster
