// Tests for CSS colour parsing (src/paint/color.cpp) and the named-colour table
// (src/paint/named_colors.cpp).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/paint.hpp"
#include "paint/named_colors.hpp"
#include "skip.hpp"

using casteljau::Color;
using casteljau::Error;
using casteljau::ErrorKind;
using casteljau::parse_color;

namespace {

Color rgba(int r, int g, int b, int a = 255) {
    return Color::rgba(static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g), static_cast<std::uint8_t>(b),
                       static_cast<std::uint8_t>(a));
}

// The message of the Error(Parse) that parse_color(text) throws; fails the test when it does not.
std::string parse_error(std::string_view text) {
    try {
        const Color c = parse_color(text);
        FAIL_CHECK("parse_color('" << std::string(text) << "') did not throw; it returned rgba(" << int(c.r) << ","
                                   << int(c.g) << "," << int(c.b) << "," << int(c.a) << ")");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Parse);
        return e.what();
    }
    return {};
}

std::string upper(std::string s) {
    for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

namespace Catch {
template <>
struct StringMaker<Color> {
    static std::string convert(const Color& c) {
        std::ostringstream os;
        os << "rgba(" << int(c.r) << "," << int(c.g) << "," << int(c.b) << "," << int(c.a) << ")";
        return os.str();
    }
};
}  // namespace Catch

TEST_CASE("parse_color: hex forms #rgb #rgba #rrggbb #rrggbbaa in any case", "[color]") {
    CHECK(parse_color("#000") == rgba(0, 0, 0));
    CHECK(parse_color("#fff") == rgba(255, 255, 255));
    CHECK(parse_color("#f80") == rgba(0xff, 0x88, 0x00));
    CHECK(parse_color("#F80") == rgba(0xff, 0x88, 0x00));
    CHECK(parse_color("#1234") == rgba(0x11, 0x22, 0x33, 0x44));
    CHECK(parse_color("#0a0B0c") == rgba(10, 11, 12));
    CHECK(parse_color("#FFA07A") == rgba(255, 160, 122));
    CHECK(parse_color("#12345678") == rgba(0x12, 0x34, 0x56, 0x78));
    CHECK(parse_color("#abcdef80") == rgba(0xab, 0xcd, 0xef, 0x80));
    CHECK(parse_color("#ABCDEF00") == rgba(0xab, 0xcd, 0xef, 0));
}

TEST_CASE("parse_color: malformed hex colours are Parse errors that say why", "[color]") {
    CHECK_THAT(parse_error("#"), Catch::Contains("3, 4, 6 or 8 hex digits"));
    CHECK_THAT(parse_error("#12"), Catch::Contains("got 2"));
    CHECK_THAT(parse_error("#12345"), Catch::Contains("3, 4, 6 or 8 hex digits"));
    CHECK_THAT(parse_error("#1234567"), Catch::Contains("3, 4, 6 or 8 hex digits"));
    CHECK_THAT(parse_error("#123456789"), Catch::Contains("3, 4, 6 or 8 hex digits"));
    CHECK_THAT(parse_error("#ggg"), Catch::Contains("'g' is not a hex digit"));
    CHECK_THAT(parse_error("#12 345"), Catch::Contains("' ' is not a hex digit"));
    CHECK_THAT(parse_error("##fff"), Catch::Contains("'#' is not a hex digit"));
    CHECK_THAT(parse_error("#-12"), Catch::StartsWith("invalid colour '#-12': "));
}

TEST_CASE("parse_color: rgb() with numbers, legacy comma syntax", "[color]") {
    CHECK(parse_color("rgb(0,0,0)") == rgba(0, 0, 0));
    CHECK(parse_color("rgb(255, 128, 7)") == rgba(255, 128, 7));
    CHECK(parse_color("rgb( 1 ,2 , 3 )") == rgba(1, 2, 3));
    CHECK(parse_color("RGB(10,20,30)") == rgba(10, 20, 30));
    CHECK(parse_color("rgba(10,20,30)") == rgba(10, 20, 30));
    CHECK(parse_color("rgba(10, 20, 30, 0.5)") == rgba(10, 20, 30, 128));
    CHECK(parse_color("rgb(10, 20, 30, 0.25)") == rgba(10, 20, 30, 64));  // 63.75 -> 64
    CHECK(parse_color("rgba(10, 20, 30, 50%)") == rgba(10, 20, 30, 128));
    CHECK(parse_color("rgba(10, 20, 30, 0)") == rgba(10, 20, 30, 0));
    CHECK(parse_color("rgba(10, 20, 30, 1)") == rgba(10, 20, 30, 255));
    CHECK(parse_color("rgba(10, 20, 30, .1)") == rgba(10, 20, 30, 26));  // 25.5 -> 26
    CHECK(parse_color("rgb(1e2, 2.5e1, +0)") == rgba(100, 25, 0));
    CHECK(parse_color("rgb(1E2, 25E-1, .5)") == rgba(100, 3, 1));  // 2.5 -> 3, 0.5 -> 1 (half up)
}

TEST_CASE("parse_color: rgb() numbers and percentages round half up and clamp like CSS", "[color]") {
    // Percentages map to p * 255 / 100, rounded half up.
    CHECK(parse_color("rgb(50%, 50%, 50%)") == rgba(128, 128, 128));
    CHECK(parse_color("rgb(0%, 100%, 10%)") == rgba(0, 255, 26));  // 25.5 -> 26
    CHECK(parse_color("rgb(20%, 40%, 60%)") == rgba(51, 102, 153));
    CHECK(parse_color("rgb(33.3333%, 66.6667%, 1%)") == rgba(85, 170, 3));  // 2.55 -> 3
    // Non-integer numbers are rounded half up too.
    CHECK(parse_color("rgb(127.5, 127.49, 0.5)") == rgba(128, 127, 1));
    // Out-of-range values are clamped, not rejected.
    CHECK(parse_color("rgb(300, -20, 256)") == rgba(255, 0, 255));
    CHECK(parse_color("rgb(150%, -5%, 100.1%)") == rgba(255, 0, 255));
    CHECK(parse_color("rgba(1, 2, 3, 2)") == rgba(1, 2, 3, 255));
    CHECK(parse_color("rgba(1, 2, 3, -1)") == rgba(1, 2, 3, 0));
    CHECK(parse_color("rgba(1, 2, 3, 250%)") == rgba(1, 2, 3, 255));
    CHECK(parse_color("rgb(1e30, -1e30, 0)") == rgba(255, 0, 0));
}

TEST_CASE("parse_color: rgb() in the CSS Color 4 space syntax with optional / alpha", "[color]") {
    CHECK(parse_color("rgb(255 0 0)") == rgba(255, 0, 0));
    CHECK(parse_color("rgb(255 0 0 / 0.5)") == rgba(255, 0, 0, 128));
    CHECK(parse_color("rgb(255 0 0/50%)") == rgba(255, 0, 0, 128));
    CHECK(parse_color("rgba(  0   128   255   /   1  )") == rgba(0, 128, 255, 255));
    CHECK(parse_color("rgb(100% 50% 0 / 25%)") == rgba(255, 128, 0, 64));  // mixing allowed here
    CHECK(parse_color("rgb(\t1\n2\r3\f)") == rgba(1, 2, 3));
}

TEST_CASE("parse_color: malformed rgb() is a Parse error naming the problem", "[color]") {
    CHECK_THAT(parse_error("rgb(1, 50%, 3)"), Catch::Contains("all three components as numbers or all as percentages"));
    CHECK_THAT(parse_error("rgb(1,2)"), Catch::Contains("needs 3 components"));
    CHECK_THAT(parse_error("rgb(1 2)"), Catch::Contains("needs 3 components"));
    CHECK_THAT(parse_error("rgb(1,2,3,4,5)"), Catch::Contains("3 components and an optional alpha"));
    CHECK_THAT(parse_error("rgb(1 2 3 4)"), Catch::Contains("3 components and an optional alpha"));
    CHECK_THAT(parse_error("rgb(1 2 3, 0.5)"), Catch::Contains("commas cannot be mixed"));
    CHECK_THAT(parse_error("rgb(1 2, 3)"), Catch::Contains("commas cannot be mixed"));
    CHECK_THAT(parse_error("rgb(1, 2, 3 / 0.5)"), Catch::Contains("'/' cannot be mixed with commas"));
    CHECK_THAT(parse_error("rgb(1 2 / 0.5)"), Catch::Contains("3 components before '/'"));
    CHECK_THAT(parse_error("rgb(1 2 3 /)"), Catch::Contains("missing alpha"));
    CHECK_THAT(parse_error("rgb(1,2,3,)"), Catch::Contains("missing alpha"));
    CHECK_THAT(parse_error("rgb(1px 2 3)"), Catch::Contains("unit 'px'"));
    CHECK_THAT(parse_error("rgb(1 2 3 / 1deg)"), Catch::Contains("alpha must be a number or a percentage"));
    CHECK_THAT(parse_error("rgb(1 2 3"), Catch::Contains("missing ')'"));
    CHECK_THAT(parse_error("rgb(1 2 3) x"), Catch::Contains("missing ')'"));
    CHECK_THAT(parse_error("rgb()"), Catch::Contains("missing the first component"));
    CHECK_THAT(parse_error("rgb(none 2 3)"), Catch::Contains("'none' keyword"));
    CHECK_THAT(parse_error("rgb(a, b, c)"), Catch::Contains("expected a number for the first component, got 'a'"));
    CHECK_THAT(parse_error("rgb(1., 2, 3)"), Catch::Contains("got '.'"));
    CHECK_THAT(parse_error("rgb(1, 2, 1e999)"), Catch::Contains("out of range"));
    CHECK_THAT(parse_error("rgb (1,2,3)"), Catch::Contains("expected #rgb, #rrggbb, rgb(...), hsl(...)"));
    CHECK_THAT(parse_error("rgbx(1,2,3)"), Catch::Contains("unsupported colour function 'rgbx()'"));
    CHECK_THAT(parse_error("lab(50% 0 0)"), Catch::Contains("unsupported colour function 'lab()'"));
}

TEST_CASE("parse_color: hsl() and hsla() with hue units", "[color]") {
    // Expected values of the non-trivial cases come from Python 3.11's colorsys.hls_to_rgb (an
    // independent implementation), scaled by 255 and rounded half up.
    CHECK(parse_color("hsl(0, 100%, 50%)") == rgba(255, 0, 0));
    CHECK(parse_color("hsl(120, 100%, 25%)") == rgba(0, 128, 0));  // = CSS "green"
    CHECK(parse_color("hsl(240 100% 50%)") == rgba(0, 0, 255));
    CHECK(parse_color("hsl(210, 50%, 40%)") == rgba(51, 102, 153));
    CHECK(parse_color("hsl(270, 50%, 40%)") == rgba(102, 51, 153));  // = CSS "rebeccapurple"
    CHECK(parse_color("hsl(30, 80%, 60%)") == rgba(235, 153, 71));
    CHECK(parse_color("hsl(330, 25%, 75%)") == rgba(207, 175, 191));
    CHECK(parse_color("hsl(45, 100%, 50%)") == rgba(255, 191, 0));
    CHECK(parse_color("hsl(200, 60%, 90%)") == rgba(214, 235, 245));
    CHECK(parse_color("hsl(15, 40%, 10%)") == rgba(36, 20, 15));
    CHECK(parse_color("hsl(0, 0%, 50%)") == rgba(128, 128, 128));
    CHECK(parse_color("hsl(77, 0%, 100%)") == rgba(255, 255, 255));
    CHECK(parse_color("hsl(77, 100%, 0%)") == rgba(0, 0, 0));
    // Units: deg (the default), rad, grad, turn, in any case.
    CHECK(parse_color("hsl(60deg, 100%, 50%)") == rgba(255, 255, 0));
    CHECK(parse_color("hsl(0.5turn 100% 50%)") == rgba(0, 255, 255));
    CHECK(parse_color("hsl(200grad 100% 50%)") == rgba(0, 255, 255));
    CHECK(parse_color("hsl(3.141592653589793rad 100% 50%)") == rgba(0, 255, 255));
    CHECK(parse_color("hsl(300DEG 100% 50%)") == rgba(255, 0, 255));
    CHECK(parse_color("hsl(1TURN 100% 50%)") == rgba(255, 0, 0));
    // The hue wraps around; saturation and lightness clamp.
    CHECK(parse_color("hsl(-120, 100%, 50%)") == rgba(0, 0, 255));
    CHECK(parse_color("hsl(480, 100%, 50%)") == rgba(0, 255, 0));
    CHECK(parse_color("hsl(-1.5turn 100% 50%)") == rgba(0, 255, 255));
    CHECK(parse_color("hsl(0, 150%, 50%)") == rgba(255, 0, 0));
    CHECK(parse_color("hsl(0, 100%, -10%)") == rgba(0, 0, 0));
    // Alpha, both syntaxes; hsla is an alias of hsl.
    CHECK(parse_color("hsla(120, 100%, 50%, 0.5)") == rgba(0, 255, 0, 128));
    CHECK(parse_color("hsl(120, 100%, 50%, 50%)") == rgba(0, 255, 0, 128));
    CHECK(parse_color("hsla(120 100% 50% / 0.25)") == rgba(0, 255, 0, 64));
    CHECK(parse_color("HSL(120 100% 50%)") == rgba(0, 255, 0));
    // The space syntax accepts plain numbers for saturation and lightness (CSS Color 4).
    CHECK(parse_color("hsl(210 50 40)") == rgba(51, 102, 153));
}

TEST_CASE("parse_color: hsl() agrees with the CSS Color 3 hue-to-rgb algorithm on a grid", "[color]") {
    // A differential check: CSS Color 3 section 4.2.4 (m1/m2 and hue_to_rgb) is a different
    // formulation of the same conversion than the CSS Color 4 one the parser uses.
    auto hue_to_rgb = [](double m1, double m2, double h) {
        if (h < 0) h += 1;
        if (h > 1) h -= 1;
        if (h * 6 < 1) return m1 + (m2 - m1) * h * 6;
        if (h * 2 < 1) return m2;
        if (h * 3 < 2) return m1 + (m2 - m1) * (2.0 / 3.0 - h) * 6;
        return m1;
    };
    int checked = 0, exact = 0;
    for (int h = 0; h < 360; h += 7)
        for (int s = 0; s <= 100; s += 9)
            for (int l = 0; l <= 100; l += 7) {
                const double hh = h / 360.0, ss = s / 100.0, ll = l / 100.0;
                const double m2 = ll <= 0.5 ? ll * (ss + 1) : ll + ss - ll * ss;
                const double m1 = ll * 2 - m2;
                const double ref[3] = {hue_to_rgb(m1, m2, hh + 1.0 / 3.0), hue_to_rgb(m1, m2, hh),
                                       hue_to_rgb(m1, m2, hh - 1.0 / 3.0)};
                const Color c = parse_color("hsl(" + std::to_string(h) + ", " + std::to_string(s) + "%, " +
                                            std::to_string(l) + "%)");
                const int got[3] = {c.r, c.g, c.b};
                bool all_exact = true;
                for (int i = 0; i < 3; ++i) {
                    const double want = ref[i] * 255.0;
                    // Equal to the rounded reference, except that a value within 1e-9 of a .5 tie
                    // may round either way between the two formulations.
                    const double diff = std::abs(got[i] - want);
                    INFO("hsl(" << h << ", " << s << "%, " << l << "%) channel " << i << ": " << got[i] << " vs "
                                << want);
                    CHECK(diff <= 0.5 + 1e-9);
                    all_exact = all_exact && got[i] == static_cast<int>(std::floor(want + 0.5));
                }
                ++checked;
                exact += all_exact ? 1 : 0;
                CHECK(c.a == 255);
            }
    CHECK(checked > 1000);
    CHECK(exact > checked * 99 / 100);
}

TEST_CASE("parse_color: malformed hsl() is a Parse error naming the problem", "[color]") {
    CHECK_THAT(parse_error("hsl(10%, 50%, 50%)"), Catch::Contains("hue of hsl() cannot be a percentage"));
    CHECK_THAT(parse_error("hsl(10px, 50%, 50%)"), Catch::Contains("unknown hue unit 'px'"));
    CHECK_THAT(parse_error("hsl(10, 50, 50)"), Catch::Contains("with commas needs the saturation as a percentage"));
    CHECK_THAT(parse_error("hsl(10, 50%, 50)"), Catch::Contains("lightness as a percentage"));
    CHECK_THAT(parse_error("hsl(10 50deg 50%)"), Catch::Contains("saturation must be a percentage"));
    CHECK_THAT(parse_error("hsl(10, 50%)"), Catch::Contains("needs 3 components"));
    CHECK_THAT(parse_error("hsla(10 50% 50% 0.5)"), Catch::Contains("3 components and an optional alpha"));
    CHECK_THAT(parse_error("hsl(1e999, 50%, 50%)"), Catch::Contains("out of range"));
}

TEST_CASE("named colour table: 148 sorted, unique, lower-case names", "[color]") {
    const auto table = casteljau::detail::named_colors();
    REQUIRE(table.size() == 148);
    for (std::size_t i = 0; i < table.size(); ++i) {
        INFO(std::string(table[i].name));
        CHECK(table[i].rgb <= 0xffffffu);
        for (char c : table[i].name) CHECK((c >= 'a' && c <= 'z'));
        if (i > 0) CHECK(table[i - 1].name < table[i].name);  // sorted and unique
    }
    // Every entry is found by parse_color, in any case, with leading/trailing whitespace.
    for (const auto& e : table) {
        const Color want = rgba(int(e.rgb >> 16), int((e.rgb >> 8) & 0xff), int(e.rgb & 0xff));
        const std::string name(e.name);
        INFO(name);
        CHECK(parse_color(name) == want);
        CHECK(parse_color(upper(name)) == want);
        CHECK(parse_color("  " + name + "\t\n") == want);
    }
}

TEST_CASE("named colours have their CSS values", "[color]") {
    // Expected values typed from CSS Color Module Level 4, section 6.1, and checked against Free
    // Pascal's independent table (Debian 12: /usr/share/fpcsrc/3.2.2/packages/rtl-objpas/src/inc/
    // system.uitypes.pp), which agrees on all of them.
    const std::pair<const char*, Color> cases[] = {
        {"aliceblue", rgba(240, 248, 255)},
        {"antiquewhite", rgba(250, 235, 215)},
        {"aqua", rgba(0, 255, 255)},
        {"black", rgba(0, 0, 0)},
        {"blanchedalmond", rgba(255, 235, 205)},
        {"blue", rgba(0, 0, 255)},
        {"burlywood", rgba(222, 184, 135)},
        {"chartreuse", rgba(127, 255, 0)},
        {"cornflowerblue", rgba(100, 149, 237)},
        {"crimson", rgba(220, 20, 60)},
        {"cyan", rgba(0, 255, 255)},
        {"darkgoldenrod", rgba(184, 134, 11)},
        {"darkgray", rgba(169, 169, 169)},
        {"darkgrey", rgba(169, 169, 169)},
        {"darkolivegreen", rgba(85, 107, 47)},
        {"darkslategray", rgba(47, 79, 79)},
        {"deeppink", rgba(255, 20, 147)},
        {"dodgerblue", rgba(30, 144, 255)},
        {"fuchsia", rgba(255, 0, 255)},
        {"gainsboro", rgba(220, 220, 220)},
        {"gold", rgba(255, 215, 0)},
        {"gray", rgba(128, 128, 128)},
        {"grey", rgba(128, 128, 128)},
        {"green", rgba(0, 128, 0)},
        {"greenyellow", rgba(173, 255, 47)},
        {"hotpink", rgba(255, 105, 180)},
        {"indigo", rgba(75, 0, 130)},
        {"lavenderblush", rgba(255, 240, 245)},
        {"lightgoldenrodyellow", rgba(250, 250, 210)},
        {"lightslategrey", rgba(119, 136, 153)},
        {"lime", rgba(0, 255, 0)},
        {"magenta", rgba(255, 0, 255)},
        {"maroon", rgba(128, 0, 0)},
        {"mediumvioletred", rgba(199, 21, 133)},
        {"navajowhite", rgba(255, 222, 173)},
        {"navy", rgba(0, 0, 128)},
        {"olive", rgba(128, 128, 0)},
        {"orange", rgba(255, 165, 0)},
        {"orangered", rgba(255, 69, 0)},
        {"papayawhip", rgba(255, 239, 213)},
        {"peru", rgba(205, 133, 63)},
        {"purple", rgba(128, 0, 128)},
        {"rebeccapurple", rgba(102, 51, 153)},
        {"red", rgba(255, 0, 0)},
        {"saddlebrown", rgba(139, 69, 19)},
        {"silver", rgba(192, 192, 192)},
        {"steelblue", rgba(70, 130, 180)},
        {"teal", rgba(0, 128, 128)},
        {"tomato", rgba(255, 99, 71)},
        {"white", rgba(255, 255, 255)},
        {"whitesmoke", rgba(245, 245, 245)},
        {"yellow", rgba(255, 255, 0)},
        {"yellowgreen", rgba(154, 205, 50)},
    };
    for (const auto& [name, want] : cases) {
        INFO(name);
        CHECK(parse_color(name) == want);
    }
    CHECK(parse_color("RebeccaPurple") == rgba(102, 51, 153));
    CHECK(parse_color("LightGoldenRodYellow") == rgba(250, 250, 210));
}

TEST_CASE("named colours agree with X11 rgb.txt except where CSS and X11 differ by design", "[color]") {
    // Independent source: Debian's /usr/share/X11/rgb.txt (package x11-common). CSS took most names
    // from X11, but gray/grey, green, maroon and purple have different values in CSS, and nine CSS
    // names are not X11 colours at all.
    std::ifstream in("/usr/share/X11/rgb.txt");
    if (!in) CASTELJAU_SKIP("/usr/share/X11/rgb.txt is absent (install x11-common to run this comparison)");
    std::map<std::string, std::uint32_t> x11;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '!') continue;
        std::istringstream ls(line);
        unsigned r = 0, g = 0, b = 0;
        if (!(ls >> r >> g >> b)) continue;
        std::string name, word;
        while (ls >> word) name += word;  // "alice blue" -> "aliceblue"
        for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        x11.emplace(name, (r << 16) | (g << 8) | b);  // first spelling wins
    }
    REQUIRE(x11.size() > 500);
    std::vector<std::string> differ, missing;
    int agree = 0;
    for (const auto& e : casteljau::detail::named_colors()) {
        const auto it = x11.find(std::string(e.name));
        if (it == x11.end()) {
            missing.emplace_back(e.name);
        } else if (it->second != e.rgb) {
            differ.emplace_back(e.name);
        } else {
            ++agree;
        }
    }
    CHECK(agree == 134);
    CHECK(differ == std::vector<std::string>{"gray", "green", "grey", "maroon", "purple"});
    CHECK(missing == std::vector<std::string>{"aqua", "crimson", "fuchsia", "indigo", "lime", "olive", "rebeccapurple",
                                              "silver", "teal"});
}

