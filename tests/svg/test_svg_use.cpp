// SVG structure: use (of elements, symbols and svg), nested svg viewports with their clip,
// switch, and the bad inputs of the structure: self-referencing and cyclic uses, a use bomb,
// 10,000 nested groups.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {
SvgDocument doc(const std::string& body, int w = 20, int h = 20) {
    return SvgDocument::parse(
        "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' width='" +
        std::to_string(w) + "' height='" + std::to_string(h) + "'>" + body + "</svg>");
}
const PremulPixel kGreen{0, 128, 0, 255};
}  // namespace

TEST_CASE("svg use: an element, a symbol with viewBox and a nested svg are instanced", "[svg][use]") {
    const Pixmap pm = doc("<defs><rect id='r' width='5' height='5' fill='green'/>"
                          "<symbol id='s' viewBox='0 0 1 1'><rect width='1' height='1' fill='green'/></symbol></defs>"
                          "<use href='#r' x='10'/><use xlink:href='#s' y='10' width='5' height='5'/>")
                          .render();
    CHECK(pm.pixel(12, 2) == kGreen);
    CHECK(pm.pixel(2, 2).a == 0);  // the defs themselves are not drawn
    CHECK(pm.pixel(2, 12) == kGreen);
    CHECK(pm.pixel(7, 12).a == 0);
}

TEST_CASE("svg: a nested svg is a new viewport that clips its content", "[svg][use]") {
    const Pixmap pm = doc("<svg x='5' y='5' width='10' height='10' viewBox='0 0 1 1'>"
                          "<rect x='-1' y='-1' width='3' height='3' fill='green'/></svg>")
                          .render();
    CHECK(pm.pixel(10, 10) == kGreen);
    CHECK(pm.pixel(2, 2).a == 0);
    CHECK(pm.pixel(17, 17).a == 0);
}

TEST_CASE("svg switch: only the first child whose conditions pass is drawn", "[svg][use]") {
    const Pixmap pm =
        doc("<switch><rect systemLanguage='xx' width='20' height='20' fill='red'/>"
            "<rect width='20' height='20' fill='green'/><rect width='20' height='20' fill='blue'/></switch>")
            .render();
    CHECK(pm.pixel(5, 5) == kGreen);
}

TEST_CASE("svg use: references to itself, directly or through a cycle, are skipped", "[svg][use][bad-input]") {
    const SvgDocument self = doc("<use id='u' href='#u'/><rect width='5' height='5' fill='green'/>");
    CHECK(self.render().pixel(2, 2) == kGreen);
    CHECK_FALSE(self.warnings().empty());
    const SvgDocument parent = doc("<g id='g'><rect width='5' height='5' fill='green'/><use href='#g'/></g>");
    CHECK(parent.render().pixel(2, 2) == kGreen);
    const SvgDocument cycle =
        doc("<g id='a'><use href='#b'/></g><g id='b'><use href='#a'/></g>"
            "<rect width='5' height='5' fill='green'/>");
    CHECK(cycle.render().pixel(2, 2) == kGreen);
    CHECK_FALSE(cycle.warnings().empty());
}

TEST_CASE("svg use: a use bomb is refused with a clear limit error", "[svg][use][bad-input]") {
    // Each level uses the previous one 10 times: 10^9 rectangles.
    std::string body = "<defs><rect id='l0' width='1' height='1'/>";
    for (int i = 1; i <= 9; ++i) {
        body += "<g id='l" + std::to_string(i) + "'>";
        for (int k = 0; k < 10; ++k) body += "<use href='#l" + std::to_string(i - 1) + "'/>";
        body += "</g>";
    }
    body += "</defs><use href='#l9'/>";
    try {
        (void)doc(body);
        FAIL("the use bomb was accepted");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Limit);
        CHECK(std::string(e.what()).find("elements") != std::string::npos);
    }
}

