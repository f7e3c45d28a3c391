// Raster stage, the engine: accumulate edges as they arrive, check overlaps by visits, resolve the
// few cells that need it exactly, scan the rows.
//
// One dense buffer per run: the shape's whole box, or one band of a larger box (rasterizer.cpp
// decides). Accumulation is the cover/area scheme of FreeType's gray rasterizer and font-rs: for a
// piece of an edge inside one row with signed height d, acc[k] gets d times the part of cell k to
// the piece's right, acc[k + 1] the rest; a prefix sum along the row gives the integral of the
// winding number over each pixel. The buffer is double: windings of hundreds stay exact. Without
// the overlap check (the shape was proven simple, or exactness is off), shapes at most
// kRowVectorMax SIMD vectors (and 64 px) wide use row vectors instead (RowPiece in raster_internal.hpp): the
// walk lists each edge's pieces per row, and finish() adds every piece's area to its whole row,
// in float (the precision this leaves is stated in casteljau/raster.hpp).
//
// Overlap check (only for shapes not proven simple before rasterizing: see topology.cpp). Plain
// accumulation is exact in a cell whose winding numbers lie in one unit interval. Edges arrive in contour order, so the walk knows, for every cell it enters, that the
// contour is starting a new "visit" there: a maximal run of consecutive edges inside that cell.
//   - A cell with one visit whose run cannot cross itself and which enters and leaves through the
//     cell's boundary is split by it into two regions whose windings differ by one: exact. A run
//     cannot cross itself when it is monotone in x or in y, has at most two edges (one bend), or
//     (checked pairwise, up to 32 edges) no two of its edges meet except consecutive ones at their
//     vertex. (The run through a contour's start vertex arrives in two parts, the contour's first
//     and last edges; they are merged when the contour closes.)
//   - A cell with two to six such runs that do not meet inside the closed cell: every region
//     between them touches the cell's boundary, so the windings in the cell are those met going
//     around the boundary, changing by -1 where a run enters and +1 where one leaves. When they
//     take two values at most (for two runs: entries and exits alternate, as in a stem with one
//     edge up and one down), accumulation is exact. Common cases are decided in closed form (two
//     single edges: which side of each other they lie on) or from where the runs enter and leave
//     (runs whose edges meet nowhere), without clipping every piece. The commonest, a contour
//     that leaves the cell and comes back one vertex later (on a world map at 4096 px, 13,400 of
//     28,000 cells with more than one run or a run that is not monotone), is decided by the walk
//     as the second visit starts, while both edges are in cache; the cell is checked after all
//     if a third visit comes or the second run grows.
//   - A closed run with every vertex inside the cell (a small island or lake of a map) is a loop:
//     simple when its edges meet only consecutively, it adds its orientation to the winding of
//     the region around it, read by crossing the other runs from its first vertex to the cell's
//     right side. With loops among the runs, accumulation is exact when all windings so found
//     take two values at most.
//   - Every other cell with visits (crossings, stacked copies, more than six runs, loops on the
//     boundary) is recomputed exactly from its edges (exact_cell.cpp) with the accumulated
//     integral.
// Only positive-length pieces inside the open cell count as visits: an edge along a cell's
// boundary only moves cover, which accumulation gets right.
#include <algorithm>
#include <cassert>
#include <climits>
#include <cmath>
#include <cstring>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "raster/engine.hpp"

