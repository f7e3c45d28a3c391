// Accuracy of the rasterizer's 8-bit coverage against the independent exact-area reference
// (tests/support/reference_area.*): polygons must be exact to within 1/255 per pixel (rounding only);
// curved shapes at the default tolerance within a mean of 0.5/255 and a max of 8/255 of the finely
// flattened curve. Every case also checks the SpanSink contract (rows in order, inside the clip).
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "accuracy_util.hpp"
#include "alloc_counter.hpp"
#include "glyph_outline.hpp"
#include "../fuzz/stroke_case.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/stroke.hpp"

using namespace casteljau;
using namespace casteljau::testing;
using ref::Contour;
using ref::Contours;

TEST_CASE("accuracy: axis-aligned rectangles at fractional coordinates", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    // Worked numbers: [0.25, 3.75] x [1.5, 2.5] covers pixel (0, 1) by 0.75 x 0.5 -> 96 (95.625),
    // pixel (1, 1) by 0.5 -> 128 (127.5 rounds up), pixel (3, 2) by 0.75 x 0.5 -> 96.
    {
        const Rendered out =
            render(r, ref::to_path({rect(0.25, 1.5, 3.75, 2.5)}), Affine::identity(), {}, {0, 0, 5, 4});
        CHECK(out.at(0, 1) == 96);
        CHECK(out.at(1, 1) == 128);
        CHECK(out.at(2, 2) == 128);
        CHECK(out.at(3, 2) == 96);
        CHECK(out.at(4, 1) == 0);
        CHECK(out.at(1, 0) == 0);
        CHECK(out.at(1, 3) == 0);
    }
    // An integer-aligned rectangle is exactly 255 inside and 0 outside.
    {
        const Rendered out = render(r, ref::to_path({rect(2, 3, 7, 5)}), Affine::identity(), {}, {0, 0, 10, 8});
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 10; ++x) {
                INFO("pixel " << x << "," << y);
                CHECK(out.at(x, y) == ((x >= 2 && x < 7 && y >= 3 && y < 5) ? 255 : 0));
            }
    }
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(-2.0, 34.0), size(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        const double x0 = u(rng), y0 = u(rng);
        // Widths from sub-pixel (1e-3) to 20 px, on a log scale.
        const double w = std::pow(10.0, -3 + 4.3 * size(rng)), h = std::pow(10.0, -3 + 4.3 * size(rng));
        Contour c = rect(x0, y0, x0 + w, y0 + h);
        if (i % 2) c = reversed(c);
        for (FillRule rule : kRules)
            worst.add(check_polygons(r, {c}, rule, {0, 0, 32, 32}, "rect " + std::to_string(i)),
                      "rect " + std::to_string(i));
        // The same through Path::add_rect.
        Path p;
        p.add_rect({x0, y0, x0 + w, y0 + h});
        const Rendered a = render(r, p, Affine::identity(), {}, {0, 0, 32, 32});
        const Rendered b = render(r, ref::to_path({c}), Affine::identity(), {}, {0, 0, 32, 32});
        REQUIRE(a.cov == b.cov);
    }
    WARN("rectangles: " << worst.text());
}

TEST_CASE("accuracy: random triangles", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(2);
    for (int i = 0; i < 400; ++i) {
        const double s = std::pow(10.0, -1 + 2.7 * std::uniform_real_distribution<double>(0, 1)(rng));
        std::uniform_real_distribution<double> c(0, 24);
        const Point o{c(rng), c(rng)};
        std::uniform_real_distribution<double> d(-s, s);
        const Contour t{{o.x + d(rng), o.y + d(rng)}, {o.x + d(rng), o.y + d(rng)}, {o.x + d(rng), o.y + d(rng)}};
        for (FillRule rule : kRules)
            worst.add(check_polygons(r, {t}, rule, {0, 0, 24, 24}, "triangle " + std::to_string(i)),
                      "triangle " + std::to_string(i));
    }
    WARN("triangles: " << worst.text());
}

TEST_CASE("accuracy: random simple and self-intersecting polygons", "[accuracy]") {
    Rasterizer r;
    Worst simple, crossing, multi;
    std::mt19937 rng(3);
    for (int i = 0; i < 300; ++i) {
        const int n = 3 + i % 30;
        const Contour s = random_simple_polygon(rng, {16.3, 15.7}, 1 + (i % 5), 6 + (i % 9), n);
        for (FillRule rule : kRules)
            simple.add(check_polygons(r, {s}, rule, {0, 0, 32, 32}, "simple " + std::to_string(i)),
                       "simple " + std::to_string(i));
    }
    for (int i = 0; i < 300; ++i) {
        const int n = 4 + i % 25;
        const Contour s = random_polygon(rng, {1.5, 0.5, 30.2, 22.9}, n);
        for (FillRule rule : kRules)
            crossing.add(check_polygons(r, {s}, rule, {0, 0, 32, 24}, "self-intersecting " + std::to_string(i)),
                         "self-intersecting " + std::to_string(i));
    }
    // Sets of several contours in random orientations, overlapping each other.
    for (int i = 0; i < 150; ++i) {
        Contours set;
        for (int k = 0; k < 2 + i % 4; ++k) {
            Contour c = (k % 2) ? random_polygon(rng, {2, 2, 22, 22}, 3 + (i + k) % 6)
                                : random_simple_polygon(rng, {12, 12}, 2, 9, 5 + (i * k) % 11);
            if ((i >> k) & 1) c = reversed(c);
            set.push_back(c);
        }
        for (FillRule rule : kRules)
            multi.add(check_polygons(r, set, rule, {0, 0, 24, 24}, "set " + std::to_string(i)),
                      "set " + std::to_string(i));
    }
    WARN("simple polygons: " << simple.text());
    WARN("self-intersecting polygons: " << crossing.text());
    WARN("overlapping contour sets: " << multi.text());
}

