// Filter effects through the SVG reader: the filter property, regions and units, the primitives
// end to end with values worked out by hand (flat lighting, lattice-point turbulence, morphology
// squares, identity kernels), the CSS filter functions, and the invalid-filter rules.
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/svg.hpp"
#include "svg_test_util.hpp"

using namespace casteljau;

namespace {
Pixmap render(const std::string& body, int w = 20, int h = 20) {
    return SvgDocument::parse(casteljau::test::svg_text(body, w, h)).render();
}
const PremulPixel kNone{0, 0, 0, 0};
}  // namespace

TEST_CASE("svg filter: feFlood fills the filter region in user space, transparent outside", "[filter][svg]") {
    const Pixmap pm = render(
        "<filter id='f' filterUnits='userSpaceOnUse' x='5' y='5' width='10' height='8'>"
        "<feFlood flood-color='#00ff00' flood-opacity='0.5'/></filter>"
        "<rect width='20' height='20' fill='red' filter='url(#f)'/>");
    CHECK(pm.pixel(10, 10) == PremulPixel{0, 128, 0, 128});
    CHECK(pm.pixel(2, 2) == kNone);
    CHECK(pm.pixel(10, 14) == kNone);
}

TEST_CASE("svg filter: the default region is the bounding box grown by 10 percent on each side", "[filter][svg]") {
    const Pixmap pm = render(
        "<filter id='f'><feFlood flood-color='blue'/></filter>"
        "<rect x='5' y='5' width='10' height='10' filter='url(#f)'/>");
    CHECK(pm.pixel(4, 4).a == 255);  // 4 .. 16
    CHECK(pm.pixel(15, 15).a == 255);
    CHECK(pm.pixel(3, 3).a == 0);
    CHECK(pm.pixel(16, 16).a == 0);
}

TEST_CASE("svg filter: a missing filter, an empty filter and a zero-sized subregion hide the element",
          "[filter][svg]") {
    CHECK(render("<rect width='20' height='20' filter='url(#nothing)'/>").pixel(10, 10) == kNone);
    CHECK(render("<filter id='f'/><rect width='20' height='20' filter='url(#f)'/>").pixel(10, 10) == kNone);
    CHECK(render("<filter id='f'><feOffset width='0'/></filter><rect width='20' height='20' filter='url(#f)'/>")
              .pixel(10, 10) == kNone);
    // A malformed filter value is ignored: the element is drawn unfiltered.
    CHECK(render("<rect width='20' height='20' filter='url(#f'/>").pixel(10, 10).a == 255);
}

TEST_CASE("svg filter: feOffset and SourceAlpha move and blacken the element", "[filter][svg]") {
    const Pixmap pm = render(
        "<filter id='f' filterUnits='userSpaceOnUse' x='0' y='0' width='20' height='20'>"
        "<feOffset in='SourceAlpha' dx='5' dy='3'/></filter>"
        "<rect width='5' height='5' fill='red' filter='url(#f)'/>");
    CHECK(pm.pixel(7, 5) == PremulPixel{0, 0, 0, 255});
    CHECK(pm.pixel(2, 2) == kNone);
}

TEST_CASE("svg filter: flat diffuse and specular lighting give kd and ks times the light colour", "[filter][svg]") {
    const std::string fu =
        "filterUnits='userSpaceOnUse' x='0' y='0' width='20' height='20' color-interpolation-filters='sRGB'";
    const Pixmap d = render("<filter id='f' " + fu +
                            "><feDiffuseLighting diffuseConstant='0.5' lighting-color='#ff8000'>"
                            "<feDistantLight elevation='90'/></feDiffuseLighting></filter>"
                            "<rect width='20' height='20' filter='url(#f)'/>");
    // A flat surface (opaque everywhere) has N = (0, 0, 1) = L: colour kd x (255, 128, 0), opaque.
    CHECK(d.pixel(10, 10) == PremulPixel{128, 64, 0, 255});
    const Pixmap s = render("<filter id='f' " + fu +
                            "><feSpecularLighting specularConstant='0.5' specularExponent='7'>"
                            "<feDistantLight elevation='90'/></feSpecularLighting></filter>"
                            "<rect width='20' height='20' filter='url(#f)'/>");
    // H = N: ks x 1^n x white = 0.5 (premultiplied), alpha the largest channel.
    CHECK(s.pixel(10, 10) == PremulPixel{128, 128, 128, 128});
}

TEST_CASE("svg filter: fractal noise is one half at the lattice points, turbulence zero", "[filter][svg]") {
    // With baseFrequency 1 every pixel corner is a lattice point, where Perlin noise is 0.
    const std::string fu =
        "filterUnits='userSpaceOnUse' x='0' y='0' width='20' height='20' color-interpolation-filters='sRGB'";
    const Pixmap f = render("<filter id='f' " + fu +
                            "><feTurbulence type='fractalNoise' baseFrequency='1' numOctaves='3'/></filter>"
                            "<rect width='20' height='20' filter='url(#f)'/>");
    CHECK(f.pixel(3, 7) == PremulPixel{64, 64, 64, 128});
    const Pixmap t = render("<filter id='f' " + fu +
                            "><feTurbulence baseFrequency='1'/></filter>"
                            "<rect width='20' height='20' filter='url(#f)'/>");
    CHECK(t.pixel(3, 7) == kNone);
    // Between lattice points the noise is not zero.
    const Pixmap n = render("<filter id='f' " + fu +
                            "><feTurbulence baseFrequency='0.13' seed='3'/></filter>"
                            "<rect width='20' height='20' filter='url(#f)'/>");
    int nonzero = 0;
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x) nonzero += n.pixel(x, y).a > 0;
    CHECK(nonzero > 300);
}