namespace casteljau::raster {

namespace {

// The exact cells of one fill share a work budget (exact_cell.cpp): Limits::exact_work (5e7 by
// default: enough for any real shape to be exact everywhere, a glyph's or a map's exact cells use a
// small part of it) plus an amount growing with the fill's size, so that only shapes piling
// thousands of pieces into many pixels fall back to the dense method.
constexpr double kExactWorkPerSegment = 2000;
// Past this many times the budget, the remaining exact cells keep their accumulated coverage: the
// dense method still costs a sort of the cell's pieces per line, and a singular transform can pass
// every piece of a shape through hundreds of cells.
constexpr double kExactWorkCeiling = 2;

// Position of a point on the boundary of the unit cell (local coordinates) as a parameter in
// [0, 4) going around it; -1 when the point is not on the boundary.
double boundary_param(double x, double y) {
    constexpr double eps = 1e-9;
    const double dt = y, dr = 1 - x, db = 1 - y, dl = x;
    const double m = std::min(std::min(dt, dr), std::min(db, dl));
    if (m > eps) return -1;
    if (m == dt) return std::clamp(x, 0.0, 1.0);
    if (m == dr) return 1 + std::clamp(y, 0.0, 1.0);
    if (m == db) return 2 + (1 - std::clamp(x, 0.0, 1.0));
    return 3 + (1 - std::clamp(y, 0.0, 1.0));
}

// Neither end point of e lies inside the open cell (col, row).
inline bool passes_through(const Edge& e, int col, int row) {
    auto inside = [&](double x, double y) { return x > col && x < col + 1 && y > row && y < row + 1; };
    return !inside(e.x0, e.y0) && !inside(e.x1, e.y1);
}

// Edges `first` and `second`, consecutive along a contour (first ends where second starts, at V),
// both passing through the cell (col, row) (passes_through): whether the contour leaves the cell
// and comes back one vertex later with V outside the closed cell. Lines from V meet only at V
// unless they leave it along one ray, which clearly non-parallel or opposite directions rule out.
// The part of the cell between the two edges is then the cone at V cut by the cell, whose boundary
// arc nearer V joins the first edge's exit to the second's entry, so entries and exits alternate
// around the cell: accumulation is exact there.
bool leaves_and_returns(const Edge& first, const Edge& second, int col, int row) {
    const double vx = first.x1, vy = first.y1;
    const bool v_outside = vx < col || vx > col + 1 || vy < row || vy > row + 1;
    const double ux = first.x0 - vx, uy = first.y0 - vy, wx = second.x1 - vx, wy = second.y1 - vy;
    const double cross = ux * wy - uy * wx, dot = ux * wx + uy * wy;
    const double scale = (std::fabs(ux) + std::fabs(uy)) * (std::fabs(wx) + std::fabs(wy));
    return v_outside && (std::fabs(cross) > 1e-9 * scale || dot < 0);
}

// Two runs that do not meet, entering at ta0, tb0 and leaving at ta1, tb1 (boundary parameters;
// -1: not on the boundary). Going around the boundary the winding changes by -1 at every entry
// and +1 at every exit, so it takes two values only when entries and exits alternate: the end of
// one run is next to the start of the other.
bool ends_alternate(double ta0, double ta1, double tb0, double tb1) {
    if (ta0 < 0 || ta1 < 0 || tb0 < 0 || tb1 < 0) return false;
    auto fwd = [&](double t) {  // distance going around from a's exit
        const double d = t - ta1;
        return d < 0 ? d + 4 : d;
    };
    const double da = fwd(ta0), d0 = fwd(tb0), d1 = fwd(tb1);
    if (da == 0 || d0 == 0 || d1 == 0 || d0 == da || d1 == da || d0 == d1) return false;
    const bool before0 = d0 < da, before1 = d1 < da;
    if (before0 != before1) return false;  // interleaved: they would have to cross
    // The neighbour of a's exit on b's side: the nearer of b's ends going forward when b lies
    // between a's exit and a's entry, else the farther one (reached going backward).
    return before0 ? d0 < d1 : d0 > d1;
}

// Grows a buffer that is all zero between shapes to at least n zeros. A reallocation copies
// nothing (the old contents are zeros), and only the new tail is written (a large map grows these
// buffers feature after feature, band after band).
template <class V>
void grow_zeroed(V& v, std::size_t n) {
    if (v.size() >= n) return;
    if (v.capacity() < n) {
        const std::size_t cap = std::max(n, 2 * v.capacity());
        v.clear();
        v.reserve(cap);
    }
    v.resize(n);
}

}  // namespace

DirectRows direct_rows(const CoverageTarget& t, int ox, int oy, int w, int h) {
    const IRect& b = t.bounds;
    if (!t.data || ox < b.x0 || ox + w > b.x1) return {};
    const int r0 = std::clamp(b.y0 - oy, 0, h), r1 = std::clamp(b.y1 - oy, r0, h);
    if (r1 == r0) return {};
    return {t.data + static_cast<std::ptrdiff_t>(oy + r0 - b.y0) * t.stride + (ox - b.x0), t.stride, r0, r1};
}

void Engine::trim(std::size_t records) {
    segs_.release_above(records);
    visits_.release_above(records);
    auto release = [records](auto& v) {
        if (v.capacity() > records) std::remove_reference_t<decltype(v)>().swap(v);
    };
    pieces_.release_above(records);
    release(cands_);
    release(exact_ids_);
}

// The most rows of room push_polyline() reserves from the box's height alone (128 KiB of pieces).
constexpr double kRoomByHeight = 8192;

// Polylines of more points than this are listed a SIMD vector of edges at a time (list_row_pieces);
// shorter ones one edge at a time, here: through the dispatched call, a 12 px DejaVu glyph (whose
// contours are short) measured a few per cent slower.
constexpr std::size_t kListVectorMin = 16;

// push()'s steps for the row vectors (most glyphs), with its choice of walk made once: each point
// held at the box's bottom once, the pieces of all the edges written through a local pointer into
// room reserved for them (an edge over |dy| rows makes at most |dy| + 2 pieces), and the edge count
// added and checked once, after the last edge (which lets at most these edges past the limit), so
// that nothing goes back to memory per edge.
template <bool kReverse>
void Engine::push_rows(const double* xy, std::size_t n, double rows) {
    const std::size_t room = static_cast<std::size_t>(rows) + 2 * n;
    RowPiece* out = pieces_.room(room);
    [[maybe_unused]] const RowPiece* const room_end = out + room;
    std::size_t edges = 0;
    out = n > kListVectorMin ? list_row_pieces(xy, n, kReverse, fh_, out, edges)
                             : list_polyline_pieces<kReverse>(xy, n, fh_, out, edges);
    assert(out <= room_end);
    pieces_.commit(out);
    count_ += edges;
    if (count_ > max_edges_)
        throw Error(ErrorKind::Limit, "path too complex: more than " + std::to_string(max_edges_) + " edges");
}

void Engine::push_polyline(const double* xy, std::size_t n) {
    if (vec_) {
        // Room for the pieces: each edge spans at most the box's height. Bounding by that spares
        // a pass over the points, whose sum of heights is one floating-point addition waiting for
        // the one before (about a tenth of a 24 px CFF glyph); a tall box sums the heights, so as
        // not to reserve far more room than its edges need.
        const double by_height = static_cast<double>(n) * fh_;
        if (by_height <= kRoomByHeight) return push_rows<false>(xy, n, by_height);
        double rows = 0;
        for (std::size_t i = 1; i < n; ++i) rows += std::abs(xy[2 * i + 1] - xy[2 * i - 1]);
        return push_rows<false>(xy, n, rows);
    }
    for (std::size_t i = 1; i < n; ++i) push(xy[2 * i - 2], xy[2 * i - 1], xy[2 * i], xy[2 * i + 1]);
}

void Engine::push_chain(const double* xy, std::size_t n, bool reverse) {
    if (vec_) {
        chains_ = true;
        // The points are monotone in y, so the edges' heights add up to the chain's.
        const double rows = std::abs(xy[2 * n - 1] - xy[1]);
#ifndef NDEBUG
        for (std::size_t i = 1; i < n; ++i) assert((xy[2 * i + 1] - xy[2 * i - 1]) * (xy[2 * n - 1] - xy[1]) >= 0);
#endif
        return reverse ? push_rows<true>(xy, n, rows) : push_rows<false>(xy, n, rows);
    }
    if (!reverse) return push_polyline(xy, n);
    for (std::size_t i = n - 1; i > 0; --i) push(xy[2 * i], xy[2 * i + 1], xy[2 * i - 2], xy[2 * i - 1]);
}

void Engine::begin(int w, int h, bool track) {
    w_ = w;
    h_ = h;
    fh_ = h;
    stride_ = static_cast<std::size_t>(w) + 2;
    track_ = track;
    const std::size_t cells = stride_ * static_cast<std::size_t>(h);
    if (dirty_) {
        std::fill(acc_.begin(), acc_.end(), 0.0);
        std::fill(facc_.begin(), facc_.end(), 0.0f);
        std::fill(head_.begin(), head_.end(), 0);
        std::fill(cand_.begin(), cand_.end(), std::uint8_t(0));
    }
    if (track) {
        grow_zeroed(head_, cells);
        grow_zeroed(cand_, cells);
    }
    clear_region();
    dirty_ = true;
    const int lanes = row_vector_lanes();
    vec_ = !track && w <= std::min(kRowVectorMax * lanes, kRowVectorMaxPixels);
    fcells_ = !track && !vec_ && w <= kFloatCellsMax;
    if (vec_) {
        const int granule = row_vector_granule();
        vstride_ = std::max(1, (w + granule - 1) / granule) * granule;
        const std::size_t n = static_cast<std::size_t>(vstride_) * static_cast<std::size_t>(h);
        grow_zeroed(facc_, n);
        restart();
    } else {
        if (fcells_) {
            stride_ = (stride_ + 7) & ~std::size_t(7);  // whole 8-cell blocks: the scan's vectors
            grow_zeroed(facc_, stride_ * static_cast<std::size_t>(h));
        } else {
            grow_zeroed(acc_, cells);
        }
        words_ = ((stride_ >> kBlockShift) + 64) / 64;
        blocks_.assign(words_ * static_cast<std::size_t>(h), 0);
    }
    segs_.clear();
    count_ = 0;
    const Limits limits = current_limits();
    max_edges_ = limits.flattened_segments;
    exact_base_ = static_cast<double>(limits.exact_work);
    visits_.clear();
    cands_.clear();
    cur_cell_ = kNoCell;
    cur_visit_ = -1;
    contour_visit_ = 0;
    contour_started_ = false;
    px_ = py_ = NAN;
}

void Engine::mark_region(std::uint8_t value) {
    for (const IRect& r : region_rects_)
        for (int y = r.y0; y < r.y1; ++y)
            std::fill_n(region_.data() + static_cast<std::size_t>(y) * region_stride_ + r.x0, r.x1 - r.x0, value);
}

void Engine::clear_region() {
    mark_region(0);
    region_rects_.clear();
    region_on_ = false;
}

void Engine::set_region(std::span<const Rect> boxes, double dx, double dy) {
    if (!track_) return;
    const double wmax = static_cast<double>(stride_), hmax = h_;
    // The cells of each box, and their total: boxes that would mark more cells than the shape has
    // (long segments crossing it many times) leave the check looking everywhere, so that marking
    // costs at most the shape's cells.
    std::size_t marked = 0;
    for (const Rect& b : boxes) {
        // Cells floor(x0) - 1 .. floor(x1) + 1: the closed box and a cell of slack each way.
        const double x0 = std::clamp(std::floor(b.x0 + dx) - 1, 0.0, wmax),
                     x1 = std::clamp(std::floor(b.x1 + dx) + 2, 0.0, wmax);
        const double y0 = std::clamp(std::floor(b.y0 + dy) - 1, 0.0, hmax),
                     y1 = std::clamp(std::floor(b.y1 + dy) + 2, 0.0, hmax);
        if (!(x1 > x0 && y1 > y0)) continue;
        const IRect r{static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1), static_cast<int>(y1)};
        marked += static_cast<std::size_t>(r.x1 - r.x0) * static_cast<std::size_t>(r.y1 - r.y0);
        if (marked > stride_ * static_cast<std::size_t>(h_)) {
            region_rects_.clear();
            return;
        }
        region_rects_.push_back(r);
    }
    grow_zeroed(region_, stride_ * static_cast<std::size_t>(h_));
    region_on_ = true;
    region_stride_ = stride_;
    mark_region(1);
}