TEST_CASE("accuracy: two edges from one vertex outside a pixel, crossing it", "[accuracy]") {
    // The overlap check decides a pixel crossed by two single edges of one contour that meet at a
    // vertex outside it (the contour leaves and comes back) in closed form: the winding takes two
    // values there. Two edges that both leave the vertex (two contours touching at it) do not
    // qualify: the pixel's part between them has a third winding, and accumulation is wrong there.
    Rasterizer r;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> y(0.05, 0.95), far(2.0, 30.0);
    for (int i = 0; i < 200; ++i) {
        // Vertex V left of the pixel column x in [5, 6], rays through it to x = 40.
        const double vy = 8 + y(rng), ay = 8 + y(rng), by = 8 + y(rng);
        const Point v{0.5 + 3 * y(rng), vy}, p{40, ay}, q{40, by};
        const Contour wedge{p, v, q};                    // ... -> p -> V -> q -> ...
        const Contour below{v, p, {40, ay + far(rng)}};  // V -> p first
        const Contour above{v, q, {40, by - far(rng)}};  // V -> q first
        for (FillRule rule : kRules) {
            check_polygons(r, {wedge}, rule, {0, 0, 48, 40}, "wedge " + std::to_string(i));
            check_polygons(r, {below, above}, rule, {0, 0, 48, 40}, "touching at V " + std::to_string(i));
            check_polygons(r, {below, reversed(above)}, rule, {0, 0, 48, 40},
                           "touching at V, one reversed " + std::to_string(i));
        }
    }
}

TEST_CASE("accuracy: a contour that comes back into a pixel and crosses itself there", "[accuracy]") {
    // Edge A crosses the pixel [10, 11] x [10, 11] to a vertex V right of it, edge B comes back
    // from V and ends on the pixel's bottom side, and edge C goes on from there up through the
    // pixel, crossing A inside it. A and B alone are the pair the walk lets pass without a check
    // (Engine::returns_harmlessly); C continues B's run in the same pixel, which must bring the
    // pixel back to the overlap check, since accumulation is wrong where C crosses A.
    Rasterizer r;
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> j(-0.08, 0.08);
    for (int i = 0; i < 100; ++i) {
        const Point p{8.5 + j(rng), 10.3 + j(rng)}, v{12.5 + j(rng), 10.7 + j(rng)};
        const Point w{10.5 + j(rng), 11.0}, q{10.1 + j(rng), 9.5 + j(rng)};
        for (const Contour& c : {Contour{p, v, w, q}, Contour{q, w, v, p}})
            for (FillRule rule : kRules) {
                FillOptions o;
                o.rule = rule;
                o.topology = Topology::Overlapping;
                check_polygons(r, {c}, Affine::identity(), o, {0, 0, 24, 20}, "comes back " + std::to_string(i));
            }
    }
}

TEST_CASE("accuracy: three runs in a pixel that meet only outside it", "[accuracy]") {
    // A triangle round the pixel [20, 21] x [20, 21] with its vertex V just above it and p, q on
    // either side: all three sides cross the pixel, and each two meet at a vertex outside it. Their
    // parts inside do not meet and the winding round the pixel's boundary takes two values, so
    // accumulation is exact there: the overlap check (forced) marks no exact cell.
    Rasterizer r;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    std::size_t exact_cells = 0;
    for (int i = 0; i < 100; ++i) {
        const Point v{20.5 + jitter(rng), 19.9 + jitter(rng)};
        const Point p{18.5 + jitter(rng), 20.7 + jitter(rng)}, q{22.5 + jitter(rng), 20.7 + jitter(rng)};
        for (const Contour& c : {Contour{p, v, q}, Contour{q, v, p}})
            for (FillRule rule : kRules) {
                FillOptions o;
                o.rule = rule;
                o.topology = Topology::Overlapping;
                check_polygons(r, {c}, Affine::identity(), o, {0, 0, 40, 40}, "triangle " + std::to_string(i));
                exact_cells += r.last_stats().exact_cells;
            }
    }
    CHECK(exact_cells == 0);
}

