// Tests for SVG arcs (include/casteljau/arc.hpp): the error bound of a cubic piece and the piece
// counts, the cubics against the ellipse of SVG 2's F.6.5 / F.6.6 worked out here (bound and its
// tightness), radius correction, degenerate arcs, rotation, and invalid arguments and overflow.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

#include "casteljau/arc.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/svg_path.hpp"
#include "svg_path_test_util.hpp"

using namespace casteljau;
using namespace svg_path_test;

namespace {

// Independent reference: SVG 2 F.6.5 / F.6.6 exactly as written in the specification.
struct RefArc {
    double cx, cy, rx, ry, cphi, sphi, theta1, dtheta;
    bool scaled;  // the radii were too small and were scaled up
};

RefArc reference_arc(Point p1, double rx, double ry, double deg, bool fa, bool fs, Point p2) {
    rx = std::abs(rx);
    ry = std::abs(ry);
    const double phi = deg * kPi / 180;
    const double c = std::cos(phi), s = std::sin(phi);
    const double dx = (p1.x - p2.x) / 2, dy = (p1.y - p2.y) / 2;
    const double x1 = c * dx + s * dy, y1 = -s * dx + c * dy;
    const double lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
    if (lambda > 1) {
        rx *= std::sqrt(lambda);
        ry *= std::sqrt(lambda);
    }
    const double num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    const double den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    // (When the radii were scaled num is 0 up to rounding, which the square root would amplify to
    // 1e-8 relative; the centre is then exactly the midpoint.)
    double coef = lambda > 1 ? 0.0 : std::sqrt(std::max(0.0, num / den));
    if (fa == fs) coef = -coef;
    const double cxp = coef * rx * y1 / ry, cyp = -coef * ry * x1 / rx;
    RefArc r;
    r.scaled = lambda > 1;
    r.cx = c * cxp - s * cyp + (p1.x + p2.x) / 2;
    r.cy = s * cxp + c * cyp + (p1.y + p2.y) / 2;
    r.rx = rx;
    r.ry = ry;
    r.cphi = c;
    r.sphi = s;
    auto angle = [](double ux, double uy, double vx, double vy) {
        const double d = (ux * vx + uy * vy) / (std::hypot(ux, uy) * std::hypot(vx, vy));
        const double a = std::acos(std::clamp(d, -1.0, 1.0));
        return (ux * vy - uy * vx) < 0 ? -a : a;
    };
    const double ux = (x1 - cxp) / rx, uy = (y1 - cyp) / ry, vx = (-x1 - cxp) / rx, vy = (-y1 - cyp) / ry;
    r.theta1 = angle(1, 0, ux, uy);
    double dt = std::fmod(angle(ux, uy, vx, vy), 2 * kPi);
    if (!fs && dt > 0) dt -= 2 * kPi;
    if (fs && dt < 0) dt += 2 * kPi;
    r.dtheta = dt;
    return r;
}

struct ArcCheck {
    double max_distance = 0;                    // upper bound of the distance of a sample to the ellipse
    double min_radius = 1e300, max_radius = 0;  // |q| in the unit space of the ellipse
    double travel = 0;                          // signed angle travelled along the samples
    int cubics = 0;
};

// Samples every cubic after the first `skip_verbs` verbs of `path` and measures them against the
// reference ellipse.
ArcCheck check_arc_samples(const Path& path, std::size_t skip_verbs, const RefArc& ref) {
    ArcCheck out;
    Point cur = path.points()[skip_verbs - 1];
    std::size_t pi = skip_verbs;
    double prev_angle = 0;
    bool first = true;
    for (std::size_t vi = skip_verbs; vi < path.verbs().size(); ++vi) {
        REQUIRE(path.verbs()[vi] == Verb::Cubic);
        const Point c1 = path.points()[pi], c2 = path.points()[pi + 1], p = path.points()[pi + 2];
        pi += 3;
        ++out.cubics;
        for (int j = 0; j <= 400; ++j) {
            const Point s = cubic_at(cur, c1, c2, p, j / 400.0);
            const double dx = s.x - ref.cx, dy = s.y - ref.cy;
            const double lx = ref.cphi * dx + ref.sphi * dy, ly = -ref.sphi * dx + ref.cphi * dy;
            const double qx = lx / ref.rx, qy = ly / ref.ry;
            const double r = std::hypot(qx, qy);
            out.min_radius = std::min(out.min_radius, r);
            out.max_radius = std::max(out.max_radius, r);
            // The radial projection onto the ellipse is a point of the ellipse, so this distance is
            // at least the distance to the ellipse.
            const double ex = ref.rx * qx / r, ey = ref.ry * qy / r;
            const Point on{ref.cphi * ex - ref.sphi * ey + ref.cx, ref.sphi * ex + ref.cphi * ey + ref.cy};
            out.max_distance = std::max(out.max_distance, distance(s, on));
            const double a = std::atan2(qy, qx);
            if (!first) {
                double d = a - prev_angle;
                if (d > kPi) d -= 2 * kPi;
                if (d < -kPi) d += 2 * kPi;
                out.travel += d;
            }
            first = false;
            prev_angle = a;
        }
        cur = p;
    }
    return out;
}

}  // namespace

