// stroke_outline()'s interior capsules: they lie inside the outline, so filling with them as the
// rasterizer's FillOptions::inside gives the same pixels while skipping exact cells.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <thread>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/stroke.hpp"

using namespace casteljau;

namespace {

// A random path of lines, quadratics and cubics in a 100 x 100 box, sometimes closed.
Path random_path(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0, 1);
    auto pt = [&] { return Point{100 * u(rng), 100 * u(rng)}; };
    Path p;
    p.move_to(pt());
    const int n = 1 + static_cast<int>(rng() % 6);
    for (int j = 0; j < n; ++j) {
        switch (rng() % 3) {
            case 0: p.line_to(pt()); break;
            case 1: p.quad_to(pt(), pt()); break;
            default: p.cubic_to(pt(), pt(), pt());
        }
    }
    if (rng() % 3 == 0) p.close();
    return p;
}

// Three sides of the square [0, 100]^2, open at the left: (0, 0) -> (100, 0) -> (100, 100) -> (0, 100).
Path open_square() {
    Path p;
    p.move_to(0, 0);
    p.line_to(100, 0);
    p.line_to(100, 100);
    p.line_to(0, 100);
    return p;
}

}  // namespace

TEST_CASE("stroke_outline: interior capsules leave every pixel of random strokes unchanged", "[stroke][interior]") {
    std::mt19937 rng(20261128);
    std::uniform_real_distribution<double> u(0, 1);
    Rasterizer raster;
    std::size_t inside = 0, exact = 0;
    for (int i = 0; i < 400; ++i) {
        const Path path = random_path(rng);
        StrokeStyle st;
        st.width = 0.3 + 24 * u(rng) * u(rng);
        st.join = static_cast<LineJoin>(rng() % 4);
        st.cap = static_cast<LineCap>(rng() % 3);
        if (rng() % 4 == 0) st.dashes = {2 + 20 * u(rng), 1 + 10 * u(rng)};
        Affine m;
        if (rng() % 3 == 0) m = Affine::rotate(6 * u(rng)) * Affine{1 + u(rng), 0.3 * u(rng), 0, 0.5 + u(rng), 0, 0};
        if (rng() % 4 == 0) m = Affine::translate(200, 0) * Affine::scale(-1, 1) * m;  // a mirror
        const double tol = rng() % 2 ? 0.015 : 0.25;
        const StrokeOutline s = stroke_outline(path, st, m, tol);
        REQUIRE(s.outline == stroke(path, st, m, tol));
        FillOptions plain;  // the overlap check, which the capsules shorten
        plain.tolerance = tol;
        plain.winding_sweep = false;
        FillOptions hinted = plain;
        hinted.inside = s.inside;
        const Mask a = raster.fill_mask(s.outline, m, plain);
        exact += raster.last_stats().exact_cells;
        const Mask b = raster.fill_mask(s.outline, m, hinted);
        inside += raster.last_stats().inside_cells;
        INFO("case " << i << ": width " << st.width << ", join " << int(st.join) << ", cap " << int(st.cap));
        REQUIRE(a.bounds == b.bounds);
        REQUIRE(a.data == b.data);
    }
    // The capsules took a good share of the exact work (about 15 % of the cells here).
    CHECK(inside * 10 > exact);
}

TEST_CASE("stroke_outline: interior capsules of short crowded strokes leave every pixel unchanged",
          "[stroke][interior]") {
    // Short polylines and curves in a small box under wide pens: every part of the path lies near
    // an end, where the capsules are cut or dropped.
    std::mt19937 rng(20261129);
    std::uniform_real_distribution<double> u(0, 1);
    Rasterizer raster;
    std::size_t inside = 0;
    for (int i = 0; i < 600; ++i) {
        auto pt = [&] { return Point{20 + 16 * u(rng), 20 + 16 * u(rng)}; };
        Path path;
        path.move_to(pt());
        const int n = 2 + static_cast<int>(rng() % 7);
        for (int j = 0; j < n; ++j) {
            if (rng() % 3 == 0)
                path.cubic_to(pt(), pt(), pt());
            else
                path.line_to(pt());
        }
        StrokeStyle st;
        st.width = 1.5 + 14 * u(rng);
        st.join = LineJoin::Round;
        st.cap = static_cast<LineCap>(rng() % 3);
        if (rng() % 4 == 0) st.dashes = {3 + 10 * u(rng), 1 + 4 * u(rng)};
        const double tol = rng() % 2 ? 0.015 : 0.2;
        const StrokeOutline s = stroke_outline(path, st, Affine{}, tol);
        FillOptions plain;  // the overlap check, which the capsules shorten
        plain.tolerance = tol;
        plain.winding_sweep = false;
        FillOptions hinted = plain;
        hinted.inside = s.inside;
        const Mask a = raster.fill_mask(s.outline, Affine{}, plain);
        const Mask b = raster.fill_mask(s.outline, Affine{}, hinted);
        inside += raster.last_stats().inside_cells;
        INFO("case " << i << ": width " << st.width << ", cap " << int(st.cap));
        REQUIRE(a.bounds == b.bounds);
        REQUIRE(a.data == b.data);
    }
    CHECK(inside > 1000);
}

