// The winding sweep (src/raster/winding_sweep.hpp): shapes that are not proven simple are
// replaced by the boundary of the region they fill, which plain accumulation renders exactly.
// Every pixel is compared with the independent exact reference (tests/support/reference_area.*);
// check_polygons also renders each shape through the per-cell overlap check.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include "accuracy_util.hpp"
#include "glyph_outline.hpp"

using namespace casteljau;
using namespace casteljau::testing;
using ref::Contour;
using ref::Contours;

namespace {

// Renders with default options and checks that the sweep, not the overlap check, made it exact.
Comparison check_swept(Rasterizer& r, const Contours& shape, FillRule rule, const IRect& clip,
                       const std::string& what) {
    FillOptions o;
    o.rule = rule;
    o.topology = Topology::Overlapping;
    const Rendered out = render(r, ref::to_path(shape), Affine::identity(), o, clip);
    INFO(what);
    CHECK(out.stats.swept);
    CHECK(out.stats.exact_cells == 0);
    return check_polygons(r, shape, Affine::identity(), o, clip, what);
}

// A random polygon of n vertices in [0, size)^2: it crosses itself about n^2 / 10 times.
Contour scribble(std::mt19937& rng, int n, double size) {
    std::uniform_real_distribution<double> u(0.0, size);
    Contour c;
    for (int i = 0; i < n; ++i) c.push_back({u(rng), u(rng)});
    return c;
}

// The largest |difference| of two renders over their clip.
int max_difference(const Rendered& a, const Rendered& b) {
    int worst = 0;
    for (int y = a.clip.y0; y < a.clip.y1; ++y)
        for (int x = a.clip.x0; x < a.clip.x1; ++x) worst = std::max(worst, std::abs(a.at(x, y) - b.at(x, y)));
    return worst;
}

}  // namespace

TEST_CASE("winding sweep: random self-crossing polygons, both rules", "[raster][sweep]") {
    Rasterizer r;
    std::mt19937 rng(20261130);
    for (int i = 0; i < 60; ++i) {
        const int n = 3 + i % 9;
        const double size = 4 + 40 * ((i * 7) % 11) / 10.0;
        Contours shape{scribble(rng, n, size)};
        if (i % 3 == 0) shape.push_back(scribble(rng, n, size));  // a second contour over the first
        const int side = static_cast<int>(size) + 1;
        for (FillRule rule : kRules) check_swept(r, shape, rule, {0, 0, side, side}, "scribble " + std::to_string(i));
    }
}

TEST_CASE("winding sweep: stacked, touching and nested contours", "[raster][sweep]") {
    Rasterizer r;
    const IRect clip{0, 0, 24, 24};
    for (FillRule rule : kRules) {
        // An exact copy: windings 0 and 2, the region of one square.
        check_swept(r, {rect(2.3, 2.3, 17.6, 15.2), rect(2.3, 2.3, 17.6, 15.2)}, rule, clip, "stacked copy");
        // Two squares sharing a side, the same way round: no seam along it.
        check_swept(r, {rect(2.3, 2.3, 9.5, 15.2), rect(9.5, 2.3, 17.6, 15.2)}, rule, clip, "shared side");
        // A hole the other way round, and an island inside it.
        check_swept(r, {rect(2.3, 2.3, 20.6, 20.2), reversed(rect(5.5, 5.5, 15.1, 15.1)), rect(8.2, 8.2, 9.9, 12.7)},
                    rule, clip, "hole and island");
        // Overlapping squares of opposite orientations: windings -1, 0 and 1 side by side.
        check_swept(r, {rect(2.3, 2.3, 12.6, 12.2), reversed(rect(7.5, 7.5, 20.1, 18.1))}, rule, clip,
                    "opposite orientations");
        // A bow-tie whose crossing lies on a pixel corner, and one whose crossing is inside a pixel.
        check_swept(r, {{{2, 2}, {12, 12}, {12, 2}, {2, 12}}}, rule, clip, "bow-tie on a corner");
        check_swept(r, {{{2.3, 2.1}, {12.7, 13.3}, {12.2, 2.6}, {2.5, 12.9}}}, rule, clip, "bow-tie");
    }
    // Every pixel of the shared side is full: the two halves meet without a seam.
    const Rendered out = render(r, ref::to_path({rect(2.3, 2.3, 9.5, 15.2), rect(9.5, 2.3, 17.6, 15.2)}),
                                Affine::identity(), FillOptions{}, clip);
    for (int y = 3; y < 15; ++y) CHECK(out.at(9, y) == 255);
}

