// Geometry at the output's resolution (MapOptions::simplify): the run simplifier's bound on random
// polylines, its degenerate inputs, border nodes, shared borders simplified identically in both
// rings (GeoJSON and TopoJSON), seams, coverage against the original on the shipped world, sparse
// data drawn as they are, and tiles drawn from one simplified copy per zoom.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <random>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/file_io.hpp"
#include "casteljau/map.hpp"
#include "casteljau/png.hpp"
#include "casteljau/tiles.hpp"
#include "map/border_nodes.hpp"
#include "map/ring_spikes.hpp"
#include "map/simplify_map.hpp"
#include "map/simplify_polyline.hpp"
#include "map_test_util.hpp"

using namespace casteljau;
using casteljau::map_detail::RunSimplifier;

namespace {

double segment_distance(Point p, Point a, Point b) {
    const Point d = b - a;
    const double len2 = d.dot(d);
    const double t = len2 > 0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (p - (a + d * t)).length();
}

double polyline_distance(Point p, std::span<const Point> line) {
    double best = INFINITY;
    for (std::size_t i = 0; i + 1 < line.size(); ++i) best = std::min(best, segment_distance(p, line[i], line[i + 1]));
    if (line.size() == 1) best = (p - line[0]).length();
    return best;
}

std::vector<std::uint8_t> simplify(std::span<const Point> q, double tolerance) {
    RunSimplifier rs;
    std::vector<std::uint8_t> keep(q.size(), 0);
    rs.simplify(q, tolerance, keep, [](std::size_t, std::size_t) { return false; });
    return keep;
}

// A random walk of n steps of up to `step` pixels, with occasional reversals and sharp turns.
std::vector<Point> random_walk(std::mt19937& rng, std::size_t n, double step) {
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> pts{{50, 50}};
    double heading = 0;
    for (std::size_t i = 1; i < n; ++i) {
        heading += u(rng) * (u(rng) > 0.9 ? 3.0 : 0.6);
        const double len = step * (0.5 + 0.5 * u(rng));
        pts.push_back(pts.back() + Point{std::cos(heading), std::sin(heading)} * len);
    }
    return pts;
}

// Two squares sharing a dense, wiggly border along longitude 0 (n positions between latitudes -40
// and 40, wiggling by up to `wiggle` degrees across it), the second ring running the border the
// other way. As GeoJSON text.
std::string two_neighbours(std::size_t n, double wiggle) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Point> border;
    for (std::size_t i = 0; i < n; ++i) {
        const double lat = 40 - 80.0 * double(i) / double(n - 1);
        border.push_back({i == 0 || i + 1 == n ? 0.0 : wiggle * u(rng), lat});
    }
    auto text = [](const std::vector<Point>& r) {
        std::string s = "[[";
        for (std::size_t i = 0; i < r.size(); ++i) {
            char buf[80];
            std::snprintf(buf, sizeof buf, "%s[%.17g,%.17g]", i ? "," : "", r[i].x, r[i].y);
            s += buf;
        }
        return s + "]]";
    };
    // West: down the border, then round the west side. East: round the east side, then up the border.
    std::vector<Point> west = border, east{{40, 40}, {40, -40}};
    west.push_back({-40, -40});
    west.push_back({-40, 40});
    west.push_back(west.front());
    for (auto it = border.rbegin(); it != border.rend(); ++it) east.push_back(*it);
    east.push_back(east.front());
    return R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{"name":"west"},"geometry":)"
           R"({"type":"Polygon","coordinates":)" +
           text(west) +
           R"(}},{"type":"Feature","properties":{"name":"east"},)"
           R"("geometry":{"type":"Polygon","coordinates":)" +
           text(east) + "}}]}";
}

}  // namespace

