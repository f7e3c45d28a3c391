// Tests for Bézier curves of any degree (include/casteljau/bezier.hpp): the textbook's worked
// numbers, seeded property tests over random curves, joins, the Path bridge and bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "casteljau/bezier.hpp"
#include "curve_test_util.hpp"
#include "casteljau/limits.hpp"

using namespace casteljau;
using namespace curve_test;

namespace {

void check_point(Point a, Point b, double eps) {
    INFO("got (" << a.x << ", " << a.y << "), expected (" << b.x << ", " << b.y << ")");
    CHECK(std::abs(a.x - b.x) <= eps);
    CHECK(std::abs(a.y - b.y) <= eps);
}

}  // namespace

// ---- worked numbers ---------------------------------------------------------------------------

TEST_CASE("Bezier: the textbook cubic at t = 0.4 is (69.12, 80.64)", "[bezier]") {
    const Bezier<Point> c{{0, 0}, {48, 96}, {120, 120}, {216, 72}};
    check_point(c.eval(0.4), {69.12, 80.64}, 1e-12);
    check_point(c.eval_bernstein(0.4), {69.12, 80.64}, 1e-12);
    check_point(c.to_power().eval(0.4), {69.12, 80.64}, 1e-12);
}

TEST_CASE("Bezier: the textbook cubic's polynomial form x = 144t + 72t^2, y = 288t - 216t^2", "[bezier]") {
    // a_0 = P0, a_1 = 3(P1 - P0), a_2 = 3(P0 - 2P1 + P2), a_3 = P3 - 3P2 + 3P1 - P0 = (0, 0): this
    // "cubic" is a parabola. All coefficients are exact in binary.
    const Bezier<Point> c{{0, 0}, {48, 96}, {120, 120}, {216, 72}};
    const PowerForm<Point> pf = c.to_power();
    REQUIRE(pf.degree() == 3);
    CHECK(pf.coefficients[0] == Point{0, 0});
    CHECK(pf.coefficients[1] == Point{144, 288});
    CHECK(pf.coefficients[2] == Point{72, -216});
    CHECK(pf.coefficients[3] == Point{0, 0});
    // And back.
    const Bezier<Point> back = Bezier<Point>::from_power(pf);
    for (int i = 0; i < 4; ++i) check_point(back[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(i)], 1e-12);
}

TEST_CASE("Bezier: the cubic power-form matrix is the textbook one", "[bezier]") {
    const std::vector<double> M = bernstein_to_power_matrix(3);
    const std::vector<double> expected = {1, 0, 0, 0, -3, 3, 0, 0, 3, -6, 3, 0, -1, 3, -3, 1};
    CHECK(M == expected);
    CHECK(bernstein_to_power_matrix(2) == std::vector<double>{1, 0, 0, -2, 2, 0, 1, -2, 1});
}

TEST_CASE("Bezier: elevating (0,0),(0,100),(100,0),(100,100) gives (0,0),(0,75),(50,50),(100,25),(100,100)",
          "[bezier]") {
    const Bezier<Point> c{{0, 0}, {0, 100}, {100, 0}, {100, 100}};
    const Bezier<Point> e = c.elevated();
    REQUIRE(e.degree() == 4);
    const std::vector<Point> expected = {{0, 0}, {0, 75}, {50, 50}, {100, 25}, {100, 100}};
    for (std::size_t i = 0; i < expected.size(); ++i) check_point(e[i], expected[i], 0);
}

TEST_CASE("Bezier: the quartic's whole de Casteljau triangle at t = 1/2", "[bezier]") {
    // By hand, exact in binary (every entry is a multiple of 1/32):
    const Bezier<Point> q{{30, 0}, {60, 10}, {80, 30}, {90, 60}, {90, 90}};
    const std::vector<std::vector<Point>> expected = {
        {{30, 0}, {60, 10}, {80, 30}, {90, 60}, {90, 90}},
        {{45, 5}, {70, 20}, {85, 45}, {90, 75}},
        {{57.5, 12.5}, {77.5, 32.5}, {87.5, 60}},
        {{67.5, 22.5}, {82.5, 46.25}},
        {{75, 34.375}},
    };
    const auto tri = q.triangle(0.5);
    REQUIRE(tri.size() == expected.size());
    for (std::size_t r = 0; r < expected.size(); ++r) {
        REQUIRE(tri[r].size() == expected[r].size());
        for (std::size_t i = 0; i < expected[r].size(); ++i) {
            INFO("row " << r << " entry " << i);
            CHECK(tri[r][i] == expected[r][i]);
        }
    }
    CHECK(q.eval(0.5) == Point{75, 34.375});
    // The edges of the triangle are the halves.
    const auto [left, right] = q.split(0.5);
    for (std::size_t r = 0; r <= 4; ++r) {
        CHECK(left[r] == tri[r][0]);
        CHECK(right[4 - r] == tri[r].back());
    }
}

