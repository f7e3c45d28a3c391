// Fill rules (nonzero, even-odd) where plain accumulation is not exact: self-intersecting stars,
// overlapping and nested contours in both orientations, stacked copies (winding far beyond 255),
// winding +/-3, +1/-1 pairs sharing a pixel. Every pixel is compared with the independent exact
// reference (tests/support/reference_area.*), crossings included.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "casteljau/stroke.hpp"
#include "core/simd_dispatch.hpp"

#include "accuracy_util.hpp"
#include "glyph_outline.hpp"

using namespace casteljau;
using namespace casteljau::testing;
using ref::Contour;
using ref::Contours;

namespace {

const char* rule_name(FillRule r) { return r == FillRule::NonZero ? "nonzero" : "even-odd"; }

FillOptions with_rule(FillRule r, double tolerance = kDefaultTolerance) {
    FillOptions o;
    o.rule = r;
    o.tolerance = tolerance;
    return o;
}

constexpr double kFineTolerance = 0.01;

}  // namespace

TEST_CASE("fill rules: self-intersecting stars", "[fillrule]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(0, 1);
    struct Star {
        int p, q;
    };
    for (Star s : {Star{5, 2}, Star{7, 3}, Star{7, 2}, Star{9, 4}, Star{8, 3}, Star{11, 5}}) {
        for (int i = 0; i < 12; ++i) {
            const double radius = 1.5 + 30 * u(rng) * u(rng);
            const Point c{radius + 1 + u(rng), radius + 1 + u(rng)};
            Contour star = star_polygon(c, radius, s.p, s.q, 2 * kPi * u(rng));
            if (i % 2) star = reversed(star);
            const IRect clip{0, 0, static_cast<int>(2 * radius + 3), static_cast<int>(2 * radius + 3)};
            for (FillRule rule : kRules) {
                std::string what = "star ";
                what += std::to_string(s.p);
                what += '/';
                what += std::to_string(s.q);
                what += " r=";
                what += std::to_string(radius);
                worst.add(check_polygons(r, {star}, rule, clip, what), what);
            }
        }
    }
    // The pentagram's centre: winding 2, so full under nonzero and empty under even-odd.
    const Contour penta = star_polygon({20, 20}, 18, 5, 2);
    const Rendered nz =
        render(r, ref::to_path({penta}), Affine::identity(), with_rule(FillRule::NonZero), {0, 0, 40, 40});
    const Rendered eo =
        render(r, ref::to_path({penta}), Affine::identity(), with_rule(FillRule::EvenOdd), {0, 0, 40, 40});
    CHECK(nz.at(20, 20) == 255);
    CHECK(eo.at(20, 20) == 0);
    CHECK(nz.at(20, 5) == 255);  // a tip: winding 1
    CHECK(eo.at(20, 5) == 255);
    WARN("stars: " << worst.text());
}

TEST_CASE("fill rules: a crossing inside one pixel", "[fillrule]") {
    Rasterizer r;
    // Bow-tie whose two edges cross at (5.37, 4.61), inside pixel (5, 4): winding +1 and -1 on
    // either side, so accumulation alone would cancel there.
    const Contour bow{{1.2, 0.9}, {9.54, 8.32}, {9.1, 0.7}, {1.64, 8.52}};
    for (FillRule rule : kRules) check_polygons(r, {bow}, rule, {0, 0, 11, 10}, "bow-tie");
    // An X of two thin bars crossing: winding 2 in the middle.
    const Contour a{{0.3, 1.1}, {1.1, 0.3}, {11.7, 10.9}, {10.9, 11.7}};
    const Contour b = reversed({{11.7, 1.1}, {10.9, 0.3}, {0.3, 10.9}, {1.1, 11.7}});
    for (FillRule rule : kRules) {
        check_polygons(r, {a, b}, rule, {0, 0, 12, 12}, "X of bars");
        check_polygons(r, {a, reversed(b)}, rule, {0, 0, 12, 12}, "X of bars, opposite orientation");
    }
}

TEST_CASE("fill rules: overlapping circles", "[fillrule]") {
    Rasterizer r;
    Worst polys, curves;
    std::mt19937 rng(22);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 40; ++i) {
        // 2..5 circles, random orientation, overlapping near the middle. As 96-gons they are
        // polygons (exact bound); as cubic circles they are curves (curve bounds).
        Contours set;
        Path curved;
        const int n = 2 + i % 4;
        for (int k = 0; k < n; ++k) {
            const Point c{20 + 8 * (u(rng) - 0.5), 20 + 8 * (u(rng) - 0.5)};
            const double radius = 3 + 12 * u(rng);
            const bool cw = u(rng) < 0.5;
            set.push_back(regular_polygon(c, radius, 96, cw, u(rng)));
            Path one;
            one.add_circle(c, radius);
            curved.append(cw ? one : one.reversed());
        }
        for (FillRule rule : kRules) {
            const std::string what = std::to_string(n) + " circles #" + std::to_string(i);
            polys.add(check_polygons(r, set, rule, {0, 0, 40, 40}, what + " (96-gons)"), what);
            curves.add(check_curves(r, curved, Affine::identity(), with_rule(rule), {0, 0, 40, 40}, what), what);
        }
    }
    WARN("overlapping circles as polygons: " << polys.text());
    WARN("overlapping circles as curves at tolerance " << kDefaultTolerance << ": " << curves.text());
}

