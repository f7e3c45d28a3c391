// OpenType SVG glyphs: tests/data/svg_test.ttf (tests/data/make_color_fonts.py describes its
// documents) drawn through draw_text with the SVG reader as the glyph drawer, against the areas of
// its rectangles worked out by hand; the outline when no drawer is set or a document is malformed;
// the same glyphs from an SVG document's text and from `casteljau text`.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/png.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/text.hpp"
#include "cli_util.hpp"
#include "temp_dir.hpp"

using namespace casteljau;
using casteljau::test::CliResult;
using casteljau::test::run_cli;
using casteljau::test::shell_quote;

namespace {

const std::string kSvgFont = std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/svg_test.ttf";

// `text` at 100 px (an em: 100 px, the ascender 100 px above the baseline) with the layout box's
// top-left corner at (10.25, 10.5): a glyph's font unit (x, y up) lands on pixel
// (10.25 + x / 10 + advance, 110.5 - y / 10).
Pixmap draw(const std::string& text, const Paint& paint = Paint::solid(Color::rgba(0, 128, 0))) {
    const Font font = Font::load(kSvgFont);
    Pixmap pm(260, 130);
    Canvas canvas(pm);
    draw_text(canvas, text, font, 100, Point{10.25, 10.5}, paint);
    return pm;
}

// Sum of alpha over the whole pixmap, in pixels (255 = one pixel).
double alpha_area(const Pixmap& pm) {
    double sum = 0;
    for (int y = 0; y < pm.height(); ++y)
        for (int x = 0; x < pm.width(); ++x) sum += pm.pixel(x, y).a;
    return sum / 255;
}

bool is(PremulPixel p, int r, int g, int b, int a) { return p.r == r && p.g == g && p.b == b && p.a == a; }

}  // namespace

TEST_CASE("SVG glyphs: without a drawer the outline is drawn, with one the glyph's document", "[svg][text][color]") {
    const Font font = Font::load(kSvgFont);
    set_svg_glyph_drawer(nullptr);
    CHECK_FALSE(is_color_glyph(font, 2));
    // The outline square, 100..900 font units both ways, in the paint's colour.
    const Pixmap outline = draw("A");
    CHECK(is(outline.pixel(50, 40), 0, 128, 0, 255));
    CHECK(alpha_area(outline) == Approx(80.0 * 80.0).margin(1));
    enable_svg_glyphs();
    CHECK(is_color_glyph(font, 2));
    CHECK_FALSE(is_color_glyph(font, 1));  // space: no document
    // A: red over blue, x 100..900, y -900..-500 and -500..-100 (y down): pixels x 20.25..100.25,
    // y 20.5..60.5 red and 60.5..100.5 blue.
    const Pixmap a = draw("A");
    CHECK(is(a.pixel(50, 40), 255, 0, 0, 255));
    CHECK(is(a.pixel(50, 80), 0, 0, 255, 255));
    CHECK(a.pixel(50, 105).a == 0);
    CHECK(a.pixel(15, 40).a == 0);
    CHECK(std::abs(a.pixel(20, 40).a - 191) <= 1);  // a quarter of the column outside
    CHECK(std::abs(a.pixel(50, 20).a - 128) <= 1);  // half of the row outside
    // Row 60 is half red, half blue, drawn one over the other: 1/2 + 1/2 (1 - 1/2) = 3/4 covered.
    CHECK(std::abs(a.pixel(50, 60).a - 191) <= 1);
    CHECK(alpha_area(a) == Approx(80.0 * 80.0 - 80 * 0.25).margin(1));
}

TEST_CASE("SVG glyphs: a compressed document, and one document holding two glyphs", "[svg][text][color]") {
    enable_svg_glyphs();
    // B, gzip-compressed: green x 200..600, y -700..-300: pixels x 30.25..70.25, y 40.5..80.5.
    const Pixmap b = draw("B");
    CHECK(is(b.pixel(50, 60), 0, 255, 0, 255));
    CHECK(b.pixel(25, 60).a == 0);
    CHECK(alpha_area(b) == Approx(40.0 * 40.0).margin(1));
    // C and D share a document: C draws only its red left half, D (advance 100 px further) only its
    // blue right half.
    const Pixmap cd = draw("CD");
    CHECK(is(cd.pixel(30, 60), 255, 0, 0, 255));
    CHECK(cd.pixel(80, 60).a == 0);
    CHECK(cd.pixel(130, 60).a == 0);
    CHECK(is(cd.pixel(180, 60), 0, 0, 255, 255));
    CHECK(alpha_area(cd) == Approx(2 * 40.0 * 80.0).margin(1));
}

TEST_CASE("SVG glyphs: a malformed document falls back to the outline, and opacity and layout bounds",
          "[svg][text][color]") {
    enable_svg_glyphs();
    const Pixmap e = draw("E");
    CHECK(is(e.pixel(50, 40), 0, 128, 0, 255));
    CHECK(alpha_area(e) == Approx(80.0 * 80.0).margin(1));
    Paint half = Paint::solid(Color::black());
    half.opacity = 0.5;
    const Pixmap a = draw("A", half);
    CHECK(std::abs(a.pixel(50, 40).a - 128) <= 1);
    CHECK(std::abs(a.pixel(50, 40).r - 128) <= 1);
    // The layout's ink box holds the glyph's outline and its line box.
    const Font font = Font::load(kSvgFont);
    TextStyle style;
    style.size = 100;
    const Rect box = layout_text("A", font, style).bounds();
    CHECK(box.x0 <= 10);
    CHECK(box.x1 >= 90);
    CHECK(box.y1 - box.y0 >= 80);
}

