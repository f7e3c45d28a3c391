// What SVG filters convert to, without drawing them: the filter graphs that the display list
// (src/formats/svg/display_list.hpp) hands to the filter stage. Each expected value is worked out
// from the Filter Effects specification (or, where it says so, from what browsers do).
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/filter.hpp"
#include "formats/svg/display_list.hpp"

using namespace casteljau;
using svg::DisplayItem;

namespace {

// The first primitive of the filter `filter` (the children of a <filter>) applied to a
// 100 x 100 rect in a 200 x 200 svg.
filter::Primitive first_primitive(const std::string& primitives) {
    const svg::DisplayList items =
        svg::convert("<svg xmlns='http://www.w3.org/2000/svg' width='200' height='200'><filter id='f'>" + primitives +
                     "</filter><rect x='50' y='50' width='100' height='100' filter='url(#f)'/></svg>");
    for (const DisplayItem& it : items)
        if (it.kind == DisplayItem::EndFilter && it.filters && !it.filters->empty() &&
            !it.filters->front().primitives.empty())
            return it.filters->front().primitives.front();
    FAIL("no filter primitive in the display list");
    return {};
}

}  // namespace

TEST_CASE("svg filter conversion: an unknown feColorMatrix type is the initial value, matrix",
          "[svg][display_list][filter]") {
    // Filter Effects 1: type is matrix | saturate | hueRotate | luminanceToAlpha with initial
    // value matrix; an invalid value is as if the attribute were absent, so the 20 values are
    // the matrix.
    const filter::Primitive p =
        first_primitive("<feColorMatrix type='qwe' values='-1 0 0 0 1  0 -1 0 0 1  0 0 -1 0 1  0 0 0 1 0'/>");
    CHECK(p.op == filter::Primitive::ColorMatrix);
    const std::array<double, 20> inverse{-1, 0, 0, 0, 1, 0, -1, 0, 0, 1, 0, 0, -1, 0, 1, 0, 0, 0, 1, 0};
    CHECK(p.matrix == inverse);
}

TEST_CASE("svg filter conversion: a morphology radius of zero on one axis is 1 on that axis",
          "[svg][display_list][filter]") {
    // The specification disables the primitive for a zero radius; Chrome and Safari (and the
    // resvg references) instead take a zero on one axis as 1 user unit when the other is
    // positive, and 1 on both axes when both are zero.
    filter::Primitive p = first_primitive("<feMorphology radius='10 0'/>");
    CHECK(p.op == filter::Primitive::Morphology);
    CHECK(p.rx == 10);
    CHECK(p.ry == 1);
    p = first_primitive("<feMorphology radius='0 4'/>");
    CHECK(p.rx == 1);
    CHECK(p.ry == 4);
    p = first_primitive("<feMorphology radius='0'/>");
    CHECK(p.rx == 1);
    CHECK(p.ry == 1);
}

TEST_CASE("svg filter conversion: a negative spot light exponent is 1", "[svg][display_list][filter]") {
    // Filter Effects 1 gives feSpotLight's specularExponent no meaning below 0 (the cone's
    // falloff is cos^e, which would grow away from the axis); Chrome pins the exponent to
    // [1, 128] and the resvg references take 1, so -10 is 1. Positive values stay as given.
    filter::Primitive p = first_primitive(
        "<feDiffuseLighting><feSpotLight x='100' y='150' z='40' specularExponent='-10'/></feDiffuseLighting>");
    CHECK(p.light.type == filter::Light::Spot);
    CHECK(p.light.specular_exponent == 1);
    p = first_primitive(
        "<feDiffuseLighting><feSpotLight x='100' y='150' z='40' specularExponent='25'/></feDiffuseLighting>");
    CHECK(p.light.specular_exponent == 25);
}

TEST_CASE("svg filter conversion: a kernel whose values sum to zero has divisor 1", "[svg][display_list][filter]") {
    // Filter Effects 1: the default divisor is the sum of the kernel's values, and 1 when that sum
    // is zero. Eight times 0.1 and -0.8 sum to zero, although adding their nearest doubles leaves
    // about -1e-16, which as a divisor would multiply every result by -9e15.
    filter::Primitive p = first_primitive("<feConvolveMatrix kernelMatrix='0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 -0.8'/>");
    CHECK(p.op == filter::Primitive::ConvolveMatrix);
    CHECK(p.divisor == 1);
    // A sum that is not zero stays the divisor.
    p = first_primitive("<feConvolveMatrix kernelMatrix='0.1 0.1 0.1 0.1 0.1 0.1 0.1 0.1 -0.7'/>");
    CHECK(p.divisor == Approx(0.1));
}
