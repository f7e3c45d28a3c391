// Path stage: SVG elliptical arcs to cubic Beziers (include/casteljau/arc.hpp).
//
// Endpoint to center parameterization follows SVG 2 F.6.5, but computed in the "unit space" of the
// ellipse (rotated by -phi and scaled by 1/rx, 1/ry), where the ellipse is the unit circle and the
// endpoints are p and -p around the chord's midpoint. That avoids the products rx^2 ry^2 of the
// textbook formula, which overflow for radii above 1e77, and makes the radius correction (F.6.6)
// a single division: when |p| > 1 the radii grow by |p| and the center is the midpoint.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "casteljau/arc.hpp"
#include "casteljau/error.hpp"
#include "path/arc_detail.hpp"
#include "casteljau/limits.hpp"

namespace casteljau {

namespace {

// cos and sin of an angle in degrees, exact for multiples of 90 degrees (so that an axis-aligned
// ellipse stays exactly axis-aligned).
void sincos_degrees(double degrees, double& c, double& s) {
    double r = std::fmod(degrees, 360.0);
    if (r < 0) r += 360.0;
    if (r == 0) {
        c = 1;
        s = 0;
        return;
    }
    if (r == 90) {
        c = 0;
        s = 1;
        return;
    }
    if (r == 180) {
        c = -1;
        s = 0;
        return;
    }
    if (r == 270) {
        c = 0;
        s = -1;
        return;
    }
    const double rad = r * (kPi / 180.0);
    c = std::cos(rad);
    s = std::sin(rad);
}

}  // namespace

double arc_cubic_error(double angle) {
    // Goldapp (1991): the distance from the center of the cubic with handles k = 4/3 tan(theta/4)
    // is between 1 and 1 + 2 sin^6(theta/4) / (27 cos^2(theta/4)). Checked by sampling in
    // tests/path/test_arc.cpp.
    const double q = std::abs(angle) / 4;
    const double s = std::sin(q), c = std::cos(q);
    const double s2 = s * s;
    return 2 * s2 * s2 * s2 / (27 * c * c);
}

int arc_piece_count(double sweep_angle, double radius, double tolerance) {
    const double a = std::abs(sweep_angle);
    if (!(a > 0)) return 0;
    // At least one piece per 90 degrees; the factor forgives the rounding of a sweep of exactly
    // k * 90 degrees computed from atan2.
    int n = static_cast<int>(std::ceil(a / (kPi / 2) * (1 - 1e-12)));
    n = std::clamp(n, 1, limits::kMaxArcPieces);
    radius = std::abs(radius);
    if (!(tolerance < std::numeric_limits<double>::infinity()) || !(radius > 0)) return n;
    // e(theta) ~ theta^6 / 55296 from below (within 0.6% up to 90 degrees): start just under the
    // answer and step up.
    const double rel = tolerance / radius;
    const double theta_est = std::pow(55296.0 * rel, 1.0 / 6.0);
    if (theta_est > 0 && a / theta_est < limits::kMaxArcPieces)
        n = std::max(n, static_cast<int>(a / theta_est));
    else if (!(theta_est > 0))
        n = limits::kMaxArcPieces;
    n = std::clamp(n, 1, limits::kMaxArcPieces);
    while (n < limits::kMaxArcPieces && radius * arc_cubic_error(a / n) > tolerance) ++n;
    return n;
}

namespace detail {

bool arc_center(Point start, double rx, double ry, double x_axis_rotation_degrees, bool large_arc, bool sweep,
                Point end, ArcCenter& c, ArcKind& kind) {
    if (start == end) {
        kind = ArcKind::Nothing;
        return false;
    }
    rx = std::abs(rx);
    ry = std::abs(ry);
    if (rx == 0 || ry == 0) {
        kind = ArcKind::Line;
        return false;
    }

    double cp, sp;
    sincos_degrees(x_axis_rotation_degrees, cp, sp);
    // Half the chord, rotated into the ellipse's axes (F.6.5.1). Halving first keeps it finite.
    const double hx = start.x * 0.5 - end.x * 0.5, hy = start.y * 0.5 - end.y * 0.5;
    const double x1p = cp * hx + sp * hy, y1p = -sp * hx + cp * hy;
    // The start point in unit space; the end point is -p.
    double px = x1p / rx, py = y1p / ry;
    if (!std::isfinite(px) || !std::isfinite(py)) {
        kind = ArcKind::OutOfRange;
        return false;
    }
    const double len = std::hypot(px, py);
    // len == 0 although start != end: the half chord underflowed, or the radii exceed the chord by
    // more than 1e308; either way the arc is indistinguishable from its chord.
    if (len == 0) {
        kind = ArcKind::Line;
        return false;
    }

    double cx = 0, cy = 0;  // center in unit space
    if (len >= 1) {
        // Radii too small (F.6.6.2): scale them up by len; the center is the chord's midpoint.
        rx *= len;
        ry *= len;
        px /= len;
        py /= len;
    } else {
        // F.6.5.2 in unit space: the center lies on the perpendicular bisector of the chord, at
        // distance sqrt(1 - len^2) / len times |p| from the midpoint, on the side chosen by the flags.
        double f = std::sqrt((1 - len) * (1 + len)) / len;
        if (large_arc == sweep) f = -f;
        cx = f * py;
        cy = -f * px;
    }
    const double ux = px - cx, uy = py - cy;    // start, relative to the center
    const double vx = -px - cx, vy = -py - cy;  // end, relative to the center
    c.theta1 = std::atan2(uy, ux);
    double dt = std::atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    if (!sweep && dt > 0)
        dt -= 2 * kPi;
    else if (sweep && dt < 0)
        dt += 2 * kPi;
    c.dtheta = dt;
    c.rx = rx;
    c.ry = ry;
    c.cos_phi = cp;
    c.sin_phi = sp;
    const double mx = start.x * 0.5 + end.x * 0.5, my = start.y * 0.5 + end.y * 0.5;
    const double ex = rx * cx, ey = ry * cy;
    c.center = {cp * ex - sp * ey + mx, sp * ex + cp * ey + my};
    if (!std::isfinite(rx) || !std::isfinite(ry) || !c.center.is_finite()) {
        kind = ArcKind::OutOfRange;
        return false;
    }
    kind = ArcKind::Cubics;
    return true;
}

ArcCubics arc_cubics(Point start, double rx, double ry, double x_axis_rotation_degrees, bool large_arc, bool sweep,
                     Point end, double tolerance, std::span<Point> out) {
    ArcCenter c;
    ArcCubics r;
    if (!arc_center(start, rx, ry, x_axis_rotation_degrees, large_arc, sweep, end, c, r.kind)) return r;

    const int n = std::max(1, arc_piece_count(c.dtheta, std::max(c.rx, c.ry), tolerance));
    const double step = c.dtheta / n;
    const double k = 4.0 / 3.0 * std::tan(step / 4);
    // Unit circle point (x, y) to the ellipse: scale by the radii, rotate by phi, move to the center.
    auto map = [&](double x, double y) {
        const double ex = c.rx * x, ey = c.ry * y;
        return Point{c.cos_phi * ex - c.sin_phi * ey + c.center.x, c.sin_phi * ex + c.cos_phi * ey + c.center.y};
    };
    double ca = std::cos(c.theta1), sa = std::sin(c.theta1);
    bool finite = true;
    for (int i = 0; i < n; ++i) {
        const double b = c.theta1 + step * (i + 1);
        const double cb = std::cos(b), sb = std::sin(b);
        Point* q = &out[static_cast<std::size_t>(3 * i)];
        q[0] = map(ca - k * sa, sa + k * ca);
        q[1] = map(cb + k * sb, sb - k * cb);
        q[2] = i + 1 == n ? end : map(cb, sb);
        finite = finite && q[0].is_finite() && q[1].is_finite() && q[2].is_finite();
        ca = cb;
        sa = sb;
    }
    if (!finite) {
        r.kind = ArcKind::OutOfRange;
        return r;
    }
    r.count = n;
    return r;
}

}  // namespace detail

void arc_to(Path& path, double rx, double ry, double x_axis_rotation_degrees, bool large_arc, bool sweep, Point end,
            double tolerance) {
    if (!std::isfinite(rx) || !std::isfinite(ry) || !std::isfinite(x_axis_rotation_degrees) || !end.is_finite())
        throw Error(ErrorKind::InvalidArgument, "arc_to: radii, rotation and end point must be finite");
    if (!(tolerance > 0)) throw Error(ErrorKind::InvalidArgument, "arc_to: the tolerance must be a positive number");
    const Point start = path.current_point();
    if (!start.is_finite()) throw Error(ErrorKind::InvalidArgument, "arc_to: the path's current point is not finite");
    std::array<Point, 3 * limits::kMaxArcPieces> buf;
    const detail::ArcCubics r =
        detail::arc_cubics(start, rx, ry, x_axis_rotation_degrees, large_arc, sweep, end, tolerance, buf);
    switch (r.kind) {
        case detail::ArcKind::Nothing: return;
        case detail::ArcKind::Line: path.line_to(end); return;
        case detail::ArcKind::OutOfRange:
            throw Error(ErrorKind::InvalidData, "arc_to: the arc's geometry exceeds the range of double");
        case detail::ArcKind::Cubics:
            for (int i = 0; i < r.count; ++i) {
                const Point* q = &buf[static_cast<std::size_t>(3 * i)];
                path.cubic_to(q[0], q[1], q[2]);
            }
            return;
    }
}

void arc_to(Path& path, double rx, double ry, double x_axis_rotation_degrees, bool large_arc, bool sweep, Point end) {
    arc_to(path, rx, ry, x_axis_rotation_degrees, large_arc, sweep, end, kDefaultArcTolerance);
}

}  // namespace casteljau
