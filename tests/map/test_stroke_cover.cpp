// An opaque round stroke swept before the fills it covers (map/stroke_cover.hpp): the pixels it
// covers fully are hidden from the fills, and the map comes out as with the stroke swept after
// them.
#include <catch2/catch.hpp>

#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "casteljau/map.hpp"
#include "map/stroke_cover.hpp"
#include "map_test_util.hpp"

using namespace casteljau;

namespace {

// Two features on 2 px per degree (bbox 0..100 x 0..50 on 200 x 100 px): a square stacked twice
// (its side pixels need the exact computation: accumulation adds the copies), and a ring of 60
// random positions in 2 x 2 degrees, crossing itself everywhere (its pixels need it too, and a
// stroke of a few tenths of a pixel covers most of them fully).
MapData overlapping_parts() {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(60.0, 62.0), v(20.0, 22.0);
    std::string ring, first;
    for (int i = 0; i < 60; ++i) {
        char position[64];
        const double x = u(rng), y = v(rng);
        std::snprintf(position, sizeof position, "[%.6f,%.6f]", x, y);
        if (i == 0) first = position;
        ring.append(position).append(",");
    }
    ring.append(first);  // closed
    return read_geojson(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"MultiPolygon","coordinates":[
        [[[5.15,5.15],[40.15,5.15],[40.15,40.15],[5.15,40.15],[5.15,5.15]]],
        [[[5.15,5.15],[40.15,5.15],[40.15,40.15],[5.15,40.15],[5.15,5.15]]]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[)" +
                        ring + "]]}}]}");
}

int differing(const Pixmap& a, const Pixmap& b) {
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) n += !(a.pixel(x, y) == b.pixel(x, y));
    return n;
}

}  // namespace

TEST_CASE("Map strokes: an opaque stroke over its fill gives the pixels of the stroke drawn after the fill",
          "[map][stroke][hidden]") {
    const MapData d = overlapping_parts();
    MapOptions o;
    o.width = 200;
    o.height = 100;
    o.bbox = Rect{0, 0, 100, 50};
    MapStyle one;
    one.background = Color::white();
    one.layers[0].fill = Color::rgba(200, 180, 60, 255);
    one.layers[0].stroke = Color::rgba(20, 30, 90, 255);
    one.layers[0].stroke_width = 0.4;
    // The same stroke in a layer of its own is swept after the fills, which then hide nothing.
    const MapStyle two = test::stroke_in_own_layer(one, *one.layers[0].stroke);
    for (int threads : {1, 2}) {
        INFO(threads << " threads");
        o.threads = threads;
        const Pixmap a = render_map(d, MapProjection{}, one, o), b = render_map(d, MapProjection{}, two, o);
        CHECK(differing(a, b) == 0);
        // The fills' exact cells show where the stroke does not cover them fully: plain
        // accumulation gives other pixels.
        MapOptions plain = o;
        plain.exact_overlaps = false;
        CHECK(differing(a, render_map(d, MapProjection{}, one, plain)) > 50);
    }
}

TEST_CASE("StrokeCover: the rows of the stroke and the pixels it covers fully", "[map][stroke][hidden]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(10.0, 40.0), v(5.0, 25.0);
    std::vector<LineSegment> segs;
    Point p{u(rng), v(rng)};
    for (int i = 0; i < 80; ++i) {
        const Point q{u(rng), v(rng)};
        segs.push_back({p, q});
        p = q;
    }
    segs.push_back({{45, 28}, {45, 28}});  // a disc
    const IRect image{0, 0, 50, 30};
    const Mask mask = round_stroke_mask(segs, 0.6, image);
    for (const std::vector<IRect>& regions :
         {std::vector<IRect>{image}, std::vector<IRect>{{0, 0, 50, 11}, {0, 11, 50, 17}, {0, 17, 50, 30}}}) {
        INFO(regions.size() << " regions");
        map_detail::StrokeCover cover;
        cover.sweep(segs, 0.6, image, regions, 2);
        std::size_t full = 0;
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 50; ++x) {
                CHECK(cover.full().contains(x, y) == (mask.at(x, y) == 255));
                full += mask.at(x, y) == 255;
            }
        CHECK(full > 100);
        CHECK(cover.full().count() == full);
        // Composited region by region, the rows give the mask's pixels.
        Pixmap a(50, 30), b(50, 30);
        const Paint ink = Paint::solid(Color::rgba(200, 20, 10, 255));
        Canvas ca(a), cb(b);
        for (std::size_t k = 0; k < regions.size(); ++k) cover.composite(k, ca, ink);
        cb.fill_mask(mask, ink);
        CHECK(differing(a, b) == 0);
    }
}
