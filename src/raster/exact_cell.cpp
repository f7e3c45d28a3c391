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

// One cell's exact coverage, step by step (see the top of the file): the pieces and the slab
// breaks, the reference point, the crossings, then either the slabs or the dense lines.
class ExactCell {
public:
    ExactCell(double cx, double ry, ExactScratch& sc) : cx_(cx), ry_(ry), cr_(cx + 1), rb_(ry + 1), sc_(sc) {}

    double coverage(const Edge* edges, const std::vector<std::uint32_t>& ids, double integral, FillRule rule) {
        clip_pieces(edges, ids);
        choose_reference();
        plan();
        start_sweep();
        if (dense_)
            dense_lines();
        else
            slabs();
        const long w0 = std::lround(integral - sum_l_);
        double coverage = 0;
        for (const auto& r : sc_.regions) coverage += fill_value(w0 + r.b, rule) * r.area;
        return std::clamp(coverage, 0.0, 1.0);
    }

private:
    // Pieces inside the closed cell; `inside` keeps them as (ya, yb, xa, xb, slope, dir) for the
    // slabs (top to bottom) and `pieces` in the edge's direction for the crossing counts.
    void clip_pieces(const Edge* edges, const std::vector<std::uint32_t>& ids) {
        sc_.inside.clear();
        sc_.breaks.clear();
        sc_.regions.clear();
        sc_.breaks.push_back(ry_);
        sc_.breaks.push_back(rb_);
        sc_.pieces.clear();
        for (std::uint32_t id : ids) {
            double ax, ay, bx, by;
            if (!cell_portion(edges[id], cx_, ry_, ax, ay, bx, by)) continue;
            if (ax == bx && ay == by) continue;
            sc_.pieces.push_back({ax, ay, bx, by});
            sc_.breaks.push_back(ay);
            sc_.breaks.push_back(by);
            if (ay == by) continue;  // horizontal: a slab boundary, no slab of its own
            if (ay < by)
                sc_.inside.push_back({ay, by, ax, bx, (bx - ax) / (by - ay), 1});
            else
                sc_.inside.push_back({by, ay, bx, ax, (ax - bx) / (ay - by), -1});
        }
        n_ = sc_.inside.size();
        sc_.work += static_cast<double>(ids.size());  // clipping every edge to the cell
    }

    // Reference point in general position: on no piece's line through an end point.
    void choose_reference() {
        rx_ = cx_ + kRef[0][0];
        ry_ref_ = ry_ + kRef[0][1];
        for (const auto& ref : kRef) {
            rx_ = cx_ + ref[0];
            ry_ref_ = ry_ + ref[1];
            bool ok = true;
            for (const ExactScratch::Piece& p : sc_.pieces)
                if (orient(p.ax, p.ay, p.bx, p.by, rx_, ry_ref_) == 0) {
                    ok = false;
                    break;
                }
            if (ok) break;
        }
    }

    // L at (px, py): the signed crossings of the segment from the reference point.
    int winding_offset(double px, double py) const {
        int l = 0;
        for (const ExactScratch::Piece& p : sc_.pieces) {
            const double o1 = orient(p.ax, p.ay, p.bx, p.by, rx_, ry_ref_);
            const double o2 = orient(p.ax, p.ay, p.bx, p.by, px, py);
            if ((o1 < 0) == (o2 < 0) || o2 == 0) continue;
            const double o3 = orient(rx_, ry_ref_, px, py, p.ax, p.ay);
            const double o4 = orient(rx_, ry_ref_, px, py, p.bx, p.by);
            if ((o3 < 0 && o4 < 0) || (o3 > 0 && o4 > 0)) continue;
            // The segment r -> p crosses the piece: into its negative side raises w.
            l += o2 < 0 ? 1 : -1;
        }
        return l;
    }

    double budget_left() const { return std::max(0.0, sc_.budget - sc_.work); }