TEST_CASE("Bezier: the cubic through Q0(50,0), Q1(100,0), Q2(0,50), Q3(0,100) at 0, 1/3, 2/3, 1", "[bezier]") {
    const Point q0{50, 0}, q1{100, 0}, q2{0, 50}, q3{0, 100};
    const Bezier<Point> c = interpolate_cubic(q0, q1, q2, q3);
    // P1 = (-5 Q0 + 18 Q1 - 9 Q2 + 2 Q3)/6 = (1550/6, -250/6); P2 = (2 Q0 - 9 Q1 + 18 Q2 - 5 Q3)/6 = (-800/6, 400/6).
    check_point(c[0], q0, 0);
    check_point(c[1], {1550.0 / 6, -250.0 / 6}, 1e-12);
    check_point(c[2], {-800.0 / 6, 400.0 / 6}, 1e-12);
    check_point(c[3], q3, 0);
    check_point(c.eval(0), q0, 0);
    check_point(c.eval(1.0 / 3), q1, 1e-12);
    check_point(c.eval(2.0 / 3), q2, 1e-12);
    check_point(c.eval(1), q3, 0);
}

TEST_CASE("Bezier: curvature of the parabola y = x^2 is 2 at its vertex, cusp gives infinity", "[bezier]") {
    const Bezier<Point> p{{-1, 1}, {0, -1}, {1, 1}};  // x = 2t - 1, y = x^2
    CHECK(p.curvature(0.5) == Approx(2.0).epsilon(1e-14));
    CHECK(p.signed_curvature(0.5) == Approx(2.0).epsilon(1e-14));
    CHECK(p.reversed().signed_curvature(0.5) == Approx(-2.0).epsilon(1e-14));
    // At x = 1 (t = 1): k = 2 / (1 + 4)^(3/2).
    CHECK(p.curvature(1) == Approx(2.0 / std::pow(5.0, 1.5)).epsilon(1e-14));
    const Bezier<Point> cusp{{0, 0}, {100, 100}, {0, 100}, {100, 0}};  // P'(1/2) = 0
    CHECK(cusp.derivative(1, 0.5) == Point{0, 0});
    CHECK(std::isinf(cusp.curvature(0.5)));
    const Bezier<Point3> helixish{{1, 0, 0}, {1, 1, 0.5}, {0, 1, 1}};
    CHECK(helixish.curvature(0.3) > 0);
}

TEST_CASE("Bezier: tight bounds from the derivative's roots", "[bezier]") {
    const Bezier<Point> arch{{0, 0}, {0, 100}, {100, 100}, {100, 0}};
    const Box<Point> b = arch.bounds();
    CHECK(b.lo == Point{0, 0});
    CHECK(b.hi.x == 100);
    CHECK(b.hi.y == Approx(75).epsilon(1e-15));
    CHECK(arch.control_bounds().hi.y == 100);
    REQUIRE(arch.extrema(1).size() == 1);
    CHECK(arch.extrema(1)[0] == Approx(0.5).epsilon(1e-15));
}

