// Tests for B-splines and the interpolating splines (include/casteljau/spline.hpp): basis
// functions, de Boor, derivatives, knot insertion, conversion to Bézier, the uniform cubic matrices,
// Hermite / Cardinal / Catmull-Rom / Kochanek-Bartels / natural splines, and bad input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "casteljau/spline.hpp"
#include "curve_test_util.hpp"

using namespace casteljau;
using namespace curve_test;

namespace {

// The literal Cox-de Boor recursion (exponential; small degrees only), half-open spans.
double naive_basis(int i, int p, const std::vector<double>& U, double t) {
    const auto I = static_cast<std::size_t>(i), Pp = static_cast<std::size_t>(p);
    if (p == 0) return U[I] <= t && t < U[I + 1] ? 1.0 : 0.0;
    double v = 0;
    if (U[I + Pp] > U[I]) v += (t - U[I]) / (U[I + Pp] - U[I]) * naive_basis(i, p - 1, U, t);
    if (U[I + Pp + 1] > U[I + 1])
        v += (U[I + Pp + 1] - t) / (U[I + Pp + 1] - U[I + 1]) * naive_basis(i + 1, p - 1, U, t);
    return v;
}

// Random non-decreasing knots: interior multiplicities up to p, clamped ends (p + 1 equal knots) or
// free ends; retried until the domain [u_p, u_n] is not empty.
std::vector<double> random_knots(std::mt19937& rng, int p, std::size_t count, bool clamp_ends) {
    const auto P = static_cast<std::size_t>(p);
    const std::size_t m = count + P + 1;
    for (;;) {
        std::vector<double> U;
        double u = uniform(rng, -1, 1);
        const std::size_t body = clamp_ends ? m - 2 * (P + 1) : m;
        if (clamp_ends) U.assign(P + 1, u);
        while (U.size() < (clamp_ends ? P + 1 + body : m)) {
            u += uniform(rng, 0.2, 2);
            std::size_t mult = 1;
            if (uniform(rng, 0, 1) < 0.3) mult = 1 + static_cast<std::size_t>(uniform(rng, 0, p));
            for (std::size_t k = 0; k < mult && U.size() < (clamp_ends ? P + 1 + body : m); ++k) U.push_back(u);
        }
        if (clamp_ends) {
            u += uniform(rng, 0.2, 2);
            U.insert(U.end(), P + 1, u);
        }
        if (U[P] < U[count]) return U;
    }
}

template <class P>
BSpline<P> random_spline(std::mt19937& rng, int kind) {
    const int p = 1 + static_cast<int>(uniform(rng, 0, 5));
    const std::size_t count = static_cast<std::size_t>(p) + 1 + static_cast<std::size_t>(uniform(rng, 0, 8));
    auto pts = random_points<P>(rng, count);
    switch (kind % 4) {
        case 0: return BSpline<P>::clamped(p, pts);
        case 1: return BSpline<P>::uniform(p, pts);
        case 2: return BSpline<P>::periodic(p, pts);
        default: return BSpline<P>(p, pts, random_knots(rng, p, count, kind % 8 == 3));
    }
}

}  // namespace

// ---- basis functions ----------------------------------------------------------------------------

TEST_CASE("B-spline basis: knot vector builders", "[spline]") {
    CHECK(clamped_knots(3, 7) == std::vector<double>{0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1});
    CHECK(clamped_knots(2, 3) == std::vector<double>{0, 0, 0, 1, 1, 1});
    CHECK(uniform_knots(2, 4) == std::vector<double>{0, 1, 2, 3, 4, 5, 6});
}

