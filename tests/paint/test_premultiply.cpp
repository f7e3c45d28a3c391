// Tests for premultiplication and its inverse (src/paint/pixmap.cpp), the rule that makes PNG round
// trips of premultiplied pixmaps exact.
#include <catch2/catch.hpp>
#include <cmath>

#include "casteljau/paint.hpp"

using casteljau::Color;
using casteljau::PremulPixel;
using casteljau::premultiply;
using casteljau::unpremultiply;

TEST_CASE("premultiply is round(c * a / 255) for all 65536 (c, a) pairs", "[color]") {
    int wrong = 0;
    for (int a = 0; a < 256; ++a)
        for (int c = 0; c < 256; ++c) {
            const auto b = static_cast<std::uint8_t>(c);
            const PremulPixel p = premultiply(Color{b, b, b, static_cast<std::uint8_t>(a)});
            // c * a / 255 is never exactly half-way between integers (255 is odd), so plain
            // rounding is unambiguous.
            const int want = static_cast<int>(std::floor(c * a / 255.0 + 0.5));
            if (p.r != want || p.g != want || p.b != want || p.a != a) ++wrong;
        }
    CHECK(wrong == 0);
}

TEST_CASE("unpremultiply is round(p * 255 / a) clamped to 255, and zero for a = 0", "[color]") {
    int wrong = 0;
    for (int a = 0; a < 256; ++a)
        for (int c = 0; c < 256; ++c) {
            const auto b = static_cast<std::uint8_t>(c);
            const Color s = unpremultiply(PremulPixel{b, b, b, static_cast<std::uint8_t>(a)});
            int want = 0;
            if (a > 0) want = std::min(255, static_cast<int>(std::floor(c * 255.0 / a + 0.5)));
            if (s.r != want || s.g != want || s.b != want || s.a != a) ++wrong;
        }
    CHECK(wrong == 0);
}

TEST_CASE("premultiply(unpremultiply(p)) == p for every valid premultiplied pixel (c <= a)", "[color]") {
    // The exact rule behind lossless PNG round trips: straight = round(p * 255 / a) is within 1/2
    // of p * 255 / a, so re-premultiplying lands within a / 510 < 1/2 of p again.
    int checked = 0, wrong = 0;
    for (int a = 0; a < 256; ++a)
        for (int c = 0; c <= a; ++c) {
            const auto b = static_cast<std::uint8_t>(c);
            const PremulPixel p{b, static_cast<std::uint8_t>(a - c), static_cast<std::uint8_t>(c / 2),
                                static_cast<std::uint8_t>(a)};
            if (premultiply(unpremultiply(p)) != p) ++wrong;
            ++checked;
        }
    CHECK(checked == 256 * 257 / 2);
    CHECK(wrong == 0);
    // The other direction is lossy at low alpha, as expected: straight colours that differ can
    // share one premultiplied value.
    CHECK(premultiply(Color{100, 0, 0, 1}) == PremulPixel{0, 0, 0, 1});
    CHECK(premultiply(Color{120, 0, 0, 1}) == PremulPixel{0, 0, 0, 1});
    CHECK(premultiply(Color{130, 0, 0, 1}) == PremulPixel{1, 0, 0, 1});
    CHECK(unpremultiply(PremulPixel{1, 0, 0, 1}) == Color{255, 0, 0, 1});
    CHECK(unpremultiply(PremulPixel{1, 0, 0, 3}) == Color{85, 0, 0, 3});
    CHECK(unpremultiply(PremulPixel{64, 0, 0, 128}) == Color{128, 0, 0, 128});  // 127.5 -> 128
}