TEST_CASE("Bezier: bernstein_roots finds simple, clustered and double roots", "[bezier]") {
    // p(t) = prod (t - r_k), built in power form and converted with from_power (x coordinate).
    const std::vector<double> rts = {0.05, 0.3, 0.31, 0.5, 0.77, 0.999};
    std::vector<double> poly = {1};
    for (double r : rts) {
        std::vector<double> next(poly.size() + 1, 0.0);
        for (std::size_t i = 0; i < poly.size(); ++i) {
            next[i + 1] += poly[i];
            next[i] -= r * poly[i];
        }
        poly = next;
    }
    PowerForm<Point> pf;
    for (double a : poly) pf.coefficients.push_back({a, 0});
    const Bezier<Point> b = Bezier<Point>::from_power(pf);
    std::vector<double> c;
    for (const Point& p : b.points()) c.push_back(p.x);
    const std::vector<double> found = bernstein_roots(c);
    REQUIRE(found.size() == rts.size());
    for (std::size_t i = 0; i < rts.size(); ++i) CHECK(found[i] == Approx(rts[i]).margin(1e-12));

    // (t - 1/2)^2: Bernstein coefficients 1/4, -1/4, 1/4.
    const std::vector<double> dbl = {0.25, -0.25, 0.25};
    const auto d = bernstein_roots(dbl);
    REQUIRE(d.size() == 1);
    CHECK(d[0] == Approx(0.5).margin(1e-7));
    // Roots at the ends, none inside; no roots; identically zero.
    CHECK(bernstein_roots(std::vector<double>{0, 1, 0}) == std::vector<double>{0, 1});
    CHECK(bernstein_roots(std::vector<double>{1, 2, 3}).empty());
    CHECK(bernstein_roots(std::vector<double>{0, 0, 0}).empty());
}

// ---- seeded property tests --------------------------------------------------------------------

TEST_CASE("Bernstein basis: partition of unity, non-negativity, symmetry (all degrees to 64)", "[bezier]") {
    std::mt19937 rng(20240501);
    std::vector<double> b;
    for (int n = 0; n <= limits::kMaxBezierDegree; ++n) {
        b.resize(static_cast<std::size_t>(n) + 1);
        for (int k = 0; k < 20; ++k) {
            const double t = uniform(rng, 0, 1);
            bernstein_all(n, t, b);
            double sum = 0;
            for (int i = 0; i <= n; ++i) {
                const double v = b[static_cast<std::size_t>(i)];
                CHECK(v >= 0);
                sum += v;
                CHECK(v == Approx(bernstein(i, n, t)).margin(1e-14).epsilon(1e-10));
                CHECK(bernstein(i, n, t) == Approx(bernstein(n - i, n, 1 - t)).margin(1e-15).epsilon(1e-12));
            }
            CHECK(sum == Approx(1.0).margin(1e-13));
        }
    }
}

TEST_CASE("Bezier: de Casteljau and Bernstein-Horner agree to 1e-12 relative at every degree", "[bezier]") {
    std::mt19937 rng(7);
    double worst = 0;
    for (int n = 1; n <= limits::kMaxBezierDegree; ++n) {
        const auto pts = random_points<Point>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point> c(pts);
        const double scale = max_norm(pts);
        for (int k = 0; k <= 50; ++k) {
            const double t = k / 50.0;
            worst = std::max(worst, dist(c.eval(t), c.eval_bernstein(t)) / scale);
        }
    }
    INFO("worst relative difference " << worst);
    CHECK(worst <= 1e-12);
}

TEST_CASE("Bezier: the power form agrees with de Casteljau to 1e-12 relative up to degree 8", "[bezier]") {
    std::mt19937 rng(8);
    for (int n = 1; n <= 8; ++n) {
        for (int rep = 0; rep < 20; ++rep) {
            const auto pts = random_points<Point3>(rng, static_cast<std::size_t>(n) + 1);
            const Bezier<Point3> c(pts);
            const auto pf = c.to_power();
            const double scale = max_norm(pts);
            for (int k = 0; k <= 20; ++k) {
                const double t = k / 20.0;
                CHECK(dist(c.eval(t), pf.eval(t)) <= 1e-12 * scale);
            }
            const Bezier<Point3> back = Bezier<Point3>::from_power(pf);
            for (std::size_t i = 0; i < pts.size(); ++i) CHECK(dist(back[i], pts[i]) <= 1e-12 * scale);
        }
    }
}

TEST_CASE("Bezier: symmetry, end points and end tangents over random curves", "[bezier]") {
    std::mt19937 rng(11);
    for (int rep = 0; rep < 200; ++rep) {
        const int n = 1 + rep % 12;
        const auto pts = random_points<Point>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point> c(pts);
        const Bezier<Point> r = c.reversed();
        const double scale = max_norm(pts);
        for (int k = 0; k < 5; ++k) {
            const double t = uniform(rng, 0, 1);
            CHECK(dist(c.eval(t), r.eval(1 - t)) <= 1e-12 * scale);
        }
        CHECK(c.eval(0) == pts.front());
        CHECK(c.eval(1) == pts.back());
        CHECK(dist(c.derivative(1, 0), (pts[1] - pts[0]) * n) <= 1e-12 * scale * n);
        CHECK(dist(c.derivative(1, 1), (pts[static_cast<std::size_t>(n)] - pts[static_cast<std::size_t>(n) - 1]) * n) <=
              1e-12 * scale * n);
    }
}

