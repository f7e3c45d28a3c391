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
// L is counted along a path only once per slab: down the vertical through r to the slab's middle
// (a running sum of the crossings of that vertical), then left past the slab's pieces; moving right
// across a piece then adds its direction. Any path inside the cell gives the same count, so this
// equals the straight segment's, which is kept for the slabs where the path would pass within a
// hair of a piece end.
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
    if (!clip(-dx, qx0, -ix) || !clip(dx, qx1, ix) || !clip(-dy, qy0, -iy) || !clip(dy, qy1, iy)) return false;
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
constexpr double kRef[4][2] = {
    {0.5012345, 0.4987654}, {0.3141593, 0.7182818}, {0.6931472, 0.2718282}, {0.1414214, 0.8660254}};

// For pathological pixels the slab decomposition (up to cubic in the pieces) gives way to
// horizontal lines through the cell, each integrated exactly in x (the dense method): the result is
// then within 1/(2 lines) of the pixel instead of exact, on such pixels only. The switch happens
// when slabs x pieces (the work of the exact method) would pass kMaxSlabWork (equal break points
// are merged first: stacked copies of one shape make few distinct slabs), or straight away beyond
// kMaxExactPieces pieces, where even finding the crossings costs too much. A 500-segment scribble
// inside one pixel (62,000 crossings) is still computed exactly.
//
// Each fill also has a work budget for all its exact cells together (ExactScratch::budget, set by
// the engine from the fill's segment count), so that a shape made of thousands of pieces stacked
// in many pixels costs time in proportion to its size, not to the square of it: once the budget is
// spent, cells take the dense method with kDenseRows lines shrinking to kMinDenseRows (within
// 1/32 of a pixel).
constexpr std::size_t kMaxExactPieces = 4096;
constexpr double kMaxSlabWork = 6e7;
constexpr int kDenseRows = 1024;
constexpr int kMinDenseRows = 16;

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
        if (ay < by)
            sc.inside.push_back({ay, by, ax, bx, (bx - ax) / (by - ay), 1});
        else
            sc.inside.push_back({by, ay, bx, ax, (ax - bx) / (ay - by), -1});
    }
    const std::size_t n = sc.inside.size();
    sc.work += static_cast<double>(ids.size());  // clipping every edge to the cell
    // Reference point in general position: on no piece's line through an end point.
    double rx = cx + kRef[0][0], ryy = ry + kRef[0][1];
    for (const auto& ref : kRef) {
        rx = cx + ref[0];
        ryy = ry + ref[1];
        bool ok = true;
        for (const ExactScratch::Piece& p : pieces)
            if (orient(p.ax, p.ay, p.bx, p.by, rx, ryy) == 0) {
                ok = false;
                break;
            }
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

    // Work is counted in piece visits: the pairwise crossing search visits n^2 / 2 pairs, a slab or
    // a dense line visits its active pieces and, where its offset cannot be read off the crossings
    // of the vertical through r (below), every piece once more through winding_offset: 2n per
    // line, an upper bound.
    const double nd = static_cast<double>(n);
    const double pair_work = 0.5 * nd * nd;
    auto left = [&] { return std::max(0.0, sc.budget - sc.work); };
    bool dense = n > kMaxExactPieces || pair_work > left();
    if (!dense) {
        // Pairwise crossings of the pieces cut the slabs too.
        for (std::size_t i = 0; i < n && !dense; ++i) {
            const auto& a = sc.inside[i];
            const double ka = a.k;
            for (std::size_t j = i + 1; j < n; ++j) {
                const auto& b = sc.inside[j];
                const double lo = std::max(a.ya, b.ya), hi = std::min(a.yb, b.yb);
                if (!(hi > lo)) continue;
                const double kb = b.k;
                if (ka == kb) continue;
                const double y = (b.xa - a.xa + a.ya * ka - b.ya * kb) / (ka - kb);
                if (y > lo && y < hi) sc.breaks.push_back(y);
            }
            if (static_cast<double>(sc.breaks.size()) * nd > 4 * kMaxSlabWork) dense = true;
        }
        sc.work += pair_work;
        std::sort(sc.breaks.begin(), sc.breaks.end());
        sc.breaks.erase(std::unique(sc.breaks.begin(), sc.breaks.end()), sc.breaks.end());
        const double slab_work = 2 * static_cast<double>(sc.breaks.size()) * nd;
        if (slab_work > 2 * kMaxSlabWork || slab_work > left())
            dense = true;
        else
            sc.work += slab_work;
    }
    int lines = kDenseRows;
    if (dense) {
        lines = static_cast<int>(std::clamp(left() / (2 * nd + 1), double{kMinDenseRows}, double{kDenseRows}));
        sc.work += 2 * nd * lines;
        ++sc.dense_cells;
    }
    double sum_l = 0;
    // Both methods below go down the cell with an active list in x order: pieces enter in order of
    // their top end and leave past their bottom end, and an insertion sort restores the x order
    // from the previous line's, so a line costs its active pieces plus the swaps of the pieces that
    // crossed since the line above, not a full sort.
    auto& order = sc.order;
    order.resize(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = static_cast<std::uint32_t>(i);
    std::sort(order.begin(), order.end(),
              [&](std::uint32_t u, std::uint32_t v) { return sc.inside[u].ya < sc.inside[v].ya; });
    auto& live = sc.live;
    live.clear();
    std::size_t next = 0;
    // Makes `live` the pieces with ya < y < yb (ya <= y when `from_top`), y increasing call to call.
    auto advance = [&](double y, bool from_top) {
        std::size_t kept = 0;
        for (const std::uint32_t i : live)
            if (y < sc.inside[i].yb) live[kept++] = i;
        live.resize(kept);
        for (; next < n && (sc.inside[order[next]].ya < y || (from_top && sc.inside[order[next]].ya == y)); ++next)
            if (y < sc.inside[order[next]].yb) live.push_back(order[next]);
    };
    // Sorts sc.active (filled in `live` order) by xm, carrying `live` along. Insertion from the
    // previous line's order costs the swaps of the pieces that crossed since; when they pass a few
    // per piece (thousands of pieces crossing every which way between two lines of the dense
    // method, where the swaps would grow with the square of the pieces), a full sort takes over.
    // The swaps and the full sorts count as work.
    auto sort_active = [&] {
        const std::size_t na = live.size();
        const std::size_t max_swaps = 4 * na + 64;
        std::size_t swaps = 0;
        for (std::size_t a = 1; a < na; ++a) {
            const ExactScratch::Cross c = sc.active[a];
            const std::uint32_t id = live[a];
            std::size_t b = a;
            for (; b > 0 && sc.active[b - 1].xm > c.xm; --b) {
                sc.active[b] = sc.active[b - 1];
                live[b] = live[b - 1];
            }
            sc.active[b] = c;
            live[b] = id;
            swaps += a - b;
            if (swaps > max_swaps) {
                sc.ranked.resize(na);
                for (std::size_t i = 0; i < na; ++i) sc.ranked[i] = {sc.active[i], live[i]};
                std::sort(sc.ranked.begin(), sc.ranked.end(),
                          [](const ExactScratch::Ranked& u, const ExactScratch::Ranked& v) { return u.c.xm < v.c.xm; });
                for (std::size_t i = 0; i < na; ++i) {
                    sc.active[i] = sc.ranked[i].c;
                    live[i] = sc.ranked[i].id;
                }
                sc.work += static_cast<double>(na) * std::log2(static_cast<double>(na));
                return;
            }
        }
        sc.work += static_cast<double>(swaps);
    };
    // The offset of a line's leftmost region without counting crossings from r for every line:
    // along the vertical x = rx through r, w changes only where a piece crosses it, by +1 going
    // down across a piece that runs right to left (onto its negative side) and -1 otherwise. So
    // L(rx, y) is a running sum over those crossings in y order, and the leftmost region is that
    // minus the directions of the active pieces left of rx. Lines that pass within kNearRef of a
    // crossing, or whose active pieces pass that close to rx, use winding_offset instead.
    constexpr double kNearRef = 1e-9;
    auto& vc = sc.vcross;
    vc.clear();
    for (const ExactScratch::Piece& p : pieces)
        if ((p.ax < rx) != (p.bx < rx))
            vc.push_back({p.ay + (rx - p.ax) * (p.by - p.ay) / (p.bx - p.ax), p.bx < p.ax ? 1 : -1});
    std::sort(vc.begin(), vc.end(),
              [](const ExactScratch::VCross& u, const ExactScratch::VCross& v) { return u.y < v.y; });
    int above_r = 0;
    for (const ExactScratch::VCross& c : vc)
        if (c.y < ryy) above_r += c.d;
    std::size_t vi = 0;
    int vsum = 0;
    // Sets l to the offset of the leftmost region at height y (y increasing call to call, active
    // sorted by xm); false when y or an active piece is too close to call.
    auto leftmost_offset = [&](double y, int& l) {
        for (; vi < vc.size() && vc[vi].y < y; ++vi) vsum += vc[vi].d;
        if ((vi < vc.size() && vc[vi].y - y < kNearRef) || (vi > 0 && y - vc[vi - 1].y < kNearRef)) return false;
        int left = 0;
        for (const ExactScratch::Cross& a : sc.active) {
            if (std::abs(a.xm - rx) < kNearRef) return false;
            if (a.xm > rx) break;
            left += a.dir;
        }
        l = vsum - above_r - left;
        return true;
    };
    if (dense) {
        // Piece ends by height, so that a line passing within kNearRef of one (where rounding may
        // have left a hair between a clipped piece and the cell's edge) counts crossings from r.
        std::sort(sc.breaks.begin(), sc.breaks.end());
        std::size_t bi = 0;
        for (int k = 0; k < lines; ++k) {
            const double ym = ry + (k + 0.5) / lines;
            while (bi < sc.breaks.size() && sc.breaks[bi] < ym - kNearRef) ++bi;
            const bool near_end = bi < sc.breaks.size() && sc.breaks[bi] < ym + kNearRef;
            advance(ym, true);
            sc.active.resize(live.size());
            for (std::size_t a = 0; a < live.size(); ++a) {
                const auto& p = sc.inside[live[a]];
                const double x = std::clamp(p.xa + (ym - p.ya) * (p.xb - p.xa) / (p.yb - p.ya), cx, cr);
                sc.active[a] = {x, x, x, p.dir};
            }
            sort_active();
            double px = cx;
            int l = 0;
            bool known = !near_end && leftmost_offset(ym, l);
            const std::size_t na = sc.active.size();
            for (std::size_t i = 0; i <= na; ++i) {
                const double nx = i < na ? sc.active[i].xm : cr;
                if (nx > px) {
                    if (!known) {
                        l = winding_offset(0.5 * (px + nx), ym);
                        known = true;
                    }
                    const double area = (nx - px) / lines;
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
        advance(ym, false);
        sc.active.resize(live.size());
        for (std::size_t a = 0; a < live.size(); ++a) {
            const auto& p = sc.inside[live[a]];
            const double k = p.k;
            sc.active[a] = {std::clamp(p.xa + (y0 - p.ya) * k, cx, cr), std::clamp(p.xa + (y1 - p.ya) * k, cx, cr),
                            std::clamp(p.xa + (ym - p.ya) * k, cx, cr), p.dir};
        }
        sort_active();
        // The leftmost region's offset by crossings from r; moving right across a piece changes
        // w by the piece's direction (down: +1), the accumulation's own convention.
        double px0 = cx, px1 = cx, pxm = cx;
        const std::size_t na = sc.active.size();
        int l = 0;
        // Else l is computed by crossings from r at the first region with an area. A slab thinner
        // than 2 kNearRef lies between piece ends that rounding may have left a hair apart (a
        // piece clipped at the cell's edge): crossings counted along another path could differ.
        bool known = h > 2 * kNearRef && leftmost_offset(ym, l);
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
