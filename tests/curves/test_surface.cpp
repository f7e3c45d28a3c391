// Tests for surfaces (include/casteljau/surface.hpp): Bézier patches (de Casteljau in u then v, the
// bicubic matrix form, derivatives, twist, normals), B-spline and NURBS surfaces, projections, iso
// grids, shaded quads and bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "casteljau/surface.hpp"
#include "curve_test_util.hpp"

using namespace casteljau;
using namespace curve_test;

namespace {

template <class P>
P tensor_sum(const BezierPatch<P>& s, double u, double v) {
    P acc{};
    for (int i = 0; i <= s.degree_u(); ++i)
        for (int j = 0; j <= s.degree_v(); ++j)
            acc += s.at(i, j) * (bernstein(i, s.degree_u(), u) * bernstein(j, s.degree_v(), v));
    return acc;
}

BezierPatch<Point3> random_patch(std::mt19937& rng, int m, int n) {
    return BezierPatch<Point3>(m, n, random_points<Point3>(rng, static_cast<std::size_t>((m + 1) * (n + 1))));
}

// A NURBS cylinder of radius r and height h around the z axis: the 9-point circle in u, linear in v.
NurbsSurface<Point3> cylinder(double r, double h) {
    const Nurbs<Point> c = nurbs_circle({0, 0}, r);
    std::vector<Point3> net;
    std::vector<double> w;
    for (std::size_t i = 0; i < c.points().size(); ++i) {
        for (double z : {0.0, h}) {
            net.push_back({c.points()[i].x, c.points()[i].y, z});
            w.push_back(c.weights()[i]);
        }
    }
    return NurbsSurface<Point3>(2, 1, c.points().size(), 2, net, w,
                                std::vector<double>(c.knots().begin(), c.knots().end()), {0, 0, 1, 1});
}

}  // namespace

TEST_CASE("Bezier patch: de Casteljau in u then v, the tensor sum and the bicubic matrix form agree", "[surface]") {
    std::mt19937 rng(301);
    for (int rep = 0; rep < 100; ++rep) {
        const BezierPatch<Point3> s = random_patch(rng, 3, 3);
        // The transposed net: u and v swap roles.
        std::vector<Point3> tnet;
        for (int j = 0; j <= 3; ++j)
            for (int i = 0; i <= 3; ++i) tnet.push_back(s.at(i, j));
        const BezierPatch<Point3> t(3, 3, tnet);
        const double scale = max_norm(std::vector<Point3>(s.net().begin(), s.net().end()));
        for (int k = 0; k < 10; ++k) {
            const double u = uniform(rng, 0, 1), v = uniform(rng, 0, 1);
            const Point3 p = s.eval(u, v);
            CHECK(dist(p, s.eval_matrix(u, v)) <= 1e-12 * scale);
            CHECK(dist(p, tensor_sum(s, u, v)) <= 1e-12 * scale);
            CHECK(dist(p, t.eval(v, u)) <= 1e-12 * scale);  // v then u
            CHECK(dist(p, s.iso_u(u).eval(v)) <= 1e-12 * scale);
            CHECK(dist(p, s.iso_v(v).eval(u)) <= 1e-12 * scale);
        }
        CHECK(s.eval(0, 0) == s.at(0, 0));
        CHECK(s.eval(1, 0) == s.at(3, 0));
        CHECK(s.eval(0, 1) == s.at(0, 3));
        CHECK(s.eval(1, 1) == s.at(3, 3));
    }
    CHECK(bezier_cubic_matrix() == std::array<double, 16>{-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0});
}

TEST_CASE("Bezier patch: any m x n degree, boundary curves are the net's edges", "[surface]") {
    std::mt19937 rng(302);
    for (int rep = 0; rep < 60; ++rep) {
        const int m = 1 + rep % 6, n = 1 + (rep / 6) % 5;
        const BezierPatch<Point3> s = random_patch(rng, m, n);
        const double scale = max_norm(std::vector<Point3>(s.net().begin(), s.net().end()));
        for (int k = 0; k < 5; ++k) {
            const double u = uniform(rng, 0, 1), v = uniform(rng, 0, 1);
            CHECK(dist(s.eval(u, v), tensor_sum(s, u, v)) <= 1e-12 * scale);
        }
        const Bezier<Point3> edge = s.iso_u(0);
        for (int j = 0; j <= n; ++j) CHECK(edge[static_cast<std::size_t>(j)] == s.at(0, j));
        const Bezier<Point3> edge2 = s.iso_v(1);
        for (int i = 0; i <= m; ++i) CHECK(edge2[static_cast<std::size_t>(i)] == s.at(i, n));
        // Convex hull: inside the control box.
        CHECK(s.control_bounds().contains(s.eval(uniform(rng, 0, 1), uniform(rng, 0, 1)), 1e-9));
    }
    // 2-D patches work too.
    const BezierPatch<Point> flat(1, 1, {{0, 0}, {0, 10}, {10, 0}, {10, 10}});
    CHECK(flat.eval(0.25, 0.5) == Point{2.5, 5});
}

