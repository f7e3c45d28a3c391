// Stroke stage, internal interface shared by src/stroke/*.cpp (not installed).
//
// stroke() = validate -> flatten in user space (casteljau::flatten with the identity transform and
// the user-space tolerance) -> [dash the polylines] -> outline each polyline.
// Polylines use casteljau::Polyline (flatten.hpp); a contour of the dashed output may carry a
// direction hint, used for the caps of zero-length dashes.
#pragma once

#include <span>
#include <vector>

#include "casteljau/flatten.hpp"
#include "casteljau/path.hpp"
#include "casteljau/stroke.hpp"

namespace casteljau::stroke_detail {

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
void dash_polyline(const Polyline& in, std::span<const double> pattern, double offset, Polyline& out,
                   std::vector<Point>& dirs);

// Appends the stroke outline of every contour of `poly` to `out`. `dirs` (may be empty) gives
// per-contour directions for zero-length contours. `tol` is the user-space tolerance for arcs.
void stroke_polyline(const Polyline& poly, std::span<const Point> dirs, const StrokeStyle& style, double tol,
                     Path& out);

}  // namespace casteljau::stroke_detail