void Engine::contour_end() {
    // The run through the contour's start vertex: its last part (now) continues into its first.
    if (track_ && cur_visit_ >= 0 && static_cast<std::size_t>(cur_visit_) > contour_visit_ &&
        contour_visit_ < visits_.size() && contour_started_ && px_ == sx_ && py_ == sy_) {
        Visit& last = visits_[static_cast<std::size_t>(cur_visit_)];
        Visit& first = visits_[contour_visit_];
        // Only a first visit that starts with the contour's first edge continues the last one: when
        // that edge lies on a cell side (no visit), the first visit starts further on, and joining
        // the two would hide the step between them from the run's directions.
        if (last.cell == first.cell && cur_cell_ == last.cell && first.pre < 0 && first.s0 == contour_seg_) {
            first.pre = cur_visit_;
            first.dirs |= last.dirs;
            last.merged_away = true;
            // Entering the cell again made it a candidate; when these two parts are its only
            // visits, it is a one-visit cell after all, unless the joined run is not monotone.
            if (!cands_.empty() && cands_.back() == last.cell &&
                last.next == static_cast<std::int32_t>(contour_visit_) && first.next < 0) {
                cand_[last.cell] = 0;
                cands_.pop_back();
            }
            if (!monotone(first.dirs)) add_cand(first.cell);
        }
    }
    contour_visit_ = visits_.size();
    contour_started_ = false;
    cur_cell_ = kNoCell;
    cur_visit_ = -1;
    px_ = py_ = NAN;
}

