// `casteljau map` end to end: inputs by extension and on standard input, options, and every
// kind of bad input with its exit code and no output file left behind.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "casteljau/png.hpp"
#include "cli_util.hpp"

using casteljau::test::run_cli;
using casteljau::test::shell_quote;
namespace fs = std::filesystem;

namespace {

const std::string kWorld = std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json";

fs::path write_text(const fs::path& dir, const std::string& name, const std::string& text) {
    const fs::path p = dir / name;
    std::ofstream f(p, std::ios::binary);
    f << text;
    return p;
}

const char* kSquare =
    R"({"type":"Feature","properties":{"v":3},"geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]]]}})";

}  // namespace

TEST_CASE("map CLI renders the world TopoJSON with a choropleth and strokes", "[map][cli]") {
    const fs::path dir = casteljau::test::scratch_dir("map_cli_world");
    const std::string out = (dir / "world.png").string();
    const auto r = run_cli("map " + shell_quote(kWorld) + " -o " + shell_quote(out) +
                           " --width 512 --layer countries --fill-by name --stroke white --stroke-width 0.5"
                           " --background '#dde8f0' --projection mercator");
    INFO(r.err);
    REQUIRE(r.status == 0);
    const casteljau::Pixmap pm = casteljau::read_png(out);
    CHECK(pm.width() == 512);
    CHECK(pm.height() > 300);
    // Ocean pixel = background.
    CHECK(pm.pixel(5, pm.height() / 2) == casteljau::premultiply(casteljau::parse_color("#dde8f0")));
}

TEST_CASE("map CLI --exact-strokes draws round strokes through their outlines", "[map][cli]") {
    // The world at 256 px with round strokes up to 64 px wide: sampled (default) and exact agree
    // within the sampled strokes' bound, and differ somewhere (each option is really taken). Wider
    // ones go through their outlines either way: the same pixels.
    const fs::path dir = casteljau::test::scratch_dir("map_cli_exact_strokes");
    for (const char* width : {"0.8", "3", "40", "70"}) {
        const std::string base = "map " + shell_quote(kWorld) + " --width 256 --layer countries --fill none" +
                                 " --stroke black --stroke-width " + width + " -o ";
        const std::string a = (dir / "sampled.png").string(), b = (dir / "exact.png").string();
        REQUIRE(run_cli(base + shell_quote(a)).status == 0);
        REQUIRE(run_cli(base + shell_quote(b) + " --exact-strokes").status == 0);
        const casteljau::Pixmap pa = casteljau::read_png(a), pb = casteljau::read_png(b);
        REQUIRE(pa.width() == pb.width());
        REQUIRE(pa.height() == pb.height());
        int worst = 0, differ = 0;
        for (int y = 0; y < pa.height(); ++y)
            for (int x = 0; x < pa.width(); ++x) {
                const int d = std::abs(pa.pixel(x, y).a - pb.pixel(x, y).a);
                worst = std::max(worst, d);
                differ += d != 0;
            }
        INFO("stroke width " << width);
        CHECK(worst <= 8);
        if (std::string(width) == "70")
            CHECK(differ == 0);
        else
            CHECK(differ > 0);
    }
}

