// Internal: where a capsule (a segment swept by a disc) crosses horizontal sample lines, for
// round_stroke.cpp. The sections of one capsule on a run of lines are computed together, with
// Highway's runtime dispatch (core/simd_dispatch.hpp), one line per lane, and a row's capsules
// one after another in one call while they leave nothing for the caller.
//
// Conventions: pixel space, y down. Line s of a row j of `lines` lines is y = j + (s + 0.5) / lines.
// Thread-safety: pure functions.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace casteljau::raster {

// A segment and its disc radius, in the form the sections are computed from.
struct SweptCapsule {
    double ax, ay, bx, by;  // the segment's ends
    double y0, y1;          // vertical extent, the radius included
    // The band swept by the segment, on the line y = ay + dy, as x ranges:
    //   between its sides:  ax + side_slope dy -/+ side_half  (side_half infinite: horizontal segment)
    //   between its ends:   ax - end_slope dy + [end_lo, end_hi]
    // and for a vertical segment x in ax -/+ r while dy lies in [end_lo, end_hi].
    double side_slope = 0, side_half = INFINITY, end_slope = 0, end_lo = 0, end_hi = 0;
    bool band = false, vertical = false;
    // False when another capsule of the same sweep holds the disc at (ax, ay) (the previous segment
    // of a polyline ends there): the section is then that of the band and the disc at (bx, by),
    // still convex (the capsule cut by the perpendicular at a), and the union is the same.
    bool start_disc = true;
};

// Lines per call at most, and the room lo and hi need beyond the lines asked for (whole vectors
// are stored).
inline constexpr int kMaxSectionLines = 256;
inline constexpr int kSectionPadding = 64;

// Closed intervals of one capsule and one SIMD vector of lines, settled together: their summed
// lengths in pixels x .. x + count - 1 (count <= kSettledPixels), in units of kSettledUnit px.
inline constexpr int kSettledPixels = 4;
inline constexpr double kSettledUnit = 0x1p-20;
struct SettledRun {
    int x, count;
    std::int32_t units[kSettledPixels];
};

// Where intervals settle for a capsule with left end x0, when capsules come in order of their left
// ends: none still to come reaches left of x0, less `margin` (relative) for the rounding of the
// sections.
inline double settle_bound(double x0, double margin) { return x0 - margin * std::max(1.0, std::fabs(x0)); }

// One pixel row's sample lines, as capsule_sections folds capsules into them; T is double or
// float. Line s of the row's `lines` is y = row + (s + 0.5) / lines.
template <class T>
struct SectionRow {
    int row = 0, lines = 0;
    double r = 0;  // the capsules' radius
    // Per line from the row's line 0 (lines + kSectionPadding values): the open interval and the
    // end of the closed ones (see capsule_sections), and settle_limit: +infinity while the line's
    // closed intervals are in order (one may settle), -infinity once not (the caller keeps all).
    T *open_lo = nullptr, *open_hi = nullptr, *closed_hi = nullptr, *settle_limit = nullptr;
    // One capsule's sections or closed intervals left for the caller, from its first line (n +
    // kSectionPadding values), and which lines hold which (n / 64 words, rounded up).
    T *lo = nullptr, *hi = nullptr;
    std::uint64_t *left_bits = nullptr, *closed_bits = nullptr;
    // Settling: the row's pixels span x in [clip_lo, clip_hi]; `margin` is the relative rounding
    // allowed for a section's left end; runs[0 .. n_runs) receive what settled (max_runs at most).
    double clip_lo = 0, clip_hi = 0, margin = 0;
    SettledRun* runs = nullptr;
    int n_runs = 0, max_runs = 0;
};

// The capsules caps[0], caps[1], ... (their left ends in x0, in increasing order) in order, each
// on its lines s0 .. s0 + n - 1 of the row (those whose centres may lie inside its vertical extent
// (y0, y1), with a line to spare on each side; n <= kMaxSectionLines), until one leaves lines for
// the caller.
//
// For each capsule, the interval of x where each of its lines lies within r of it is folded into
// the line's union where that is simple. A line's union is kept as its open interval
// open_lo[i] <= open_hi[i] (the rightmost; open_lo = +infinity and open_hi = -infinity: none yet)
// and, left of it, closed intervals ending at most at closed_hi[i] (-infinity: none). A line with
// no open interval takes the section as its open one; a section meeting the open interval and
// starting right of closed_hi merges with it; a section right of the open interval closes it
// (closed_hi becomes its end) and becomes the open one. Any other section is left for the caller.
// A closed interval is settled when no capsule still to come can reach it (it ends left of this
// capsule's left end, less the margin) and its line is in order: the closed intervals of one
// SIMD vector of lines ending within kSettledPixels pixels go, cut to [clip_lo, clip_hi], to one
// SettledRun; any other closed interval is left for the caller. Lines the capsule misses (or does
// not cross strictly inside (y0, y1)) change nothing.
//
// Returns the index of the first capsule that left something, with its s0 and n in *s0 and *n:
// for its line s0 + i, bit i of left_bits is set when lo[i], hi[i] hold a section left for the
// caller, bit i of closed_bits when they hold the interval it closed (each line has one bit at
// most). Returns count when no capsule left anything. The values are those of the scalar formula
// (the same operations in the same order, no fused multiply-add), whatever the target; a run's
// lengths are rounded to whole units before they are summed, so its sums are too.
//
// In double, or in float (twice the lines per vector): the capsule's values are rounded to float
// first and every operation is done in float. Heights are taken from the row's top (a capsule's y
// minus `row`, in double, then rounded), so that they stay small wherever a line meets the capsule.
int capsule_sections(const SweptCapsule* const* caps, const double* x0, int count, SectionRow<double>& row, int* s0,
                     int* n);
int capsule_sections(const SweptCapsule* const* caps, const double* x0, int count, SectionRow<float>& row, int* s0,
                     int* n);

}  // namespace casteljau::raster
