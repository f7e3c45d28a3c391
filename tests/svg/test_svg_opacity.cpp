// SVG opacity, pixel for pixel: fill-opacity, stroke-opacity, opacity on shapes and on groups.
// Expected pixels come from the compositing formula (straight colour with alpha round(255 x o),
// premultiplied, source-over rounded once), worked out by hand in the comments; the shapes cover
// whole pixels, so coverage is 255 and any error is in the opacity handling.
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/paint.hpp"
#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {

Pixmap render(const std::string& body, const std::string& size = "10") {
    return SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='" + size + "' height='" + size + "'>" +
                              body + "</svg>")
        .render();
}

}  // namespace

TEST_CASE("svg: fill-opacity scales the fill's alpha, pixel-exact", "[svg][opacity]") {
    // alpha round(255 x 0.5) = 128; red premultiplied: round(255 x 128 / 255) = 128.
    Pixmap pm = render("<rect x='2' y='2' width='6' height='6' fill='#ff0000' fill-opacity='0.5'/>");
    CHECK(pm.pixel(4, 4) == PremulPixel{128, 0, 0, 128});
    CHECK(pm.pixel(1, 1) == PremulPixel{0, 0, 0, 0});
    // #336699 at 0.3: alpha round(76.5) = 77; channels round(51 x 77 / 255) = 15,
    // round(102 x 77 / 255) = 31, round(153 x 77 / 255) = 46.
    pm = render("<rect x='2' y='2' width='6' height='6' fill='#336699' fill-opacity='0.3'/>");
    CHECK(pm.pixel(4, 4) == PremulPixel{15, 31, 46, 77});
    // The same through the style attribute, and over an opaque white rectangle: red 128 + 255 x
    // 127 / 255 = 255, green and blue 255 x 127 / 255 = 127.
    pm = render(
        "<rect width='10' height='10' fill='white'/>"
        "<rect x='2' y='2' width='6' height='6' style='fill:#ff0000;fill-opacity:0.5'/>");
    CHECK(pm.pixel(4, 4) == PremulPixel{255, 127, 127, 255});
    CHECK(pm.pixel(0, 0) == PremulPixel{255, 255, 255, 255});
    // fill-opacity does not touch the stroke.
    pm = render(
        "<rect x='1' y='1' width='8' height='8' fill='none' stroke='#0000ff' stroke-width='2' fill-opacity='0.1'/>");
    CHECK(pm.pixel(1, 4) == PremulPixel{0, 0, 255, 255});
}

TEST_CASE("svg: stroke-opacity scales the stroke's alpha, pixel-exact", "[svg][opacity][stroke]") {
    // A horizontal line 4 px wide over rows 3..6; green at 0.5: (0, 128, 0, 128).
    Pixmap pm = render("<line x1='0' y1='5' x2='10' y2='5' stroke='#00ff00' stroke-width='4' stroke-opacity='0.5'/>");
    CHECK(pm.pixel(5, 3) == PremulPixel{0, 128, 0, 128});
    CHECK(pm.pixel(5, 6) == PremulPixel{0, 128, 0, 128});
    CHECK(pm.pixel(5, 2) == PremulPixel{0, 0, 0, 0});
    // stroke-opacity does not touch the fill: the fill is opaque red inside the stroke.
    pm = render(
        "<rect x='2' y='2' width='6' height='6' fill='#ff0000' stroke='#00ff00' stroke-width='2' "
        "stroke-opacity='0.25'/>");
    CHECK(pm.pixel(5, 5) == PremulPixel{255, 0, 0, 255});
    // On the stroke's outer half (x = 1) the stroke alone: alpha round(63.75) = 64, green 64.
    CHECK(pm.pixel(1, 5) == PremulPixel{0, 64, 0, 64});
    // Its inner half (x = 2) lies over the red fill: red 255 x (1 - 64/255) = 191, green 64.
    CHECK(pm.pixel(2, 5) == PremulPixel{191, 64, 0, 255});
}

TEST_CASE("svg: opacity on a shape multiplies with fill-opacity, pixel-exact", "[svg][opacity]") {
    // Blue at opacity 0.5: (0, 0, 128, 128).
    Pixmap pm = render("<rect x='2' y='2' width='6' height='6' fill='#0000ff' opacity='0.5'/>");
    CHECK(pm.pixel(4, 4) == PremulPixel{0, 0, 128, 128});
    // opacity 0.5 and fill-opacity 0.5: alpha 64 whether rounded once (63.75) or twice (128 -> 64).
    pm = render("<rect x='2' y='2' width='6' height='6' fill='#0000ff' opacity='0.5' fill-opacity='0.5'/>");
    CHECK(pm.pixel(4, 4) == PremulPixel{0, 0, 64, 64});
    // opacity 0 hides the shape.
    pm = render("<rect x='2' y='2' width='6' height='6' fill='#0000ff' opacity='0'/>");
    CHECK(pm.pixel(4, 4) == PremulPixel{0, 0, 0, 0});
}

