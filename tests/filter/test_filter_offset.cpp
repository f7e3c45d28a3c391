// Filter effects, feOffset: the shift of a single opaque pixel by device offsets with and
// without a fractional part, worked out here.
#include <catch2/catch.hpp>

#include "casteljau/filter.hpp"

using namespace casteljau;

namespace {

// Where the single opaque pixel of a 20 x 5 pixmap at (10, 2) lands after feOffset dx (device
// pixels, the identity transform); -1 when it is gone.
int shifted_column(double dx) {
    Pixmap src(20, 5);
    src.set_pixel(10, 2, premultiply(Color::rgba(255, 255, 255, 255)));
    filter::FilterGraph g;
    g.region = Rect::from_xywh(0, 0, 20, 5);
    filter::Primitive p;
    p.op = filter::Primitive::Offset;
    p.subregion = g.region;
    p.dx = dx;
    g.primitives.push_back(p);
    const Pixmap out = filter::apply_filter(g, Affine::identity(), src);
    int column = -1;
    for (int x = 0; x < out.width(); ++x)
        if (out.pixel(x, 2).a == 255) column = x;
    return column;
}

}  // namespace

TEST_CASE("filter: feOffset moves by the nearest whole device pixels, halves toward zero", "[filter]") {
    // feOffset shifts the image by whole device pixels: the nearest whole number of pixels, and
    // for an offset halfway between two, the one nearer zero (on either side). So 1.5 moves one
    // pixel, 1.9 two, -1.5 one pixel back, -1.9 two, and 0.5 leaves the image where it is.
    CHECK(shifted_column(0) == 10);
    CHECK(shifted_column(3) == 13);
    CHECK(shifted_column(1.5) == 11);
    CHECK(shifted_column(1.9) == 12);
    CHECK(shifted_column(-1.5) == 9);
    CHECK(shifted_column(-1.9) == 8);
    CHECK(shifted_column(0.5) == 10);
}