// Shapes that wind 0 and one other value only keep their own edges; the sweep must find every
// other value, or the crossing that makes one, and then keep only the region's boundary.
TEST_CASE("winding sweep: shapes winding one value keep their edges, others do not", "[raster][sweep]") {
    Rasterizer r;
    const IRect clip{0, 0, 24, 24};
    struct Case {
        const char* what;
        Contours shape;
        bool one_value;
    };
    const std::vector<Case> cases{
        {"square", {rect(2.3, 2.3, 17.6, 15.2)}, true},
        {"square the other way round", {reversed(rect(2.3, 2.3, 17.6, 15.2))}, true},
        {"hole and island",
         {rect(2.3, 2.3, 20.6, 20.2), reversed(rect(5.5, 5.5, 15.1, 15.1)), rect(8.2, 8.2, 9.9, 12.7)},
         true},
        // Steps: a horizontal edge between two edges going down ends one chain and starts another.
        {"staircase", {{{2.5, 2.5}, {2.5, 8.5}, {6.5, 8.5}, {6.5, 16.5}, {14.5, 16.5}, {14.5, 2.5}}}, true},
        {"two apart", {rect(2.3, 2.3, 8.6, 15.2), rect(12.5, 2.5, 20.1, 18.1)}, true},
        // Windings 1 and -1, apart here, but the test is for the whole shape.
        {"two apart, opposite orientations", {rect(2.3, 2.3, 8.6, 15.2), reversed(rect(12.5, 2.5, 20.1, 18.1))}, false},
        {"stacked copy", {rect(2.3, 2.3, 17.6, 15.2), rect(2.3, 2.3, 17.6, 15.2)}, false},
        {"island the same way round as its square", {rect(2.3, 2.3, 20.6, 20.2), rect(5.5, 5.5, 15.1, 15.1)}, false},
        {"opposite orientations", {rect(2.3, 2.3, 12.6, 12.2), reversed(rect(7.5, 7.5, 20.1, 18.1))}, false},
        // Strips winding -1 only above the first that is not simple: they must keep winding the
        // same way as the region's boundary below them.
        {"opposite orientations, the reversed one above",
         {reversed(rect(2.3, 2.3, 12.6, 12.2)), rect(7.5, 7.5, 20.1, 18.1)},
         false},
        {"bow-tie", {{{2.3, 2.1}, {12.7, 13.3}, {12.2, 2.6}, {2.5, 12.9}}}, false},
        // A side crossed twice in one strip (no chain starts or ends between the crossings), by a
        // contour of either orientation.
        {"zigzag over a side", {rect(5, 2, 12, 20), {{4, 2}, {6, 10}, {4, 18}, {1, 18}, {1, 2}}}, false},
        {"zigzag over a side, reversed",
         {rect(5, 2, 12, 20), reversed({{4, 2}, {6, 10}, {4, 18}, {1, 18}, {1, 2}})},
         false},
        // Two contours meeting at one point: the first's bottom is the second's top, or a corner
        // of one touches a side of the other from outside.
        {"diamonds corner to corner",
         {{{10, 2}, {14, 10}, {10, 18}, {6, 10}}, {{10, 18}, {14, 20}, {10, 22}, {6, 20}}},
         true},
        {"corner on a side", {rect(2, 2, 10, 20), {{10, 8}, {18, 4}, {18, 14}}}, true},
        {"corner through a side", {rect(2, 2, 10, 20), {{9.5, 8}, {18, 4}, {18, 14}}}, false},
        // A contour starting (its top) at a point of another's side, inside it: windings 1 and 2.
        {"inner wedge from a side", {rect(2, 2, 18, 20), {{2, 6}, {12, 14}, {6, 16}}}, false},
        // Chains a and b are neighbours, then c passes between them and leaves; below it, a
        // crosses b (the crossing can only be found over the height a and b span together).
        {"crossing below a passing contour",
         {{{3, 2}, {9, 20}, {1, 20}}, {{8, 2}, {10, 2}, {4, 21}, {2, 21}}, {{5.5, 1}, {6.5, 1}, {6, 6}}},
         false},
        {"no crossing below a passing contour",
         {{{1, 2}, {3, 2}, {3, 20}, {1, 20}}, {{8, 2}, {10, 2}, {10, 21}, {8, 21}}, {{5.5, 1}, {6.5, 1}, {6, 6}}},
         true},
        // Many nested rings, alternating orientation: every chain has a neighbour on either side.
        {"nested rings",
         {rect(1, 1, 22, 22), reversed(rect(3, 3, 20, 20)), rect(5, 5, 18, 18), reversed(rect(7, 7, 16, 16)),
          rect(9, 9, 14, 14)},
         true},
    };
    for (const Case& c : cases)
        for (FillRule rule : kRules) {
            FillOptions o;
            o.rule = rule;
            o.topology = Topology::Overlapping;
            const Rendered out = render(r, ref::to_path(c.shape), Affine::identity(), o, clip);
            INFO(c.what);
            CHECK(out.stats.swept);
            CHECK(out.stats.swept_simple == c.one_value);
            check_swept(r, c.shape, rule, clip, c.what);
        }
}