TEST_CASE("B-spline basis: the uniform cubic at a knot and mid-span", "[spline]") {
    const auto U = uniform_knots(3, 4);  // 0..7, domain [3, 4]
    const auto at3 = bspline_basis_all(3, U, 3.0);
    CHECK(at3[0] == Approx(1.0 / 6));
    CHECK(at3[1] == Approx(2.0 / 3));
    CHECK(at3[2] == Approx(1.0 / 6));
    CHECK(at3[3] == 0);
    const auto mid = bspline_basis_all(3, U, 3.5);
    CHECK(mid[0] == Approx(1.0 / 48).epsilon(1e-14));
    CHECK(mid[1] == Approx(23.0 / 48).epsilon(1e-14));
    CHECK(mid[2] == Approx(23.0 / 48).epsilon(1e-14));
    CHECK(mid[3] == Approx(1.0 / 48).epsilon(1e-14));
    // The domain end belongs to the last span.
    const auto at4 = bspline_basis_all(3, U, 4.0);
    CHECK(at4[3] == Approx(1.0 / 6));
    // Clamped quadratic on [0, 1] with one span: the Bernstein basis.
    const auto B = bspline_basis_all(2, std::vector<double>{0, 0, 0, 1, 1, 1}, 0.25);
    CHECK(B[0] == Approx(0.5625));
    CHECK(B[1] == Approx(0.375));
    CHECK(B[2] == Approx(0.0625));
}

TEST_CASE("B-spline basis: partition of unity, non-negativity, local support, agreement with the recursion",
          "[spline]") {
    std::mt19937 rng(101);
    for (int rep = 0; rep < 300; ++rep) {
        const int p = rep % 6;  // degrees 0..5
        const std::size_t count = static_cast<std::size_t>(p) + 2 + static_cast<std::size_t>(uniform(rng, 0, 8));
        std::vector<double> U;
        switch (rep % 3) {
            case 0: U = clamped_knots(p, count); break;
            case 1: U = uniform_knots(p, count); break;
            default: U = random_knots(rng, std::max(p, 1), count, rep % 2 == 0); break;
        }
        if (p == 0) {  // multiplicity at most 1 for degree 0
            U = uniform_knots(0, count);
        }
        const double a = U[static_cast<std::size_t>(p)], b = U[count];
        for (int k = 0; k < 10; ++k) {
            const double t = k == 0 ? a : k == 1 ? b : uniform(rng, a, b);
            const auto N = bspline_basis_all(p, U, t);
            REQUIRE(N.size() == count);
            double sum = 0;
            for (std::size_t i = 0; i < count; ++i) {
                CHECK(N[i] >= 0);
                sum += N[i];
                // Local support: N_i vanishes outside [u_i, u_(i+p+1)].
                if (t < U[i] || t > U[i + static_cast<std::size_t>(p) + 1]) CHECK(N[i] == 0);
                if (p <= 4 && t < b) CHECK(N[i] == Approx(naive_basis(static_cast<int>(i), p, U, t)).margin(1e-13));
                CHECK(bspline_basis(static_cast<int>(i), p, U, t) == N[i]);
            }
            CHECK(sum == Approx(1.0).margin(1e-13));
        }
    }
}

// ---- curves -------------------------------------------------------------------------------------

TEST_CASE("B-spline: de Boor equals the basis-function sum, clamped ends interpolate", "[spline]") {
    std::mt19937 rng(102);
    for (int rep = 0; rep < 200; ++rep) {
        const auto s = random_spline<Point>(rng, rep);
        const double a = s.domain_start(), b = s.domain_end();
        const double scale = max_norm(std::vector<Point>(s.points().begin(), s.points().end()));
        for (int k = 0; k < 10; ++k) {
            const double t = uniform(rng, a, b);
            const auto N = bspline_basis_all(s.degree(), s.knots(), t);
            Point sum{};
            for (std::size_t i = 0; i < N.size(); ++i) sum += s.points()[i] * N[i];
            CHECK(dist(sum, s.eval(t)) <= 1e-12 * scale);
        }
        if (rep % 4 == 0) {
            CHECK(dist(s.eval(a), s.points().front()) <= 1e-12 * scale);
            CHECK(dist(s.eval(b), s.points().back()) <= 1e-12 * scale);
            // End tangent p / (u_(p+1) - u_1) (P_1 - P_0).
            const auto U = s.knots();
            const auto p = static_cast<std::size_t>(s.degree());
            const Point expect = (s.points()[1] - s.points()[0]) * (static_cast<double>(p) / (U[p + 1] - U[1]));
            CHECK(dist(s.derivative(1, a), expect) <= 1e-9 * (1 + expect.length()));
        }
    }
}

