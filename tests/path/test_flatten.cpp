// Flattening: the flatness bound holds, depth is limited, degenerate and hostile input.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/flatten.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/raster.hpp"

using namespace casteljau;

namespace {
Point cubic_at(Point p0, Point p1, Point p2, Point p3, double t) {
    const double u = 1 - t;
    return p0 * (u * u * u) + p1 * (3 * u * u * t) + p2 * (3 * u * t * t) + p3 * (t * t * t);
}
double dist_to_segment(Point p, Point a, Point b) {
    const Point ab = b - a;
    const double len2 = ab.dot(ab);
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + ab * t)).length();
}
double dist_to_polyline(Point p, const Polyline& pl) {
    double best = INFINITY;
    for (std::size_t i = 0; i + 1 < pl.points.size(); ++i)
        best = std::min(best, dist_to_segment(p, pl.points[i], pl.points[i + 1]));
    return best;
}
}  // namespace

TEST_CASE("flatness bound: the curve stays within the bound of its chord", "[flatten]") {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(-100, 100);
    for (int i = 0; i < 500; ++i) {
        const Point p0{u(rng), u(rng)}, p1{u(rng), u(rng)}, p2{u(rng), u(rng)}, p3{u(rng), u(rng)};
        const double bound = flatness_bound_cubic(p0, p1, p2, p3);
        double worst = 0;
        for (int k = 0; k <= 200; ++k)
            worst = std::max(worst, dist_to_segment(cubic_at(p0, p1, p2, p3, k / 200.0), p0, p3));
        REQUIRE(worst <= bound * (1 + 1e-12) + 1e-12);
    }
    // The quadratic bound is attained at t = 1/2 for a symmetric curve.
    CHECK(flatness_bound_quad({0, 0}, {1, 2}, {2, 0}) == Approx(1.0));
}

TEST_CASE("flatten: every curve point is within the tolerance of the polyline", "[flatten]") {
    std::mt19937 rng(777);
    std::uniform_real_distribution<double> u(0, 300);
    for (double tol : {0.01, 0.05, 0.25}) {
        for (int i = 0; i < 100; ++i) {
            const Point p0{u(rng), u(rng)}, p1{u(rng), u(rng)}, p2{u(rng), u(rng)}, p3{u(rng), u(rng)};
            Path p;
            p.move_to(p0).cubic_to(p1, p2, p3);
            Polyline pl;
            flatten(p, Affine{}, tol, pl);
            REQUIRE(pl.points.front() == p0);
            REQUIRE(pl.points.back() == p3);
            for (int k = 0; k <= 400; ++k)
                REQUIRE(dist_to_polyline(cubic_at(p0, p1, p2, p3, k / 400.0), pl) <= tol * 1.0000001);
        }
    }
}

namespace {
// The flattening rule classify_topology's similarity verdict is proven for: a cubic is halved at
// t = 1/2 (de Casteljau) while 0.75 max(|P0 - 2 P1 + P2|, |P1 - 2 P2 + P3|) exceeds the
// tolerance, down to limits::kMaxFlattenDepth; each leaf contributes its end point.
void halving_leaves(Point p0, Point p1, Point p2, Point p3, double tol, int depth, std::vector<Point>& out) {
    const Point d0 = p0 - p1 * 2 + p2, d1 = p1 - p2 * 2 + p3;
    if (depth >= limits::kMaxFlattenDepth || !(0.5625 * std::max(d0.dot(d0), d1.dot(d1)) > tol * tol)) {
        out.push_back(p3);
        return;
    }
    auto mid = [](Point a, Point b) { return a * 0.5 + b * 0.5; };
    const Point a1 = mid(p0, p1), b1 = mid(p1, p2), c1 = mid(p2, p3), a2 = mid(a1, b1), b2 = mid(b1, c1),
                a3 = mid(a2, b2);
    halving_leaves(p0, a1, a2, a3, tol, depth + 1, out);
    halving_leaves(a3, b2, c1, p3, tol, depth + 1, out);
}
}  // namespace

