// The PNG encoder of the default filters (src/formats/png_direct.cpp) against libpng: the same
// chunks and, once inflated, the same filtered rows (the streaming path: the same bytes) for every
// colour type, for images small enough that libpng shrinks the zlib window, one pixel wide or high
// (no Paeth), at every deflate level, on every SIMD target the Paeth filter is compiled for
// (src/formats/png_paeth.cpp), and for the golden pictures.
#include <zlib.h>

#include <catch2/catch.hpp>

#include <algorithm>
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

std::uint32_t read32(const std::uint8_t* b) {
    return std::uint32_t{b[0]} << 24 | std::uint32_t{b[1]} << 16 | std::uint32_t{b[2]} << 8 | b[3];
}

// A PNG file taken apart: every chunk but IDAT as it is (type and data), and the IDAT data joined.
struct Chunks {
    std::vector<std::vector<std::uint8_t>> others;
    std::vector<std::uint8_t> idat;
    std::size_t largest_idat = 0;
};

Chunks chunks_of(const std::vector<std::uint8_t>& file) {
    Chunks c;
    for (std::size_t at = 8; at + 12 <= file.size();) {
        const std::size_t n = read32(&file[at]);
        const std::uint8_t* type = &file[at + 4];
        if (std::string(type, type + 4) == "IDAT") {
            c.idat.insert(c.idat.end(), type + 4, type + 4 + n);
            c.largest_idat = std::max(c.largest_idat, n);
        } else {
            c.others.emplace_back(type, type + 4 + n + 4);  // type, data and CRC
        }
        at += 12 + n;
    }
    return c;
}

// The zlib stream `z` inflated (empty when it is not a complete, valid stream).
std::vector<std::uint8_t> inflated(const std::vector<std::uint8_t>& z) {
    std::vector<std::uint8_t> out(1 << 16);
    z_stream s{};
    if (inflateInit(&s) != Z_OK) return {};
    s.next_in = const_cast<Bytef*>(z.data());
    s.avail_in = static_cast<uInt>(z.size());
    int ret = Z_OK;
    while (ret == Z_OK) {
        if (s.total_out == out.size()) out.resize(out.size() * 2);
        s.next_out = out.data() + s.total_out;
        s.avail_out = static_cast<uInt>(out.size() - s.total_out);
        ret = inflate(&s, Z_NO_FLUSH);
    }
    out.resize(ret == Z_STREAM_END && s.avail_in == 0 ? s.total_out : 0);
    inflateEnd(&s);
    return out;
}

void same_as_libpng(const Pixmap& p, int level) {
    const int type = colour_type_of(p);
    for (const bool paeth : {false, true}) {
        INFO(p.width() << "x" << p.height() << ", colour type " << type << ", level " << level << ", Paeth " << paeth);
        const std::vector<std::uint8_t> libpng =
            png_detail::encode_png_libpng(p, type, level, paeth ? (kNone | kPaeth) : kNone);
        // Deflated in one piece by libdeflate: libpng's chunks and rows, another stream.
        const Chunks whole = chunks_of(png_detail::encode_png_direct(p, type, level, paeth));
        const Chunks want = chunks_of(libpng);
        CHECK(whole.others == want.others);
        CHECK(whole.largest_idat <= 8192);
        const std::vector<std::uint8_t> rows = inflated(whole.idat);
        CHECK(!rows.empty());
        CHECK(rows == inflated(want.idat));
        // Too large to hold filtered: zlib a row at a time, libpng's file byte for byte.
        CHECK(png_detail::encode_png_direct(p, type, level, paeth, 0) == libpng);
    }
}

}  // namespace

TEST_CASE("encode_png_direct writes libpng's rows for the default filters", "[png]") {
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

TEST_CASE("encode_png_direct writes libpng's rows for the golden pictures", "[png]") {
    int pictures = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(std::string(CASTELJAU_SOURCE_DIR) + "/golden")) {
        if (e.path().extension() != ".png") continue;
        same_as_libpng(read_png(e.path().string()), 4);
        ++pictures;
    }
    CHECK(pictures > 10);
}
