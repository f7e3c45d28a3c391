// The svg command's --export-id (-i) and --dpi (-d) end to end: pixels, sizes, exit statuses,
// messages, no partial files.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include "casteljau/png.hpp"
#include "cli_util.hpp"

using namespace casteljau;
using namespace casteljau::test;
namespace fs = std::filesystem;

namespace {
// `casteljau svg IN ARGS -o OUT`.
CliResult svg(const fs::path& in, const std::string& args, const fs::path& out) {
    return run_cli("svg " + shell_quote(in.string()) + " " + args + " -o " + shell_quote(out.string()));
}
// An 8 x 4 document: a red square on the left, a blue one on the right, and a green group moved
// by (2, 1) around a 2 x 2 square.
const std::string kTwoSquares =
    "<svg xmlns='http://www.w3.org/2000/svg' width='8' height='4'>"
    "<rect id='red' width='4' height='4' fill='#ff0000'/><rect id='blue' x='4' width='4' height='4' fill='#0000ff'/>"
    "<g transform='translate(2 1)' fill='#00ff00'><rect id='inner' width='2' height='2'/></g></svg>";
}  // namespace

TEST_CASE("svg --export-id: only that element, on the document's canvas, #ID and -i alike", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-export-id");
    write_text(d / "a.svg", kTwoSquares);
    for (const char* args : {"--export-id blue", "--export-id '#blue'", "-i blue"}) {
        INFO(args);
        const CliResult r = svg(d / "a.svg", args, d / "a.png");
        REQUIRE(r.status == 0);
        CHECK(r.err.empty());
        const Pixmap pm = read_png((d / "a.png").string());
        REQUIRE(pm.width() == 8);
        REQUIRE(pm.height() == 4);
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 8; ++x) {
                INFO(x << ", " << y);
                CHECK(pm.pixel(x, y) == (x >= 4 ? PremulPixel{0, 0, 255, 255} : PremulPixel{}));
            }
    }
    REQUIRE(svg(d / "a.svg", "-i inner", d / "b.png").status == 0);
    const Pixmap pm = read_png((d / "b.png").string());
    CHECK(pm.pixel(2, 1) == PremulPixel{0, 255, 0, 255});
    CHECK(pm.pixel(3, 2) == PremulPixel{0, 255, 0, 255});
    CHECK(pm.pixel(1, 1).a == 0);
    CHECK(pm.pixel(4, 2).a == 0);
}

TEST_CASE("svg --export-id: an id no element has exits 1 with one line and writes nothing", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-export-missing");
    write_text(d / "a.svg", kTwoSquares);
    const fs::path out = d / "out";
    fs::create_directories(out);
    for (const char* id : {"nope", "'#nope'"}) {
        const CliResult r = svg(d / "a.svg", std::string("--export-id ") + id, out / "a.png");
        CHECK(r.status == 1);
        CHECK(r.err == "casteljau: error: no element with id 'nope' in " + (d / "a.svg").string() + "\n");
    }
    CHECK(dir_is_empty(out));
}

TEST_CASE("svg --export-id: with several inputs each error line names its file once", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-export-missing-batch");
    write_text(d / "a.svg", kTwoSquares);
    write_text(d / "b.svg", kTwoSquares);
    const fs::path out = d / "out";
    fs::create_directories(out);
    const CliResult r =
        run_cli("svg " + shell_quote((d / "a.svg").string()) + " " + shell_quote((d / "b.svg").string()) +
                " --jobs 1 --export-id nope -o " + shell_quote(out.string()));
    CHECK(r.status == 1);
    CHECK(r.err == "casteljau: error: " + (d / "a.svg").string() + ": no element with id 'nope'\n" +
                       "casteljau: error: " + (d / "b.svg").string() + ": no element with id 'nope'\n" +
                       "casteljau: error: 2 of 2 files were not rendered (their errors are above)\n");
    CHECK(dir_is_empty(out));
}

TEST_CASE("svg --dpi: inches become that many pixels, with --zoom and --width on top", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-dpi");
    // 1in x 0.5in, a rect of 0.5in x 0.25in in its top left corner.
    write_text(d / "a.svg",
               "<svg xmlns='http://www.w3.org/2000/svg' width='1in' height='0.5in'>"
               "<rect width='0.5in' height='0.25in' fill='#ff0000'/></svg>");
    struct Case {
        const char* args;
        int w, h;
    };
    for (const Case& c : {Case{"", 96, 48}, Case{"--dpi 300", 300, 150}, Case{"-d 300", 300, 150},
                          Case{"--dpi 300 --zoom 2", 600, 300}, Case{"--dpi 300 --width 200", 200, 100}}) {
        INFO(c.args);
        REQUIRE(svg(d / "a.svg", c.args, d / "a.png").status == 0);
        const Pixmap pm = read_png((d / "a.png").string());
        CHECK(pm.width() == c.w);
        CHECK(pm.height() == c.h);
        // The rect covers the top left quarter: its last pixel full, the next ones empty.
        CHECK(pm.pixel(c.w / 2 - 1, c.h / 2 - 1) == PremulPixel{255, 0, 0, 255});
        CHECK(pm.pixel(c.w / 2, c.h / 2 - 1).a == 0);
        CHECK(pm.pixel(c.w / 2 - 1, c.h / 2).a == 0);
    }
}

TEST_CASE("svg --dpi: outside 1 to 10000 is bad usage, exit 2", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-dpi-range");
    write_text(d / "a.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='1in' height='1in'/>");
    const fs::path out = d / "out";
    fs::create_directories(out);
    for (const char* dpi : {"0", "0.5", "-96", "10001", "abc"}) {
        INFO(dpi);
        const CliResult r = svg(d / "a.svg", std::string("--dpi ") + dpi, out / "a.png");
        CHECK(r.status == 2);
        CHECK(r.err.rfind("casteljau: error: --dpi: ", 0) == 0);
        CHECK(r.err.find('\n') == r.err.size() - 1);
    }
    CHECK(dir_is_empty(out));
}