TEST_CASE("flatten: a cubic's chords are the end points of its halving tree's leaves", "[flatten]") {
    // The public flatten() in Chords mode halves cubics (de Casteljau) until each piece meets the
    // bound; a flattener that cut them otherwise would change every stroke's polygon.
    std::mt19937 rng(4242);
    std::uniform_real_distribution<double> u(-1, 1), lg(-2, 4);
    for (FlattenMode mode : {FlattenMode::Chords})
        for (double tol : {0.015, 0.25, 1e-3}) {
            for (int i = 0; i < 300; ++i) {
                const double size = std::pow(10.0, lg(rng));
                Point q[4];
                for (Point& pt : q) pt = Point{500 + size * u(rng), 300 + size * u(rng)};
                if (i % 5 == 0) q[1] = q[0];             // a coincident control point
                if (i % 7 == 0) q[2] = q[1] * 2 - q[0];  // collinear controls
                Path p;
                p.move_to(q[0]).cubic_to(q[1], q[2], q[3]);
                Polyline pl;
                flatten(p, Affine{}, tol, pl, mode);
                std::vector<Point> want{q[0]};
                halving_leaves(q[0], q[1], q[2], q[3], tol, 0, want);
                REQUIRE(pl.points.size() == want.size());
                REQUIRE(pl.points.back() == q[3]);
                for (std::size_t k = 0; k < want.size(); ++k) {
                    REQUIRE(std::abs(pl.points[k].x - want[k].x) <= 1e-12 * (500 + size));
                    REQUIRE(std::abs(pl.points[k].y - want[k].y) <= 1e-12 * (500 + size));
                }
            }
        }
}

namespace {
Point quad_at(Point p0, Point p1, Point p2, double t) {
    const double u = 1 - t;
    return p0 * (u * u) + p1 * (2 * u * t) + p2 * (t * t);
}
// Signed area enclosed by a closed polygon (shoelace).
double polygon_area(const std::vector<Point>& v) {
    double a = 0;
    for (std::size_t i = 0; i < v.size(); ++i) a += v[i].cross(v[(i + 1) % v.size()]);
    return 0.5 * a;
}
}  // namespace

TEST_CASE("flatten: quadratics in both modes stay within the tolerance, both ways", "[flatten]") {
    std::mt19937 rng(4242);
    std::uniform_real_distribution<double> u(0, 300);
    for (FlattenMode mode : {FlattenMode::Chords, FlattenMode::AreaBalanced}) {
        for (double tol : {0.01, 0.05, 0.25}) {
            for (int i = 0; i < 100; ++i) {
                const Point p0{u(rng), u(rng)}, p1{u(rng), u(rng)}, p2{u(rng), u(rng)};
                Path p;
                p.move_to(p0).quad_to(p1, p2);
                Polyline pl;
                flatten(p, Affine{}, tol, pl, mode);
                REQUIRE(pl.points.front() == p0);
                REQUIRE(pl.points.back() == p2);
                // Curve -> polyline, and every polyline point (vertices and chord midpoints) -> curve.
                std::vector<Point> curve;
                for (int k = 0; k <= 2000; ++k) curve.push_back(quad_at(p0, p1, p2, k / 2000.0));
                double to_poly = 0, to_curve = 0;
                for (const Point& q : curve) to_poly = std::max(to_poly, dist_to_polyline(q, pl));
                for (std::size_t k = 0; k + 1 < pl.points.size(); ++k)
                    for (double t : {0.0, 0.25, 0.5, 0.75}) {
                        const Point q = pl.points[k] + (pl.points[k + 1] - pl.points[k]) * t;
                        double best = INFINITY;
                        for (std::size_t j = 0; j + 1 < curve.size(); ++j)
                            best = std::min(best, dist_to_segment(q, curve[j], curve[j + 1]));
                        to_curve = std::max(to_curve, best);
                    }
                INFO("tolerance " << tol << ", " << pl.points.size() << " points");
                REQUIRE(to_poly <= tol * 1.0000001);
                REQUIRE(to_curve <= tol * 1.001);  // the curve is sampled (2000 chords)
            }
        }
    }
}

