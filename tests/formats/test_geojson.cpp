// The GeoJSON readers (RFC 7946 and newline-delimited): geometry types, properties, collections,
// and every kind of bad input naming its JSON path or byte offset.
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/error.hpp"
#include "casteljau/geojson.hpp"
#include "casteljau/file_io.hpp"
#include "temp_dir.hpp"

#include <fstream>

using namespace casteljau;

namespace {

std::string error_of(const std::string& text, ErrorKind* kind = nullptr) {
    try {
        (void)read_geojson(text);
    } catch (const Error& e) {
        if (kind) *kind = e.kind();
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("GeoJSON reads every geometry type with properties", "[geojson]") {
    const std::string text = R"({"type":"FeatureCollection","features":[
      {"type":"Feature","id":7,"properties":{"name":"A","pop":12.5,"ok":true,"tags":[1,2],"none":null},
       "geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]],[[2,2],[2,4],[4,4],[2,2]]]}},
      {"type":"Feature","properties":null,"geometry":{"type":"MultiPolygon","coordinates":[
         [[[0,0],[1,0],[1,1],[0,0]]],[[[5,5],[6,5],[6,6],[5,5]]]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[0,0],[1,1],[2,0,99]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"MultiLineString","coordinates":[[[0,0],[1,1]],[[3,3],[4,4]]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"Point","coordinates":[-179.5,89]}},
      {"type":"Feature","properties":{},"geometry":{"type":"MultiPoint","coordinates":[[1,2],[3,4]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"GeometryCollection","geometries":[
         {"type":"Point","coordinates":[0,0]},
         {"type":"GeometryCollection","geometries":[{"type":"LineString","coordinates":[[0,0],[1,0]]}]}]}},
      {"type":"Feature","properties":{"x":1},"geometry":null}
    ]})";
    const MapData d = read_geojson(text);
    REQUIRE(d.features.size() == 8);
    const Feature& a = d.features[0];
    CHECK(a.id == "7");
    REQUIRE(a.property("name"));
    CHECK(a.property("name")->type == PropertyValue::Type::String);
    CHECK(a.property("name")->text == "A");
    CHECK(a.property("pop")->number == 12.5);
    CHECK(a.property("ok")->to_string() == "true");
    CHECK(a.property("tags")->to_string() == "[1,2]");
    CHECK(a.property("none")->type == PropertyValue::Type::Null);
    CHECK(a.property("missing") == nullptr);
    REQUIRE(a.geometries.size() == 1);
    const Geometry& poly = a.geometries[0];
    CHECK(poly.kind == GeometryKind::Polygons);
    CHECK(poly.points.size() == 9);
    CHECK(poly.ring_ends == std::vector<std::uint32_t>{5, 9});
    CHECK(poly.polygon_ends == std::vector<std::uint32_t>{2});
    CHECK(d.features[1].geometries[0].polygon_ends == std::vector<std::uint32_t>{1, 2});
    CHECK(d.features[1].properties.empty());
    const Geometry& line = d.features[2].geometries[0];
    CHECK(line.kind == GeometryKind::Lines);
    CHECK(line.points.back() == Point{2, 0});  // altitude ignored
    CHECK(d.features[3].geometries[0].ring_ends == std::vector<std::uint32_t>{2, 4});
    CHECK(d.features[4].geometries[0].points[0] == Point{-179.5, 89});
    CHECK(d.features[5].geometries[0].points.size() == 2);
    CHECK(d.features[5].geometries[0].ring_ends.empty());
    REQUIRE(d.features[6].geometries.size() == 2);  // nested collection flattened
    CHECK(d.features[6].geometries[1].kind == GeometryKind::Lines);
    CHECK(d.features[7].geometries.empty());
    CHECK(d.position_count() == 9 + 8 + 3 + 4 + 1 + 2 + 1 + 2);
}

TEST_CASE("GeoJSON accepts a bare Feature, a bare geometry and empty collections", "[geojson]") {
    CHECK(read_geojson(R"({"type":"Feature","geometry":{"type":"Point","coordinates":[1,2]},"properties":null})")
              .features.size() == 1);
    CHECK(read_geojson(R"({"type":"LineString","coordinates":[[1,2],[3,4]]})").features.at(0).geometries.size() == 1);
    CHECK(read_geojson(R"({"type":"FeatureCollection","features":[]})").features.empty());
    const MapData e =
        read_geojson(R"({"type":"Feature","properties":{},"geometry":{"type":"MultiPolygon","coordinates":[]}})");
    CHECK(e.features.at(0).geometries.empty());
    CHECK(read_geojson(R"({"type":"GeometryCollection","geometries":[]})").features.at(0).geometries.empty());
}

TEST_CASE("GeoJSON invalid JSON names the byte offset", "[geojson][errors]") {
    ErrorKind k{};
    const std::string msg = error_of(R"({"type":"FeatureCollection","features":[}]})", &k);
    CHECK(k == ErrorKind::Parse);
    CHECK(msg.find("invalid JSON at byte 40") != std::string::npos);
    CHECK(error_of(R"({"type":"Feature", "geometry": nul})").find("at byte 34") != std::string::npos);
    CHECK(error_of(R"({"type":"Feature")").find("ends early") != std::string::npos);
    CHECK(error_of("").find("invalid JSON") != std::string::npos);
    CHECK(error_of(R"({"a":1} x)").find("at byte 8") != std::string::npos);
}

TEST_CASE("GeoJSON bad content names the JSON path", "[geojson][errors]") {
    ErrorKind k{};
    const std::string head = R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":)";
    // Wrong geometry type.
    std::string m = error_of(head + R"({"type":"Polygonn","coordinates":[]}}]})", &k);
    CHECK(k == ErrorKind::Parse);
    CHECK(m.find("features[0].geometry.type") != std::string::npos);
    CHECK(m.find("unknown geometry type \"Polygonn\"") != std::string::npos);
    // Coordinates nested at the wrong depth.
    m = error_of(head + R"({"type":"Polygon","coordinates":[[0,0],[1,1]]}}]})", &k);
    CHECK(k == ErrorKind::Parse);
    CHECK(m.find("features[0].geometry.coordinates[0][0]") != std::string::npos);
    // Ring with fewer than 4 positions.
    m = error_of(head + R"({"type":"Polygon","coordinates":[[[0,0],[1,1],[0,0]]]}}]})", &k);
    CHECK(k == ErrorKind::InvalidData);
    CHECK(m.find("features[0].geometry.coordinates[0]: a polygon ring needs at least 4 positions, got 3") !=
          std::string::npos);
    // Unclosed ring.
    m = error_of(head + R"({"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,1]]]]}}]})", &k);
    CHECK(k == ErrorKind::InvalidData);
    CHECK(m.find("features[0].geometry.coordinates[0][0]: polygon ring is not closed") != std::string::npos);
    // Out-of-range coordinates.
    m = error_of(head + R"({"type":"LineString","coordinates":[[0,0],[1,91]]}}]})", &k);
    CHECK(k == ErrorKind::InvalidData);
    CHECK(m.find("features[0].geometry.coordinates[1]") != std::string::npos);
    CHECK(m.find("outside") != std::string::npos);
    m = error_of(R"({"type":"Point","coordinates":[400,0]})", &k);
    CHECK(k == ErrorKind::InvalidData);
    // NaN is not JSON; a number too large for a double is refused by the parser.
    m = error_of(R"({"type":"Point","coordinates":[NaN,0]})", &k);
    CHECK(k == ErrorKind::Parse);
    CHECK(m.find("at byte 31") != std::string::npos);
    m = error_of(R"({"type":"Point","coordinates":[1e999,0]})", &k);
    CHECK(k == ErrorKind::Parse);
    // A position with one number, a string coordinate.
    m = error_of(R"({"type":"Point","coordinates":[1]})", &k);
    CHECK(k == ErrorKind::InvalidData);
    m = error_of(R"({"type":"Point","coordinates":["1",2]})", &k);
    CHECK(k == ErrorKind::Parse);
    CHECK(m.find("coordinates[0]: expected a number") != std::string::npos);
    // Not a feature inside features, a missing type, features not an array.
    m = error_of(R"({"type":"FeatureCollection","features":[{"type":"Point","coordinates":[0,0]}]})", &k);
    CHECK(m.find("features[0]") != std::string::npos);
    CHECK(error_of(R"({"coordinates":[0,0]})").find("type") != std::string::npos);
    CHECK(error_of(R"({"type":"FeatureCollection","features":{}})").find("features") != std::string::npos);
    CHECK(error_of("[1,2]").find("expected a GeoJSON object") != std::string::npos);
    CHECK(error_of(R"({"type":"Feature","properties":5,"geometry":null})").find("properties") != std::string::npos);
}