TEST_CASE("B-spline: strong convex hull: a point in span k lies in the hull of P_(k-p)..P_k", "[spline]") {
    std::mt19937 rng(103);
    for (int rep = 0; rep < 200; ++rep) {
        const auto s = random_spline<Point>(rng, rep);
        for (int k = 0; k < 10; ++k) {
            const double t = uniform(rng, s.domain_start(), s.domain_end());
            const std::size_t span = s.span_index(t);
            const std::vector<Point> local(s.points().begin() + static_cast<std::ptrdiff_t>(span) - s.degree(),
                                           s.points().begin() + static_cast<std::ptrdiff_t>(span) + 1);
            CHECK(in_convex_hull(local, s.eval(t), 1e-9));
        }
    }
}

TEST_CASE("B-spline: derivatives match finite differences", "[spline]") {
    std::mt19937 rng(104);
    for (int rep = 0; rep < 200; ++rep) {
        const auto s = random_spline<Point3>(rng, rep);
        const auto bp = s.breakpoints();
        // Inside a span, away from knots.
        const std::size_t j = static_cast<std::size_t>(uniform(rng, 0, static_cast<double>(bp.size() - 1)));
        const double lo = bp[j], hi = bp[j + 1];
        const double t = lo + (hi - lo) * uniform(rng, 0.2, 0.8);
        const double h = 1e-6 * (hi - lo);
        for (int k = 1; k <= s.degree(); ++k) {
            const Point3 fd = (s.derivative(k - 1, t + h) - s.derivative(k - 1, t - h)) / (2 * h);
            const Point3 d = s.derivative(k, t);
            INFO("degree " << s.degree() << " order " << k);
            CHECK(dist(fd, d) <= 1e-4 * (1 + d.length() + s.derivative(k - 1, t).length() / (hi - lo)));
        }
        CHECK(s.derivative(s.degree() + 1, t) == Point3{});
    }
}

TEST_CASE("B-spline: Boehm knot insertion leaves the curve unchanged", "[spline]") {
    std::mt19937 rng(105);
    for (int rep = 0; rep < 200; ++rep) {
        auto s = random_spline<Point>(rng, rep);
        const double a = s.domain_start(), b = s.domain_end();
        const double scale = max_norm(std::vector<Point>(s.points().begin(), s.points().end()));
        const auto original = s;
        for (int ins = 0; ins < 3; ++ins) {
            const double u = ins == 2 ? a : uniform(rng, a, b);
            const int mult = static_cast<int>(std::count(s.knots().begin(), s.knots().end(), u));
            if (mult + 1 > s.degree() + 1) continue;
            s = s.with_knot(u);
        }
        CHECK(s.points().size() >= original.points().size());
        for (int k = 0; k <= 40; ++k) {
            const double t = k == 40 ? b : a + (b - a) * k / 40.0;
            CHECK(dist(s.eval(t), original.eval(t)) <= 1e-12 * scale);
        }
    }
}

TEST_CASE("B-spline: conversion to Bezier pieces reproduces the curve to 1e-12", "[spline]") {
    std::mt19937 rng(106);
    for (int rep = 0; rep < 300; ++rep) {
        const auto s = rep % 2 ? random_spline<Point>(rng, rep / 2) : random_spline<Point>(rng, 3);
        const auto pieces = s.to_bezier();
        const auto bp = s.breakpoints();
        REQUIRE(pieces.size() + 1 == bp.size());
        const double scale = max_norm(std::vector<Point>(s.points().begin(), s.points().end()));
        for (std::size_t j = 0; j < pieces.size(); ++j) {
            CHECK(pieces[j].degree() == s.degree());
            for (int k = 0; k <= 10; ++k) {
                const double u = k / 10.0;
                const double t = k == 10 ? bp[j + 1] : bp[j] + (bp[j + 1] - bp[j]) * u;
                CHECK(dist(pieces[j].eval(u), s.eval(t)) <= 1e-12 * scale);
            }
        }
    }
}