namespace {
// The area a curve closed by its chord loses when flattened at 0.05 px in both modes: chords lose
// area on every piece, balanced pieces only on the two end pieces (half a piece each).
struct AreaLoss {
    double chords, balanced;
    std::size_t chord_points, balanced_points;
};
AreaLoss area_loss(const Path& p, double exact) {
    Polyline chords, balanced;
    flatten(p, Affine{}, 0.05, chords, FlattenMode::Chords);
    flatten(p, Affine{}, 0.05, balanced, FlattenMode::AreaBalanced);
    const AreaLoss l{exact - std::abs(polygon_area(chords.points)), exact - std::abs(polygon_area(balanced.points)),
                     chords.points.size(), balanced.points.size()};
    INFO("chords: " << l.chord_points << " points, area error " << l.chords << "; balanced: " << l.balanced_points
                    << " points, area error " << l.balanced);
    CHECK(l.chords > 0);                        // chords are always inside a convex arc
    CHECK(l.balanced_points < l.chord_points);  // the balanced bound is below the chord's
    CHECK(std::abs(l.balanced) < 0.3 * l.chords);
    return l;
}
}  // namespace

TEST_CASE("flatten: area-balanced quadratics lose far less area than chords", "[flatten]") {
    // Area of the region between a parabola arc and its base chord: 2/3 of the triangle's area,
    // i.e. |cross(P1 - P0, P2 - P0)| / 3.
    const Point p0{0, 0}, p1{50, 80}, p2{100, 0};
    Path p;
    p.move_to(p0).quad_to(p1, p2);
    const AreaLoss l = area_loss(p, std::abs((p1 - p0).cross(p2 - p0)) / 3.0);
    // The pieces are equal in parameter, so with n pieces the loss is one chord piece's worth:
    // (2/3) (|A| / (4 n^2)) * (piece length), with A = P0 - 2 P1 + P2 = (0, -160).
    const double n = static_cast<double>(l.balanced_points - 1);
    CHECK(l.balanced == Approx(std::abs((p1 - p0).cross(p2 - p0)) / 3.0 / (n * n * n)).epsilon(0.05));
}

