// Tile pyramids: shards as parallel processes equal one unsharded run byte for byte, MBTiles equal
// the folder, strokes continue across tile edges, resume, empty tiles, limits and bad paths.
#include <catch2/catch.hpp>
#include <sqlite3.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <stdexcept>
#include <thread>

#include "casteljau/file_io.hpp"
#include "casteljau/png.hpp"
#include "casteljau/tiles.hpp"
#include "cli_util.hpp"

using namespace casteljau;
using casteljau::test::run_cli;
using casteljau::test::shell_quote;
namespace fs = std::filesystem;

namespace {

const std::string kWorld = std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json";
const std::string kStyle =
    " --layer countries --fill-by name --stroke '#333' --stroke-width 1.5 --background '#cde0ee'";

std::map<std::string, std::vector<std::uint8_t>> folder_files(const fs::path& dir) {
    std::map<std::string, std::vector<std::uint8_t>> out;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = read_file(e.path().string());
    return out;
}

std::map<std::string, std::vector<std::uint8_t>> mbtiles_files(const fs::path& file) {
    std::map<std::string, std::vector<std::uint8_t>> out;
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(file.string().c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* st = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, "SELECT zoom_level, tile_column, tile_row, tile_data FROM tiles", -1, &st,
                               nullptr) == SQLITE_OK);
    while (sqlite3_step(st) == SQLITE_ROW) {
        const int z = sqlite3_column_int(st, 0);
        const int x = sqlite3_column_int(st, 1);
        const int y = (1 << z) - 1 - sqlite3_column_int(st, 2);  // TMS row back to XYZ
        const auto* b = static_cast<const std::uint8_t*>(sqlite3_column_blob(st, 3));
        out[std::to_string(z) + "/" + std::to_string(x) + "/" + std::to_string(y) + ".png"] =
            std::vector<std::uint8_t>(b, b + sqlite3_column_bytes(st, 3));
    }
    sqlite3_finalize(st);
    sqlite3_close(db);
    return out;
}

std::map<std::string, std::string> mbtiles_metadata(const fs::path& file) {
    std::map<std::string, std::string> out;
    sqlite3* db = nullptr;
    REQUIRE(sqlite3_open_v2(file.string().c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK);
    sqlite3_stmt* st = nullptr;
    REQUIRE(sqlite3_prepare_v2(db, "SELECT name, value FROM metadata", -1, &st, nullptr) == SQLITE_OK);
    while (sqlite3_step(st) == SQLITE_ROW)
        out[reinterpret_cast<const char*>(sqlite3_column_text(st, 0))] =
            reinterpret_cast<const char*>(sqlite3_column_text(st, 1));
    sqlite3_finalize(st);
    sqlite3_close(db);
    return out;
}

}  // namespace

TEST_CASE("tiles: three shards in parallel processes equal one unsharded run byte for byte", "[tiles][cli]") {
    const fs::path dir = casteljau::test::scratch_dir("tiles_shards");
    const std::string args = "tiles " + shell_quote(kWorld) + " --zoom 0-3 --metatile 2 -q" + kStyle;
    auto r = run_cli(args + " --threads 1 -o " + shell_quote((dir / "one").string()));
    INFO(r.err);
    REQUIRE(r.status == 0);
    std::string cmd;
    for (int i = 0; i < 3; ++i)
        cmd += std::string(CASTELJAU_CLI_PATH) + " " + args + " --threads 1 --shard " + std::to_string(i) + "/3 -o " +
               shell_quote((dir / "sharded").string()) + " & ";
    cmd += "wait";
    REQUIRE(std::system(cmd.c_str()) == 0);
    const auto one = folder_files(dir / "one");
    const auto sharded = folder_files(dir / "sharded");
    CHECK(one.size() == 1 + 4 + 16 + 64);
    CHECK(sharded.size() == one.size());
    CHECK(sharded == one);
    // Two threads give the same bytes too; so does the shard index taken from a Slurm array.
    r = run_cli(args + " --threads 2 -o " + shell_quote((dir / "threads").string()));
    REQUIRE(r.status == 0);
    CHECK(folder_files(dir / "threads") == one);
    std::string env_cmd;
    for (int i = 0; i < 2; ++i)
        env_cmd += "SLURM_ARRAY_TASK_ID=" + std::to_string(i) + " SLURM_ARRAY_TASK_COUNT=2 " + CASTELJAU_CLI_PATH +
                   " " + args + " -o " + shell_quote((dir / "slurm").string()) + " && ";
    env_cmd += "true";
    REQUIRE(std::system(env_cmd.c_str()) == 0);
    CHECK(folder_files(dir / "slurm") == one);
}

