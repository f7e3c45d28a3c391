// The map stage: fit, projections, antimeridian split, seamless (area) compositing, strokes drawn
// once, styles; checked against the independent exact-area reference (tests/support/reference_area).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/map.hpp"
#include "casteljau/seamless.hpp"
#include "casteljau/stroke.hpp"
#include "casteljau/threads.hpp"
#include "map_test_util.hpp"

using namespace casteljau;
using casteljau::test::EquirectFrame;

namespace {

MapOptions world_options(int w, int h, bool seamless) {
    MapOptions o;
    o.width = w;
    o.height = h;
    o.bbox = Rect{-180, -90, 180, 90};
    o.seamless = seamless;
    return o;
}

// Per-feature reference coverage of the world at W x H (computed once per size).
struct WorldReference {
    std::vector<ref::CoverageGrid> grids;  // one per feature, over its pixel bounds
};

const WorldReference& world_reference(const MapData& world, int w, int h) {
    static std::map<std::pair<int, int>, WorldReference> cache;
    auto it = cache.find({w, h});
    if (it != cache.end()) return it->second;
    WorldReference r;
    const EquirectFrame fr{w, h};
    const IRect image{0, 0, w, h};
    for (const Feature& f : world.features) {
        const ref::Contours cs = test::reference_contours(f, fr);
        IRect b = ref::pixel_bounds(cs, 1);
        b = IRect{std::max(b.x0, 0), std::max(b.y0, 0), std::min(b.x1, image.x1), std::min(b.y1, image.y1)};
        if (b.x0 >= b.x1 || b.y0 >= b.y1) b = IRect{0, 0, 1, 1};
        r.grids.push_back(ref::slab_area(cs, FillRule::EvenOdd, b));
    }
    return cache.emplace(std::make_pair(w, h), std::move(r)).first->second;
}

}  // namespace

TEST_CASE("Map fit: --bbox maps the extent pixel-exactly", "[map]") {
    const MapData d = read_geojson(R"({"type":"Point","coordinates":[0,0]})");
    const MapProjection eq;
    const MapFrame fr = fit_map(d, eq, world_options(2048, 1024, true));
    CHECK(fr.width == 2048);
    CHECK(fr.height == 1024);
    CHECK(fr.to_pixel.apply({-180, 90}) == Point{0, 0});
    CHECK(fr.to_pixel.apply({180, -90}) == Point{2048, 1024});
    CHECK(fr.to_pixel.apply({0, 0}) == Point{1024, 512});
    // Height from the bbox aspect ratio when not given.
    MapOptions o = world_options(1000, 0, true);
    o.bbox = Rect{0, 0, 20, 10};
    CHECK(fit_map(d, eq, o).height == 500);
    // A square of 10 x 10 pixels at the top-left corner covers exactly those pixels.
    const MapData sq = read_geojson(
        R"({"type":"Polygon","coordinates":[[[-180,90],[-180,88.2421875],[-178.2421875,88.2421875],[-178.2421875,90],[-180,90]]]})");
    const Pixmap pm = render_map(sq, eq, MapStyle{}, world_options(2048, 1024, true));
    CHECK(pm.pixel(0, 0).a == 255);
    CHECK(pm.pixel(9, 9).a == 255);
    CHECK(pm.pixel(10, 9).a == 0);
    CHECK(pm.pixel(9, 10).a == 0);
}

TEST_CASE("Map fit: data extent plus padding, aspect kept", "[map]") {
    const MapData d = read_geojson(R"({"type":"Polygon","coordinates":[[[0,0],[40,0],[40,10],[0,10],[0,0]]]})");
    MapOptions o;
    o.width = 420;
    o.padding = 10;
    const MapFrame fr = fit_map(d, MapProjection{}, o);
    CHECK(fr.height == 120);  // 400 px for 40 degrees, 100 px for 10, plus padding
    CHECK(fr.to_pixel.apply({0, 10}).x == Approx(10));
    CHECK(fr.to_pixel.apply({0, 10}).y == Approx(10));
    CHECK(fr.to_pixel.apply({40, 0}).x == Approx(410));
    CHECK(fr.to_pixel.apply({40, 0}).y == Approx(110));
    o.height = 300;  // taller image: the extent is centred vertically
    const MapFrame tall = fit_map(d, MapProjection{}, o);
    CHECK(tall.to_pixel.apply({0, 5}).y == Approx(150));
    CHECK(tall.to_pixel.apply({40, 5}).x == Approx(410));
    // Nothing to fit.
    CHECK_THROWS_AS(fit_map(read_geojson(R"({"type":"FeatureCollection","features":[]})"), MapProjection{}, o), Error);
    o.padding = 300;
    CHECK_THROWS_AS(fit_map(d, MapProjection{}, o), Error);
}

