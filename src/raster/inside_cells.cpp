// Raster stage: cells wholly inside known-inside capsules (see inside_cells.hpp).
#include "raster/inside_cells.hpp"

#include <algorithm>
#include <cmath>

namespace casteljau::raster {

void InsideCells::reset(std::span<const CutCapsule> capsules, int ox, int oy, int w, int h, std::size_t queries) {
    items_.clear();
    order_.clear();
    active_.clear();
    next_row_ = 0;
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
    budget_ = kTestsPerItem * (items_.size() + queries);
}

bool InsideCells::covers(int col, int row) {
    if (items_.empty() || budget_ == 0) return false;
    if (row >= next_row_) {
        // Keep the capsules whose box spans the whole row; add those whose first row has come.
        std::erase_if(active_, [&](std::size_t i) { return items_[i].bottom < row + 1; });
        const std::size_t last = std::min(static_cast<std::size_t>(row) + 1, row_start_.size() - 1);
        for (std::size_t k = row_start_[static_cast<std::size_t>(next_row_)]; k < row_start_[last]; ++k)
            if (items_[order_[k]].bottom >= row + 1) active_.push_back(order_[k]);
        next_row_ = row + 1;
    }
    const double x0 = col, y0 = row, x1 = col + 1.0, y1 = row + 1.0;
    for (std::size_t i : active_) {
        if (budget_ == 0) return false;
        --budget_;
        const Item& it = items_[i];
        if (it.left > x0 || it.right < x1) continue;
        const CutCapsule& c = it.cap;
        if (c.contains({x0, y0}) && c.contains({x1, y0}) && c.contains({x0, y1}) && c.contains({x1, y1})) return true;
    }
    return false;
}

}  // namespace casteljau::raster
