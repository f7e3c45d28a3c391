// Tests for rational curves (include/casteljau/nurbs.hpp): rational de Casteljau, NURBS, exact
// circles, arcs and conics, derivatives, knot insertion, conversion to rational Bézier pieces, the
// Path route (Conic verb / proven cubic approximation) and bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "casteljau/nurbs.hpp"
#include "curve_test_util.hpp"

using namespace casteljau;
using namespace curve_test;

namespace {

std::vector<double> random_weights(std::mt19937& rng, std::size_t n) {
    std::vector<double> w;
    for (std::size_t i = 0; i < n; ++i) w.push_back(uniform(rng, 0.2, 5));
    return w;
}

// Direct formula sum w_i P_i B_i / sum w_i B_i.
template <class P>
P rational_direct(const std::vector<P>& pts, const std::vector<double>& w, double t) {
    const int n = static_cast<int>(pts.size()) - 1;
    P num{};
    double den = 0;
    for (int i = 0; i <= n; ++i) {
        const double b = bernstein(i, n, t) * w[static_cast<std::size_t>(i)];
        num += pts[static_cast<std::size_t>(i)] * b;
        den += b;
    }
    return num / den;
}

}  // namespace

TEST_CASE("NURBS: the full circle's radius is exact to 1e-12", "[nurbs]") {
    const Point c{3, -2};
    const double r = 7.5;
    const Nurbs<Point> circle = nurbs_circle(c, r);
    CHECK(circle.to_bezier().size() == 4);
    double worst = 0;
    for (int k = 0; k <= 10000; ++k) {
        const double t = k / 10000.0;
        const Point p = circle.eval(t);
        worst = std::max(worst, std::abs((p - c).length() - r));
        // The tangent is perpendicular to the radius.
        const Point d = circle.derivative(1, t);
        CHECK(std::abs(d.dot(p - c)) <= 1e-9 * d.length() * r);
    }
    INFO("worst radial error " << worst);
    CHECK(worst <= 1e-12 * r);
    CHECK(dist(circle.eval(0), circle.eval(1)) <= 1e-12);
    CHECK(dist(circle.eval(0.25), c + Point{0, r}) <= 1e-12);  // quarter turn from +x towards +y
    // Also through random (projectively equivalent) weights: scaling all weights changes nothing.
    std::vector<double> w(circle.weights().begin(), circle.weights().end());
    for (double& x : w) x *= 3.7;
    const Nurbs<Point> scaled(2, std::vector<Point>(circle.points().begin(), circle.points().end()), w,
                              std::vector<double>(circle.knots().begin(), circle.knots().end()));
    CHECK(dist(scaled.eval(0.37), circle.eval(0.37)) <= 1e-12);
}

TEST_CASE("NURBS: circular and elliptical arcs are exact", "[nurbs]") {
    std::mt19937 rng(201);
    for (int rep = 0; rep < 50; ++rep) {
        const Point c = random_point<Point>(rng);
        const double r = uniform(rng, 0.1, 100), start = uniform(rng, -7, 7);
        double sweep = uniform(rng, 0.01, 3.1);
        if (rep % 2) sweep = -sweep;
        const RationalBezier<Point> arc = circular_arc(c, r, start, sweep);
        CHECK(arc.weights()[1] == Approx(std::cos(sweep / 2)).epsilon(1e-15));
        CHECK(conic_kind(arc.weights()[1]) == ConicKind::Ellipse);
        for (int k = 0; k <= 50; ++k) {
            const Point p = arc.eval(k / 50.0);
            CHECK(std::abs((p - c).length() - r) <= 1e-12 * (r + c.length()));
        }
        const Point mid = arc.eval(0.5);
        CHECK(dist(mid, c + Point{std::cos(start + sweep / 2), std::sin(start + sweep / 2)} * r) <= 1e-11 * (r + 100));
        // Elliptical arcs of any sweep up to a full turn.
        const double rx = uniform(rng, 1, 50), ry = uniform(rng, 1, 50), rot = uniform(rng, -3, 3);
        const double big = uniform(rng, 0.1, 2 * std::numbers::pi) * (rep % 3 ? 1 : -1);
        const Nurbs<Point> e = nurbs_ellipse_arc(c, rx, ry, rot, start, big);
        for (int k = 0; k <= 100; ++k) {
            const Point p = e.eval(k / 100.0) - c;
            const double u = (std::cos(rot) * p.x + std::sin(rot) * p.y) / rx;
            const double v = (-std::sin(rot) * p.x + std::cos(rot) * p.y) / ry;
            CHECK(std::abs(u * u + v * v - 1) <= 1e-12 * (1 + c.length()));
        }
        const Point end = e.eval(1) - c;
        const double ex = std::cos(start + big), ey = std::sin(start + big);
        CHECK(dist(end, Point{std::cos(rot) * rx * ex - std::sin(rot) * ry * ey,
                              std::sin(rot) * rx * ex + std::cos(rot) * ry * ey}) <= 1e-10 * (1 + c.length()));
    }
    CHECK(conic_kind(1.0) == ConicKind::Parabola);
    CHECK(conic_kind(2.0) == ConicKind::Hyperbola);
    // A parabola (w = 1) is the polynomial quadratic.
    const auto par = conic({0, 0}, {5, 10}, {10, 0}, 1.0);
    const Bezier<Point> q{{0, 0}, {5, 10}, {10, 0}};
    CHECK(dist(par.eval(0.3), q.eval(0.3)) <= 1e-14);
}