TEST_CASE("Run simplifier: every dropped vertex within the tolerance, ends kept, both ways within it",
          "[map][simplify]") {
    std::mt19937 rng(2024);
    std::uniform_real_distribution<double> tol_of(0.001, 2.0);
    for (int trial = 0; trial < 300; ++trial) {
        const std::vector<Point> q = random_walk(rng, 2 + trial * 7 % 1500, trial % 3 == 0 ? 0.02 : 0.7);
        const double tol = tol_of(rng);
        const std::vector<std::uint8_t> keep = simplify(q, tol);
        REQUIRE(keep.front() == 1);
        REQUIRE(keep.back() == 1);
        std::vector<Point> kept;
        std::size_t last = 0;
        for (std::size_t i = 0; i < q.size(); ++i) {
            if (!keep[i]) continue;
            kept.push_back(q[i]);
            for (std::size_t k = last + 1; k < i; ++k) {
                INFO("trial " << trial << " vertex " << k << " of " << q.size());
                REQUIRE(segment_distance(q[k], q[last], q[i]) <= tol * (1 + 1e-12));
            }
            last = i;
        }
        // Hausdorff: points along the simplified run are near the original, and the other way.
        for (std::size_t i = 0; i + 1 < kept.size(); ++i)
            for (int s = 0; s <= 8; ++s)
                REQUIRE(polyline_distance(lerp(kept[i], kept[i + 1], s / 8.0), q) <= tol * (1 + 1e-9) + 1e-12);
        for (Point p : q) REQUIRE(polyline_distance(p, kept) <= tol * (1 + 1e-9) + 1e-12);
        // A run with interior vertices keeps at least one of them.
        if (q.size() > 2) CHECK(std::count(keep.begin(), keep.end(), 1) >= 3);
    }
}

TEST_CASE("Run simplifier: degenerate runs", "[map][simplify]") {
    CHECK(simplify({}, 0.1).empty());
    CHECK(simplify(std::vector<Point>{{1, 1}}, 0.1) == std::vector<std::uint8_t>{1});
    CHECK(simplify(std::vector<Point>{{1, 1}, {2, 2}}, 0.1) == std::vector<std::uint8_t>{1, 1});
    // Every point equal: the ends, and the forced vertices (distance zero).
    const std::vector<Point> same(50, Point{3, 3});
    const std::vector<std::uint8_t> k = simplify(same, 0.1);
    CHECK(k.front() == 1);
    CHECK(k.back() == 1);
    CHECK(std::count(k.begin(), k.end(), 1) <= 4);
    // A closed run (first == last) keeps three vertices even when all lie within the tolerance.
    const std::vector<Point> loop{{0, 0}, {0.01, 0}, {0.01, 0.01}, {0.005, 0.012}, {0, 0.01}, {0, 0}};
    const std::vector<std::uint8_t> kl = simplify(loop, 1.0);
    CHECK(std::count(kl.begin(), kl.end(), 1) == 5);  // both ends (one position) and three more
    // Collinear points go; a spike that doubles back beyond the chord's end stays.
    const std::vector<Point> line{{0, 0}, {1, 0}, {2, 0}, {3, 0}, {-1, 0}, {4, 0}, {5, 0}, {6, 0}};
    const std::vector<std::uint8_t> kk = simplify(line, 0.01);
    CHECK(kk == std::vector<std::uint8_t>{1, 0, 0, 1, 1, 0, 0, 1});
    // Past kMaxRunPoints the run is cut, and the cut vertices are kept.
    std::vector<Point> longrun;
    for (std::size_t i = 0; i < 3 * map_detail::kMaxRunPoints; ++i) longrun.push_back({double(i), 0});
    const std::vector<std::uint8_t> kr = simplify(longrun, 1.0);
    CHECK(kr[map_detail::kMaxRunPoints] == 1);
    CHECK(std::count(kr.begin(), kr.end(), 1) <= 7);
}