TEST_CASE("parse_color: transparent, none, whitespace, unknown names, currentColor", "[color]") {
    CHECK(parse_color("transparent") == rgba(0, 0, 0, 0));
    CHECK(parse_color("TRANSPARENT") == rgba(0, 0, 0, 0));
    CHECK(parse_color("none") == rgba(0, 0, 0, 0));
    CHECK(parse_color(" None ") == rgba(0, 0, 0, 0));
    CHECK(parse_color("\t#fff\n") == rgba(255, 255, 255));
    CHECK(parse_color("  rgb(1,2,3)  ") == rgba(1, 2, 3));

    CHECK(parse_error("xyz") ==
          "invalid colour 'xyz': expected #rgb, #rrggbb, rgb(...), hsl(...) or a CSS colour name");
    CHECK(parse_error("reds") ==
          "invalid colour 'reds': expected #rgb, #rrggbb, rgb(...), hsl(...) or a CSS colour name");
    CHECK_THAT(parse_error("light blue"), Catch::Contains("expected #rgb"));
    CHECK_THAT(parse_error(""), Catch::StartsWith("invalid colour '': empty text"));
    CHECK_THAT(parse_error("   "), Catch::Contains("empty text"));
    CHECK_THAT(parse_error("currentColor"), Catch::Contains("currentColor is not supported here"));
    CHECK_THAT(parse_error("currentcolor"), Catch::Contains("currentColor is not supported here"));
    CHECK_THAT(parse_error(std::string_view("re\0d", 4)), Catch::StartsWith("invalid colour 're?d'"));
    // Long input is shortened in the message so that it stays one line.
    const std::string long_text(1000, 'q');
    const std::string msg = parse_error(long_text);
    CHECK(msg.size() < 200);
    CHECK_THAT(msg, Catch::Contains("qqq...'"));
    CHECK_THAT(parse_error("red\nblue"), Catch::StartsWith("invalid colour 'red?blue'"));
}