TEST_CASE("tiles: MBTiles holds the folder's tiles, TMS rows and metadata, and tiles-merge joins shards",
          "[tiles][cli]") {
    const fs::path dir = casteljau::test::scratch_dir("tiles_mbtiles");
    const std::string args = "tiles " + shell_quote(kWorld) + " --zoom 0-2 --metatile 2 -q" + kStyle;
    REQUIRE(run_cli(args + " -o " + shell_quote((dir / "folder").string())).status == 0);
    const auto r = run_cli(args + " --name world -o " + shell_quote((dir / "all.mbtiles").string()));
    INFO(r.err);
    REQUIRE(r.status == 0);
    const auto folder = folder_files(dir / "folder");
    CHECK(folder.size() == 21);
    CHECK(mbtiles_files(dir / "all.mbtiles") == folder);
    const auto meta = mbtiles_metadata(dir / "all.mbtiles");
    CHECK(meta.at("name") == "world");
    CHECK(meta.at("format") == "png");
    CHECK(meta.at("minzoom") == "0");
    CHECK(meta.at("maxzoom") == "2");
    CHECK(meta.at("bounds") == "-180,-85.05112878,180,85.05112878");
    CHECK(meta.count("center") == 1);
    for (int i = 0; i < 2; ++i)
        REQUIRE(run_cli(args + " --shard " + std::to_string(i) + "/2 -o " +
                        shell_quote((dir / ("s" + std::to_string(i) + ".mbtiles")).string()))
                    .status == 0);
    CHECK(mbtiles_files(dir / "s0.mbtiles").size() < folder.size());
    REQUIRE(run_cli("tiles-merge " + shell_quote((dir / "s0.mbtiles").string()) + " " +
                    shell_quote((dir / "s1.mbtiles").string()) + " -o " +
                    shell_quote((dir / "merged.mbtiles").string()))
                .status == 0);
    CHECK(mbtiles_files(dir / "merged.mbtiles") == folder);
    // No temporary files left next to the outputs.
    for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().string().find(".tmp-") == std::string::npos);
}