TEST_CASE("stroke_outline: the capsules of an open polyline are cut at its ends", "[stroke][interior]") {
    Path p = open_square();
    StrokeStyle st;
    st.width = 10;
    st.join = LineJoin::Round;
    // Radius: h - 3 x tolerance.
    const StrokeOutline s = stroke_outline(p, st, Affine{}, 0.05);
    REQUIRE(s.inside.size() == 3);
    // The first segment's capsule is cut by the start's line x = 0, moved back by the tolerance.
    CHECK(s.inside[0].capsule.a == Point{0, 0});
    CHECK(s.inside[0].capsule.radius == Approx(4.85));
    REQUIRE(s.inside[0].cut_count == 1);
    CHECK(s.inside[0].cuts[0].at.x == Approx(0.05));
    CHECK(s.inside[0].cuts[0].out.x < 0);
    CHECK(s.inside[0].contains({0.06, 4.8}));
    CHECK_FALSE(s.inside[0].contains({0.04, 0}));
    // The middle one lies 100 behind both ends' lines: whole.
    CHECK(s.inside[1].capsule.a == Point{100, 0});
    CHECK(s.inside[1].capsule.b == Point{100, 100});
    CHECK(s.inside[1].cut_count == 0);
    // The last one is cut by the end's line x = 0 as well.
    REQUIRE(s.inside[2].cut_count == 1);
    CHECK(s.inside[2].cuts[0].at == Point{0.05, 100});
    // Under a scale of 2 (x) and 3 (y) the pixel-space capsule and cuts follow.
    const StrokeOutline s2 = stroke_outline(p, st, Affine::scale(2, 3), 0.05);
    REQUIRE(s2.inside.size() == 3);
    CHECK(s2.inside[1].capsule.b == Point{200, 300});
    CHECK(s2.inside[1].capsule.radius == Approx(2 * (5 - 3 * 0.05 / 3)));
    CHECK(s2.inside[0].cuts[0].at.x == Approx(2 * 0.05 / 3));
    CHECK(s2.inside[0].cuts[0].out.x < 0);
    CHECK(s2.inside[0].cuts[0].out.y == Approx(0).margin(1e-12));
    // Miter and bevel joins may leave a corner's outside short of the pen: the capsules keep to
    // the segments' rectangles, cut square at both ends, and the segments an open end would cut
    // give none.
    for (LineJoin join : {LineJoin::Miter, LineJoin::Bevel}) {
        st.join = join;
        const StrokeOutline cut = stroke_outline(p, st, Affine{}, 0.05);
        REQUIRE(cut.inside.size() == 1);
        const CutCapsule& middle = cut.inside[0];
        CHECK(middle.capsule.a == Point{100, 0});
        REQUIRE(middle.cut_count == 2);
        CHECK(middle.contains({104.8, 0.01}));
        CHECK(middle.contains({95.2, 99.99}));
        CHECK_FALSE(middle.contains({104, -0.5}));
        CHECK_FALSE(middle.contains({100, 101}));
        Path ring = p;
        ring.close();
        CHECK(stroke_outline(ring, st, Affine{}, 0.05).inside.size() == 4);
    }
    // Closed, every segment keeps one.
    st.join = LineJoin::Round;
    p.close();
    CHECK(stroke_outline(p, st, Affine{}, 0.05).inside.size() == 4);
}

TEST_CASE("stroke_outline: a segment that comes back near an open end is cut only where the end may matter",
          "[stroke][interior]") {
    // Out along y = 0 from the start E = (0, 0), up, and back along y = c past E: what the start
    // draws differs from the ideal only within 2h of E, beyond the line x = 0.
    StrokeStyle st;
    st.width = 8;  // h = 4, capsule radius r = 4 - 3 x 0.05 = 3.85
    st.join = LineJoin::Round;
    auto back_at = [&](double c) {
        Path p;
        p.move_to(0, 0);
        p.line_to(40, 0);
        p.line_to(40, c);
        p.line_to(-30, c);
        return stroke_outline(p, st, Affine{}, 0.05);
    };
    // 12 from E, at least 2h + r away: whole but for its own end's line x = -30.
    const StrokeOutline far = back_at(12);
    REQUIRE(far.inside.size() == 3);
    CHECK(far.inside[2].cut_count == 1);
    CHECK(far.inside[2].contains({-10, 12}));
    CHECK(far.inside[2].contains({-10, 15.8}));
    // 10 from E: cut by the line y = 2h + tol, square to the way from E to the segment, which
    // keeps the whole segment (the line x = 0 would keep none of it beyond E).
    const StrokeOutline near = back_at(10);
    REQUIRE(near.inside.size() == 3);
    REQUIRE(near.inside[2].cut_count == 2);
    CHECK(near.inside[2].contains({-10, 10}));
    CHECK(near.inside[2].contains({-10, 8.1}));
    CHECK_FALSE(near.inside[2].contains({-10, 8}));
    CHECK_FALSE(near.inside[2].contains({-10, 7}));
    // Both give the pixels of the plain fill.
    Rasterizer raster;
    for (const StrokeOutline* s : {&far, &near}) {
        FillOptions hinted;
        hinted.inside = s->inside;
        const Mask a = raster.fill_mask(s->outline, Affine{});
        const Mask b = raster.fill_mask(s->outline, Affine{}, hinted);
        REQUIRE(a.bounds == b.bounds);
        CHECK(a.data == b.data);
    }
}

