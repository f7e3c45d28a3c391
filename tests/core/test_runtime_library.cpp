// platform::RuntimeLibrary (src/core/runtime_library.hpp) opens libraries that only some
// commands need on first use: its errors name the library, and a casteljau process that draws
// text loads neither SQLite nor PROJ, while one that writes MBTiles does load SQLite.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <cstring>
#include <string>

#include "cli_util.hpp"
#include "core/runtime_library.hpp"

using casteljau::platform::RuntimeLibrary;

TEST_CASE("runtime library: functions are found, and a missing library or function is named in the error",
          "[platform]") {
    RuntimeLibrary libc("the C library", "libc.so.6");
    std::size_t (*len)(const char*) = nullptr;
    libc.get(len, "strlen");
    REQUIRE(len != nullptr);
    CHECK(len("casteljau") == 9);
    CHECK(libc.error().empty());
    void (*nothing)() = nullptr;
    libc.get(nothing, "casteljau_no_such_function");
    CHECK(nothing == nullptr);
    CHECK(libc.error() == "the C library (libc.so.6) lacks casteljau_no_such_function");

    RuntimeLibrary missing("Nothing", "libcasteljau-no-such-library.so.0");
    missing.get(len, "strlen");
    CHECK(len == nullptr);
    CHECK(missing.error().rfind("cannot load Nothing (libcasteljau-no-such-library.so.0): ", 0) == 0);
}

TEST_CASE("runtime library: casteljau text loads neither SQLite nor PROJ, an MBTiles run loads SQLite",
          "[platform][cli]") {
    using namespace casteljau::test;
    const auto dir = scratch_dir("runtime_library");
    // The dynamic loader lists every object it loads on stderr.
    ::setenv("LD_DEBUG", "files", 1);
    const CliResult text =
        run_cli("text Ag --font " + shell_quote(std::string(CASTELJAU_TEST_FONT_DIR) + "/DejaVuSans.ttf") +
                " --size 24 -o " + shell_quote((dir / "a.png").string()));
    const CliResult tiles =
        run_cli("tiles " + shell_quote(std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/maps/countries-110m.json") +
                " --layer countries --zoom 0-0 -o " + shell_quote((dir / "t.mbtiles").string()));
    ::unsetenv("LD_DEBUG");
    REQUIRE(text.status == 0);
    REQUIRE(tiles.status == 0);
    CHECK(text.err.find("libharfbuzz") != std::string::npos);  // the listing is there
    CHECK(text.err.find("libsqlite3") == std::string::npos);
    CHECK(text.err.find("libproj") == std::string::npos);
    CHECK(tiles.err.find("libsqlite3") != std::string::npos);
}