TEST_CASE("Bezier patch: partial derivatives and twist match finite differences", "[surface]") {
    std::mt19937 rng(303);
    for (int rep = 0; rep < 60; ++rep) {
        const int m = 2 + rep % 4, n = 1 + (rep / 4) % 4;
        const BezierPatch<Point3> s = random_patch(rng, m, n);
        const double u = uniform(rng, 0.1, 0.9), v = uniform(rng, 0.1, 0.9), h = 1e-6;
        const Point3 fu = (s.eval(u + h, v) - s.eval(u - h, v)) / (2 * h);
        const Point3 fv = (s.eval(u, v + h) - s.eval(u, v - h)) / (2 * h);
        const Point3 fuv = (s.du(u, v + h) - s.du(u, v - h)) / (2 * h);
        CHECK(dist(fu, s.du(u, v)) <= 1e-5 * (1 + fu.length()));
        CHECK(dist(fv, s.dv(u, v)) <= 1e-5 * (1 + fv.length()));
        CHECK(dist(fuv, s.twist(u, v)) <= 1e-5 * (1 + fuv.length()));
        const Point3 fuu = (s.du(u + h, v) - s.du(u - h, v)) / (2 * h);
        CHECK(dist(fuu, s.derivative(2, 0, u, v)) <= 1e-5 * (1 + fuu.length()));
        // Corner tangents: P_u(0,0) = m (P_10 - P_00), twist(0,0) = m n (P_11 - P_10 - P_01 + P_00).
        CHECK(dist(s.du(0, 0), (s.at(1, 0) - s.at(0, 0)) * m) <= 1e-12 * 300 * m);
        const Point3 tw = (s.at(1, 1) - s.at(1, 0) - s.at(0, 1) + s.at(0, 0)) * (m * n);
        CHECK(dist(s.twist(0, 0), tw) <= 1e-12 * 600 * m * n);
        CHECK(s.derivative(m + 1, 0, u, v) == Point3{});
    }
}

TEST_CASE("Surface normals: flat, cylindrical, degenerate", "[surface]") {
    // A bilinear patch in the plane z = 5: normal (0, 0, 1) (u along x, v along y).
    const BezierPatch<Point3> flat(1, 1, {{0, 0, 5}, {0, 10, 5}, {10, 0, 5}, {10, 10, 5}});
    CHECK(dist(normal(flat, 0.3, 0.7), Point3{0, 0, 1}) <= 1e-15);
    // The NURBS cylinder: normals are radial.
    const auto cyl = cylinder(3, 4);
    for (int k = 0; k <= 20; ++k) {
        const double u = k / 20.0;
        const Point3 p = cyl.eval(u, 0.5);
        const Point3 radial = Point3{p.x, p.y, 0} / std::hypot(p.x, p.y);
        const Point3 n = normal(cyl, u, 0.5);
        CHECK(std::abs(std::abs(n.dot(radial)) - 1) <= 1e-12);
    }
    // A patch with a collapsed edge (all P_0j equal): the normal is still defined at u = 0.
    const BezierPatch<Point3> cone(1, 1, {{0, 0, 10}, {0, 0, 10}, {10, 0, 0}, {0, 10, 0}});
    const Point3 n = normal(cone, 0, 0.5);
    CHECK(n.length() == Approx(1).epsilon(1e-12));
}