TEST_CASE("fill rules: nested contours in both orientations", "[fillrule]") {
    Rasterizer r;
    Worst worst;
    const IRect clip{0, 0, 40, 40};
    // Squares nested three deep, and 64-gons nested three deep, every orientation combination.
    for (int mask = 0; mask < 8; ++mask) {
        Contours squares, rings;
        for (int k = 0; k < 3; ++k) {
            const double in = 2.3 + 5.7 * k;
            Contour s = rect(in, in + 0.4, 38.6 - in, 38.1 - in);
            Contour g = regular_polygon({20.2, 19.7}, 18.5 - 6.1 * k, 64, true, 0.05 * k);
            if ((mask >> k) & 1) {
                s = reversed(s);
                g = reversed(g);
            }
            squares.push_back(s);
            rings.push_back(g);
        }
        for (FillRule rule : kRules) {
            const std::string what = "orientations " + std::to_string(mask);
            worst.add(check_polygons(r, squares, rule, clip, "nested squares, " + what), "squares " + what);
            worst.add(check_polygons(r, rings, rule, clip, "nested 64-gons, " + what), "64-gons " + what);
        }
        // The centre's winding is the sum of the orientations (+1 each, -1 reversed).
        const int w = 3 - 2 * (((mask >> 0) & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1));
        const Rendered nz = render(r, ref::to_path(squares), Affine::identity(), with_rule(FillRule::NonZero), clip);
        const Rendered eo = render(r, ref::to_path(squares), Affine::identity(), with_rule(FillRule::EvenOdd), clip);
        INFO("orientations " << mask << ", centre winding " << w);
        CHECK(nz.at(20, 20) == (w != 0 ? 255 : 0));
        CHECK(eo.at(20, 20) == 255);  // three contours around it: odd whatever the orientations
        CHECK(eo.at(6, 20) == 255);   // inside the outer square only
        CHECK(eo.at(10, 20) == 0);    // between the second and third squares: two contours around
    }
    // Nested curves: circles in both orientations, rendered as curves (curve bounds).
    Path same, opposite;
    same.add_circle({20, 20}, 17).add_circle({20, 20}, 9.5);
    opposite.add_circle({20, 20}, 17).append(Path().add_circle({20, 20}, 9.5).reversed());
    for (FillRule rule : kRules) {
        worst.add(check_curves(r, same, Affine::identity(), with_rule(rule), clip, "nested circles, same orientation"),
                  "circles same");
        worst.add(check_curves(r, opposite, Affine::identity(), with_rule(rule), clip, "nested circles, opposite"),
                  "circles opposite");
    }
    CHECK(render(r, same, Affine::identity(), with_rule(FillRule::NonZero), clip).at(20, 20) == 255);
    CHECK(render(r, same, Affine::identity(), with_rule(FillRule::EvenOdd), clip).at(20, 20) == 0);
    CHECK(render(r, opposite, Affine::identity(), with_rule(FillRule::NonZero), clip).at(20, 20) == 0);
    WARN("nested contours: " << worst.text());
}