TEST_CASE("GeoJSON nesting beyond the limit is refused", "[geojson][errors]") {
    std::string s;
    for (int i = 0; i < 100; ++i) s += R"({"type":"GeometryCollection","geometries":[)";
    for (int i = 0; i < 100; ++i) s += "]}";
    ErrorKind k{};
    const std::string m = error_of(s, &k);
    CHECK(k == ErrorKind::Limit);
    CHECK(m.find("nested too deeply") != std::string::npos);
}

TEST_CASE("GeoJSON lines: one feature per line, errors name the line", "[geojson]") {
    const std::string text =
        "{\"type\":\"Feature\",\"properties\":{\"n\":1},\"geometry\":{\"type\":\"Point\",\"coordinates\":[1,2]}}\n"
        "\n"
        "\x1e{\"type\":\"Feature\",\"properties\":{\"n\":2},\"geometry\":{\"type\":\"Point\",\"coordinates\":[3,4]}}"
        "\r\n";
    const MapData d = read_geojson_lines(text);
    REQUIRE(d.features.size() == 2);
    CHECK(d.features[1].property("n")->number == 2);
    // read_map_data recognises the form.
    CHECK(read_map_data(text).features.size() == 2);
    try {
        (void)read_geojson_lines(
            text +
            "{\"type\":\"Feature\",\"properties\":{},\"geometry\":{\"type\":\"Point\",\"coordinates\":[1,99]}}\n");
        FAIL("expected an error");
    } catch (const Error& e) { CHECK(std::string(e.what()).find("line 4 geometry.coordinates") != std::string::npos); }
    try {
        (void)read_geojson_lines(text + "{oops}\n");
        FAIL("expected an error");
    } catch (const Error& e) {
        const std::string m = e.what();
        CHECK(m.find("GeoJSON line 4: invalid JSON at byte 1") != std::string::npos);
        CHECK(m.find("line starts at byte") != std::string::npos);
    }
}