TEST_CASE("accuracy: thin slivers", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 200; ++i) {
        // A long thin quadrilateral (width 1e-5 .. 0.3 px) at a random angle through the canvas.
        const double ang = kPi * u(rng), len = 5 + 30 * u(rng), wid = std::pow(10.0, -5 + 4.5 * u(rng));
        const Point c{4 + 24 * u(rng), 4 + 24 * u(rng)};
        const Point d{std::cos(ang) * len / 2, std::sin(ang) * len / 2};
        const Point nrm{-std::sin(ang) * wid / 2, std::cos(ang) * wid / 2};
        const Contour q{c - d - nrm, c + d - nrm, c + d + nrm, c - d + nrm};
        for (FillRule rule : kRules)
            worst.add(check_polygons(r, {q}, rule, {0, 0, 32, 32}, "sliver " + std::to_string(i)),
                      "sliver " + std::to_string(i));
        // A needle triangle (apex angle tiny).
        const Contour t{c - d, c + d - nrm, c + d + nrm};
        worst.add(check_polygons(r, {t}, FillRule::NonZero, {0, 0, 32, 32}, "needle " + std::to_string(i)),
                  "needle " + std::to_string(i));
    }
    // Axis-aligned slivers: a horizontal and a vertical strip of height/width 1/1024.
    worst.add(
        check_polygons(r, {rect(1.1, 5.25, 20.7, 5.25 + 1.0 / 1024)}, FillRule::NonZero, {0, 0, 24, 12}, "h strip"),
        "h strip");
    worst.add(check_polygons(r, {rect(5.5, 0.3, 5.5 + 1.0 / 1024, 11.2)}, FillRule::NonZero, {0, 0, 24, 12}, "v strip"),
              "v strip");
    WARN("slivers: " << worst.text());
}

TEST_CASE("accuracy: polygons at huge offsets translated back by the transform", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(5);
    for (double ox : {1e7, -1e7, 0.0})
        for (double oy : {1e7, -1e7, 0.0}) {
            for (int i = 0; i < 15; ++i) {
                Contour local = (i % 3 == 0) ? random_polygon(rng, {0.5, 0.5, 15.5, 15.5}, 7)
                                             : random_simple_polygon(rng, {8.2, 7.9}, 1, 7.5, 4 + i);
                Contour far = local;
                for (Point& p : far) p = {p.x + ox, p.y + oy};
                const Affine back = Affine::translate(-ox, -oy);
                FillOptions o;
                for (FillRule rule : kRules) {
                    o.rule = rule;
                    const std::string what =
                        "offset (" + std::to_string(ox) + ", " + std::to_string(oy) + ") #" + std::to_string(i);
                    worst.add(check_polygons(r, {far}, back, o, {0, 0, 16, 16}, what), what);
                }
            }
        }
    WARN("huge offsets: " << worst.text());
}

TEST_CASE("accuracy: polygons whose corners a transform puts on whole pixels, the box's sides", "[accuracy]") {
    // The shape's box comes from its transformed control points, its edges from the transform
    // composed with the box's offset: the two round differently, so a corner on the box's side can
    // reach the engine a rounding step outside the box (below 0, or past its width or height).
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> scale(0.3, 3.0), shift(-40.0, 40.0), frac(0.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const double s = scale(rng), ex = shift(rng), ey = shift(rng);
        // A user coordinate that the transform maps to pixel k, up to rounding.
        auto ux = [&](double k) { return (k - ex) / s; };
        auto uy = [&](double k) { return (k - ey) / s; };
        const double x0 = std::floor(4 * frac(rng)), y0 = std::floor(4 * frac(rng));
        const double x1 = x0 + 1 + std::floor(7 * frac(rng)), y1 = y0 + 1 + std::floor(7 * frac(rng));
        const Contour box{{ux(x0), uy(y0)}, {ux(x1), uy(y0)}, {ux(x1), uy(y1)}, {ux(x0), uy(y1)}};
        const Contour tri{{ux(x0), uy(y1)}, {ux(x1), uy(y0)}, {ux(x1), uy(y1)}};
        const Affine m{s, 0, 0, s, ex, ey};
        FillOptions o;
        for (const Contour& c : {box, tri}) {
            const std::string what = "scale " + std::to_string(s) + " #" + std::to_string(i);
            worst.add(check_polygons(r, {c}, m, o, {0, 0, 12, 12}, what), what);
        }
    }
    WARN("corners on whole pixels: " << worst.text());
}

TEST_CASE("accuracy: polygons partly outside the target on every side", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(6);
    const IRect clip{10, 20, 42, 44};  // not at the origin
    std::uniform_real_distribution<double> u(0, 1);
    for (int side = 0; side < 4; ++side) {
        for (int i = 0; i < 40; ++i) {
            // A polygon centred near one side of the clip (or a corner when i is odd), larger than
            // the distance to it, so that part lies outside.
            Point c{26 + 10 * (u(rng) - 0.5), 32 + 8 * (u(rng) - 0.5)};
            if (side == 0) c.x = 10 + 4 * (u(rng) - 0.5);
            if (side == 1) c.x = 42 + 4 * (u(rng) - 0.5);
            if (side == 2) c.y = 20 + 4 * (u(rng) - 0.5);
            if (side == 3) c.y = 44 + 4 * (u(rng) - 0.5);
            if (i % 2) c = {side < 2 ? c.x : (i % 4 == 1 ? 10.3 : 41.6), side < 2 ? (i % 4 == 1 ? 20.4 : 43.8) : c.y};
            const Contour p = (i % 3 == 0) ? random_polygon(rng, {c.x - 9, c.y - 9, c.x + 9, c.y + 9}, 6 + i % 5)
                                           : random_simple_polygon(rng, c, 2, 12, 5 + i % 9);
            for (FillRule rule : kRules) {
                const std::string what = "side " + std::to_string(side) + " #" + std::to_string(i);
                worst.add(check_polygons(r, {p}, rule, clip, what), what);
            }
        }
    }
    // Bigger than the clip on all sides: every pixel full.
    {
        const Rendered out =
            render(r, ref::to_path({rect(-100.5, -50.25, 400.75, 300.5)}), Affine::identity(), {}, clip);
        for (std::uint8_t v : out.cov) REQUIRE(v == 255);
        CHECK(out.rows_delivered == static_cast<std::size_t>(clip.height()));
    }
    // Crossing the clip on all sides at once (a rotated square larger than the clip).
    {
        const Contour big = regular_polygon({26.5, 31.7}, 24, 4, true, 0.3);
        for (FillRule rule : kRules)
            worst.add(check_polygons(r, {big}, rule, clip, "big rotated square"), "big rotated square");
    }
    WARN("partly outside: " << worst.text());
}

