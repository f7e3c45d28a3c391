// bench/bench_raster.cpp: Google Benchmark cases for casteljau's flattening and rasterization.
//
//   BM_FlattenQuads / BM_FlattenCubics   1000 random curves (seeded) across a 512 px square
//   BM_FlattenCircle/R                   a circle of radius R px (four cubics)
//   BM_FlattenGlyphs/PX                  every glyph of the benchmark set (glyph_set.hpp) at PX px
//   BM_RasterGlyphs/PX/EXACT             Rasterizer::fill of the set into a reused buffer
//   BM_FillMaskGlyphs/PX/EXACT           Rasterizer::fill_mask of the set (allocates a Mask per glyph)
//   BM_RasterCircle2000/EXACT            a 2000 px circle into a 2002 x 2002 buffer
//   BM_RasterStar4000/EXACT/RULE         a self-intersecting five-pointed star across a 4000 x 4000 canvas
//   BM_RasterOverlaps/EXACT              64 overlapping circles (every crossing cell goes the exact way)
//   BM_RasterStacked/COPIES/EXACT        COPIES stacked copies of one circle of radius 40 px
// EXACT is FillOptions::exact_overlaps (1 on, the default; 0 off); RULE 0 nonzero, 1 even-odd.
// items_per_second is glyphs (glyph cases), curves (flattening) or shapes (big shapes).
// Flattening uses casteljau::kDefaultTolerance throughout.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <vector>

#include "casteljau/flatten.hpp"
#include "casteljau/raster.hpp"
#include "glyph_set.hpp"

namespace {

using casteljau::Affine;
using casteljau::FillOptions;
using casteljau::FillRule;
using casteljau::IRect;
using casteljau::Path;
using casteljau::Point;

// Glyph sets are loaded once per size and kept for the whole run.
const bench::GlyphSet& glyphs(int px) {
    static bench::Font font;
    static std::map<int, std::unique_ptr<bench::GlyphSet>> sets;
    auto& s = sets[px];
    if (!s) s = std::make_unique<bench::GlyphSet>(font, px);
    return *s;
}

Path random_curves(bool cubic, int count) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 512.0);
    Path p;
    p.move_to(u(rng), u(rng));
    for (int i = 0; i < count; ++i) {
        if (cubic)
            p.cubic_to({u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)});
        else
            p.quad_to({u(rng), u(rng)}, {u(rng), u(rng)});
    }
    p.close();
    return p;
}

void flatten_path(benchmark::State& state, const Path& path, std::int64_t curves) {
    casteljau::Polyline poly;
    for (auto _ : state) {
        casteljau::flatten(path, Affine::identity(), casteljau::kDefaultTolerance, poly);
        benchmark::DoNotOptimize(poly.points.data());
    }
    state.SetItemsProcessed(state.iterations() * curves);
    state.counters["points"] = static_cast<double>(poly.points.size());
}

void BM_FlattenQuads(benchmark::State& state) { flatten_path(state, random_curves(false, 1000), 1000); }
void BM_FlattenCubics(benchmark::State& state) { flatten_path(state, random_curves(true, 1000), 1000); }

void BM_FlattenCircle(benchmark::State& state) {
    const double r = static_cast<double>(state.range(0));
    Path p;
    p.add_circle({r + 1, r + 1}, r);
    flatten_path(state, p, 4);
}

void BM_FlattenGlyphs(benchmark::State& state) {
    const bench::GlyphSet& set = glyphs(static_cast<int>(state.range(0)));
    casteljau::Polyline poly;
    std::size_t points = 0;
    for (auto _ : state) {
        points = 0;
        for (const bench::Glyph& g : set.glyphs()) {
            casteljau::flatten(g.path, g.to_box, casteljau::kDefaultTolerance, poly);
            points += poly.points.size();
        }
        benchmark::DoNotOptimize(points);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.size()));
    state.counters["points/glyph"] = static_cast<double>(points) / static_cast<double>(set.size());
}

void BM_RasterGlyphs(benchmark::State& state) {
    const bench::GlyphSet& set = glyphs(static_cast<int>(state.range(0)));
    FillOptions opts;
    opts.exact_overlaps = state.range(1) != 0;
    casteljau::Rasterizer rast;
    std::vector<std::uint8_t> buf(set.max_box_pixels());
    std::size_t exact = 0;
    for (auto _ : state) {
        exact = 0;
        for (const bench::Glyph& g : set.glyphs()) {
            std::memset(buf.data(), 0, g.box.pixels());
            bench::BufferSink sink(buf.data(), g.box.width);
            rast.fill(g.path, g.to_box, opts, IRect{0, 0, g.box.width, g.box.height}, sink);
            exact += rast.last_stats().exact_cells;
        }
        benchmark::DoNotOptimize(buf.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.size()));
    state.counters["exact_cells/glyph"] = static_cast<double>(exact) / static_cast<double>(set.size());
}

