// The rasterizer's one engine has two storage policies: one dense buffer (the shape's box inside
// the target fits it: edges accumulate as they are flattened) and bands (larger boxes: the edges
// are kept and swept band by band, each band a dense buffer). Both compute exact coverage, so they
// must agree; and the engine must survive a sink that throws halfway. The row scan is SIMD with runtime dispatch: every instruction set this CPU and
// the build support must give the same pixels.
#include <catch2/catch.hpp>
#include "core/simd_dispatch.hpp"

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
// 900 x 700 px: 630,000 cells, past one dense buffer's 2^18.
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

TEST_CASE("raster paths: banded and dense storage (tiles, clipped) agree", "[raster]") {
    const Path scene = busy_scene();
    const Affine m = Affine::translate(0.37, 0.61);
    const IRect whole{0, 0, 910, 720};
    for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
        FillOptions o;
        o.rule = rule;
        Rasterizer r;
        const Rendered big = render(r, scene, m, o, whole);
        REQUIRE(big.contract_violation.empty());
        CHECK(big.stats.strips > 1);  // bands
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
        INFO("rule " << (rule == FillRule::NonZero ? "nonzero" : "evenodd") << ": worst difference " << worst << " at ("
                     << worst_x << ", " << worst_y << ")");
        CHECK(direct_tiles == tiles);
        CHECK(worst <= 1);  // both exact; only the rounding of sums in a different order may differ
    }
}

TEST_CASE("raster paths: the overlap check takes smaller bands than plain accumulation, with the same pixels",
          "[raster]") {
    // A self-crossing star, and the same star with a dot 1200 px to its right: a box of 1201 x 80
    // cells, one dense buffer for plain accumulation (at most 2^18 cells) but bands of 27 rows
    // for the overlap check (at most 2^15 cells).
    Path star;
    star.add_polygon(star_polygon({40, 40}, 38, 7, 3, 0.3));
    Path wide = star;
    wide.add_rect(Rect{1200, 10, 1201, 11});
    Rasterizer r;
    FillOptions exact;
    exact.topology = Topology::Overlapping;
    exact.winding_sweep = false;
    for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
        exact.rule = rule;
        const Mask alone = r.fill_mask(star, Affine{}, exact, IRect{0, 0, 80, 80});
        CHECK(r.last_stats().strips == 1);
        const Mask banded = r.fill_mask(wide, Affine{}, exact, IRect{0, 0, 1210, 80});
        CHECK(r.last_stats().strips >= 3);
        FillOptions plain = exact;
        plain.topology = Topology::Unknown;
        plain.exact_overlaps = false;
        (void)r.fill_mask(wide, Affine{}, plain, IRect{0, 0, 1210, 80});
        CHECK(r.last_stats().strips == 1);
        int worst = 0;
        for (int y = 0; y < 80; ++y)
            for (int x = 0; x < 80; ++x) worst = std::max(worst, std::abs(banded.at(x, y) - alone.at(x, y)));
        CHECK(worst <= 1);
        CHECK(alone.at(40, 40) > 0);
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

TEST_CASE("raster paths: every SIMD target of the row scan gives the same pixels", "[raster]") {
    // A busy scene through both paths, and 300 stacked copies of a star (sums far beyond 255, where
    // the order of additions differs most between 4-lane, 2-lane and scalar scans).
    const Path scene = busy_scene();
    Path stacked;
    for (int i = 0; i < 300; ++i) stacked.add_polygon(star_polygon({60, 60}, 50, 7, 3, 0.2));
    Path one;
    one.add_polygon(star_polygon({60, 60}, 50, 7, 3, 0.2));
    struct Job {
        const Path* path;
        IRect clip;
    };
    const Job jobs[] = {{&scene, {0, 0, 910, 720}},
                        {&scene, {130, 150, 260, 300}},
                        {&stacked, {0, 0, 120, 120}},
                        {&one, {0, 0, 120, 120}}};
    const std::vector<std::int64_t> targets = simd::available_targets();
    REQUIRE(!targets.empty());
    std::vector<std::vector<std::uint8_t>> first;
    for (std::int64_t t : targets) {
        simd::restrict_targets(t);
        INFO("SIMD target " << simd::target_name(t));
        std::size_t k = 0;
        for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            FillOptions o;
            o.rule = rule;
            for (const Job& j : jobs) {
                Rasterizer r;
                const Rendered out = render(r, *j.path, Affine::translate(0.37, 0.61), o, j.clip);
                REQUIRE(out.contract_violation.empty());
                if (first.size() <= k) {
                    first.push_back(out.cov);
                } else {
                    int worst = 0;
                    for (std::size_t i = 0; i < out.cov.size(); ++i)
                        worst = std::max(worst, std::abs(out.cov[i] - first[k][i]));
                    CHECK(worst <= 1);  // the same sums, added in another order
                }
                ++k;
            }
        }
        // 300 stacked copies: the single star under nonzero, nothing under even-odd.
        FillOptions nz;
        Rasterizer r;
        CHECK(render(r, stacked, Affine{}, nz, {0, 0, 120, 120}).cov ==
              render(r, one, Affine{}, nz, {0, 0, 120, 120}).cov);
        FillOptions eo;
        eo.rule = FillRule::EvenOdd;
        const Rendered none = render(r, stacked, Affine{}, eo, {0, 0, 120, 120});
        CHECK(std::all_of(none.cov.begin(), none.cov.end(), [](std::uint8_t c) { return c == 0; }));
    }
    simd::restrict_targets(0);
    WARN("row scan checked on " << targets.size() << " SIMD target(s)");
}