TEST_CASE("fill rules: winding reaching +3 and -3", "[fillrule]") {
    Rasterizer r;
    const IRect clip{0, 0, 30, 30};
    // Three overlapping triangles around (15, 15): winding 3 in the common part, 2 and 1 around it.
    Contours tris;
    for (int k = 0; k < 3; ++k) {
        const double a = 2 * kPi * k / 3 + 0.2;
        const Point c{15 + 4 * std::cos(a), 15 + 4 * std::sin(a)};
        tris.push_back(regular_polygon(c, 11.3, 3, true, a));
    }
    Contours neg;
    for (const Contour& c : tris) neg.push_back(reversed(c));
    for (const Contours* set : {&tris, &neg}) {
        for (FillRule rule : kRules) check_polygons(r, *set, rule, clip, set == &tris ? "winding +3" : "winding -3");
        // Where all three overlap (the centre) the winding is +/-3: filled under both rules.
        CHECK(render(r, ref::to_path(*set), Affine::identity(), with_rule(FillRule::EvenOdd), clip).at(15, 15) == 255);
        CHECK(render(r, ref::to_path(*set), Affine::identity(), with_rule(FillRule::NonZero), clip).at(15, 15) == 255);
    }
    // The same squares three times with shifts: regions of winding 1, 2 and 3 side by side, and
    // a ring where +3 meets -3 contours (winding 0 between them).
    const Contours ladder{rect(2.5, 2.5, 20.5, 20.5), rect(5.25, 5.25, 23.25, 23.25), rect(8.75, 8.75, 26.75, 26.75)};
    const Contours mixed{rect(2.5, 2.5, 20.5, 20.5),           rect(5.25, 5.25, 23.25, 23.25),
                         rect(8.75, 8.75, 26.75, 26.75),       reversed(rect(3.5, 3.5, 27.5, 27.5)),
                         reversed(rect(4.5, 4.5, 28.5, 28.5)), reversed(rect(6.5, 6.5, 29.5, 29.5))};
    for (FillRule rule : kRules) {
        check_polygons(r, ladder, rule, clip, "ladder of windings 1..3");
        check_polygons(r, mixed, rule, clip, "windings from -3 to +3");
    }
    const Rendered eo = render(r, ref::to_path(ladder), Affine::identity(), with_rule(FillRule::EvenOdd), clip);
    CHECK(eo.at(3, 3) == 255);    // winding 1
    CHECK(eo.at(6, 6) == 0);      // winding 2
    CHECK(eo.at(12, 12) == 255);  // winding 3
}

TEST_CASE("fill rules: +1/-1 contours sharing a pixel", "[fillrule]") {
    Rasterizer r;
    const IRect clip{0, 0, 12, 6};
    // Two rectangles meeting at x = 5.5 inside pixel column 5, the second one reversed: the
    // column is half +1, half -1. Truth: fully covered under both rules; signed areas cancel.
    const Contours pair{rect(0.5, 1, 5.5, 5), reversed(rect(5.5, 1, 10.5, 5))};
    for (FillRule rule : kRules) {
        check_polygons(r, pair, rule, clip, "+1/-1 pair");
        CHECK(render(r, ref::to_path(pair), Affine::identity(), with_rule(rule), clip).at(5, 2) == 255);
    }
    // Overlapping by a fraction of a pixel instead: [0.5, 5.7] and reversed [5.3, 10.5]: pixel 5
    // has winding +1 on [5, 5.3), 0 on [5.3, 5.7), -1 on [5.7, 6): coverage 0.6 under both rules.
    const Contours overlap{rect(0.5, 1, 5.7, 5), reversed(rect(5.3, 1, 10.5, 5))};
    for (FillRule rule : kRules) {
        check_polygons(r, overlap, rule, clip, "+1/-1 overlapping");
        CHECK(render(r, ref::to_path(overlap), Affine::identity(), with_rule(rule), clip).at(5, 2) == 153);
    }
}

namespace {

// Renders `copies` copies of `one` (a Path) and compares with `expected`: the same coverage up to
// the last bit of rounding. The single shape's edge pixels come from float accumulation, the
// stacked ones from the exact (double) cell computation; where the true value lies within float
// noise of a rounding boundary (k + 1/2)/255 the two may round to neighbouring bytes, so one
// unit of difference is allowed and anything more fails. Both are checked against the exact
// reference elsewhere in this file.
void check_stacked(Rasterizer& r, const Path& one, int copies, FillRule rule, const IRect& clip,
                   const std::vector<std::uint8_t>& expected, const std::string& what) {
    Path many;
    for (int i = 0; i < copies; ++i) many.append(one);
    const Rendered out = render(r, many, Affine::identity(), with_rule(rule, kFineTolerance), clip);
    REQUIRE(out.contract_violation.empty());
    std::size_t diff = 0, first = 0;
    int worst = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        const int d = std::abs(out.cov[i] - expected[i]);
        if (d != 0 && diff++ == 0) first = i;
        worst = std::max(worst, d);
    }
    INFO(what << ": " << copies << " copies under " << rule_name(rule) << ": " << diff << " pixels differ, worst by "
              << worst << "; first at (" << clip.x0 + static_cast<int>(first % clip.width()) << ", "
              << clip.y0 + static_cast<int>(first / clip.width()) << ")");
    CHECK(worst <= 1);
    CHECK(diff <= expected.size() / 20);
}

}  // namespace