TEST_CASE("flatten: area-balanced cubics stay within the tolerance, in the hull, monotone where the curve is",
          "[flatten][topology]") {
    // src/raster/topology.cpp relies on all three: a polygon within the tolerance of its curve
    // (bands_apart), inside the control hull (the hull tests) and monotone along a coordinate
    // whenever the control points are (no self-crossing).
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> u(0, 300), lg(-2, 3);
    int monotone = 0;
    for (double tol : {0.01, 0.05, 0.25})
        for (int i = 0; i < 150; ++i) {
            Point q[4];
            for (Point& pt : q) pt = Point{u(rng), u(rng)};
            if (i % 3 == 0) {  // control points monotone in x, some with a vertical end tangent
                std::sort(q, q + 4, [](Point a, Point b) { return a.x < b.x; });
                if (i % 2 == 0) q[1].x = q[0].x;
            }
            if (i % 5 == 0) {  // small curves: few pieces
                const double s = std::pow(10.0, lg(rng)) / 300;
                for (Point& pt : q) pt = q[0] + (pt - q[0]) * s;
            }
            Path p;
            p.move_to(q[0]).cubic_to(q[1], q[2], q[3]);
            Polyline pl;
            flatten(p, Affine{}, tol, pl, FlattenMode::AreaBalanced);
            REQUIRE(pl.points.front() == q[0]);
            REQUIRE(pl.points.back() == q[3]);
            const std::size_t n = pl.points.size() - 1;
            // Piece k against the curve over [k / n, (k + 1) / n], at the same parameter.
            double worst = 0;
            for (std::size_t k = 0; k < n; ++k)
                for (int j = 0; j <= 64; ++j) {
                    const double f = j / 64.0;
                    const Point on = cubic_at(q[0], q[1], q[2], q[3], (k + f) / static_cast<double>(n));
                    const Point poly = pl.points[k] + (pl.points[k + 1] - pl.points[k]) * f;
                    worst = std::max(worst, (on - poly).length());
                }
            INFO("tolerance " << tol << ", " << n << " pieces");
            REQUIRE(worst <= tol * (1 + 1e-9));
            // Inside the hull: on the inner side of every hull edge (the hull of 4 points is
            // bounded by lines through two of them with the others on one side).
            for (int a = 0; a < 4; ++a)
                for (int b = a + 1; b < 4; ++b) {
                    const Point d = q[b] - q[a];
                    double lo = INFINITY, hi = -INFINITY;
                    for (const Point& c : q) {
                        lo = std::min(lo, d.cross(c - q[a]));
                        hi = std::max(hi, d.cross(c - q[a]));
                    }
                    const double slack = 1e-9 * (d.length() * 600 + 1);
                    if (lo < -slack && hi > slack) continue;  // not a hull edge
                    for (const Point& v : pl.points) {
                        const double c = d.cross(v - q[a]);
                        REQUIRE((c >= lo - slack && c <= hi + slack));
                    }
                }
            const bool mono = q[0].x <= q[1].x && q[1].x <= q[2].x && q[2].x <= q[3].x;
            if (mono) {
                ++monotone;
                for (std::size_t k = 0; k < n; ++k) REQUIRE(pl.points[k + 1].x >= pl.points[k].x - 1e-9);
            }
        }
    CHECK(monotone >= 150);
}

TEST_CASE("flatten: an area-balanced cubic takes the fewest pieces its error bound allows", "[flatten]") {
    // The bound (src/path/flatten_internal.hpp): n pieces are within (25/48) M / n^2 of the curve,
    // M = max(|P0 - 2 P1 + P2|, |P1 - 2 P2 + P3|); the flattener takes the smallest n >= 2 that
    // meets the tolerance (a curve within (3/4) M of its chord is its chord), so n - 1 pieces
    // would not. Curves whose second differences differ most (|E| large against M) are where a
    // bound that also counts |E| would cut more pieces than needed.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 40);
    int cut = 0;
    for (double tol : {0.015, 0.1})
        for (int i = 0; i < 300; ++i) {
            Point q[4];
            for (Point& pt : q) pt = Point{u(rng), u(rng)};
            Path p;
            p.move_to(q[0]).cubic_to(q[1], q[2], q[3]);
            Polyline pl;
            flatten(p, Affine{}, tol, pl, FlattenMode::AreaBalanced);
            const double n = static_cast<double>(pl.points.size() - 1);
            const double M = std::max((q[0] - q[1] * 2 + q[2]).length(), (q[1] - q[2] * 2 + q[3]).length());
            const double need = (25.0 / 48.0) * M / tol;  // n^2 must reach it
            INFO("tolerance " << tol << ", M " << M << ", " << n << " pieces");
            if (0.75 * M <= tol * (1 - 1e-12)) {
                CHECK(n == 1);
                continue;
            }
            if (0.75 * M <= tol * (1 + 1e-12)) continue;  // on the chord test's rounding edge
            ++cut;
            CHECK(n * n >= need * (1 - 1e-12));
            if (n > 2) CHECK((n - 1) * (n - 1) < need * (1 + 1e-12));
        }
    CHECK(cut > 500);
}

