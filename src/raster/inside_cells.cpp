// Raster stage: cells wholly inside known-inside capsules (see inside_cells.hpp).
#include "raster/inside_cells.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace casteljau::raster {

namespace {

// Widens [lo, hi] to take x.
inline void take(double x, double& lo, double& hi) {
    lo = std::min(lo, x);
    hi = std::max(hi, x);
}

// The x interval where the horizontal line at y meets the cut capsule (lo > hi: nowhere). The
// capsule is the union of its end discs and its segment's rectangle, and convex, so its chord is
// the hull of theirs; each cut then bounds the chord from one side.
void chord(const CutCapsule& cc, double y, double& lo, double& hi) {
    const Capsule& c = cc.capsule;
    const double r = c.radius;
    lo = std::numeric_limits<double>::infinity();
    hi = -lo;
    for (const Point& p : {c.a, c.b}) {
        const double dy = y - p.y, s2 = r * r - dy * dy;
        if (s2 < 0) continue;
        const double s = std::sqrt(s2);
        take(p.x - s, lo, hi);
        take(p.x + s, lo, hi);
    }
    const Vec d = c.b - c.a;
    const double len = std::sqrt(d.dot(d));
    if (len > 0) {
        const Vec n{-d.y * r / len, d.x * r / len};
        const Point q[4] = {c.a + n, c.b + n, c.b - n, c.a - n};
        for (int k = 0; k < 4; ++k) {
            const Point p0 = q[k], p1 = q[(k + 1) % 4];
            if ((p0.y > y && p1.y > y) || (p0.y < y && p1.y < y)) continue;
            if (p0.y == p1.y) {
                take(p0.x, lo, hi);
                take(p1.x, lo, hi);
            } else {
                take(p0.x + (y - p0.y) * (p1.x - p0.x) / (p1.y - p0.y), lo, hi);
            }
        }
    }
    for (int k = 0; k < cc.cut_count; ++k) {
        // (x - at.x) out.x + (y - at.y) out.y <= 0
        const HalfPlane& hp = cc.cuts[k];
        const double bound = hp.at.x * hp.out.x - (y - hp.at.y) * hp.out.y;
        if (hp.out.x > 0)
            hi = std::min(hi, bound / hp.out.x);
        else if (hp.out.x < 0)
            lo = std::max(lo, bound / hp.out.x);
        else if ((y - hp.at.y) * hp.out.y > 0)
            hi = -std::numeric_limits<double>::infinity();
    }
}

bool holds_cell(const CutCapsule& c, int col, int row) {
    const double x0 = col, y0 = row, x1 = col + 1.0, y1 = row + 1.0;
    return c.contains({x0, y0}) && c.contains({x1, y0}) && c.contains({x0, y1}) && c.contains({x1, y1});
}

}  // namespace

void InsideCells::reset(std::span<const CutCapsule> capsules, int ox, int oy, int w, int h, std::size_t queries) {
    items_.clear();
    order_.clear();
    active_.clear();
    runs_.clear();
    next_row_ = 0;
    row_ = -1;
    w_ = w;
    h_ = h;
    constexpr double kHalfDiagonal = 0.70710678118654757;  // a disc must be this wide to hold a cell
    const Point origin(ox, oy);
    for (const CutCapsule& cc : capsules) {
        const Capsule& c = cc.capsule;
        if (!(c.radius >= kHalfDiagonal) || !std::isfinite(c.radius) || !c.a.is_finite() || !c.b.is_finite()) continue;
        if (cc.cut_count < 0 || cc.cut_count > 2) continue;
        Item it{cc, 0, 0, 0, 0};
        it.cap.capsule.a = c.a - origin;
        it.cap.capsule.b = c.b - origin;
        for (int k = 0; k < cc.cut_count; ++k) it.cap.cuts[k].at = cc.cuts[k].at - origin;
        const Capsule& t = it.cap.capsule;
        it.top = std::min(t.a.y, t.b.y) - c.radius;
        it.bottom = std::max(t.a.y, t.b.y) + c.radius;
        it.left = std::min(t.a.x, t.b.x) - c.radius;
        it.right = std::max(t.a.x, t.b.x) + c.radius;
        // The first row whose cells can lie inside: the box must reach from the row's top to its
        // bottom, within the engine's rows.
        const double first = std::max(0.0, std::ceil(it.top));
        if (first + 1 > it.bottom || first >= h || it.right - it.left < 1 || it.right <= 0 || it.left >= w) continue;
        it.top = first;
        items_.push_back(it);
    }
    // Bucketed by first row (a counting sort: the sweep meets them in that order).
    const std::size_t rows = static_cast<std::size_t>(h);
    row_start_.assign(rows + 1, 0);
    for (const Item& it : items_) ++row_start_[static_cast<std::size_t>(it.top) + 1];
    for (std::size_t r = 0; r < rows; ++r) row_start_[r + 1] += row_start_[r];
    order_.resize(items_.size());
    fill_.assign(row_start_.begin(), row_start_.end() - 1);
    for (std::size_t i = 0; i < items_.size(); ++i) order_[fill_[static_cast<std::size_t>(items_[i].top)]++] = i;
    budget_ = kWorkPerItem * (items_.size() + queries);
}