TEST_CASE("tiles: a stroke crossing tile edges matches a single render of the area", "[tiles]") {
    // A diagonal line and a polygon outline crossing the tile edges at zoom 2 (tile x = 2, y = 1..2
    // meet at latitude 0, tiles 1 and 2 at longitude 0).
    const MapData d = read_geojson(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"LineString","coordinates":[[-40,30],[45,-25],[70,10]]}},
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[-20,-20],[20,-20],[20,20],[-20,20],[-20,-20]]]}}]})");
    MapStyle st;
    st.layers[0].fill = Color::rgba(200, 120, 40);
    st.layers[0].stroke = Color::rgba(20, 20, 120, 200);
    st.layers[0].stroke_width = 5;
    TileOptions to;
    to.min_zoom = to.max_zoom = 2;
    to.metatile = 1;  // every tile rendered on its own (with its buffer)
    to.buffer = 16;
    std::map<std::pair<int, int>, Pixmap> tiles;
    render_tiles(d, st, to, [&](int, int x, int y, const std::vector<std::uint8_t>& png) {
        tiles[{x, y}] = decode_png(png);
    });
    REQUIRE(tiles.size() == 16);
    // One render of the whole zoom-2 world (1024 x 1024).
    const double half = std::numbers::pi * kWebMercatorRadius, s = 1024 / (2 * half);
    MapFrame fr;
    fr.width = fr.height = 1024;
    fr.to_pixel = Affine{s, 0, 0, -s, half * s, half * s};
    Pixmap whole(1024, 1024);
    render_map(d, MapProjection::parse("mercator"), fr, st, MapOptions{}, whole);
    int max_diff = 0, stroke_pixels = 0;
    for (const auto& [xy, tile] : tiles)
        for (int y = 0; y < 256; ++y)
            for (int x = 0; x < 256; ++x) {
                const PremulPixel a = tile.pixel(x, y), b = whole.pixel(xy.first * 256 + x, xy.second * 256 + y);
                max_diff = std::max(
                    {max_diff, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
                if (b.b > 100) ++stroke_pixels;
            }
    CHECK(stroke_pixels > 500);
    CHECK(max_diff <= 1);
    // The pixels on both sides of the vertical edge x = 512 where the line crosses it.
    int crossings = 0;
    for (int y = 0; y < 1024; ++y) {
        const PremulPixel l = tiles.at({1, y / 256}).pixel(255, y % 256), r = tiles.at({2, y / 256}).pixel(0, y % 256);
        if (l.b > 100 && r.b > 100) ++crossings;
    }
    CHECK(crossings >= 4);
}

TEST_CASE("tiles: resume, skip-empty, and bad input", "[tiles][cli][errors]") {
    const fs::path dir = casteljau::test::scratch_dir("tiles_misc");
    const std::string args = "tiles " + shell_quote(kWorld) + " --layer countries --zoom 0-3";
    auto r = run_cli(args + " --skip-empty -o " + shell_quote((dir / "sparse").string()));
    INFO(r.err);
    REQUIRE(r.status == 0);
    CHECK(r.err.find("empty skipped") != std::string::npos);
    const auto sparse = folder_files(dir / "sparse");
    CHECK(sparse.size() < 85);
    CHECK(sparse.size() > 20);
    r = run_cli(args + " --skip-empty --resume -o " + shell_quote((dir / "sparse").string()));
    REQUIRE(r.status == 0);
    CHECK(r.err.find(" 0 tiles written") != std::string::npos);
    CHECK(folder_files(dir / "sparse") == sparse);
    // A removed tile comes back on resume.
    fs::remove(dir / "sparse" / sparse.begin()->first);
    r = run_cli(args + " --skip-empty --resume -o " + shell_quote((dir / "sparse").string()));
    CHECK(r.err.find(" 1 tiles written") != std::string::npos);
    CHECK(folder_files(dir / "sparse") == sparse);

    r = run_cli(args.substr(0, args.find("--zoom")) + "--zoom 0-25 -o " + shell_quote((dir / "z").string()));
    CHECK(r.status == 2);
    CHECK(r.err.find("--zoom: at most 24") != std::string::npos);
    CHECK(!fs::exists(dir / "z"));
    r = run_cli(args + " -o /nonexistent-folder/world.mbtiles");
    CHECK(r.status == 1);
    CHECK(r.err.find("MBTiles '/nonexistent-folder/world.mbtiles'") != std::string::npos);
    r = run_cli(args + " --shard 3/3 -o " + shell_quote((dir / "bad").string()));
    CHECK(r.status == 2);
    r = run_cli(args + " --resume -o " + shell_quote((dir / "x.mbtiles").string()));
    CHECK(r.status == 2);
    // Bad data fails before any output appears.
    r = run_cli("tiles - --zoom 0-1 -o " + shell_quote((dir / "broken.mbtiles").string()), "{\"type\":\"Feature\"");
    CHECK(r.status == 1);
    CHECK(!fs::exists(dir / "broken.mbtiles"));
    for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().string().find(".tmp-") == std::string::npos);
    CHECK(list_metatiles(0, 3, 8).size() == 1 + 1 + 1 + 1);
    CHECK(shard_range(10, 2, 3) == std::pair<std::size_t, std::size_t>{6, 10});
}

