// SVG lengths relative to the element: em and ex against the element's computed font-size (set
// on it or inherited, 12 px where none is set), percentages of stroke-width, stroke-dasharray and
// stroke-dashoffset against the nearest viewport's normalised diagonal sqrt((w^2 + h^2) / 2).
#include <catch2/catch.hpp>

#include <initializer_list>
#include <string>
#include <utility>

#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {
Pixmap draw(const std::string& body) {
    return SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='40' height='40'>" + body + "</svg>")
        .render();
}
using Pixels = std::initializer_list<std::pair<int, int>>;
// Every pixel of `inked` fully covered, every pixel of `blank` empty.
void check_pixels(const Pixmap& pm, Pixels inked, Pixels blank) {
    for (auto [x, y] : inked) {
        INFO("inked at " << x << ", " << y);
        CHECK(pm.pixel(x, y).a == 255);
    }
    for (auto [x, y] : blank) {
        INFO("blank at " << x << ", " << y);
        CHECK(pm.pixel(x, y).a == 0);
    }
}
}  // namespace

TEST_CASE("svg units: em on rect sizes is the inherited font-size", "[svg][units]") {
    // font-size 20: x = 0.5em = 10, width = height = 1em = 20.
    const Pixmap pm = draw("<g font-size='20'><rect x='0.5em' width='1em' height='1em'/></g>");
    check_pixels(pm, {{10, 5}, {29, 19}}, {{9, 5}, {30, 5}, {20, 20}});
}

TEST_CASE("svg units: em in font-size is relative to the parent's, ex is half an em", "[svg][units]") {
    // 2em of 10 = 20; 1ex = 10.
    const Pixmap pm = draw("<g font-size='10'><g font-size='2em'><rect width='1ex' height='1em'/></g></g>");
    check_pixels(pm, {{9, 19}}, {{10, 10}, {5, 20}});
}

TEST_CASE("svg units: em without any font-size is 12 user units", "[svg][units]") {
    const Pixmap pm = draw("<rect width='1em' height='1em'/>");
    check_pixels(pm, {{11, 11}}, {{12, 5}, {5, 12}});
}

TEST_CASE("svg units: stroke-width percent is of the viewport diagonal", "[svg][units]") {
    // A 40 x 40 viewport: diagonal sqrt((40^2 + 40^2) / 2) = 40, so 50% = 20 (y 10..30).
    const Pixmap pm = draw("<line x1='0' y1='20' x2='40' y2='20' stroke='black' stroke-width='50%'/>");
    check_pixels(pm, {{20, 10}, {20, 29}}, {{20, 9}, {20, 30}});
    // Inside a nested 20 x 40 svg: sqrt((400 + 1600) / 2) = 31.62..., 50% = 15.81 (y 12.09..27.91).
    const Pixmap nested = draw(
        "<svg width='20' height='40'><line x1='0' y1='20' x2='20' y2='20' stroke='black' "
        "stroke-width='50%'/></svg>");
    check_pixels(nested, {{10, 13}, {10, 26}}, {{10, 11}, {10, 28}});
}

TEST_CASE("svg units: em and percent in stroke-dasharray and stroke-dashoffset", "[svg][units]") {
    // font-size 5: dashes of 2em = 10 on, 1em = 5 off along y = 5 from x = 0.
    const Pixmap em = draw(
        "<line x1='0' y1='5' x2='40' y2='5' stroke='black' stroke-width='4' font-size='5' "
        "stroke-dasharray='2em 1em'/>");
    check_pixels(em, {{1, 5}, {9, 5}, {16, 5}}, {{11, 5}, {14, 5}});
    // Percentages of the 40 px diagonal: 25% = 10 on, 25% off, shifted by an offset of 12.5% = 5.
    const Pixmap pct = draw(
        "<line x1='0' y1='5' x2='40' y2='5' stroke='black' stroke-width='4' "
        "stroke-dasharray='25% 25%' stroke-dashoffset='12.5%'/>");
    check_pixels(pct, {{1, 5}, {4, 5}, {16, 5}, {24, 5}}, {{6, 5}, {14, 5}, {26, 5}});
}

TEST_CASE("svg units: em in a CSS filter function is the element's font-size", "[svg][units]") {
    // font-size 20: the shadow of the 10 x 10 square moves by 1em = 20 (x 20..30), not 16.
    const Pixmap pm =
        draw("<rect width='10' height='10' fill='black' font-size='20' filter='drop-shadow(black 1em 0 0)'/>");
    check_pixels(pm, {{5, 5}, {21, 5}, {29, 5}}, {{18, 5}, {31, 5}});
}
