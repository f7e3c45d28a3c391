// Raster stage, internal: which cells lie wholly inside capsules the caller knows are inside the
// shape (FillOptions::inside), asked cell after cell in increasing rows by Engine::finish.
//
// The capsules (possibly cut by lines) that can hold a unit square (radius at least sqrt(1/2)) and
// reach the engine's box are kept in cell coordinates, bucketed by the first row their boxes span whole. A sweep down the
// rows keeps the ones whose box spans the current row; a cell is inside when one of them holds all four corners
// (a cut capsule is convex). Each query costs the active capsules it tests, and the tests of one fill
// stop at a budget of kTestsPerItem per capsule and per query: past it every cell gets "no",
// which only sends it to the exact computation.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "casteljau/geometry.hpp"

namespace casteljau::raster {

class InsideCells {
public:
    // Takes the capsules (pixel space) that can hold a cell of the box of w x h cells whose
    // top-left cell is pixel (ox, oy). `queries` bounds the number of covers() calls to come.
    void reset(std::span<const CutCapsule> capsules, int ox, int oy, int w, int h, std::size_t queries);
    // Whether cell (col, row) lies wholly inside one of the capsules; rows may not decrease
    // between calls.
    bool covers(int col, int row);

private:
    struct Item {
        CutCapsule cap;                   // cell coordinates
        double top, bottom, left, right;  // top: the first row whose cells may lie inside
    };
    static constexpr std::size_t kTestsPerItem = 8;
    std::vector<Item> items_;
    std::vector<std::size_t> row_start_;  // per row: where its bucket starts in order_ (h + 1 entries)
    std::vector<std::size_t> fill_;
    std::vector<std::size_t> order_;  // items by first row
    std::vector<std::size_t> active_;
    int next_row_ = 0;  // rows before it have been swept
    std::size_t budget_ = 0;
};

}  // namespace casteljau::raster
