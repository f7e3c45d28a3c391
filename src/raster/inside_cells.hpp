// Raster stage, internal: which cells lie wholly inside capsules the caller knows are inside the
// shape (FillOptions::inside), asked cell after cell in increasing rows by Engine::finish.
//
// The capsules (possibly cut by lines) that can hold a unit square (radius at least sqrt(1/2)) and
// reach the engine's box are kept in cell coordinates, bucketed by the first row their boxes span
// whole. A sweep down the rows keeps the ones whose box spans the current row. A row's first
// questions are answered by scanning those capsules, box first, corners second, stopping at the
// first that holds the cell: a few questions in a row (the corners of a thin stroke) cost a few
// scans. Once the scans of a row have cost kScansPerCapsule visits per capsule spanning it (a
// wide stroke whose thousands of capsules span each row), the rest of the row is answered from
// runs: a cut capsule is convex, so the cells of one row it holds whole are a run of consecutive
// cells, each capsule gives its run (from its chords along the row's top and bottom, its two end
// cells checked corner by corner), and the runs, sorted by first cell, answer the row's remaining
// questions in one pass. Either way a cell is "yes" only when a capsule holds its four corners.
// Work: at most kScansPerCapsule visits and one run per capsule and row asked, within a budget of
// kWorkPerItem per capsule and per question; past it every cell gets "no", which only sends it to
// the exact computation.
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
    // Whether cell (col, row) lies wholly inside one of the capsules. Rows may not decrease between
    // calls; within a row, columns in increasing order are answered fastest.
    bool covers(int col, int row);

private:
    struct Item {
        CutCapsule cap;                   // cell coordinates
        double top, bottom, left, right;  // top: the first row whose cells may lie inside
    };
    struct Run {
        int first, last;  // cells first .. last of the row lie inside
    };
    void enter_row(int row);
    // Whether one of the active capsules holds the cell, capsule after capsule.
    bool scan(int col, int row);
    // The row's runs, sorted, for from_runs().
    void make_runs(int row);
    bool from_runs(int col);
    bool run_of(const CutCapsule& c, int row, Run& out) const;

    static constexpr std::size_t kWorkPerItem = 8;
    static constexpr std::size_t kScansPerCapsule = 16;
    int w_ = 0, h_ = 0;
    std::vector<Item> items_;
    std::vector<std::size_t> row_start_;  // per row: where its bucket starts in order_ (h + 1 entries)
    std::vector<std::size_t> fill_;
    std::vector<std::size_t> order_;  // items by first row
    std::vector<std::size_t> active_;
    int next_row_ = 0;           // rows before it have been swept
    int row_ = -1;               // the row asked last
    std::size_t row_scans_ = 0;  // capsules visited by scan() in row_
    bool runs_ready_ = false;    // runs_ holds row_'s runs
    std::vector<Run> runs_;      // row_'s, by first cell
    std::size_t next_run_ = 0;
    int reach_ = -1;     // the farthest last cell of runs_[0 .. next_run_)
    int last_col_ = -1;  // the column asked last in row_
    std::size_t budget_ = 0;
};

}  // namespace casteljau::raster