    // Work is counted in piece visits: the pairwise crossing search visits n^2 / 2 pairs, a slab or
    // a dense line visits its active pieces and, where its offset cannot be read off the crossings
    // of the vertical through r (below), every piece once more through winding_offset: 2n per
    // line, an upper bound. Chooses the dense method when the slabs would cost too much.
    void plan() {
        const double nd = static_cast<double>(n_);
        const double pair_work = 0.5 * nd * nd;
        dense_ = n_ > kMaxExactPieces || pair_work > budget_left();
        if (!dense_) {
            add_crossings();
            sc_.work += pair_work;
            std::sort(sc_.breaks.begin(), sc_.breaks.end());
            sc_.breaks.erase(std::unique(sc_.breaks.begin(), sc_.breaks.end()), sc_.breaks.end());
            const double slab_work = 2 * static_cast<double>(sc_.breaks.size()) * nd;
            if (slab_work > 2 * kMaxSlabWork || slab_work > budget_left())
                dense_ = true;
            else
                sc_.work += slab_work;
        }
        if (dense_) {
            lines_ =
                static_cast<int>(std::clamp(budget_left() / (2 * nd + 1), double{kMinDenseRows}, double{kDenseRows}));
            sc_.work += 2 * nd * lines_;
            ++sc_.dense_cells;
        }
    }

    // Pairwise crossings of the pieces cut the slabs too (too many of them: the dense method).
    void add_crossings() {
        const double nd = static_cast<double>(n_);
        for (std::size_t i = 0; i < n_ && !dense_; ++i) {
            const auto& a = sc_.inside[i];
            const double ka = a.k;
            for (std::size_t j = i + 1; j < n_; ++j) {
                const auto& b = sc_.inside[j];
                const double lo = std::max(a.ya, b.ya), hi = std::min(a.yb, b.yb);
                if (!(hi > lo)) continue;
                const double kb = b.k;
                if (ka == kb) continue;
                const double y = (b.xa - a.xa + a.ya * ka - b.ya * kb) / (ka - kb);
                if (y > lo && y < hi) sc_.breaks.push_back(y);
            }
            if (static_cast<double>(sc_.breaks.size()) * nd > 4 * kMaxSlabWork) dense_ = true;
        }
    }

    // Both methods go down the cell with an active list in x order: pieces enter in order of their
    // top end and leave past their bottom end, and an insertion sort restores the x order from the
    // previous line's, so a line costs its active pieces plus the swaps of the pieces that crossed
    // since the line above, not a full sort. The offset of a line's leftmost region is read without
    // counting crossings from r for every line: along the vertical x = rx through r, w changes only
    // where a piece crosses it, by +1 going down across a piece that runs right to left (onto its
    // negative side) and -1 otherwise. So L(rx, y) is a running sum over those crossings in y order,
    // and the leftmost region is that minus the directions of the active pieces left of rx.
    void start_sweep() {
        auto& order = sc_.order;
        order.resize(n_);
        for (std::size_t i = 0; i < n_; ++i) order[i] = static_cast<std::uint32_t>(i);
        std::sort(order.begin(), order.end(),
                  [&](std::uint32_t u, std::uint32_t v) { return sc_.inside[u].ya < sc_.inside[v].ya; });
        sc_.live.clear();
        next_ = 0;
        auto& vc = sc_.vcross;
        vc.clear();
        for (const ExactScratch::Piece& p : sc_.pieces)
            if ((p.ax < rx_) != (p.bx < rx_))
                vc.push_back({p.ay + (rx_ - p.ax) * (p.by - p.ay) / (p.bx - p.ax), p.bx < p.ax ? 1 : -1});
        std::sort(vc.begin(), vc.end(),
                  [](const ExactScratch::VCross& u, const ExactScratch::VCross& v) { return u.y < v.y; });
        above_r_ = 0;
        for (const ExactScratch::VCross& c : vc)
            if (c.y < ry_ref_) above_r_ += c.d;
        vi_ = 0;
        vsum_ = 0;
    }

    // Makes `live` the pieces with ya < y < yb (ya <= y when `from_top`), y increasing call to call.
    void advance(double y, bool from_top) {
        auto& live = sc_.live;
        std::size_t kept = 0;
        for (const std::uint32_t i : live)
            if (y < sc_.inside[i].yb) live[kept++] = i;
        live.resize(kept);
        for (;
             next_ < n_ && (sc_.inside[sc_.order[next_]].ya < y || (from_top && sc_.inside[sc_.order[next_]].ya == y));
             ++next_)
            if (y < sc_.inside[sc_.order[next_]].yb) live.push_back(sc_.order[next_]);
    }