TEST_CASE("B-spline: Bezier extraction equals Boehm insertion to multiplicity p (clamped)", "[spline]") {
    std::mt19937 rng(107);
    for (int rep = 0; rep < 50; ++rep) {
        const int p = 1 + rep % 4;
        const std::size_t count = static_cast<std::size_t>(p) + 1 + static_cast<std::size_t>(rep % 5);
        auto s = BSpline<Point>(p, random_points<Point>(rng, count), random_knots(rng, p, count, true));
        const auto pieces = s.to_bezier();
        const auto bp = s.breakpoints();
        for (std::size_t j = 1; j + 1 < bp.size(); ++j) {
            const int mult = static_cast<int>(std::count(s.knots().begin(), s.knots().end(), bp[j]));
            if (mult < p) s = s.with_knot(bp[j], p - mult);
        }
        // Now the control polygon is the Bézier pieces end to end.
        REQUIRE(s.points().size() == pieces.size() * static_cast<std::size_t>(p) + 1);
        for (std::size_t j = 0; j < pieces.size(); ++j)
            for (std::size_t i = 0; i <= static_cast<std::size_t>(p); ++i)
                CHECK(dist(pieces[j][i], s.points()[j * static_cast<std::size_t>(p) + i]) <= 1e-9);
    }
}

TEST_CASE("B-spline: the uniform cubic <-> Bezier matrices", "[spline]") {
    const auto M = uniform_cubic_bspline_to_bezier_matrix(), Mi = bezier_to_uniform_cubic_bspline_matrix();
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c) {
            double v = 0;
            for (std::size_t k = 0; k < 4; ++k) v += M[r * 4 + k] * Mi[k * 4 + c];
            CHECK(v == Approx(r == c ? 1.0 : 0.0).margin(1e-15));
        }
    std::mt19937 rng(108);
    for (int rep = 0; rep < 50; ++rep) {
        const auto pts = random_points<Point>(rng, 4 + static_cast<std::size_t>(rep % 5));
        const auto s = BSpline<Point>::uniform(3, pts);
        const auto pieces = s.to_bezier();
        for (std::size_t j = 0; j < pieces.size(); ++j) {
            const std::array<Point, 4> d = {pts[j], pts[j + 1], pts[j + 2], pts[j + 3]};
            const auto b = uniform_cubic_bspline_to_bezier(d);
            for (std::size_t i = 0; i < 4; ++i) CHECK(dist(b[i], pieces[j][i]) <= 1e-12 * max_norm(pts));
            const auto back = bezier_to_uniform_cubic_bspline(b);
            for (std::size_t i = 0; i < 4; ++i) CHECK(dist(back[i], d[i]) <= 1e-12 * max_norm(pts));
        }
    }
    const std::array<Point, 4> d = {Point{0, 0}, Point{6, 0}, Point{6, 6}, Point{0, 6}};
    const auto b = uniform_cubic_bspline_to_bezier(d);
    CHECK(dist(b[0], Point{5, 1}) <= 1e-14);  // (D0 + 4 D1 + D2) / 6
    CHECK(dist(b[1], Point{6, 2}) <= 1e-14);  // (2 D1 + D2) / 3
    CHECK(dist(b[2], Point{6, 4}) <= 1e-14);
    CHECK(dist(b[3], Point{5, 5}) <= 1e-14);
}

TEST_CASE("B-spline: periodic splines close with C^(p-1) continuity", "[spline]") {
    std::mt19937 rng(109);
    for (int p = 1; p <= 5; ++p) {
        const auto pts = random_points<Point>(rng, 7);
        const auto s = BSpline<Point>::periodic(p, pts);
        const double a = s.domain_start(), b = s.domain_end();
        CHECK(b - a == 7);
        for (int k = 0; k < p; ++k)
            CHECK(dist(s.derivative(k, a), s.derivative(k, b)) <= 1e-9 * (1 + s.derivative(k, a).length()));
    }
}

