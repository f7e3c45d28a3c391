// Clip paths and masks: clip coverage is the product of the shape's and the clip's exact-area
// coverage (within 1/255), luminance and alpha masks, and clip-path / mask cycles.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "casteljau/canvas.hpp"
#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {
SvgDocument doc(const std::string& body, int w = 40, int h = 40) {
    return SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='" + std::to_string(w) + "' height='" +
                              std::to_string(h) + "'>" + body + "</svg>");
}
}  // namespace

TEST_CASE("clip: coverage equals the product of shape and clip coverage within 1/255", "[svg][clip]") {
    // A slanted quadrilateral clipped by a circle, both with anti-aliased edges everywhere; the
    // coverages of each alone come from the rasterizer on the same geometry.
    const char* quad = "M 9.3 3.1 L 35.2 10.4 L 29.9 36.6 L 4.1 28.7 Z";
    const Pixmap pm = doc(std::string("<clipPath id='c'><circle cx='20' cy='20' r='13.3'/></clipPath>"
                                      "<path d='") +
                          quad + "' fill='#000' clip-path='url(#c)'/>")
                          .render();
    Rasterizer r;
    Path circle;
    circle.add_circle({20, 20}, 13.3);
    Path shape;
    shape.move_to(9.3, 3.1);
    shape.line_to(35.2, 10.4);
    shape.line_to(29.9, 36.6);
    shape.line_to(4.1, 28.7);
    shape.close();
    const Mask mc = r.fill_mask(circle, Affine{});
    const Mask ms = r.fill_mask(shape, Affine{});
    int partial = 0;
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            const double want = ms.at(x, y) * mc.at(x, y) / 255.0;
            INFO("pixel " << x << "," << y);
            CHECK(std::abs(pm.pixel(x, y).a - want) <= 1.0);
            partial += ms.at(x, y) > 0 && ms.at(x, y) < 255 && mc.at(x, y) > 0 && mc.at(x, y) < 255;
        }
    CHECK(partial > 0);  // some pixels have both edges: the product is really exercised
}

TEST_CASE("mask: luminance and alpha masks multiply the content", "[svg][mask]") {
    const Pixmap lum = doc("<mask id='m' maskUnits='userSpaceOnUse' x='0' y='0' width='40' height='40'>"
                           "<rect width='40' height='40' fill='rgb(128,128,128)'/></mask>"
                           "<rect width='40' height='40' fill='#000' mask='url(#m)'/>")
                           .render();
    CHECK(std::abs(lum.pixel(20, 20).a - 128) <= 1);
    const Pixmap alpha =
        doc("<mask id='m' mask-type='alpha' maskUnits='userSpaceOnUse' x='0' y='0' width='40' height='40'>"
            "<rect width='40' height='40' fill='rgb(0,0,0)' fill-opacity='0.25'/></mask>"
            "<rect width='40' height='40' fill='#000' mask='url(#m)'/>")
            .render();
    CHECK(std::abs(alpha.pixel(20, 20).a - 64) <= 1);
}

TEST_CASE("clip and mask cycles: the reference back into the cycle is ignored, or the element not drawn",
          "[svg][clip][bad-input]") {
    // Inside clip paths the reference that closes a cycle is ignored (resvg's behaviour), so the
    // clip is the plain rectangle.
    const SvgDocument a =
        doc("<clipPath id='a' clip-path='url(#b)'><rect width='40' height='40'/></clipPath>"
            "<clipPath id='b' clip-path='url(#a)'><rect width='40' height='40'/></clipPath>"
            "<rect width='40' height='40' clip-path='url(#a)'/>");
    CHECK(a.render().pixel(20, 20).a == 255);
    const SvgDocument self =
        doc("<clipPath id='a'><rect width='40' height='40' clip-path='url(#a)'/></clipPath>"
            "<rect width='40' height='40' clip-path='url(#a)'/>");
    CHECK(self.render().pixel(20, 20).a == 255);
    // A mask whose content uses the mask itself: that reference is ignored too, so the content
    // is drawn unmasked and the white rect lets the masked rect through.
    const SvgDocument m =
        doc("<mask id='m'><rect width='40' height='40' fill='white' mask='url(#m)'/></mask>"
            "<rect width='40' height='40' mask='url(#m)'/>");
    CHECK(m.render().pixel(20, 20).a == 255);
}