TEST_CASE("flatten: area-balanced cubics lose far less area than chords", "[flatten]") {
    // A cubic arch closed by its chord, against its closed-form area (P0 at the origin, so the
    // chord adds nothing): (1/20) (6 P0xP1 + 3 P0xP2 + P0xP3 + 3 P1xP2 + 3 P1xP3 + 6 P2xP3).
    const Point p0{0, 0}, p1{10, 90}, p2{80, 70}, p3{100, 0};
    Path p;
    p.move_to(p0).cubic_to(p1, p2, p3);
    area_loss(p, std::abs(3 * p1.cross(p2) + 3 * p1.cross(p3) + 6 * p2.cross(p3)) / 20);
}

TEST_CASE("flatten: the tolerance is in pixels, after the transform", "[flatten]") {
    Path p;
    p.move_to(0, 0).quad_to({1, 1}, {2, 0});
    Polyline small, big;
    flatten(p, Affine{}, 0.05, small);
    flatten(p, Affine::scale(100), 0.05, big);
    CHECK(big.points.size() > small.points.size());
    CHECK(big.points.back() == Point{200, 0});
}

TEST_CASE("flatten: conics (exact circle arcs) stay within tolerance", "[flatten]") {
    // Quarter circle of radius 100 as a conic with weight cos(45 deg).
    Path p;
    p.move_to(100, 0).conic_to({100, 100}, {0, 100}, std::sqrt(0.5));
    Polyline pl;
    flatten(p, Affine{}, 0.05, pl);
    for (const Point& q : pl.points) CHECK(q.length() == Approx(100).margin(1e-9));  // vertices on the circle
    for (std::size_t i = 0; i + 1 < pl.points.size(); ++i) {
        const Point m = midpoint(pl.points[i], pl.points[i + 1]);
        CHECK(100 - m.length() <= 0.05);  // chord sagitta within tolerance
    }
}

TEST_CASE("flatten: degenerate curves, cusps and loops do not explode", "[flatten]") {
    Path p;
    p.move_to(5, 5).cubic_to({5, 5}, {5, 5}, {5, 5});          // coincident points
    p.move_to(0, 0).cubic_to({100, 100}, {0, 100}, {100, 0});  // loop
    p.move_to(0, 0).cubic_to({100, 0}, {0, 0}, {100, 0});      // cusp / collinear backtrack
    Polyline pl;
    flatten(p, Affine{}, 0.05, pl);
    CHECK(pl.contour_count() == 3);
    CHECK(pl.points.size() < 2000);
}

TEST_CASE("flatten: huge values terminate with at most 2^16 pieces per curve", "[flatten]") {
    Path p;
    p.move_to(-1e300, 0).cubic_to({1e300, 1e300}, {-1e300, 1e300}, {1e300, 0});
    Polyline pl;
    flatten(p, Affine{}, 0.05, pl);
    CHECK(pl.points.size() <= (1u << limits::kMaxFlattenDepth) + 1);
    for (const Point& q : pl.points) CHECK(q.is_finite());
}

TEST_CASE("flatten: non-finite input is an error", "[flatten]") {
    Polyline pl;
    Path p;
    p.move_to(0, 0).line_to(NAN, 1);
    CHECK_THROWS_AS(flatten(p, Affine{}, 0.05, pl), Error);
    Path q;
    q.move_to(0, 0).line_to(1e300, 1);
    CHECK_THROWS_AS(flatten(q, Affine::scale(1e300), 0.05, pl), Error);  // overflows after the transform
    CHECK_THROWS_AS(flatten(q, Affine{}, 0.0, pl), Error);
}