TEST_CASE("svg arc: error bound formula and piece counts", "[svgpath]") {
    CHECK(arc_cubic_error(kPi / 2) == Approx(2.72567e-4).epsilon(1e-5));
    CHECK(arc_cubic_error(kPi / 4) == Approx(4.2455e-6).epsilon(1e-4));
    CHECK(arc_cubic_error(-kPi / 4) == arc_cubic_error(kPi / 4));
    CHECK(arc_cubic_error(0) == 0);
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(arc_piece_count(0, 1, 1) == 0);
    CHECK(arc_piece_count(kPi / 2, 1, inf) == 1);
    CHECK(arc_piece_count(kPi / 2 + 1e-15, 1, inf) == 1);  // rounding of an exact quarter
    CHECK(arc_piece_count(kPi / 2 + 1e-6, 1, inf) == 2);
    CHECK(arc_piece_count(-kPi, 1, inf) == 2);
    CHECK(arc_piece_count(2 * kPi, 1, inf) == 4);
    CHECK(arc_piece_count(kPi / 2, 3.6, kDefaultArcTolerance) == 1);
    CHECK(arc_piece_count(kPi / 2, 3.7, kDefaultArcTolerance) == 2);
    CHECK(arc_piece_count(kPi, 1000, kDefaultArcTolerance) == 6);
    CHECK(arc_piece_count(kPi / 2, 1000, kDefaultArcTolerance) == 3);
    CHECK(arc_piece_count(2 * kPi, 1, 1e-300) == limits::kMaxArcPieces);
    // The count is minimal: one piece fewer would break the tolerance (or the 90-degree rule).
    for (double r : {0.5, 7.0, 100.0, 1000.0, 12345.0}) {
        for (double a : {0.3, 1.0, kPi / 2, 2.0, kPi, 5.0, 2 * kPi}) {
            const int n = arc_piece_count(a, r, kDefaultArcTolerance);
            CHECK(r * arc_cubic_error(a / n) <= kDefaultArcTolerance);
            CHECK(a / n <= kPi / 2 + 1e-12);
            if (n > 1) CHECK((r * arc_cubic_error(a / (n - 1)) > kDefaultArcTolerance || a / (n - 1) > kPi / 2));
        }
    }
}

TEST_CASE("svg arc: the cubics stay within the documented bound of the true ellipse", "[svgpath]") {
    struct Case {
        Point start;
        double rx, ry, deg;
        bool large, sweep;
        Point end;
    };
    const Case cases[] = {
        {{0, 0}, 50, 50, 0, false, true, {100, 0}},    // half circle, radii exact
        {{0, 0}, 50, 50, 0, true, false, {50, 50}},    // three quarters, large arc
        {{10, 20}, 30, 10, 30, false, true, {40, 5}},  // rotated ellipse
        {{10, 20}, 30, 10, 30, true, true, {40, 5}},
        {{10, 20}, 30, 10, -150, true, false, {40, 5}},
        {{0, 0}, 1, 2, 0, false, false, {100, 100}},       // radii far too small: scaled
        {{-5, 3}, 400, 120, 75, true, true, {300, -200}},  // big
        {{0, 0}, 1000, 1000, 0, true, true, {0, 1}},       // nearly a full circle of radius 1000
        {{0, 0}, 0.01, 0.003, 10, true, false, {0.001, 0.002}},
    };
    const double inf = std::numeric_limits<double>::infinity();
    for (const Case& c : cases) {
        for (double tol : {inf, kDefaultArcTolerance, 1e-6}) {
            INFO("arc to (" << c.end.x << ", " << c.end.y << ") rx " << c.rx << " ry " << c.ry << " rot " << c.deg
                            << " flags " << c.large << c.sweep << " tolerance " << tol);
            Path p;
            p.move_to(c.start);
            arc_to(p, c.rx, c.ry, c.deg, c.large, c.sweep, c.end, tol);
            const RefArc ref = reference_arc(c.start, c.rx, c.ry, c.deg, c.large, c.sweep, c.end);
            const ArcCheck k = check_arc_samples(p, 1, ref);
            const double big = std::max(ref.rx, ref.ry);
            // (The reference's sweep of a scaled arc is pi only up to 1e-8: acos loses half the digits.)
            const int n = arc_piece_count(ref.dtheta * (1 - 1e-7), big, tol);
            CHECK(k.cubics == n);
            const double bound = big * arc_cubic_error(ref.dtheta / n);
            const double slack = 1e-12 * (big + std::abs(c.start.x) + std::abs(c.start.y));
            CHECK(k.max_distance <= bound + slack);
            CHECK(k.max_distance <= tol);
            CHECK(k.min_radius >= 1 - 1e-12);  // outward only
            CHECK(k.max_radius <= 1 + arc_cubic_error(ref.dtheta / n) + 1e-12);
            // The cubics cover exactly the arc the flags select, in the right direction.
            CHECK(k.travel == Approx(ref.dtheta).margin(1e-9));
            if (ref.scaled)
                CHECK(std::abs(ref.dtheta) == Approx(kPi));
            else
                CHECK((std::abs(ref.dtheta) > kPi) == c.large);
            CHECK((ref.dtheta > 0) == c.sweep);
            // Exact endpoint; the first cubic starts at the current point.
            CHECK(p.points().back() == c.end);
            CHECK(p.points()[0] == c.start);
        }
    }
}

