// Path stage, internal: the arc geometry of arc.cpp without exceptions, for the path-data parser
// (which reports failures with a column) and for tests.
#pragma once

#include <span>

#include "casteljau/arc.hpp"
#include "casteljau/limits.hpp"

namespace casteljau::detail {

enum class ArcKind {
    Nothing,     // end == start: the arc is omitted
    Line,        // rx == 0 or ry == 0: a straight line to the end
    Cubics,      // `count` cubics, 3 points each (control 1, control 2, end), written to `out`
    OutOfRange,  // the geometry overflowed double range; nothing was written that should be used
};

struct ArcCubics {
    ArcKind kind = ArcKind::Nothing;
    int count = 0;
};

// Center parameterization of an SVG arc (SVG 2 F.6.5), after radius correction (F.6.6).
struct ArcCenter {
    Point center;
    double rx = 0, ry = 0;
    double cos_phi = 1, sin_phi = 0;
    double theta1 = 0;  // start angle, radians
    double dtheta = 0;  // signed sweep, radians, |dtheta| <= 2 pi
};

// Converts endpoint to center parameterization. Returns false when the arc degenerates (end == start,
// a zero radius) or the computation overflows; `kind` says which.
bool arc_center(Point start, double rx, double ry, double x_axis_rotation_degrees, bool large_arc, bool sweep,
                Point end, ArcCenter& c, ArcKind& kind);

// Computes the cubics of an arc (inputs must be finite, tolerance > 0). `out` must hold
// 3 * limits::kMaxArcPieces points.
ArcCubics arc_cubics(Point start, double rx, double ry, double x_axis_rotation_degrees, bool large_arc, bool sweep,
                     Point end, double tolerance, std::span<Point> out);

}  // namespace casteljau::detail
