// Flatten stage: curves to polylines by recursive de Casteljau subdivision (flatten.hpp).
//
// The flatness bound. For a Bezier curve B(t) of degree n with control points P_i, let L(t) be
// the chord traversed at the same parameter, L(t) = (1 - t) P_0 + t P_n. Writing B - L in the
// Bernstein basis of degree n and bounding its second derivative, which is
// n (n - 1) sum_i (P_i - 2 P_(i+1) + P_(i+2)) B_(i,n-2)(t), gives (one line):
//     |B(t) - L(t)| <= t (1 - t) / 2 * max_t |B''(t)| <= (1/8) n (n - 1) max_i |P_i - 2 P_(i+1) + P_(i+2)|
// because B - L vanishes at t = 0 and t = 1 (interpolation error of a linear fit, t(1 - t)/2 f'').
// So a quadratic stays within |P0 - 2 P1 + P2| / 4 of its chord and a cubic within
// 3/4 max(|P0 - 2 P1 + P2|, |P1 - 2 P2 + P3|). Every point of the curve is within that distance
// of a point of the chord segment, so emitting the chord keeps the polyline within the bound.
// Halving a curve at t = 1/2 divides these second differences by at least 4 (for the left half of
// a cubic they become D0 / 4 and (D0 + D1) / 8), so the bound shrinks 4x per level: depth
// ceil(log4(bound / tolerance)) suffices and the depth limit is only reached for absurd ratios.
//
// For a conic (rational quadratic, weights 1, w, 1) in standard form the point farthest from the
// chord line is at t = 1/2 (its tangent there is parallel to the chord), at distance
// w / (1 + w) * dist(P1, chord line), which we bound by w / (1 + w) * |P1 - (P0 + P2) / 2|.
// Halving a conic gives two conics of weight sqrt((1 + w) / 2).
#include "casteljau/flatten.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "path/flatten_internal.hpp"

namespace casteljau {

double flatness_bound_quad(Point p0, Point p1, Point p2) { return 0.25 * (p0 - p1 * 2 + p2).length(); }

double flatness_bound_cubic(Point p0, Point p1, Point p2, Point p3) {
    return 0.75 * std::max((p0 - p1 * 2 + p2).length(), (p1 - p2 * 2 + p3).length());
}

double flatness_bound_conic(Point p0, Point p1, Point p2, double w) {
    const Point m = p0 * 0.5 + p2 * 0.5;
    return w / (1 + w) * (p1 - m).length();
}

Rect check_flatten_input(const Path& path, const Affine& m, double tolerance) {
    if (!m.is_finite()) throw Error(ErrorKind::InvalidData, "transform has a non-finite entry");
    if (!(tolerance > 0) || !std::isfinite(tolerance))
        throw Error(ErrorKind::InvalidArgument, "flattening tolerance must be a positive number of pixels");
    if (path.empty()) return {INFINITY, INFINITY, -INFINITY, -INFINITY};
    if (m.b == 0 && m.c == 0 && path.is_finite()) {
        // Scale and translation (glyphs, most shapes): each coordinate maps monotonically (with
        // rounding too), so the path's cached control bounds give the exact result in O(1).
        const Rect r = path.control_bounds();
        const double xa = m.a * r.x0 + m.e, xb = m.a * r.x1 + m.e;
        const double ya = m.d * r.y0 + m.f, yb = m.d * r.y1 + m.f;
        if (std::isfinite(xa) && std::isfinite(xb) && std::isfinite(ya) && std::isfinite(yb))
            return {std::min(xa, xb), std::min(ya, yb), std::max(xa, xb), std::max(ya, yb)};
        // Overflow: the loop below reports it.
    }
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (Point p : path.points()) {
        const Point q = m.apply(p);
        if (!(std::isfinite(q.x) && std::isfinite(q.y))) {
            if (!p.is_finite())
                throw Error(ErrorKind::InvalidData, "path has a non-finite coordinate (NaN or infinity)");
            // 1e300 scaled by 1e10 overflows.
            throw Error(ErrorKind::InvalidData, "path coordinate overflows after the transform");
        }
        x0 = q.x < x0 ? q.x : x0;
        x1 = q.x > x1 ? q.x : x1;
        y0 = q.y < y0 ? q.y : y0;
        y1 = q.y > y1 ? q.y : y1;
    }
    for (double w : path.weights())
        if (!std::isfinite(w)) throw Error(ErrorKind::InvalidData, "path has a non-finite conic weight");
    return {x0, y0, x1, y1};
}

void flatten_culled(const Path& path, const Affine& m, double tolerance, const Rect* cull, Polyline& out,
                    FlattenMode mode) {
    out.clear();
    check_flatten_input(path, m, tolerance);
    out.points.reserve(path.points().size() * 2);
    flatten_detail::PolylineSink sink{out};
    flatten_into(path, m, tolerance, cull, sink, mode == FlattenMode::AreaBalanced);
}

void flatten(const Path& path, const Affine& m, double tolerance, Polyline& out, FlattenMode mode) {
    flatten_culled(path, m, tolerance, nullptr, out, mode);
}

}  // namespace casteljau