TEST_CASE("Border nodes: where a shared border starts and ends, line ends, antimeridian steps", "[map][simplify]") {
    // 40,000 positions on the border: the table of positions grows (and renumbers its entries)
    // while the second ring is added.
    for (int n : {200, 40000}) {
        const MapData d = read_geojson(two_neighbours(n, 0.01));
        const map_detail::BorderNodes nodes = map_detail::find_border_nodes(d);
        REQUIRE(nodes.feature_start.size() == 3);
        INFO(n << " positions on the border");
        // The border's two ends are nodes in both rings; no other position of the border is.
        for (std::size_t f = 0; f < 2; ++f) {
            const Geometry& g = d.features[f].geometries[0];
            for (std::size_t i = 0; i + 1 < g.points.size(); ++i) {  // the closing repeat is skipped
                const Point p = g.points[i];
                const bool end = p.x == 0 && std::fabs(p.y) == 40;
                const bool on = p.x != 40 && p.x != -40 && !end;
                if (end)
                    CHECK(nodes.node[nodes.feature_start[f] + i] == 1);
                else if (on)
                    CHECK(nodes.node[nodes.feature_start[f] + i] == 0);
            }
        }
    }
    const MapData l =
        read_geojson(R"({"type":"LineString","coordinates":[[170,0],[175,1],[179,2],[-179,3],[-175,4],[-170,5]]})");
    const map_detail::BorderNodes ln = map_detail::find_border_nodes(l);
    CHECK(ln.node == std::vector<std::uint8_t>{1, 0, 1, 1, 0, 1});
}

TEST_CASE("Border nodes: TopoJSON's arc starts give the nodes the position table finds", "[map][simplify]") {
    // Quantized positions repeat at arc joins here and there; the nodes must land on the first of
    // the repeats, as distinct_positions counts them.
    const auto bytes = read_file(std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json");
    const MapData topo = read_map_data(std::string(bytes.begin(), bytes.end()));
    MapData plain = topo;
    for (Feature& f : plain.features)
        for (Geometry& g : f.geometries) g.arc_starts.clear();  // no arc starts: the table of positions
    const map_detail::BorderNodes from_arcs = map_detail::find_border_nodes(topo);
    const map_detail::BorderNodes from_positions = map_detail::find_border_nodes(plain);
    REQUIRE(from_arcs.node.size() == from_positions.node.size());
    CHECK(std::count(from_arcs.node.begin(), from_arcs.node.end(), 1) > 500);
    // A ring that is one arc (an island) starts at a node; the table finds none in it.
    std::size_t base = 0, islands = 0;
    for (const Feature& f : topo.features)
        for (const Geometry& g : f.geometries) {
            std::uint32_t start = 0;
            for (std::uint32_t end : g.ring_ends) {
                const auto a = from_arcs.node.begin() + std::ptrdiff_t(base + start);
                const auto p = from_positions.node.begin() + std::ptrdiff_t(base + start);
                const bool island = std::count(p, p + (end - start), 1) == 0;
                islands += island;
                for (std::uint32_t i = 0; i < end - start; ++i) {
                    INFO("position " << base + start + i);
                    REQUIRE(a[i] == (island && i == 0 ? 1 : p[i]));
                }
                start = end;
            }
            base += g.points.size();
        }
    CHECK(islands > 50);
    // A join that repeats its position, and a ring closing on repeats of its first.
    const MapData rep = read_topojson(R"({"type":"Topology","objects":{"o":{"type":"GeometryCollection","geometries":[
        {"type":"Polygon","arcs":[[0,1]]},{"type":"Polygon","arcs":[[2,-1]]}]}},"arcs":[
        [[0,40],[1,20],[0,0],[0,0]],
        [[0,0],[0,0],[-40,0],[-40,40],[0,40],[0,40]],
        [[0,40],[40,40],[40,0],[0,0]]]})");
    MapData rep_plain = rep;
    for (Feature& f : rep_plain.features)
        for (Geometry& g : f.geometries) g.arc_starts.clear();
    CHECK(map_detail::find_border_nodes(rep).node == map_detail::find_border_nodes(rep_plain).node);
    CHECK(map_detail::find_border_nodes(rep).node ==
          std::vector<std::uint8_t>{1, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 0});
}