TEST_CASE("B-spline: knot multiplicity p passes through a control point, p + 1 breaks the curve", "[spline]") {
    const std::vector<Point> pts = {{0, 0}, {10, 20}, {20, 0}, {30, 20}, {40, 0}, {50, 20}, {60, 0}};
    // Quadratic, interior knot 0.5 of multiplicity 2 = p: the curve passes through P_3 at t = 0.5.
    const BSpline<Point> s(2, pts, {0, 0, 0, 0.25, 0.5, 0.5, 0.75, 1, 1, 1});
    CHECK(dist(s.eval(0.5), pts[3]) <= 1e-12);
    // Cubic with knot 0.5 of multiplicity 4 = p + 1: left and right limits differ.
    std::vector<Point> eight = pts;
    eight.push_back({70, 20});
    const BSpline<Point> c(3, eight, {0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1});
    CHECK(dist(c.eval(0.5), eight[4]) <= 1e-12);         // the right piece starts at P_4
    CHECK(dist(c.eval(0.5 - 1e-12), eight[3]) <= 1e-9);  // the left piece ends at P_3
    CHECK(c.to_bezier().size() == 2);
}

TEST_CASE("B-spline: to Path is exact for cubics", "[spline]") {
    const auto s = BSpline<Point>::clamped(3, {{0, 0}, {10, 30}, {30, 30}, {40, 0}, {60, 10}});
    const Path p = to_path(s);
    CHECK(p.contour_count() == 1);
    CHECK(p.verbs().size() == 3);  // move + 2 cubics
    CHECK(p.verbs()[1] == Verb::Cubic);
    CHECK(p.points().back() == Point{60, 10});
    // Random splines stay one contour (piece ends are shared exactly).
    std::mt19937 rng(114);
    for (int rep = 0; rep < 50; ++rep) {
        const auto r = BSpline<Point>(3, random_points<Point>(rng, 12), random_knots(rng, 3, 12, rep % 2 == 0));
        CHECK(to_path(r).contour_count() == 1);
    }
}

// ---- interpolating splines ----------------------------------------------------------------------

TEST_CASE("Hermite: the Mh basis and the Bezier form agree", "[spline]") {
    std::mt19937 rng(110);
    for (int rep = 0; rep < 100; ++rep) {
        const Point p0 = random_point<Point>(rng), p1 = random_point<Point>(rng);
        const Point m0 = random_point<Point>(rng), m1 = random_point<Point>(rng);
        const Bezier<Point> b = hermite_to_bezier(p0, m0, p1, m1);
        for (int k = 0; k <= 10; ++k)
            CHECK(dist(hermite_eval(p0, m0, p1, m1, k / 10.0), b.eval(k / 10.0)) <= 1e-12 * 300);
        CHECK(dist(b.derivative(1, 0), m0) <= 1e-12 * 300);
        CHECK(dist(b.derivative(1, 1), m1) <= 1e-12 * 300);
    }
    const std::vector<Point> pts = {{0, 0}, {10, 0}, {20, 10}}, tans = {{10, 0}, {10, 10}, {0, 10}};
    const auto h = hermite_spline<Point>(pts, tans);
    REQUIRE(h.size() == 2);
    CHECK(join_continuity(h[0], h[1]) == Continuity::G1);
    CHECK(dist(h[1].derivative(1, 0), Point{10, 10}) <= 1e-12);
}