TEST_CASE("Rational Bezier: rational de Casteljau equals the direct formula, derivatives, split", "[nurbs]") {
    std::mt19937 rng(202);
    for (int rep = 0; rep < 200; ++rep) {
        const std::size_t n = 2 + static_cast<std::size_t>(rep % 8);
        const auto pts = random_points<Point3>(rng, n);
        const auto w = random_weights(rng, n);
        const RationalBezier<Point3> r(pts, w);
        const double scale = max_norm(pts);
        for (int k = 0; k <= 10; ++k) {
            const double t = k / 10.0;
            CHECK(dist(r.eval(t), rational_direct(pts, w, t)) <= 1e-12 * scale);
        }
        CHECK(r.eval(0) == pts.front());
        CHECK(r.eval(1) == pts.back());
        // Derivatives against finite differences.
        const double t = uniform(rng, 0.2, 0.8), h = 1e-6;
        for (int k = 1; k <= 3; ++k) {
            const Point3 fd = (r.derivative(k - 1, t + h) - r.derivative(k - 1, t - h)) / (2 * h);
            const Point3 d = r.derivative(k, t);
            CHECK(dist(fd, d) <= 1e-4 * (1 + d.length() + r.derivative(k - 1, t).length()));
        }
        // End tangent n w_1 / w_0 (P_1 - P_0).
        const Point3 d0 = (pts[1] - pts[0]) * (static_cast<double>(n - 1) * w[1] / w[0]);
        CHECK(dist(r.derivative(1, 0), d0) <= 1e-10 * (1 + d0.length()));
        // Split.
        const double s = uniform(rng, 0.1, 0.9);
        const auto [a, b] = r.split(s);
        for (int k = 0; k <= 10; ++k) {
            const double u = k / 10.0;
            CHECK(dist(a.eval(u), r.eval(u * s)) <= 1e-11 * scale);
            CHECK(dist(b.eval(u), r.eval(s + u * (1 - s))) <= 1e-11 * scale);
        }
        // Normalised: end weights 1, same point set (a reparametrisation): the points of the
        // normalised curve lie on the original (checked through the split at the matching parameter).
        const auto nr = r.normalized();
        CHECK(nr.weights().front() == 1);
        CHECK(nr.weights().back() == 1);
        CHECK(dist(nr.eval(0), r.eval(0)) <= 1e-12 * scale);
        CHECK(dist(nr.eval(1), r.eval(1)) <= 1e-12 * scale);
    }
    // Normalising a circular arc with unbalanced weights keeps it on the circle.
    const auto arc = circular_arc({0, 0}, 10, 0.3, 2.0);
    const RationalBezier<Point> skew(std::vector<Point>(arc.points().begin(), arc.points().end()),
                                     {4.0, 2.0 * arc.weights()[1], 1.0});  // w_i rho^i times 4, rho = 1/2
    const auto norm = skew.normalized();
    for (int k = 0; k <= 20; ++k) CHECK(std::abs(skew.eval(k / 20.0).length() - 10) <= 1e-11);
    for (int k = 0; k <= 20; ++k) CHECK(std::abs(norm.eval(k / 20.0).length() - 10) <= 1e-11);
    CHECK(norm.weights()[1] == Approx(arc.weights()[1]).epsilon(1e-14));
}

TEST_CASE("NURBS: unit weights give the B-spline, insertion and Bezier extraction preserve the curve", "[nurbs]") {
    std::mt19937 rng(203);
    for (int rep = 0; rep < 100; ++rep) {
        const int p = 1 + rep % 4;
        const std::size_t count = static_cast<std::size_t>(p) + 1 + static_cast<std::size_t>(rep % 6);
        const auto pts = random_points<Point>(rng, count);
        const auto w = random_weights(rng, count);
        const auto bs = BSpline<Point>::clamped(p, pts);
        const Nurbs<Point> unit(bs);
        const Nurbs<Point> nu(p, pts, w, clamped_knots(p, count));
        const double scale = max_norm(pts);
        for (int k = 0; k <= 20; ++k) {
            const double t = k / 20.0;
            CHECK(dist(unit.eval(t), bs.eval(t)) <= 1e-12 * scale);
            // The NURBS equals the B-spline of the homogeneous points, projected.
            const auto N = bspline_basis_all(p, nu.knots(), t);
            Point num{};
            double den = 0;
            for (std::size_t i = 0; i < count; ++i) {
                num += pts[i] * (w[i] * N[i]);
                den += w[i] * N[i];
            }
            CHECK(dist(nu.eval(t), num / den) <= 1e-12 * scale);
        }
        const double u = uniform(rng, 0.05, 0.95);
        const auto ins = nu.with_knot(u, std::min(p, 2));
        for (int k = 0; k <= 20; ++k) CHECK(dist(ins.eval(k / 20.0), nu.eval(k / 20.0)) <= 1e-12 * scale);
        const auto pieces = nu.to_bezier();
        const auto bp = nu.breakpoints();
        REQUIRE(pieces.size() + 1 == bp.size());
        for (std::size_t j = 0; j < pieces.size(); ++j)
            for (int k = 0; k <= 10; ++k) {
                const double s = k / 10.0;
                const double t = k == 10 ? bp[j + 1] : bp[j] + (bp[j + 1] - bp[j]) * s;
                CHECK(dist(pieces[j].eval(s), nu.eval(t)) <= 1e-12 * scale);
            }
        // Derivative against finite differences inside a span.
        const double t = 0.5 * (bp[0] + bp[1]), h = 1e-7;
        const Point fd = (nu.eval(t + h) - nu.eval(t - h)) / (2 * h);
        CHECK(dist(fd, nu.derivative(1, t)) <= 1e-4 * (1 + fd.length()));
    }
}