TEST_CASE("accuracy: tiny polygons inside one pixel", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 200; ++i) {
        const double s = std::pow(10.0, -4 + 3.5 * u(rng));  // size 1e-4 .. 0.3 px
        const Point c{3 + u(rng), 2 + u(rng)};
        const Contour p = (i % 2) ? random_simple_polygon(rng, c, 0.2 * s, s, 3 + i % 6)
                                  : random_polygon(rng, {c.x - s, c.y - s, c.x + s, c.y + s}, 3 + i % 5);
        for (FillRule rule : kRules)
            worst.add(check_polygons(r, {p}, rule, {0, 0, 8, 6}, "tiny " + std::to_string(i)),
                      "tiny " + std::to_string(i));
    }
    // Worked number: a 0.5 x 0.5 square inside pixel (2, 3): 63.75 -> 64.
    const Rendered out = render(r, ref::to_path({rect(2.2, 3.3, 2.7, 3.8)}), Affine::identity(), {}, {0, 0, 8, 6});
    CHECK(out.at(2, 3) == 64);
    int nonzero = 0;
    for (std::uint8_t v : out.cov) nonzero += v != 0;
    CHECK(nonzero == 1);
    WARN("tiny polygons: " << worst.text());
}

TEST_CASE("accuracy: a polygon with many vertices inside one pixel", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(8);
    // 2000-vertex simple polygon, radius 0.05 .. 0.45 around the pixel centre.
    const Contour many = random_simple_polygon(rng, {5.5, 4.5}, 0.05, 0.45, 2000);
    for (FillRule rule : kRules)
        worst.add(check_polygons(r, {many}, rule, {0, 0, 10, 8}, "2000-gon in a pixel"), "2000-gon");
    // 500 random vertices inside one pixel: hundreds of crossings.
    const Contour scribble = random_polygon(rng, {5.02, 4.03, 5.97, 4.98}, 500);
    for (FillRule rule : kRules)
        worst.add(check_polygons(r, {scribble}, rule, {0, 0, 10, 8}, "500-vertex scribble"), "scribble");
    // Many vertices straddling a pixel corner.
    const Contour corner = random_simple_polygon(rng, {6.0, 3.0}, 0.1, 0.6, 1000);
    for (FillRule rule : kRules)
        worst.add(check_polygons(r, {corner}, rule, {0, 0, 10, 8}, "1000-gon on a corner"), "corner");
    WARN("many vertices: " << worst.text());
}

// A shape piling hundreds of crossing pieces into each of dozens of pixels (a scribble, or the
// stroke of a long zig-zag with round joins) would cost the exact method time quadratic in its
// size; the fill's exact-work budget bounds it in proportion to the fill (exact_cell.cpp) and the
// cells past it are integrated line by line, still within 1/32 of a pixel of the exact area.
TEST_CASE("accuracy: thousands of pieces over many pixels stay within the fill's exact-work budget", "[accuracy]") {
    Rasterizer r;
    std::mt19937 rng(12);
    const Contour pile = random_polygon(rng, {2.05, 2.1, 7.9, 7.95}, 1500);
    const IRect clip{0, 0, 10, 10};
    for (FillRule rule : kRules) {
        FillOptions o;
        o.rule = rule;
        const Rendered out = render(r, ref::to_path({pile}), Affine::identity(), o, clip);
        const RasterStats st = r.last_stats();
        INFO("exact cells " << st.exact_cells << ", dense " << st.dense_cells << ", work " << st.exact_work);
        CHECK(st.dense_cells > 0);
        // The budget: 5e7 plus 2000 per segment, then at most 16 lines of 2 visits per piece in each
        // cell past it (a few thousand pieces per cell here).
        CHECK(st.exact_work <= 5e7 + 2000.0 * static_cast<double>(st.segments) + 36 * 2 * 16 * 1500.0);
        const Comparison c = compare(out, ref::slab_area({pile}, rule, clip));
        INFO(c.text());
        CHECK(c.max_err <= 255.0 / 32);
    }
}