TEST_CASE("Cardinal and Catmull-Rom: through the points with the textbook tangents", "[spline]") {
    std::mt19937 rng(111);
    for (int rep = 0; rep < 50; ++rep) {
        const auto pts = random_points<Point>(rng, 3 + static_cast<std::size_t>(rep % 6));
        const double tension = uniform(rng, -0.5, 0.9);
        const auto c = cardinal_spline<Point>(pts, tension);
        REQUIRE(c.size() == pts.size() - 1);
        for (std::size_t i = 0; i < c.size(); ++i) {
            CHECK(c[i].front() == pts[i]);
            CHECK(c[i].back() == pts[i + 1]);
            if (i > 0) {
                const Point m = (pts[i + 1] - pts[i - 1]) * ((1 - tension) / 2);
                CHECK(dist(c[i].derivative(1, 0), m) <= 1e-11 * 300);
                CHECK(dist(c[i - 1].derivative(1, 1), m) <= 1e-11 * 300);
                CHECK(join_continuity(c[i - 1], c[i]) >= Continuity::G1);
            }
        }
        // Catmull-Rom is tension 0.
        const auto cr = catmull_rom_spline<Point>(pts), c0 = cardinal_spline<Point>(pts, 0.0);
        for (std::size_t i = 0; i < cr.size(); ++i) CHECK(cr[i] == c0[i]);
        // Closed: one more piece, back to the start, smooth at the seam.
        const auto closed = catmull_rom_spline<Point>(pts, EndCondition::Closed);
        REQUIRE(closed.size() == pts.size());
        CHECK(closed.back().back() == pts.front());
        CHECK(join_continuity(closed.back(), closed.front()) >= Continuity::G1);
    }
    // Inner: 4 points give the one piece from P1 to P2.
    const std::vector<Point> four = {{0, 0}, {10, 10}, {20, 10}, {30, 0}};
    const auto inner = catmull_rom_spline<Point>(four, EndCondition::Inner);
    REQUIRE(inner.size() == 1);
    CHECK(inner[0].front() == Point{10, 10});
    CHECK(inner[0].back() == Point{20, 10});
    CHECK(dist(inner[0][1], Point{10 + 20.0 / 6, 10 + 10.0 / 6}) <= 1e-12);  // P1 + (P2 - P0)/6
    // Tension 1: straight pieces.
    const auto lines = cardinal_spline<Point>(four, 1.0);
    for (const auto& b : lines) CHECK(b[1] == b.front());
}

TEST_CASE("Kochanek-Bartels: reduces to Catmull-Rom and Cardinal, continuity -1 gives corners", "[spline]") {
    std::mt19937 rng(112);
    for (int rep = 0; rep < 30; ++rep) {
        const auto pts = random_points<Point>(rng, 4 + static_cast<std::size_t>(rep % 5));
        const auto kb0 = kochanek_bartels_spline<Point>(pts, {});
        const auto cr = catmull_rom_spline<Point>(pts);
        for (std::size_t i = 0; i < cr.size(); ++i)
            for (std::size_t j = 0; j < 4; ++j) CHECK(dist(kb0[i][j], cr[i][j]) <= 1e-12 * 300);
        const double t = uniform(rng, -0.5, 0.9);
        const auto kbt = kochanek_bartels_spline<Point>(pts, {t, 0, 0});
        const auto card = cardinal_spline<Point>(pts, t);
        for (std::size_t i = 0; i < card.size(); ++i)
            for (std::size_t j = 0; j < 4; ++j) CHECK(dist(kbt[i][j], card[i][j]) <= 1e-12 * 300);
        // Bias keeps C1 (both tangents equal), continuity != 0 breaks it.
        const auto biased = kochanek_bartels_spline<Point>(pts, {0, 0, 0.4});
        for (std::size_t i = 1; i < biased.size(); ++i)
            CHECK(dist(biased[i - 1].derivative(1, 1), biased[i].derivative(1, 0)) <= 1e-10 * 300);
        const auto kinked = kochanek_bartels_spline<Point>(pts, {0, 0.5, 0});
        int kinks = 0;
        for (std::size_t i = 1; i < kinked.size(); ++i)
            kinks += join_continuity(kinked[i - 1], kinked[i]) == Continuity::G0;
        CHECK(kinks > 0);
        // c = -1: each piece is its chord (box corners).
        const auto box = kochanek_bartels_spline<Point>(pts, {0, -1, 0});
        for (const auto& b : box) {
            const Point chord = b.back() - b.front();
            CHECK(std::abs(chord.cross(b[1] - b.front())) <= 1e-9 * chord.dot(chord));
            CHECK(std::abs(chord.cross(b[2] - b.front())) <= 1e-9 * chord.dot(chord));
        }
    }
}