    // Sorts sc.active (filled in `live` order) by xm, carrying `live` along. Insertion from the
    // previous line's order costs the swaps of the pieces that crossed since; when they pass a few
    // per piece (thousands of pieces crossing every which way between two lines of the dense
    // method, where the swaps would grow with the square of the pieces), a full sort takes over.
    // The swaps and the full sorts count as work.
    void sort_active() {
        auto& live = sc_.live;
        auto& active = sc_.active;
        const std::size_t na = live.size();
        const std::size_t max_swaps = 4 * na + 64;
        std::size_t swaps = 0;
        for (std::size_t a = 1; a < na; ++a) {
            const ExactScratch::Cross c = active[a];
            const std::uint32_t id = live[a];
            std::size_t b = a;
            for (; b > 0 && active[b - 1].xm > c.xm; --b) {
                active[b] = active[b - 1];
                live[b] = live[b - 1];
            }
            active[b] = c;
            live[b] = id;
            swaps += a - b;
            if (swaps > max_swaps) {
                sc_.ranked.resize(na);
                for (std::size_t i = 0; i < na; ++i) sc_.ranked[i] = {active[i], live[i]};
                std::sort(sc_.ranked.begin(), sc_.ranked.end(),
                          [](const ExactScratch::Ranked& u, const ExactScratch::Ranked& v) { return u.c.xm < v.c.xm; });
                for (std::size_t i = 0; i < na; ++i) {
                    active[i] = sc_.ranked[i].c;
                    live[i] = sc_.ranked[i].id;
                }
                sc_.work += static_cast<double>(na) * std::log2(static_cast<double>(na));
                return;
            }
        }
        sc_.work += static_cast<double>(swaps);
    }

    // Lines that pass within kNearRef of a crossing of the vertical through r, or whose active
    // pieces pass that close to rx, count crossings from r instead (winding_offset).
    static constexpr double kNearRef = 1e-9;

    // Sets l to the offset of the leftmost region at height y (y increasing call to call, active
    // sorted by xm); false when y or an active piece is too close to call.
    bool leftmost_offset(double y, int& l) {
        const auto& vc = sc_.vcross;
        for (; vi_ < vc.size() && vc[vi_].y < y; ++vi_) vsum_ += vc[vi_].d;
        if ((vi_ < vc.size() && vc[vi_].y - y < kNearRef) || (vi_ > 0 && y - vc[vi_ - 1].y < kNearRef)) return false;
        int left = 0;
        for (const ExactScratch::Cross& a : sc_.active) {
            if (std::abs(a.xm - rx_) < kNearRef) return false;
            if (a.xm > rx_) break;
            left += a.dir;
        }
        l = vsum_ - above_r_ - left;
        return true;
    }

    // The dense method: lines through the cell, each integrated exactly in x.
    void dense_lines() {
        // Piece ends by height, so that a line passing within kNearRef of one (where rounding may
        // have left a hair between a clipped piece and the cell's edge) counts crossings from r.
        std::sort(sc_.breaks.begin(), sc_.breaks.end());
        std::size_t bi = 0;
        for (int k = 0; k < lines_; ++k) {
            const double ym = ry_ + (k + 0.5) / lines_;
            while (bi < sc_.breaks.size() && sc_.breaks[bi] < ym - kNearRef) ++bi;
            const bool near_end = bi < sc_.breaks.size() && sc_.breaks[bi] < ym + kNearRef;
            advance(ym, true);
            sc_.active.resize(sc_.live.size());
            for (std::size_t a = 0; a < sc_.live.size(); ++a) {
                const auto& p = sc_.inside[sc_.live[a]];
                const double x = std::clamp(p.xa + (ym - p.ya) * (p.xb - p.xa) / (p.yb - p.ya), cx_, cr_);
                sc_.active[a] = {x, x, x, p.dir};
            }
            sort_active();
            double px = cx_;
            int l = 0;
            bool known = !near_end && leftmost_offset(ym, l);
            const std::size_t na = sc_.active.size();
            for (std::size_t i = 0; i <= na; ++i) {
                const double nx = i < na ? sc_.active[i].xm : cr_;
                if (nx > px) {
                    if (!known) {
                        l = winding_offset(0.5 * (px + nx), ym);
                        known = true;
                    }
                    const double area = (nx - px) / lines_;
                    sc_.regions.push_back({l, area});
                    sum_l_ += l * area;
                }
                if (i < na && known) l += sc_.active[i].dir;
                px = nx;
            }
        }
    }

