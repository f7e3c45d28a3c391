// The TopoJSON reader: delta-encoded quantized arcs, shared and reversed arcs, objects, layers,
// bad arc indices, and the Natural Earth 110m countries shipped in tests/data/maps.
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/error.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/file_io.hpp"

using namespace casteljau;

namespace {

// Two unit squares side by side sharing the arc x = 1 (arc 0), quantized with scale 0.5 and
// translate (10, 20): quantized x 0..4 -> 10..12, y 0..2 -> 20..21.
const char* kTwoSquares = R"({"type":"Topology",
  "transform":{"scale":[0.5,0.5],"translate":[10,20]},
  "objects":{
    "squares":{"type":"GeometryCollection","geometries":[
      {"type":"Polygon","arcs":[[0,1]],"id":"left","properties":{"name":"L","v":1}},
      {"type":"Polygon","arcs":[[2,-1]],"id":"right","properties":{"name":"R","v":2}}]},
    "border":{"type":"LineString","arcs":[0]},
    "dots":{"type":"MultiPoint","coordinates":[[0,0],[4,2]]}
  },
  "arcs":[
    [[2,0],[0,2]],
    [[2,2],[-2,0],[0,-2],[2,0]],
    [[2,0],[2,0],[0,2],[-2,0]]
  ]})";

}  // namespace

TEST_CASE("TopoJSON decodes quantized delta arcs and shares them", "[topojson]") {
    const MapData d = read_topojson(kTwoSquares);
    REQUIRE(d.features.size() == 4);
    CHECK(d.arc_ends == std::vector<std::uint32_t>{2, 6, 10});
    CHECK(d.arc_points[0] == Point{11, 20});
    CHECK(d.arc_points[1] == Point{11, 21});
    CHECK(d.used_arcs == std::vector<std::uint32_t>{0, 1, 2});
    const Feature& left = d.features[0];
    CHECK(left.id == "left");
    CHECK(left.property("name")->text == "L");
    const Geometry& lg = left.geometries.at(0);
    CHECK(lg.kind == GeometryKind::Polygons);
    // Arc 0 then arc 1 without repeating their common point: 2 + 3 positions, closed.
    const std::vector<Point> want_left = {{11, 20}, {11, 21}, {10, 21}, {10, 20}, {11, 20}};
    CHECK(lg.points == want_left);
    CHECK(lg.ring_ends == std::vector<std::uint32_t>{5});
    CHECK(lg.polygon_ends == std::vector<std::uint32_t>{1});
    // Arc 1 starts where arc 0 ends (index 1, kept once).
    CHECK(lg.arc_starts == std::vector<std::uint32_t>{0, 1});
    // Arc 2 then arc 0 reversed (~0 = -1).
    const std::vector<Point> want_right = {{11, 20}, {12, 20}, {12, 21}, {11, 21}, {11, 20}};
    CHECK(d.features[1].geometries.at(0).points == want_right);
    CHECK(d.features[1].geometries.at(0).arc_starts == std::vector<std::uint32_t>{0, 3});
    CHECK(d.features[2].geometries.at(0).kind == GeometryKind::Lines);
    CHECK(d.features[2].geometries.at(0).arc_starts == std::vector<std::uint32_t>{0});
    CHECK(d.features[3].geometries.at(0).arc_starts.empty());
    CHECK(d.features[2].geometries.at(0).points.size() == 2);
    // Points are quantized but not delta-encoded.
    const std::vector<Point> want_dots = {{10, 20}, {12, 21}};
    CHECK(d.features[3].geometries.at(0).points == want_dots);
}

TEST_CASE("TopoJSON selects one object by name", "[topojson]") {
    CHECK(read_topojson(kTwoSquares, "squares").features.size() == 2);
    CHECK(read_topojson(kTwoSquares, "dots").features.size() == 1);
    CHECK(read_map_data(kTwoSquares, "border").features.size() == 1);
    try {
        (void)read_topojson(kTwoSquares, "nope");
        FAIL("expected an error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::InvalidArgument);
        CHECK(std::string(e.what()).find("it has: squares, border, dots") != std::string::npos);
    }
}

TEST_CASE("TopoJSON without a transform reads absolute positions", "[topojson]") {
    const MapData d = read_topojson(R"({"type":"Topology","objects":{"a":{"type":"Polygon","arcs":[[0]]}},
        "arcs":[[[0,0],[1,0],[1,1],[0,0]]]})");
    REQUIRE(d.features.size() == 1);
    CHECK(d.features[0].geometries.at(0).points.at(2) == Point{1, 1});
}

