// SvgOptions::export_id: one element drawn alone, in its place on the document's canvas, with its
// ancestors' transforms, inherited properties and group effects, its references resolved through
// the whole document; a missing id is an error. Expected pixels are worked out by hand.
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/error.hpp"
#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {
// An 8 x 4 document: a red square on the left, a blue one on the right, a green group moved by
// (2, 1) holding a 2 x 2 square at its origin and a 1 x 1 square at (3, 0), and a gradient (red
// up to x = 2, blue from x = 3 in user space) defined before everything and used by a square over
// the red one.
const std::string kDoc =
    "<svg xmlns='http://www.w3.org/2000/svg' width='8' height='4'>"
    "<defs><linearGradient id='g' gradientUnits='userSpaceOnUse' x1='2' x2='3'>"
    "<stop offset='0' stop-color='#ff0000'/><stop offset='1' stop-color='#0000ff'/></linearGradient></defs>"
    "<rect id='red' width='4' height='4' fill='#ff0000'/>"
    "<rect id='blue' x='4' width='4' height='4' fill='#0000ff'/>"
    "<g id='group' transform='translate(2 1)' fill='#00ff00'>"
    "<rect id='inner' width='2' height='2'/><rect x='3' width='1' height='1'/></g>"
    "<rect id='grad' width='4' height='4' fill='url(#g)'/>"
    "<g opacity='0.5'><rect id='faded' x='6' y='3' width='1' height='1' fill='#0000ff'/></g>"
    "</svg>";

SvgDocument exported(const std::string& id, const std::string& doc = kDoc) {
    SvgOptions o;
    o.export_id = id;
    return SvgDocument::parse(doc, o);
}

constexpr PremulPixel kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 255}, kBlue{0, 0, 255, 255}, kClear{0, 0, 0, 0};
}  // namespace

TEST_CASE("svg export id: only that element is drawn, on the whole canvas", "[svg][export]") {
    const SvgDocument doc = exported("blue");
    REQUIRE(doc.width() == 8);
    REQUIRE(doc.height() == 4);
    const Pixmap pm = doc.render();
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            INFO(x << ", " << y);
            CHECK(pm.pixel(x, y) == (x >= 4 ? kBlue : kClear));
        }
}

TEST_CASE("svg export id: a leading # names the same element", "[svg][export]") {
    const Pixmap a = exported("blue").render(), b = exported("#blue").render();
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) CHECK(a.pixel(x, y) == b.pixel(x, y));
}

TEST_CASE("svg export id: the group's transform and inherited fill apply, its other children do not", "[svg][export]") {
    const Pixmap pm = exported("inner").render();
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) {
            INFO(x << ", " << y);
            const bool inside = x >= 2 && x < 4 && y >= 1 && y < 3;
            CHECK(pm.pixel(x, y) == (inside ? kGreen : kClear));
        }
}

TEST_CASE("svg export id: a group is drawn with all its children", "[svg][export]") {
    const Pixmap pm = exported("group").render();
    CHECK(pm.pixel(2, 1) == kGreen);
    CHECK(pm.pixel(5, 1) == kGreen);  // the 1 x 1 square at (3, 0) in the group
    CHECK(pm.pixel(0, 0) == kClear);
    CHECK(pm.pixel(7, 0) == kClear);
}

TEST_CASE("svg export id: a gradient defined elsewhere in the document still paints it", "[svg][export]") {
    const Pixmap pm = exported("grad").render();
    for (int y = 0; y < 4; ++y) {
        CHECK(pm.pixel(0, y) == kRed);
        CHECK(pm.pixel(1, y) == kRed);
        CHECK(pm.pixel(3, y) == kBlue);
        CHECK(pm.pixel(4, y) == kClear);
    }
}

TEST_CASE("svg export id: an ancestor's group opacity still applies", "[svg][export]") {
    const Pixmap pm = exported("faded").render();
    CHECK(pm.pixel(6, 3).a == Approx(128).margin(1));
    CHECK(pm.pixel(5, 3) == kClear);
    CHECK(pm.pixel(0, 0) == kClear);
}

TEST_CASE("svg export id: an element the document does not draw draws nothing, with a warning", "[svg][export]") {
    const SvgDocument doc = exported("g");
    const Pixmap pm = doc.render();
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 8; ++x) CHECK(pm.pixel(x, y) == kClear);
    bool warned = false;
    for (const std::string& w : doc.warnings()) warned = warned || w.find("id 'g' is not drawn") != std::string::npos;
    CHECK(warned);
}

TEST_CASE("svg export id: the root's own background-color is not drawn, the root's id draws everything",
          "[svg][export]") {
    const std::string doc =
        "<svg xmlns='http://www.w3.org/2000/svg' id='root' width='4' height='2' "
        "style='background-color: #ff0000'><rect id='r' x='2' width='2' height='2' fill='#0000ff'/>"
        "</svg>";
    const Pixmap one = exported("r", doc).render();
    CHECK(one.pixel(0, 0) == kClear);
    CHECK(one.pixel(3, 1) == kBlue);
    const Pixmap all = exported("root", doc).render();
    CHECK(all.pixel(0, 0) == kRed);
    CHECK(all.pixel(3, 1) == kBlue);
}

TEST_CASE("svg export id: an id no element has is an error", "[svg][export]") {
    try {
        exported("nope");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::InvalidData);
        CHECK(std::string(e.what()) == "no element with id 'nope'");
    }
}
