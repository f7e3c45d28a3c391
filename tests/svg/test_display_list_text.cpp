// What SVG text converts to, without drawing it: the display list (src/formats/svg/
// display_list.hpp) of small documents with text, drawn with the repository's fonts only. Each
// expected value is worked out from the SVG and CSS specifications in the comments.
#include <catch2/catch.hpp>

#include <memory>
#include <string>
#include <vector>

#include "casteljau/font.hpp"
#include "casteljau/font_database.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/svg.hpp"
#include "formats/svg/display_list.hpp"

using namespace casteljau;
using svg::DisplayItem;

namespace {

SvgOptions repo_fonts() {
    FontDatabaseOptions o;
    o.font_dirs = {CASTELJAU_TEST_FONT_DIR};
    o.system_fonts = false;
    SvgOptions s;
    s.font_database = std::make_shared<const FontDatabase>(o);
    s.font_family = "DejaVu Sans";
    return s;
}

// The display list of `body` in a 200 x 200 svg, text drawn with DejaVu Sans.
svg::DisplayList convert(const std::string& body) {
    return svg::convert("<svg xmlns='http://www.w3.org/2000/svg' width='200' height='200'>" + body + "</svg>",
                        repo_fonts());
}

// The test emoji font (tests/data/emoji_cbdt_test.ttf, family "Noto Color Emoji") alone, with
// U+1F600's advance and the middle of the ascender-to-descender box at 50 user units.
struct EmojiAt50 {
    SvgOptions options;
    double advance = 0, mid = 0;
    EmojiAt50() {
        FontDatabaseOptions o;
        o.font_files = {std::string(CASTELJAU_SOURCE_DIR) + "/tests/data/emoji_cbdt_test.ttf"};
        o.system_fonts = false;
        options.font_database = std::make_shared<const FontDatabase>(o);
        const Font font = Font::load(o.font_files[0]);
        const double k = 50.0 / font.units_per_em();
        advance = font.glyph_metrics(font.glyph_index(0x1F600)).advance * k;
        mid = (font.metrics().ascender + font.metrics().descender) / 2 * k;
    }
};

// The fills and strokes of `items` (leaving out Bounds items).
svg::DisplayList painted(const svg::DisplayList& items) {
    svg::DisplayList out;
    for (const DisplayItem& it : items)
        if (it.kind == DisplayItem::Fill || it.kind == DisplayItem::Stroke) out.push_back(it);
    return out;
}

// The union of the bounds of the painted items' paths in user space (all items here share the
// text's user space).
Rect ink_bounds(const svg::DisplayList& items) {
    const svg::DisplayList p = painted(items);
    Rect r = p.empty() ? Rect{} : p.front().path.bounds();
    for (const DisplayItem& it : p) r = r.united(it.path.bounds());
    return r;
}

}  // namespace

TEST_CASE("svg text: comma-separated decoration keywords are an invalid value", "[svg][display_list][svg_text]") {
    // CSS Text Decoration 3: text-decoration-line is `none | [underline || overline ||
    // line-through || blink]`, keywords separated by white space. A comma makes the declaration
    // invalid, so it is ignored and the text has no decoration at all.
    const std::string text = "<text x='20' y='100' font-size='48'";
    const svg::DisplayList plain = painted(convert(text + ">Text</text>"));
    const svg::DisplayList comma =
        painted(convert(text + " text-decoration='underline,overline,line-through'>Text</text>"));
    const svg::DisplayList spaced =
        painted(convert(text + " text-decoration='underline overline line-through'>Text</text>"));
    REQUIRE_FALSE(plain.empty());
    CHECK(comma.size() == plain.size());
    CHECK(ink_bounds(comma) == ink_bounds(plain));
    // The same keywords separated by spaces do decorate: the overline lies above the glyphs.
    CHECK(ink_bounds(spaced).y0 < ink_bounds(plain).y0);
}

TEST_CASE("svg text: the font shorthand resets font-kerning to auto", "[svg][display_list][svg_text]") {
    // CSS Fonts: the font shorthand first resets every font subproperty it does not set to its
    // initial value, font-kerning (auto) among them, so an inherited font-kerning: none no longer
    // applies and "AVA" is kerned exactly as text that never had it.
    const std::string text = "<text x='20' y='100' style='font: 48px \"DejaVu Sans\"'>AVA</text>";
    const svg::DisplayList kerned = convert(text);
    const svg::DisplayList reset = convert("<g style='font-kerning: none; font-weight: bold'>" + text + "</g>");
    const svg::DisplayList unkerned = convert(
        "<g style='font-kerning: none'><text x='20' y='100' font-size='48' font-family='DejaVu Sans'>AVA</text></g>");
    REQUIRE_FALSE(kerned.empty());
    CHECK(ink_bounds(reset) == ink_bounds(kerned));
    // Without the shorthand the inherited font-kerning: none keeps A and V apart.
    CHECK(ink_bounds(unkerned).x1 > ink_bounds(kerned).x1);
}