TEST_CASE("Bezier: curve points lie in the convex hull of the control points", "[bezier]") {
    std::mt19937 rng(12);
    for (int rep = 0; rep < 200; ++rep) {
        const int n = 1 + rep % 10;
        const auto pts = random_points<Point>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point> c(pts);
        for (int k = 0; k <= 32; ++k) {
            const Point p = c.eval(k / 32.0);
            CHECK(in_convex_hull(pts, p, 1e-9));
            CHECK(c.control_bounds().contains(p, 1e-12));
        }
    }
}

TEST_CASE("Bezier: derivatives of every order match finite differences", "[bezier]") {
    std::mt19937 rng(13);
    for (int rep = 0; rep < 60; ++rep) {
        const int n = 2 + rep % 8;
        const auto pts = random_points<Point3>(rng, static_cast<std::size_t>(n) + 1, -1, 1);
        const Bezier<Point3> c(pts);
        for (int k = 1; k <= n; ++k) {
            const double t = uniform(rng, 0.1, 0.9), h = 1e-5;
            const Point3 fd = (c.derivative(k - 1, t + h) - c.derivative(k - 1, t - h)) / (2 * h);
            const Point3 d = c.derivative(k, t);
            // Central difference error ~ h^2 |f'''| / 6; scale by the size of the derivatives.
            const double mag = 1 + c.derivative(k, t).length() + std::pow(2.0 * n, k + 2) * 1e-10;
            INFO("degree " << n << " order " << k);
            CHECK(dist(fd, d) <= 1e-5 * mag);
        }
        CHECK(c.derivative(n + 1, 0.3) == Point3{});
        // The hodograph evaluated as a Bézier equals derivative(1, t).
        const Bezier<Point3> hodo(c.derivative_points(1));
        CHECK(dist(hodo.eval(0.37), c.derivative(1, 0.37)) <= 1e-12 * (1 + hodo.eval(0.37).length()));
    }
}

TEST_CASE("Bezier: split-then-join round trip and sub-curves", "[bezier]") {
    std::mt19937 rng(14);
    for (int rep = 0; rep < 100; ++rep) {
        const int n = 1 + rep % 9;
        const auto pts = random_points<Point>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point> c(pts);
        const double scale = max_norm(pts);
        const double t = uniform(rng, 0.4, 0.7);
        const auto [l, r] = c.split(t);
        CHECK(l.back() == r.front());
        CHECK(join_continuity(l, r) == Continuity::G2);
        for (int k = 0; k <= 10; ++k) {
            const double s = k / 10.0;
            CHECK(dist(l.eval(s), c.eval(s * t)) <= 1e-12 * scale);
            CHECK(dist(r.eval(s), c.eval(t + s * (1 - t))) <= 1e-12 * scale);
        }
        // Join: the left half's blossom at (0^(n-i), (1/t)^i) extrapolates back to the original.
        std::vector<Point> rejoined;
        for (int i = 0; i <= n; ++i) {
            std::vector<double> args(static_cast<std::size_t>(n), 0.0);
            for (int j = n - i; j < n; ++j) args[static_cast<std::size_t>(j)] = 1 / t;
            rejoined.push_back(l.blossom(args));
        }
        for (std::size_t i = 0; i < pts.size(); ++i) CHECK(dist(rejoined[i], pts[i]) <= 1e-9 * scale);
        // Sub-curve [t0, t1] (and reversed).
        const double t0 = uniform(rng, 0, 0.5), t1 = uniform(rng, 0.5, 1);
        const Bezier<Point> sub = c.subcurve(t0, t1), rev = c.subcurve(t1, t0);
        for (int k = 0; k <= 10; ++k) {
            const double s = k / 10.0;
            CHECK(dist(sub.eval(s), c.eval(t0 + s * (t1 - t0))) <= 1e-12 * scale);
            CHECK(dist(rev.eval(s), c.eval(t1 + s * (t0 - t1))) <= 1e-12 * scale);
        }
    }
}