void BM_FillMaskGlyphs(benchmark::State& state) {
    const bench::GlyphSet& set = glyphs(static_cast<int>(state.range(0)));
    FillOptions opts;
    opts.exact_overlaps = state.range(1) != 0;
    casteljau::Rasterizer rast;
    for (auto _ : state) {
        for (const bench::Glyph& g : set.glyphs()) {
            casteljau::Mask m = rast.fill_mask(g.path, g.to_box, opts);
            benchmark::DoNotOptimize(m.data.data());
        }
    }
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.size()));
}

// Fills `path` into a w x h buffer (cleared each time, as a canvas would not be; clearing is part
// of the cost here so that repeated runs stay identical).
void fill_shape(benchmark::State& state, const Path& path, int w, int h, const FillOptions& opts, bool clear) {
    casteljau::Rasterizer rast;
    std::vector<std::uint8_t> buf(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    bench::BufferSink sink(buf.data(), w);
    for (auto _ : state) {
        if (clear) std::memset(buf.data(), 0, buf.size());
        rast.fill(path, Affine::identity(), opts, IRect{0, 0, w, h}, sink);
        benchmark::DoNotOptimize(buf.data());
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["edges"] = static_cast<double>(rast.last_stats().segments);
    state.counters["exact_cells"] = static_cast<double>(rast.last_stats().exact_cells);
    state.counters["strips"] = static_cast<double>(rast.last_stats().strips);
}

void BM_RasterCircle2000(benchmark::State& state) {
    Path p;
    p.add_circle({1001, 1001}, 1000);
    FillOptions o;
    o.exact_overlaps = state.range(0) != 0;
    fill_shape(state, p, 2002, 2002, o, false);
}

void BM_RasterStar4000(benchmark::State& state) {
    Path p;
    const double cx = 2000, cy = 2000, r = 1950;
    for (int i = 0; i < 5; ++i) {
        const double a = -std::numbers::pi / 2 + i * 4 * std::numbers::pi / 5;  // every second vertex: a pentagram
        const Point q{cx + r * std::cos(a), cy + r * std::sin(a)};
        if (i == 0)
            p.move_to(q);
        else
            p.line_to(q);
    }
    p.close();
    FillOptions o;
    o.exact_overlaps = state.range(0) != 0;
    o.rule = state.range(1) ? FillRule::EvenOdd : FillRule::NonZero;
    fill_shape(state, p, 4000, 4000, o, false);
}

void BM_RasterOverlaps(benchmark::State& state) {
    Path p;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(100.0, 412.0);
    for (int i = 0; i < 64; ++i) p.add_circle({u(rng), u(rng)}, 90);
    FillOptions o;
    o.exact_overlaps = state.range(0) != 0;
    fill_shape(state, p, 512, 512, o, true);
}

void BM_RasterStacked(benchmark::State& state) {
    Path one;
    one.add_circle({50, 50}, 40);
    Path p;
    for (int i = 0; i < state.range(0); ++i) p.append(one);
    FillOptions o;
    o.exact_overlaps = state.range(1) != 0;
    fill_shape(state, p, 100, 100, o, true);
}

}  // namespace

BENCHMARK(BM_FlattenQuads);
BENCHMARK(BM_FlattenCubics);
BENCHMARK(BM_FlattenCircle)->Arg(4)->Arg(16)->Arg(64)->Arg(256)->Arg(1000);
BENCHMARK(BM_FlattenGlyphs)->Arg(12)->Arg(24)->Arg(48)->Arg(96)->Arg(256);
BENCHMARK(BM_RasterGlyphs)->ArgsProduct({{12, 24, 48, 96, 256}, {1, 0}});
BENCHMARK(BM_FillMaskGlyphs)->ArgsProduct({{12, 48, 256}, {1, 0}});
BENCHMARK(BM_RasterCircle2000)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RasterStar4000)->ArgsProduct({{1, 0}, {0, 1}})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_RasterOverlaps)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RasterStacked)->ArgsProduct({{2, 300}, {1, 0}})->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