TEST_CASE("Natural cubic spline: through the points, C2, zero curvature at the ends", "[spline]") {
    std::mt19937 rng(113);
    for (Parametrization param :
         {Parametrization::Uniform, Parametrization::ChordLength, Parametrization::Centripetal}) {
        for (int rep = 0; rep < 30; ++rep) {
            const auto pts = random_points<Point3>(rng, 2 + static_cast<std::size_t>(rep % 9));
            const auto s = natural_spline<Point3>(pts, param);
            REQUIRE(s.size() == pts.size() - 1);
            std::vector<double> h;
            for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
                const double d = (pts[i + 1] - pts[i]).length();
                h.push_back(param == Parametrization::Uniform       ? 1
                            : param == Parametrization::ChordLength ? d
                                                                    : std::sqrt(d));
            }
            for (std::size_t i = 0; i < s.size(); ++i) {
                CHECK(s[i].front() == pts[i]);
                CHECK(s[i].back() == pts[i + 1]);
                if (i > 0) {
                    // d/ds = (d/dt) / h, d2/ds2 = (d2/dt2) / h^2 in the global parameter s.
                    const Point3 d1a = s[i - 1].derivative(1, 1) / h[i - 1], d1b = s[i].derivative(1, 0) / h[i];
                    const Point3 d2a = s[i - 1].derivative(2, 1) / (h[i - 1] * h[i - 1]);
                    const Point3 d2b = s[i].derivative(2, 0) / (h[i] * h[i]);
                    CHECK(dist(d1a, d1b) <= 1e-9 * (1 + d1a.length()));
                    CHECK(dist(d2a, d2b) <= 1e-9 * (1 + d2a.length()));
                    CHECK(join_continuity(s[i - 1], s[i], {1e-9, 1e-7, 1e-7}) == Continuity::G2);
                }
            }
            CHECK(s.front().derivative(2, 0).length() <= 1e-9 * 300);
            CHECK(s.back().derivative(2, 1).length() <= 1e-9 * 300);
        }
    }
    // Equally spaced collinear points: the straight line at uniform speed.
    const std::vector<Point> line = {{0, 0}, {1, 2}, {2, 4}, {3, 6}};
    for (const auto& b : natural_spline<Point>(line)) {
        CHECK(dist(b[1], b.front() + (b.back() - b.front()) / 3.0) <= 1e-12);
        CHECK(dist(b[2], b.front() + (b.back() - b.front()) * (2.0 / 3)) <= 1e-12);
    }
    // Two points: a line.
    const auto two = natural_spline<Point>(std::vector<Point>{{0, 0}, {3, 3}});
    REQUIRE(two.size() == 1);
    CHECK(two[0][1] == Point{1, 1});
    // As a Path: one contour of cubics.
    const std::vector<Point> zig = {{0, 0}, {10, 10}, {20, 0}, {30, 10}};
    const auto pieces = natural_spline<Point>(zig);
    const Path p = to_path(std::span<const Bezier<Point>>(pieces));
    CHECK(p.contour_count() == 1);
    CHECK(p.verbs().size() == 4);
}

// ---- bad input ----------------------------------------------------------------------------------

