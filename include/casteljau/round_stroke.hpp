// casteljau/round_stroke.hpp: coverage of round strokes, in time that grows with the pixels
// they cover.
//
// The stroke of a polyline with round joins and round caps is the set of points within half the
// width of the polyline: the union of one capsule (the segment swept by a disc) per segment. The
// union of the strokes of many polylines with the same width is the union of all their capsules,
// whatever their order, direction or repetition. round_stroke_mask() computes the coverage of that
// union directly, without building an outline: a polyline folding over itself inside one pixel
// (thousands of vertices per pixel on a small world map) costs its capsules, not the exact union of
// the folded outline's pieces.
//
// Method: every pixel row is sampled on `lines_per_pixel` horizontal lines at the centres of equal
// bands; on each line every capsule crossing it covers one interval, found in closed form (two
// circles and a band), the intervals are merged and their lengths in each pixel added exactly. The
// coverage of a pixel is exact in x and a midpoint rule in y. Its error is at most 1 / (2 lines)
// times the total variation of the covered length along the pixel's height, which is at most the
// horizontal extent of the union's boundary inside the pixel (see src/raster/round_stroke.cpp):
// zero where the boundary is straight and crosses the bands without ending in them, 1/64 (4/255)
// for one horizontal boundary across the pixel with the default 32 lines, 8/255 for both sides of
// a horizontal line. 32 lines: on the world maps of BENCHMARKS.md at 4096 and 256 px wide, a 0.8 px
// stroke is within 0.15/255 of the exact union on average and 8/255 in any pixel (10/255 on
// Natural Earth at 1024 px), at half the cost of 64 lines (16 lines reach 15/255). The map
// stage's measured error is in BENCHMARKS.md.
//
// Precision: a clip whose x range, widened by the radius and a pixel, lies within 8192 px of x = 0
// is swept in float (twice the lines per SIMD vector), its segments first cut to that strip of x
// and their y taken from each row's top; any other clip in double. Float moves an interval's ends
// by a few 2^-10 px at most: the pixels stay within 1/255 of the double computation. The choice
// and the cut depend on the clip's x range only, so clips that differ in y (bands of one image)
// give the same pixels where they overlap.
//
// Conventions: pixel space, x right, y down, pixel (i, j) is the square [i, i+1) x [j, j+1).
// Coverage is rounded to 1/255 (half-way rounds up).
// Cost: each capsule costs the sample lines it spans (its height plus the width, times
// lines_per_pixel), computed several lines at a time with SIMD; each interval costs a comparison
// with the last one on its line (they arrive nearly in order; a line whose intervals do not is
// sorted once); each row costs the 16-pixel blocks its intervals reach. Memory: 32 bytes per
// segment reaching the clip and one row of accumulators, plus the mask for round_stroke_mask().
// Thread-safety: a pure function of its arguments; calls may run concurrently.
#pragma once

#include <cstdint>
#include <span>

#include "casteljau/geometry.hpp"
#include "casteljau/raster.hpp"

namespace casteljau {

// One straight piece of a polyline, in pixel space.
struct LineSegment {
    Point a, b;
};

inline constexpr int kRoundStrokeLines = 32;      // sample lines per pixel row by default
inline constexpr int kMaxRoundStrokeLines = 256;  // the most that may be asked for

// The coverage, inside `clip`, of the points within `radius` of any of `segments` (a zero-length
// segment is a disc). Throws Error(InvalidArgument) for a radius that is not finite and > 0, for
// non-finite segment coordinates and for lines_per_pixel outside [1, kMaxRoundStrokeLines], and
// Error(Limit) for a clip larger than limits::kMaxCanvasDimension on a side.
Mask round_stroke_mask(std::span<const LineSegment> segments, double radius, const IRect& clip,
                       int lines_per_pixel = kRoundStrokeLines);
// The same into `mask`, reusing its memory (a caller drawing band after band maps it once).
void round_stroke_mask(std::span<const LineSegment> segments, double radius, const IRect& clip, Mask& mask,
                       int lines_per_pixel = kRoundStrokeLines);
// The same coverage handed to `sink` row by row, top to bottom, in runs that hold every pixel the
// union reaches (pixels outside them are 0): no mask, so a caller compositing the rows directly
// (Canvas::fill_round_stroke) touches only the pixels near the strokes. Throws as above.
void round_stroke_spans(std::span<const LineSegment> segments, double radius, const IRect& clip, SpanSink& sink,
                        int lines_per_pixel = kRoundStrokeLines);

}  // namespace casteljau
