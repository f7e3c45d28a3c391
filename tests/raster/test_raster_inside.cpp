// FillOptions::inside: capsules known to lie inside the shape make the overlap check's cells in
// them full without the exact computation; everything else stays as it is.
#include <catch2/catch.hpp>

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