TEST_CASE("accuracy: Limits::exact_work sets the base of the fill's exact-work budget", "[accuracy][limits]") {
    // 150 pieces crossing in a few pixels: exact under the default budget; with a base of 1 the
    // cells past the per-segment share are integrated on lines, within 1/32 of the exact area.
    Rasterizer r;
    std::mt19937 rng(13);
    const Contour pile = random_polygon(rng, {2.05, 2.1, 4.9, 4.95}, 150);
    const IRect clip{0, 0, 8, 8};
    const ref::CoverageGrid exact = ref::slab_area({pile}, FillRule::NonZero, clip);
    const Rendered plain = render(r, ref::to_path({pile}), Affine::identity(), FillOptions{}, clip);
    CHECK(r.last_stats().dense_cells == 0);
    CHECK(compare(plain, exact).max_err <= 1);
    Limits low = current_limits();
    low.exact_work = 1;
    set_limits(low);
    const Rendered lined = render(r, ref::to_path({pile}), Affine::identity(), FillOptions{}, clip);
    const RasterStats st = r.last_stats();
    reset_limits();
    INFO("exact cells " << st.exact_cells << ", dense " << st.dense_cells << ", work " << st.exact_work);
    CHECK(st.dense_cells > 0);
    CHECK(compare(lined, exact).max_err <= 255.0 / 32);
}

TEST_CASE(
    "accuracy: thousands of pieces crossing between the dense method's lines are re-sorted, not swapped one by one",
    "[accuracy][regression]") {
    // Found by fuzz_stroke (fuzz/regressions/stroke/huge-width-...): a stroke 1.3e8 wide under a
    // singular transform puts nearly all of a 27,785-segment outline through each of 270 pixels.
    // Once the exact-work budget is spent each such pixel is integrated on 16 lines, and between
    // two lines nearly every pair of pieces swaps: restoring their x order by insertion cost the
    // square of the pieces per line (5 s in Release). The swaps count as work, so the fill stays
    // within twice its budget plus the last cell's lines only when the order is re-sorted whole.
    const std::vector<std::uint8_t> bytes =
        read_file(std::string(CASTELJAU_SOURCE_DIR) +
                  "/fuzz/regressions/stroke/"
                  "huge-width-under-a-singular-transform-piles-crossing-pieces-dense-lines-insertion-sort-quadratic");
    fuzz::Bytes in(bytes.data(), bytes.size());
    const fuzz::StrokeCase c = fuzz::read_stroke_case(in);
    const Path outline = stroke(c.path, c.style, c.m, 0.05);
    Rasterizer r;
    (void)r.fill_mask(outline, c.m, FillOptions{}, IRect{0, 0, 128, 128});
    const RasterStats st = r.last_stats();
    INFO("segments " << st.segments << ", exact cells " << st.exact_cells << ", dense " << st.dense_cells
                     << ", accumulated " << st.accumulated_cells << ", work " << st.exact_work);
    CHECK(st.dense_cells > 0);
    // 16 lines of 2 visits and a sort (log2 of 27,785 pieces < 15 visits) per piece.
    const double budget = 5e7 + 2000.0 * static_cast<double>(st.segments);
    CHECK(st.exact_work <= 2 * budget + 16 * (2 + 15) * static_cast<double>(st.segments));
}

TEST_CASE("accuracy: polygons under rotation, scale and skew transforms", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(0, 1);
    for (int i = 0; i < 100; ++i) {
        const Contour p =
            (i % 2) ? random_simple_polygon(rng, {0, 0}, 0.3, 1.0, 6 + i % 7) : random_polygon(rng, {-1, -1, 1, 1}, 6);
        const Affine m = Affine::translate(16 + 3 * u(rng), 16 + 3 * u(rng)) * Affine::rotate(2 * kPi * u(rng)) *
                         Affine::skew_x(0.8 * (u(rng) - 0.5)) * Affine::scale(2 + 12 * u(rng), 2 + 12 * u(rng));
        FillOptions o;
        for (FillRule rule : kRules) {
            o.rule = rule;
            worst.add(check_polygons(r, {p}, m, o, {0, 0, 32, 32}, "transformed " + std::to_string(i)),
                      "transformed " + std::to_string(i));
        }
    }
    WARN("transformed polygons: " << worst.text());
}

TEST_CASE("accuracy: fill_mask agrees with fill into a sink", "[accuracy]") {
    Rasterizer r;
    std::mt19937 rng(10);
    const Contours set{random_polygon(rng, {3.3, 2.1, 40.2, 30.8}, 9), random_simple_polygon(rng, {20, 20}, 4, 15, 12)};
    const Path p = ref::to_path(set);
    for (FillRule rule : kRules) {
        FillOptions o;
        o.rule = rule;
        const Mask m = r.fill_mask(p, Affine::identity(), o);
        const IRect pb = ref::pixel_bounds(set);
        CHECK(m.bounds.x0 <= pb.x0);
        CHECK(m.bounds.y0 <= pb.y0);
        CHECK(m.bounds.x1 >= pb.x1);
        CHECK(m.bounds.y1 >= pb.y1);
        const Rendered out = render(r, p, Affine::identity(), o, m.bounds);
        for (int y = m.bounds.y0; y < m.bounds.y1; ++y)
            for (int x = m.bounds.x0; x < m.bounds.x1; ++x) REQUIRE(m.at(x, y) == out.at(x, y));
        const Comparison c = compare(out, ref::slab_area(set, rule, m.bounds));
        INFO(c.text());
        CHECK(c.max_err <= kPolygonMaxErr);
    }
}

// ---------------------------------------------------------------------------------------------
// Curves