TEST_CASE("svg text: textLength 0 squeezes the spacing until the text ends where it starts",
          "[svg][display_list][svg_text]") {
    // SVG 1.1 textLength: only a negative value is an error. With lengthAdjust spacing, the
    // advance of the whole text becomes 0: the gap after each of the n - 1 first glyphs changes
    // by -W / (n - 1) (W the natural width). "T" stays at x = 20; the last glyph, which starts
    // at 20 + (W - w_t) - W, ends exactly at x = 20, where "t" anchored at its end would be.
    // The glyphs between lie within these two (each starts W / 3 further left than it would).
    const std::string text = "<text x='20' y='100' font-size='48'";
    const Rect zero = ink_bounds(convert(text + " textLength='0'>Text</text>"));
    const Rect first = ink_bounds(convert(text + ">T</text>"));
    const Rect last = ink_bounds(convert(text + " text-anchor='end'>t</text>"));
    CHECK(zero.x0 == Approx(last.x0));
    CHECK(zero.x1 == Approx(first.x1));
}

TEST_CASE("svg text: text instanced by use inherits from the use element, not from its own parents",
          "[svg][display_list][svg_text]") {
    // SVG 2 use: the instance is a shadow tree whose host is the use element, so the text's
    // inherited properties come from the use (font-size 48), not from the group around the
    // original in defs (font-size 18). The glyph outlines are those of the same text drawn with
    // font-size 48 at the use's origin (the use's x and y move the instance by its transform).
    const svg::DisplayList used = convert(
        "<g font-size='18'><defs><text id='t'>Text</text></defs></g>"
        "<use href='#t' x='50' y='120' font-size='48'/>");
    const svg::DisplayList direct = convert("<text font-size='48'>Text</text>");
    REQUIRE(used.size() == direct.size());
    REQUIRE_FALSE(used.empty());
    for (std::size_t i = 0; i < used.size(); ++i) {
        CHECK(used[i].path.bounds() == direct[i].path.bounds());
        CHECK(used[i].transform == Affine::translate(50, 120));
    }
}

TEST_CASE("svg text: transform-origin on a text path's path moves the text with the path",
          "[svg][display_list][svg_text]") {
    // CSS Transforms: transform-origin o wraps the transform T as translate(o) T translate(-o);
    // "center" is the middle of the reference box, here the 200 x 200 viewport: (100, 100). A
    // text path follows its path in the path's transformed coordinates, so both documents place
    // the glyphs identically.
    const std::string text = "<text font-size='24'><textPath href='#p'>abcdefghijklm</textPath></text>";
    const svg::DisplayList origin = convert(
        "<path id='p' d='M 30 100 A 40 30 20 1 1 160 100' transform='rotate(90)' transform-origin='center'/>" + text);
    const svg::DisplayList explicit_origin = convert(
        "<path id='p' d='M 30 100 A 40 30 20 1 1 160 100' transform='translate(100 100) rotate(90) "
        "translate(-100 -100)'/>" +
        text);
    REQUIRE(origin.size() == explicit_origin.size());
    REQUIRE(origin.size() >= 2);
    // The path itself (item 0) and the text (the items after it) agree.
    for (std::size_t i = 0; i < origin.size(); ++i) {
        const Rect a = origin[i].path.bounds(), b = explicit_origin[i].path.bounds();
        CHECK(a.x0 == Approx(b.x0).margin(1e-9));
        CHECK(a.y0 == Approx(b.y0).margin(1e-9));
        CHECK(a.x1 == Approx(b.x1).margin(1e-9));
        CHECK(a.y1 == Approx(b.y1).margin(1e-9));
    }
}