TEST_CASE("Map projections: Web Mercator, PROJ strings and CRSs", "[map][projection]") {
    const MapProjection m = MapProjection::parse("mercator");
    CHECK(m.kind() == MapProjection::Kind::WebMercator);
    CHECK(MapProjection::parse("EPSG:3857").kind() == MapProjection::Kind::WebMercator);
    Point p;
    REQUIRE(m.project({0, 0}, p));
    CHECK(p.x == Approx(0).margin(1e-9));
    CHECK(p.y == Approx(0).margin(1e-9));
    REQUIRE(m.project({180, 85.0511287798}, p));
    CHECK(p.x == Approx(20037508.342789244));
    CHECK(p.y == Approx(20037508.342789244));
    Point q;
    REQUIRE(m.project({180, 89.9}, q));  // clamped
    CHECK(q.y == p.y);
    const MapProjection robin = MapProjection::parse("+proj=robin");
    CHECK(robin.kind() == MapProjection::Kind::Proj);
    REQUIRE(robin.project({0, 0}, p));
    CHECK(p.x == Approx(0).margin(1e-6));
    const MapProjection laea = MapProjection::parse("EPSG:3035");
    REQUIRE(laea.project({10, 52}, p));  // the projection centre
    CHECK(p.x == Approx(4321000).margin(0.01));
    CHECK(p.y == Approx(3210000).margin(0.01));
    try {
        (void)MapProjection::parse("+proj=nonsense");
        FAIL("expected an error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::InvalidArgument);
        CHECK(std::string(e.what()).find("unknown projection '+proj=nonsense'") != std::string::npos);
    }
    CHECK_THROWS_AS(MapProjection::parse("EPSG:999999"), Error);
    CHECK_THROWS_AS(MapProjection::parse(""), Error);
}

TEST_CASE("Antimeridian: ring and line pieces", "[map][antimeridian]") {
    std::vector<std::vector<Point>> out;
    const std::vector<Point> ring = {{170, -10}, {-170, -10}, {-170, 10}, {170, 10}, {170, -10}};
    split_ring_at_antimeridian(ring, out);
    REQUIRE(out.size() == 2);
    for (const auto& piece : out) {
        for (const Point& p : piece) CHECK(std::fabs(p.x) <= 180);
    }
    out.clear();
    const std::vector<Point> plain = {{0, 0}, {10, 0}, {10, 10}, {0, 0}};
    split_ring_at_antimeridian(plain, out);
    REQUIRE(out.size() == 1);
    CHECK(out[0].size() == 3);
    out.clear();
    split_line_at_antimeridian(std::vector<Point>{{170, 0}, {-170, 20}, {-160, 20}}, out);
    REQUIRE(out.size() == 2);
    CHECK(out[0].back() == Point{180, 10});
    CHECK(out[1].front() == Point{-180, 10});
    CHECK(out[1].back() == Point{-160, 20});
}

TEST_CASE("Antimeridian: a polygon crossing 180 matches the exact reference, no band", "[map][antimeridian]") {
    const MapData d = read_geojson(R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon",
        "coordinates":[[[170.3,-10.1],[-170.2,-10.1],[-169.7,10.4],[170.3,10.4],[170.3,-10.1]]]}})");
    const Pixmap pm = render_map(d, MapProjection{}, MapStyle{}, world_options(720, 360, false));
    const EquirectFrame fr{720, 360};
    const ref::CoverageGrid g =
        ref::slab_area(test::reference_contours(d.features[0], fr), FillRule::EvenOdd, {0, 0, 720, 360});
    double max_err = 0;
    for (int y = 0; y < 360; ++y)
        for (int x = 0; x < 720; ++x) max_err = std::max(max_err, std::fabs(pm.pixel(x, y).a / 255.0 - g.at(x, y)));
    CHECK(max_err <= 0.5 / 255 + 1e-9);
    // No band: the middle of the map stays empty on the polygon's rows.
    for (int x = 25; x < 690; ++x) REQUIRE(pm.pixel(x, 180).a == 0);
    CHECK(pm.pixel(2, 180).a == 255);
    CHECK(pm.pixel(717, 180).a == 255);
    // A line crossing 180 leaves no streak either.
    MapStyle st;
    st.layers[0].stroke = Color::black();
    const MapData l = read_geojson(R"({"type":"LineString","coordinates":[[170,0],[-170,5]]})");
    const Pixmap lp = render_map(l, MapProjection{}, st, world_options(720, 360, true));
    for (int x = 25; x < 690; ++x)
        for (int y = 160; y < 200; ++y) REQUIRE(lp.pixel(x, y).a == 0);
    CHECK(lp.pixel(5, 173).a > 0);
    CHECK(lp.pixel(715, 176).a > 0);
}

TEST_CASE("Antimeridian: Fiji, Russia and Antarctica against the exact reference", "[map][antimeridian]") {
    const MapData world = test::load_world();
    const EquirectFrame fr{2048, 1024};
    for (const char* name : {"Fiji", "Russia", "Antarctica"}) {
        MapData one;
        for (const Feature& f : world.features)
            if (f.property("name") && f.property("name")->text == name) one.features.push_back(f);
        REQUIRE(one.features.size() == 1);
        // Every position drawn: this checks the cut and the rasterizer against the exact area; the
        // simplification's bound is checked in test_map_simplify.cpp.
        MapOptions o = world_options(2048, 1024, false);
        o.simplify = 0;
        const Pixmap pm = render_map(one, MapProjection{}, MapStyle{}, o);
        const ref::CoverageGrid g =
            ref::slab_area(test::reference_contours(one.features[0], fr), FillRule::EvenOdd, {0, 0, 2048, 1024});
        double sum_err = 0, max_err = 0;
        for (int y = 0; y < 1024; ++y)
            for (int x = 0; x < 2048; ++x) {
                const double e = std::fabs(pm.pixel(x, y).a / 255.0 - g.at(x, y));
                sum_err += e;
                max_err = std::max(max_err, e);
            }
        INFO(name << " max error " << max_err * 255 << "/255");
        CHECK(max_err <= 1.0 / 255 + 1e-9);
        CHECK(sum_err / (2048.0 * 1024) <= 0.01 / 255);
    }
    // Antarctica reaches the bottom of the map (its ring winds around the south pole).
    MapData ant;
    for (const Feature& f : world.features)
        if (f.property("name")->text == "Antarctica") ant.features.push_back(f);
    const Pixmap pm = render_map(ant, MapProjection{}, MapStyle{}, world_options(2048, 1024, true));
    CHECK(pm.pixel(1024, 1023).a == 255);
    CHECK(pm.pixel(1024, 500).a == 0);
}

TEST_CASE("Map --separate: world countries at 2048x1024 within 0.5/255 of the exact reference", "[map][accuracy]") {
    const MapData world = test::load_world();
    const int W = 2048, H = 1024;
    const WorldReference& r = world_reference(world, W, H);
    // Source-over of each feature's exact coverage, in file order.
    std::vector<double> alpha(static_cast<std::size_t>(W) * H, 0.0);
    for (const ref::CoverageGrid& g : r.grids)
        for (int y = g.bounds.y0; y < g.bounds.y1; ++y)
            for (int x = g.bounds.x0; x < g.bounds.x1; ++x) {
                double& a = alpha[static_cast<std::size_t>(y) * W + x];
                a = a + g.at(x, y) * (1 - a);
            }
    // Natural Earth polygons are valid, so plain accumulation (exact_overlaps off) is exact too.
    // Every position drawn (the simplification's bound is checked in test_map_simplify.cpp).
    for (bool exact : {true, false}) {
        MapOptions o = world_options(W, H, false);
        o.exact_overlaps = exact;
        o.simplify = 0;
        const Pixmap pm = render_map(world, MapProjection{}, MapStyle{}, o);
        double sum = 0, max_err = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const double e = std::fabs(pm.pixel(x, y).a / 255.0 - alpha[static_cast<std::size_t>(y) * W + x]);
                sum += e;
                max_err = std::max(max_err, e);
            }
        const double mean = sum / (static_cast<double>(W) * H);
        INFO("exact_overlaps " << exact << ": mean abs error " << mean * 255 << "/255, max " << max_err * 255
                               << "/255");
        CHECK(mean <= 0.5 / 255);
        CHECK(max_err <= 2.0 / 255);
    }
}