namespace {

MapOptions world_options(int w, int h) {
    MapOptions o;
    o.width = w;
    o.height = h;
    o.bbox = Rect{-180, -90, 180, 90};
    return o;
}

// The positions of feature f's first ring after simplification, less its closing repeat.
std::vector<Point> first_ring(const map_detail::SimplifiedMap& sm, std::size_t f) {
    const Geometry& g = sm.features[f].at(0);
    return std::vector<Point>(g.points.begin(), g.points.begin() + g.ring_ends.at(0) - 1);
}

// The positions of `ring` on the border near longitude 0 (two features' common edge), top to bottom.
std::vector<Point> on_border(const std::vector<Point>& ring) {
    std::vector<Point> out;
    for (Point p : ring)
        if (std::fabs(p.x) < 1) out.push_back(p);
    std::sort(out.begin(), out.end(), [](Point a, Point b) { return a.y > b.y; });
    return out;
}

}  // namespace

TEST_CASE("Map simplify: non-finite positions are rejected before, bad tolerances at the call", "[map][simplify]") {
    CHECK_THROWS_AS(read_geojson(R"({"type":"LineString","coordinates":[[0,0],[1e999,0]]})"), Error);
    const MapData d = read_geojson(R"({"type":"LineString","coordinates":[[0,0],[10,5]]})");
    for (double bad : {-1.0, double(NAN), double(INFINITY)}) {
        MapOptions o = world_options(64, 32);
        o.simplify = bad;
        CHECK_THROWS_AS(render_map(d, MapProjection{}, MapStyle{}, o), Error);
    }
}

TEST_CASE("Map simplify: a dense border shared by two features keeps the same positions in both", "[map][simplify]") {
    const MapData d = read_geojson(two_neighbours(5000, 0.02));
    const MapData topo = read_topojson(R"({"type":"Topology","objects":{"o":{"type":"GeometryCollection","geometries":[
        {"type":"Polygon","arcs":[[0,1]]},{"type":"Polygon","arcs":[[2,-1]]}]}},"arcs":[
        [[0,40],[0.01,30],[-0.02,20],[0.015,10],[-0.01,0],[0.02,-10],[-0.005,-20],[0.01,-30],[0,-40]],
        [[0,-40],[-40,-40],[-40,40],[0,40]],
        [[0,40],[40,40],[40,-40],[0,-40]]]})");
    for (int w : {64, 256, 4096}) {
        const Affine to_pixel{w / 360.0, 0, 0, -w / 360.0, w / 2.0, w / 4.0};
        for (const MapData* data : {&d, &topo}) {
            const map_detail::SimplifiedMap sm = map_detail::simplify_map(*data, map_detail::find_border_nodes(*data),
                                                                          MapProjection{}, to_pixel, 1.0 / 64, 2);
            const std::vector<Point> a = on_border(first_ring(sm, 0)), b = on_border(first_ring(sm, 1));
            INFO("width " << w << (data == &d ? " GeoJSON" : " TopoJSON"));
            CHECK(a == b);
            CHECK(a.size() >= 2);
            if (data == &d && w == 64) CHECK(a.size() < 1000);  // at 64 px the 5000 positions mostly go
        }
    }
}

TEST_CASE("Seamless: two features sharing a long dense border stay seamless when simplified",
          "[map][seamless][simplify]") {
    // 20,000 positions along 80 degrees: at 200 px about a thousand per pixel of border, which the
    // simplification reduces; the border runs at a fractional pixel position.
    const MapData d = read_geojson(two_neighbours(20000, 0.003));
    MapOptions o = world_options(200, 100);
    o.bbox = Rect{-60.123, -50, 59.877, 50};
    MapStyle st;
    st.layers[0].fill = Color::rgba(20, 40, 200);
    for (double simplify : {0.0, 1.0 / 64, 0.25}) {
        o.simplify = simplify;
        const Pixmap pm = render_map(d, MapProjection{}, st, o);
        const MapFrame fr = fit_map(d, MapProjection{}, o);
        const Point top = fr.to_pixel.apply({0, 38}), bottom = fr.to_pixel.apply({0, -38});
        int gaps = 0;
        for (int y = static_cast<int>(top.y) + 1; y < static_cast<int>(bottom.y); ++y)
            for (int x = static_cast<int>(top.x) - 3; x <= static_cast<int>(top.x) + 3; ++x)
                gaps += pm.pixel(x, y).a != 255;
        INFO("simplify " << simplify);
        CHECK(gaps == 0);
    }
}