TEST_CASE("stroke_outline: no capsules for pens too thin to hold a pixel or contours of no length",
          "[stroke][interior]") {
    Path p = open_square();
    p.close();
    StrokeStyle st;
    st.join = LineJoin::Round;
    st.width = 1.4;  // radius 0.7 - 3 tol: under sqrt(1/2)
    CHECK(stroke_outline(p, st, Affine{}, 0.01).inside.empty());
    st.width = 1.6;
    CHECK(stroke_outline(p, st, Affine{}, 0.01).inside.size() == 4);
    CHECK(stroke_outline(p, st, Affine::scale(0.5), 0.01).inside.empty());
    // A closed contour of zero length draws nothing with butt caps: no capsule may claim it.
    Path dot;
    dot.move_to(50, 50);
    dot.line_to(50, 50);
    dot.close();
    st.width = 20;
    CHECK(stroke_outline(dot, st, Affine{}, 0.05).inside.empty());
}

TEST_CASE("stroke_outline into a kept outline gives what a fresh one gives, stroke after stroke",
          "[stroke][interior]") {
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> u(0, 1);
    StrokeOutline kept;
    for (int i = 0; i < 60; ++i) {
        const Path path = random_path(rng);
        StrokeStyle st;
        st.width = 0.5 + 20 * u(rng);
        st.join = rng() % 2 ? LineJoin::Round : LineJoin::Bevel;
        if (rng() % 3 == 0) st.dashes = {4 + 10 * u(rng), 2 + 5 * u(rng)};
        stroke_outline(path, st, Affine{}, 0.05, kept);
        const StrokeOutline fresh = stroke_outline(path, st, Affine{}, 0.05);
        REQUIRE(kept.outline == fresh.outline);
        REQUIRE(kept.inside.size() == fresh.inside.size());
        for (std::size_t k = 0; k < fresh.inside.size(); ++k) {
            CHECK(kept.inside[k].capsule.a == fresh.inside[k].capsule.a);
            CHECK(kept.inside[k].capsule.b == fresh.inside[k].capsule.b);
            CHECK(kept.inside[k].cut_count == fresh.inside[k].cut_count);
        }
    }
    // A stroke that fails, at once or halfway through its outline, leaves no outline behind.
    Path bad;
    bad.move_to(0, 0);
    bad.line_to(std::numeric_limits<double>::infinity(), 1);
    CHECK_THROWS_AS(stroke_outline(bad, StrokeStyle{}, Affine{}, 0.05, kept), Error);
    CHECK(kept.outline.empty());
    CHECK(kept.inside.empty());
    Path two;  // two contours: the first is emitted before the second passes the limit
    two.add_circle({50, 50}, 20);
    two.add_circle({150, 50}, 20);
    StrokeStyle round;
    round.width = 10;
    round.join = LineJoin::Round;
    const std::size_t one = stroke(Path().add_circle({50, 50}, 20), round, Affine{}, 0.05).points().size();
    Limits small = current_limits();
    small.path_points = one + 20;
    set_limits(small);
    CHECK_THROWS_AS(stroke_outline(two, round, Affine{}, 0.05, kept), Error);
    reset_limits();
    CHECK(kept.outline.empty());
    CHECK(kept.inside.empty());
}

TEST_CASE("stroke: two threads stroking at once get the outlines one thread gets", "[stroke][interior]") {
    std::vector<Path> paths;
    std::mt19937 rng(78);
    for (int i = 0; i < 40; ++i) paths.push_back(random_path(rng));
    StrokeStyle st;
    st.width = 6;
    st.join = LineJoin::Round;
    st.dashes = {9, 4};
    std::vector<Path> alone;
    for (const Path& p : paths) alone.push_back(stroke(p, st, Affine{}, 0.02));
    std::vector<Path> a(paths.size()), b(paths.size());
    std::thread ta([&] {
        for (std::size_t i = 0; i < paths.size(); ++i) a[i] = stroke(paths[i], st, Affine{}, 0.02);
    });
    std::thread tb([&] {
        for (std::size_t i = paths.size(); i-- > 0;) b[i] = stroke(paths[i], st, Affine{}, 0.02);
    });
    ta.join();
    tb.join();
    CHECK(a == alone);
    CHECK(b == alone);
}