TEST_CASE("fill rules: 300 stacked copies", "[fillrule]") {
    // Curves are flattened at 0.01 px here so that the single shape's check against the reference
    // is about the fill rule, not the default tolerance (tested in test_raster_accuracy.cpp).
    Rasterizer r;
    GlyphFont font(dejavu_sans_path());
    struct Shape {
        std::string name;
        Path path;
        IRect clip;
    };
    std::vector<Shape> shapes;
    shapes.push_back({"triangle", ref::to_path({{{1.2, 0.7}, {17.9, 6.3}, {5.1, 14.6}}}), {0, 0, 20, 16}});
    shapes.push_back({"pentagram", ref::to_path({star_polygon({10.3, 10.1}, 9.2, 5, 2, 0.3)}), {0, 0, 21, 21}});
    {
        Path c;
        c.add_circle({10.4, 9.7}, 8.3);
        shapes.push_back({"circle", c, {0, 0, 21, 21}});
    }
    {
        Path g;
        font.append_glyph(U'g', 24, {1.25, 19.5}, g);
        shapes.push_back({"glyph g", g, {0, 0, 18, 28}});
    }
    std::vector<std::uint8_t> empty;
    for (const Shape& s : shapes) {
        empty.assign(static_cast<std::size_t>(s.clip.width()) * s.clip.height(), 0);
        for (FillRule rule : kRules) {
            const Rendered single = render(r, s.path, Affine::identity(), with_rule(rule, kFineTolerance), s.clip);
            // The single shape is itself right (polygons exact, curves within curve bounds).
            const Comparison c = compare(single, ref::path_reference(s.path, Affine::identity(), rule, s.clip));
            INFO(s.name << " single: " << c.text());
            CHECK(c.max_err <= kCurveMaxErr);
            if (rule == FillRule::NonZero) {
                check_stacked(r, s.path, 300, rule, s.clip, single.cov, s.name);
                check_stacked(r, s.path, 301, rule, s.clip, single.cov, s.name);
            } else {
                // Even-odd: the single shape's own even-odd coverage repeats for every odd count.
                const Rendered single_eo = single;
                check_stacked(r, s.path, 300, rule, s.clip, empty, s.name);
                check_stacked(r, s.path, 301, rule, s.clip, single_eo.cov, s.name);
            }
        }
        // 150 copies one way and 150 reversed: winding 0 everywhere, nothing under either rule.
        Path both;
        for (int i = 0; i < 150; ++i) both.append(s.path).append(s.path.reversed());
        for (FillRule rule : kRules) check_stacked(r, both, 1, rule, s.clip, empty, s.name + " (+150/-150)");
    }
    // Against the reference directly, too: a polygon stacked 300 / 301 times.
    const Contour tri{{1.2, 0.7}, {17.9, 6.3}, {5.1, 14.6}};
    check_polygons(r, Contours(300, tri), FillRule::NonZero, {0, 0, 20, 16}, "300 triangles");
    check_polygons(r, Contours(300, tri), FillRule::EvenOdd, {0, 0, 20, 16}, "300 triangles");
    check_polygons(r, Contours(301, tri), FillRule::EvenOdd, {0, 0, 20, 16}, "301 triangles");
}

TEST_CASE("fill rules: plain accumulation stays exact where the winding is simple", "[fillrule]") {
    // With exact_overlaps off the rasterizer only accumulates. Where no two contours meet and no
    // edges cross, the winding inside every pixel lies in one unit interval and the result must
    // still be exact; with it on, such shapes must not need the exact path at all.
    Rasterizer r;
    std::mt19937 rng(23);
    FillOptions plain;
    plain.exact_overlaps = false;
    for (int i = 0; i < 100; ++i) {
        const Contour s = random_simple_polygon(rng, {16.2, 16.6}, 3, 14, 5 + i % 12);
        for (FillRule rule : kRules) {
            plain.rule = rule;
            check_polygons(r, {s}, Affine::identity(), plain, {0, 0, 33, 33}, "simple polygon, plain accumulation");
        }
    }
    // The fast path is kept for simple shapes: no exact cells for a rectangle or a triangle.
    render(r, ref::to_path({rect(1.3, 2.7, 30.1, 20.9)}), Affine::identity(), {}, {0, 0, 32, 32});
    CHECK(r.last_stats().exact_cells == 0);
    render(r, ref::to_path({{{1.3, 2.7}, {30.1, 9.9}, {12.4, 29.6}}}), Affine::identity(), {}, {0, 0, 32, 32});
    CHECK(r.last_stats().exact_cells == 0);
    // And what the exact path costs on text: exact cells against partially covered pixels,
    // reported as a warning (no bound applies; every exact cell is cross-checked above).
    GlyphFont font(dejavu_sans_path());
    for (double px : {12.0, 24.0, 96.0}) {
        const Path p = font.text(U"Hamburgefonstiv 0123456789", px, {1, std::ceil(px)});
        const IRect clip = ref::pixel_bounds(ref::fine_flatten(p, Affine::identity()), 1);
        const Rendered out = render(r, p, Affine::identity(), {}, clip);
        std::size_t edge = 0;
        for (std::uint8_t v : out.cov) edge += v != 0 && v != 255;
        WARN("text at " << px << " px: " << out.stats.exact_cells << " exact cells for " << out.stats.segments
                        << " segments and " << edge << " partially covered pixels");
    }
}