TEST_CASE("B-spline surface: tensor-product basis sum, iso curves, derivatives, single span equals the Bezier patch",
          "[surface]") {
    std::mt19937 rng(304);
    for (int rep = 0; rep < 40; ++rep) {
        const int pu = 1 + rep % 3, pv = 1 + (rep / 3) % 3;
        const std::size_t nu = static_cast<std::size_t>(pu) + 1 + static_cast<std::size_t>(rep % 4);
        const std::size_t nv = static_cast<std::size_t>(pv) + 1 + static_cast<std::size_t>(rep % 3);
        const auto net = random_points<Point3>(rng, nu * nv);
        const auto s = rep % 2
                           ? BSplineSurface<Point3>::clamped(pu, pv, nu, nv, net)
                           : BSplineSurface<Point3>(pu, pv, nu, nv, net, uniform_knots(pu, nu), uniform_knots(pv, nv));
        const double scale = max_norm(net);
        for (int k = 0; k < 8; ++k) {
            const double u = uniform(rng, s.u_start(), s.u_end()), v = uniform(rng, s.v_start(), s.v_end());
            const auto Nu = bspline_basis_all(pu, s.knots_u(), u), Nv = bspline_basis_all(pv, s.knots_v(), v);
            Point3 acc{};
            for (std::size_t i = 0; i < nu; ++i)
                for (std::size_t j = 0; j < nv; ++j) acc += net[i * nv + j] * (Nu[i] * Nv[j]);
            const Point3 p = s.eval(u, v);
            CHECK(dist(p, acc) <= 1e-12 * scale);
            CHECK(dist(p, s.iso_u(u).eval(v)) <= 1e-12 * scale);
            CHECK(dist(p, s.iso_v(v).eval(u)) <= 1e-12 * scale);
            const double h = 1e-6;
            if (u - h > s.u_start() && u + h < s.u_end()) {
                const Point3 fu = (s.eval(u + h, v) - s.eval(u - h, v)) / (2 * h);
                CHECK(dist(fu, s.du(u, v)) <= 1e-4 * (1 + fu.length()));
                CHECK(dist(s.iso_v(v).derivative(1, u), s.du(u, v)) <= 1e-9 * (1 + fu.length()));
            }
            if (v - h > s.v_start() && v + h < s.v_end() && u - h > s.u_start() && u + h < s.u_end()) {
                const Point3 fuv = (s.du(u, v + h) - s.du(u, v - h)) / (2 * h);
                CHECK(dist(fuv, s.twist(u, v)) <= 1e-4 * (1 + fuv.length()));
            }
        }
    }
    // Clamped with p + 1 control points each way: one span, the Bézier patch.
    const auto net = random_points<Point3>(rng, 16);
    const auto bs = BSplineSurface<Point3>::clamped(3, 3, 4, 4, net);
    const BezierPatch<Point3> bz(3, 3, net);
    for (int k = 0; k <= 10; ++k)
        CHECK(dist(bs.eval(k / 10.0, 1 - k / 10.0), bz.eval(k / 10.0, 1 - k / 10.0)) <= 1e-12 * 300);
}

TEST_CASE("NURBS surface: the cylinder is exact, derivatives, unit weights give the B-spline surface", "[surface]") {
    const auto cyl = cylinder(3, 4);
    double worst = 0;
    for (int a = 0; a <= 100; ++a)
        for (int b = 0; b <= 4; ++b) {
            const Point3 p = cyl.eval(a / 100.0, b / 4.0);
            worst = std::max(worst, std::abs(std::hypot(p.x, p.y) - 3));
            CHECK(p.z == Approx(4 * b / 4.0).margin(1e-14));
        }
    CHECK(worst <= 1e-12 * 3);
    std::mt19937 rng(305);
    for (int rep = 0; rep < 30; ++rep) {
        const std::size_t nu = 4, nv = 3;
        const auto net = random_points<Point3>(rng, nu * nv);
        std::vector<double> w;
        for (std::size_t i = 0; i < nu * nv; ++i) w.push_back(uniform(rng, 0.3, 3));
        const NurbsSurface<Point3> s(2, 2, nu, nv, net, w, clamped_knots(2, nu), clamped_knots(2, nv));
        const double u = uniform(rng, 0.1, 0.9), v = uniform(rng, 0.1, 0.9), h = 1e-6;
        const Point3 fu = (s.eval(u + h, v) - s.eval(u - h, v)) / (2 * h);
        const Point3 fv = (s.eval(u, v + h) - s.eval(u, v - h)) / (2 * h);
        const Point3 fuv = (s.du(u, v + h) - s.du(u, v - h)) / (2 * h);
        CHECK(dist(fu, s.du(u, v)) <= 1e-4 * (1 + fu.length()));
        CHECK(dist(fv, s.dv(u, v)) <= 1e-4 * (1 + fv.length()));
        CHECK(dist(fuv, s.twist(u, v)) <= 1e-4 * (1 + fuv.length()));
        CHECK(dist(s.iso_u(u).eval(v), s.eval(u, v)) <= 1e-12 * 300);
        CHECK(dist(s.iso_v(v).eval(u), s.eval(u, v)) <= 1e-12 * 300);
        const NurbsSurface<Point3> unit(2, 2, nu, nv, net, std::vector<double>(nu * nv, 1.0), clamped_knots(2, nu),
                                        clamped_knots(2, nv));
        const auto bs = BSplineSurface<Point3>::clamped(2, 2, nu, nv, net);
        CHECK(dist(unit.eval(u, v), bs.eval(u, v)) <= 1e-12 * 300);
    }
}