TEST_CASE("tiles: write_tiles picks the store by the output's name and resumes folders only", "[tiles]") {
    const fs::path dir = casteljau::test::scratch_dir("tiles_write");
    const MapData data = read_map_file(kWorld);
    TileOptions to;
    to.max_zoom = 1;
    to.metatile = 2;
    const TileStats folder = write_tiles(data, MapStyle{}, to, (dir / "folder").string(), "w");
    CHECK(folder.written == 5);
    const auto files = folder_files(dir / "folder");
    CHECK(files.size() == 5);
    CHECK(files.count("1/1/0.png") == 1);
    const TileStats db = write_tiles(data, MapStyle{}, to, (dir / "w.mbtiles").string(), "w");
    CHECK(db.written == 5);
    CHECK(mbtiles_files(dir / "w.mbtiles") == files);
    CHECK(mbtiles_metadata(dir / "w.mbtiles").at("name") == "w");

    // Resume: a tile removed from the folder is drawn again, the others are kept.
    fs::remove(dir / "folder" / "1" / "1" / "0.png");
    to.resume = true;
    const TileStats again = write_tiles(data, MapStyle{}, to, (dir / "folder").string(), "w");
    CHECK(again.written == 1);
    CHECK(again.skipped_existing == 4);
    CHECK(folder_files(dir / "folder") == files);
    CHECK_THROWS_AS(write_tiles(data, MapStyle{}, to, (dir / "r.mbtiles").string(), "w"), Error);
    CHECK(!fs::exists(dir / "r.mbtiles"));
}

TEST_CASE("tiles: after the sink or progress throws, no other metatile reaches either", "[tiles][errors]") {
    // A small pyramid of small metatiles on several threads: when a callback throws, the other
    // workers are waiting to hand their metatiles on. The callback that throws first waits a
    // moment, so that one is waiting for certain.
    const MapData d = read_geojson(R"({"type":"FeatureCollection","features":[
      {"type":"Feature","properties":{},"geometry":{"type":"Polygon","coordinates":[[[-20,-20],[20,-20],[20,20],[-20,20],[-20,-20]]]}}]})");
    MapStyle st;
    st.layers[0].fill = Color::rgba(200, 120, 40);
    TileOptions to;
    to.min_zoom = 0;
    to.max_zoom = 3;  // 85 metatiles of one tile
    to.metatile = 1;
    to.tile_px = 16;
    to.buffer = 0;
    to.threads = 4;
    for (int round = 0; round < 10; ++round) {
        int progress_calls = 0, sink_calls_after = 0;
        bool thrown = false;
        auto sink = [&](int, int, int, const std::vector<std::uint8_t>&) {
            if (thrown) ++sink_calls_after;
        };
        auto progress = [&](std::uint64_t, std::uint64_t) {
            if (++progress_calls == 3) {
                thrown = true;
                std::this_thread::sleep_for(std::chrono::milliseconds(2));
                throw std::runtime_error("stop");
            }
        };
        CHECK_THROWS_WITH(render_tiles(d, st, to, sink, {}, progress), "stop");
        CHECK(progress_calls == 3);
        CHECK(sink_calls_after == 0);
        // The same for a sink that throws.
        int sink_calls = 0;
        auto failing_sink = [&](int, int, int, const std::vector<std::uint8_t>&) {
            if (++sink_calls == 3) {
                std::this_thread::sleep_for(std::chrono::milliseconds(2));
                throw std::runtime_error("full");
            }
        };
        CHECK_THROWS_WITH(render_tiles(d, st, to, failing_sink), "full");
        CHECK(sink_calls == 3);
    }
}