TEST_CASE("fill rules: the overlap check accepts simple cells without exact computation, and no others", "[fillrule]") {
    Rasterizer r;
    // A hairpin whose tip turns back inside pixel (5, 5), going both ways in x and in y over four
    // edges without crossing itself: one simple run, no exact cell.
    const Contour hairpin{{1.0, 5.3}, {5.5, 5.5}, {5.8, 5.3}, {5.7, 5.7}, {1.0, 5.8}};
    // Two bars of 0.3 px inside one pixel column: four runs per pixel, windings 0 1 0 1 0.
    const Contours bars{rect(5.1, 2.0, 5.4, 10.0), rect(5.6, 2.0, 5.9, 10.0)};
    for (FillRule rule : kRules) {
        check_polygons(r, {hairpin}, rule, {0, 0, 8, 8}, "hairpin");
        CHECK(r.last_stats().exact_cells == 0);
        check_polygons(r, bars, rule, {0, 0, 8, 12}, "two thin bars in one pixel column");
        CHECK(r.last_stats().exact_cells == 0);
    }
    // The same bars overlapping (windings 0 1 2 1 0), one reversed (0 1 0 -1 0), a hairpin whose
    // tip crosses itself, and three bars: every pixel they share must be computed exactly.
    const Contours overlapping{rect(5.1, 2.0, 5.5, 10.0), rect(5.3, 2.0, 5.8, 10.0)};
    Contour reversed_bar = rect(5.6, 2.0, 5.9, 10.0);
    std::reverse(reversed_bar.begin(), reversed_bar.end());
    const Contours opposite{rect(5.1, 2.0, 5.4, 10.0), reversed_bar};
    const Contour crossed{{1.0, 5.3}, {5.8, 5.6}, {5.8, 5.3}, {5.5, 5.7}, {1.0, 5.8}};
    const Contours three{rect(5.05, 2.0, 5.25, 10.0), rect(5.4, 2.0, 5.6, 10.0), rect(5.5, 2.0, 5.95, 10.0)};
    for (FillRule rule : kRules) {
        check_polygons(r, overlapping, rule, {0, 0, 8, 12}, "two overlapping bars");
        CHECK(r.last_stats().exact_cells == 8);
        check_polygons(r, opposite, rule, {0, 0, 8, 12}, "two bars of opposite orientation");
        if (rule == FillRule::NonZero) CHECK(r.last_stats().exact_cells == 8);
        check_polygons(r, {crossed}, rule, {0, 0, 8, 8}, "hairpin crossing itself");
        CHECK(r.last_stats().exact_cells >= 1);
        check_polygons(r, three, rule, {0, 0, 8, 12}, "three bars, two overlapping");
        CHECK(r.last_stats().exact_cells == 8);
    }
}

TEST_CASE("fill rules: small closed loops inside one pixel are exact by accumulation only when the windings allow",
          "[fillrule]") {
    // A rectangle whose right side crosses pixel column 10, and small triangles with every vertex
    // inside pixel (10, 5): lakes left of the side (inside the rectangle), islands right of it. The
    // verdict is withheld (Overlapping), so every cell goes through the per-cell check.
    Rasterizer r;
    const Contour land = rect(1.0, 1.0, 10.3, 10.0);
    const double o = ref::signed_area(land) > 0 ? 1 : -1;
    auto triangle = [&](double x0, double sign) {  // sign +1: the land's orientation
        Contour t{{x0, 5.2}, {x0 + 0.15, 5.8}, {x0 + 0.05, 5.5}};
        if ((ref::signed_area(t) > 0 ? 1 : -1) != sign * o) std::reverse(t.begin(), t.end());
        return t;
    };
    struct Case {
        const char* name;
        Contours shape;
        bool harmless;  // the windings in the pixel take two values at most
    };
    const Case cases[] = {
        {"lake of the opposite orientation (windings 0, 1)", {land, triangle(10.05, -1)}, true},
        {"lake of the same orientation (windings 0, 1, 2)", {land, triangle(10.05, 1)}, false},
        {"island of the same orientation (windings 0, 1)", {land, triangle(10.6, 1)}, true},
        {"island of the opposite orientation (windings -1, 0, 1)", {land, triangle(10.6, -1)}, false},
        {"two islands alike, no side in the pixel", {triangle(10.05, 1), triangle(10.6, 1)}, true},
        {"two islands of opposite orientations, no side in the pixel", {triangle(10.05, 1), triangle(10.6, -1)}, false},
    };
    FillOptions opts;
    opts.topology = Topology::Overlapping;
    for (const Case& c : cases)
        for (FillRule rule : kRules) {
            opts.rule = rule;
            check_polygons(r, c.shape, Affine::identity(), opts, {0, 0, 12, 12}, c.name);
            INFO(c.name << " [" << rule_name(rule) << "]");
            if (c.harmless)
                CHECK(r.last_stats().exact_cells == 0);
            else if (rule == FillRule::NonZero)
                CHECK(r.last_stats().exact_cells >= 1);
        }
    // A pond on an island in a lake (windings 1, 0, 1 nested in the land): harmless.
    Contour pond{{10.1, 5.45}, {10.12, 5.6}, {10.11, 5.52}};
    if ((ref::signed_area(pond) > 0 ? 1 : -1) != o) std::reverse(pond.begin(), pond.end());
    const Contour lake{{10.02, 5.1}, {10.28, 5.1}, {10.28, 5.9}, {10.02, 5.9}};
    Contour lake_reversed = lake;
    if ((ref::signed_area(lake_reversed) > 0 ? 1 : -1) == o) std::reverse(lake_reversed.begin(), lake_reversed.end());
    for (FillRule rule : kRules) {
        opts.rule = rule;
        check_polygons(r, {land, lake_reversed, pond}, Affine::identity(), opts, {0, 0, 12, 12}, "pond in a lake");
        CHECK(r.last_stats().exact_cells == 0);
    }
}