TEST_CASE("SVG glyphs: two fonts whose documents differ for one glyph each draw their own", "[svg][text][color]") {
    enable_svg_glyphs();
    std::ifstream f(kSvgFont, std::ios::binary);
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    // The same font with glyph A's red turned cyan (the document is stored uncompressed).
    const std::string red = "#ff0000", cyan = "#00ffff";
    const auto at = std::search(bytes.begin(), bytes.end(), red.begin(), red.end());
    REQUIRE(at != bytes.end());
    std::copy(cyan.begin(), cyan.end(), at);
    const Font original = Font::load(kSvgFont);
    const Font patched = Font::from_memory(bytes);
    auto pixel = [](const Font& font) {
        Pixmap pm(120, 120);
        Canvas canvas(pm);
        draw_text(canvas, "A", font, 100, Point{10.25, 10.5}, Paint::solid(Color::black()));
        return pm.pixel(50, 40);
    };
    for (int round = 0; round < 2; ++round) {  // the second time from the converted documents kept
        CHECK(is(pixel(original), 255, 0, 0, 255));
        CHECK(is(pixel(patched), 0, 255, 255, 255));
    }
}

TEST_CASE("SVG glyphs: currentColor and context-fill take the text's colour, a colour the document sets wins",
          "[svg][text][color]") {
    enable_svg_glyphs();
    // F: currentColor over x 100..500 (pixels 20.25..60.25), blue over 500..900. G: context-fill
    // left, currentColor right under the document's own color:#00ff00.
    for (int round = 0; round < 2; ++round) {  // the second time from the converted documents kept
        for (const Color text : {Color::rgba(200, 100, 0), Color::rgba(0, 50, 220)}) {
            const Pixmap f = draw("F", Paint::solid(text));
            CHECK(is(f.pixel(40, 60), text.r, text.g, text.b, 255));
            CHECK(is(f.pixel(80, 60), 0, 0, 255, 255));
            const Pixmap g = draw("G", Paint::solid(text));
            CHECK(is(g.pixel(40, 60), text.r, text.g, text.b, 255));
            CHECK(is(g.pixel(80, 60), 0, 255, 0, 255));
            // Column 60 is a quarter left, three quarters right, drawn one over the other:
            // 1/4 + 3/4 (1 - 1/4) = 13/16 covered, over 80 rows.
            CHECK(alpha_area(g) == Approx(80.0 * 80.0 - 80 * 3.0 / 16).margin(1));
        }
    }
}

TEST_CASE("SVG: SvgOptions::color is the initial currentColor and context_fill the root's context-fill", "[svg]") {
    const std::string doc = R"(<svg xmlns="http://www.w3.org/2000/svg" width="20" height="10">
        <rect width="10" height="10" fill="currentColor"/><rect x="10" width="10" height="10" fill="context-fill"/>
        </svg>)";
    const Pixmap plain = SvgDocument::parse(doc).render();
    CHECK(is(plain.pixel(5, 5), 0, 0, 0, 255));  // black, the initial colour
    CHECK(plain.pixel(15, 5).a == 0);            // no context: none
    SvgOptions options;
    options.color = Color::rgba(255, 0, 0);
    options.context_fill = Color::rgba(0, 0, 255);
    const Pixmap given = SvgDocument::parse(doc, options).render();
    CHECK(is(given.pixel(5, 5), 255, 0, 0, 255));
    CHECK(is(given.pixel(15, 5), 0, 0, 255, 255));
}

TEST_CASE("SVG glyphs: an SVG document's text and the text command draw them in colour", "[svg][text][color][cli]") {
    SvgOptions options;
    options.font_files = {kSvgFont};
    options.system_fonts = false;
    const SvgDocument doc = SvgDocument::parse(
        R"(<svg xmlns="http://www.w3.org/2000/svg" width="120" height="120">
             <text x="10" y="110" font-family="Casteljau SVG Test" font-size="100">A</text></svg>)",
        options);
    const Pixmap pm = doc.render();
    CHECK(is(pm.pixel(50, 30), 255, 0, 0, 255));
    CHECK(is(pm.pixel(50, 70), 0, 0, 255, 255));

    const std::string out = (casteljau::testing::process_temp_dir() / "svg_glyph_text.png").string();
    const CliResult r = run_cli("text A --font " + shell_quote(kSvgFont) +
                                " --no-system-fonts --size 100 --padding 0 --background white -o " + shell_quote(out));
    REQUIRE(r.status == 0);
    const Pixmap cli = read_png(out);
    int red = 0, blue = 0;
    for (int y = 0; y < cli.height(); ++y)
        for (int x = 0; x < cli.width(); ++x) {
            red += is(cli.pixel(x, y), 255, 0, 0, 255);
            blue += is(cli.pixel(x, y), 0, 0, 255, 255);
        }
    CHECK(red >= 78 * 38);
    CHECK(blue >= 78 * 38);
}
