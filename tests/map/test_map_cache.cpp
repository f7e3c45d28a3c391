// MapCache: the fills' overlap analyses found by one render and kept for the next ones, in any
// frame. The pixels must stay exact: checked against analytic areas, and against renders without
// a cache (both exact; a pixel may round to the neighbouring level).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <thread>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/map.hpp"
#include "map_test_util.hpp"

using namespace casteljau;

namespace {

int max_difference(const Pixmap& a, const Pixmap& b) {
    REQUIRE(a.width() == b.width());
    REQUIRE(a.height() == b.height());
    int worst = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const PremulPixel p = a.pixel(x, y), q = b.pixel(x, y);
            worst =
                std::max({worst, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
        }
    return worst;
}

// A feature whose polygon is there twice (a stacked copy: winding 2 inside), a bow tie (its ring
// crosses itself) and a plain square with a hole.
MapData overlapping_features() {
    return read_geojson(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"MultiPolygon","coordinates":[
        [[[5.15,5.15],[40.15,5.15],[40.15,40.15],[5.15,40.15],[5.15,5.15]]],
        [[[5.15,5.15],[40.15,5.15],[40.15,40.15],[5.15,40.15],[5.15,5.15]]]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[
        [[50.2,5.3],[90.7,44.1],[90.7,5.3],[50.2,44.1],[50.2,5.3]]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[
        [[60,30],[95,30],[95,48],[60,48],[60,30]],[[70,35],[80,35],[80,40],[70,40],[70,35]]]}}]})");
}

MapOptions frame_options(int w, int h, Rect bbox) {
    MapOptions o;
    o.width = w;
    o.height = h;
    o.bbox = bbox;
    return o;
}

}  // namespace

TEST_CASE("MapCache: overlapping features stay exact in every later frame", "[map][cache]") {
    const MapData d = overlapping_features();
    const MapStyle st;
    MapCache cache;
    MapOptions a = frame_options(200, 100, Rect{0, 0, 100, 50});
    // Frames of other scales (one not uniform), offsets and sizes.
    const MapOptions frames[] = {frame_options(370, 160, Rect{-3.3, 1.1, 96.7, 51.1}),
                                 frame_options(123, 61, Rect{2, 3, 60, 40}),
                                 frame_options(800, 400, Rect{0, 0, 100, 50}), a};
    a.cache = &cache;
    const Pixmap first = render_map(d, MapProjection{}, st, a);
    CHECK(cache.kept() == 3);
    for (MapOptions o : frames) {
        INFO("frame " << o.width << " x " << o.height);
        const Pixmap without = render_map(d, MapProjection{}, st, o);
        o.cache = &cache;
        CHECK(max_difference(render_map(d, MapProjection{}, st, o), without) <= 1);
    }
    // In the first frame (2 px per degree), with the cache kept: the stacked copy adds nothing, so
    // its sides at x = 10.3 and 80.3 keep their area (0.7 and 0.3 of a pixel), not twice it.
    const Pixmap again = render_map(d, MapProjection{}, st, a);
    for (int y = 20; y < 89; ++y) {
        CHECK(int(again.pixel(10, y).a) == 179);
        CHECK(int(again.pixel(80, y).a) == 77);
        CHECK(int(again.pixel(45, y).a) == 255);
    }
    CHECK(max_difference(again, first) == 0);
}

TEST_CASE("MapCache: the world's countries draw what they draw without it", "[map][cache]") {
    const MapData world = test::load_world();
    MapStyle st;
    // Fills by name under a thin opaque stroke: the stroke's cover hides pixels from the fills'
    // overlap check too (FillOptions::hidden), inside the cache's boxes and out.
    st.layers[0].fill_by = "name";
    st.layers[0].stroke = Color::rgba(40, 40, 40, 255);
    st.layers[0].stroke_width = 0.8;
    MapCache cache;
    MapOptions o = frame_options(1024, 512, Rect{-180, -90, 180, 90});
    o.simplify = 0;  // the cache serves renders of the data as they are
    o.cache = &cache;
    (void)render_map(world, MapProjection{}, st, o);
    CHECK(cache.kept() > world.features.size() / 2);
    for (Rect bbox : {Rect{-180, -90, 180, 90}, Rect{-20.5, 30.25, 45.5, 72.75}}) {
        MapOptions f = frame_options(700, 350, bbox);
        f.simplify = 0;
        const Pixmap without = render_map(world, MapProjection{}, st, f);
        f.cache = &cache;
        CHECK(max_difference(render_map(world, MapProjection{}, st, f), without) <= 1);
    }
}

TEST_CASE("MapCache: serves only the data and the projection it was first used with", "[map][cache]") {
    const MapData d = overlapping_features();
    const MapData copy = d;
    const MapStyle st;
    MapCache cache;
    MapOptions o = frame_options(100, 50, Rect{0, 0, 100, 50});
    o.cache = &cache;
    (void)render_map(d, MapProjection{}, st, o);
    CHECK_THROWS_AS(render_map(copy, MapProjection{}, st, o), Error);
    CHECK_THROWS_AS(render_map(d, MapProjection::parse("webmercator"), st, o), Error);
    Pixmap target(100, 50);
    CHECK_THROWS_AS(render_map(copy, MapProjection{}, MapFrame{Affine{}, 100, 50}, st, o, target), Error);
    CHECK_NOTHROW(render_map(d, MapProjection{}, st, o));
}

TEST_CASE("MapCache: renders on several threads share one cache", "[map][cache]") {
    const MapData world = test::load_world();
    const MapStyle st;
    // Small enough for the data to be simplified: the threads share the scaled copy too.
    MapOptions o = frame_options(120, 60, Rect{-180, -90, 180, 90});
    o.threads = 1;
    const Pixmap without = render_map(world, MapProjection{}, st, o);
    MapCache cache;
    o.cache = &cache;
    std::vector<Pixmap> out(4, Pixmap(1, 1));
    std::vector<std::thread> threads;
    for (std::size_t t = 0; t < out.size(); ++t)
        threads.emplace_back([&, t] { out[t] = render_map(world, MapProjection{}, st, o); });
    for (std::thread& t : threads) t.join();
    for (const Pixmap& p : out) CHECK(max_difference(p, without) <= 1);
    CHECK(cache.kept() > 0);
}

TEST_CASE("MapCache: each scale's simplified copy serves every window of that scale", "[map][cache]") {
    // At 3 and 1.5 degrees per pixel the world is simplified: one copy per scale, kept, and used
    // by windows of the same scale at other offsets.
    const MapData world = test::load_world();
    const MapStyle st;
    MapCache cache;
    const MapOptions frames[] = {
        frame_options(120, 60, Rect{-180, -90, 180, 90}), frame_options(240, 120, Rect{-180, -90, 180, 90}),
        frame_options(60, 60, Rect{-180, -90, 0, 90}), frame_options(90, 40, Rect{-45, -60, 90, 0}),
        frame_options(120, 60, Rect{-180, -90, 180, 90})};
    for (MapOptions o : frames) {
        INFO("frame " << o.width << " x " << o.height);
        const Pixmap without = render_map(world, MapProjection{}, st, o);
        o.cache = &cache;
        CHECK(max_difference(render_map(world, MapProjection{}, st, o), without) <= 1);
    }
}