TEST_CASE("fill rules: a run of 27 edges winding through one pixel is checked, not computed exactly", "[fillrule]") {
    // The contour enters pixel (5, 5) from the left, meanders down through it (right, down, left,
    // down, ...), climbs back along its right side and leaves: one run of 27 edges, monotone in
    // neither x nor y, that does not cross itself. A copy whose lower rungs reach across the climb
    // crosses itself there.
    const Contour meander = [] {
        Contour c{{1.0, 5.1}, {5.0, 5.1}};
        double y = 5.1;
        for (int k = 0; k < 12; ++k) {
            const bool right = k % 2 == 0;
            c.push_back({right ? 5.9 : 5.1, y});
            y += 0.055;
            c.push_back({right ? 5.9 : 5.1, y});
        }
        c.push_back({5.95, y});
        c.push_back({5.95, 5.05});
        c.push_back({6.5, 5.05});
        c.push_back({6.5, 9.0});
        c.push_back({1.0, 9.0});
        return c;
    }();
    Rasterizer r;
    FillOptions opts;
    opts.topology = Topology::Overlapping;
    for (FillRule rule : kRules) {
        opts.rule = rule;
        check_polygons(r, {meander}, Affine::identity(), opts, {0, 0, 8, 10}, "meander");
        CHECK(r.last_stats().exact_cells == 0);
    }
    Contour crossed = meander;
    for (Point& q : crossed)
        if (q.x == 5.9 && q.y > 5.6) q.x = 5.97;
    opts.rule = FillRule::NonZero;
    check_polygons(r, {crossed}, Affine::identity(), opts, {0, 0, 8, 10}, "meander crossing its climb");
    CHECK(r.last_stats().exact_cells >= 1);
}

TEST_CASE("fill rules: random small loops among a pixel's edges match the exact reference", "[fillrule]") {
    // Random polygons with random small triangles (inside one pixel each, either orientation):
    // whatever the per-cell check decides for the loops, the coverage is exact.
    Rasterizer r;
    std::mt19937 rng(91);
    std::uniform_real_distribution<double> u(0.05, 0.8);
    std::uniform_int_distribution<int> cell(2, 13);
    FillOptions opts;
    opts.topology = Topology::Overlapping;
    std::size_t loops_accepted = 0;
    for (int i = 0; i < 150; ++i) {
        Contours cs{random_simple_polygon(rng, {8.3, 8.6}, 2, 7, 5 + i % 8)};
        for (int k = 0; k < 1 + i % 4; ++k) {
            const double x = cell(rng) + u(rng) * 0.5, y = cell(rng) + u(rng) * 0.5;
            Contour t{{x, y}, {x + u(rng) * 0.2 + 0.1, y + u(rng) * 0.1}, {x + u(rng) * 0.1, y + u(rng) * 0.2 + 0.1}};
            if (rng() % 2) std::reverse(t.begin(), t.end());
            cs.push_back(t);
        }
        for (FillRule rule : kRules) {
            opts.rule = rule;
            check_polygons(r, cs, Affine::identity(), opts, {0, 0, 17, 17}, "polygon and small loops");
            if (r.last_stats().exact_cells == 0) ++loops_accepted;
        }
    }
    // Some shapes are decided harmless everywhere, so the accepting branch is exercised.
    CHECK(loops_accepted > 20);
}