TEST_CASE("accuracy: circles and ellipses at the default tolerance", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    for (double radius : {0.3, 0.7, 1.5, 3.2, 7.5, 16.0, 40.0, 95.0, 230.0}) {
        for (int k = 0; k < 3; ++k) {
            Path p;
            const Point c{radius + 2 + u(rng), radius + 2 + u(rng)};
            p.add_circle(c, radius);
            const IRect clip{0, 0, static_cast<int>(2 * radius + 5), static_cast<int>(2 * radius + 5)};
            const std::string what = "circle r=" + std::to_string(radius);
            worst.add(check_curves(r, p, Affine::identity(), {}, clip, what), what);
        }
    }
    for (int i = 0; i < 30; ++i) {
        // Ellipses, some rotated by the transform (so the tolerance applies after it).
        Path p;
        const double rx = 1 + 60 * u(rng), ry = 0.5 + 30 * u(rng);
        p.add_ellipse({0, 0}, rx, ry);
        const double R = std::max(rx, ry);
        const Affine m = Affine::translate(R + 2.3, R + 2.6) * Affine::rotate(u(rng) * kPi);
        const IRect clip{0, 0, static_cast<int>(2 * R + 6), static_cast<int>(2 * R + 6)};
        const std::string what = "ellipse " + std::to_string(rx) + "x" + std::to_string(ry);
        worst.add(check_curves(r, p, m, {}, clip, what), what);
    }
    WARN("circles and ellipses at tolerance " << kDefaultTolerance << ": " << worst.text());
}

TEST_CASE("accuracy: cubic loops and cusps", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    const IRect clip{0, 0, 80, 80};
    struct Case {
        const char* name;
        Point p0, p1, p2, p3;
    };
    const Case cases[] = {
        {"loop", {10, 60}, {90, 0}, {-10, 0}, {70, 60}},
        {"small loop", {20, 40}, {50, 10}, {30, 10}, {60, 40}},
        {"cusp", {10, 70}, {70, 10}, {10, 10}, {70, 70}},
        {"near cusp", {10, 70}, {70, 10.01}, {10, 10}, {70, 70}},
        {"coincident controls", {10, 10}, {10, 10}, {70, 70}, {70, 70}},
        {"collinear overshoot", {10, 40}, {80, 40}, {0, 40.5}, {70, 41}},
        {"tight turn", {40, 5}, {79, 75}, {1, 75}, {40, 5.5}},
    };
    for (const Case& c : cases) {
        Path p;
        p.move_to(c.p0).cubic_to(c.p1, c.p2, c.p3).close();
        FillOptions o;
        for (FillRule rule : kRules) {
            o.rule = rule;
            worst.add(check_curves(r, p, Affine::identity(), o, clip, c.name), c.name);
        }
        // The same curve twice, the second reversed and shifted: crossings of curves.
        Path q = p;
        q.append(p.reversed(), Affine::translate(3.3, 2.7));
        for (FillRule rule : kRules) {
            o.rule = rule;
            worst.add(check_curves(r, q, Affine::identity(), o, clip, std::string(c.name) + " + shifted reverse"),
                      std::string(c.name) + " + shifted reverse");
        }
    }
    WARN("loops and cusps at tolerance " << kDefaultTolerance << ": " << worst.text());
}

TEST_CASE("accuracy: DejaVu Sans glyphs at the default tolerance", "[accuracy]") {
    Rasterizer r;
    GlyphFont font(dejavu_sans_path());
    Worst worst;
    const std::u32string text = U"casteljau Bézier @&%$ QWxyz gjpq 0123456789 ©ß";
    for (double px : {9.0, 12.0, 16.5, 24.0, 48.0, 96.0}) {
        const Path p = font.text(text, px, {1.3, std::ceil(px * 1.05) + 0.4});
        const ref::Contours fine = ref::fine_flatten(p, Affine::identity());
        const IRect clip = ref::pixel_bounds(fine, 1);
        const std::string what = "text at " + std::to_string(px) + " px";
        worst.add(check_curves(r, p, Affine::identity(), {}, clip, what), what);
    }
    // One glyph with a fractional, rotated placement: font units through the Affine.
    Path g;
    font.append_glyph(U'&', 2048.0, {0, 0}, g);  // 1 unit per font unit, y flipped
    const Affine m = Affine::translate(40.5, 50.25) * Affine::rotate(0.4) * Affine::scale(60.0 / 2048.0);
    const IRect clip = ref::pixel_bounds(ref::fine_flatten(g, m), 1);
    worst.add(check_curves(r, g, m, {}, clip, "rotated ampersand"), "rotated ampersand");
    WARN("glyphs at tolerance " << kDefaultTolerance << ": " << worst.text());
}

// ---------------------------------------------------------------------------------------------
// Clipping

