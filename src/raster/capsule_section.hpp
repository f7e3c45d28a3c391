// Internal: where a capsule (a segment swept by a disc) crosses horizontal sample lines, for
// round_stroke.cpp. The sections of one capsule on a run of lines are computed together, with
// Highway's runtime dispatch (core/simd_dispatch.hpp), one line per lane, and a row's capsules
// one after another in one call while they leave nothing for the caller.
//
// Conventions: pixel space, y down. Line s of a row j of `lines` lines is y = j + (s + 0.5) / lines.
// Thread-safety: pure functions.
#pragma once

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

// The capsules caps[0], caps[1], ... in order, each on its lines s0 .. s0 + n - 1 of row `row`
// (those whose centres may lie inside its vertical extent (y0, y1), with a line to spare on each
// side; n <= kMaxSectionLines), until one leaves lines for the caller.
//
// For each capsule, the interval of x where each of its lines lies within r of it is folded into
// the line's union where that is simple. A line's union is kept as its open interval
// open_lo[i] <= open_hi[i] (the rightmost; open_lo = +infinity and open_hi = -infinity: none yet)
// and, left of it, closed intervals ending at most at closed_hi[i] (-infinity: none). A line with
// no open interval takes the section as its open one; a section meeting the open interval and
// starting right of closed_hi merges with it; a section right of the open interval closes it
// (closed_hi becomes its end) and becomes the open one. Any other section is left for the caller,
// and so is each closed interval. Lines the capsule misses (or does not cross strictly inside
// (y0, y1)) change nothing.
//
// Returns the index of the first capsule that left something, with its s0 and n in *s0 and *n:
// for its line s0 + i, bit i of left_bits is set when lo[i], hi[i] hold a section left for the
// caller, bit i of closed_bits when they hold the interval it closed (each line has one bit at
// most). Returns count when no capsule left anything. open_lo, open_hi and closed_hi hold the
// row's lines from its line 0, lines + kSectionPadding values; lo and hi n + kSectionPadding
// values; left_bits and closed_bits n / 64 words, rounded up. The values are those of the scalar
// formula (the same operations in the same order, no fused multiply-add), whatever the target.
//
// In double, or in float (twice the lines per vector): the capsule's values are rounded to float
// first and every operation is done in float. Heights are taken from the row's top (a capsule's y
// minus `row`, in double, then rounded), so that they stay small wherever a line meets the capsule.
int capsule_sections(const SweptCapsule* const* caps, int count, double r, int row, int lines, double* lo, double* hi,
                     double* open_lo, double* open_hi, double* closed_hi, std::uint64_t* left_bits,
                     std::uint64_t* closed_bits, int* s0, int* n);
int capsule_sections(const SweptCapsule* const* caps, int count, double r, int row, int lines, float* lo, float* hi,
                     float* open_lo, float* open_hi, float* closed_hi, std::uint64_t* left_bits,
                     std::uint64_t* closed_bits, int* s0, int* n);

}  // namespace casteljau::raster