TEST_CASE("map CLI reads GeoJSON lines, standard input and the bbox", "[map][cli]") {
    const fs::path dir = casteljau::test::scratch_dir("map_cli_inputs");
    const std::string lines = std::string(kSquare) + "\n" + kSquare + "\n";
    const fs::path in = write_text(dir, "two.geojsonl", lines);
    auto r = run_cli("map " + shell_quote(in.string()) + " -o " + shell_quote((dir / "a.png").string()) +
                     " --width 40 --bbox 0,0,20,10");
    INFO(r.err);
    REQUIRE(r.status == 0);
    casteljau::Pixmap pm = casteljau::read_png((dir / "a.png").string());
    CHECK(pm.height() == 20);
    CHECK(pm.pixel(0, 0).a == 255);
    CHECK(pm.pixel(19, 19).a == 255);
    CHECK(pm.pixel(20, 0).a == 0);
    r = run_cli("map - -o " + shell_quote((dir / "b.png").string()) +
                    " --width 30 --padding 5 --fill-by v --ramp 0:white,3:red",
                kSquare);
    INFO(r.err);
    REQUIRE(r.status == 0);
    pm = casteljau::read_png((dir / "b.png").string());
    CHECK(pm.height() == 30);
    CHECK(pm.pixel(15, 15) == casteljau::PremulPixel{255, 0, 0, 255});
    CHECK(pm.pixel(2, 2).a == 0);
    // A style file.
    const fs::path style =
        write_text(dir, "style.json", R"({"layers":[{"fill":"#00ff00","stroke":"black","width":2}]})");
    r = run_cli(
        "map - -o " + shell_quote((dir / "c.png").string()) + " --width 30 --style " + shell_quote(style.string()),
        kSquare);
    INFO(r.err);
    REQUIRE(r.status == 0);
    pm = casteljau::read_png((dir / "c.png").string());
    CHECK(pm.pixel(15, 15) == casteljau::PremulPixel{0, 255, 0, 255});
    CHECK(pm.pixel(0, 15) == casteljau::PremulPixel{0, 0, 0, 255});
}

TEST_CASE("map CLI bad input: one-line error, exit code, no output file", "[map][cli][errors]") {
    const fs::path dir = casteljau::test::scratch_dir("map_cli_errors");
    const std::string head = R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":{},"geometry":)";
    struct Case {
        const char* name;
        std::string input;
        std::string extra;
        int status;
        const char* message;
    };
    const Case cases[] = {
        {"invalid JSON", R"({"type":"FeatureCollection","features":[}]})", "", 1, "invalid JSON at byte 40"},
        {"wrong geometry type", head + R"({"type":"Circle","coordinates":[0,0]}}]})", "", 1, "unknown geometry type"},
        {"empty collection", R"({"type":"FeatureCollection","features":[]})", "", 1, "no geometry to draw"},
        {"NaN coordinate", head + R"({"type":"Point","coordinates":[NaN,0]}}]})", "", 1, "invalid JSON at byte"},
        {"out-of-range coordinate", head + R"({"type":"Point","coordinates":[0,95]}}]})", "", 1,
         "features[0].geometry.coordinates: position"},
        {"unclosed ring", head + R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1]]]}}]})", "", 1,
         "not closed"},
        {"ring with 3 positions", head + R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[0,0]]]}}]})", "", 1,
         "at least 4 positions"},
        {"arc index out of range",
         R"({"type":"Topology","objects":{"a":{"type":"Polygon","arcs":[[7]]}},"arcs":[[[0,0],[1,0],[1,1],[0,0]]]})",
         "", 1, "arc index 7 is out of range"},
        {"unknown projection", kSquare, "--projection +proj=nonsense", 2, "unknown projection"},
        {"bad bbox", kSquare, "--bbox 10,0,5,10", 2, "--bbox"},
        {"ramp without fill-by", kSquare, "--ramp 0:red,1:blue", 2, "--ramp needs --fill-by"},
        {"bad ramp", kSquare, "--fill-by v --ramp 0:red", 2, "--ramp"},
        {"unknown TopoJSON layer",
         R"({"type":"Topology","objects":{"a":{"type":"Point","coordinates":[0,0]}},"arcs":[]})", "--layer b", 2,
         "no object named 'b'"},
        {"bad colour", kSquare, "--fill nocolour", 2, "--fill"},
    };
    for (const Case& c : cases) {
        INFO(c.name);
        const fs::path out = dir / "out.png";
        const auto r = run_cli("map - -o " + shell_quote(out.string()) + " --width 64 " + c.extra, c.input);
        INFO(r.err);
        CHECK(r.status == c.status);
        CHECK(r.err.rfind("casteljau: error: ", 0) == 0);
        CHECK(r.err.find(c.message) != std::string::npos);
        CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
        CHECK(!fs::exists(out));
    }
    // With a bbox, an empty collection is an empty (background) map.
    const auto r = run_cli(
        "map - -o " + shell_quote((dir / "empty.png").string()) + " --width 16 --bbox -10,-10,10,10 --background white",
        R"({"type":"FeatureCollection","features":[]})");
    CHECK(r.status == 0);
    CHECK(casteljau::read_png((dir / "empty.png").string()).pixel(3, 3) == casteljau::PremulPixel{255, 255, 255, 255});
    // A missing input file.
    const auto m = run_cli("map /nonexistent/x.geojson -o " + shell_quote((dir / "m.png").string()) + " --width 16");
    CHECK(m.status == 1);
    CHECK(!fs::exists(dir / "m.png"));
}