TEST_CASE("svg arc: the bound is tight (the measured error of 90-degree pieces is 2.7e-4 x radius)", "[svgpath]") {
    Path p;
    p.move_to(100, 0);
    arc_to(p, 100, 100, 0, false, true, {-100, 0}, std::numeric_limits<double>::infinity());
    const ArcCheck k = check_arc_samples(p, 1, reference_arc({100, 0}, 100, 100, 0, false, true, {-100, 0}));
    CHECK(k.cubics == 2);
    CHECK(k.max_distance > 0.99 * 100 * arc_cubic_error(kPi / 2));
    CHECK(k.max_distance <= 100 * arc_cubic_error(kPi / 2));
    CHECK(k.max_distance == Approx(2.7253e-2).epsilon(1e-3));
    // With the default tolerance a circle of radius 1000 stays within 1e-3 units (< 0.01).
    Path big;
    big.move_to(1000, 0);
    arc_to(big, 1000, 1000, 0, true, true, {1000, -1e-9});
    const ArcCheck kb = check_arc_samples(big, 1, reference_arc({1000, 0}, 1000, 1000, 0, true, true, {1000, -1e-9}));
    CHECK(kb.max_distance <= kDefaultArcTolerance);
    CHECK(kb.max_distance > 0.1 * kDefaultArcTolerance);  // and is not wastefully fine
}

TEST_CASE("svg arc: radius correction gives a half ellipse centred on the chord", "[svgpath]") {
    // Radii 1 cannot span 10 units: scaled to 5, centre (5, 0). Sweep 1 runs through increasing
    // angles, from 180 degrees via 270 (y = -5) to 360.
    Path p = parse_svg_path("M0 0 A1 1 0 0 1 10 0");
    const RefArc ref = reference_arc({0, 0}, 1, 1, 0, false, true, {10, 0});
    CHECK(ref.rx == Approx(5));
    CHECK(ref.cx == Approx(5));
    CHECK(ref.cy == Approx(0).margin(1e-12));
    const ArcCheck k = check_arc_samples(p, 1, ref);
    CHECK(k.max_distance <= 5 * arc_cubic_error(kPi / 3));
    CHECK(k.travel == Approx(kPi));
    // Radius 5 with the default tolerance: three pieces of 60 degrees. The middle of the arc is the
    // middle of the second cubic.
    REQUIRE(p.verbs().size() == 4);
    const Point mid = cubic_at(p.points()[3], p.points()[4], p.points()[5], p.points()[6], 0.5);
    CHECK(mid.x == Approx(5));
    CHECK(mid.y == Approx(-5).epsilon(1e-4));
    // Both flags give the same half circle when the radii are too small (only the sweep matters).
    CHECK(parse_svg_path("M0 0 A1 1 0 1 1 10 0") == p);
    // An elliptic one keeps the ratio of the radii: 2:1 scaled so that the chord is the major axis.
    const RefArc e = reference_arc({0, 0}, 2, 1, 0, false, false, {10, 0});
    CHECK(e.rx == Approx(5));
    CHECK(e.ry == Approx(2.5));
    Path q = parse_svg_path("M0 0 A2 1 0 0 0 10 0");
    CHECK(check_arc_samples(q, 1, e).max_distance <= 5 * arc_cubic_error(kPi / 3));
    REQUIRE(q.verbs().size() == 4);
    CHECK(cubic_at(q.points()[3], q.points()[4], q.points()[5], q.points()[6], 0.5).y == Approx(2.5).epsilon(1e-4));
}

