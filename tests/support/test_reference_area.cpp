// Tests of the independent exact-area reference itself (tests/support/reference_area.*): hand-computed
// values, the two methods against each other, and winding-rule identities.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "raster_check.hpp"
#include "reference_area.hpp"

using namespace casteljau;
using namespace casteljau::ref;
using casteljau::testing::random_simple_polygon;
using casteljau::testing::regular_polygon;
using casteljau::testing::reversed;
using casteljau::testing::star_polygon;

namespace {

double max_diff(const CoverageGrid& a, const CoverageGrid& b) {
    double m = 0;
    const IRect u{std::min(a.bounds.x0, b.bounds.x0), std::min(a.bounds.y0, b.bounds.y0),
                  std::max(a.bounds.x1, b.bounds.x1), std::max(a.bounds.y1, b.bounds.y1)};
    for (int y = u.y0; y < u.y1; ++y)
        for (int x = u.x0; x < u.x1; ++x) m = std::max(m, std::abs(a.at(x, y) - b.at(x, y)));
    return m;
}

CoverageGrid add(const CoverageGrid& a, const CoverageGrid& b, double sb = 1.0) {
    CoverageGrid r = a;
    for (std::size_t i = 0; i < r.v.size(); ++i) r.v[i] += sb * b.v[i];
    return r;
}

}  // namespace

TEST_CASE("reference: hand-computed coverage of a square and a triangle", "[reference]") {
    const Contour sq{{0.25, 0.5}, {1.25, 0.5}, {1.25, 1.5}, {0.25, 1.5}};
    const IRect region{-1, -1, 3, 3};
    for (const Contour& c : {sq, reversed(sq)}) {
        const CoverageGrid a = clip_area_simple(c, region);
        const CoverageGrid b = slab_area({c}, FillRule::NonZero, region);
        for (const CoverageGrid* g : {&a, &b}) {
            CHECK(g->at(0, 0) == Approx(0.375).margin(1e-15));
            CHECK(g->at(1, 0) == Approx(0.125).margin(1e-15));
            CHECK(g->at(0, 1) == Approx(0.375).margin(1e-15));
            CHECK(g->at(1, 1) == Approx(0.125).margin(1e-15));
            CHECK(g->at(2, 1) == 0.0);
            CHECK(g->at(-1, 0) == 0.0);
            CHECK(g->sum() == Approx(1.0).margin(1e-14));
        }
    }
    const Contour tri{{0, 0}, {2, 0}, {0, 2}};
    for (const CoverageGrid& g : {clip_area_simple(tri, region), slab_area({tri}, FillRule::EvenOdd, region)}) {
        CHECK(g.at(0, 0) == Approx(1.0).margin(1e-15));
        CHECK(g.at(1, 0) == Approx(0.5).margin(1e-15));
        CHECK(g.at(0, 1) == Approx(0.5).margin(1e-15));
        CHECK(g.at(1, 1) == Approx(0.0).margin(1e-15));
    }
    // A sliver triangle inside one pixel: area 0.5 * 0.8 * 0.01 = 0.004.
    const Contour sliver{{2.1, 1.3}, {2.9, 1.3}, {2.1, 1.31}};
    CHECK(slab_area({sliver}, FillRule::NonZero, region).at(2, 1) == Approx(0.004).epsilon(1e-12));
    CHECK(clip_area_simple(sliver, region).at(2, 1) == Approx(0.004).epsilon(1e-12));
}

TEST_CASE("reference: Sutherland-Hodgman and slab integration agree on random simple polygons", "[reference]") {
    std::mt19937 rng(20240601);
    std::uniform_real_distribution<double> off(-3.0, 3.0);
    double worst = 0;
    for (int iter = 0; iter < 200; ++iter) {
        const int n = 3 + iter % 40;
        const Point c{20 + off(rng), 20 + off(rng)};
        Contour poly = random_simple_polygon(rng, c, 0.5 + (iter % 7), 4 + (iter % 17), n);
        if (iter % 2) poly = reversed(poly);
        const IRect region{-5, -5, 45, 45};  // holds the whole polygon (radius <= 20 around (20, 20) +/- 3)
        const CoverageGrid a = clip_area_simple(poly, region);
        const CoverageGrid nz = slab_area({poly}, FillRule::NonZero, region);
        const CoverageGrid eo = slab_area({poly}, FillRule::EvenOdd, region);
        INFO("polygon " << iter << " with " << poly.size() << " vertices");
        const double d = std::max(max_diff(a, nz), max_diff(a, eo));
        worst = std::max(worst, d);
        REQUIRE(d <= 1e-9);
        // Whole polygon inside the region: the coverages add up to its area.
        REQUIRE(nz.sum() == Approx(std::abs(signed_area(poly))).epsilon(1e-12));
    }
    WARN("largest |clip - slab| difference over 200 random simple polygons: " << worst);
}