TEST_CASE("Bezier: elevation preserves the curve to 1e-12", "[bezier]") {
    std::mt19937 rng(15);
    for (int rep = 0; rep < 100; ++rep) {
        const int n = 1 + rep % 20;
        const auto pts = random_points<Point3>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point3> c(pts);
        const Bezier<Point3> e = c.elevated(1 + rep % 5);
        const double scale = max_norm(pts);
        for (int k = 0; k <= 40; ++k) {
            const double t = k / 40.0;
            CHECK(dist(c.eval(t), e.eval(t)) <= 1e-12 * scale);
        }
    }
}

TEST_CASE("Bezier: reducing an elevated curve returns the original (all three methods)", "[bezier]") {
    std::mt19937 rng(16);
    for (int rep = 0; rep < 60; ++rep) {
        const int n = 1 + rep % 10;
        const auto pts = random_points<Point>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point> c(pts);
        const Bezier<Point> e = c.elevated();
        const double scale = max_norm(pts);
        for (ReductionMethod m : {ReductionMethod::Forward, ReductionMethod::Backward, ReductionMethod::Combined}) {
            const Reduction<Point> red = reduce_degree(e, m);
            REQUIRE(red.curve.degree() == n);
            for (std::size_t i = 0; i < pts.size(); ++i) CHECK(dist(red.curve[i], pts[i]) <= 1e-10 * scale);
            CHECK(red.max_deviation <= 1e-10 * scale);
            CHECK(red.deviation_bound <= 1e-10 * scale);
        }
    }
}

TEST_CASE("Bezier: reduction reports deviations, the bound holds, combined is symmetric", "[bezier]") {
    std::mt19937 rng(17);
    for (int rep = 0; rep < 60; ++rep) {
        const int n = 2 + rep % 8;
        const auto pts = random_points<Point>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point> c(pts);
        for (ReductionMethod m : {ReductionMethod::Forward, ReductionMethod::Backward, ReductionMethod::Combined}) {
            const Reduction<Point> red = reduce_degree(c, m);
            // The sampled deviation is checked against an independent dense sampling, and the proven
            // bound must dominate both.
            double dense = 0;
            for (int k = 0; k <= 2000; ++k)
                dense = std::max(dense, dist(c.eval(k / 2000.0), red.curve.eval(k / 2000.0)));
            CHECK(red.max_deviation <= dense * (1 + 1e-3) + 1e-9);  // the two grids differ
            CHECK(red.max_deviation >= 0.95 * dense);
            CHECK(red.deviation_bound >= dense - 1e-9);
        }
        // Forward keeps P0 (and the start tangent), backward keeps Pn.
        CHECK(reduce_degree(c, ReductionMethod::Forward).curve.front() == c.front());
        CHECK(reduce_degree(c, ReductionMethod::Backward).curve.back() == c.back());
        const auto a = reduce_degree(c, ReductionMethod::Combined).curve;
        const auto b = reduce_degree(c.reversed(), ReductionMethod::Combined).curve.reversed();
        for (std::size_t i = 0; i < a.points().size(); ++i) CHECK(dist(a[i], b[i]) <= 1e-9 * max_norm(pts));
    }
    // A quadratic reduces to the line between its ends with the combined method.
    const Bezier<Point> q{{0, 0}, {50, 40}, {100, 0}};
    const auto red = reduce_degree(q, ReductionMethod::Combined);
    CHECK(red.curve.front() == Point{0, 0});
    CHECK(red.curve.back() == Point{100, 0});
    CHECK(red.max_deviation == Approx(20).epsilon(1e-12));  // the apex at t = 1/2 is (50, 20)
    CHECK(red.deviation_bound == Approx(40).epsilon(1e-12));
}

