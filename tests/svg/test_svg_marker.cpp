// SVG markers and paint-order: markers at the start, middle and end vertices, oriented along
// the path, scaled by the stroke width; paint-order putting the stroke under the fill.
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {
Pixmap draw(const std::string& body) {
    return SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='40' height='40'>" + body + "</svg>")
        .render();
}
const PremulPixel kGreen{0, 128, 0, 255};
}  // namespace

TEST_CASE("svg marker: start, mid and end vertices, orient auto, strokeWidth units", "[svg][marker]") {
    // A 2x1 marker (in stroke widths of 2: 4x2 px) whose reference point is its left middle.
    const std::string marker =
        "<marker id='m' markerWidth='2' markerHeight='1' refX='0' refY='0.5' orient='auto'>"
        "<rect width='2' height='1' fill='green'/></marker>";
    const Pixmap pm = draw(marker +
                           "<path d='M 5 5 L 25 5 L 25 30' stroke='none' stroke-width='2' fill='none' "
                           "marker-start='url(#m)' marker-mid='url(#m)' marker-end='url(#m)'/>");
    CHECK(pm.pixel(7, 5) == kGreen);  // start, pointing right
    CHECK(pm.pixel(3, 5).a == 0);     // nothing before the reference point
    // The mid vertex bisects right and down: 45 degrees; its first pixel along the diagonal.
    CHECK(pm.pixel(26, 6).a > 0);
    CHECK(pm.pixel(25, 32) == kGreen);  // end, pointing down
    CHECK(pm.pixel(29, 30).a == 0);
}

TEST_CASE("svg paint-order: stroke before fill", "[svg][marker]") {
    const std::string shape = "<rect x='10' y='10' width='20' height='20' fill='green' stroke='red' stroke-width='4' ";
    CHECK(draw(shape + "/>").pixel(11, 20) == PremulPixel{255, 0, 0, 255});
    CHECK(draw(shape + "paint-order='stroke'/>").pixel(11, 20) == kGreen);
    CHECK(draw(shape + "paint-order='stroke'/>").pixel(9, 20) == PremulPixel{255, 0, 0, 255});
}

namespace {
// A 4 x 4 green square centred on each vertex, in user units.
const std::string kSquareMarker =
    "<marker id='m' markerUnits='userSpaceOnUse' markerWidth='4' markerHeight='4' refX='2' refY='2'>"
    "<rect width='4' height='4' fill='green'/></marker>";
}  // namespace

TEST_CASE("svg marker: rect, circle and ellipse get markers at the vertices of their paths", "[svg][marker]") {
    const std::string refs = "fill='none' marker-start='url(#m)' marker-mid='url(#m)' marker-end='url(#m)'/>";
    // The rect's corners (10, 10), (30, 10), (30, 30), (10, 30); nothing along the edges.
    const Pixmap rect = draw(kSquareMarker + "<rect x='10' y='10' width='20' height='20' " + refs);
    for (auto [x, y] : {std::pair{9, 9}, {30, 9}, {30, 30}, {9, 30}}) CHECK(rect.pixel(x, y) == kGreen);
    CHECK(rect.pixel(20, 10).a == 0);
    CHECK(rect.pixel(20, 20).a == 0);
    // A circle's quarter points (30, 20), (20, 30), (10, 20), (20, 10); nothing between them.
    const Pixmap circle = draw(kSquareMarker + "<circle cx='20' cy='20' r='10' " + refs);
    for (auto [x, y] : {std::pair{30, 20}, {20, 30}, {9, 20}, {20, 9}}) CHECK(circle.pixel(x, y) == kGreen);
    CHECK(circle.pixel(27, 27).a == 0);
    const Pixmap ellipse = draw(kSquareMarker + "<ellipse cx='20' cy='20' rx='15' ry='5' " + refs);
    for (auto [x, y] : {std::pair{35, 20}, {20, 25}, {4, 20}, {20, 14}}) CHECK(ellipse.pixel(x, y) == kGreen);
}