TEST_CASE("NURBS: the Path route: conics as Conic verbs, higher degrees with a proven bound", "[nurbs]") {
    const auto arc = circular_arc({0, 0}, 10, 0, std::numbers::pi / 2);
    const Path pa = to_path(arc);
    REQUIRE(pa.verbs().size() == 2);
    CHECK(pa.verbs()[1] == Verb::Conic);
    CHECK(pa.weights()[0] == Approx(std::sqrt(0.5)).epsilon(1e-15));
    const Path pc = to_path(nurbs_circle({0, 0}, 5));
    CHECK(pc.contour_count() == 1);
    CHECK(std::count(pc.verbs().begin(), pc.verbs().end(), Verb::Conic) == 4);
    CHECK(dist(pc.points().back(), pc.points().front()) <= 1e-12);
    // An unnormalised conic is reparametrised to end weights 1 with the same shape.
    const RationalBezier<Point> un({{10, 0}, {10, 10}, {0, 10}}, {2.0, std::sqrt(0.5), 0.5});  // w1^2 / (w0 w2) = 1/2
    const Path pu = to_path(un);
    CHECK(pu.weights()[0] == Approx(std::sqrt(0.5)).epsilon(1e-12));
    // Rational cubic: cubic pieces, proven bound below the tolerance, checked by sampling.
    std::mt19937 rng(204);
    for (int rep = 0; rep < 10; ++rep) {
        const std::size_t n = 4 + static_cast<std::size_t>(rep % 4);
        const RationalBezier<Point> r(random_points<Point>(rng, n), random_weights(rng, n));
        Path p;
        const double tol = 0.05;
        const double achieved = append_to_path(p, r, tol);
        CHECK(achieved <= tol);
        CHECK(p.points().front() == r.points().front());
        CHECK(dist(p.points().back(), r.eval(1)) <= 1e-9);
        const double worst = max_cubic_path_deviation(p, r, 4000, 8, 200);
        CHECK(worst <= tol + 1e-3);
    }
}

TEST_CASE("NURBS: bad input gives clear errors", "[nurbs]") {
    const std::vector<Point> pts = {{0, 0}, {1, 1}, {2, 0}};
    CHECK(kind_of([&] { RationalBezier<Point>(pts, {1, 0, 1}); }) == ErrorKind::InvalidData);
    CHECK_THROWS_WITH(RationalBezier<Point>(pts, {1, 0, 1}),
                      "rational Bezier curve weight 1 is 0; weights must be positive and finite");
    CHECK(kind_of([&] { RationalBezier<Point>(pts, {1, -2, 1}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { RationalBezier<Point>(pts, {1, NAN, 1}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { RationalBezier<Point>(pts, {1, 1}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { RationalBezier<Point>(std::vector<Point>{{0, 0}}, {1}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { Nurbs<Point>(2, pts, {1, 1, -1}, {0, 0, 0, 1, 1, 1}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { Nurbs<Point>(2, pts, {1, 1, 1}, {0, 0, 0, 1, 1}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { Nurbs<Point>(2, pts, {1, 1, 1}, {0, 0, 1, 0, 1, 1}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { Nurbs<Point>(0, pts, {1, 1, 1}, {0, 1, 2, 3}); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { Nurbs<Point>(1000, pts, {1, 1, 1}, {0, 1, 2, 3}); }) == ErrorKind::Limit);
    const auto r = RationalBezier<Point>(pts, {1, 2, 1});
    CHECK(kind_of([&] { r.eval(1.5); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { r.split(-1); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { nurbs_circle({0, 0}, 5).eval(2); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([] { circular_arc({0, 0}, 1, 0, std::numbers::pi); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([] { circular_arc({0, 0}, 0, 0, 1); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([] { nurbs_ellipse_arc({0, 0}, 1, 1, 0, 0, 7); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([] { conic_kind(0); }) == ErrorKind::InvalidData);
    CHECK(kind_of([] { conic({0, 0}, {1, 1}, {2, 0}, -1); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { to_path(r, -1); }) == ErrorKind::InvalidArgument);
}
