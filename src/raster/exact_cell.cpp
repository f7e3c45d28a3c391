// Raster stage, exact cells: the coverage of one pixel computed exactly from the edges in it.
//
// Accumulation yields f(integral of w) where the truth is the integral of f(w) (f: the fill rule
// applied to the winding number w). For a marked cell we compute the integral directly: cut the
// cell into horizontal slabs at every y where the picture changes (end points of edge pieces,
// crossings of the pieces inside the cell, and the y where an edge enters the cell from the left),
// so that inside a slab no two pieces cross and each spans the whole slab. Within a slab the
// winding number just left of the cell is constant (W: the signed count of pieces lying left of the
// cell there), and walking right it changes by each inside piece's direction; the area of each
// region between consecutive pieces is a trapezoid. Sum f(w) x area.
#include <algorithm>
#include <cmath>

#include "raster/raster_internal.hpp"

namespace casteljau::raster {

namespace {

inline double fill_value(int w, FillRule rule) {
    return rule == FillRule::NonZero ? (w != 0 ? 1.0 : 0.0) : ((w & 1) ? 1.0 : 0.0);
}

}  // namespace

double exact_cell_coverage(const std::vector<RowPiece>& pieces, double cx, double ry, FillRule rule,
                           ExactScratch& sc) {
    const double cr = cx + 1, rb = ry + 1;
    sc.left.clear();
    sc.inside.clear();
    sc.breaks.clear();
    sc.breaks.push_back(ry);
    sc.breaks.push_back(rb);
    for (const RowPiece& p : pieces) {
        const double xmin = std::min(p.x0, p.x1), xmax = std::max(p.x0, p.x1);
        if (xmin >= cr) continue;  // at or right of the cell's right side: no effect inside
        if (xmax <= cx) {          // entirely left (or on the left side): a constant contribution
            sc.left.push_back({p.y0, p.y1, 0, 0, p.dir});
            sc.breaks.push_back(p.y0);
            sc.breaks.push_back(p.y1);
            continue;
        }
        if (p.x0 == p.x1) {  // vertical, strictly inside the cell
            sc.inside.push_back({p.y0, p.y1, p.x0, p.x0, p.dir});
            sc.breaks.push_back(p.y0);
            sc.breaks.push_back(p.y1);
            continue;
        }
        // x(y) = p.x0 + (y - p.y0) k; find the y-intervals with x <= cx and cx < x < cr.
        const double k = (p.x1 - p.x0) / (p.y1 - p.y0);
        const double yl = p.y0 + (cx - p.x0) / k;  // y where x == cx
        const double yr = p.y0 + (cr - p.x0) / k;  // y where x == cr
        double lya, lyb, iya, iyb;
        if (k > 0) {
            lya = p.y0; lyb = std::min(yl, p.y1);
            iya = std::max(yl, p.y0); iyb = std::min(yr, p.y1);
        } else {
            lya = std::max(yl, p.y0); lyb = p.y1;
            iya = std::max(yr, p.y0); iyb = std::min(yl, p.y1);
        }
        if (lyb > lya) {
            sc.left.push_back({lya, lyb, 0, 0, p.dir});
            sc.breaks.push_back(lya);
            sc.breaks.push_back(lyb);
        }
        if (iyb > iya) {
            const double xa = std::clamp(p.x0 + (iya - p.y0) * k, cx, cr);
            const double xb = std::clamp(p.x0 + (iyb - p.y0) * k, cx, cr);
            sc.inside.push_back({iya, iyb, xa, xb, p.dir});
            sc.breaks.push_back(iya);
            sc.breaks.push_back(iyb);
        }
    }
    // Crossings of inside pieces.
    const std::size_t n = sc.inside.size();
    for (std::size_t i = 0; i < n; ++i) {
        const auto& a = sc.inside[i];
        const double ka = (a.xb - a.xa) / (a.yb - a.ya);
        for (std::size_t j = i + 1; j < n; ++j) {
            const auto& b = sc.inside[j];
            const double lo = std::max(a.ya, b.ya), hi = std::min(a.yb, b.yb);
            if (!(hi > lo)) continue;
            const double kb = (b.xb - b.xa) / (b.yb - b.ya);
            if (ka == kb) continue;  // parallel (or coincident): no single crossing
            // a.xa + (y - a.ya) ka == b.xa + (y - b.ya) kb
            const double y = (b.xa - a.xa + a.ya * ka - b.ya * kb) / (ka - kb);
            if (y > lo && y < hi) sc.breaks.push_back(y);
        }
    }
    std::sort(sc.breaks.begin(), sc.breaks.end());
    double coverage = 0;
    for (std::size_t bi = 0; bi + 1 < sc.breaks.size(); ++bi) {
        const double y0 = std::max(sc.breaks[bi], ry), y1 = std::min(sc.breaks[bi + 1], rb);
        if (!(y1 > y0)) continue;
        const double ym = 0.5 * (y0 + y1), h = y1 - y0;
        int w = 0;
        for (const auto& l : sc.left)
            if (l.ya < ym && ym < l.yb) w += l.dir;
        sc.active.clear();
        for (const auto& p : sc.inside) {
            if (!(p.ya < ym && ym < p.yb)) continue;
            const double k = (p.xb - p.xa) / (p.yb - p.ya);
            sc.active.push_back({std::clamp(p.xa + (y0 - p.ya) * k, cx, cr), std::clamp(p.xa + (y1 - p.ya) * k, cx, cr),
                                 p.xa + (ym - p.ya) * k, p.dir});
        }
        std::sort(sc.active.begin(), sc.active.end(),
                  [](const ExactScratch::Cross& a, const ExactScratch::Cross& b) { return a.xm < b.xm; });
        double px0 = cx, px1 = cx;
        for (const auto& a : sc.active) {
            coverage += fill_value(w, rule) * h * 0.5 * ((a.x0 + a.x1) - (px0 + px1));
            w += a.dir;
            px0 = a.x0;
            px1 = a.x1;
        }
        coverage += fill_value(w, rule) * h * 0.5 * ((cr + cr) - (px0 + px1));
    }
    return std::clamp(coverage, 0.0, 1.0);
}

}  // namespace casteljau::raster