// The pieces of visit v (and of its merged first part) inside cell (col, row), in travel order.
void Engine::gather(const Visit& v, int col, int row, std::vector<ExactScratch::Piece>& out) const {
    out.clear();
    auto add = [&](const Visit& u) {
        for (std::uint32_t s = u.s0; s <= u.s1; ++s) {
            double ax, ay, bx, by;
            if (!cell_portion(segs_[s], col, row, ax, ay, bx, by)) continue;
            if (ax == bx && ay == by) continue;
            out.push_back({ax - col, ay - row, bx - col, by - row});
        }
    };
    if (v.pre >= 0) add(visits_[static_cast<std::size_t>(v.pre)]);
    add(v);
}

bool Engine::returns_harmlessly(std::int32_t before, std::uint32_t sid, std::uint32_t cell) const {
    const Visit& p = visits_[static_cast<std::size_t>(before)];
    if (p.next >= 0 || p.pre >= 0 || p.s0 != p.s1 || p.s1 + 1 != sid) return false;
    const Edge& a = segs_[p.s0];
    const Edge& b = segs_[sid];
    // A contour of these two edges alone: harmless_two may take its other vertex as V.
    if (!(a.x1 == b.x0 && a.y1 == b.y0) || (b.x1 == a.x0 && b.y1 == a.y0)) return false;
    const int row = static_cast<int>(cell / stride_), col = static_cast<int>(cell % stride_);
    return passes_through(a, col, row) && passes_through(b, col, row) && leaves_and_returns(a, b, col, row);
}

