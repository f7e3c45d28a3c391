// FillOptions::inside: capsules known to lie inside the shape make the overlap check's cells in
// them full without the exact computation; everything else stays as it is.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "casteljau/raster.hpp"
#include "raster_check.hpp"

using namespace casteljau;

using casteljau::testing::overlapping_squares;

TEST_CASE("FillOptions::inside: cells inside a true capsule are full, pixels unchanged", "[raster][inside]") {
    Rasterizer r;
    const Path p = overlapping_squares();
    FillOptions cells;  // capsules skip the overlap check's exact cells
    cells.winding_sweep = false;
    const Mask plain = r.fill_mask(p, Affine{}, cells);
    const std::size_t exact = r.last_stats().exact_cells;
    REQUIRE(exact > 0);
    REQUIRE(r.last_stats().inside_cells == 0);
    // Inside the third square, through two crossings of the first two squares' sides.
    const CutCapsule caps[] = {Capsule{{20.6, 30.3}, {30.3, 20.6}, 3}};
    FillOptions fo;
    fo.inside = caps;
    const Mask hinted = r.fill_mask(p, Affine{}, fo);
    CHECK(r.last_stats().inside_cells > 0);
    CHECK(r.last_stats().inside_cells + r.last_stats().exact_cells == exact);
    CHECK(hinted.data == plain.data);
}

TEST_CASE("FillOptions::inside: trusted as given, ignored under even-odd and when too thin", "[raster][inside]") {
    Rasterizer r;
    // A ring (outer square, hole wound the same way: nonzero fills the hole, even-odd does not),
    // drawn twice so that every boundary cell is recomputed.
    Path p;
    p.add_rect(Rect{0.5, 0.5, 40.5, 40.5});
    p.add_rect(Rect{10.5, 10.5, 30.5, 30.5});
    p.append(p);
    const CutCapsule across[] = {Capsule{{3.5, 20}, {37.5, 20}, 3}};
    FillOptions fo;
    fo.inside = across;
    fo.rule = FillRule::EvenOdd;
    FillOptions eo;
    eo.rule = FillRule::EvenOdd;
    const Mask eo_plain = r.fill_mask(p, Affine{}, eo);
    const Mask eo_hinted = r.fill_mask(p, Affine{}, fo);
    CHECK(r.last_stats().inside_cells == 0);
    CHECK(eo_hinted.data == eo_plain.data);
    // Under nonzero the capsule is true (the hole is filled) and the cells it holds on the hole's
    // boundary are full, as the exact computation finds them.
    fo.rule = FillRule::NonZero;
    const Mask nz_plain = r.fill_mask(p, Affine{}, FillOptions{});
    const Mask nz_hinted = r.fill_mask(p, Affine{}, fo);
    CHECK(r.last_stats().inside_cells > 0);
    CHECK(nz_hinted.data == nz_plain.data);
    // A capsule under sqrt(1/2) px holds no pixel and is not used.
    const CutCapsule thin[] = {Capsule{{3.5, 20}, {37.5, 20}, 0.7}};
    fo.inside = thin;
    (void)r.fill_mask(p, Affine{}, fo);
    CHECK(r.last_stats().inside_cells == 0);
}

TEST_CASE("FillOptions::inside: a capsule that is not inside is believed", "[raster][inside]") {
    // The contract is the caller's: a cell the overlap check marks inside a false capsule is full.
    Rasterizer r;
    Path p;
    p.add_rect(Rect{0.5, 0.5, 20.5, 20.5});
    p.add_rect(Rect{0.5, 0.5, 20.5, 20.5});  // stacked: every boundary cell is recomputed
    const Mask plain = r.fill_mask(p, Affine{}, FillOptions{});
    const CutCapsule wrong[] = {Capsule{{0.5, 10}, {0.5, 10}, 3}};  // half of it lies outside the square
    FillOptions fo;
    fo.inside = wrong;
    const Mask hinted = r.fill_mask(p, Affine{}, fo);
    CHECK(plain.at(0, 10) == 128);
    CHECK(hinted.at(0, 10) == 255);
}

TEST_CASE("FillOptions::inside: every recomputed cell inside a capsule is found among thousands", "[raster][inside]") {
    // A rectangle drawn twice: its boundary cells, and only they, are recomputed exactly. Thousands
    // of capsules (some cut by lines) cross its rows; the contract is the caller's, so each cell
    // of the boundary that one of them holds whole must come out full, and every other pixel as
    // without capsules. A row's questions see every capsule that spans it, however many.
    Rasterizer r;
    const Rect box{0.5, 0.5, 200.5, 60.5};
    Path p;
    p.add_rect(box);
    p.add_rect(box);
    FillOptions plain_fo;
    plain_fo.winding_sweep = false;
    const Mask plain = r.fill_mask(p, Affine{}, plain_fo);
    std::vector<std::pair<int, int>> boundary;  // (col, row): the cells the rectangle's sides cross
    for (int y = 0; y <= 60; ++y)
        for (int x = 0; x <= 200; ++x)
            if (x == 0 || x == 200 || y == 0 || y == 60) boundary.emplace_back(x, y);
    REQUIRE(r.last_stats().exact_cells == boundary.size());

    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ux(-4, 205), uy(-4, 65), ur(0.7, 2.2), ul(-6, 6), ua(0, 6.283185307179586);
    std::vector<CutCapsule> caps;
    for (int i = 0; i < 4000; ++i) {
        const Point a{ux(rng), uy(rng)};
        CutCapsule c(Capsule{a, a + Vec{ul(rng), ul(rng)}, ur(rng)});
        c.cut_count = i % 3;
        for (int k = 0; k < c.cut_count; ++k) {
            const double t = ua(rng);
            c.cuts[k] = {a + Vec{ul(rng) / 3, ul(rng) / 3}, Vec{std::cos(t), std::sin(t)}};
        }
        caps.push_back(c);
    }
    auto held = [&](int x, int y) {
        for (const CutCapsule& c : caps)
            if (c.contains({double(x), double(y)}) && c.contains({x + 1.0, double(y)}) &&
                c.contains({double(x), y + 1.0}) && c.contains({x + 1.0, y + 1.0}))
                return true;
        return false;
    };
    FillOptions fo;
    fo.inside = caps;
    const Mask hinted = r.fill_mask(p, Affine{}, fo);
    std::size_t expected = 0;
    for (auto [x, y] : boundary) {
        const bool full = held(x, y);
        expected += full;
        INFO("cell " << x << ", " << y);
        CHECK(hinted.at(x, y) == (full ? 255 : plain.at(x, y)));
    }
    REQUIRE(expected > 100);  // both kinds of cells are there
    REQUIRE(expected + 100 < boundary.size());
    CHECK(r.last_stats().inside_cells == expected);
    CHECK(r.last_stats().inside_cells + r.last_stats().exact_cells == boundary.size());
    for (int y = 1; y < 60; ++y)
        for (int x = 1; x < 200; ++x) REQUIRE(hinted.at(x, y) == plain.at(x, y));
}
