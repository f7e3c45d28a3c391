// SvgOptions::dpi: the pixels per inch of the physical units (in, cm, mm, pt, pc), the root's
// width and height included; 96 (CSS pixels) by default; px lengths do not change.
#include <catch2/catch.hpp>

#include <string>

#include "casteljau/error.hpp"
#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {
SvgDocument at_dpi(const std::string& doc, double dpi) {
    SvgOptions o;
    o.dpi = dpi;
    return SvgDocument::parse(doc, o);
}
const std::string kInches = "<svg xmlns='http://www.w3.org/2000/svg' width='1in' height='0.5in'/>";
}  // namespace

TEST_CASE("svg dpi: a document in inches is 96 pixels an inch by default, 300 at 300 dpi", "[svg][dpi]") {
    const SvgDocument css = SvgDocument::parse(kInches);
    CHECK(css.width() == 96);
    CHECK(css.height() == 48);
    const SvgDocument print = at_dpi(kInches, 300);
    CHECK(print.width() == 300);
    CHECK(print.height() == 150);
    // Zoom and width scale from the size the resolution gives.
    CHECK(print.output_size_for_zoom(2) == std::make_pair(600, 300));
    CHECK(print.output_size_for_width(150) == std::make_pair(150, 75));
}

TEST_CASE("svg dpi: a rect one inch wide fills that many pixels, px lengths stay", "[svg][dpi]") {
    // A 400 x 4 px document: a 1in x 2px rect, then a 2px-wide rect at x = 396.
    const std::string doc =
        "<svg xmlns='http://www.w3.org/2000/svg' width='400' height='4'>"
        "<rect width='1in' height='2'/><rect x='396' width='2' height='4'/></svg>";
    for (double dpi : {96.0, 300.0, 72.0}) {
        INFO("dpi " << dpi);
        const Pixmap pm = at_dpi(doc, dpi).render();
        REQUIRE(pm.width() == 400);
        const int inch = static_cast<int>(dpi);
        CHECK(pm.pixel(inch - 1, 1).a == 255);
        CHECK(pm.pixel(inch, 1).a == 0);
        CHECK(pm.pixel(inch - 1, 2).a == 0);
        CHECK(pm.pixel(396, 3).a == 255);
        CHECK(pm.pixel(398, 3).a == 0);
    }
}

TEST_CASE("svg dpi: points, picas, millimetres and centimetres follow it too", "[svg][dpi]") {
    // At 144 dpi: 36pt = 0.5in = 72 px, 3pc = 0.5in, 12.7mm = 0.5in, 1.27cm = 0.5in.
    for (const char* w : {"36pt", "3pc", "12.7mm", "1.27cm"}) {
        INFO(w);
        const Pixmap pm =
            at_dpi(std::string("<svg xmlns='http://www.w3.org/2000/svg' width='100' height='2'><rect width='") + w +
                       "' height='2'/></svg>",
                   144)
                .render();
        CHECK(pm.pixel(71, 1).a == 255);
        CHECK(pm.pixel(72, 1).a == 0);
    }
}

TEST_CASE("svg dpi: outside 1 to 10000 is refused", "[svg][dpi]") {
    for (double dpi : {0.0, 0.5, -96.0, 10001.0}) {
        INFO(dpi);
        try {
            at_dpi(kInches, dpi);
            FAIL("no error");
        } catch (const Error& e) { CHECK(e.kind() == ErrorKind::InvalidArgument); }
    }
    CHECK(at_dpi(kInches, 1).width() == 1);
    CHECK(at_dpi(kInches, 10000).width() == 10000);
}