TEST_CASE("Seamless: world countries show no seam, --separate does", "[map][seamless]") {
    const MapData world = test::load_world();
    const int W = 2048, H = 1024;
    const WorldReference& r = world_reference(world, W, H);
    std::vector<double> sum(static_cast<std::size_t>(W) * H, 0.0);
    for (const ref::CoverageGrid& g : r.grids)
        for (int y = g.bounds.y0; y < g.bounds.y1; ++y)
            for (int x = g.bounds.x0; x < g.bounds.x1; ++x) sum[static_cast<std::size_t>(y) * W + x] += g.at(x, y);
    const Pixmap seamless = render_map(world, MapProjection{}, MapStyle{}, world_options(W, H, true));
    const Pixmap separate = render_map(world, MapProjection{}, MapStyle{}, world_options(W, H, false));
    int full = 0, seamless_gaps = 0, separate_gaps = 0, shared = 0;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double s = sum[static_cast<std::size_t>(y) * W + x];
            if (s < 1 - 1e-9) continue;  // not fully covered by the countries together
            ++full;
            bool partial = false;  // covered by two or more features sharing the pixel
            for (const ref::CoverageGrid& g : r.grids) {
                const double c = g.at(x, y);
                if (c > 1e-9 && c < 1 - 1e-9) {
                    partial = true;
                    break;
                }
            }
            if (partial) ++shared;
            if (seamless.pixel(x, y).a != 255) ++seamless_gaps;
            if (separate.pixel(x, y).a != 255) ++separate_gaps;
        }
    INFO(full << " fully covered pixels, " << shared << " on shared borders");
    CHECK(shared > 1000);
    CHECK(seamless_gaps == 0);
    CHECK(separate_gaps > shared / 2);  // the seams the default mode removes
}

TEST_CASE("Seamless: two squares sharing an edge at fractional x leave no lighter pixel", "[map][seamless]") {
    // bbox 0..100 x 0..50 degrees on 200 x 100 pixels: 2 px per degree; the shared edge at
    // longitude 25.15 lies at x = 50.3.
    const MapData d = read_geojson(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[5,5],[25.15,5],[25.15,45],[5,45],[5,5]]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[25.15,5],[45,5],[45,45],[25.15,45],[25.15,5]]]}}]})");
    MapStyle st;
    st.background = Color::white();
    st.layers[0].fill = Color::rgba(51, 102, 204);
    MapOptions o;
    o.width = 200;
    o.height = 100;
    o.bbox = Rect{0, 0, 100, 50};
    const Pixmap pm = render_map(d, MapProjection{}, st, o);
    const PremulPixel fill = premultiply(Color::rgba(51, 102, 204));
    for (int y = 11; y < 89; ++y)
        for (int x = 11; x < 89; ++x) REQUIRE(pm.pixel(x, y) == fill);
    o.seamless = false;
    const Pixmap sep = render_map(d, MapProjection{}, st, o);
    CHECK(sep.pixel(50, 50).r > fill.r);  // the seam the default mode avoids
}

TEST_CASE("Map fills: a feature whose parts overlap is exact in both modes", "[map][accuracy]") {
    // One feature whose polygon is there twice (duplicated rings are common in real data), on
    // 2 px per degree: its sides at x = 10.3 and 80.3, y = 19.7 and 89.7. A stacked copy adds
    // nothing: the side pixels keep their area (0.7 and 0.3 of a pixel), not twice it. Its box is
    // large for its few segments, so the renderer classifies it once (Overlapping) for every band.
    const MapData d =
        read_geojson(R"({"type":"Feature","properties":{},"geometry":{"type":"MultiPolygon","coordinates":[
      [[[5.15,5.15],[40.15,5.15],[40.15,40.15],[5.15,40.15],[5.15,5.15]]],
      [[[5.15,5.15],[40.15,5.15],[40.15,40.15],[5.15,40.15],[5.15,5.15]]]]}})");
    MapStyle st;
    MapOptions o;
    o.width = 200;
    o.height = 100;
    o.bbox = Rect{0, 0, 100, 50};
    for (bool seamless : {true, false}) {
        INFO("seamless " << seamless);
        o.seamless = seamless;
        const Pixmap pm = render_map(d, MapProjection{}, st, o);
        for (int y = 20; y < 89; ++y) {
            CHECK(int(pm.pixel(10, y).a) == 179);  // 0.7 x 255
            CHECK(int(pm.pixel(80, y).a) == 77);   // 0.3 x 255
            CHECK(int(pm.pixel(45, y).a) == 255);
        }
        CHECK(int(pm.pixel(45, 19).a) == 77);
        CHECK(int(pm.pixel(45, 89).a) == 179);
    }
}

TEST_CASE("Seamless: complementary coverages of a shared edge always sum to full", "[map][seamless]") {
    std::mt19937 rng(14);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Rasterizer raster;
    for (int trial = 0; trial < 300; ++trial) {
        // A shared slanted edge from (x0, 0) to (x1, 32) with random fractional positions.
        const double x0 = 8 + 16 * u(rng), x1 = 8 + 16 * u(rng), y0 = 4 * u(rng), y1 = 28 + 4 * u(rng);
        Path left, right;
        left.move_to(0, y0).line_to(x0, y0).line_to(x1, y1).line_to(0, y1).close();
        right.move_to(x0, y0).line_to(32, y0).line_to(32, y1).line_to(x1, y1).close();
        SeamlessCompositor ac(32, 32);
        ac.add(raster, right, FillOptions{}, Color::black());
        ac.add(raster, left, FillOptions{}, Color::black());
        const int r0 = static_cast<int>(std::ceil(y0)), r1 = static_cast<int>(std::floor(y1));
        for (int y = r0; y < r1; ++y)
            for (int x = 0; x < 32; ++x) REQUIRE(ac.taken(x, y) == 255);
        Pixmap pm(32, 32);
        ac.composite_onto(pm);
        for (int y = r0; y < r1; ++y)
            for (int x = 0; x < 32; ++x) REQUIRE(pm.pixel(x, y).a == 255);
    }
}

TEST_CASE("Seamless: earlier fills take precedence where fills overlap", "[map][seamless]") {
    Rasterizer raster;
    SeamlessCompositor ac(8, 8);
    Path a, b;
    a.add_rect(Rect{0, 0, 8, 8});
    b.add_rect(Rect{0, 0, 4.5, 8});
    ac.add(raster, b, FillOptions{}, Color::rgba(255, 0, 0));
    ac.add(raster, a, FillOptions{}, Color::rgba(0, 0, 255));
    Pixmap pm(8, 8);
    pm.fill(Color::white());
    ac.composite_onto(pm);
    CHECK(pm.pixel(1, 1) == PremulPixel{255, 0, 0, 255});
    CHECK(pm.pixel(6, 1) == PremulPixel{0, 0, 255, 255});
    CHECK(pm.pixel(4, 1) == PremulPixel{128, 0, 127, 255});  // half red, half blue, no white
}

