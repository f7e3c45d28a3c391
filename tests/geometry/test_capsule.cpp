// Capsule::contains, Affine::min_scale and Affine::map_bounds, against values worked out by hand.
#include <catch2/catch.hpp>

#include <cmath>

#include "casteljau/geometry.hpp"

using namespace casteljau;

TEST_CASE("Capsule: points within the radius of the segment, ends rounded", "[geometry]") {
    const Capsule c{{0, 0}, {10, 0}, 2};
    CHECK(c.contains({5, 0}));
    CHECK(c.contains({5, 2}));  // on the side: boundary included
    CHECK_FALSE(c.contains({5, 2.001}));
    CHECK(c.contains({-2, 0}));            // on the round end
    CHECK_FALSE(c.contains({-1.5, 1.5}));  // 2.12 from the end
    CHECK(c.contains({11.4, 1.4}));        // 1.98 from (10, 0)
    const Capsule disc{{3, 4}, {3, 4}, 5};
    CHECK(disc.contains({0, 0}));
    CHECK_FALSE(disc.contains({-0.01, 0}));
}

TEST_CASE("Affine::min_scale: the smaller singular value", "[geometry]") {
    CHECK(Affine{}.min_scale() == 1);
    CHECK(Affine::scale(3, 0.5).min_scale() == Approx(0.5));
    CHECK(Affine::rotate(0.7).min_scale() == Approx(1));
    CHECK((Affine::rotate(0.3) * Affine::scale(2, 5)).min_scale() == Approx(2));
    // [1 1; 0 1] (a shear): singular values (sqrt(5) -/+ 1) / 2.
    CHECK(Affine{1, 0, 1, 1, 0, 0}.min_scale() == Approx((std::sqrt(5.0) - 1) / 2));
    CHECK(Affine::scale(1, 0).min_scale() == 0);
}

TEST_CASE("Affine::map_bounds: the bounds of the four mapped corners", "[geometry]") {
    const Rect r{1, 2, 4, 6};
    CHECK(Affine{}.map_bounds(r) == r);
    CHECK(Affine::translate(10, -1).map_bounds(r) == Rect{11, 1, 14, 5});
    CHECK(Affine::scale(-2, 0.5).map_bounds(r) == Rect{-8, 1, -2, 3});  // a mirror swaps the ends
    // A quarter turn: (x, y) -> (-y, x).
    const Rect q = Affine{0, 1, -1, 0, 0, 0}.map_bounds(r);
    CHECK(q == Rect{-6, 1, -2, 4});
    // A shear: (x, y) -> (x + y, y); the corner (4, 6) reaches x = 10, (1, 2) x = 3.
    CHECK(Affine{1, 0, 1, 1, 0, 0}.map_bounds(r) == Rect{3, 2, 10, 6});
}