TEST_CASE("Splines: bad input gives clear errors", "[spline]") {
    const std::vector<Point> four = {{0, 0}, {1, 1}, {2, 0}, {3, 1}};
    const std::vector<Point> one = {{0, 0}};
    // Fewer than 2 points.
    CHECK(kind_of([&] { BSpline<Point>::clamped(1, one); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { BSpline<Point>::periodic(1, one); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { natural_spline<Point>(one); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { catmull_rom_spline<Point>(one); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { hermite_spline<Point>(one, one); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] {
              catmull_rom_spline<Point>(std::vector<Point>{{0, 0}, {1, 1}, {2, 2}}, EndCondition::Inner);
          }) == ErrorKind::InvalidData);
    // Too few control points for the degree.
    CHECK(kind_of([&] { BSpline<Point>::clamped(4, four); }) == ErrorKind::InvalidData);
    CHECK_THROWS_WITH(BSpline<Point>::clamped(4, four), "a degree-4 B-spline needs at least 5 control points, got 4");
    // Knot vector length mismatch.
    CHECK(kind_of([&] { BSpline<Point>(2, four, {0, 0, 0, 1, 1, 1}); }) == ErrorKind::InvalidData);
    CHECK_THROWS_WITH(BSpline<Point>(2, four, {0, 0, 0, 1, 1, 1}),
                      "knot vector has 6 knots; 4 control points of degree 2 need 7");
    // Decreasing knots.
    CHECK(kind_of([&] { BSpline<Point>(2, four, {0, 0, 0, 0.7, 0.5, 1, 1}); }) == ErrorKind::InvalidData);
    CHECK_THROWS_WITH(BSpline<Point>(2, four, {0, 0, 0, 0.7, 0.5, 1, 1}),
                      "knots must be non-decreasing: knot 4 = 0.5 follows 0.69999999999999996");
    CHECK(kind_of([&] { BSpline<Point>(2, four, {0, 0, 0, NAN, 1, 1, 1}); }) == ErrorKind::InvalidData);
    // Multiplicity above p + 1, empty domain.
    CHECK(kind_of([&] { BSpline<Point>(1, four, {0, 0, 0, 1, 1, 1}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { BSpline<Point>(2, four, {0, 0, 1, 1, 2, 2, 2}); }) == ErrorKind::Io);  // valid: domain [1, 2]
    CHECK(kind_of([&] { BSpline<Point>(2, four, {0, 0, 1, 1, 1, 2, 2}); }) == ErrorKind::InvalidData);  // empty domain
    CHECK(kind_of([&] {
              BSpline<Point>(1, std::vector<Point>{{0, 0}, {1, 1}}, {0, 1, 1, 2});
          }) == ErrorKind::InvalidData);
    // Degree 0 and absurd degrees.
    CHECK(kind_of([&] { BSpline<Point>::clamped(0, four); }) == ErrorKind::InvalidArgument);
    CHECK_THROWS_WITH(BSpline<Point>::clamped(0, four), "B-spline degree must be at least 1, got 0");
    CHECK(kind_of([&] { BSpline<Point>::clamped(1000, std::vector<Point>(1001)); }) == ErrorKind::Limit);
    CHECK(kind_of([&] { BSpline<Point>::uniform(65, std::vector<Point>(70)); }) == ErrorKind::Limit);
    CHECK(kind_of([&] { clamped_knots(-1, 4); }) == ErrorKind::InvalidArgument);
    // Parameters outside the domain.
    const auto s = BSpline<Point>::clamped(2, four);
    CHECK(kind_of([&] { s.eval(-0.01); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { s.eval(1.01); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { s.eval(NAN); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { bspline_basis_all(2, s.knots(), 2.0); }) == ErrorKind::InvalidArgument);
    const auto u = BSpline<Point>::uniform(2, four);  // domain [2, 4]
    CHECK(kind_of([&] { u.eval(1.0); }) == ErrorKind::InvalidArgument);
    CHECK_THROWS_WITH(u.eval(1.0), "t = 1 is outside [2, 4]");
    // Knot insertion beyond multiplicity p + 1 or outside the domain.
    CHECK(kind_of([&] { s.with_knot(0.0); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { s.with_knot(0.5, 4); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { s.with_knot(1.5); }) == ErrorKind::InvalidArgument);
    // Non-finite points and parameters.
    CHECK(kind_of([&] { BSpline<Point>::clamped(1, {{0, 0}, {INFINITY, 0}}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { cardinal_spline<Point>(four, NAN); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { hermite_spline<Point>(four, std::vector<Point>{{1, 0}}); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] {
              natural_spline<Point>(std::vector<Point>{{0, 0}, {0, 0}, {1, 1}}, Parametrization::ChordLength);
          }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { hermite_eval(Point{}, Point{}, Point{}, Point{}, 2.0); }) == ErrorKind::InvalidArgument);
    // Regression: an overflowing construction names the spline, not an internal Bézier point.
    CHECK_THROWS_WITH(natural_spline<Point>(std::vector<Point>{{0, 0}, {1e308, 0}, {-1e308, 0}}),
                      "natural spline: coordinates too large (the construction overflows)");
    CHECK(kind_of([&] {
              catmull_rom_spline<Point>(std::vector<Point>{{-1e308, 0}, {1e308, 0}, {-1e308, 0}});
          }) == ErrorKind::InvalidData);
}