    // The exact method: slabs between consecutive breaks, trapezoids between consecutive pieces.
    void slabs() {
        for (std::size_t bi = 0; bi + 1 < sc_.breaks.size(); ++bi) {
            const double y0 = std::max(sc_.breaks[bi], ry_), y1 = std::min(sc_.breaks[bi + 1], rb_);
            if (!(y1 > y0)) continue;
            const double ym = 0.5 * (y0 + y1), h = y1 - y0;
            advance(ym, false);
            sc_.active.resize(sc_.live.size());
            for (std::size_t a = 0; a < sc_.live.size(); ++a) {
                const auto& p = sc_.inside[sc_.live[a]];
                const double k = p.k;
                sc_.active[a] = {std::clamp(p.xa + (y0 - p.ya) * k, cx_, cr_),
                                 std::clamp(p.xa + (y1 - p.ya) * k, cx_, cr_),
                                 std::clamp(p.xa + (ym - p.ya) * k, cx_, cr_), p.dir};
            }
            sort_active();
            slab_regions(ym, h);
        }
    }

    // The regions of one slab (middle ym, height h), left to right; moving right across a piece
    // changes w by the piece's direction (down: +1), the accumulation's own convention.
    void slab_regions(double ym, double h) {
        double px0 = cx_, px1 = cx_, pxm = cx_;
        const std::size_t na = sc_.active.size();
        int l = 0;
        // Else l is computed by crossings from r at the first region with an area. A slab thinner
        // than 2 kNearRef lies between piece ends that rounding may have left a hair apart (a
        // piece clipped at the cell's edge): crossings counted along another path could differ.
        bool known = h > 2 * kNearRef && leftmost_offset(ym, l);
        for (std::size_t i = 0; i <= na; ++i) {
            const double nx0 = i < na ? sc_.active[i].x0 : cr_, nx1 = i < na ? sc_.active[i].x1 : cr_;
            const double nxm = i < na ? sc_.active[i].xm : cr_;
            const double area = h * 0.5 * ((nx0 + nx1) - (px0 + px1));
            if (area > 0 && nxm > pxm) {
                if (!known) {
                    l = winding_offset(0.5 * (pxm + nxm), ym);
                    known = true;
                }
                sc_.regions.push_back({l, area});
                sum_l_ += l * area;
            }
            if (i < na && known) l += sc_.active[i].dir;
            px0 = nx0;
            px1 = nx1;
            pxm = nxm;
        }
    }

    const double cx_, ry_, cr_, rb_;
    ExactScratch& sc_;
    std::size_t n_ = 0;           // pieces with a height
    double rx_ = 0, ry_ref_ = 0;  // the reference point r
    bool dense_ = false;
    int lines_ = kDenseRows;
    std::size_t next_ = 0;        // the next piece by top end to enter the active list
    std::size_t vi_ = 0;          // the next crossing of the vertical through r
    int vsum_ = 0, above_r_ = 0;  // crossings of that vertical so far, and above r
    double sum_l_ = 0;            // the integral of L over the regions so far
};

}  // namespace

double exact_cell_coverage(const Edge* edges, const std::vector<std::uint32_t>& ids, double cx, double ry,
                           double integral, FillRule rule, ExactScratch& sc) {
    return ExactCell(cx, ry, sc).coverage(edges, ids, integral, rule);
}

std::uint8_t exact_cell_u8(const Edge* edges, std::vector<std::uint32_t>& ids, double cx, double ry, double integral,
                           FillRule rule, ExactScratch& scratch) {
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    return area_to_u8(exact_cell_coverage(edges, ids, cx, ry, integral, rule, scratch));
}

}  // namespace casteljau::raster