TEST_CASE("accuracy: shapes far outside the target give nothing", "[accuracy]") {
    Rasterizer r;
    const IRect clip{0, 0, 40, 30};
    std::mt19937 rng(12);
    for (Point c : {Point{-500, 15}, Point{-30, 15}, Point{540, 15}, Point{20, -200}, Point{20, 260}, Point{-1e7, 5},
                    Point{1e7, 5}, Point{5, -1e7}, Point{5, 1e7}, Point{-1e7, -1e7}}) {
        for (int i = 0; i < 4; ++i) {
            const Contour p = (i % 2) ? random_polygon(rng, {c.x - 20, c.y - 12, c.x + 20, c.y + 12}, 7)
                                      : random_simple_polygon(rng, c, 3, 20, 9);
            Path path = ref::to_path({p});
            path.add_circle(c, 9.5);
            for (FillRule rule : kRules) {
                FillOptions o;
                o.rule = rule;
                const Rendered out = render(r, path, Affine::identity(), o, clip);
                INFO("shape at (" << c.x << ", " << c.y << ")");
                REQUIRE(out.contract_violation.empty());
                for (std::uint8_t v : out.cov) REQUIRE(v == 0);
            }
        }
    }
}

TEST_CASE("accuracy: huge coordinates crossing the target", "[accuracy]") {
    Rasterizer r;
    Worst worst;
    const IRect clip{0, 0, 64, 48};
    const Contours cases[] = {
        {{{-1e7, -1e7}, {1e7, 7.5}, {20.25, 1e7}}},
        {{{-1e7, 30.2}, {1e7, 31.7}, {1e7, 29.1}}},              // a needle 2e7 px long through the canvas
        {{{-1e7, -1e7}, {1e7, -1e7}, {1e7, 1e7}, {-1e7, 1e7}}},  // covers everything
        {{{-1e7, -1e7}, {1e7, 1e7 + 3.3}, {-1e7, 1e7}}},         // diagonal edge through the canvas
        {{{32.1, -1e7}, {32.6, 1e7}, {-1e7, 24.4}}, {{-1e7, 10}, {1e7, 40.5}, {1e7, 10.2}}},  // crossing triangles
        {{{1e7, 1e7}, {-1e7, 1e7 - 5}, {-3e6, -1e7}, {5e6, -1e7}, {17.3, 20.9}}},
    };
    int i = 0;
    for (const Contours& c : cases) {
        for (FillRule rule : kRules) {
            const std::string what = "huge #" + std::to_string(i);
            worst.add(check_polygons(r, c, rule, clip, what), what);
        }
        ++i;
    }
    // Huge coordinates brought back by a large scale.
    FillOptions o;
    const Contours small{{{1e7 + 1, 2e7}, {3e7, 1e7 + 5}, {1.3e7, 4.2e7}}};
    worst.add(check_polygons(r, small, Affine::scale(1e-6), o, clip, "scaled down from 1e7"), "scaled down");
    WARN("huge coordinates: " << worst.text());
}

namespace {

// Counts what a 16384 x 16384 fill delivers without storing the canvas.
class CountingSink final : public SpanSink {
public:
    explicit CountingSink(Rendered& r) : r_(r) {}
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        ++rows;
        span_pixels += static_cast<std::size_t>(length);
        for (int i = 0; i < length; ++i) {
            const int px = x + i;
            const IRect& w = r_.window;
            if (px >= w.x0 && px < w.x1 && y >= w.y0 && y < w.y1)
                r_.cov[static_cast<std::size_t>(y - w.y0) * w.width() + (px - w.x0)] = coverage[i];
            else if (coverage[i] != 0)
                ++r_.nonzero_outside_window;
        }
    }
    std::size_t rows = 0, span_pixels = 0;

private:
    Rendered& r_;
};

}  // namespace

TEST_CASE("accuracy: a 16384 x 16384 target holding one small shape", "[accuracy]") {
    Rasterizer r;
    const IRect clip{0, 0, 16384, 16384};
    for (Point c : {Point{9000.3, 12000.7}, Point{3.2, 16379.9}, Point{16380.6, 4.1}}) {
        const Contours shape{star_polygon(c, 20, 7, 3, 0.2)};
        Path p = ref::to_path(shape);
        p.add_circle(c, 6.5);
        IRect window = ref::pixel_bounds(shape, 2);
        window = {std::max(window.x0, clip.x0), std::max(window.y0, clip.y0), std::min(window.x1, clip.x1),
                  std::min(window.y1, clip.y1)};
        Rendered out;
        out.clip = clip;
        out.window = window;
        out.cov.assign(static_cast<std::size_t>(window.width()) * window.height(), 0);
        CountingSink sink(out);
        for (FillRule rule : kRules) {
            FillOptions o;
            o.rule = rule;
            std::fill(out.cov.begin(), out.cov.end(), 0);
            sink.rows = sink.span_pixels = 0;
            AllocationTotals alloc;
            {
                AllocationScope scope;
                r.fill(p, Affine::identity(), o, clip, sink);
                alloc = scope.totals();
            }
            // No buffer that scales with the 2^28-pixel target: a few MiB at most in total (the
            // strip buffers are bounded by the shape's width), no single block near a canvas row
            // count times its width.
            INFO("fill allocated " << alloc.bytes << " bytes in " << alloc.count << " blocks, largest "
                                   << alloc.largest);
            CHECK(alloc.bytes <= (8u << 20));
            CHECK(alloc.largest <= (4u << 20));
            const Comparison cmp = compare(out, ref::path_reference(p, Affine::identity(), rule, window));
            INFO("star at (" << c.x << ", " << c.y << "): " << cmp.text());
            CHECK(out.nonzero_outside_window == 0);
            CHECK(cmp.max_err <= kCurveMaxErr);
            CHECK(cmp.mean_all <= kCurveMeanErr);
            // Work grows with the shape: only its rows are delivered, and spans stay near its width.
            CHECK(sink.rows <= 45);
            CHECK(sink.span_pixels <= 45u * 45u);
        }
    }
}