// Two monotone runs in one cell: harmless when they do not meet and the end of one is next to the
// start of the other around the cell's boundary (see the top of the file).
bool Engine::harmless_two(const Visit& a, const Visit& b, int col, int row) {
    // Closed forms for two single edges that pass through the cell (no end point inside the open
    // cell), so that each piece is its edge's whole line inside the cell and splits it in two.
    if (a.pre < 0 && b.pre < 0 && a.s0 == a.s1 && b.s0 == b.s1) {
        const Edge& A = segs_[a.s0];
        const Edge& B = segs_[b.s0];
        if (passes_through(A, col, row) && passes_through(B, col, row)) {
            // The two sides of a stem: when each edge lies strictly on one side of the other's
            // line they cannot meet, and the region between them is on the other edge's side of
            // each; the windings span one unit exactly when that side is the same one (left of
            // both or right of both).
            const double ax = A.x1 - A.x0, ay = A.y1 - A.y0, bx = B.x1 - B.x0, by = B.y1 - B.y0;
            const double b0 = ax * (B.y0 - A.y0) - ay * (B.x0 - A.x0), b1 = ax * (B.y1 - A.y0) - ay * (B.x1 - A.x0);
            const double a0 = bx * (A.y0 - B.y0) - by * (A.x0 - B.x0), a1 = bx * (A.y1 - B.y0) - by * (A.x1 - B.x0);
            if ((b0 > 0 && b1 > 0) || (b0 < 0 && b1 < 0))
                if ((a0 > 0 && a1 > 0) || (a0 < 0 && a1 < 0)) return (b0 > 0) == (a0 > 0);
            const Edge* first = &A;
            const Edge* second = &B;
            if (!(first->x1 == second->x0 && first->y1 == second->y0)) std::swap(first, second);
            if (first->x1 == second->x0 && first->y1 == second->y0 && leaves_and_returns(*first, *second, col, row))
                return true;
        }
    }
    // Multi-edge runs: when no edge of one meets an edge of the other anywhere, they cannot meet
    // in the cell, and only their entry and exit points matter (the first edge's and the last
    // edge's pieces, not every piece).
    if (a.pre < 0 && b.pre < 0) {
        bool meet = false;
        for (std::uint32_t i = a.s0; i <= a.s1 && !meet; ++i)
            for (std::uint32_t j = b.s0; j <= b.s1 && !meet; ++j) {
                const Edge& p = segs_[i];
                const Edge& q = segs_[j];
                meet = segments_meet(p.x0, p.y0, p.x1, p.y1, q.x0, q.y0, q.x1, q.y1);
            }
        double ta0, ta1, tb0, tb1;
        if (!meet && run_ends(a, col, row, ta0, ta1) && run_ends(b, col, row, tb0, tb1))
            return ends_alternate(ta0, ta1, tb0, tb1);
    }
    gather(a, col, row, pa_);
    gather(b, col, row, pb_);
    if (pa_.empty() || pb_.empty()) return false;
    for (const auto& p : pa_)
        for (const auto& q : pb_)
            if (segments_meet(p.ax, p.ay, p.bx, p.by, q.ax, q.ay, q.bx, q.by)) return false;
    return ends_alternate(boundary_param(pa_.front().ax, pa_.front().ay), boundary_param(pa_.back().bx, pa_.back().by),
                          boundary_param(pb_.front().ax, pb_.front().ay), boundary_param(pb_.back().bx, pb_.back().by));
}

// Where run v enters and leaves the cell, as boundary parameters; false when its first or last
// edge has no piece of positive length in the cell or an end of the run is inside the cell.
bool Engine::run_ends(const Visit& v, int col, int row, double& t0, double& t1) const {
    double ax, ay, bx, by;
    if (!cell_portion(segs_[v.s0], col, row, ax, ay, bx, by) || (ax == bx && ay == by)) return false;
    t0 = boundary_param(ax - col, ay - row);
    if (v.s1 != v.s0 && (!cell_portion(segs_[v.s1], col, row, ax, ay, bx, by) || (ax == bx && ay == by))) return false;
    t1 = boundary_param(bx - col, by - row);
    return t0 >= 0 && t1 >= 0;
}

// The edges of run v in travel order (its merged first part first) into out[0, kMaxRunEdges);
// returns how many, or -1 when there are more.
int Engine::run_edges(const Visit& v, std::uint32_t* out) const {
    int n = 0;
    auto add = [&](const Visit& u) {
        for (std::uint32_t s = u.s0; s <= u.s1; ++s) {
            if (n == kMaxRunEdges) return false;
            out[n++] = s;
        }
        return true;
    };
    if (v.pre >= 0 && !add(visits_[static_cast<std::size_t>(v.pre)])) return -1;
    return add(v) ? n : -1;
}

// Whether run v ends where it starts (a loop, when every vertex is inside the cell).
bool Engine::closed_run(const Visit& v) const {
    const Edge& first = segs_[v.pre >= 0 ? visits_[static_cast<std::size_t>(v.pre)].s0 : v.s0];
    const Edge& last = segs_[v.s1];
    return last.x1 == first.x0 && last.y1 == first.y0;
}