// The model of seamless.hpp, pixel by pixel from each fill's own coverage: c_i = min(coverage_i,
// 1 - taken), the last 1/255 given when a later fill would leave exactly 1/255, and the layer adds c_i
// times the premultiplied colour (rounded per channel, clamped to the alpha). Opaque and
// translucent fills in random order and positions, so that rows go from the layer's alpha to the
// coverage plane at every stage of their fills.
TEST_CASE("Seamless: opaque and translucent fills in any order give the model's coverage and pixels",
          "[map][seamless]") {
    auto mul = [](unsigned a, unsigned b) { return (a * b + 127) / 255; };  // round(a b / 255)
    std::mt19937 rng(33);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Rasterizer raster;
    const int W = 40, H = 24;
    for (int trial = 0; trial < 60; ++trial) {
        SeamlessCompositor ac(W, H);
        std::vector<unsigned> taken(W * H, 0);
        std::vector<std::array<unsigned, 4>> layer(W * H, {0, 0, 0, 0});
        const int fills = 2 + static_cast<int>(u(rng) * 6);
        for (int f = 0; f < fills; ++f) {
            const double x0 = u(rng) * 30, y0 = u(rng) * 18, x1 = x0 + 2 + u(rng) * 20, y1 = y0 + 2 + u(rng) * 10;
            Path p;
            p.move_to(x0, y0).line_to(x1, y0 + u(rng) * 3).line_to(x1 - u(rng) * 2, y1).line_to(x0, y1).close();
            const bool opaque = u(rng) < 0.6;
            const Color col = Color::rgba(
                static_cast<std::uint8_t>(u(rng) * 255), static_cast<std::uint8_t>(u(rng) * 255),
                static_cast<std::uint8_t>(u(rng) * 255), opaque ? 255 : static_cast<std::uint8_t>(40 + u(rng) * 200));
            ac.add(raster, p, FillOptions{}, col);
            const PremulPixel c = premultiply(col);
            const Mask m = raster.fill_mask(p, Affine{}, FillOptions{}, IRect{0, 0, W, H});
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    const unsigned a = m.at(x, y);
                    unsigned& t = taken[static_cast<std::size_t>(y * W + x)];
                    auto& l = layer[static_cast<std::size_t>(y * W + x)];
                    if (a == 0 || t == 255) continue;
                    const unsigned rem = 255 - t;
                    unsigned take = std::min(a, rem);
                    if (t > 0 && take + 1 == rem) take = rem;  // a second fill meeting the first
                    t += take;
                    const unsigned na = std::min(255u, l[3] + mul(take, c.a));
                    l = {std::min(na, l[0] + mul(take, c.r)), std::min(na, l[1] + mul(take, c.g)),
                         std::min(na, l[2] + mul(take, c.b)), na};
                }
        }
        Pixmap pm(W, H);
        ac.composite_onto(pm);  // onto transparent: the layer itself
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const auto& l = layer[static_cast<std::size_t>(y * W + x)];
                INFO("trial " << trial << ", pixel (" << x << ", " << y << ")");
                REQUIRE(int(ac.taken(x, y)) == int(taken[static_cast<std::size_t>(y * W + x)]));
                REQUIRE(pm.pixel(x, y) == PremulPixel{static_cast<std::uint8_t>(l[0]), static_cast<std::uint8_t>(l[1]),
                                                      static_cast<std::uint8_t>(l[2]),
                                                      static_cast<std::uint8_t>(l[3])});
            }
    }
}

TEST_CASE("Seamless: reset() and clear() forget every earlier fill, composite_onto() leaves untouched rows alone",
          "[map][seamless]") {
    Rasterizer raster;
    Path big, dot;
    big.add_rect(Rect{0.5, 0.5, 31.5, 15.5});
    dot.add_rect(Rect{40, 20, 42, 22});
    SeamlessCompositor ac(IRect{0, 0, 32, 16});
    ac.add(raster, big, FillOptions{}, Color::rgba(255, 0, 0));
    CHECK(ac.taken(10, 10) == 255);
    ac.reset(IRect{32, 16, 64, 32});  // same size elsewhere: the memory is reused
    CHECK(ac.taken(40, 20) == 0);
    ac.add(raster, dot, FillOptions{}, Color::rgba(0, 0, 255));
    Pixmap pm(64, 32);
    pm.fill(Color::white());
    ac.composite_onto(pm);
    int changed = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) changed += !(pm.pixel(x, y) == PremulPixel{255, 255, 255, 255});
    CHECK(changed == 4);  // the dot only, nothing of the red fill
    CHECK(pm.pixel(41, 21) == PremulPixel{0, 0, 255, 255});
    ac.clear();
    for (int y = 16; y < 32; ++y)
        for (int x = 32; x < 64; ++x) REQUIRE(ac.taken(x, y) == 0);
    pm.fill(Color::white());
    ac.composite_onto(pm);
    CHECK(pm.pixel(41, 21) == PremulPixel{255, 255, 255, 255});
}

TEST_CASE("Seamless: band compositors give the whole-image compositor's pixels, also on a strided target",
          "[map][seamless]") {
    // render_map composites each band in a compositor covering that band only; the result must
    // equal one compositor over the whole image, and compositing must follow the target's stride.
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Path> fills;
    std::vector<Color> colors;
    for (int i = 0; i < 40; ++i) {
        Path p;
        const double cx = 60 * u(rng), cy = 45 * u(rng), r = 2 + 12 * u(rng);
        p.move_to(cx + r, cy);
        for (int k = 1; k < 7; ++k) p.line_to(cx + r * std::cos(k * 0.9), cy + r * std::sin(k * 1.3));
        p.close();
        fills.push_back(p);
        colors.push_back(Color::rgba(static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()),
                                     static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(128 + rng() % 128)));
    }
    Rasterizer raster;
    SeamlessCompositor whole(64, 48);
    for (std::size_t i = 0; i < fills.size(); ++i) whole.add(raster, fills[i], FillOptions{}, colors[i], 0.9);
    Pixmap expected(64, 48);
    expected.fill(Color::rgba(10, 20, 30));
    whole.composite_onto(expected);
    // The same into caller memory with 7 pixels of padding per row, band by band (17 rows each).
    const std::size_t stride = (64 + 7) * 4;
    std::vector<std::uint8_t> memory(stride * 48, 0xAB);
    Pixmap banded = Pixmap::borrow(memory.data(), 64, 48, stride);
    banded.fill(Color::rgba(10, 20, 30));
    std::optional<SeamlessCompositor> band;
    for (int y0 = 0; y0 < 48; y0 += 17) {
        const IRect region{0, y0, 64, std::min(48, y0 + 17)};
        if (band)
            band->reset(region);
        else
            band.emplace(region);
        for (std::size_t i = 0; i < fills.size(); ++i)
            band->add(raster, fills[i], FillOptions{}, colors[i], 0.9, region);
        band->composite_onto(banded);
    }
    int differ = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 64; ++x) differ += !(banded.pixel(x, y) == expected.pixel(x, y));
    CHECK(differ == 0);
    int padding_touched = 0;
    for (int y = 0; y < 48; ++y)
        for (std::size_t k = 64 * 4; k < stride; ++k)
            padding_touched += memory[static_cast<std::size_t>(y) * stride + k] != 0xAB;
    CHECK(padding_touched == 0);
}

