// The path and svg commands end to end: output, exit statuses, messages, no partial files.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "casteljau/file_io.hpp"
#include "casteljau/png.hpp"
#include "cli_util.hpp"

using namespace casteljau;
using namespace casteljau::test;
namespace fs = std::filesystem;

namespace {
// One line, starting with the tool's prefix.
void check_one_line_error(const CliResult& r) {
    INFO("stderr: " << r.err);
    REQUIRE(r.err.rfind("casteljau: error: ", 0) == 0);
    REQUIRE(r.err.find('\n') == r.err.size() - 1);
}
}  // namespace

TEST_CASE("path: renders the expected pixels", "[cli]") {
    const fs::path d = scratch_dir("path-ok");
    const std::string out = (d / "sq.png").string();
    const CliResult r = run_cli("path 'M1 1 H3 V3 H1 Z' --size 4x4 --fill '#ff0000' -o " + shell_quote(out));
    REQUIRE(r.status == 0);
    REQUIRE(r.err.empty());
    const Pixmap pm = read_png(out);
    REQUIRE(pm.width() == 4);
    REQUIRE(pm.height() == 4);
    CHECK(pm.pixel(0, 0).a == 0);
    CHECK(pm.pixel(1, 1) == PremulPixel{255, 0, 0, 255});
    CHECK(pm.pixel(2, 2) == PremulPixel{255, 0, 0, 255});
    CHECK(pm.pixel(3, 3).a == 0);
}

TEST_CASE("path: half-covered pixels and the even-odd rule", "[cli]") {
    const fs::path d = scratch_dir("path-aa");
    const std::string out = (d / "a.png").string();
    // A square from x = 0.5 to 2.5: edge pixels are half covered; a nested square makes a hole under even-odd.
    REQUIRE(
        run_cli("path 'M0.5 0 H2.5 V3 H0.5 Z M1 1 H2 V2 H1 Z' --size 3x3 --fill-rule evenodd -o " + shell_quote(out))
            .status == 0);
    const Pixmap pm = read_png(out);
    CHECK(pm.pixel(0, 0).a == 128);
    CHECK(pm.pixel(1, 0).a == 255);
    CHECK(pm.pixel(1, 1).a == 0);
    CHECK(pm.pixel(2, 1).a == 128);
}

TEST_CASE("path: path data from a file and from standard input", "[cli]") {
    const fs::path d = scratch_dir("path-input");
    write_text(d / "p.txt", "M0 0 H2 V2 H0 Z");
    REQUIRE(run_cli("path @" + shell_quote((d / "p.txt").string()) + " --size 2x2 -o " +
                    shell_quote((d / "a.png").string()))
                .status == 0);
    REQUIRE(run_cli("path - --size 2x2 -o " + shell_quote((d / "b.png").string()), "M0 0 H2 V2 H0 Z").status == 0);
    CHECK(read_png((d / "a.png").string()).pixel(1, 1).a == 255);
    CHECK(read_png((d / "b.png").string()).pixel(1, 1).a == 255);
}

TEST_CASE("path: bad data exits 1 with one line and writes nothing", "[cli]") {
    const fs::path d = scratch_dir("path-bad");
    const std::string out = shell_quote((d / "o.png").string());
    SECTION("malformed path data") {
        const CliResult r = run_cli("path 'M 10 10 L 20' --size 10x10 -o " + out);
        CHECK(r.status == 1);
        check_one_line_error(r);
        CHECK(r.err.find("column") != std::string::npos);
    }
    SECTION("NaN in path data") {
        const CliResult r = run_cli("path 'M 0 0 L NaN 5 Z' --size 10x10 -o " + out);
        CHECK(r.status == 1);
        check_one_line_error(r);
    }
    SECTION("1e400 in path data") {
        const CliResult r = run_cli("path 'M 0 0 L 1e400 5 L 3 3 Z' --size 10x10 -o " + out);
        CHECK(r.status == 1);
        check_one_line_error(r);
        CHECK(r.err.find("out of range") != std::string::npos);
    }
    SECTION("missing path file") {
        const CliResult r = run_cli("path @/nonexistent/p.txt --size 10x10 -o " + out);
        CHECK(r.status == 1);
        check_one_line_error(r);
    }
    CHECK(dir_is_empty(d));
}

