// The rasterizer has two ways through: the direct path (the shape's box inside the target fits one
// buffer: edges accumulate as they are flattened, overlaps found by runs of edges per cell) and the
// strip path (larger boxes: an edge list swept in strips, overlaps found by per-edge cell tags).
// Both compute exact coverage, so they must agree; and the direct path must survive a sink that
// throws halfway.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "casteljau/raster.hpp"
#include "raster_check.hpp"

using namespace casteljau;
using namespace casteljau::testing;

namespace {

// Overlapping, self-intersecting polygons plus curved contours in both orientations, about
// 900 x 700 px: 630,000 cells, past the direct path's 2^18.
Path busy_scene() {
    std::mt19937 rng(77);
    Path p;
    for (int i = 0; i < 6; ++i) p.add_polygon(random_polygon(rng, {20, 20, 880, 680}, 7 + i));
    p.add_polygon(star_polygon({450, 350}, 330, 11, 4, 0.1));
    for (int i = 0; i < 5; ++i) {
        const double cx = 150 + 150 * i, cy = 350 + 120 * std::sin(i), r = 90 + 13 * i;
        p.move_to({cx + r, cy});
        const double k = 0.5522847498 * r;
        const double s = i % 2 ? -1 : 1;  // alternate orientation
        p.cubic_to({cx + r, cy + s * k}, {cx + k, cy + s * r}, {cx, cy + s * r});
        p.cubic_to({cx - k, cy + s * r}, {cx - r, cy + s * k}, {cx - r, cy});
        p.cubic_to({cx - r, cy - s * k}, {cx - k, cy - s * r}, {cx, cy - s * r});
        p.cubic_to({cx + k, cy - s * r}, {cx + r, cy - s * k}, {cx + r, cy});
        p.close();
    }
    return p;
}

}  // namespace

TEST_CASE("raster paths: the strip path and the direct path (tiles, clipped) agree", "[raster]") {
    const Path scene = busy_scene();
    const Affine m = Affine::translate(0.37, 0.61);
    const IRect whole{0, 0, 910, 720};
    for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
        FillOptions o;
        o.rule = rule;
        Rasterizer r;
        const Rendered big = render(r, scene, m, o, whole);
        REQUIRE(big.contract_violation.empty());
        CHECK(big.stats.strips > 1);  // the strip path
        int worst = 0, worst_x = 0, worst_y = 0, direct_tiles = 0, tiles = 0;
        for (int ty = 0; ty < whole.y1; ty += 150) {
            for (int tx = 0; tx < whole.x1; tx += 130) {
                const IRect tile{tx, ty, std::min(tx + 130, whole.x1), std::min(ty + 150, whole.y1)};
                const Rendered part = render(r, scene, m, o, tile);
                REQUIRE(part.contract_violation.empty());
                ++tiles;
                direct_tiles += part.stats.strips == 1;
                for (int y = tile.y0; y < tile.y1; ++y)
                    for (int x = tile.x0; x < tile.x1; ++x) {
                        const int d = std::abs(part.at(x, y) - big.at(x, y));
                        if (d > worst) worst = d, worst_x = x, worst_y = y;
                    }
            }
        }
        INFO("rule " << (rule == FillRule::NonZero ? "nonzero" : "evenodd") << ": worst difference " << worst
                     << " at (" << worst_x << ", " << worst_y << ")");
        CHECK(direct_tiles == tiles);
        CHECK(worst <= 1);  // both exact; only the rounding of sums in a different order may differ
    }
}

TEST_CASE("raster paths: a sink that throws leaves the rasterizer usable", "[raster]") {
    struct Throwing : SpanSink {
        int rows = 0;
        void row(int, int, int, const std::uint8_t*) override {
            if (++rows == 3) throw std::runtime_error("sink failed");
        }
    };
    Path p;
    p.add_polygon(star_polygon({20, 20}, 15, 7, 3));
    Rasterizer r;
    const Mask before = r.fill_mask(p, Affine{});
    Throwing t;
    CHECK_THROWS_AS(r.fill(p, Affine{}, {}, {0, 0, 40, 40}, t), std::runtime_error);
    const Mask after = r.fill_mask(p, Affine{});
    CHECK(after.bounds == before.bounds);
    CHECK(after.data == before.data);
}
