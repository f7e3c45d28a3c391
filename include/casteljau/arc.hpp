// casteljau/arc.hpp: SVG elliptical arcs (endpoint parameterization) appended to a Path as cubics.
//
// The arc follows SVG 2, implementation notes F.6.5 and F.6.6: it starts at the path's current point
// and ends at `end`; end == start appends nothing; rx == 0 or ry == 0 appends a straight line; negative
// radii are taken as their absolute values; radii too small to span the endpoints are scaled up
// uniformly until they just do (the arc is then half an ellipse). The rotation is in degrees, like in
// path data. Coordinates are the Path's own (user) units, no axis convention is assumed: `sweep` = 1
// means the arc runs in the direction of increasing angle, i.e. clockwise on a y-down screen.
//
// Accuracy. The arc is split into n pieces of equal angle theta <= 90 degrees; each piece of the
// unit circle becomes the standard cubic with handles k = 4/3 tan(theta/4) along the tangents, whose
// radial error is at most
//     e(theta) = 2 sin^6(theta/4) / (27 cos^2(theta/4))      (relative to the radius; outward only)
// (2.7e-4 for 90 degrees, 4.2e-6 for 45, 3.7e-7 for 30, 6.6e-8 for 22.5, ~theta^6/55296 for small
// theta). The ellipse is that circle under the linear map scale(rx, ry) then rotate, which stretches
// no vector by more than max(rx, ry), so every point of the cubics lies within
//     max(rx, ry) * e(theta)
// of the true ellipse (radii after the radius correction). Given a tolerance in path units, n is the
// smallest count with pieces of at most 90 degrees for which that bound is <= tolerance (at most
// limits::kMaxArcPieces pieces; they reach the limit of double precision long before). The start of the first
// cubic is the current point and the end of the last is `end`, exactly.
//
// kDefaultArcTolerance = 1e-3 path units: at any radius the error is at most 1e-3 units, so arcs up to
// radius 1000 (and beyond) stay well under 0.01 units. The largest piece angle this allows, by radius:
//     radius <= 3.6: 90 degrees (error <= 2.7e-4 x radius);  10: 76;  100: 52;  1000: 35;  10000: 24
// (a half circle of radius 1000 thus takes 6 cubics). The error is in path units: a path drawn scaled
// by s has up to s times that error in pixels; when drawing path data much larger than its units
// (s > 20 or so), pass a tolerance of about (flattening tolerance) / s.
//
// Thread-safety: free functions; they only modify the Path passed in.
#pragma once

#include "casteljau/geometry.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/path.hpp"

namespace casteljau {

inline constexpr double kDefaultArcTolerance = 1e-3;  // path units

// Upper bound of the radial error, relative to the radius, of the standard cubic for a circular arc
// of `angle` radians (|angle| <= pi): e(angle) above.
double arc_cubic_error(double angle);

// Number of cubics arc_to uses for an arc of `sweep_angle` radians on an ellipse whose larger radius
// is `radius`, for the given tolerance (in the radius's units): the smallest n with
// |sweep_angle| / n <= 90 degrees and radius * e(|sweep_angle| / n) <= tolerance, capped at
// limits::kMaxArcPieces; 0 for a zero sweep.
int arc_piece_count(double sweep_angle, double radius, double tolerance);

// Appends the SVG arc from path.current_point() to `end` to `path` as cubic Beziers whose distance to
// the true ellipse is at most `tolerance` path units (see above). Throws Error(InvalidArgument) for a
// non-finite argument or a tolerance that is not > 0 (an infinite tolerance means plain 90-degree
// pieces), and Error(InvalidData) when the arc's geometry overflows double range (path unchanged).
void arc_to(Path& path, double rx, double ry, double x_axis_rotation_degrees, bool large_arc, bool sweep, Point end,
            double tolerance);

// The same with tolerance kDefaultArcTolerance.
void arc_to(Path& path, double rx, double ry, double x_axis_rotation_degrees, bool large_arc, bool sweep, Point end);

}  // namespace casteljau
