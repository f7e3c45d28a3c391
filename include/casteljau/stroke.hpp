// casteljau/stroke.hpp: stroking and dashing, as Path -> Path steps.
//
// Pipeline position: Path --dash--> Path --stroke--> outline Path --(Affine)--> flatten --> fill
// (nonzero). The outline of a stroke is an ordinary closed Path that the rasterizer fills with the
// NONZERO rule. Its pieces may overlap (inner sides of sharp joins, self-crossing paths, dashes that
// touch); the rasterizer computes overlapping pixels exactly, so nothing here tries to union them.
// Every piece of the outline has the same orientation, so overlaps never cancel.
//
// Coordinates: everything is computed in USER space, the space of `path`, and the result is in user
// space too. `m` is the user-to-pixel transform that the result will be drawn with: it only chooses
// how finely curves and round joins/caps are flattened (`tolerance` / m.max_scale() in user units,
// so the error stays below `tolerance` pixels after `m`). Because the pen is a circle of diameter
// `width` in user space, a non-uniform `m` gives the elliptical pen SVG requires.
// The result contains line segments only (curves and arcs are already flattened).
//
// Semantics (SVG 2, as resvg / tiny-skia implement them):
// - Caps: Butt, Round (half disk), Square (half a square beyond the end). Joins: Miter, falling back
//   to Bevel when miter length / width = 1 / sin(alpha / 2) exceeds miter_limit (alpha: the angle
//   between the two segments; a right angle has ratio sqrt(2)); MiterClip (SVG 2 'miter-clip'): the
//   miter cut by a line perpendicular to the join's bisector at distance miter_limit * width / 2 from
//   the vertex; Round (circle arc); Bevel. miter_limit below 1 is treated as 1.
// - Curves are stroked as the sweep of their normal: no join inside a curve, nor where two segments
//   meet with the same tangent (the join style applies at corners only), and in a bend tighter than
//   the pen the normals sweep past the centre of curvature and cover the far side, as SVG 2
//   defines the stroke shape. Caps stand square to the curve's own direction at its end, taken
//   from its control points; a control point within max(user-space tolerance, width / 40) of its end
//   turns the curve over a length too short to show and is passed over (a straight line drawn
//   as a cubic with a control point on its end strokes as the line).
// - Closed contours (Path::close) join their end to their start and get no caps.
// - Zero-length segments are skipped when directions are taken. A contour of zero length (move +
//   close, or segments that all have length 0) draws a disk (Round cap) or a square oriented along
//   the user-space x axis (Square cap), and nothing with Butt caps. A lone move_to draws nothing.
// - width <= 0 gives an empty path.
// - Dashing: the pattern is repeated; an odd count of values is repeated once to make it even (SVG);
//   a pattern with a negative value, or whose values are all zero, means no dashing (SVG calls a
//   negative value an error; casteljau then renders the stroke solid, as browsers do). dash_offset
//   may be positive or negative. The pattern runs on across the segments of a contour and restarts
//   at every contour. On a closed contour the last and first dashes become one dash when the pattern
//   is "on" where the contour wraps around, and a contour that is "on" throughout stays closed.
//   Zero-length dashes are kept, so (0, d) with Round caps draws dots; Square caps of such dashes
//   follow the path direction. Dash lengths are measured along the curve: each chord of the
//   flattening counts as the arc it stands for, from the turns of the path at its ends, which on a
//   circle of radius r flattened with user tolerance t leaves a relative error of order (t / r)^2
//   (chords alone fall short by up to t / 3r). Points inside a chord lie on the chord.
// Errors: a non-finite point, transform or style value (width, miter_limit, dash values, offset)
// throws Error(InvalidData); a tolerance that is not a positive finite number throws
// Error(InvalidArgument); more than Limits::dashes dashes from one path or Limits::path_points
// output points (casteljau/limits.hpp) throws Error(Limit).
// Thread-safety: free functions without shared state.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/path.hpp"

