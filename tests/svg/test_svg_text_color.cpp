// SVG text with colour glyphs (COLR layers and paint graphs, CBDT and sbix bitmaps): drawn in the
// font's palette colours, with the fill colour standing for the text colour entry, as the
// OpenType COLR table specifies for palette entry 0xFFFF. The test fonts are tests/data's
// (tests/data/make_color_fonts.py describes their glyphs).
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/font_database.hpp"
#include "casteljau/svg.hpp"
#include "formats/svg/display_list.hpp"
#include "text_support.hpp"

using namespace casteljau;
using svg::DisplayItem;

namespace {

SvgOptions color_fonts() {
    FontDatabaseOptions o;
    o.font_files = {text_test::source_path("tests/data/colr_test.ttf"),
                    text_test::source_path("tests/data/emoji_cbdt_test.ttf")};
    o.system_fonts = false;
    SvgOptions s;
    s.font_database = std::make_shared<const FontDatabase>(o);
    s.font_family = "Casteljau COLR Test";
    return s;
}

// A 100 x 100 document with `text_attributes` on a text of the COLR test font at 100 px whose
// origin is the bottom-left corner: font point (fx, fy) lands on pixel (fx / 10, 100 - fy / 10).
std::string colr_document(const std::string& text_attributes, const std::string& text) {
    return "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'><text x='0' y='100' "
           "font-size='100' " +
           text_attributes + ">" + text + "</text></svg>";
}

}  // namespace

TEST_CASE("svg text: a COLR v0 glyph in its palette colours and the fill colour", "[svg][svg_text][color]") {
    // Glyph D: the square 100..900 in palette entry 1 (blue), then the inner square 300..700 in
    // entry 0xFFFF, the text colour, which for SVG text is the fill colour (lime here).
    const Pixmap pm = SvgDocument::parse(colr_document("fill='#00ff00'", "D"), color_fonts()).render();
    // Pixel (20, 50): font point (205, 495), in the square but not the inner one.
    CHECK(pm.pixel(20, 50).r == 0);
    CHECK(pm.pixel(20, 50).g == 0);
    CHECK(pm.pixel(20, 50).b == 255);
    CHECK(pm.pixel(20, 50).a == 255);
    // Pixel (50, 50): font point (505, 495), in the inner square.
    CHECK(pm.pixel(50, 50).r == 0);
    CHECK(pm.pixel(50, 50).g == 255);
    CHECK(pm.pixel(50, 50).b == 0);
    CHECK(pm.pixel(50, 50).a == 255);
    // Pixel (5, 50): font point (55, 495), left of the square.
    CHECK(pm.pixel(5, 50).a == 0);
}

TEST_CASE("svg text: fill-opacity multiplies a colour glyph", "[svg][svg_text][color]") {
    const Pixmap pm =
        SvgDocument::parse(colr_document("fill='#00ff00' fill-opacity='0.5'", "D"), color_fonts()).render();
    // Half of 255 either way of rounding.
    CHECK(std::abs(pm.pixel(20, 50).a - 127.5) <= 1);
    CHECK(std::abs(pm.pixel(50, 50).a - 127.5) <= 1);
}

TEST_CASE("svg text: a colour glyph converts to one colour glyph item, not a fill",
          "[svg][display_list][svg_text][color]") {
    // Two letters of 1000 units' advance at 100 px: the second's origin is 100 px further right.
    const svg::DisplayList items = svg::convert(colr_document("fill='#00ff00'", "DF"), color_fonts());
    std::vector<const DisplayItem*> glyphs;
    for (const DisplayItem& it : items) {
        CHECK(it.kind != DisplayItem::Fill);
        if (it.kind == DisplayItem::ColorGlyph) glyphs.push_back(&it);
    }
    REQUIRE(glyphs.size() == 2);
    CHECK(glyphs[0]->glyph_size == 100);
    CHECK(glyphs[0]->transform.apply({0, 0}).x == Approx(0));
    CHECK(glyphs[0]->transform.apply({0, 0}).y == Approx(100));
    CHECK(glyphs[1]->transform.apply({0, 0}).x == Approx(100));
    CHECK(glyphs[0]->color.g == 255);
}

TEST_CASE("svg text: a CBDT emoji draws its bitmap", "[svg][svg_text][color]") {
    // The font has no outlines at all: without its bitmap nothing would show. U+1F600 at 64 px
    // in the middle of the canvas covers the canvas centre with the emoji's opaque face.
    const std::string doc =
        "<svg xmlns='http://www.w3.org/2000/svg' width='100' height='100'>"
        "<text x='18' y='74' font-size='64' font-family='Noto Color Emoji'>&#x1F600;</text></svg>";
    const Pixmap pm = SvgDocument::parse(doc, color_fonts()).render();
    CHECK(pm.pixel(50, 50).a == 255);
    // A yellow face: red and green well above blue.
    CHECK(pm.pixel(50, 50).r > 200);
    CHECK(pm.pixel(50, 50).b < 128);
}