TEST_CASE("path: bad usage exits 2", "[cli]") {
    const fs::path d = scratch_dir("path-usage");
    const std::string out = shell_quote((d / "o.png").string());
    CHECK(run_cli("path 'M0 0 H1 V1 Z' --size 10x10").status == 2);               // missing -o
    CHECK(run_cli("path 'M0 0 H1 V1 Z' --size 10 -o " + out).status == 2);        // bad size
    CHECK(run_cli("path 'M0 0 H1 V1 Z' --size 0x10 -o " + out).status == 2);      // zero size
    CHECK(run_cli("path 'M0 0 H1 V1 Z' --size 99999x10 -o " + out).status == 2);  // over the limit
    CHECK(run_cli("path 'M0 0 H1 V1 Z' --size 10x10 --fill nocolour -o " + out).status == 2);
    CHECK(run_cli("path 'M0 0 H1 V1 Z' --size 10x10 --fill-rule winding -o " + out).status == 2);
    CHECK(run_cli("path 'M0 0 H1 V1 Z' --size 10x10 --transform '1 0 0' -o " + out).status == 2);
    CHECK(run_cli("frobnicate").status == 2);
    CHECK(run_cli("").status == 2);
    check_one_line_error(run_cli("path 'M0 0 H1 V1 Z' --size 10x10"));
    CHECK(dir_is_empty(d));
}

TEST_CASE("path: unwritable output path exits 1 and leaves nothing", "[cli]") {
    const fs::path d = scratch_dir("path-unwritable");
    const CliResult r = run_cli("path 'M0 0 H1 V1 Z' --size 4x4 -o " + shell_quote((d / "missing" / "o.png").string()));
    CHECK(r.status == 1);
    check_one_line_error(r);
    const CliResult r2 = run_cli("path 'M0 0 H1 V1 Z' --size 4x4 -o " + shell_quote(d.string()));
    CHECK(r2.status == 1);
    CHECK(dir_is_empty(d));
}

TEST_CASE("help is available on every command", "[cli]") {
    for (const char* c : {"--help", "path --help", "svg --help"}) {
        const CliResult r = run_cli(c);
        INFO(c);
        CHECK(r.status == 0);
        CHECK(r.out.find("Usage") != std::string::npos);
    }
}

TEST_CASE("svg: renders at the declared size, transparent elsewhere", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-ok");
    write_text(d / "a.svg",
               "<svg xmlns='http://www.w3.org/2000/svg' width='20' height='10' viewBox='0 0 40 20'>"
               "<rect x='0' y='0' width='20' height='20' fill='blue'/></svg>");
    REQUIRE(
        run_cli("svg " + shell_quote((d / "a.svg").string()) + " -o " + shell_quote((d / "a.png").string())).status ==
        0);
    const Pixmap pm = read_png((d / "a.png").string());
    CHECK(pm.width() == 20);
    CHECK(pm.height() == 10);
    CHECK(pm.pixel(2, 2) == PremulPixel{0, 0, 255, 255});
    CHECK(pm.pixel(15, 5).a == 0);
}