namespace casteljau {

enum class LineCap { Butt, Round, Square };
enum class LineJoin { Miter, MiterClip, Round, Bevel };  // SVG 2 names

// The SVG names of caps (butt, round, square) and joins (miter, miter-clip, round, bevel); false
// when `name` is none of them (`out` is then unchanged).
bool parse_line_cap(std::string_view name, LineCap& out);
bool parse_line_join(std::string_view name, LineJoin& out);

struct StrokeStyle {
    double width = 1;
    LineCap cap = LineCap::Butt;
    LineJoin join = LineJoin::Miter;
    double miter_limit = 4;
    std::vector<double> dashes;  // empty: solid
    double dash_offset = 0;
};

// Outline of the stroke of `path` (user space) as closed contours to be filled with the nonzero rule.
// `m` is the user-to-pixel transform used to pick the flattening tolerance (see above).
Path stroke(const Path& path, const StrokeStyle& style, const Affine& m = {}, double tolerance = 0.05);
// The outline stroke() gives, with capsules in PIXEL space (under `m`) that lie wholly inside it,
// for the rasterizer's FillOptions::inside: pixels inside them are full, so the rasterizer skips
// their exact computation where the outline's pieces pile up (round joins, tight bends, the
// pivots of inner joins) and the stroke covers the pixel anyway.
// Which capsules: with round joins, one per segment of the flattened (and dashed) centre line,
// radius (width / 2 - 3 x user tolerance) x m.min_scale(), on contours at least `width` long.
// Near an open end (closer than 2 x width) a capsule that does not lie wholly behind the line
// through the end square to the path's direction there is cut by that line, or dropped where the
// path turns sharply within its first chord. The stroke holds every point within width / 2 of its
// centre line except beyond or near its open ends (caps, and the cuts of tight ends) and, with
// other joins, outside corners; the margin covers the flattening of round joins and the swept
// wedges left out when shallower than the tolerance. A contour with a corner joined otherwise
// gives only its segments' rectangles (the capsule cut square at both ends of its segment), none
// for the segments an open end would cut. Capsules that cannot hold a pixel (radius under
// sqrt(1/2) pixel) are left out.
struct StrokeOutline {
    Path outline;
    std::vector<CutCapsule> inside;
};
StrokeOutline stroke_outline(const Path& path, const StrokeStyle& style, const Affine& m = {}, double tolerance = 0.05);
// The same into `out`, whose lists keep their memory: for a caller that strokes many paths in turn
// (a canvas). On an exception `out` holds no outline.
void stroke_outline(const Path& path, const StrokeStyle& style, const Affine& m, double tolerance, StrokeOutline& out);
// The capsules stroke_outline() gives, without making the outline: for a caller that draws a
// stroke through other outlines whose union is the same (SharedBorders' chains, map.hpp).
std::vector<CutCapsule> stroke_interior(const Path& path, const StrokeStyle& style, const Affine& m = {},
                                        double tolerance = 0.05);

// The distance, in the path's units, under which stroke(path, style, m, tolerance) merges a
// point into the one before it (their direction would be noise): 1/1000 of the user-space
// tolerance. A contour whose points all lie within it of its first point has zero length (a disk or
// a square with Round or Square caps, nothing with Butt caps). Throws like stroke() for a bad
// transform or tolerance.
double stroke_merge_distance(const Affine& m = {}, double tolerance = 0.05);
// The stroker's test for keeping point b after the point a it kept last (or, closing a contour,
// its first): their squared distance exceeds merge_distance squared. A distance too small to square
// (below about 1e-154) counts as none. Code that must see a path's points as the stroker does
// (SharedBorders) uses the same test.
inline bool stroke_keeps_apart(Point a, Point b, double merge_distance) {
    return (a - b).dot(a - b) > merge_distance * merge_distance;
}

// The dashes of `path` as open contours (made of line segments, in user space); a contour that the
// pattern leaves "on" all around stays closed. Without an effective pattern (empty, all zero, a
// negative value) the result is the flattened path itself.
Path dash(const Path& path, std::span<const double> dashes, double offset, const Affine& m = {},
          double tolerance = 0.05);

}  // namespace casteljau