namespace {

// A sink offering part of a larger buffer as its direct target. Rows handed to row() go into the
// target where they lie in it, else into a picture of their own; every byte of the buffer outside
// the target must keep its guard value.
class TargetSink final : public SpanSink {
public:
    static constexpr std::uint8_t kGuard = 0xA7;
    TargetSink(const IRect& clip, const IRect& target) : clip_(clip), target_(target) {
        stride_ = clip.width() + 5;  // guard bytes right of every row
        mem_.assign(static_cast<std::size_t>(stride_) * static_cast<std::size_t>(clip.height() + 2), kGuard);
        rows_pic_.assign(static_cast<std::size_t>(clip.width()) * static_cast<std::size_t>(clip.height()), 0);
        for (int y = target.y0; y < target.y1; ++y)
            for (int x = target.x0; x < target.x1; ++x) *byte(x, y) = 0;
    }
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        ++rows_;
        for (int i = 0; i < length; ++i)
            if (x + i >= clip_.x0 && x + i < clip_.x1 && y >= clip_.y0 && y < clip_.y1)
                (inside_target(x + i, y) ? *byte(x + i, y) : *pic(x + i, y)) = coverage[i];
    }
    CoverageTarget target() override { return {byte(target_.x0, target_.y0), stride_, target_}; }
    int at(int x, int y) { return inside_target(x, y) ? *byte(x, y) : *pic(x, y); }
    bool guards_intact() const {
        for (std::size_t i = 0; i < mem_.size(); ++i) {
            const int x = clip_.x0 + static_cast<int>(i % static_cast<std::size_t>(stride_));
            const int y = clip_.y0 + static_cast<int>(i / static_cast<std::size_t>(stride_));
            if (!inside_target(x, y) && mem_[i] != kGuard) return false;
        }
        return true;
    }
    std::size_t rows() const { return rows_; }

private:
    bool inside_target(int x, int y) const {
        return x >= target_.x0 && x < target_.x1 && y >= target_.y0 && y < target_.y1;
    }
    std::uint8_t* byte(int x, int y) {
        return &mem_[static_cast<std::size_t>(y - clip_.y0) * static_cast<std::size_t>(stride_) +
                     static_cast<std::size_t>(x - clip_.x0)];
    }
    std::uint8_t* pic(int x, int y) {
        return &rows_pic_[static_cast<std::size_t>(y - clip_.y0) * static_cast<std::size_t>(clip_.width()) +
                          static_cast<std::size_t>(x - clip_.x0)];
    }
    IRect clip_, target_;
    int stride_ = 0;
    std::vector<std::uint8_t> mem_, rows_pic_;
    std::size_t rows_ = 0;
};

}  // namespace

TEST_CASE("raster paths: a sink's direct target gets the pixels its rows would get", "[raster]") {
    // Shapes for each accumulation: narrow ones proven simple (row vectors), wider simple ones
    // (float cells), self-intersecting ones (the overlap check's double cells and exact cells,
    // the winding sweep) and the busy scene (bands).
    Path narrow, wide, crossing;
    narrow.add_polygon(regular_polygon({21.3, 19.8}, 17.4, 29));
    wide.add_polygon(regular_polygon({150.2, 90.7}, 83.1, 61));
    crossing.add_polygon(star_polygon({61.5, 58.2}, 52, 7, 3, 0.2));
    crossing.add_polygon(star_polygon({70.1, 50.6}, 40, 5, 2, 0.4));
    const Path scene = busy_scene();
    struct Job {
        const Path* path;
        IRect clip;
        Topology topology;
    };
    const Job jobs[] = {{&narrow, {0, 0, 50, 45}, Topology::Simple},
                        {&wide, {0, 0, 260, 190}, Topology::Simple},
                        {&crossing, {0, 0, 120, 120}, Topology::Unknown},
                        {&scene, {0, 0, 910, 720}, Topology::Unknown}};
    const std::vector<std::int64_t> targets = simd::available_targets();
    for (std::int64_t t : targets) {
        simd::restrict_targets(t);
        INFO("SIMD target " << simd::target_name(t));
        for (const Job& j : jobs) {
            const IRect& c = j.clip;
            // The whole clip; rows cut at both ends; one column short on the left (no direct row).
            const IRect cuts[] = {c, {c.x0, c.y0 + 7, c.x1, c.y1 - 9}, {c.x0 + 1, c.y0, c.x1, c.y1}};
            for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd})
                for (bool sweep : {true, false})
                    for (const IRect& cut : cuts) {
                        FillOptions o;
                        o.rule = rule;
                        o.topology = j.topology;
                        o.winding_sweep = sweep;
                        Rasterizer r;
                        const Rendered want = render(r, *j.path, Affine{}, o, c);
                        REQUIRE(want.contract_violation.empty());
                        TargetSink sink(c, cut);
                        r.fill(*j.path, Affine{}, o, c, sink);
                        INFO("clip " << c.x1 << " x " << c.y1 << ", target rows " << cut.y0 << ".." << cut.y1
                                     << " from column " << cut.x0 << ", sweep " << sweep);
                        CHECK(sink.guards_intact());
                        int worst = 0;
                        for (int y = c.y0; y < c.y1; ++y)
                            for (int x = c.x0; x < c.x1; ++x)
                                worst = std::max(worst, std::abs(sink.at(x, y) - want.at(x, y)));
                        CHECK(worst == 0);
                        // Rows of the dense scan wholly in the target are written there, not
                        // handed over (row vectors, the narrow shape, are always handed over).
                        if (cut.x0 == c.x0 && j.path != &narrow) CHECK(sink.rows() < want.rows_delivered);
                    }
        }
    }
    simd::restrict_targets(0);
}
