// The PNG encoder of the default filters (src/formats/png_direct.cpp) against libpng: the same
// bytes for every colour type, for images small enough that libpng shrinks the zlib window, one
// pixel wide or high (no Paeth), at every zlib level, on every SIMD target the Paeth filter is
// compiled for (src/formats/png_paeth.cpp), and for the golden pictures.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "casteljau/png.hpp"
#include "core/simd_dispatch.hpp"
#include "formats/png_direct.hpp"
#include "formats/png_paeth.hpp"

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

TEST_CASE("The Paeth filter and its sums are the scalar formula's on every SIMD target", "[png]") {
    // Every (a, b, c) of bytes once: a the byte to the left, b above, c above-left; rows of
    // 1 to 4 bytes per pixel, with tails shorter than a vector.
    std::vector<std::uint8_t> row, prev;
    for (int a = 0; a < 256; ++a)
        for (int b = 0; b < 256; ++b)
            for (int c = 0; c < 256; c += 3) {
                row.insert(row.end(), {static_cast<std::uint8_t>(a), static_cast<std::uint8_t>(b ^ c)});
                prev.insert(prev.end(), {static_cast<std::uint8_t>(c), static_cast<std::uint8_t>(b)});
            }
    auto scalar = [&](std::size_t n, std::size_t bpp, std::vector<std::uint8_t>& out) {
        png_detail::RowSums s;
        for (std::size_t i = 0; i < n; ++i) {
            const int x = row[i], a = i >= bpp ? row[i - bpp] : 0, b = prev[i], c = i >= bpp ? prev[i - bpp] : 0;
            const int p = b - c, q = a - c;
            const int pa = std::abs(p), pb = std::abs(q), pc = std::abs(p + q);
            const int pred = (pa <= pb && pa <= pc) ? a : (pb <= pc) ? b : c;
            out[i] = static_cast<std::uint8_t>(x - pred);
            s.none += row[i] < 128 ? row[i] : 256 - row[i];
            s.paeth += out[i] < 128 ? out[i] : 256 - out[i];
        }
        return s;
    };
    for (const std::int64_t t : simd::available_targets()) {
        simd::restrict_targets(t);
        for (const std::size_t bpp : {1, 2, 3, 4})
            for (const std::size_t n : {row.size(), row.size() - 37, std::size_t{5}, std::size_t{0}}) {
                std::vector<std::uint8_t> want(n), got(n);
                const png_detail::RowSums w = scalar(n, bpp, want);
                const png_detail::RowSums g = png_detail::paeth_row(row.data(), prev.data(), n, bpp, got.data());
                INFO(simd::target_name(t) << ", " << bpp << " bytes per pixel, " << n << " bytes");
                CHECK(got == want);
                CHECK(g.none == w.none);
                CHECK(g.paeth == w.paeth);
            }
        std::mt19937 rng(11);
        same_as_libpng(picture(300, 40, 3, rng), 4);
    }
    simd::restrict_targets(0);
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
