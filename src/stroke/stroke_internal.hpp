// Stroke stage, internal interface shared by src/stroke/*.cpp (not installed).
//
// stroke() = validate -> flatten in user space (casteljau::flatten with the identity transform and
// the user-space tolerance) -> [dash the polylines] -> outline each polyline.
// Polylines use casteljau::Polyline (flatten.hpp); a contour of the dashed output may carry a
// direction hint, used for the caps of zero-length dashes.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "casteljau/flatten.hpp"
#include "casteljau/path.hpp"
#include "casteljau/stroke.hpp"

namespace casteljau::stroke_detail {

// |v|: the square root of the sum of squares where that is exact enough (no overflow or
// underflow), std::hypot's careful scaling otherwise. hypot is several times slower, and the
// stroker takes a length for every segment it meets.
inline double length_of(Vec v) {
    const double s = v.x * v.x + v.y * v.y;
    return s > 1e-280 && s < 1e280 ? std::sqrt(s) : std::hypot(v.x, v.y);
}

// A flattened path with what the stroker needs to know about the curve behind it.
//   smooth: per point, whether the path turns continuously there (a point inside a curve, or where
//           two segments meet with the same tangent): no join belongs there, the stroke is the sweep
//           of the pen's normal around the point (see stroke.cpp);
//   head, tail: per contour, the path's own unit direction at its first and last point, or (0, 0)
//           where the first or last chord's direction is the path's (lines, dash ends).
struct FlatContours {
    Polyline poly;
    std::vector<std::uint8_t> smooth;
    std::vector<Vec> head, tail;

    void clear() {
        poly.clear();
        smooth.clear();
        head.clear();
        tail.clear();
    }
};

// Flattens `path` (user space) at user tolerance `tol` into `out` (cleared first). A curve's
// control points nearer than `near` to its ends do not set its directions there.
void flatten_for_stroke(const Path& path, double tol, double near, FlatContours& out);

// `near` for a pen of width `width` at user tolerance `tol`: the larger of the tolerance and 1/40
// of the width.
double tangent_resolution(double width, double tol);

// The user-space tolerance for `tolerance` pixels under `m` (validates both).
double user_tolerance(const Affine& m, double tolerance);

// Throws Error(InvalidData) when the path has a non-finite point or weight.
void check_finite(const Path& path);

// The effective dash pattern: `dashes` doubled when its count is odd; empty when there is no dashing
// (empty, a negative value, or all zero). Throws Error(InvalidData) for a non-finite value.
std::vector<double> effective_pattern(std::span<const double> dashes);

// Dashes every contour of `in` with a non-empty effective `pattern` starting `offset` into it.
// `dirs` receives one direction per output contour: the unit direction of the path where a
// zero-length dash lies, or (0, 0) when not needed.
// Points keep their smoothness; a dash keeps the contour's head or tail where it starts at the
// contour's start or ends at its end.
void dash_polyline(const FlatContours& in, std::span<const double> pattern, double offset, FlatContours& out,
                   std::vector<Point>& dirs);

// Appends the stroke outline of every contour of `poly` to `out`. `dirs` (may be empty) gives
// per-contour directions for zero-length contours. `tol` is the user-space tolerance for arcs.
void stroke_polyline(const FlatContours& flat, std::span<const Point> dirs, const StrokeStyle& style, double tol,
                     Path& out);

// Appends to `out` the pixel-space capsules (under `m`) that lie wholly inside the outline
// stroke_polyline(flat, ..., style, tol) draws: see stroke_outline() in casteljau/stroke.hpp.
void interior_capsules(const FlatContours& flat, const StrokeStyle& style, double tol, const Affine& m,
                       std::vector<CutCapsule>& out);

}  // namespace casteljau::stroke_detail