TEST_CASE("reference: the two methods agree far from the origin and on partly outside polygons", "[reference]") {
    std::mt19937 rng(77);
    for (int iter = 0; iter < 40; ++iter) {
        const double big = (iter % 2 ? 1e7 : -1e7);
        const Contour local = random_simple_polygon(rng, {5, 5}, 1, 9, 12);
        // Far away: translate both the polygon and the region.
        Contour far = local;
        for (Point& p : far) p = {p.x + big, p.y - big};
        const IRect region{static_cast<int>(big) - 2, static_cast<int>(-big) - 2, static_cast<int>(big) + 8,
                           static_cast<int>(-big) + 8};  // cuts the polygon on the right and bottom
        const CoverageGrid a = clip_area_simple(far, region);
        const CoverageGrid b = slab_area({far}, FillRule::NonZero, region);
        REQUIRE(max_diff(a, b) <= 1e-7);  // coordinates of 1e7 keep ~1e-9 absolute precision
        // And the same coverage as the polygon near the origin.
        const CoverageGrid near = slab_area({local}, FillRule::NonZero, {-2, -2, 8, 8});
        for (int y = 0; y < 10; ++y)
            for (int x = 0; x < 10; ++x)
                REQUIRE(b.at(region.x0 + x, region.y0 + y) == Approx(near.at(x - 2, y - 2)).margin(1e-7));
    }
}

TEST_CASE("reference: winding rules on overlaps, bow-ties and stars", "[reference]") {
    const IRect region{-1, -1, 12, 12};
    // Two overlapping squares, both clockwise: nonzero is the union, even-odd the symmetric difference.
    const Contour s1{{0.5, 0.5}, {6.5, 0.5}, {6.5, 6.5}, {0.5, 6.5}};
    const Contour s2{{3.25, 3.75}, {9.25, 3.75}, {9.25, 9.75}, {3.25, 9.75}};
    const CoverageGrid nz = slab_area({s1, s2}, FillRule::NonZero, region);
    const CoverageGrid eo = slab_area({s1, s2}, FillRule::EvenOdd, region);
    const double overlap = (6.5 - 3.25) * (6.5 - 3.75);
    CHECK(nz.sum() == Approx(72 - overlap).epsilon(1e-12));
    CHECK(eo.sum() == Approx(72 - 2 * overlap).epsilon(1e-12));
    CHECK(nz.at(5, 5) == 1.0);
    CHECK(eo.at(5, 5) == 0.0);
    CHECK(eo.at(3, 4) == Approx(0.25).margin(1e-15));  // inside s1; s2 covers x in [3.25, 4] of it
    // Opposite orientations: nonzero also cancels in the overlap.
    const CoverageGrid nz_rev = slab_area({s1, reversed(s2)}, FillRule::NonZero, region);
    CHECK(max_diff(nz_rev, eo) <= 1e-12);

    // Bow-tie (0,0)-(4,4)-(4,0)-(0,4): two triangles meeting at (2, 2), winding +1 and -1.
    const Contour bow{{0, 0}, {4, 4}, {4, 0}, {0, 4}};
    const CoverageGrid left = clip_area_simple({{0, 0}, {2, 2}, {0, 4}}, region);
    const CoverageGrid right = clip_area_simple({{4, 4}, {4, 0}, {2, 2}}, region);
    const CoverageGrid both = add(left, right);
    CHECK(max_diff(slab_area({bow}, FillRule::NonZero, region), both) <= 1e-12);
    CHECK(max_diff(slab_area({bow}, FillRule::EvenOdd, region), both) <= 1e-12);

    // The pentagram {5/2}: nonzero fills its outline (a simple decagon), even-odd leaves out the
    // central pentagon (winding 2).
    const Point c{5.3, 5.6};
    const double R = 5.0;
    const Contour star = star_polygon(c, R, 5, 2, 0.1);
    const Contour tips = star_polygon(c, R, 5, 1, 0.1);  // the 5 tips in order around the circle
    // The inner vertices of the pentagram: intersections of chord (tip[i], tip[i+2]) with (tip[i+1], tip[i+4]).
    auto intersect = [](Point p1, Point p2, Point p3, Point p4) {
        const double d = (p2.x - p1.x) * (p4.y - p3.y) - (p2.y - p1.y) * (p4.x - p3.x);
        const double t = ((p3.x - p1.x) * (p4.y - p3.y) - (p3.y - p1.y) * (p4.x - p3.x)) / d;
        return Point{p1.x + t * (p2.x - p1.x), p1.y + t * (p2.y - p1.y)};
    };
    Contour outline, inner;
    for (int i = 0; i < 5; ++i) {
        const Point a = tips[static_cast<std::size_t>(i)];
        const Point q =
            intersect(tips[static_cast<std::size_t>(i)], tips[static_cast<std::size_t>((i + 2) % 5)],
                      tips[static_cast<std::size_t>((i + 1) % 5)], tips[static_cast<std::size_t>((i + 4) % 5)]);
        outline.push_back(a);
        outline.push_back(q);
        inner.push_back(q);
    }
    const CoverageGrid deca = clip_area_simple(outline, region);
    const CoverageGrid penta = clip_area_simple(inner, region);
    CHECK(max_diff(slab_area({star}, FillRule::NonZero, region), deca) <= 1e-9);
    CHECK(max_diff(slab_area({star}, FillRule::EvenOdd, region), add(deca, penta, -1.0)) <= 1e-9);
}