TEST_CASE("Map simplify: the world's coverage within 0.2/255 on average and 8/255 at most of the original",
          "[map][simplify][accuracy]") {
    // The original drawn with simplify 0 is the reference (the shipped world has few positions per
    // pixel, so no fill runs out of its exact-work budget). The frame is moved by a fraction of a
    // pixel so that the -180 meridian does not lie on a pixel boundary (see bench/map_accuracy.cpp).
    // At 256 px the world is simplified; at 4096 px it is sparse and drawn as it is.
    const MapData world = test::load_world();
    for (int w : {256, 4096}) {
        MapOptions o = world_options(w, w / 2);
        MapFrame fr = fit_map(world, MapProjection{}, o);
        fr.to_pixel = Affine{1, 0, 0, 1, 0.37, 0.29} * fr.to_pixel;
        for (bool stroke : {false, true}) {
            MapStyle st;
            if (stroke) {
                st.layers[0].fill.reset();
                st.layers[0].stroke = Color::black();
                st.layers[0].stroke_width = 0.8;
            }
            Pixmap ref(fr.width, fr.height), out(fr.width, fr.height);
            o.simplify = 0;
            render_map(world, MapProjection{}, fr, st, o, ref);
            o.simplify = kDefaultMapSimplify;
            render_map(world, MapProjection{}, fr, st, o, out);
            double sum = 0;
            int worst = 0;
            for (int y = 0; y < fr.height; ++y)
                for (int x = 0; x < fr.width; ++x) {
                    const int e = std::abs(int(ref.pixel(x, y).a) - int(out.pixel(x, y).a));
                    sum += e;
                    worst = std::max(worst, e);
                }
            const double mean = sum / (double(fr.width) * fr.height);
            INFO(w << " px, " << (stroke ? "stroke" : "fill") << ": mean " << mean << "/255, max " << worst << "/255");
            CHECK(mean <= 0.2);
            CHECK(worst <= 8);
        }
    }
}

TEST_CASE("Map simplify: deciding from the data's lon/lat bounds decides as the projected bounds do",
          "[map][simplify]") {
    const MapData world = test::load_world();
    const MapData north = read_geojson(R"({"type":"LineString","coordinates":[[-20,50],[-10,60],[5,55],[30,75]]})");
    for (const char* spec : {"equirectangular", "mercator"}) {
        const MapProjection proj = MapProjection::parse(spec);
        for (const MapData* data : {&world, &north}) {
            const map_detail::SimplifiedMap as_is = map_detail::bounds_only(*data, proj, 1);
            // From a pixel for the whole extent to 2^20 across it: the decision flips once between.
            const double base = 1 / std::max(as_is.extent.x1 - as_is.extent.x0, as_is.extent.y1 - as_is.extent.y0);
            int flips = 0;
            bool last = false;
            for (double k = 0; k <= 20; k += 0.25) {
                const double s = base * std::exp2(k);
                const Affine to_pixel{s, 0, 0, -s, 3, 7};
                const bool decided = map_detail::worth_simplifying(*data, proj, to_pixel);
                INFO(spec << ", scale 2^" << k);
                CHECK(decided == map_detail::worth_simplifying(as_is, proj, to_pixel));
                flips += k > 0 && decided != last;
                last = decided;
            }
            CHECK(flips == 1);
        }
    }
}