TEST_CASE("svg text: the bounding box of text is its glyph cells, hidden text included",
          "[svg][display_list][svg_text]") {
    // SVG 2 (bounding box of text content): every glyph counts with its full cell, its advance
    // by the font's ascender to descender. Text at x = 20 anchored at its end spans the cells
    // [20 - W, 20] x [100 - ascender, 100 - descender] (W the advance of "Text"); anchored at its
    // start, [20, 20 + W]. The box is a Bounds item before the fills, so it counts in its group's
    // bounding box.
    const FontMetrics m = Font::load(std::string(CASTELJAU_TEST_FONT_DIR) + "/DejaVuSans.ttf").metrics();
    const double s = 48.0 / m.units_per_em;
    const std::string text = "<text x='20' y='100' font-size='48'";
    const svg::DisplayList end = convert(text + " text-anchor='end'>Text</text>");
    const svg::DisplayList start = convert(text + ">Text</text>");
    REQUIRE(end.size() == 2);
    REQUIRE(start.size() == 2);
    CHECK(end[0].kind == DisplayItem::Bounds);
    CHECK(end[1].kind == DisplayItem::Fill);
    const Rect cells = end[0].path.bounds();
    CHECK(cells.x1 == Approx(20));
    CHECK(cells.y0 == Approx(100 - m.ascender * s));
    CHECK(cells.y1 == Approx(100 - m.descender * s));
    CHECK(start[0].path.bounds().x0 == Approx(20));
    CHECK(start[0].path.bounds().x1 == Approx(20 + cells.width()));
    // visibility: hidden paints nothing, but the element keeps its geometry: only the Bounds
    // item is left, the same box.
    const svg::DisplayList hidden = convert(text + " visibility='hidden'>Text</text>");
    REQUIRE(hidden.size() == 1);
    CHECK(hidden[0].kind == DisplayItem::Bounds);
    CHECK(hidden[0].path.bounds() == start[0].path.bounds());
    // A hidden tspan: its glyphs are not filled but its cells stay in the text's box.
    const svg::DisplayList part = convert(text + ">Te<tspan visibility='hidden'>xt</tspan></text>");
    REQUIRE(part.size() == 2);
    CHECK(part[0].path.bounds() == start[0].path.bounds());
    CHECK(part[1].kind == DisplayItem::Fill);
    CHECK(part[1].path.bounds().x1 < start[1].path.bounds().x1);
}

TEST_CASE("svg text: alignment-baseline inherit and dominant-baseline no-change keep the parent's baseline",
          "[svg][display_list][svg_text]") {
    // alignment-baseline is not inherited, but the keyword inherit takes the parent's value
    // (CSS Cascade): hanging from the group, as if the text said hanging itself.
    const std::string text = "<text x='20' y='100' font-size='36'";
    CHECK(ink_bounds(
              convert("<g alignment-baseline='hanging'>" + text + " alignment-baseline='inherit'>Text</text></g>")) ==
          ink_bounds(convert(text + " alignment-baseline='hanging'>Text</text>")));
    // SVG 1.1 dominant-baseline no-change: the dominant baseline stays the parent's (middle), so
    // the tspan sits exactly as if it had no dominant-baseline of its own.
    const std::string middle = text + " dominant-baseline='middle'>Some <tspan";
    CHECK(ink_bounds(convert(middle + " dominant-baseline='no-change'>text</tspan></text>")) ==
          ink_bounds(convert(middle + ">text</tspan></text>")));
}

TEST_CASE("svg text: context-fill on text uses the context element's paint and box", "[svg][display_list][svg_text]") {
    // SVG 2 context-fill: the fill of the context element (the use), resolved as for the context
    // element, so an objectBoundingBox gradient spans the use's content box, for the text as for
    // the rect beside it in the same user space: both get the same gradient transform.
    const svg::DisplayList items = convert(
        "<linearGradient id='lg'><stop offset='0' stop-color='white'/><stop offset='1' stop-color='green'/>"
        "</linearGradient><defs><g id='g'><rect x='25' y='25' width='150' height='150' fill='context-fill'/>"
        "<text x='100' y='100' font-size='64' fill='context-fill'>Text</text></g></defs>"
        "<use href='#g' fill='url(#lg)'/>");
    const svg::DisplayList fills = painted(items);
    REQUIRE(fills.size() == 2);
    REQUIRE(fills[0].shader);
    REQUIRE(fills[1].shader);
    CHECK(fills[1].transform == fills[0].transform);
    CHECK(fills[1].shader->transform() == fills[0].shader->transform());
}

TEST_CASE("svg text: text-anchor counts a white space at the end of a chunk", "[svg][display_list][svg_text]") {
    // SVG 2 text-anchor shifts a chunk by its total advance, white space included: the chunk
    // "ab " (the space before the next chunk's tspan stays after white-space collapsing) anchored
    // at its end on x = 100 puts "ab" where "ab" alone anchored at 100 - s would be, s the
    // space's advance (DejaVu Sans, 48 user units).
    const Font font = Font::load(std::string(CASTELJAU_TEST_FONT_DIR) + "/DejaVuSans.ttf");
    const double s = font.glyph_metrics(font.glyph_index(U' ')).advance * 48 / font.units_per_em();
    const svg::DisplayList chunks = painted(
        convert("<text x='100' y='100' font-size='48' text-anchor='end'>ab <tspan x='100' y='150'>c</tspan></text>"));
    const svg::DisplayList alone = painted(
        convert("<text x='" + std::to_string(100 - s) + "' y='100' font-size='48' text-anchor='end'>ab</text>"));
    REQUIRE(chunks.size() == 2);  // "ab" (the text's style), "c" (the tspan's)
    REQUIRE(alone.size() == 1);
    CHECK(chunks[0].path.bounds().x0 == Approx(alone[0].path.bounds().x0).margin(1e-6));
    CHECK(chunks[0].path.bounds().x1 == Approx(alone[0].path.bounds().x1).margin(1e-6));
}