TEST_CASE("Map strokes: a shared border is stroked once, not twice darker", "[map][stroke]") {
    const MapData d = read_geojson(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[10,10],[50,10],[50,40],[10,40],[10,10]]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[50,10],[90,10],[90,40],[50,40],[50,10]]]}}]})");
    MapStyle st;
    st.layers[0].fill.reset();
    st.layers[0].stroke = Color::rgba(0, 0, 0, 128);
    st.layers[0].stroke_width = 4;
    MapOptions o;
    o.width = 100;
    o.height = 50;
    o.bbox = Rect{0, 0, 100, 50};
    const Pixmap pm = render_map(d, MapProjection{}, st, o);
    const int shared = pm.pixel(50, 25).a, outer = pm.pixel(10, 25).a;
    CHECK(outer == 128);
    CHECK(shared == 128);
}

TEST_CASE("Map strokes: a wide stroke over crowded borders is the union of its rings' strokes", "[map][stroke]") {
    // A grid of small jittered cells sharing their borders, stroked far wider than a cell: the
    // outlines pile up in every pixel, as a world map's do at a small scale. The reference strokes
    // every ring whole and fills the union exactly. render_map strokes the borders once
    // (SharedBorders): through their outlines (bevel joins, or round ones with sampled strokes
    // off), marking the pixels its capsules hold full, it gives the same coverage; sampled (round
    // joins and caps), it is within the sampling's bound (casteljau/round_stroke.hpp: 1/64 of
    // full coverage per boundary in a pixel, both sides of a line 8/255).
    constexpr int kCols = 16, kRows = 8;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> jitter(-0.6, 0.6);
    std::vector<std::vector<Point>> node(kCols + 1, std::vector<Point>(kRows + 1));
    for (int i = 0; i <= kCols; ++i)
        for (int j = 0; j <= kRows; ++j) node[i][j] = {20 + 3.5 * i + jitter(rng), 12 + 3 * j + jitter(rng)};
    std::string json = R"({"type":"FeatureCollection","features":[)";
    for (int i = 0; i < kCols; ++i)
        for (int j = 0; j < kRows; ++j) {
            const Point ring[] = {node[i][j], node[i + 1][j], node[i + 1][j + 1], node[i][j + 1], node[i][j]};
            json += (i || j) ? "," : "";
            json += R"({"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[)";
            for (int k = 0; k < 5; ++k) {
                char buf[64];
                std::snprintf(buf, sizeof buf, "%s[%.17g,%.17g]", k ? "," : "", ring[k].x, ring[k].y);
                json += buf;
            }
            json += "]]}}";
        }
    json += "]}";
    const MapData d = read_geojson(json);
    struct Case {
        LineJoin join;
        bool sampled;
        int bound;  // 1/255
    };
    for (const Case c :
         {Case{LineJoin::Round, false, 1}, Case{LineJoin::Bevel, true, 1}, Case{LineJoin::Round, true, 8}}) {
        const LineJoin join = c.join;
        MapStyle st;
        st.layers[0].fill.reset();
        st.layers[0].stroke = Color::rgba(0, 0, 0, 255);
        st.layers[0].stroke_width = 9;
        st.join = join;
        MapOptions o;
        o.width = 100;
        o.height = 50;
        o.bbox = Rect{0, 0, 100, 50};
        o.simplify = 0;
        o.threads = 1;
        o.sampled_strokes = c.sampled;
        const Pixmap pm = render_map(d, MapProjection{}, st, o);
        const Affine to_pixel = fit_map(d, MapProjection{}, o).to_pixel;
        StrokeStyle ss;
        ss.width = 9;
        ss.join = join;
        Path outlines;
        for (int i = 0; i < kCols; ++i)
            for (int j = 0; j < kRows; ++j) {
                Path ring;
                ring.move_to(to_pixel.apply(node[i][j]));
                ring.line_to(to_pixel.apply(node[i + 1][j]));
                ring.line_to(to_pixel.apply(node[i + 1][j + 1]));
                ring.line_to(to_pixel.apply(node[i][j + 1]));
                ring.close();
                outlines.append(stroke(ring, ss, Affine{}, MapOptions{}.tolerance));
            }
        Rasterizer r;
        FillOptions fo;
        fo.tolerance = MapOptions{}.tolerance;
        const Mask ref = r.fill_mask(outlines, Affine{}, fo);
        int worst = 0;
        for (int y = 0; y < 50; ++y)
            for (int x = 0; x < 100; ++x) worst = std::max(worst, std::abs(int(pm.pixel(x, y).a) - int(ref.at(x, y))));
        INFO("join " << int(join) << ", sampled " << c.sampled);
        CHECK(worst <= c.bound);
    }
}

TEST_CASE("Map styles: categorical palette, numeric ramp, points, style file", "[map][style]") {
    const MapData d = read_geojson(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{"kind":"a","v":0},"geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]]]}},
      {"type":"Feature","properties":{"kind":"b","v":10},"geometry":{"type":"Polygon","coordinates":[[[20,0],[30,0],[30,10],[20,10],[20,0]]]}},
      {"type":"Feature","properties":{"kind":"a","v":5},"geometry":{"type":"Point","coordinates":[45,5]}}]})");
    MapOptions o;
    o.width = 100;
    o.height = 20;
    o.bbox = Rect{0, 0, 50, 10};
    MapStyle st;
    st.layers[0].fill_by = "kind";
    st.point_radius = 4;
    Pixmap pm = render_map(d, MapProjection{}, st, o);
    const Color ca = *st.layers[0].fill_for(d.features[0]);
    CHECK(ca == *st.layers[0].fill_for(d.features[2]));
    CHECK(!(ca == *st.layers[0].fill_for(d.features[1])));
    CHECK(pm.pixel(10, 10) == premultiply(ca));
    CHECK(pm.pixel(90, 10) == premultiply(ca));  // the point disk (radius 4 px)
    CHECK(pm.pixel(95, 10).a == 0);
    st.layers[0].ramp = ColorRamp{0, 10, Color::rgba(0, 0, 0), Color::rgba(200, 100, 50)};
    st.layers[0].fill_by = "v";
    pm = render_map(d, MapProjection{}, st, o);
    CHECK(pm.pixel(10, 10) == PremulPixel{0, 0, 0, 255});
    CHECK(pm.pixel(50, 10) == PremulPixel{200, 100, 50, 255});
    CHECK(pm.pixel(90, 10) == PremulPixel{100, 50, 25, 255});
    // A style file with a filter.
    const MapStyle file = read_map_style(R"({"background":"white","layers":[
        {"filter":{"property":"kind","==":"b"},"fill":"#ff0000"},
        {"filter":{"property":"v","<":3},"fill":"#0000ff","opacity":0.5}]})");
    REQUIRE(file.layers.size() == 2);
    pm = render_map(d, MapProjection{}, file, o);
    CHECK(pm.pixel(50, 10) == PremulPixel{255, 0, 0, 255});
    CHECK(pm.pixel(10, 10) == PremulPixel{127, 127, 255, 255});
    CHECK(pm.pixel(90, 10) == PremulPixel{255, 255, 255, 255});
    CHECK_THROWS_AS(read_map_style(R"({"layers":[{"filter":{"property":"x"}}]})"), Error);
    CHECK_THROWS_AS(read_map_style(R"({"layers":[{"fill":"notacolour"}]})"), Error);
    CHECK_THROWS_AS(read_map_style(R"({"layers":{}})"), Error);
}