// A run that cannot cross itself: monotone in x or in y, at most two edges (one bend), or (up to
// kMaxRunEdges edges) no two of its edges meet except consecutive ones at their shared vertex,
// and no two consecutive ones fold back onto each other. A run whose last edge ends where its
// first starts (a whole small contour inside the cell, such as an island of a map) is a closed
// polygon: its last and first edges are consecutive there.
bool Engine::simple_run(const Visit& v) const {
    if (monotone(v.dirs)) return true;
    std::uint32_t ids[kMaxRunEdges];
    const int n = run_edges(v, ids);
    if (n < 0) return false;
    if (n <= 2) return true;
    const bool closed = closed_run(v);
    auto folds = [](const Edge& a, const Edge& b) {
        const double ax = a.x1 - a.x0, ay = a.y1 - a.y0, bx = b.x1 - b.x0, by = b.y1 - b.y0;
        return ax * by - ay * bx == 0 && ax * bx + ay * by < 0;
    };
    if (closed && folds(segs_[ids[n - 1]], segs_[ids[0]])) return false;
    for (int i = 0; i < n; ++i) {
        const Edge& a = segs_[ids[i]];
        if (i + 1 < n && folds(a, segs_[ids[i + 1]])) return false;
        for (int j = i + 2; j < n - (closed && i == 0 ? 1 : 0); ++j) {
            const Edge& b = segs_[ids[j]];
            if (segments_meet(a.x0, a.y0, a.x1, a.y1, b.x0, b.y0, b.x1, b.y1)) return false;
        }
    }
    return true;
}

// Two to six simple runs in one cell, of two kinds: open runs, which enter and leave through the
// cell's boundary, and loops, closed runs with every vertex inside the open cell (a small island
// or lake of a map). When no two runs meet inside the closed cell, each region between the open
// runs touches the boundary, where the windings change by -1 at every entry and +1 at every exit
// going around it. A loop adds its orientation (+1 or -1) to the winding of the region around it,
// which is read at the loop's first vertex P: the winding at the boundary point level with P on
// the cell's right side, less the steps of the other runs' pieces crossed on the way there
// (-1 for a piece going down, in y, +1 going up: the same rule as at the boundary). Accumulation
// is exact when all these windings take two values at most.
struct Engine::ManyRuns {
    // The arrays are filled as the steps go (not zeroed first: this runs for every crowded cell).
    ManyRuns(const Engine& engine, int runs, int c, int r) : e(engine), n(runs), col(c), row(r) {}

    const Engine& e;
    const int n, col, row;
    std::uint32_t ids[kMaxRuns][kMaxRunEdges];
    int counts[kMaxRuns];
    bool loop[kMaxRuns];
    struct End {
        double t;  // position along the cell's boundary (boundary_param)
        int step;  // -1 where a run enters, +1 where it leaves
    };
    End ends[2 * kMaxRuns];
    int nends = 0;
    ExactScratch::Piece pieces[kMaxRuns][kMaxRunEdges];  // each run's parts inside the closed cell
    int inside[kMaxRuns];
    int lo = 0, hi = 0;  // the windings seen so far span [lo, hi]

    // Each run's edges; loops apart; the open runs' ends on the boundary. False when a run is too
    // long or an end is not clearly on the boundary.
    bool gather(const Visit* const* runs) {
        auto inside_open = [&](double x, double y) { return x > col && x < col + 1 && y > row && y < row + 1; };
        for (int k = 0; k < n; ++k) {
            counts[k] = e.run_edges(*runs[k], ids[k]);
            if (counts[k] < 0) return false;
            loop[k] = e.closed_run(*runs[k]);
            for (int i = 0; i < counts[k] && loop[k]; ++i)
                loop[k] = inside_open(e.segs_[ids[k][i]].x0, e.segs_[ids[k][i]].y0);
            if (loop[k]) continue;
            const Edge& first = e.segs_[ids[k][0]];
            const Edge& last = e.segs_[ids[k][counts[k] - 1]];
            double ax, ay, bx, by;
            if (!cell_portion(first, col, row, ax, ay, bx, by) || (ax == bx && ay == by)) return false;
            ends[nends++] = {boundary_param(ax - col, ay - row), -1};
            if (!cell_portion(last, col, row, ax, ay, bx, by) || (ax == bx && ay == by)) return false;
            ends[nends++] = {boundary_param(bx - col, by - row), 1};
            if (ends[nends - 2].t < 0 || ends[nends - 1].t < 0) return false;
        }
        return true;
    }

    // The walk around the boundary: the windings of the regions that touch it. It is cheap, and
    // where many runs crowd a cell (the hub of a tight bend) it usually finds the windings spanning
    // more than one unit at once.
    bool boundary_windings() {
        for (int k = 1; k < nends; ++k)  // insertion sort (at most 2 * kMaxRuns ends)
            for (int j = k; j > 0 && ends[j].t < ends[j - 1].t; --j) std::swap(ends[j], ends[j - 1]);
        int w = 0;
        for (int k = 0; k < nends; ++k) {
            if (k > 0 && ends[k].t == ends[k - 1].t) return false;
            w += ends[k].step;
            lo = std::min(lo, w);
            hi = std::max(hi, w);
        }
        return hi - lo <= 1;
    }