TEST_CASE("svg arc: degenerate arcs", "[svgpath]") {
    // rx or ry zero: a straight line.
    check_parse("M0 0 A0 5 0 0 1 10 0", Path().move_to(0, 0).line_to(10, 0));
    check_parse("M0 0 a5 0 30 1 1 10 5", Path().move_to(0, 0).line_to(10, 5));
    // End point == start point: nothing.
    check_parse("M5 5 A3 3 0 0 1 5 5", Path().move_to(5, 5));
    check_parse("M5 5 L6 6 a3 3 0 1 1 0 0", Path().move_to(5, 5).line_to(6, 6));
    Path p;
    p.move_to(1, 1);
    arc_to(p, 0, 0, 0, false, false, {2, 3});
    CHECK(p == Path().move_to(1, 1).line_to(2, 3));
    // arc_to on an empty path starts at (0, 0).
    Path e;
    arc_to(e, 1, 1, 0, false, true, {2, 0});
    CHECK(e.verbs()[0] == Verb::Move);
    CHECK(e.points()[0] == Point{0, 0});
    CHECK(e.points().back() == Point{2, 0});
}

TEST_CASE("svg arc: rotation", "[svgpath]") {
    // A 90-degree rotation swaps the radii exactly.
    const Path a = parse_svg_path("M0 0 A20 10 90 0 1 10 20");
    const Path b = parse_svg_path("M0 0 A10 20 0 0 1 10 20");
    REQUIRE(a.points().size() == b.points().size());
    for (std::size_t i = 0; i < a.points().size(); ++i) {
        CHECK(a.points()[i].x == Approx(b.points()[i].x).margin(1e-12));
        CHECK(a.points()[i].y == Approx(b.points()[i].y).margin(1e-12));
    }
    // Rotations by whole turns are the same arc; -30 is 330.
    CHECK(parse_svg_path("M0 0 A20 10 390 0 1 10 20") == parse_svg_path("M0 0 A20 10 30 0 1 10 20"));
    const Path c = parse_svg_path("M0 0 A20 10 -30 1 0 10 20");
    const Path d = parse_svg_path("M0 0 A20 10 330 1 0 10 20");
    REQUIRE(c.points().size() == d.points().size());
    for (std::size_t i = 0; i < c.points().size(); ++i) CHECK(distance(c.points()[i], d.points()[i]) < 1e-12);
    // Every sample of a rotated arc satisfies the rotated ellipse's equation within the bound.
    const RefArc ref = reference_arc({0, 0}, 20, 10, -30, true, false, {10, 20});
    const ArcCheck k = check_arc_samples(c, 1, ref);
    CHECK(k.max_distance <= kDefaultArcTolerance);
    CHECK(k.travel == Approx(ref.dtheta).margin(1e-9));
}

TEST_CASE("svg arc: invalid arguments and overflow", "[svgpath]") {
    Path p;
    p.move_to(0, 0);
    CHECK_THROWS_AS(arc_to(p, std::nan(""), 1, 0, false, false, {1, 1}), Error);
    CHECK_THROWS_AS(arc_to(p, 1, 1, std::numeric_limits<double>::infinity(), false, false, {1, 1}), Error);
    CHECK_THROWS_AS(arc_to(p, 1, 1, 0, false, false, {1, 1}, 0.0), Error);
    CHECK_THROWS_AS(arc_to(p, 1, 1, 0, false, false, {1, 1}, -1.0), Error);
    try {
        arc_to(p, 1e-300, 1, 45, false, false, {1e10, 1e10});
        FAIL("no error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::InvalidData); }
    CHECK(p == Path().move_to(0, 0));  // unchanged
    CHECK(parse_error("M0 0 A1e-300 1 45 0 0 1e10 1e10") == "path data column 7: arc out of range");
    // Huge but finite arcs work: radii 1e300, endpoints near the limits of double.
    Path h;
    h.move_to(-1e308, 0);
    arc_to(h, 1e300, 1e300, 0, false, true, {1e308, 0});
    CHECK(h.is_finite());
    CHECK(h.points().back() == Point{1e308, 0});
    CHECK(h.bounds().y0 == Approx(-1e308).epsilon(1e-3));
}