TEST_CASE("Map threads: 1, 2 and 5 threads give the same pixels in every mode", "[map][threads]") {
    const MapData world = test::load_world();
    MapStyle style;
    style.layers[0].fill_by = "name";
    style.layers[0].stroke = Color::rgba(40, 40, 40);
    style.layers[0].stroke_width = 0.8;
    set_thread_count(5);  // the pool: five threads even on a smaller machine
    for (bool seamless : {true, false}) {
        MapOptions o = world_options(1500, 750, seamless);
        o.threads = 1;
        const Pixmap one = render_map(world, MapProjection{}, style, o);
        for (int t : {2, 5}) {
            o.threads = t;
            const Pixmap many = render_map(world, MapProjection{}, style, o);
            INFO("seamless " << seamless << ", " << t << " threads");
            REQUIRE(many.width() == one.width());
            REQUIRE(many.height() == one.height());
            std::size_t differ = 0;
            for (int y = 0; y < one.height(); ++y)
                for (int x = 0; x < one.width(); ++x) differ += !(many.pixel(x, y) == one.pixel(x, y));
            CHECK(differ == 0);
        }
    }
    set_thread_count(0);
    MapOptions bad = world_options(100, 50, true);
    bad.threads = -1;
    CHECK_THROWS_AS(render_map(world, MapProjection{}, style, bad), Error);
}

TEST_CASE("render_map onto a drawn pixmap replaces every pixel with the background first, transparent too", "[map]") {
    const MapData d = read_map_data(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[10,10],[40,10],[40,40],[10,40],[10,10]]]}}]})");
    MapOptions o;
    o.width = 100;
    o.height = 50;
    o.bbox = Rect{0, 0, 100, 50};
    for (int seamless = 0; seamless < 2; ++seamless) {
        o.seamless = seamless != 0;
        const MapStyle st;  // transparent background, black fill
        const Pixmap fresh = render_map(d, MapProjection{}, st, o);
        Pixmap drawn(100, 50);
        drawn.fill(Color::rgba(255, 0, 0));
        render_map(d, MapProjection{}, fit_map(d, MapProjection{}, o), st, o, drawn);
        for (int y = 0; y < 50; ++y)
            for (int x = 0; x < 100; ++x) REQUIRE(drawn.pixel(x, y) == fresh.pixel(x, y));
        CHECK(fresh.pixel(80, 5) == PremulPixel{0, 0, 0, 0});
        CHECK(fresh.pixel(25, 25) == PremulPixel{0, 0, 0, 255});
    }
}

TEST_CASE("render_map into the memory of a released image of its size clears it first", "[map]") {
    // An image of 2 MiB and more takes the memory of a released one of its size (its pixels still
    // there); render_map clears it band by band. Each image is compared with the same map drawn
    // into a pixmap made (zero) while the reused one is alive, so in other memory.
    const MapData world = test::load_world();
    MapStyle red;
    red.background = Color::rgba(255, 0, 0);
    MapStyle clear_style;  // transparent background, black fill
    for (int threads : {1, 2}) {
        MapOptions o = world_options(1024, 512, true);
        o.threads = threads;
        (void)render_map(world, MapProjection{}, red, o);  // released: its red memory waits
        const Pixmap reused = render_map(world, MapProjection{}, clear_style, o);
        Pixmap want(reused.width(), reused.height());
        render_map(world, MapProjection{}, fit_map(world, MapProjection{}, o), clear_style, o, want);
        std::size_t differ = 0, red_left = 0;
        for (int y = 0; y < want.height(); ++y)
            for (int x = 0; x < want.width(); ++x) {
                differ += !(reused.pixel(x, y) == want.pixel(x, y));
                red_left += reused.pixel(x, y) == PremulPixel{255, 0, 0, 255};
            }
        INFO("threads " << threads);
        CHECK(differ == 0);
        CHECK(red_left == 0);
        CHECK(reused.pixel(10, 10) == PremulPixel{0, 0, 0, 0});  // ocean
    }
}

TEST_CASE("Seamless: a compositor writing into a transparent target gives the pixels of a layer composited onto it",
          "[map][seamless]") {
    // Fills overlapping across two bands, translucent and opaque, sharing an edge at a fractional x.
    Rasterizer raster;
    Path a, b, c;
    a.add_rect(Rect{2.5, 3.25, 30.5, 20.75});
    b.add_rect(Rect{30.5, 1.5, 60.25, 29.5});
    c.add_circle(Point{31, 15}, 9.3);
    const IRect top{0, 0, 64, 16}, bottom{0, 16, 64, 32};
    auto fills = [&](SeamlessCompositor& ac) {
        ac.add(raster, c, FillOptions{}, Color::rgba(0, 0, 255, 128), 0.7);
        ac.add(raster, a, FillOptions{}, Color::rgba(255, 0, 0));
        ac.add(raster, b, FillOptions{}, Color::rgba(0, 160, 0, 200));
    };
    Pixmap want(64, 32);
    SeamlessCompositor layer(top);
    for (const IRect& band : {top, bottom}) {
        layer.reset(band);
        fills(layer);
        layer.composite_onto(want);
    }
    Pixmap got(64, 32);
    SeamlessCompositor into(got, top);
    fills(into);
    into.composite_onto(got);      // nothing: the layer is got's own pixels
    into.reset_into(got, bottom);  // the top band's pixels stay
    fills(into);
    std::size_t differ = 0, drawn = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) {
            differ += !(got.pixel(x, y) == want.pixel(x, y));
            drawn += want.pixel(x, y).a != 0;
        }
    CHECK(differ == 0);
    CHECK(drawn > 1000);
    CHECK(into.taken(40, 20) == 255);
    // reset() after reset_into() leaves the target alone; clear() after reset_into() forgets the
    // fills' pixels too.
    into.reset(bottom);
    CHECK(got.pixel(40, 20) == want.pixel(40, 20));
    CHECK(into.taken(40, 20) == 0);
    into.reset_into(got, bottom);
    fills(into);
    into.clear();
    CHECK(got.pixel(40, 20) == PremulPixel{0, 0, 0, 0});
    CHECK(got.pixel(40, 5) == want.pixel(40, 5));
    CHECK_THROWS_AS(into.reset_into(got, IRect{0, 16, 65, 32}), Error);
}