TEST_CASE("accuracy: error against the flattening tolerance", "[accuracy]") {
    // Not an acceptance bound: a table for choosing the default tolerance, and two properties that
    // hold at any tolerance. The polyline stays within `tol` of the curve, so inside a pixel the
    // area between them is at most tol x (length of boundary in the pixel); 3 tol allows for two
    // boundaries in one pixel (thin stems). At tol = 1e-3 the result is nearly exact.
    Rasterizer r;
    GlyphFont font(dejavu_sans_path());
    struct Scene {
        std::string name;
        Path path;
        IRect clip;
    };
    std::vector<Scene> scenes;
    {
        Path p;
        for (int i = 0; i < 6; ++i) p.add_circle({20.0 + 45 * i + 0.3 * i, 60.0 + 0.7 * i}, 4.0 + 7.0 * i);
        scenes.push_back({"circles r=4..39", p, ref::pixel_bounds(ref::fine_flatten(p, Affine::identity()), 1)});
    }
    for (double px : {12.0, 48.0}) {
        const Path p = font.text(U"Sphinx of black quartz, judge my vow", px, {1.5, std::ceil(px) + 0.25});
        scenes.push_back({"text " + std::to_string(static_cast<int>(px)) + "px", p,
                          ref::pixel_bounds(ref::fine_flatten(p, Affine::identity()), 1)});
    }
    std::string table = "tolerance | scene | max | mean (all) | mean (edge pixels) | segments\n";
    for (double tol : {0.2, 0.1, 0.05, 0.025, 0.01, 0.005, 0.001}) {
        for (const Scene& s : scenes) {
            FillOptions o;
            o.tolerance = tol;
            const Rendered out = render(r, s.path, Affine::identity(), o, s.clip);
            const Comparison c =
                compare(out, ref::path_reference(s.path, Affine::identity(), FillRule::NonZero, s.clip));
            char line[200];
            std::snprintf(line, sizeof line, "%.3f | %s | %.2f | %.3f | %.3f | %zu\n", tol, s.name.c_str(), c.max_err,
                          c.mean_all, c.mean_err, out.stats.segments);
            table += line;
            INFO(s.name << " at tolerance " << tol << ": " << c.text());
            CHECK(c.max_err <= 255.0 * 3 * tol + 1.0);
            if (tol <= 1e-3) CHECK(c.max_err <= 1.0);
        }
    }
    WARN(table);
}

// ---------------------------------------------------------------------------------------------
// Regressions: minimal reproducers of bugs these tests found, each named after what broke.

TEST_CASE("raster regression: a square inside one pixel keeps all four edges in its exact cell", "[accuracy]") {
    // Four edges of one contour in one cell: three are accepted as one polyline, the fourth marks
    // the cell, and the exact recomputation must see all four (with only the last three, the
    // square's bottom edge would be missing and the coverage below it would count as inside).
    Rasterizer r;
    const Contour sq{{1.25, 2.25}, {1.75, 2.25}, {1.75, 2.75}, {1.25, 2.75}};
    for (const Contour& c : {sq, reversed(sq)})
        for (FillRule rule : kRules) {
            const Rendered out = render(r, ref::to_path({c}), Affine::identity(),
                                        [&] {
                                            FillOptions o;
                                            o.rule = rule;
                                            return o;
                                        }(),
                                        {0, 0, 4, 4});
            CHECK(out.at(1, 2) == 64);  // 0.25 x 255 = 63.75
        }
    // The seeded case that found it: a sliver rectangle of 0.553 x 0.0035 px.
    check_polygons(r, {rect(11.005396851662153, 18.556308238888061, 11.558360852807962, 18.559800880211878)},
                   FillRule::NonZero, {0, 0, 32, 32}, "sliver rectangle in one pixel");
}

TEST_CASE("raster regression: curves crossing the side of a target not at the origin are not culled to chords",
          "[accuracy]") {
    // The clipping path culls curves whose control box misses the target (plus a pixel); the cull
    // rectangle must be in the same coordinates as the points (local to the target).
    Rasterizer r;
    Path c;
    c.add_circle({60, 60}, 10);
    for (IRect clip : {IRect{55, 45, 75, 75}, IRect{45, 55, 75, 75}, IRect{45, 45, 65, 75}, IRect{45, 45, 75, 65},
                       IRect{52, 52, 68, 68}}) {
        const Rendered out = render(r, c, Affine::identity(), FillOptions{}, clip);
        const ref::CoverageGrid truth = ref::path_reference(c, Affine::identity(), FillRule::NonZero, clip);
        const Comparison cmp = compare(out, truth);
        INFO("circle (60, 60) r 10 in clip {" << clip.x0 << ", " << clip.y0 << ", " << clip.x1 << ", " << clip.y1
                                              << "}: " << cmp.text() << "; " << out.stats.segments << " segments");
        CHECK(cmp.max_err <= 3 * 255 * kDefaultTolerance + 1);
    }
}