TEST_CASE("winding sweep: a shape it proves simple renders as with the verdict given", "[raster][sweep]") {
    // Once proven, the shape's edges go to the engine as they came, in outline order: the same
    // pieces in the same order as a fill told the shape is simple, so the same bits. Lines of real
    // glyphs (TrueType quadratics and CFF cubics) at text and display sizes, inside the target
    // (flattened in batches of points), and a ring reaching past the target's left side (its
    // edges clipped one by one).
    Rasterizer r;
    auto same = [&](const Path& p, const IRect& clip, const std::string& what) {
        for (FillRule rule : kRules) {
            FillOptions swept;
            swept.rule = rule;
            FillOptions given = swept;
            given.topology = Topology::Simple;
            const Rendered a = render(r, p, Affine::identity(), swept, clip);
            const Rendered v = render(r, p, Affine::identity(), given, clip);
            INFO(what);
            REQUIRE(a.stats.swept);
            CHECK(a.stats.swept_simple);
            CHECK(!v.stats.swept);
            CHECK(a.cov == v.cov);
        }
    };
    for (const std::string& font :
         {dejavu_sans_path(), std::string(CASTELJAU_SOURCE_DIR) + "/fonts/LinLibertine_R.otf"}) {
        const GlyphFont g(font);
        for (double px : {12.0, 40.0}) {
            const Path p = g.text(U"Casteljau Bezier", px, {1.25, px + 0.5});
            const Rect b = p.control_bounds();
            same(p, IRect{0, 0, static_cast<int>(b.x1) + 2, static_cast<int>(b.y1) + 2},
                 font + " at " + std::to_string(px) + " px");
        }
    }
    // The inner ellipse the other way round: a ring winding one value.
    Path p;
    p.add_ellipse({6.3, 20.7}, 17.2, 12.9);
    p.append(Path().add_ellipse({6.3, 20.7}, 9.4, 6.1).reversed());
    same(p, IRect{0, 0, 40, 40}, "ring past the left side");
}

