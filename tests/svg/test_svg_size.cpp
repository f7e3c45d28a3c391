// The SVG output size: the intrinsic size is kept fractional until the output size is chosen, and
// the output size follows resvg's rule (svg.hpp); a root written with a namespace prefix.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "casteljau/error.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "cli_util.hpp"

using namespace casteljau;
using namespace casteljau::test;
namespace fs = std::filesystem;

TEST_CASE("svg size: a fractional width is not rounded up before scaling", "[svg]") {
    const SvgDocument doc = SvgDocument::parse(
        "<svg xmlns='http://www.w3.org/2000/svg' width='16.031' height='16'><rect width='16.031' height='16'/></svg>");
    CHECK(doc.width() == 16);
    CHECK(doc.height() == 16);
    CHECK(doc.intrinsic_width() == Approx(16.031));
    CHECK(doc.output_size_for_width(256) == std::pair<int, int>{256, 256});
    CHECK(doc.output_size_for_height(256) == std::pair<int, int>{256, 256});
    // The document fills the output exactly: the last column is fully covered.
    const Pixmap pm = doc.render_size(256, 256);
    CHECK(pm.pixel(255, 255).a == 255);
    CHECK(pm.pixel(255, 0).a == 255);
}

TEST_CASE("svg size: rounding to the nearest pixel, at least 1, and the other side rounded up", "[svg]") {
    const SvgDocument a = SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='10.4' height='0.3'/>");
    CHECK(a.width() == 10);
    CHECK(a.height() == 1);
    const SvgDocument b = SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='200' height='100.6'/>");
    CHECK(b.height() == 101);
    CHECK(b.output_size_for_width(300) == std::pair<int, int>{300, 152});  // ceil(300 * 101 / 200) = 152
    CHECK(b.output_size_for_zoom(1.5) == std::pair<int, int>{300, 152});
}

TEST_CASE("svg size: the CLI at --width 256 writes 256x256 for a 16.031 x 16 document", "[svg][cli]") {
    const fs::path d = scratch_dir("svg-size");
    {
        std::ofstream f(d / "a.svg");
        f << "<svg xmlns='http://www.w3.org/2000/svg' width='16.031' height='16'><rect width='20' height='20' "
             "fill='red'/></svg>";
    }
    for (const char* opt : {"--width 256", "-w 256"}) {
        const CliResult r = run_cli("svg " + shell_quote((d / "a.svg").string()) + " " + opt + " -o " +
                                    shell_quote((d / "a.png").string()));
        REQUIRE(r.status == 0);
        const Pixmap pm = read_png((d / "a.png").string());
        CHECK(pm.width() == 256);
        CHECK(pm.height() == 256);
    }
    const CliResult r = run_cli("svg " + shell_quote((d / "a.svg").string()) + " -w 64 --height 32 -b white -o " +
                                shell_quote((d / "b.png").string()));
    REQUIRE(r.status == 0);
    const Pixmap pm = read_png((d / "b.png").string());
    CHECK(pm.width() == 64);
    CHECK(pm.height() == 32);
}

TEST_CASE("svg: a root written <svg:svg> with the SVG namespace bound to its prefix", "[svg]") {
    const SvgDocument doc = SvgDocument::parse(
        "<svg:svg xmlns:svg='http://www.w3.org/2000/svg' width='4' height='4'><svg:rect width='2' height='4' "
        "fill='#00ff00'/>"
        "<other:rect xmlns:other='urn:x' width='4' height='4' fill='red'/></svg:svg>");
    const Pixmap pm = doc.render();
    CHECK(pm.pixel(0, 0) == PremulPixel{0, 255, 0, 255});
    CHECK(pm.pixel(3, 0).a == 0);  // the element of another namespace is not drawn
    CHECK_THROWS_AS(SvgDocument::parse("<svg:svg xmlns:svg='urn:not-svg' width='4' height='4'/>"), Error);
}