TEST_CASE("reference: stacked copies follow the winding rules", "[reference]") {
    const Contour tri{{1.2, 0.7}, {7.9, 2.3}, {3.1, 6.6}};
    const IRect region{0, 0, 9, 8};
    const CoverageGrid one = slab_area({tri}, FillRule::NonZero, region);
    Contours many(300, tri);
    CHECK(max_diff(slab_area(many, FillRule::NonZero, region), one) <= 1e-12);
    CHECK(slab_area(many, FillRule::EvenOdd, region).sum() == 0.0);
    many.push_back(tri);
    CHECK(max_diff(slab_area(many, FillRule::EvenOdd, region), one) <= 1e-12);
}

TEST_CASE("reference: fine flattening of curves has the expected area", "[reference]") {
    // Parabolic segment: the area between a quadratic and its chord is 2/3 base x height, with
    // height half the control point's distance: 2/3 * 10 * 5. The inscribed polygon loses at most
    // 2/3 x sagitta (1e-4) x arc length (< 16) = 1.1e-3.
    Path p;
    p.move_to(1, 12).quad_to({6, 2}, {11, 12}).close();
    const IRect region{0, 0, 13, 13};
    const double parabola = path_reference(p, Affine::identity(), FillRule::NonZero, region).sum();
    CHECK(parabola <= 100.0 / 3);
    CHECK(parabola >= 100.0 / 3 - 1.1e-3);
    // A circle of radius 10 (four cubic arcs; their radial error is below 2.8e-4 r).
    Path c;
    c.add_circle({15, 15}, 10);
    const double area = path_reference(c, Affine::identity(), FillRule::NonZero, {0, 0, 30, 30}).sum();
    CHECK(area == Approx(3.14159265358979 * 100).epsilon(6e-4));
    // Every flattened point lies on the curve (direct Bernstein evaluation): distance to the centre
    // within the cubic approximation's radial error.
    for (const Contour& k : fine_flatten(c, Affine::identity()))
        for (Point q : k) CHECK(std::hypot(q.x - 15, q.y - 15) == Approx(10).epsilon(3e-4));
    // Chords are short enough: consecutive points of a circle of radius 10 at tolerance 1e-4
    // have sagitta r (1 - cos(theta / 2)) <= 1e-4.
    for (const Contour& k : fine_flatten(c, Affine::scale(2), 1e-4))
        for (std::size_t i = 0; i + 1 < k.size(); ++i) {
            const double chord = std::hypot(k[i + 1].x - k[i].x, k[i + 1].y - k[i].y);
            CHECK(chord * chord / (8 * 20) <= 1.1e-4);
        }
}

TEST_CASE("reference: slab integration matches supersampled winding on self-intersecting polygons", "[reference]") {
    // A third, brute-force method: the winding number at 64 x 64 sample points per pixel. Its
    // error per pixel is about (boundary length inside the pixel) / 64 at most (0.004 observed).
    std::mt19937 rng(4242);
    constexpr int kS = 64;
    double all_worst = 0;
    for (int iter = 0; iter < 12; ++iter) {
        const Contours polys{casteljau::testing::random_polygon(rng, {0.2, 0.3, 7.7, 7.9}, 5 + iter),
                             casteljau::testing::random_polygon(rng, {1.0, 0.1, 7.9, 6.8}, 4)};
        const IRect region{0, 0, 8, 8};
        for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            const CoverageGrid g = slab_area(polys, rule, region);
            double worst = 0;
            for (int py = 0; py < 8; ++py)
                for (int px = 0; px < 8; ++px) {
                    int hits = 0;
                    for (int sy = 0; sy < kS; ++sy)
                        for (int sx = 0; sx < kS; ++sx) {
                            const double x = px + (sx + 0.5) / kS, y = py + (sy + 0.5) / kS;
                            int w = 0;
                            for (const Contour& c : polys)
                                for (std::size_t i = 0; i < c.size(); ++i) {
                                    const Point a = c[i], b = c[(i + 1) % c.size()];
                                    if ((a.y <= y) != (b.y <= y)) {
                                        const double xc = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                                        if (xc < x) w += (b.y > a.y) ? 1 : -1;
                                    }
                                }
                            hits += rule == FillRule::NonZero ? (w != 0) : (w & 1);
                        }
                    worst = std::max(worst, std::abs(g.at(px, py) - static_cast<double>(hits) / (kS * kS)));
                }
            INFO("iteration " << iter << (rule == FillRule::NonZero ? " nonzero" : " even-odd"));
            CHECK(worst <= 0.02);
            all_worst = std::max(all_worst, worst);
        }
    }
    WARN("largest |slab - supersampled| difference: " << all_worst);
}