TEST_CASE("winding sweep: edges of subnormal height", "[raster][sweep]") {
    // A zigzag whose edges rise by 1e-309 px each (subnormal heights) while moving by 0.1875 px:
    // a strip's edge taken at a y inside one of them must not divide the width by the height
    // first (that overflows to infinity, and an infinite x reaches the cell walk).
    Contour zigzag{{0, 0}};
    for (int i = 1; i <= 556; ++i) {
        const int k = i / 2;
        zigzag.push_back({i % 2 ? 0.1875 * (k - 1) : 0.1875 * k, i * 1.0846046641719174e-309});
    }
    zigzag.push_back({1, 262});
    zigzag.push_back({225, 225});
    Rasterizer r;
    for (FillRule rule : kRules) check_swept(r, {zigzag}, rule, {-32, -50, 206, 58}, "subnormal zigzag");
}

TEST_CASE("winding sweep: shapes reaching outside the target", "[raster][sweep]") {
    Rasterizer r;
    std::mt19937 rng(7);
    for (int i = 0; i < 20; ++i) {
        Contours shape{scribble(rng, 7, 40), scribble(rng, 5, 40)};
        for (Contour& c : shape)
            for (Point& p : c) p = {p.x - 10, p.y - 8};  // parts left of and above the target
        for (FillRule rule : kRules)
            check_swept(r, shape, rule, {0, 0, 20, 22}, "clipped scribble " + std::to_string(i));
    }
}

TEST_CASE("winding sweep: curved glyph-like shapes agree with the overlap check", "[raster][sweep]") {
    Rasterizer r;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0.0, 30.0);
    for (int i = 0; i < 40; ++i) {
        Path p;
        for (int c = 0; c < 2; ++c) {
            p.move_to({u(rng), u(rng)});
            p.cubic_to({u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)});
            p.quad_to({u(rng), u(rng)}, {u(rng), u(rng)});
            p.close();
        }
        for (FillRule rule : kRules) {
            FillOptions swept;
            swept.rule = rule;
            swept.topology = Topology::Overlapping;
            FillOptions cells = swept;
            cells.winding_sweep = false;
            const IRect clip{0, 0, 31, 31};
            const Rendered a = render(r, p, Affine::identity(), swept, clip);
            const Rendered b = render(r, p, Affine::identity(), cells, clip);
            REQUIRE(a.stats.swept);
            REQUIRE(!b.stats.swept);
            INFO("path " << i);
            CHECK(max_difference(a, b) <= 1);
            check_curves(r, p, Affine::identity(), swept, clip, "curves " + std::to_string(i));
        }
    }
}

TEST_CASE("winding sweep: too many crossings for the budget go to the overlap check", "[raster][sweep]") {
    Rasterizer r;
    // 60 thin bars at random angles through one 40 x 40 square: about 1,800 crossings for 240
    // edges, more strips than the sweep's budget allows.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Contours bars;
    for (int i = 0; i < 60; ++i) {
        const double a = 3.14159 * u(rng), cx = 15 + 10 * u(rng), cy = 15 + 10 * u(rng);
        const double dx = 18 * std::cos(a), dy = 18 * std::sin(a), nx = -0.2 * std::sin(a), ny = 0.2 * std::cos(a);
        bars.push_back({{cx - dx - nx, cy - dy - ny},
                        {cx + dx - nx, cy + dy - ny},
                        {cx + dx + nx, cy + dy + ny},
                        {cx - dx + nx, cy - dy + ny}});
    }
    const IRect clip{0, 0, 42, 42};
    for (FillRule rule : kRules) {
        FillOptions o;
        o.rule = rule;
        o.topology = Topology::Overlapping;
        const Rendered out = render(r, ref::to_path(bars), Affine::identity(), o, clip);
        CHECK(!out.stats.swept);
        CHECK(out.stats.exact_cells > 0);
        check_polygons(r, bars, Affine::identity(), o, clip, "60 crossing bars");
    }
    // A few of them stay within the budget.
    const Contours few(bars.begin(), bars.begin() + 4);
    for (FillRule rule : kRules) check_swept(r, few, rule, clip, "4 crossing bars");
}