TEST_CASE("svg: bad files exit 1 with one line and write nothing", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-bad");
    const fs::path in = d / "in";
    fs::create_directories(in);
    const fs::path outdir = d / "out";
    fs::create_directories(outdir);
    const std::string out = shell_quote((outdir / "o.png").string());
    write_text(in / "empty.svg", "");
    write_text(in / "huge.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='1e9' height='10'/>");
    write_text(in / "negative.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='-10' height='10'/>");
    write_text(in / "broken.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'><path d='M0 0'");
    write_text(in / "notsvg.svg", "<html/>");
    std::string deep = "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>";
    for (int i = 0; i < 200; ++i) deep += "<g>";
    for (int i = 0; i < 200; ++i) deep += "</g>";
    write_text(in / "deep.svg", deep + "</svg>");
    for (const char* f :
         {"empty.svg", "huge.svg", "negative.svg", "broken.svg", "notsvg.svg", "deep.svg", "missing.svg"}) {
        INFO(f);
        const CliResult r = run_cli("svg " + shell_quote((in / f).string()) + " -o " + out);
        CHECK(r.status == 1);
        check_one_line_error(r);
    }
    CHECK(run_cli("svg " + shell_quote((in / "huge.svg").string())).status == 2);  // missing -o
    CHECK(dir_is_empty(outdir));
}

TEST_CASE("svg: several inputs go into a folder as NAME.png, on several threads, as each alone", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-many");
    const char* colours[] = {"red", "lime", "blue", "#808080", "black"};
    std::string inputs;
    // Names and documents built with += (GCC 12 warns falsely on some chains of string +).
    auto name_of = [](int i) {
        std::string n = "f";
        n += static_cast<char>('0' + i);
        return n;
    };
    for (int i = 0; i < 5; ++i) {
        const fs::path f = d / (name_of(i) + ".svg");
        std::string doc = "<svg xmlns='http://www.w3.org/2000/svg' height='7' width='";
        doc += static_cast<char>('5' + i);
        doc += "'><circle cx='5' cy='3.5' r='3' fill='";
        doc += colours[i];
        doc += "'/></svg>";
        write_text(f, doc);
        inputs += " ";
        inputs += shell_quote(f.string());
    }
    // The folder is created; --jobs 3 draws three files at once.
    const CliResult r = run_cli("svg" + inputs + " -o " + shell_quote((d / "out").string()) + " --jobs 3");
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    for (int i = 0; i < 5; ++i) {
        const std::string name = name_of(i);
        const fs::path alone = d / (name + "-alone.png");
        REQUIRE(run_cli("svg " + shell_quote((d / (name + ".svg")).string()) + " -o " + shell_quote(alone.string()))
                    .status == 0);
        INFO(name);
        CHECK(read_file((d / "out" / (name + ".png")).string()) == read_file(alone.string()));
    }
    // One input and an existing folder: the same naming.
    fs::create_directories(d / "one");
    REQUIRE(
        run_cli("svg " + shell_quote((d / "f0.svg").string()) + " -o " + shell_quote((d / "one").string())).status ==
        0);
    CHECK(fs::exists(d / "one" / "f0.png"));
}

TEST_CASE("svg: a bad file among several gets its own error line and no output, and the rest are drawn", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-many-bad");
    write_text(d / "good.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='4' height='4'/>");
    write_text(d / "broken.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='4' height='4'><g");
    write_text(d / "huge.svg", "<svg xmlns='http://www.w3.org/2000/svg' width='1e9' height='10'/>");
    const CliResult r =
        run_cli("svg " + shell_quote((d / "broken.svg").string()) + " " + shell_quote((d / "good.svg").string()) + " " +
                shell_quote((d / "huge.svg").string()) + " -o " + shell_quote((d / "out").string()) + " -j 2");
    CHECK(r.status == 1);
    // One line per failed file, naming it, then the summary.
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 3);
    CHECK(r.err.find("broken.svg: ") != std::string::npos);
    CHECK(r.err.find("huge.svg: ") != std::string::npos);
    CHECK(r.err.find("2 of 3 files were not rendered") != std::string::npos);
    CHECK(fs::exists(d / "out" / "good.png"));
    CHECK_FALSE(fs::exists(d / "out" / "broken.png"));
    CHECK_FALSE(fs::exists(d / "out" / "huge.png"));
}