TEST_CASE("TopoJSON bad input: arc index out of range, unclosed ring, not a topology", "[topojson][errors]") {
    auto error_of = [](const std::string& t, ErrorKind& k) {
        try {
            (void)read_topojson(t);
        } catch (const Error& e) {
            k = e.kind();
            return std::string(e.what());
        }
        return std::string();
    };
    ErrorKind k{};
    std::string m = error_of(R"({"type":"Topology","objects":{"a":{"type":"GeometryCollection","geometries":[
        {"type":"Polygon","arcs":[[0,5]]}]}},"arcs":[[[0,0],[1,0],[1,1],[0,0]]]})",
                             k);
    CHECK(k == ErrorKind::InvalidData);
    CHECK(m.find("objects.a.geometries[0].arcs[0][1]: arc index 5 is out of range (the topology has 1 arcs)") !=
          std::string::npos);
    m = error_of(R"({"type":"Topology","objects":{"a":{"type":"LineString","arcs":[-3]}},"arcs":[[[0,0],[1,0]]]})", k);
    CHECK(k == ErrorKind::InvalidData);
    CHECK(m.find("arc index -3") != std::string::npos);
    m = error_of(
        R"({"type":"Topology","objects":{"a":{"type":"Polygon","arcs":[[0]]}},"arcs":[[[0,0],[1,0],[1,1],[0,1]]]})", k);
    CHECK(k == ErrorKind::InvalidData);
    CHECK(m.find("not closed") != std::string::npos);
    m = error_of(R"({"type":"Topology","objects":{"a":{"type":"Polygon","arcs":[[0]]}},"arcs":[[[0,0],[500,0]]]})", k);
    CHECK(k == ErrorKind::InvalidData);
    CHECK(m.find("arcs[0][1]") != std::string::npos);
    // A ring collapsed by quantization is dropped, not an error.
    const MapData collapsed =
        read_topojson(R"({"type":"Topology","objects":{"a":{"type":"MultiPolygon","arcs":[[[1]],[[0]]]}},
        "arcs":[[[0,0],[1,0],[1,1],[0,0]],[[5,5],[5,5]]]})");
    REQUIRE(collapsed.features.size() == 1);
    CHECK(collapsed.features[0].geometries.at(0).polygon_ends == std::vector<std::uint32_t>{1});
    CHECK(collapsed.features[0].geometries.at(0).points.size() == 4);
    CHECK(collapsed.features[0].geometries.at(0).arc_starts == std::vector<std::uint32_t>{0});
    m = error_of(R"({"type":"FeatureCollection","features":[]})", k);
    CHECK(k == ErrorKind::Parse);
    m = error_of(R"({"type":"Topology","objects":{"a":{"type":"Squiggle","arcs":[]}},"arcs":[]})", k);
    CHECK(k == ErrorKind::Parse);
    CHECK(m.find("unknown geometry type") != std::string::npos);
    m = error_of(R"({"type":"Topology","transform":{"scale":[0,1],"translate":[0,0]},"objects":{},"arcs":[]})", k);
    CHECK(k == ErrorKind::InvalidData);
    m = error_of(R"({"type":"Topology","objects":{"a":{"type":"Polygon","arcs":[[0.5]]}},"arcs":[]})", k);
    CHECK(k == ErrorKind::Parse);
    m = error_of(R"({"type":"Topology","objects":{"a":)", k);
    CHECK(k == ErrorKind::Parse);
    CHECK(m.find("TopoJSON: invalid JSON") != std::string::npos);
}

TEST_CASE("TopoJSON Natural Earth 110m countries", "[topojson]") {
    const auto bytes = read_file(std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json");
    const std::string text(bytes.begin(), bytes.end());
    const MapData all = read_map_data(text);
    const MapData countries = read_map_data(text, "countries");
    CHECK(countries.features.size() == 177);
    CHECK(all.features.size() == 178);  // + the single "land" feature
    CHECK(countries.arc_ends.size() == 595);
    // Shared borders: every arc is used, and ring positions outnumber the decoded arc positions.
    CHECK(countries.used_arcs.size() == 595);
    CHECK(countries.position_count() > countries.arc_points.size());
    const Feature* fiji = nullptr;
    for (const Feature& f : countries.features)
        if (f.property("name") && f.property("name")->text == "Fiji") fiji = &f;
    REQUIRE(fiji);
    CHECK(fiji->id == "242");
    const Rect b = countries.bounds();
    CHECK(b.x0 == Approx(-180));
    CHECK(b.x1 == Approx(180));
    CHECK(b.y0 == Approx(-85.609).margin(0.001));  // world-atlas stops Antarctica there
}