TEST_CASE("Bezier: bounds contain the curve and are tight", "[bezier]") {
    std::mt19937 rng(18);
    for (int rep = 0; rep < 100; ++rep) {
        const int n = 1 + rep % 15;
        const auto pts = random_points<Point3>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point3> c(pts);
        const Box<Point3> box = c.bounds();
        Box<Point3> sampled{c.eval(0), c.eval(0)};
        for (int k = 0; k <= 4000; ++k) {
            const Point3 p = c.eval(k / 4000.0);
            CHECK(box.contains(p, 1e-9));
            sampled.include(p);
        }
        // Dense sampling approaches the box from inside: within the sampling step times the speed.
        const double slack = 1e-3 * max_norm(pts) * n;
        CHECK(dist(box.lo, sampled.lo) <= slack);
        CHECK(dist(box.hi, sampled.hi) <= slack);
    }
}

TEST_CASE("Bezier: G1 and G2 joins from alpha and beta", "[bezier]") {
    std::mt19937 rng(19);
    for (int rep = 0; rep < 50; ++rep) {
        const int n = 2 + rep % 5;
        const auto pts = random_points<Point>(rng, static_cast<std::size_t>(n) + 1);
        const Bezier<Point> a(pts);
        const double alpha = uniform(rng, 0.3, 3), beta = uniform(rng, -2, 2);
        // G1.
        std::vector<Point> q = g1_join_points(a, alpha);
        for (int i = 2; i <= n; ++i) q.push_back(random_point<Point>(rng));
        const Bezier<Point> b1(q);
        CHECK(join_continuity(a, b1) >= Continuity::G1);
        CHECK(dist(b1.derivative(1, 0), a.derivative(1, 1) * alpha) <= 1e-9 * max_norm(pts) * n);
        // G2, and the textbook formula for equal degrees.
        std::vector<Point> q2 = g2_join_points(a, alpha, beta);
        const auto N = static_cast<std::size_t>(n);
        const Point textbook = pts[N] + (pts[N] - pts[N - 1]) * (alpha * alpha + 2 * alpha + beta / (n - 1)) -
                               (pts[N - 1] - pts[N - 2]) * (alpha * alpha);
        CHECK(dist(q2[2], textbook) <= 1e-9 * max_norm(pts) * (1 + alpha * alpha));
        for (int i = 3; i <= n; ++i) q2.push_back(random_point<Point>(rng));
        const Bezier<Point> b2(q2);
        CHECK(join_continuity(a, b2) == Continuity::G2);
        const Point expect2 = a.derivative(2, 1) * (alpha * alpha) + a.derivative(1, 1) * beta;
        CHECK(dist(b2.derivative(2, 0), expect2) <= 1e-9 * (1 + expect2.length()));
        // A different next degree keeps G2.
        std::vector<Point> q3 = g2_join_points(a, alpha, beta, 5);
        for (int i = 3; i <= 5; ++i) q3.push_back(random_point<Point>(rng));
        CHECK(join_continuity(a, Bezier<Point>(q3)) == Continuity::G2);
        // Perturbing Q2 breaks G2 but not G1; perturbing Q1 sideways breaks G1; moving Q0 breaks G0.
        std::vector<Point> bad = q2;
        bad[2] += Point{3, -2};
        CHECK(join_continuity(a, Bezier<Point>(bad)) == Continuity::G1);
        bad = q2;
        const Point dir = q2[1] - q2[0];
        bad[1] += Point{-dir.y, dir.x} * 0.1;
        CHECK(join_continuity(a, Bezier<Point>(bad)) == Continuity::G0);
        bad = q2;
        bad[0] += Point{0.5, 0};
        CHECK(join_continuity(a, Bezier<Point>(bad)) == Continuity::None);
    }
    // A tangent that turns back (cusp at the join) is G0 only.
    const Bezier<Point> a{{0, 0}, {1, 0}}, b{{1, 0}, {0, 0}};
    CHECK(join_continuity(a, b) == Continuity::G0);
    // A coincident control point does not hide the tangent.
    const Bezier<Point> c{{0, 0}, {1, 0}, {2, 0}, {2, 0}}, d{{2, 0}, {3, 0}, {4, 1}};
    CHECK(join_continuity(c, d) >= Continuity::G1);
    // 3-D.
    const Bezier<Point3> s{{0, 0, 0}, {1, 0, 1}, {2, 1, 1}};
    const auto q = g2_join_points(s, 1.5, 0.25, 3);
    CHECK(join_continuity(s, Bezier<Point3>({q[0], q[1], q[2], {5, 5, 5}})) == Continuity::G2);
}