TEST_CASE("flatten and fill: more than limits::kMaxFlattenedSegments segments is Error(Limit)", "[flatten][limits]") {
    // Each of these cubics needs the full subdivision depth (2^16 pieces) at this tolerance, so
    // 2^23 / 2^16 = 128 of them reach the limit and 129 pass it.
    Path p;
    p.move_to(0, 0);
    for (int i = 0; i < 129; ++i) p.cubic_to({1000, 1000}, {-1000, 1000}, {0, 0});
    Polyline pl;
    try {
        flatten(p, Affine{}, 1e-9, pl);
        FAIL("no error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Limit); }
    pl.clear();
    pl.points.shrink_to_fit();
    // The rasterizer builds its own edges with the same limit.
    casteljau::Rasterizer r;
    FillOptions o;
    o.tolerance = 1e-9;
    try {
        (void)r.fill_mask(p, Affine::translate(2000, 100), o, IRect{0, 0, 4000, 2000});
        FAIL("no error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Limit); }
}

namespace {

// A shape that hits the edge limit inside the engine (a small box, 48 x 48, at tolerance 1e-9),
// leaving its per-cell state half written: a zigzag drawn twice over the whole box first makes
// every cell it crosses a candidate.
Path limit_breaking_shape() {
    Path big;
    for (int pass = 0; pass < 2; ++pass) {
        big.move_to(0.5, 0.3);
        for (int row = 0; row < 48; ++row) big.line_to(row % 2 ? 0.5 : 47.5, row + 0.7);
    }
    big.move_to(10, 10);
    for (int i = 0; i < 129; ++i) big.cubic_to({60, 60}, {-40, 60}, {10, 10});
    return big;
}

// Overlapping and touching contours: visits, candidates and exact cells.
Path overlapping_shapes() {
    Path shapes;
    shapes.add_circle({20, 20}, 12).add_circle({28, 22}, 9).add_rect({5.5, 18.25, 40.5, 19.0});
    return shapes;
}

}  // namespace

TEST_CASE("fill: a rasterizer interrupted by the edge limit renders the next shape as a fresh one does",
          "[flatten][limits]") {
    const Path big = limit_breaking_shape(), shapes = overlapping_shapes();
    FillOptions fine;
    fine.tolerance = 1e-9;
    Rasterizer used, fresh;
    for (int round = 0; round < 2; ++round) {
        CHECK_THROWS_AS(used.fill_mask(big, Affine{}, fine, IRect{0, 0, 48, 48}), Error);
        const Mask a = used.fill_mask(shapes, Affine{}, FillOptions{}, IRect{0, 0, 48, 48});
        const Mask b = fresh.fill_mask(shapes, Affine{}, FillOptions{}, IRect{0, 0, 48, 48});
        CHECK(used.last_stats().exact_cells == fresh.last_stats().exact_cells);
        CHECK(a.data == b.data);
    }
}

TEST_CASE("fill: a rasterizer made after one destroyed mid-fill renders as a fresh one does", "[flatten][limits]") {
    // A destroyed rasterizer's state is kept for the next one made (the spare pool in
    // rasterizer.cpp), half written when the edge limit stopped its last fill.
    const Path big = limit_breaking_shape(), shapes = overlapping_shapes();
    FillOptions fine;
    fine.tolerance = 1e-9;
    Rasterizer reference;
    const Mask want = reference.fill_mask(shapes, Affine{}, FillOptions{}, IRect{0, 0, 48, 48});
    for (int round = 0; round < 3; ++round) {
        {
            Rasterizer used;
            CHECK_THROWS_AS(used.fill_mask(big, Affine{}, fine, IRect{0, 0, 48, 48}), Error);
        }
        Rasterizer next;
        const Mask got = next.fill_mask(shapes, Affine{}, FillOptions{}, IRect{0, 0, 48, 48});
        CHECK(next.last_stats().exact_cells == reference.last_stats().exact_cells);
        CHECK(got.data == want.data);
    }
}

TEST_CASE("Path: appending a path to itself appends a copy of it", "[flatten][path]") {
    // The appended path is the one growing: reading it while its arrays grow reads freed memory
    // (the sanitizer build catches that).
    Path p;
    p.add_rect(Rect{0.5, 0.5, 40.5, 40.5});
    p.quad_to({60, 10}, {50, 50});
    p.conic_to({70, 70}, {20, 60}, 0.7);
    for (const Affine& m : {Affine{}, Affine::translate(5, -3)}) {
        Path self = p, expected = p;
        const Path copy = p;
        expected.append(copy, m);
        self.append(self, m);
        CHECK(self == expected);
        CHECK(self.points().size() == 2 * p.points().size());
    }
}

TEST_CASE("Path: append equals adding the other path's segments one by one", "[flatten][path]") {
    // The reference: other's verbs replayed through the builder, read off its arrays (moves
    // collapse, a segment after a close opens a contour at the close's point). Other's first verb
    // is a move, so the head's open contour ends there.
    auto replay = [](Path into, const Path& other, const Affine& m) {
        const auto pts = other.points();
        const auto ws = other.weights();
        std::size_t p = 0, w = 0;
        for (const Verb v : other.verbs()) {
            if (v == Verb::Move)
                into.move_to(m(pts[p]));
            else if (v == Verb::Line)
                into.line_to(m(pts[p]));
            else if (v == Verb::Quad)
                into.quad_to(m(pts[p]), m(pts[p + 1]));
            else if (v == Verb::Cubic)
                into.cubic_to(m(pts[p]), m(pts[p + 1]), m(pts[p + 2]));
            else if (v == Verb::Conic)
                into.conic_to(m(pts[p]), m(pts[p + 1]), ws[w++]);
            else
                into.close();
            p += static_cast<std::size_t>(verb_point_count(v));
        }
        return into;
    };
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-50, 50);
    auto pt = [&] { return Point{u(rng), u(rng)}; };
    auto random_path = [&](int verbs) {
        Path p;
        for (int k = 0; k < verbs; ++k) {
            switch (rng() % 7) {
                case 0: p.move_to(pt()); break;
                case 1: p.line_to(pt()); break;
                case 2: p.quad_to(pt(), pt()); break;
                case 3: p.cubic_to(pt(), pt(), pt()); break;
                case 4: p.conic_to(pt(), pt(), 0.5 + (rng() % 4)); break;
                case 5: p.close(); break;
                default: p.close().line_to(pt()); break;  // a segment after a close
            }
        }
        return p;
    };
    for (int iter = 0; iter < 300; ++iter) {
        Path head = random_path(static_cast<int>(rng() % 6));
        if (iter % 5 == 0) head.move_to(pt());  // ends on a lone move, which other's first move replaces
        const Path other = random_path(static_cast<int>(rng() % 9));
        const Affine m = iter % 2 ? Affine{} : Affine::rotate_degrees(u(rng)) * Affine::scale(2, -3);
        const Path want = replay(head, other, m);
        Path got = head;
        got.append(other, m);
        if (other.empty()) {  // nothing added (append also ends the head's open contour)
            CHECK(std::ranges::equal(got.verbs(), head.verbs()));
            CHECK(std::ranges::equal(got.points(), head.points()));
            continue;
        }
        REQUIRE(got == want);
        CHECK(got.control_bounds() == want.control_bounds());
        CHECK(got.current_point() == want.current_point());
        // What comes next continues alike (the open contour and its start point carried over).
        const Point q = pt();
        got.line_to(q).close().line_to(q);
        Path next = want;
        next.line_to(q).close().line_to(q);
        CHECK(got == next);
    }
    // add_polygon adds its lines in one piece: the same as a move and one line_to per point.
    for (int iter = 0; iter < 50; ++iter) {
        Path head = random_path(static_cast<int>(rng() % 4));
        std::vector<Point> pts(1 + rng() % 6);
        for (Point& p : pts) p = pt();
        const bool close = iter % 2 == 0;
        Path want = head;
        want.move_to(pts[0]);
        for (std::size_t i = 1; i < pts.size(); ++i) want.line_to(pts[i]);
        if (close) want.close();
        Path got = head;
        got.add_polygon(pts, close);
        REQUIRE(got == want);
        CHECK(got.control_bounds() == want.control_bounds());
    }
}

TEST_CASE("Path: control bounds and finiteness are kept up to date as the path changes", "[flatten][path]") {
    auto loop_bounds = [](const Path& p) {
        if (p.points().empty()) return Rect{};
        Rect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
        for (Point q : p.points())
            if (q.is_finite()) r.include(q);
        return r;
    };
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-50, 50);
    auto pt = [&] { return Point{u(rng), u(rng)}; };
    for (int iter = 0; iter < 50; ++iter) {
        Path p;
        for (int k = 0; k < 12; ++k) {
            switch (rng() % 7) {
                case 0: p.move_to(pt()); break;
                case 1: p.line_to(pt()); break;
                case 2: p.quad_to(pt(), pt()); break;
                case 3: p.cubic_to(pt(), pt(), pt()); break;
                case 4: p.conic_to(pt(), pt(), 0.7); break;
                case 5: p.close(); break;
                default: p.move_to(pt()).move_to(pt()); break;  // the second move replaces the first point
            }
            REQUIRE(p.control_bounds() == loop_bounds(p));
        }
        const Affine m = Affine::rotate_degrees(u(rng)) * Affine::scale(2, -3);
        Path t = p.transformed(m);
        CHECK(t.control_bounds() == loop_bounds(t));
        Path r = p.reversed();
        CHECK(r.control_bounds() == loop_bounds(r));
        Path a;
        a.append(p, m);
        CHECK(a.control_bounds() == loop_bounds(a));
        // Scale and translation: the rasterizer's O(1) bounds are exactly the transformed points'.
        const Affine s = Affine::translate(3.25, -7.5) * Affine::scale(-1.5, 0.75);
        const Rect want = loop_bounds(p.transformed(s));
        Rasterizer rast;
        const Mask mask = rast.fill_mask(p, s, FillOptions{});
        CHECK(mask.bounds.x0 == static_cast<int>(std::floor(want.x0)));
        CHECK(mask.bounds.y0 == static_cast<int>(std::floor(want.y0)));
        CHECK(mask.bounds.x1 == std::max(static_cast<int>(std::ceil(want.x1)), mask.bounds.x0 + 1));
        CHECK(mask.bounds.y1 == std::max(static_cast<int>(std::ceil(want.y1)), mask.bounds.y0 + 1));
    }
    Path p;
    p.move_to(0, 0).line_to(10, 5);
    CHECK(p.is_finite());
    p.move_to(NAN, 1);
    CHECK_FALSE(p.is_finite());
    p.move_to(2, 3);  // replaces the NaN point
    CHECK(p.is_finite());
    CHECK(p.control_bounds() == Rect{0, 0, 10, 5});
    p.line_to(INFINITY, 0);
    CHECK_FALSE(p.is_finite());
    // add_polygon takes its points' bounds and finiteness in one piece: a NaN or an infinity
    // anywhere among them makes the path not finite, and a NaN leaves the bounds of the others.
    for (double bad : {double(NAN), double(INFINITY), -double(INFINITY)}) {
        for (std::size_t at = 0; at < 4; ++at) {
            std::vector<Point> pts{{1, 2}, {-3, 4}, {5, -6}, {7, 8}};
            pts[at] = Point{bad, bad};
            Path q;
            q.add_polygon(pts);
            CHECK_FALSE(q.is_finite());
            if (std::isnan(bad)) CHECK(q.control_bounds() == loop_bounds(q));
        }
    }
    Polyline pl;
    CHECK_THROWS_AS(flatten(p, Affine::scale(2), 0.05, pl), Error);  // the O(1) path sees it too
    p.clear();
    CHECK(p.is_finite());
    CHECK(p.control_bounds() == Rect{});
    p.line_to(1, 1);
    CHECK(p.control_bounds() == Rect{0, 0, 1, 1});
}
