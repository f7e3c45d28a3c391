// Geometry at the output's resolution: the run simplifier's bound on random polylines, its
// degenerate inputs, and the border nodes that shared borders are cut at.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "casteljau/geojson.hpp"
#include "map/border_nodes.hpp"
#include "map/simplify_polyline.hpp"

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
           R"({"type":"Polygon","coordinates":)" + text(west) + R"(}},{"type":"Feature","properties":{"name":"east"},)"
           R"("geometry":{"type":"Polygon","coordinates":)" + text(east) + "}}]}";
}

}  // namespace

TEST_CASE("Run simplifier: every dropped vertex within the tolerance, ends kept, both ways within it", "[map][simplify]") {
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
    const MapData d = read_geojson(two_neighbours(200, 0.01));
    const map_detail::BorderNodes nodes = map_detail::find_border_nodes(d);
    REQUIRE(nodes.feature_start.size() == 3);
    // The border's two ends are nodes in both rings; no other position of the border is.
    for (std::size_t f = 0; f < 2; ++f) {
        const Geometry& g = d.features[f].geometries[0];
        for (std::size_t i = 0; i + 1 < g.points.size(); ++i) {  // the closing repeat is skipped
            const Point p = g.points[i];
            const bool end = p.x == 0 && std::fabs(p.y) == 40;
            const bool on = p.x != 40 && p.x != -40 && !end;
            if (end) CHECK(nodes.node[nodes.feature_start[f] + i] == 1);
            else if (on) CHECK(nodes.node[nodes.feature_start[f] + i] == 0);
        }
    }
    const MapData l = read_geojson(R"({"type":"LineString","coordinates":[[170,0],[175,1],[179,2],[-179,3],[-175,4],[-170,5]]})");
    const map_detail::BorderNodes ln = map_detail::find_border_nodes(l);
    CHECK(ln.node == std::vector<std::uint8_t>{1, 0, 1, 1, 0, 1});
}