TEST_CASE("Seamless: composite_onto with a background sets the region's rows to it, then composites",
          "[map][seamless]") {
    Rasterizer raster;
    Path a, b;
    a.add_rect(Rect{2.5, 3.25, 30.5, 20.75});
    b.add_circle(Point{31, 15}, 9.3);
    const IRect band{0, 8, 64, 30};  // rows 25 to 29: no fill
    // White (one byte value), an opaque colour of distinct channels, a translucent one.
    for (const Color background : {Color::white(), Color::rgba(248, 244, 240), Color::rgba(20, 40, 200, 100)}) {
        SeamlessCompositor ac(band);
        ac.add(raster, b, FillOptions{}, Color::rgba(0, 0, 255, 128), 0.7);
        ac.add(raster, a, FillOptions{}, Color::rgba(255, 0, 0));
        Pixmap want(64, 32), got(64, 32);
        for (Pixmap* p : {&want, &got}) p->fill(Color::rgba(9, 90, 9));  // outside the band: left alone
        want.fill_rows(band.y0, band.y1, background);
        ac.composite_onto(want);
        ac.composite_onto(got, background);
        std::size_t differ = 0;
        for (int y = 0; y < 32; ++y)
            for (int x = 0; x < 64; ++x) differ += !(got.pixel(x, y) == want.pixel(x, y));
        CHECK(differ == 0);
        CHECK(got.pixel(20, 10) == want.pixel(20, 10));
        CHECK(got.pixel(20, 2) == PremulPixel{9, 90, 9, 255});
        CHECK(got.pixel(60, 20) == premultiply(background));
        CHECK(got.pixel(5, 28) == premultiply(background));
    }
    Pixmap target(64, 32);
    SeamlessCompositor into(target, band);
    CHECK_THROWS_AS(into.composite_onto(target, Color::white()), Error);
}

TEST_CASE("render_map with a background: every band, reached by a fill or not, is the layer over the background",
          "[map][seamless]") {
    // 700 rows: three bands of the renderer; the square reaches the last only.
    const MapData d = read_map_data(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[10.5,1.025],[40,1],[40,4.05],[10,4],[10.5,1.025]]]}}]})");
    MapOptions o;
    o.width = 100;
    o.height = 700;
    o.bbox = Rect{0, 0, 100, 70};
    o.threads = 1;
    for (const Color background : {Color::white(), Color::rgba(248, 244, 240), Color::rgba(20, 40, 200, 100)}) {
        MapStyle st;
        st.layers[0].fill = Color::rgba(200, 30, 30, 220);
        const Pixmap layer = render_map(d, MapProjection{}, st, o);  // transparent: the layer itself
        st.background = background;
        Pixmap got(100, 700);
        got.fill(Color::rgba(255, 0, 0));
        render_map(d, MapProjection{}, fit_map(d, MapProjection{}, o), st, o, got);
        Pixmap want(100, 700);
        want.fill(background);
        for (int y = 0; y < 700; ++y) composite_span_premul(want.row(y), 100, nullptr, layer.row(y));
        std::size_t differ = 0;
        for (int y = 0; y < 700; ++y)
            for (int x = 0; x < 100; ++x) differ += !(got.pixel(x, y) == want.pixel(x, y));
        CHECK(differ == 0);
        CHECK(got.pixel(50, 100) == premultiply(background));
        CHECK(got.pixel(20, 675).r != premultiply(background).r);
    }
}

TEST_CASE("render_map into a new pixmap equals render_map onto a drawn one, layers and strokes included",
          "[map][seamless]") {
    // A new pixmap with a transparent background takes the first seamless layer's fills directly
    // (no layer of the compositor's own); onto a drawn pixmap the background is written first and
    // the layers are composited. Both must give the same pixels: the 110m world in two layers
    // with strokes, and a world of more than 2^20 positions (one compositor for the whole image).
    // The second layer leaves out the added square (no "name"): its outline stays small.
    MapData big = test::load_world();
    Feature square;
    Geometry g;
    g.kind = GeometryKind::Polygons;
    // A square whose first corner is repeated: 2^20 positions, cheap to draw (repeats add no edge).
    g.points.assign((1 << 20) + 10, Point{-40.3, -30.7});
    for (Point p : {Point{80.2, -30.7}, Point{80.2, 50.4}, Point{-40.3, 50.4}, Point{-40.3, -30.7}})
        g.points.push_back(p);
    g.ring_ends.push_back(static_cast<std::uint32_t>(g.points.size()));
    g.polygon_ends.push_back(1);
    square.geometries.push_back(std::move(g));
    big.features.push_back(std::move(square));
    MapStyle style;
    style.layers[0].fill_by = "name";
    style.layers[0].opacity = 0.8;
    MapLayerStyle second;
    second.filter.op = MapFilter::Op::Has;
    second.filter.property = "name";
    second.fill = Color::rgba(0, 0, 0, 90);
    second.stroke = Color::rgba(200, 30, 30);
    second.stroke_width = 0.7;
    style.layers.push_back(second);
    for (int which = 0; which < 2; ++which) {
        const MapData data = which == 0 ? test::load_world() : big;
        MapOptions o = world_options(720, 360, true);
        o.threads = 1;  // one compositor reused band after band
        const Pixmap fresh = render_map(data, MapProjection{}, style, o);
        Pixmap drawn(fresh.width(), fresh.height());
        drawn.fill(Color::rgba(255, 0, 255));
        render_map(data, MapProjection{}, fit_map(data, MapProjection{}, o), style, o, drawn);
        std::size_t differ = 0;
        for (int y = 0; y < fresh.height(); ++y)
            for (int x = 0; x < fresh.width(); ++x) differ += !(drawn.pixel(x, y) == fresh.pixel(x, y));
        INFO((which == 0 ? "110m world" : "110m world and a square of 2^20 positions"));
        CHECK(differ == 0);
        CHECK(fresh.pixel(400, 160).a != 0);  // Chad
    }
}