TEST_CASE("svg filter: dilating a pixel gives a 2r square, eroding it removes it, an identity kernel keeps it",
          "[filter][svg]") {
    const std::string fu = "filterUnits='userSpaceOnUse' x='0' y='0' width='20' height='20'";
    const std::string dot = "<rect x='10' y='10' width='1' height='1' fill='black' filter='url(#f)'/>";
    const Pixmap dil = render("<filter id='f' " + fu + "><feMorphology operator='dilate' radius='2'/></filter>" + dot);
    // The window of radius r covers x - r .. x + r - 1 (resvg's): the pixel at 10 reaches 9 .. 12.
    CHECK(dil.pixel(9, 9).a == 255);
    CHECK(dil.pixel(12, 12).a == 255);
    CHECK(dil.pixel(8, 10).a == 0);
    CHECK(dil.pixel(13, 10).a == 0);
    const Pixmap ero = render("<filter id='f' " + fu + "><feMorphology radius='1'/></filter>" + dot);
    CHECK(ero.pixel(10, 10).a == 0);
    const Pixmap id =
        render("<filter id='f' " + fu + "><feConvolveMatrix kernelMatrix='0 0 0 0 1 0 0 0 0'/></filter>" + dot);
    CHECK(id.pixel(10, 10).a == 255);
    CHECK(id.pixel(11, 10).a == 0);
    // A shift kernel: the source pixel up-left of each output pixel.
    const Pixmap sh =
        render("<filter id='f' " + fu + "><feConvolveMatrix kernelMatrix='0 0 0 0 0 0 0 0 1'/></filter>" + dot);
    CHECK(sh.pixel(11, 11).a == 255);
    CHECK(sh.pixel(10, 10).a == 0);
}

TEST_CASE("svg filter: feTile repeats its input's subregion, feMerge stacks its nodes", "[filter][svg]") {
    const Pixmap t = render(
        "<filter id='f' filterUnits='userSpaceOnUse' x='0' y='0' width='20' height='20'>"
        "<feFlood flood-color='#0000ff' x='0' y='0' width='2' height='2'/>"
        "<feOffset dx='0'/><feTile/></filter>"
        "<rect width='20' height='20' filter='url(#f)'/>");
    CHECK(t.pixel(17, 13) == PremulPixel{0, 0, 255, 255});
    const Pixmap m = render(
        "<filter id='f' filterUnits='userSpaceOnUse' x='0' y='0' width='20' height='20'>"
        "<feFlood flood-color='#0000ff' result='b'/>"
        "<feMerge><feMergeNode in='b'/><feMergeNode in='SourceGraphic'/></feMerge></filter>"
        "<rect width='10' height='20' fill='#ff0000' filter='url(#f)'/>");
    CHECK(m.pixel(5, 5) == PremulPixel{255, 0, 0, 255});
    CHECK(m.pixel(15, 5) == PremulPixel{0, 0, 255, 255});
}

TEST_CASE("svg filter: CSS filter functions opacity, invert, grayscale and drop-shadow", "[filter][svg]") {
    CHECK(render("<rect width='20' height='20' fill='#ff0000' filter='opacity(0.5)'/>").pixel(10, 10) ==
          PremulPixel{128, 0, 0, 128});
    CHECK(render("<rect width='20' height='20' fill='#ff0000' filter='invert(100%)'/>").pixel(10, 10) ==
          PremulPixel{0, 255, 255, 255});
    const PremulPixel g = render("<rect width='20' height='20' fill='#00ff00' filter='grayscale(1)'/>").pixel(10, 10);
    CHECK(g.r == g.g);
    CHECK(g.g == g.b);
    CHECK(g.r == 182);  // 0.7152 x 255
    const Pixmap s = render("<rect width='10' height='10' fill='#ff0000' filter='drop-shadow(4px 4px #0000ff)'/>");
    CHECK(s.pixel(5, 5) == PremulPixel{255, 0, 0, 255});
    CHECK(s.pixel(12, 12) == PremulPixel{0, 0, 255, 255});
    // An unknown function makes the whole list invalid: it is ignored and the element drawn unfiltered.
    CHECK(render("<rect width='20' height='20' fill='#00ff00' filter='grayscale(1) wobble(3)'/>").pixel(10, 10) ==
          PremulPixel{0, 255, 0, 255});
    // A url naming nothing is skipped in a list, and hides the element when alone.
    CHECK(render("<rect width='20' height='20' fill='#ff0000' filter='url(#none) opacity(0.5)'/>").pixel(10, 10) ==
          PremulPixel{128, 0, 0, 128});
    CHECK(render("<rect width='20' height='20' filter='url(#none)'/>").pixel(10, 10) == kNone);
}

TEST_CASE("svg filter: the filter runs before opacity, clip and mask", "[filter][svg]") {
    const Pixmap pm = render(
        "<filter id='f' filterUnits='userSpaceOnUse' x='0' y='0' width='20' height='20'>"
        "<feFlood flood-color='#0000ff'/></filter>"
        "<clipPath id='c'><rect width='10' height='20'/></clipPath>"
        "<rect width='5' height='5' opacity='0.5' clip-path='url(#c)' filter='url(#f)'/>");
    CHECK(pm.pixel(5, 15) == PremulPixel{0, 0, 128, 128});
    CHECK(pm.pixel(15, 15) == kNone);
}