    // Only the runs' parts inside the closed cell must not meet: consecutive runs of a contour that
    // leaves the cell and comes back one vertex later meet at that vertex, outside.
    bool apart() {
        for (int k = 0; k < n; ++k) {
            inside[k] = 0;
            for (int i = 0; i < counts[k]; ++i) {
                double ax, ay, bx, by;
                if (cell_portion(e.segs_[ids[k][i]], col, row, ax, ay, bx, by))
                    pieces[k][inside[k]++] = {ax, ay, bx, by};
            }
        }
        for (int a = 0; a < n; ++a)
            for (int b = a + 1; b < n; ++b)
                for (int i = 0; i < inside[a]; ++i)
                    for (int j = 0; j < inside[b]; ++j) {
                        const ExactScratch::Piece& p = pieces[a][i];
                        const ExactScratch::Piece& q = pieces[b][j];
                        if (segments_meet(p.ax, p.ay, p.bx, p.by, q.ax, q.ay, q.bx, q.by)) return false;
                    }
        return true;
    }

    // The winding around loop k, read at its first vertex P = (px, py): the winding just inside the right
    // side level with P, less the steps of the other runs' pieces crossed between P and there.
    // False when that reading is not clear-cut.
    bool winding_around(int k, double px, double py, int& around) const {
        const double ty = 1 + (py - row);
        around = 0;
        for (int i = 0; i < nends; ++i) {
            if (ends[i].t == ty) return false;
            if (ends[i].t < ty) around += ends[i].step;
        }
        // Half-open in y, so a vertex level with P counts once.
        for (int m = 0; m < n; ++m) {
            if (m == k) continue;
            for (int i = 0; i < inside[m]; ++i) {
                const ExactScratch::Piece& q = pieces[m][i];
                if (!((q.ay <= py && q.by > py) || (q.by <= py && q.ay > py))) continue;
                if (q.ax == col + 1 && q.bx == col + 1) return false;  // along the right side
                const double side = orient(q.ax, q.ay, q.bx, q.by, px, py);
                if (side == 0) return false;
                const bool down = q.by > q.ay;
                if ((side > 0) == down) around += down ? 1 : -1;  // the piece is right of P
            }
        }
        return true;
    }

    // Each loop adds its orientation (the sign of its area, shoelace about its first vertex; > 0
    // adds +1 by the boundary's rule) to the winding around it.
    bool loop_windings() {
        for (int k = 0; k < n; ++k) {
            if (!loop[k]) continue;
            const double px = e.segs_[ids[k][0]].x0, py = e.segs_[ids[k][0]].y0;
            int around;
            if (!winding_around(k, px, py, around)) return false;
            double area = 0;
            for (int i = 0; i < counts[k]; ++i) {
                const Edge& s = e.segs_[ids[k][i]];
                area += (s.x0 - px) * (s.y1 - py) - (s.x1 - px) * (s.y0 - py);
            }
            if (!(std::fabs(area) > 1e-12)) return false;
            const int inner = around + (area > 0 ? 1 : -1);
            lo = std::min({lo, around, inner});
            hi = std::max({hi, around, inner});
        }
        return hi - lo <= 1;
    }
};

bool Engine::harmless_many(const Visit* const* runs, int n, int col, int row) const {
    ManyRuns m(*this, n, col, row);
    return m.gather(runs) && m.boundary_windings() && m.apart() && m.loop_windings();
}

std::size_t Engine::classify(int ox, int oy, const PixelSet* hidden) {
    exact_.clear();
    exact_at_.clear();
    exact_ids_.clear();
    // A hidden cell is never exact, so neither its runs nor the cell itself need deciding.
    auto is_hidden = [&](std::uint32_t cell) {
        return hidden && hidden->contains(ox + static_cast<int>(cell % stride_), oy + static_cast<int>(cell / stride_));
    };
    std::size_t hidden_cells = 0;
    // Decide each candidate (cands_ holds each cell once, in no particular order: the cells with
    // two visits or more, and those with a run that is not monotone, made candidates by the walk) ...
    for (std::uint32_t cell : cands_) {
        if (is_hidden(cell)) {
            ++hidden_cells;
            continue;
        }
        const int row = static_cast<int>(cell / stride_), col = static_cast<int>(cell % stride_);
        int n = 0;
        const Visit* runs[kMaxRuns] = {};
        bool all_simple = true;
        for (std::int32_t i = head_[cell] - 1; i >= 0; i = visits_[static_cast<std::size_t>(i)].next) {
            const Visit& v = visits_[static_cast<std::size_t>(i)];
            if (v.merged_away) continue;
            if (++n > kMaxRuns) break;  // computed exactly whatever its runs are
            runs[n - 1] = &v;
            all_simple = all_simple && simple_run(v);
        }
        if (all_simple && n == 1) continue;
        if (all_simple && n == 2 && harmless_two(*runs[0], *runs[1], col, row)) continue;
        // Two open runs harmless_two turned down are not harmless; with a loop they may be.
        if (all_simple && n >= 2 && n <= kMaxRuns && (n > 2 || closed_run(*runs[0]) || closed_run(*runs[1])) &&
            harmless_many(runs, n, col, row))
            continue;
        exact_.push_back(cell);
    }
    // ... then list the exact ones in row order (finish() sums each row from its start) with their edges.
    std::sort(exact_.begin(), exact_.end());
    for (std::uint32_t cell : exact_) {
        exact_at_.push_back(static_cast<std::uint32_t>(exact_ids_.size()));
        for (std::int32_t i = head_[cell] - 1; i >= 0; i = visits_[static_cast<std::size_t>(i)].next) {
            const Visit& v = visits_[static_cast<std::size_t>(i)];
            for (std::uint32_t s = v.s0; s <= v.s1; ++s) exact_ids_.push_back(s);
        }
    }
    exact_at_.push_back(static_cast<std::uint32_t>(exact_ids_.size()));
    return hidden_cells;
}