TEST_CASE("read_map_data refuses a TopoJSON layer name for GeoJSON", "[geojson][errors]") {
    try {
        (void)read_map_data(R"({"type":"Point","coordinates":[1,2]})", "countries");
        FAIL("expected an error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::InvalidArgument); }
}

namespace {

// The features of a and b are the same: ids, properties, geometries, positions.
void check_same_features(const MapData& a, const MapData& b) {
    REQUIRE(a.features.size() == b.features.size());
    for (std::size_t i = 0; i < a.features.size(); ++i) {
        const Feature &fa = a.features[i], &fb = b.features[i];
        INFO("feature " << i);
        CHECK(fa.id == fb.id);
        REQUIRE(fa.properties.size() == fb.properties.size());
        for (std::size_t k = 0; k < fa.properties.size(); ++k) {
            CHECK(fa.properties[k].first == fb.properties[k].first);
            CHECK(fa.properties[k].second.to_string() == fb.properties[k].second.to_string());
        }
        REQUIRE(fa.geometries.size() == fb.geometries.size());
        for (std::size_t g = 0; g < fa.geometries.size(); ++g) {
            CHECK(fa.geometries[g].kind == fb.geometries[g].kind);
            CHECK(fa.geometries[g].points == fb.geometries[g].points);
            CHECK(fa.geometries[g].ring_ends == fb.geometries[g].ring_ends);
            CHECK(fa.geometries[g].polygon_ends == fb.geometries[g].polygon_ends);
        }
    }
}

}  // namespace

TEST_CASE("read_map_data reads a FeatureCollection alike on either path", "[geojson]") {
    // read_geojson cuts a collection into features and reads them in parallel; read_map_data reads
    // a small document through one DOM, and so does it a large one that holds the word Topology
    // (it may be a TopoJSON), while a large collection without it goes feature by feature.
    const std::string collection = R"({"type":"FeatureCollection","features":[
        {"type":"Feature","id":7,"properties":{"name":"NAME","n":[1,{"a":null}]},"geometry":{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,3],[0,0]]]}},
        {"type":"Feature","properties":{},"geometry":{"type":"GeometryCollection","geometries":[
          {"type":"LineString","coordinates":[[1,1],[2,2.5]]},{"type":"MultiPoint","coordinates":[[3,1],[0.5,2]]}]}}]})";
    check_same_features(read_geojson(collection), read_map_data(collection));
    const auto sample = read_file(std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/sample.geojson");
    const std::string sample_text(sample.begin(), sample.end());
    check_same_features(read_geojson(sample_text), read_map_data(sample_text));
    // Past 8 MB: the same features repeated, with and without the word.
    std::string large = R"({"type":"FeatureCollection","features":[)";
    const std::string feature =
        R"({"type":"Feature","properties":{"name":"NAME","v":1.5},"geometry":{"type":"Polygon","coordinates":[[[0,0],[4,0],[4,3],[0.25,2.75],[0,0]]]}})";
    for (int i = 0; large.size() < (std::size_t(9) << 20); ++i) large += (i ? "," : "") + feature;
    large += "]}";
    std::string named = large;
    named.replace(named.find("\"NAME\""), 6, "\"Topology\"");
    const MapData a = read_map_data(large), b = read_map_data(named);
    CHECK(a.features.size() > 40000);
    MapData renamed = b;
    renamed.features[0].properties[0].second.text = "NAME";
    check_same_features(a, renamed);
    // A layer name refuses a collection too, on either path.
    CHECK_THROWS_AS(read_map_data(collection, "countries"), Error);
    CHECK_THROWS_AS(read_map_data(large, "countries"), Error);
}