// The run of cells of `row` that `c` holds whole. The chords along the row's top and bottom give
// it up to rounding; its end cells are then checked corner by corner (stepping inwards once where
// rounding widened it), and convexity puts every cell between them inside too.
bool InsideCells::run_of(const CutCapsule& c, int row, Run& out) const {
    double lo0, hi0, lo1, hi1;
    chord(c, row, lo0, hi0);
    chord(c, row + 1.0, lo1, hi1);
    const double lo = std::max({lo0, lo1, 0.0}), hi = std::min({hi0, hi1, static_cast<double>(w_)});
    if (!(hi - lo >= 1)) return false;
    int first = static_cast<int>(std::ceil(lo)), last = static_cast<int>(std::floor(hi)) - 1;
    if (first <= last && !holds_cell(c, first, row)) ++first;
    if (first <= last && !holds_cell(c, last, row)) --last;
    if (first > last || !holds_cell(c, first, row) || !holds_cell(c, last, row)) return false;
    out = {first, last};
    return true;
}

void InsideCells::enter_row(int row) {
    // Keep the capsules whose box spans the whole row; add those whose first row has come.
    std::erase_if(active_, [&](std::size_t i) { return items_[i].bottom < row + 1; });
    const std::size_t last = std::min(static_cast<std::size_t>(row) + 1, row_start_.size() - 1);
    for (std::size_t k = row_start_[static_cast<std::size_t>(next_row_)]; k < row_start_[last]; ++k)
        if (items_[order_[k]].bottom >= row + 1) active_.push_back(order_[k]);
    next_row_ = row + 1;
    row_ = row;
    row_scans_ = 0;
    runs_ready_ = false;
}

bool InsideCells::scan(int col, int row) {
    const double x0 = col, x1 = col + 1.0;
    for (std::size_t i : active_) {
        // kScansPerCapsule visits cost the budget one unit, as one run does.
        if (++row_scans_ % kScansPerCapsule == 0) {
            if (budget_ == 0) return false;
            --budget_;
        }
        const Item& it = items_[i];
        if (it.left > x0 || it.right < x1) continue;
        if (holds_cell(it.cap, col, row)) return true;
    }
    return false;
}

void InsideCells::make_runs(int row) {
    runs_.clear();
    for (std::size_t i : active_) {
        if (budget_ == 0) break;
        --budget_;
        Run run{};
        if (run_of(items_[i].cap, row, run)) runs_.push_back(run);
    }
    std::sort(runs_.begin(), runs_.end(), [](const Run& a, const Run& b) { return a.first < b.first; });
    runs_ready_ = true;
    next_run_ = 0;
    reach_ = -1;
    last_col_ = -1;
}

bool InsideCells::from_runs(int col) {
    if (budget_ == 0) return false;
    --budget_;
    if (col < last_col_) {  // asked out of order: scan the runs again
        next_run_ = 0;
        reach_ = -1;
    }
    last_col_ = col;
    while (next_run_ < runs_.size() && runs_[next_run_].first <= col)
        reach_ = std::max(reach_, runs_[next_run_++].last);
    return col <= reach_;
}

bool InsideCells::covers(int col, int row) {
    if (items_.empty() || row < 0 || row >= h_ || budget_ == 0) return false;
    if (row != row_) {
        if (row < next_row_) return false;
        enter_row(row);
    }
    if (!runs_ready_) {
        if (row_scans_ < kScansPerCapsule * active_.size()) return scan(col, row);
        make_runs(row);
    }
    return from_runs(col);
}

}  // namespace casteljau::raster