void Engine::finish(FillRule rule, int ox, int oy, SpanSink& sink, RasterStats& stats,
                    std::span<const CutCapsule> inside, const PixelSet* hidden) {
    stats.segments = count_;
    stats.strips = 1;
    if (track_) {
        stats.hidden_cells = classify(ox, oy, hidden);
        for (const Visit& v : visits_) head_[v.cell] = 0;
        for (std::uint32_t cell : cands_) cand_[cell] = 0;
        cands_.clear();
        stats.exact_cells = exact_.size();
    } else {
        exact_.clear();
    }
    if (vec_) {  // no overlap check, so no exact cells
        row_vector_accumulate(pieces_.data(), pieces_.size(), !chains_, facc_.data(), vstride_);
        if (cov_.size() < static_cast<std::size_t>(vstride_)) cov_.resize(static_cast<std::size_t>(vstride_));
        const RowVectorRows rows{facc_.data(), vstride_, w_, h_, rule, cov_.data(), ox, oy};
        row_vector_emit(rows, sink);
        dirty_ = false;
        return;
    }
    if (cov_.size() < stride_) cov_.resize(stride_);
    patches_.clear();
    // Exact cells first (the scan clears acc). Untouched cells hold zero, so the integral up to a
    // cell is the plain sum from its row's start.
    std::size_t row_base = 0;
    double prefix = 0;
    int pos = 0;
    scratch_.budget = exact_base_ + kExactWorkPerSegment * static_cast<double>(count_);
    scratch_.work = 0;
    scratch_.dense_cells = 0;
    const bool hinted = rule == FillRule::NonZero && !inside.empty() && !exact_.empty();
    if (hinted) inside_.reset(inside, ox, oy, w_, h_, exact_.size());
    for (std::size_t ei = 0; ei < exact_.size(); ++ei) {
        const std::size_t cell = exact_[ei];
        const int r = static_cast<int>(cell / stride_);
        if (ei == 0 || static_cast<std::size_t>(r) * stride_ != row_base) {
            row_base = static_cast<std::size_t>(r) * stride_;
            prefix = 0;
            pos = 0;
        }
        const int col = static_cast<int>(cell - row_base);
        const double* acc_row = acc_.data() + row_base;
        for (; pos <= col; ++pos) prefix += acc_row[pos];
        if (col >= w_) continue;
        if (hinted && inside_.covers(col, r)) {
            patches_.push_back({exact_[ei], 255});
            ++stats.inside_cells;
            --stats.exact_cells;
            continue;
        }
        if (scratch_.work >= kExactWorkCeiling * scratch_.budget) {
            patches_.push_back({exact_[ei], coverage_u8(prefix, rule)});
            ++stats.accumulated_cells;
            continue;
        }
        auto& ids = scratch_.ids;  // exact_cell_coverage does not use scratch_.ids itself
        ids.assign(exact_ids_.begin() + exact_at_[ei], exact_ids_.begin() + exact_at_[ei + 1]);
        patches_.push_back({exact_[ei], exact_cell_u8(segs_.data(), ids, col, r, prefix, rule, scratch_)});
    }
    stats.exact_work += scratch_.work;
    stats.dense_cells += scratch_.dense_cells;
    // Then every row in one call (one dispatch per shape, not per row).
    const ScanRows rows{fcells_ ? nullptr : acc_.data(),
                        fcells_ ? facc_.data() : nullptr,
                        cov_.data(),
                        blocks_.data(),
                        static_cast<int>(words_),
                        w_,
                        h_,
                        static_cast<int>(stride_),
                        rule,
                        patches_.data(),
                        patches_.size(),
                        ox,
                        oy,
                        direct_rows(sink.target(), ox, oy, w_, h_)};
    scan_rows(rows, sink);
    dirty_ = false;
}

}  // namespace casteljau::raster