TEST_CASE("Tiles: one simplified copy per zoom draws what render_map draws for the metatile",
          "[map][simplify][tiles]") {
    const MapData world = test::load_world();
    MapStyle st;
    st.layers[0].stroke = Color::black();
    st.layers[0].stroke_width = 1.2;
    const MapProjection merc = MapProjection::parse("mercator");
    const double half = std::numbers::pi * kWebMercatorRadius;
    const map_detail::SimplifiedMap as_is = map_detail::bounds_only(world, merc, 1);
    // 256 px tiles at zoom 2: the 110m world is sparse there and drawn as it is; 64 px tiles at
    // zoom 1: dense, simplified.
    for (const auto& [tile_px, z] : {std::pair{256, 2}, std::pair{64, 1}}) {
        INFO("tile " << tile_px << " px, zoom " << z);
        const double s = static_cast<double>(tile_px << z) / (2 * half);
        CHECK(map_detail::worth_simplifying(as_is, merc, Affine{s, 0, 0, -s, 0, 0}) == (tile_px == 64));
        TileOptions to;
        to.min_zoom = 0;
        to.max_zoom = z;
        to.tile_px = tile_px;
        to.metatile = 2;
        to.buffer = 16;
        to.threads = 2;
        std::map<std::string, std::vector<std::uint8_t>> tiles;
        render_tiles(world, st, to, [&](int tz, int x, int y, const std::vector<std::uint8_t>& png) {
            tiles[std::to_string(tz) + "/" + std::to_string(x) + "/" + std::to_string(y)] = png;
        });
        CHECK(tiles.size() == (z == 2 ? 1 + 4 + 16 : 1 + 4));
        // One metatile of the last zoom drawn alone through render_map, which decides and
        // simplifies in its own frame (the zoom's, translated), then cut.
        const int T = tile_px, B = to.buffer, m0 = z == 2 ? 2 : 0;
        MapFrame fr;
        fr.width = fr.height = 2 * T + 2 * B;
        fr.to_pixel = Affine{s, 0, 0, -s, half * s - (m0 * T - B), half * s - (m0 * T - B)};
        MapOptions mo;
        mo.threads = 1;
        Pixmap pm(fr.width, fr.height);
        render_map(world, merc, fr, st, mo, pm);
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i) {
                Pixmap tile(T, T);
                for (int r = 0; r < T; ++r) {
                    const std::uint8_t* src = pm.row(B + j * T + r) + static_cast<std::size_t>(B + i * T) * 4;
                    std::copy(src, src + static_cast<std::size_t>(T) * 4, tile.row(r));
                }
                const std::string key = std::to_string(z) + "/" + std::to_string(m0 + i) + "/" + std::to_string(m0 + j);
                INFO(key);
                CHECK(tiles.at(key) == encode_png(tile));
            }
    }
}

TEST_CASE("Map simplify: sparse data are drawn as they are, dense data simplified", "[map][simplify]") {
    // The 110m world holds about 0.09 positions per pixel of its extent at 512 px, 1.4 at 128.
    const MapData world = test::load_world();
    MapStyle st;
    st.layers[0].stroke = Color::black();
    st.layers[0].stroke_width = 0.8;
    for (int width : {512, 128}) {
        INFO(width << " px");
        MapOptions mo;
        mo.width = width;
        mo.height = width / 2;
        mo.bbox = Rect{-180, -90, 180, 90};
        mo.threads = 1;
        const Pixmap simplified = render_map(world, MapProjection{}, st, mo);
        mo.simplify = 0;
        const Pixmap every = render_map(world, MapProjection{}, st, mo);
        std::size_t differ = 0;
        for (int y = 0; y < simplified.height(); ++y)
            for (int x = 0; x < simplified.width(); ++x) differ += simplified.pixel(x, y).a != every.pixel(x, y).a;
        if (width == 512)
            CHECK(differ == 0);
        else
            CHECK(differ > 0);
    }
}

