// The PNG encoder of the default filters (src/formats/png_direct.cpp) against libpng: the same
// bytes for every colour type, for images small enough that libpng shrinks the zlib window, one
// pixel wide or high (no Paeth), at every zlib level, and for the golden pictures.
#include <catch2/catch.hpp>

#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "casteljau/png.hpp"
#include "formats/png_direct.hpp"

using namespace casteljau;

namespace {

constexpr int kNone = 0x08, kPaeth = 0x80;  // libpng's PNG_FILTER_NONE and PNG_FILTER_PAETH

// A premultiplied picture of one of six kinds: smooth grey, noise, translucent grey, translucent
// noise, colour gradients, an alpha ramp.
Pixmap picture(int w, int h, int kind, std::mt19937& rng) {
    Pixmap p(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* q = p.row(y) + 4 * x;
            const unsigned r = rng();
            const int a = kind <= 1 ? 255 : kind == 5 ? (x * 7 + y) & 255 : static_cast<int>(r >> 24);
            const int g = (x * 3 + y * 5) & 255;
            int c[3] = {g, g, g};
            if (kind == 1 || kind == 3) c[0] = r & 255, c[1] = (r >> 8) & 255, c[2] = (r >> 16) & 255;
            if (kind == 4) c[0] = g, c[1] = 255 - g, c[2] = (x * y) & 255;
            for (int k = 0; k < 3; ++k) q[k] = static_cast<std::uint8_t>(c[k] * a / 255);
            q[3] = static_cast<std::uint8_t>(a);
        }
    return p;
}

// The colour type encode_png picks for `p` (byte 25 of the file: IHDR's colour type).
int colour_type_of(const Pixmap& p) { return encode_png(p)[25]; }

void same_as_libpng(const Pixmap& p, int level) {
    const int type = colour_type_of(p);
    for (const bool paeth : {false, true}) {
        INFO(p.width() << "x" << p.height() << ", colour type " << type << ", level " << level << ", Paeth " << paeth);
        CHECK(png_detail::encode_png_direct(p, type, level, paeth) ==
              png_detail::encode_png_libpng(p, type, level, paeth ? (kNone | kPaeth) : kNone));
    }
}

}  // namespace

TEST_CASE("encode_png_direct writes libpng's bytes for the default filters", "[png]") {
    std::mt19937 rng(7);
    const int sizes[][2] = {{1, 1}, {1, 7}, {7, 1}, {2, 2}, {3, 3}, {10, 10}, {50, 50}, {64, 63}, {100, 40}, {300, 90}};
    for (const auto& s : sizes)
        for (int kind = 0; kind < 6; ++kind) same_as_libpng(picture(s[0], s[1], kind, rng), 4);
    for (int level = 0; level <= 9; ++level) {
        same_as_libpng(picture(40, 30, 4, rng), level);
        same_as_libpng(picture(200, 120, 3, rng), level);
    }
}

TEST_CASE("encode_png_direct writes libpng's bytes for the golden pictures", "[png]") {
    int pictures = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(CASTELJAU_SOURCE_DIR) + "/golden")) {
        if (e.path().extension() != ".png") continue;
        same_as_libpng(read_png(e.path().string()), 4);
        ++pictures;
    }
    CHECK(pictures > 10);
}