TEST_CASE("fill rules regression: pixels outside 300 stacked pentagrams stay empty", "[fillrule]") {
    // Float accumulation residual: with 300 coincident contours the running sum across a row
    // carries an error of ~1/500 into pixels no edge touches (their winding is an integer), which
    // rounded to 1/255 at (17, 8) (outside the star) under both rules.
    Rasterizer r;
    const Contour star{{13.018785901284325, 1.3109043000444256},
                       {13.266556835215056, 18.80859004336746},
                       {2.7812243097794003, 4.7983010156981072},
                       {19.499077785348327, 9.9697391113538014},
                       {2.9343551683728979, 15.612465529536211}};
    for (FillRule rule : kRules) {
        const Rendered out =
            render(r, ref::to_path(Contours(300, star)), Affine::identity(), with_rule(rule), {0, 0, 21, 21});
        CHECK(out.at(17, 8) == 0);
        check_polygons(r, Contours(300, star), rule, {0, 0, 21, 21}, "300 pentagrams");
    }
}

TEST_CASE("fill rules: narrow shapes accumulate by rows as the cell walk does (exact overlaps off)", "[fillrule]") {
    // Without the overlap check, shapes a few SIMD vectors wide are accumulated by row vectors
    // (float, every pixel of a row per piece) and wider ones by the cell walk (double, prefix sums).
    // The same contours rendered alone (narrow) and with a tiny square 3000 px to the right (wide)
    // take the two paths; on the narrow part they must agree to rounding, under both rules, with
    // crossings, edges on pixel sides and on the box's sides, and windings of hundreds, on every SIMD
    // target this machine runs (the row width is a whole number of that target's vectors).
    Rasterizer r;
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> u(0, 1);
    FillOptions plain;
    plain.exact_overlaps = false;
    const Contour far = rect(3050.25, 10.5, 3051.75, 11.5);
    std::vector<Contours> shapes;
    for (int i = 0; i < 40; ++i) {
        Contours cs{random_simple_polygon(rng, {20 + u(rng), 20 + u(rng)}, 2, 18, 3 + i % 20)};
        if (i % 3 == 0) cs.push_back(star_polygon({20.5, 19.5}, 4 + 14 * u(rng), 7, 3, u(rng)));
        shapes.push_back(cs);
    }
    shapes.push_back({rect(0, 0, 40, 40), rect(3, 4, 17, 30)});              // sides on pixel sides and the box
    shapes.push_back({{{10, 2}, {10.00001, 37}, {30, 37}, {29.99999, 2}}});  // nearly vertical sides
    shapes.push_back(Contours(300, Contour{{2.3, 1.7}, {37.9, 12.2}, {9.4, 38.6}}));  // winding 300
    shapes.push_back(Contours(301, Contour{{2.3, 1.7}, {37.9, 12.2}, {9.4, 38.6}}));
    const IRect window{0, 0, 40, 40};
    int worst = 0, compared = 0;
    const std::vector<std::int64_t> targets = simd::available_targets();  // every SIMD width
    REQUIRE(!targets.empty());
    for (std::size_t n = 0; n < targets.size() * shapes.size(); ++n) {
        const std::int64_t t = targets[n / shapes.size()];
        const Contours& cs = shapes[n % shapes.size()];
        simd::restrict_targets(t);
        Contours wide = cs;
        wide.push_back(far);
        for (FillRule rule : kRules) {
            plain.rule = rule;
            const Rendered a = render(r, ref::to_path(cs), Affine::identity(), plain, window, window);
            const Rendered b = render(r, ref::to_path(wide), Affine::identity(), plain, {0, 0, 3100, 40}, window);
            REQUIRE(a.contract_violation.empty());
            REQUIRE(b.contract_violation.empty());
            for (int y = 0; y < 40; ++y)
                for (int x = 0; x < 40; ++x) {
                    const int d = std::abs(a.at(x, y) - b.at(x, y));
                    if (d > worst) {
                        worst = d;
                        INFO(simd::target_name(t)
                             << ": " << describe(cs, Affine::identity(), window) << " " << rule_name(rule) << " at "
                             << x << "," << y << ": " << a.at(x, y) << " vs " << b.at(x, y));
                        CHECK(d <= 1);
                    }
                    ++compared;
                }
        }
    }
    simd::restrict_targets(0);
    CHECK(worst <= 1);
    CHECK(compared == static_cast<int>(targets.size()) * 2 * 44 * 1600);
}