TEST_CASE("svg text: an upright glyph in vertical text is centred on the line", "[svg][display_list][svg_text]") {
    // Vertical text as resvg lays it out: shaped horizontally, the line turned 90 degrees
    // clockwise about the start (x, y). An upright cluster (U+1F600 has vertical orientation U,
    // UAX #50) turns back about the middle of its advance w, which becomes its vertical step;
    // the middle of its ascender-to-descender box, (a + d) / 2 above its baseline, lands on the
    // line. So the k-th cluster's origin is (x - w/2, y + k w + w/2 + (a + d)/2). The emoji are
    // colour glyphs: their items carry the origin directly.
    const EmojiAt50 e;
    const SvgOptions& options = e.options;
    const double w = e.advance, mid = e.mid;
    const svg::DisplayList items = svg::convert(
        "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='200'><text x='100' y='20' font-size='50' "
        "font-family='Noto Color Emoji' writing-mode='tb'>&#x1F600;&#x1F600;</text></svg>",
        options);
    std::vector<Point> origins;
    for (const DisplayItem& it : items)
        if (it.kind == DisplayItem::ColorGlyph) origins.push_back(it.transform.apply({0, 0}));
    REQUIRE(origins.size() == 2);
    for (std::size_t i = 0; i < 2; ++i) {
        CHECK(origins[i].x == Approx(100 - w / 2));
        CHECK(origins[i].y == Approx(20 + static_cast<double>(i) * w + w / 2 + mid));
    }
}

TEST_CASE("svg text: an underline of vertical text runs down the line beside it", "[svg][display_list][svg_text]") {
    // Vertical text turns the horizontal frame 90 degrees clockwise about (x, y) = (100, 20);
    // a sideways cluster's baseline is moved by (a + d) / 2 so that its em box is centred on the
    // line, and, as resvg draws it, the underline sits half the line height (a - d) / 2 below
    // that baseline in the turned frame. Below in that frame is left in user space: the line's
    // centre is at x = 100 - (a + d) / 2 - (a - d) / 2 = 100 - a, and it runs from y = 20 over
    // the advance of "ll" (DejaVu Sans, 40 user units).
    const Font font = Font::load(std::string(CASTELJAU_TEST_FONT_DIR) + "/DejaVuSans.ttf");
    const double k = 40.0 / font.units_per_em();
    const double a = font.metrics().ascender * k, thick = font.metrics().underline_thickness * k;
    const double length = 2 * font.glyph_metrics(font.glyph_index(U'l')).advance * k;
    const svg::DisplayList fills =
        painted(convert("<text x='100' y='20' font-size='40' writing-mode='tb' text-decoration='underline'>ll</text>"));
    REQUIRE(fills.size() == 2);  // the underline (drawn under the glyphs), then the glyphs
    const Rect line = fills[0].path.bounds();
    CHECK(line.x0 == Approx(100 - a - thick / 2));
    CHECK(line.x1 == Approx(100 - a + thick / 2));
    CHECK(line.y0 == Approx(20));
    CHECK(line.y1 == Approx(20 + length));
}

TEST_CASE("svg text: an upright glyph of vertical text on a path turns across the path",
          "[svg][display_list][svg_text]") {
    // On a path, vertical text follows the path as horizontal text does, as resvg lays it out
    // (the specifications say little about it). An upright cluster is then turned 90 degrees
    // counterclockwise about the middle of its advance w, its em box centred on the path: on the
    // path y = 100 starting at x = 0, the emoji's middle is at (w/2, 100) and its origin at
    // (w/2 + (a + d)/2, 100 + w/2), its advance pointing up.
    const EmojiAt50 e;
    const SvgOptions& options = e.options;
    const double w = e.advance, mid = e.mid;
    const svg::DisplayList items = svg::convert(
        "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='200'><path id='p' d='M 0 100 L 200 100'/>"
        "<text font-size='50' font-family='Noto Color Emoji' writing-mode='tb'><textPath href='#p'>&#x1F600;"
        "</textPath></text></svg>",
        options);
    std::vector<Affine> placed;
    for (const DisplayItem& it : items)
        if (it.kind == DisplayItem::ColorGlyph) placed.push_back(it.transform);
    REQUIRE(placed.size() == 1);
    const Point origin = placed[0].apply({0, 0}), advance = placed[0].apply({1, 0});
    CHECK(origin.x == Approx(w / 2 + mid));
    CHECK(origin.y == Approx(100 + w / 2));
    CHECK(advance.x - origin.x == Approx(0).margin(1e-9));
    CHECK(advance.y - origin.y == Approx(-1));
}