TEST_CASE("svg: group opacity composites the group once, overlaps do not add up", "[svg][opacity]") {
    // Two opaque blue squares overlapping in x 4..6 inside a group at opacity 0.5: the overlap has
    // the same colour as the rest (0, 0, 128, 128), where two separate translucent squares would
    // give alpha 128 + 127 x 128 / 255 = 192.
    Pixmap pm = render(
        "<g opacity='0.5'><rect x='0' y='0' width='6' height='10' fill='#0000ff'/>"
        "<rect x='4' y='0' width='6' height='10' fill='#0000ff'/></g>");
    CHECK(pm.pixel(1, 5) == PremulPixel{0, 0, 128, 128});
    CHECK(pm.pixel(5, 5) == PremulPixel{0, 0, 128, 128});
    CHECK(pm.pixel(8, 5) == PremulPixel{0, 0, 128, 128});
    // Without the group opacity the children's own opacities do add up in the overlap.
    pm = render(
        "<rect x='0' y='0' width='6' height='10' fill='#0000ff' fill-opacity='0.5'/>"
        "<rect x='4' y='0' width='6' height='10' fill='#0000ff' fill-opacity='0.5'/>");
    CHECK(pm.pixel(5, 5) == PremulPixel{0, 0, 192, 192});
    // Nested groups multiply: 0.5 x 0.5 over a white background gives blue 255 x 64/255 + 255 x
    // 191/255 and red, green 255 x 191 / 255 = 191 (the inner layer composites to alpha 128, the
    // outer to 64).
    pm = render(
        "<rect width='10' height='10' fill='white'/>"
        "<g opacity='0.5'><g opacity='0.5'><rect width='10' height='10' fill='#0000ff'/></g></g>");
    CHECK(pm.pixel(5, 5) == PremulPixel{191, 191, 255, 255});
}

TEST_CASE("svg: hidden and fully transparent children still count in the group's bounding box", "[svg][opacity]") {
    // An objectBoundingBox clip keeping the left half of the group's box. The visible child covers
    // x 20..40; a hidden (or opacity 0) child widens the box to x 0..40, so the clip keeps x < 20
    // only and the visible child disappears. Counted without the hidden child, the box would be
    // x 20..40 and the clip would keep x 20..30.
    const std::string clip =
        "<clipPath id='c' clipPathUnits='objectBoundingBox'><rect width='0.5' height='1'/></clipPath>";
    const std::string visible = "<rect x='20' y='0' width='20' height='40' fill='black'/>";
    for (const std::string hidden : {"visibility='hidden'", "visibility='collapse'", "opacity='0'"}) {
        INFO(hidden);
        const Pixmap pm = render(clip + "<g clip-path='url(#c)'><rect x='0' y='0' width='40' height='40' fill='red' " +
                                     hidden + "/>" + visible + "</g>",
                                 "40");
        CHECK(pm.pixel(25, 20).a == 0);
        CHECK(pm.pixel(5, 20).a == 0);  // the hidden child itself is not drawn
    }
    // The control: with the hidden child removed, the clip keeps the visible child's left half.
    const Pixmap control = render(clip + "<g clip-path='url(#c)'>" + visible + "</g>", "40");
    CHECK(control.pixel(25, 20) == PremulPixel{0, 0, 0, 255});
    CHECK(control.pixel(35, 20).a == 0);
}

TEST_CASE("svg: opacity, display and clip-path on the root svg apply to the whole document", "[svg][opacity]") {
    auto root = [](const std::string& attrs, const std::string& body) {
        return SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10' " + attrs + ">" +
                                  body + "</svg>")
            .render();
    };
    const std::string red = "<rect width='10' height='10' fill='red'/>";
    // Group opacity 0.5: alpha round(255 x 0.5) = 128, premultiplied red 128.
    CHECK(root("opacity='0.5'", red).pixel(5, 5) == PremulPixel{128, 0, 0, 128});
    CHECK(root("display='none'", red).pixel(5, 5).a == 0);
    const Pixmap clipped =
        root("clip-path='url(#c)'", "<clipPath id='c'><rect width='5' height='10'/></clipPath>" + red);
    CHECK(clipped.pixel(2, 5) == PremulPixel{255, 0, 0, 255});
    CHECK(clipped.pixel(7, 5).a == 0);
    CHECK(root("", red).pixel(7, 5) == PremulPixel{255, 0, 0, 255});
}