TEST_CASE("Projections: cavalier, cabinet, orthographic, depth along the projection direction", "[surface]") {
    const double c = std::numbers::sqrt2 / 2;
    CHECK(dist(project({0, 0, 1}, Projection::Cavalier), Point{-c, -c}) <= 1e-15);
    CHECK(dist(project({0, 0, 1}, Projection::Cabinet), Point{-c / 2, -c / 2}) <= 1e-15);
    CHECK(project({3, 4, 5}, Projection::Orthographic) == Point{3, 4});
    CHECK(dist(project({10, 20, 2}, Projection::Cavalier), Point{10 - 2 * c, 20 - 2 * c}) <= 1e-14);
    for (Projection k : {Projection::Cavalier, Projection::Cabinet, Projection::Orthographic}) {
        View view;
        view.projection = k;
        const double f = k == Projection::Cavalier ? c : k == Projection::Cabinet ? c / 2 : 0;
        const Point3 p{1, 2, 3}, d{f, f, 1};
        // Points along d project to the same 2-D point and lie deeper.
        CHECK(dist(view.apply(p), view.apply(p + d * 5)) <= 1e-14);
        CHECK(view.depth(p + d * 5) > view.depth(p));
        CHECK(view.depth(p + d * 5) - view.depth(p) == Approx(5 * d.length()));
    }
    View v;
    v.projection = Projection::Orthographic;
    v.yaw = std::numbers::pi / 2;
    CHECK(dist(v.rotate({1, 0, 0}), Point3{0, 0, -1}) <= 1e-15);
    v.yaw = 0;
    v.pitch = std::numbers::pi / 2;
    CHECK(dist(v.rotate({0, 0, 1}), Point3{0, -1, 0}) <= 1e-15);
    v.pitch = 0;
    v.scale = 2;
    v.offset = {100, 50};
    CHECK(v.apply({1, 1, 7}) == Point{102, 52});
}

TEST_CASE("Iso grids: one contour per line, exactly the projected iso curves", "[surface]") {
    std::mt19937 rng(306);
    const BezierPatch<Point3> s = random_patch(rng, 3, 3);
    View view;
    view.scale = 2;
    view.offset = {200, 200};
    const Path g = iso_grid(s, view, 5, 4);
    CHECK(g.contour_count() == 9);
    CHECK(std::count(g.verbs().begin(), g.verbs().end(), Verb::Cubic) == 9);
    // The third iso-u curve (u = 0.5): its projected control points.
    const Bezier<Point3> iso = s.iso_u(0.5);
    std::vector<Point> expected;
    for (const Point3& p : iso.points()) expected.push_back(view.apply(p));
    const auto pts = g.points();
    // Contour k is Move + Cubic = 4 points.
    for (std::size_t i = 0; i < 4; ++i) CHECK(dist(pts[2 * 4 + i], expected[i]) <= 1e-12);
    // Sampling the projected curve equals projecting the surface.
    const Bezier<Point> drawn({pts[8], pts[9], pts[10], pts[11]});
    for (int k = 0; k <= 10; ++k) CHECK(dist(drawn.eval(k / 10.0), view.apply(s.eval(0.5, k / 10.0))) <= 1e-10);
    // Higher degrees: cubic approximations; spline and NURBS surfaces (conics for the cylinder).
    const BezierPatch<Point3> hi = random_patch(rng, 5, 2);
    const Path gh = iso_grid(hi, view, 3, 3);
    CHECK(gh.contour_count() == 6);
    const auto cyl = cylinder(30, 40);
    const Path gc = iso_grid(cyl, view, 0, 3);
    CHECK(gc.contour_count() == 3);
    CHECK(std::count(gc.verbs().begin(), gc.verbs().end(), Verb::Conic) == 12);
    const auto bs = BSplineSurface<Point3>::clamped(3, 2, 6, 4, random_points<Point3>(rng, 24));
    CHECK(iso_grid(bs, view, 4, 4).contour_count() == 8);
}

