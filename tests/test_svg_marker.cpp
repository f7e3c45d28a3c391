// SVG markers and paint-order: markers at the start, middle and end vertices, oriented along
// the path, scaled by the stroke width; paint-order putting the stroke under the fill.
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {
Pixmap draw(const std::string& body) {
    return SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='40' height='40'>" + body + "</svg>").render();
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
    CHECK(pm.pixel(7, 5) == kGreen);    // start, pointing right
    CHECK(pm.pixel(3, 5).a == 0);       // nothing before the reference point
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