TEST_CASE("svg marker: the marker shorthand works in CSS, not as a presentation attribute", "[svg][marker]") {
    const std::string path = "<path d='M 10 10 L 30 10 L 30 30' fill='none' ";
    const Pixmap attr = draw(kSquareMarker + path + "marker='url(#m)'/>");
    CHECK(attr.pixel(10, 10).a == 0);
    CHECK(attr.pixel(30, 30).a == 0);
    const Pixmap css = draw(kSquareMarker + path + "style='marker: url(#m)'/>");
    CHECK(css.pixel(10, 10) == kGreen);  // start
    CHECK(css.pixel(30, 10) == kGreen);  // mid
    CHECK(css.pixel(30, 30) == kGreen);  // end
}

TEST_CASE("svg marker: overflow inherit takes the parent's value, visible when the parent sets none", "[svg][marker]") {
    // The content (a 12 x 12 square from -4, -4) overflows the 4 x 4 marker box by 4 on each side.
    const std::string marker =
        "<marker id='m' overflow='inherit' markerUnits='userSpaceOnUse' markerWidth='4' markerHeight='4' refX='2' "
        "refY='2'>"
        "<rect x='-4' y='-4' width='12' height='12' fill='green'/></marker>";
    const std::string path = "<path d='M 20 20 L 30 20' fill='none' marker-start='url(#m)'/>";
    const Pixmap visible = draw(marker + path);
    CHECK(visible.pixel(15, 15) == kGreen);  // outside the box, inside the content
    CHECK(visible.pixel(20, 20) == kGreen);
    const Pixmap hidden = draw("<g overflow='hidden'>" + marker + "</g>" + path);
    CHECK(hidden.pixel(15, 15).a == 0);
    CHECK(hidden.pixel(20, 20) == kGreen);
    // Without inherit, a marker clips to its box.
    const Pixmap plain = draw(
        "<marker id='m' markerUnits='userSpaceOnUse' markerWidth='4' markerHeight='4' refX='2' refY='2'>"
        "<rect x='-4' y='-4' width='12' height='12' fill='green'/></marker>" +
        path);
    CHECK(plain.pixel(15, 15).a == 0);
}

TEST_CASE("svg marker: context-fill with a paint server uses the marked shape's box and user space", "[svg][marker]") {
    // An 8 x 8 marker square filled with context-fill at each vertex of a 40 x 1 strip.
    const std::string marker =
        "<marker id='m' markerUnits='userSpaceOnUse' markerWidth='8' markerHeight='8' refX='4' refY='4'>"
        "<rect width='8' height='8' fill='context-fill'/></marker>";
    const std::string strip = "d='M 0 20 L 40 20 L 40 21 L 0 21 Z' marker-start='url(#m)' marker-mid='url(#m)'/>";
    // objectBoundingBox gradient: black on the left half of the strip's box (x < 20), green on the
    // right half. The marker at x = 0 is all black, the one at x = 40 all green (with the marker's
    // own box each would be half black, half green).
    const Pixmap grad = draw(
        "<linearGradient id='g'><stop offset='0.5' stop-color='black'/>"
        "<stop offset='0.5' stop-color='green'/></linearGradient>" +
        marker + "<path fill='url(#g)' " + strip);
    const PremulPixel black{0, 0, 0, 255};
    for (int x : {1, 3}) CHECK(grad.pixel(x, 17) == black);
    for (int x : {37, 38}) CHECK(grad.pixel(x, 17) == kGreen);
    // userSpaceOnUse pattern in the strip's user space: green for x mod 20 < 10, black otherwise.
    // Around x = 40 the pixels 36..39 are black (marker space would give green at 36..39).
    const Pixmap patt = draw(
        "<pattern id='p' patternUnits='userSpaceOnUse' width='20' height='40'>"
        "<rect width='20' height='40' fill='black'/><rect width='10' height='40' fill='green'/></pattern>" +
        marker + "<path fill='url(#p)' " + strip);
    for (int x : {37, 38}) CHECK(patt.pixel(x, 17) == black);
    for (int x : {1, 3}) CHECK(patt.pixel(x, 17) == kGreen);
}