TEST_CASE("svg: 10,000 nested groups are refused with a limit error, not a crash", "[svg][bad-input]") {
    std::string body;
    for (int i = 0; i < 10000; ++i) body += "<g>";
    body += "<rect width='1' height='1'/>";
    for (int i = 0; i < 10000; ++i) body += "</g>";
    try {
        (void)doc(body);
        FAIL("accepted");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Limit); }
}

TEST_CASE("svg transform-origin: the transform turns about the origin given", "[svg]") {
    // scale(0.5) about the centre of a 20x20 viewport keeps the square centred: 5..15.
    const Pixmap pm =
        doc("<rect width='20' height='20' fill='green' transform='scale(0.5)' transform-origin='center'/>").render();
    CHECK(pm.pixel(10, 10) == kGreen);
    CHECK(pm.pixel(6, 6) == kGreen);
    CHECK(pm.pixel(3, 3).a == 0);
    CHECK(pm.pixel(16, 16).a == 0);
    const Pixmap px =
        doc("<rect width='20' height='20' fill='green' transform='scale(0.5)' transform-origin='20px 0'/>").render();
    CHECK(px.pixel(15, 5) == kGreen);
    CHECK(px.pixel(5, 5).a == 0);
}

TEST_CASE("svg use: an instanced symbol keeps its own opacity", "[svg][use]") {
    const Pixmap pm =
        doc("<symbol id='s' opacity='0.5'><rect width='20' height='20' fill='#000'/></symbol><use href='#s'/>")
            .render();
    CHECK(std::abs(pm.pixel(10, 10).a - 128) <= 1);
}

TEST_CASE("svg use: context-fill with a paint server uses the use element's bounding box", "[svg][use]") {
    // Two 10 x 10 squares 30 apart filled with context-fill; the use's box spans x 0..40, so the
    // objectBoundingBox gradient (black below offset 0.5, green above) paints the left square all
    // black and the right one all green. With each square's own box, both would be half and half.
    const Pixmap pm = doc("<linearGradient id='g'><stop offset='0.5' stop-color='black'/>"
                          "<stop offset='0.5' stop-color='green'/></linearGradient>"
                          "<defs><g id='t'><rect width='10' height='10' fill='context-fill'/>"
                          "<rect x='30' width='10' height='10' fill='context-fill'/></g></defs>"
                          "<use href='#t' y='5' fill='url(#g)'/>",
                          40, 20)
                          .render();
    CHECK(pm.pixel(1, 10) == PremulPixel{0, 0, 0, 255});
    CHECK(pm.pixel(8, 10) == PremulPixel{0, 0, 0, 255});
    CHECK(pm.pixel(31, 10) == kGreen);
    CHECK(pm.pixel(38, 10) == kGreen);
    CHECK(pm.pixel(20, 10).a == 0);
    CHECK(pm.pixel(5, 2).a == 0);  // y = 5 moves the squares down
}

TEST_CASE("svg use: 25 nested uses with a gradient fill draw, without an exponential measuring pass", "[svg][use]") {
    // Each use measures its content's box for context-fill; uses met while measuring are not
    // measured again, so this chain costs about 25^2 elements, not 2^25 (which would pass the
    // 1,000,000-element limit and be refused).
    std::string body =
        "<linearGradient id='g'><stop offset='0.5' stop-color='black'/><stop offset='0.5' stop-color='green'/>"
        "</linearGradient><defs><rect id='l0' width='20' height='10' fill='context-fill'/>";
    for (int i = 1; i <= 25; ++i)
        body += "<g id='l" + std::to_string(i) + "'><use href='#l" + std::to_string(i - 1) + "' fill='url(#g)'/></g>";
    body += "</defs><use href='#l25' fill='url(#g)'/>";
    const Pixmap pm = doc(body).render();
    CHECK(pm.pixel(5, 5) == PremulPixel{0, 0, 0, 255});  // left half of the box: black
    CHECK(pm.pixel(15, 5) == kGreen);
    CHECK(pm.pixel(5, 15).a == 0);
}
