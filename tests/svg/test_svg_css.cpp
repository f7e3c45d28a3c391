// SVG <style> sheets: selectors, specificity, !important, the cascade (presentation attribute <
// sheet < style attribute), and bad input (1 MB of garbage, deep selectors).
#include <catch2/catch.hpp>

#include <chrono>
#include <random>
#include <string>

#include "casteljau/svg.hpp"

using namespace casteljau;

namespace {
Pixmap draw(const std::string& sheet, const std::string& body) {
    return SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'><style>" + sheet +
                              "</style>" + body + "</svg>")
        .render();
}
const PremulPixel kGreen{0, 128, 0, 255};
}  // namespace

TEST_CASE("css: type, class, id, universal, attribute, descendant, child and first-child selectors", "[svg][css]") {
    const std::string rect = "<rect width='10' height='10' fill='red' ";
    CHECK(draw("rect { fill: green }", rect + "/>").pixel(5, 5) == kGreen);
    CHECK(draw(".a { fill: green }", rect + "class='b a'/>").pixel(5, 5) == kGreen);
    CHECK(draw("#r { fill: green }", rect + "id='r'/>").pixel(5, 5) == kGreen);
    CHECK(draw("* { fill: green }", rect + "/>").pixel(5, 5) == kGreen);
    CHECK(draw("[data-x='1'] { fill: green }", rect + "data-x='1'/>").pixel(5, 5) == kGreen);
    CHECK(draw("g rect { fill: green }", "<g><g>" + rect + "/></g></g>").pixel(5, 5) == kGreen);
    CHECK(draw("svg > rect { fill: green }", "<g>" + rect + "/></g>").pixel(5, 5) == PremulPixel{255, 0, 0, 255});
    CHECK(draw("g > rect:first-child { fill: green }", "<g>" + rect + "/><circle r='1'/></g>").pixel(5, 5) == kGreen);
    CHECK(draw("circle, rect { fill: green }", rect + "/>").pixel(5, 5) == kGreen);
    // An unsupported selector drops only itself.
    CHECK(draw("rect:hover, rect::x { fill: blue } rect { fill: green }", rect + "/>").pixel(5, 5) == kGreen);
}

TEST_CASE("css: specificity, order, !important and the cascade with attributes", "[svg][css]") {
    const std::string rect = "<rect id='r' class='c' width='10' height='10' ";
    // Higher specificity wins over later order.
    CHECK(draw("#r { fill: green } .c { fill: red } rect { fill: blue }", rect + "/>").pixel(5, 5) == kGreen);
    // The sheet beats the presentation attribute; the style attribute beats the sheet.
    CHECK(draw("rect { fill: green }", rect + "fill='red'/>").pixel(5, 5) == kGreen);
    CHECK(draw("rect { fill: red }", rect + "style='fill: green'/>").pixel(5, 5) == kGreen);
    // !important in the sheet beats the style attribute.
    CHECK(draw("rect { fill: green !important }", rect + "style='fill: red'/>").pixel(5, 5) == kGreen);
    // Inheritance through groups, and inherit / currentColor.
    CHECK(draw("g { fill: green }", "<g><rect width='10' height='10'/></g>").pixel(5, 5) == kGreen);
    CHECK(draw("g { color: green } rect { fill: currentColor }", "<g><rect width='10' height='10'/></g>").pixel(5, 5) ==
          kGreen);
}

TEST_CASE("css: a style sheet of 1 MB of garbage is read without error or hang", "[svg][css][bad-input]") {
    std::mt19937 rng(12345);
    const std::string alphabet = "{}[]()<>:;,.#*>~^$|=!@ \n\t\"'abcdefgrect-_0123456789/";
    std::string garbage;
    garbage.reserve(1 << 20);
    while (garbage.size() < (1u << 20)) {
        const char c = alphabet[rng() % alphabet.size()];
        if (c == '<') continue;  // stay inside the <style> text
        garbage += c;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const Pixmap pm = draw(garbage, "<rect width='10' height='10' fill='green'/>");
    CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(30));
    CHECK(pm.width() == 10);
    // A long chain of descendant selectors on a deep tree stays bounded.
    std::string sel;
    for (int i = 0; i < 30; ++i) sel += "g ";
    std::string body;
    for (int i = 0; i < 60; ++i) body += "<g>";
    body += "<rect width='10' height='10' fill='green'/>";
    for (int i = 0; i < 60; ++i) body += "</g>";
    CHECK(draw(sel + "circle { fill: red }", body).pixel(5, 5) == kGreen);
}

TEST_CASE("css: rules past the 10,000th are ignored with a warning", "[svg][css][bad-input][limits]") {
    // 10,000 rules that do not match, then one that would paint the rect red: it is past the limit.
    std::string sheet;
    for (int i = 0; i < 10000; ++i) sheet += ".c" + std::to_string(i) + "{fill:blue}";
    const std::string tail = "rect{fill:red}";
    const SvgDocument doc =
        SvgDocument::parse("<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'><style>" + sheet + tail +
                           "</style><rect width='10' height='10' fill='green'/></svg>");
    bool warned = false;
    for (const std::string& w : doc.warnings()) warned = warned || w.find("more than 10000 rules") != std::string::npos;
    CHECK(warned);
    CHECK(doc.render().pixel(5, 5) == kGreen);
    // One rule fewer and the last rule applies.
    std::string fewer;
    for (int i = 0; i < 9999; ++i) fewer += ".c" + std::to_string(i) + "{fill:blue}";
    CHECK(draw(fewer + tail, "<rect width='10' height='10' fill='green'/>").pixel(5, 5) == PremulPixel{255, 0, 0, 255});
}

TEST_CASE("css: mix-blend-mode and isolation are set by CSS only, not as presentation attributes", "[svg][css]") {
    // Red multiplied onto opaque green (0, 128, 0) is black; drawn normally it stays red.
    const std::string green = "<rect width='10' height='10' fill='green'/>";
    const PremulPixel red{255, 0, 0, 255}, black{0, 0, 0, 255};
    CHECK(draw("", green + "<rect width='10' height='10' fill='red' mix-blend-mode='multiply'/>").pixel(5, 5) == red);
    CHECK(draw("", green + "<rect width='10' height='10' fill='red' style='mix-blend-mode: multiply'/>").pixel(5, 5) ==
          black);
    CHECK(draw(".m { mix-blend-mode: multiply }", green + "<rect width='10' height='10' fill='red' class='m'/>")
              .pixel(5, 5) == black);
    // An isolated group gives its multiplying child a transparent backdrop: the red stays red.
    const std::string child = "><rect width='10' height='10' fill='red' style='mix-blend-mode: multiply'/></g>";
    CHECK(draw("", green + "<g isolation='isolate'" + child).pixel(5, 5) == black);
    CHECK(draw("", green + "<g style='isolation: isolate'" + child).pixel(5, 5) == red);
}
