// FillOptions::hidden: pixels the caller paints over keep plain accumulation, every other pixel its
// exact coverage; PixelSet and CoverageRows, the pieces render_map builds it from.
#include <catch2/catch.hpp>

#include "casteljau/raster.hpp"
#include "raster_check.hpp"

using namespace casteljau;
using casteljau::testing::overlapping_squares;
using casteljau::testing::render;

namespace {

// Collects replayed rows into a w x h image from (0, 0).
class Image final : public SpanSink {
public:
    Image(int w, int h) : w_(w), px_(static_cast<std::size_t>(w * h), 0) {}
    void row(int y, int x, int length, const std::uint8_t* c) override {
        for (int i = 0; i < length; ++i) px_[static_cast<std::size_t>(y * w_ + x + i)] = c[i];
    }
    int at(int x, int y) const { return px_[static_cast<std::size_t>(y * w_ + x)]; }

private:
    int w_;
    std::vector<std::uint8_t> px_;
};

}  // namespace

TEST_CASE("FillOptions::hidden: hidden pixels are accumulated, the others exact", "[raster][hidden]") {
    Rasterizer r;
    const Path p = overlapping_squares();
    const IRect clip{0, 0, 52, 52};
    FillOptions cells;  // hidden pixels skip the overlap check's exact cells
    cells.winding_sweep = false;
    const testing::Rendered exact = render(r, p, Affine{}, cells, clip);
    const std::size_t exact_cells = exact.stats.exact_cells;
    REQUIRE(exact_cells > 0);
    FillOptions off;
    off.exact_overlaps = false;
    const testing::Rendered plain = render(r, p, Affine{}, off, clip);
    // The left half hidden.
    PixelSet left(IRect{0, 0, 52, 52});
    for (int y = 0; y < 52; ++y) left.insert(y, 0, 26);
    FillOptions fo;
    fo.hidden = &left;
    const testing::Rendered half = render(r, p, Affine{}, fo, clip);
    const RasterStats& s = half.stats;
    CHECK(s.hidden_cells > 0);
    CHECK(s.exact_cells > 0);
    CHECK(s.exact_cells < exact_cells);
    int wrong_left = 0, wrong_right = 0;
    for (int y = 0; y < 52; ++y)
        for (int x = 0; x < 52; ++x) {
            CHECK(half.at(x, y) == (x < 26 ? plain : exact).at(x, y));
            (x < 26 ? wrong_left : wrong_right) += plain.at(x, y) != exact.at(x, y);
        }
    // Both halves have pixels where accumulation is wrong: the check above tells them apart.
    CHECK(wrong_left > 0);
    CHECK(wrong_right > 0);
    // Every pixel hidden: no exact cell, the accumulated pixels; a set elsewhere changes nothing.
    PixelSet all(IRect{0, 0, 52, 52}), far(IRect{100, 100, 200, 200});
    for (int y = 0; y < 52; ++y) all.insert(y, -5, 60);
    fo.hidden = &all;
    const testing::Rendered every = render(r, p, Affine{}, fo, clip);
    CHECK(every.stats.exact_cells == 0);
    fo.hidden = &far;
    const testing::Rendered none = render(r, p, Affine{}, fo, clip);
    CHECK(none.stats.hidden_cells == 0);
    CHECK(none.stats.exact_cells == exact_cells);
    for (int y = 0; y < 52; ++y)
        for (int x = 0; x < 52; ++x) {
            CHECK(every.at(x, y) == plain.at(x, y));
            CHECK(none.at(x, y) == exact.at(x, y));
        }
}

TEST_CASE("FillOptions::hidden: a shape swept in strips finds its hidden pixels in every strip", "[raster][hidden]") {
    // A box of more than 2^18 cells is swept in bands; the stacked squares' sides cross them all.
    Path p;
    p.add_rect(Rect{0.3, 0.3, 700.3, 700.3});
    p.add_rect(Rect{0.3, 0.3, 700.3, 700.3});
    Rasterizer r;
    const IRect clip{0, 0, 701, 701};
    FillOptions fo;
    fo.topology = Topology::Overlapping;
    const testing::Rendered exact = render(r, p, Affine{}, fo, clip);
    REQUIRE(exact.stats.strips > 1);
    PixelSet top(IRect{0, 0, 701, 701});
    for (int y = 0; y < 350; ++y) top.insert(y, 0, 701);
    fo.hidden = &top;
    const testing::Rendered half = render(r, p, Affine{}, fo, clip);
    CHECK(half.stats.hidden_cells > 0);
    // The stacked side at x = 0.3 doubles under accumulation: 0.7 x 2, clamped to full.
    CHECK(exact.at(0, 400) == 179);
    CHECK(half.at(0, 400) == 179);
    CHECK(half.at(0, 100) == 255);
}

TEST_CASE("PixelSet: runs across words, clipped to the bounds", "[raster][hidden]") {
    PixelSet s(IRect{-10, 5, 190, 8});
    CHECK(s.count() == 0);
    s.insert(5, -20, -9);   // -10 (the bounds' first pixel)
    s.insert(6, 50, 180);   // across words
    s.insert(7, 53, 54);    // one pixel
    s.insert(4, 0, 100);    // outside: no row 4
    s.insert(7, 300, 400);  // outside
    s.insert(6, 60, 60);    // empty
    CHECK(s.count() == 1 + 130 + 1);
    CHECK(s.contains(-10, 5));
    CHECK_FALSE(s.contains(-9, 5));
    CHECK_FALSE(s.contains(49, 6));
    CHECK(s.contains(50, 6));
    CHECK(s.contains(117, 6));
    CHECK(s.contains(179, 6));
    CHECK_FALSE(s.contains(180, 6));
    CHECK(s.contains(53, 7));
    CHECK_FALSE(s.contains(53, 8));
    CHECK_FALSE(s.contains(53, 4));
    CHECK_FALSE(PixelSet{}.contains(0, 0));
}

TEST_CASE("CoverageRows: replays what it recorded, in order", "[raster][hidden]") {
    Rasterizer r;
    const Path p = overlapping_squares();
    const IRect clip{0, 0, 52, 52};
    CoverageRows rows;
    r.fill(p, Affine{}, FillOptions{}, clip, rows);
    REQUIRE_FALSE(rows.empty());
    const testing::Rendered direct = render(r, p, Affine{}, FillOptions{}, clip);
    Image replayed(52, 52), twice(52, 52);
    rows.replay(replayed);
    rows.replay(twice);
    int inked = 0;
    for (int y = 0; y < 52; ++y)
        for (int x = 0; x < 52; ++x) {
            CHECK(replayed.at(x, y) == direct.at(x, y));
            CHECK(twice.at(x, y) == direct.at(x, y));
            inked += direct.at(x, y) > 0;
        }
    CHECK(inked > 1000);
    rows.clear();
    CHECK(rows.empty());
}