TEST_CASE("svg: several inputs that cannot go into one folder are refused before anything is drawn", "[cli][svg]") {
    const fs::path d = scratch_dir("svg-many-usage");
    const std::string doc = "<svg xmlns='http://www.w3.org/2000/svg' width='4' height='4'/>";
    fs::create_directories(d / "x");
    write_text(d / "a.svg", doc);
    write_text(d / "x" / "a.svg", doc);
    write_text(d / "file.png", "not a folder");
    const std::string a = shell_quote((d / "a.svg").string()), xa = shell_quote((d / "x" / "a.svg").string());
    const std::string out = shell_quote((d / "out").string());
    for (const std::string& args : {"svg " + a + " " + xa + " -o " + out,  // both would be a.png
                                    "svg " + a + " - -o " + out,           // standard input among several
                                    "svg " + a + " " + xa + " -o " + shell_quote((d / "file.png").string()),
                                    "svg " + a + " -o " + out + " --jobs 0"}) {  // no threads
        INFO(args);
        const CliResult r = run_cli(args, doc);
        CHECK(r.status == 2);
        check_one_line_error(r);
    }
    CHECK_FALSE(fs::exists(d / "out"));
}

TEST_CASE("path: --stroke draws the stroke outline over the fill", "[cli][stroke]") {
    const fs::path d = scratch_dir("path-stroke");
    const std::string out = (d / "s.png").string();
    // A horizontal line from x = 2 to 8 at y = 5, width 2: rows 4 and 5, columns 2..7 covered.
    REQUIRE(run_cli("path 'M2 5 H8' --size 10x10 --fill none --stroke blue --stroke-width 2 -o " + shell_quote(out))
                .status == 0);
    const Pixmap pm = read_png(out);
    CHECK(pm.pixel(4, 4) == PremulPixel{0, 0, 255, 255});
    CHECK(pm.pixel(4, 5) == PremulPixel{0, 0, 255, 255});
    CHECK(pm.pixel(4, 3).a == 0);
    CHECK(pm.pixel(1, 4).a == 0);
    CHECK(run_cli("path 'M2 5 H8' --size 10x10 --stroke blue --dash '1 x' -o " + shell_quote(out)).status == 2);
}

TEST_CASE("svg: strokes with width, caps and opacity", "[cli][svg][stroke]") {
    const fs::path d = scratch_dir("svg-stroke");
    write_text(
        d / "a.svg",
        "<svg xmlns='http://www.w3.org/2000/svg' width='20' height='20'>"
        "<line x1='4' y1='10' x2='16' y2='10' stroke='#00ff00' stroke-width='4' stroke-linecap='square'/></svg>");
    REQUIRE(
        run_cli("svg " + shell_quote((d / "a.svg").string()) + " -o " + shell_quote((d / "a.png").string())).status ==
        0);
    const Pixmap pm = read_png((d / "a.png").string());
    CHECK(pm.pixel(2, 9) == PremulPixel{0, 255, 0, 255});  // square cap extends 2 px
    CHECK(pm.pixel(17, 11) == PremulPixel{0, 255, 0, 255});
    CHECK(pm.pixel(10, 7).a == 0);
    CHECK(pm.pixel(10, 13).a == 0);

    // Opacity: stroke-opacity 0.5 and opacity 0.5 on a second, butt-capped line: alpha
    // round(255 x 0.25) = 64 inside it, nothing beyond its ends.
    write_text(d / "b.svg",
               "<svg xmlns='http://www.w3.org/2000/svg' width='20' height='20'>"
               "<line x1='4' y1='10' x2='16' y2='10' stroke='#00ff00' stroke-width='4' stroke-opacity='0.5' "
               "opacity='0.5'/></svg>");
    REQUIRE(
        run_cli("svg " + shell_quote((d / "b.svg").string()) + " -o " + shell_quote((d / "b.png").string())).status ==
        0);
    const Pixmap half = read_png((d / "b.png").string());
    CHECK(half.pixel(10, 9) == PremulPixel{0, 64, 0, 64});
    CHECK(half.pixel(4, 10) == PremulPixel{0, 64, 0, 64});
    CHECK(half.pixel(3, 10).a == 0);  // butt cap: no extension
}