TEST_CASE("Bezier: to Path, exact verbs up to cubic and proven cubic approximations above", "[bezier]") {
    const Bezier<Point> line{{0, 0}, {10, 0}}, quad{{0, 0}, {5, 10}, {10, 0}},
        cubic{{0, 0}, {0, 10}, {10, 10}, {10, 0}};
    CHECK(to_path(line).verbs().size() == 2);
    CHECK(to_path(quad).verbs()[1] == Verb::Quad);
    const Path pc = to_path(cubic);
    REQUIRE(pc.verbs().size() == 2);
    CHECK(pc.verbs()[1] == Verb::Cubic);
    CHECK(pc.points()[1] == Point{0, 10});

    std::mt19937 rng(20);
    for (int rep = 0; rep < 20; ++rep) {
        const int n = 4 + rep % 12;
        const Bezier<Point> c(random_points<Point>(rng, static_cast<std::size_t>(n) + 1));
        const double tol = 0.05;
        Path p;
        const double achieved = append_to_path(p, c, tol);
        CHECK(achieved <= tol);
        // Each cubic piece: sample it and find the nearest point of the original curve (coarse
        // sampling, then a fine search around the best coarse sample).
        const double worst = max_cubic_path_deviation(p, c, 2000, 16, 400);
        CHECK(worst <= tol + 1e-3);  // + the fine sampling step of the original
        CHECK(p.points().front() == c.front());
        CHECK(p.points().back() == c.back());
    }
    // Pieces sharing end points share a contour.
    const std::vector<Bezier<Point>> pieces = {cubic, Bezier<Point>{{10, 0}, {20, 0}},
                                               Bezier<Point>{{50, 50}, {60, 60}}};
    CHECK(to_path(pieces).contour_count() == 2);
}

// ---- bad input --------------------------------------------------------------------------------

TEST_CASE("Bezier: bad input gives clear errors", "[bezier]") {
    auto kind_of = [](auto&& f) {
        try {
            f();
        } catch (const Error& e) { return e.kind(); }
        return ErrorKind::Io;  // "did not throw" marker for these tests
    };
    CHECK(kind_of([] { Bezier<Point>(std::vector<Point>{}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([] { Bezier<Point>(std::vector<Point>{{1, 2}}); }) == ErrorKind::InvalidData);
    CHECK_THROWS_WITH(Bezier<Point>(std::vector<Point>{{1, 2}}), "Bezier curve needs at least 2 control points, got 1");
    CHECK(kind_of([] { Bezier<Point>(std::vector<Point>(66)); }) == ErrorKind::Limit);
    CHECK(kind_of([] { Bezier<Point>(std::vector<Point>(1001)); }) == ErrorKind::Limit);
    CHECK_NOTHROW(Bezier<Point>(std::vector<Point>(65)));
    CHECK(kind_of([] { Bezier<Point>({{0, 0}, {std::nan(""), 1}}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([] { Bezier<Point3>({{0, 0, 0}, {1, 1, INFINITY}}); }) == ErrorKind::InvalidData);
    const Bezier<Point> c{{0, 0}, {1, 1}, {2, 0}};
    CHECK(kind_of([&] { c.eval(-0.1); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { c.eval(1.1); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { c.eval(std::nan("")); }) == ErrorKind::InvalidArgument);
    CHECK_THROWS_WITH(c.eval(1.5), "t = 1.5 is outside [0, 1]");
    CHECK(kind_of([&] { c.split(2); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { c.derivative(-1, 0.5); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { c.elevated(63); }) == ErrorKind::Limit);
    CHECK(kind_of([&] {
              reduce_degree(Bezier<Point>{{0, 0}, {1, 1}}, ReductionMethod::Combined);
          }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { g1_join_points(c, 0.0); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { g1_join_points(c, -1.0); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { to_path(c, 0.0); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { c.blossom(std::vector<double>{0.5}); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([] { bernstein_to_power_matrix(65); }) == ErrorKind::InvalidArgument);
}

TEST_CASE("Bezier: bounds of huge coordinates report the overflow clearly (regression)", "[bezier]") {
    const Bezier<Point> huge{{0, 0}, {1e308, 1e308}, {-1e308, 0}, {5, 5}};
    CHECK(huge.eval(0.5).is_finite());
    CHECK_THROWS_WITH(huge.bounds(), "Bezier curve: coordinates too large (the derivative overflows)");
}