TEST_CASE("drop_spikes: steps out and straight back leave a ring, nothing else does", "[map][simplify]") {
    using map_detail::drop_spikes;
    auto spikes_out = [](std::vector<Point> r) {
        drop_spikes(r);
        return r;
    };
    const std::vector<Point> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}};
    CHECK(spikes_out(square) == square);
    // A spike, a spike with a spike on it (A B C B A), a repeated position, the first position
    // repeated at the end.
    CHECK(spikes_out({{0, 0}, {4, 0}, {6, 1}, {4, 0}, {4, 4}, {0, 4}}) == square);
    CHECK(spikes_out({{0, 0}, {4, 0}, {6, 1}, {7, 3}, {6, 1}, {4, 0}, {4, 4}, {0, 4}}) == square);
    CHECK(spikes_out({{0, 0}, {4, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}}) == square);
    // Across the start: the tip is the last position, or the first.
    CHECK(spikes_out({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {-2, -3}}) ==
          std::vector<Point>{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {-2, -3}});  // a fifth corner, not a spike
    CHECK(spikes_out({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {-2, -3}}) == square);
    CHECK(spikes_out({{-2, -3}, {0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}}) ==
          std::vector<Point>{{4, 0}, {4, 4}, {0, 4}, {0, 0}});
    // A fold only part of the way back is kept (it is not a spike).
    const std::vector<Point> fold{{0, 0}, {4, 0}, {6, 0}, {5, 0}, {4, 4}, {0, 4}};
    CHECK(spikes_out(fold) == fold);
    // Nothing but spikes: empty.
    CHECK(spikes_out({{0, 0}, {4, 0}, {0, 0}}).empty());
    CHECK(spikes_out({{0, 0}, {4, 0}, {5, 5}, {4, 0}}).empty());
    CHECK(spikes_out({}).empty());
}

TEST_CASE("map_without_spikes: the mapped ring without its spikes, as drop_spikes leaves it", "[map][simplify]") {
    std::mt19937 rng(11);
    for (int iter = 0; iter < 300; ++iter) {
        // Positions from a small grid, so that repeats, spikes and returns across the start are common.
        std::vector<Point> ring(rng() % 9);
        for (Point& p : ring) p = Point{double(rng() % 4), double(rng() % 4)};
        const Affine m = Affine::translate(0.5 * (rng() % 7), -3) * Affine::scale(1.5, -0.25 * (1 + rng() % 4));
        std::vector<Point> want(ring.size());
        for (std::size_t i = 0; i < ring.size(); ++i) want[i] = m.apply(ring[i]);
        map_detail::drop_spikes(want);
        std::vector<Point> got{{9, 9}};  // what the output held before is replaced
        map_detail::map_without_spikes(ring, m, got);
        REQUIRE(got == want);
    }
}

TEST_CASE("Maps: a polygon with spikes fills as without them, and its stroke keeps them", "[map][simplify]") {
    const char* with =
        R"({"type":"Polygon","coordinates":[[[0,0],[10,0],[15,3],[10,0],[10,10],[0,10],[-4,12],[0,10],[0,0]]]})";
    const char* without = R"({"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]]]})";
    MapOptions o;
    o.width = 200;
    o.height = 200;
    o.bbox = Rect{-5.3, -5.1, 16.1, 15.2};
    MapStyle fill_only;
    const Pixmap a = render_map(read_geojson(with), MapProjection{}, fill_only, o);
    const Pixmap b = render_map(read_geojson(without), MapProjection{}, fill_only, o);
    int differing = 0;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x) differing += !(a.pixel(x, y) == b.pixel(x, y));
    CHECK(differing == 0);
    MapStyle stroked;
    stroked.layers[0].fill.reset();
    stroked.layers[0].stroke = Color::black();
    const Pixmap c = render_map(read_geojson(with), MapProjection{}, stroked, o);
    const Pixmap d = render_map(read_geojson(without), MapProjection{}, stroked, o);
    differing = 0;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x) differing += !(c.pixel(x, y) == d.pixel(x, y));
    CHECK(differing > 20);  // the spikes' strokes
}
