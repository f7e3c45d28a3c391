// SVG gradients end to end: objectBoundingBox and userSpaceOnUse units, href inheritance of stops
// and attributes, and bad input (no stops, out-of-order offsets, href cycles, missing servers).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "casteljau/svg.hpp"
#include "svg_test_util.hpp"

using namespace casteljau;

namespace {
Pixmap draw(const std::string& body, int w = 100, int h = 10) {
    return SvgDocument::parse(casteljau::test::svg_text(body, w, h)).render();
}
}  // namespace

TEST_CASE("svg gradient: objectBoundingBox maps 0..1 onto the shape's box", "[svg][gradient]") {
    const Pixmap pm = draw(
        "<linearGradient id='g'><stop offset='0' stop-color='#000'/><stop offset='1' "
        "stop-color='#fff'/></linearGradient>"
        "<rect x='50' width='50' height='10' fill='url(#g)'/>");
    // Pixel 74's centre is at 24.5 / 50 of the box.
    CHECK(std::abs(pm.pixel(74, 5).r - std::lround(255 * 24.5 / 50)) <= 1);
    CHECK(pm.pixel(50, 5).r <= 3);
    CHECK(pm.pixel(99, 5).r >= 252);
    CHECK(pm.pixel(10, 5).a == 0);
}

TEST_CASE("svg gradient: userSpaceOnUse, href inheritance of stops and attributes, spreadMethod", "[svg][gradient]") {
    const Pixmap pm = draw(
        "<linearGradient id='base' x2='10' gradientUnits='userSpaceOnUse' spreadMethod='repeat'>"
        "<stop offset='0' stop-color='#000'/><stop offset='1' stop-color='#fff'/></linearGradient>"
        "<linearGradient id='g' xlink:href='#base'/>"
        "<rect width='100' height='10' fill='url(#g)'/>");
    // Repeats every 10 px: pixel 23 is at t = 0.35.
    CHECK(std::abs(pm.pixel(23, 5).r - std::lround(255 * 0.35)) <= 1);
    CHECK(std::abs(pm.pixel(93, 5).r - std::lround(255 * 0.35)) <= 1);
}

TEST_CASE("svg gradient: bad input is drawn as documented", "[svg][gradient]") {
    // No stops: painted as none.
    CHECK(draw("<linearGradient id='g'/><rect width='100' height='10' fill='url(#g)'/>").pixel(5, 5).a == 0);
    // One stop: its colour everywhere.
    CHECK(draw("<linearGradient id='g'><stop stop-color='#0f0'/></linearGradient><rect width='100' height='10' "
               "fill='url(#g)'/>")
              .pixel(5, 5) == PremulPixel{0, 255, 0, 255});
    // Out-of-order offsets: a stop before its predecessor moves up to it (a hard edge at 0.6).
    const Pixmap pm = draw(
        "<linearGradient id='g'><stop offset='0.6' stop-color='#f00'/><stop offset='0.2' "
        "stop-color='#00f'/></linearGradient>"
        "<rect width='100' height='10' fill='url(#g)'/>");
    CHECK(pm.pixel(30, 5) == PremulPixel{255, 0, 0, 255});
    CHECK(pm.pixel(70, 5) == PremulPixel{0, 0, 255, 255});
    // An href cycle ends the chain (no hang); the stops are still found on the first element.
    const Pixmap cyc = draw(
        "<linearGradient id='a' xlink:href='#b'><stop stop-color='#0f0'/><stop offset='1' "
        "stop-color='#0f0'/></linearGradient>"
        "<linearGradient id='b' xlink:href='#a'/><rect width='100' height='10' fill='url(#b)'/>");
    CHECK(cyc.pixel(5, 5) == PremulPixel{0, 255, 0, 255});
    // A missing server uses the fallback colour, or none.
    CHECK(draw("<rect width='100' height='10' fill='url(#nothing) #00f'/>").pixel(5, 5) == PremulPixel{0, 0, 255, 255});
    CHECK(draw("<rect width='100' height='10' fill='url(#nothing)'/>").pixel(5, 5).a == 0);
    // objectBoundingBox on a zero-height box paints nothing.
    CHECK(draw("<linearGradient id='g'><stop stop-color='#0f0'/><stop offset='1' stop-color='#00f'/></linearGradient>"
               "<line x1='0' y1='5' x2='100' y2='5' stroke='url(#g)' stroke-width='4'/>")
              .pixel(50, 5)
              .a == 0);
}

TEST_CASE("svg pattern: a tile repeats across the fill", "[svg][pattern]") {
    const Pixmap pm = draw(
        "<pattern id='p' patternUnits='userSpaceOnUse' width='10' height='10'>"
        "<rect width='5' height='10' fill='#00f'/></pattern><rect width='100' height='10' fill='url(#p)'/>");
    CHECK(pm.pixel(2, 5) == PremulPixel{0, 0, 255, 255});
    CHECK(pm.pixel(7, 5).a == 0);
    CHECK(pm.pixel(92, 5) == PremulPixel{0, 0, 255, 255});
    CHECK(pm.pixel(97, 5).a == 0);
}

TEST_CASE("svg pattern: a tile of 1e-6 px on a large canvas and a self-referencing pattern",
          "[svg][pattern][bad-input]") {
    const SvgDocument doc = SvgDocument::parse(
        "<svg xmlns='http://www.w3.org/2000/svg' width='4000' height='4000'>"
        "<pattern id='p' patternUnits='userSpaceOnUse' width='1e-6' height='1e-6'><rect width='1' height='1' "
        "fill='#00f'/></pattern>"
        "<pattern id='q' patternUnits='userSpaceOnUse' width='10' height='10'><rect width='10' height='10' "
        "fill='url(#q)'/></pattern>"
        "<rect width='4000' height='2000' fill='url(#p)'/><rect y='2000' width='4000' height='2000' "
        "fill='url(#q)'/></svg>");
    const Pixmap pm = doc.render();
    CHECK(pm.pixel(100, 100) == PremulPixel{0, 0, 255, 255});  // the tile is all blue: one pixel, repeated
    CHECK(pm.pixel(100, 3000).a == 0);                         // the self-reference paints nothing
}