TEST_CASE("read_map_file reads in place like read_map_data and reports errors", "[geojson]") {
    const std::string world = std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json";
    const auto bytes = read_file(world);
    const MapData a = read_map_file(world, "countries");
    const MapData b = read_map_data(std::string(bytes.begin(), bytes.end()), "countries");
    REQUIRE(a.features.size() == b.features.size());
    CHECK(a.position_count() == b.position_count());
    CHECK(a.features[17].geometries.at(0).points == b.features[17].geometries.at(0).points);
    const std::string sample = std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/sample.geojson";
    CHECK(read_map_file(sample).features.size() == 7);
    try {
        (void)read_map_file("/nonexistent/file.geojson");
        FAIL("expected an error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Io); }
    const std::string bad = (casteljau::testing::process_temp_dir() / "bad.geojson").string();
    {
        std::ofstream f(bad, std::ios::binary);
        f << R"({"type":"FeatureCollection","features":[}]})";
    }
    try {
        (void)read_map_file(bad);
        FAIL("expected an error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Parse);
        CHECK(std::string(e.what()).find("invalid JSON at byte 40") != std::string::npos);
    }
}

TEST_CASE("GeoJSON FeatureCollection read feature by feature equals the same features read as lines", "[geojson]") {
    const std::string f1 =
        R"({"type":"Feature","properties":{"n":"a\"]}"},"geometry":{"type":"Point","coordinates":[1,2]}})";
    const std::string f2 =
        R"({"type":"Feature","properties":{"n":[[{}]]},"geometry":{"type":"LineString","coordinates":[[0,0],[3,4]]}})";
    const MapData lines = read_geojson_lines(f1 + "\n" + f2 + "\n");
    // Member order, escaped keys, whitespace and foreign members must not matter.
    for (const std::string& text : {
             R"({"type":"FeatureCollection","features":[)" + f1 + "," + f2 + "]}",
             " {\n \"features\" : [ " + f1 + " ,\n " + f2 +
                 " ] , \"bbox\":[0,0,3,4], \"type\" : \"FeatureCollection\" } ",
             R"({"typ\u0065":"FeatureCollection","feat\u0075res":[)" + f1 + "," + f2 + "]}",
         }) {
        INFO(text);
        const MapData d = read_geojson(text);
        REQUIRE(d.features.size() == 2);
        for (std::size_t i = 0; i < 2; ++i) {
            CHECK(d.features[i].geometries.at(0).points == lines.features[i].geometries.at(0).points);
            CHECK(d.features[i].property("n")->to_string() == lines.features[i].property("n")->to_string());
        }
        CHECK(read_map_data(text).features.size() == 2);
    }
    // An error in the second feature names its index in the whole collection.
    const std::string bad = R"({"type":"FeatureCollection","features":[)" + f1 +
                            R"(,{"type":"Feature","properties":{},"geometry":{"type":"Point","coordinates":[1,95]}}]})";
    try {
        (void)read_geojson(bad);
        FAIL("expected an error");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("features[1].geometry.coordinates") != std::string::npos);
    }
    // Invalid UTF-8 outside any feature is still refused.
    CHECK_THROWS_AS(read_geojson("{\"name\":\"\xff\",\"type\":\"FeatureCollection\",\"features\":[]}"), Error);
}