TEST_CASE("fill rules: proven-simple narrow shapes round half-way coverage up, as the exact area does", "[fillrule]") {
    // A shape given as Topology::Simple skips the overlap check; a narrow one is accumulated by
    // float row vectors. Rectangles with sides on quarter pixels and 45-degree triangles with
    // corners on half pixels cover every pixel by a multiple of 1/16 of its area, so the reference
    // (Sutherland-Hodgman + shoelace), snapped to sixteenths, is exact; a coverage of 0.5
    // (127.5 / 255) must come out as 128, on every SIMD target. Stems (vertical sides) and
    // diagonals both; the float lanes need the rounding bias in coverage.cpp for the triangles.
    // With a far square added, the same shapes go through the float cells of shapes too wide for
    // row vectors, whose prefix sums round the same way.
    Rasterizer r;
    std::mt19937 rng(41);
    auto half = [&](int n) { return std::uniform_int_distribution<int>(0, n)(rng) * 0.5; };
    auto quarter = [&](int n) { return std::uniform_int_distribution<int>(0, n)(rng) * 0.25; };
    std::vector<Contour> shapes;
    for (int i = 0; i < 60; ++i) {
        const double x0 = quarter(40), y0 = quarter(40);
        shapes.push_back(rect(x0, y0, x0 + 0.25 + quarter(80), y0 + 0.25 + quarter(60)));
    }
    for (int i = 0; i < 60; ++i) {
        const double x = 20 + half(20), y = half(20), a = 0.5 + half(30);
        const double s = i % 2 ? 1 : -1;  // right or left of the vertical side
        shapes.push_back(i % 4 < 2 ? Contour{{x, y}, {x + s * a, y + a}, {x, y + a}}
                                   : Contour{{x, y}, {x + s * a, y}, {x, y + a}});
    }
    // Right triangles with integer legs a, b and corners on half pixels: every pixel's area is a
    // multiple of 1 / (32 a b), and their diagonals give half-way values that are not dyadic.
    std::vector<double> grain(shapes.size(), 16.0);
    for (int i = 0; i < 200; ++i) {
        const int a = std::uniform_int_distribution<int>(1, 12)(rng),
                  b = std::uniform_int_distribution<int>(1, 12)(rng);
        const double x = 12 + half(30), y = half(40);
        shapes.push_back(Contour{{x, y}, {x + a, y}, {x, y + b}});
        grain.push_back(32.0 * a * b);
    }
    FillOptions simple;
    simple.topology = Topology::Simple;
    const IRect window{0, 0, 64, 64};
    const Contour far = rect(400, 10, 401, 11);
    int wrong = 0, ties = 0;
    const std::vector<std::int64_t> targets = simd::available_targets();
    REQUIRE(!targets.empty());
    for (std::int64_t t : targets)
        for (bool wide : {false, true}) {
            simd::restrict_targets(t);
            for (std::size_t k = 0; k < shapes.size(); ++k) {
                const Contour& c = shapes[k];
                const double g = k < grain.size() ? grain[k] : 16.0;
                const ref::CoverageGrid exact = ref::clip_area_simple(c, window);
                const Mask m = wide ? r.fill_mask(ref::to_path({c, far}), Affine::identity(), simple, {0, 0, 420, 64})
                                    : r.fill_mask(ref::to_path({c}), Affine::identity(), simple, window);
                for (int y = 0; y < 64; ++y)
                    for (int x = 0; x < 64; ++x) {
                        // Snapping to the shape's grain removes the reference's own rounding.
                        const double snapped = std::round(exact.at(x, y) * g) / g;
                        REQUIRE(std::abs(snapped - exact.at(x, y)) < 1e-9);
                        const double a = snapped * 255.0;
                        const int want = static_cast<int>(std::floor(a + 0.5));
                        ties += a - std::floor(a) == 0.5;
                        if (m.at(x, y) != want && ++wrong <= 5) {
                            INFO(simd::target_name(t)
                                 << (wide ? " (float cells)" : "") << ": " << describe({c}, Affine::identity(), window)
                                 << " at " << x << "," << y << ": " << int(m.at(x, y)) << ", exact " << a << "/255");
                            CHECK(m.at(x, y) == want);
                        }
                    }
            }
        }
    simd::restrict_targets(0);
    CHECK(wrong == 0);
    CHECK(ties > 100);  // the half-way values this test is about do occur
}

TEST_CASE("fill rules: a thin stroke outline folding back along its own ring", "[fillrule]") {
    // A ring that turns back along x = 2 (as a world map's rings do along the -180 meridian). Its
    // 0.8 px outline has a contour whose first edge lies on the pixel side x = 2 and whose last edge
    // ends there; in pixel (2, 3) the parts before and after that edge cross each other, so they
    // are two runs to check, not one run through the contour's start.
    Path ring;
    ring.move_to({2, 3.68});
    for (Point p : {Point{2, 3.45}, Point{2, -4.2}, Point{22, -4.2}, Point{32, 3.68}}) ring.line_to(p);
    ring.close();
    StrokeStyle style;
    style.width = 0.8;
    style.join = LineJoin::Round;
    const ref::Contours outline = ref::fine_flatten(stroke(ring, style), Affine::identity());
    Rasterizer r;
    check_polygons(r, outline, FillRule::NonZero, {-2, -6, 36, 6}, "folded ring outline");
}