TEST_CASE("Map strokes: a stroke drawn with its layer's fill equals the same stroke in a layer of its own",
          "[map][stroke]") {
    // The fill's visitors hand the stroke its segments: rings (one with a spike, one leaving the
    // frame, so cut), lines (one leaving the frame), point disks and a mixed collection, in order.
    const MapData all = read_geojson(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{"k":"area"},"geometry":{"type":"Polygon","coordinates":[[[5,5],[30,5],[30,20],[35,22],[30,20],[5,20],[5,5]]]}},
      {"type":"Feature","properties":{"k":"area"},"geometry":{"type":"Polygon","coordinates":[[[60,10],[140,10],[140,45],[60,45],[60,10]],[[70,20],[80,20],[80,30],[70,20]]]}},
      {"type":"Feature","properties":{"k":"line"},"geometry":{"type":"LineString","coordinates":[[2,40],[40,30],[120,48]]}},
      {"type":"Feature","properties":{"k":"dot"},"geometry":{"type":"MultiPoint","coordinates":[[20,35],[45,8]]}},
      {"type":"Feature","properties":{"k":"mix"},"geometry":{"type":"GeometryCollection","geometries":[
        {"type":"Polygon","coordinates":[[[40,30],[55,30],[55,44],[40,30]]]},{"type":"Point","coordinates":[50,15]},
        {"type":"LineString","coordinates":[[35,2],[58,9]]}]}}]})");
    MapOptions o;
    o.width = 200;
    o.height = 100;
    o.bbox = Rect{0, 0, 100, 50};
    const Color fill = Color::rgba(200, 180, 60, 255), ink = Color::rgba(20, 30, 90, 200);
    for (bool seamless : {true, false}) {
        o.seamless = seamless;
        // With a stroke colour: rings, lines and disks are stroked. Without: the fill's colour
        // strokes the lines only (the layer of its own strokes the line feature, and the mixed
        // collection is left out).
        for (bool with_stroke : {true, false}) {
            MapData d = all;
            if (!with_stroke) d.features.pop_back();
            INFO((seamless ? "seamless" : "separate") << (with_stroke ? ", stroke colour" : ", fill colour on lines"));
            MapStyle one;
            one.point_radius = 2.5;
            one.layers[0].fill = fill;
            if (with_stroke) one.layers[0].stroke = ink;
            one.layers[0].stroke_width = 1.3;
            MapStyle two = test::stroke_in_own_layer(one, with_stroke ? ink : fill);
            if (!with_stroke)
                two.layers.back().filter =
                    read_map_style(R"({"layers":[{"filter":{"property":"k","==":"line"}}]})").layers.at(0).filter;
            const Pixmap a = render_map(d, MapProjection{}, one, o), b = render_map(d, MapProjection{}, two, o);
            int differ = 0, inked = 0;
            for (int y = 0; y < a.height(); ++y)
                for (int x = 0; x < a.width(); ++x) {
                    differ += !(a.pixel(x, y) == b.pixel(x, y));
                    inked += a.pixel(x, y).r < 150;
                }
            CHECK(inked > 100);
            CHECK(differ == 0);
        }
    }
}

TEST_CASE("Map strokes: thin round strokes are the exact union of every feature's stroke", "[map][stroke]") {
    // Wiggly rings (many vertices per pixel, folding and reversing), a ring sharing their border
    // and an open line, stroked 0.8 px with round joins and caps: render_map against the union of
    // every ring's and line's own stroke outline, filled exactly (the rasterizer's nonzero rule).
    std::mt19937 rng(53);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> wiggle;
    for (int i = 0; i < 400; ++i) {
        const double t = 2 * kPi * i / 400;
        wiggle.push_back({30 + 18 * std::cos(t) + 0.6 * u(rng), 20 + 12 * std::sin(t) + 0.6 * u(rng)});
    }
    auto coords = [](const std::vector<Point>& pts, bool close) {
        std::string s = "[";
        char buf[64];
        for (std::size_t i = 0; i < pts.size() + (close ? 1 : 0); ++i) {
            const Point& p = pts[i % pts.size()];
            std::snprintf(buf, sizeof buf, "%s[%.6f,%.6f]", i ? "," : "", p.x, p.y);
            s += buf;
        }
        s += "]";
        return s;
    };
    const std::vector<Point> square{{48, 20}, {58, 20}, {58, 30}, {48, 30}};
    const std::vector<Point> line{{5, 35}, {20, 36.3}, {20.2, 36.1}, {5.5, 35.2}, {40, 37.7}};
    auto feature = [](const char* kind, const std::string& coordinates) {
        std::string f = R"({"type":"Feature","properties":{},"geometry":{"type":")";
        f += kind;
        f += R"(","coordinates":)";
        f += coordinates;
        f += "}}";
        return f;
    };
    std::string json = R"({"type":"FeatureCollection","features":[)";
    json += feature("Polygon", "[" + coords(wiggle, true) + "]");
    json += ",";
    json += feature("Polygon", "[" + coords(square, true) + "]");
    json += ",";
    json += feature("LineString", coords(line, false));
    json += "]}";
    const MapData d = read_geojson(json);
    MapStyle st;
    st.layers[0].fill.reset();
    st.layers[0].stroke = Color::rgba(0, 0, 0, 255);
    st.layers[0].stroke_width = 0.8;
    MapOptions o;
    o.width = 64;
    o.height = 44;
    o.bbox = Rect{0, 0, 64, 44};
    o.simplify = 0;
    const Pixmap pm = render_map(d, MapProjection{}, st, o);
    // The frame maps (x, y) to (x, 44 - y).
    Path all;
    auto add = [&](const std::vector<Point>& pts, bool closed) {
        Path p;
        p.move_to({pts[0].x, 44 - pts[0].y});
        for (std::size_t i = 1; i < pts.size(); ++i) p.line_to({pts[i].x, 44 - pts[i].y});
        if (closed) p.close();
        StrokeStyle ss;
        ss.width = 0.8;
        ss.join = LineJoin::Round;
        ss.cap = LineCap::Round;
        all.append(stroke(p, ss, Affine{}, 1e-3));
    };
    add(wiggle, true);
    add(square, true);
    add(line, false);
    Rasterizer r;
    FillOptions fo;
    const Mask truth = r.fill_mask(all, Affine{}, fo, IRect{0, 0, 64, 44});
    REQUIRE(r.last_stats().dense_cells == 0);
    double worst = 0, sum = 0;
    for (int y = 0; y < 44; ++y)
        for (int x = 0; x < 64; ++x) {
            const double e = std::abs(pm.pixel(x, y).a - truth.at(x, y));
            worst = std::max(worst, e);
            sum += e;
        }
    INFO("max " << worst << "/255, mean " << sum / (64 * 44) << "/255");
    CHECK(worst <= 8);
    CHECK(sum / (64 * 44) <= 0.2);
}