TEST_CASE("Shaded quads: sorted back to front, Lambert shades", "[surface]") {
    const BezierPatch<Point3> flat(1, 1, {{0, 0, 5}, {0, 10, 5}, {10, 0, 5}, {10, 10, 5}});
    View view;
    view.projection = Projection::Orthographic;
    const auto q = shaded_quads(flat, view, 4, 3, {0, 0, -1});
    REQUIRE(q.size() == 12);
    for (const auto& quad : q) CHECK(quad.shade == Approx(1).epsilon(1e-15));
    const auto q2 = shaded_quads(flat, view, 2, 2, {1, 0, 1});
    CHECK(q2[0].shade == Approx(std::sqrt(0.5)).epsilon(1e-12));
    // A curved patch seen obliquely: depths descend, shades in [0, 1], corners are projected points.
    std::mt19937 rng(307);
    const BezierPatch<Point3> s = random_patch(rng, 3, 3);
    View v2;
    v2.yaw = 0.3;
    v2.pitch = -0.4;
    const auto qs = shaded_quads(s, v2, 8, 8);
    REQUIRE(qs.size() == 64);
    for (std::size_t i = 1; i < qs.size(); ++i) CHECK(qs[i - 1].depth >= qs[i].depth);
    for (const auto& quad : qs) {
        CHECK(quad.shade >= 0);
        CHECK(quad.shade <= 1);
    }
    const auto cyl = shaded_quads(cylinder(3, 4), v2, 16, 2);
    CHECK(cyl.size() == 32);
}

TEST_CASE("Surfaces: bad input gives clear errors", "[surface]") {
    const std::vector<Point3> nine(9);
    CHECK(kind_of([&] { BezierPatch<Point3>(2, 3, nine); }) == ErrorKind::InvalidData);
    CHECK_THROWS_WITH(BezierPatch<Point3>(2, 3, nine), "Bezier patch needs 3 x 4 = 12 control points, got 9");
    CHECK(kind_of([&] { BezierPatch<Point3>(0, 8, nine); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { BezierPatch<Point3>(65, 1, std::vector<Point3>(132)); }) == ErrorKind::Limit);
    CHECK(kind_of([&] { BezierPatch<Point3>(1000, 1000, nine); }) == ErrorKind::Limit);
    CHECK(kind_of([&] {
              BezierPatch<Point3>(2, 2, std::vector<Point3>(9, Point3{0, NAN, 0}));
          }) == ErrorKind::InvalidData);
    const BezierPatch<Point3> s(2, 2, nine);
    CHECK(kind_of([&] { s.eval(1.5, 0); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { s.eval(0, -0.5); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { s.eval_matrix(0.5, 0.5); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { iso_grid(s, View{}, 1, 2); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { iso_grid(s, View{}, 2, 100000); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { shaded_quads(s, View{}, 0, 2); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { shaded_quads(s, View{}, 2, 2, {0, 0, 0}); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { BSplineSurface<Point3>::clamped(2, 2, 3, 4, nine); }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] {
              BSplineSurface<Point3>(2, 2, 3, 3, nine, {0, 0, 0, 1, 1}, {0, 0, 0, 1, 1, 1});
          }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] {
              NurbsSurface<Point3>(2, 2, 3, 3, nine, std::vector<double>(9, 0.0), clamped_knots(2, 3),
                                   clamped_knots(2, 3));
          }) == ErrorKind::InvalidData);
    CHECK(kind_of([&] { cylinder(3, 4).derivative(2, 0, 0.5, 0.5); }) == ErrorKind::InvalidArgument);
    CHECK(kind_of([&] { cylinder(3, 4).eval(0.5, 2); }) == ErrorKind::InvalidArgument);
}
