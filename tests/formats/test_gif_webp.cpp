// GIF and WebP decoding (casteljau/image.hpp) against pictures made here with the libraries'
// own encoders (giflib's EGif, libwebp's lossless encoder), so every expected pixel is known:
// palettes, the transparent index, interlacing, an image placed on a larger screen, later frames
// ignored, straight alpha premultiplied; corrupt, truncated and oversized data refused.
#include <catch2/catch.hpp>

#include <gif_lib.h>
#include <webp/encode.h>

#include <cstring>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/image.hpp"

using namespace casteljau;

namespace {

int write_bytes(GifFileType* gif, const GifByteType* data, int length) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(gif->UserData);
    out->insert(out->end(), data, data + length);
    return length;
}

struct Frame {
    int left = 0, top = 0, width = 0, height = 0;
    bool interlace = false;
    int transparent = -1;          // index, or -1 for no graphic control extension
    std::vector<GifPixelType> px;  // width x height indices, row by row (in display order)
};

// A GIF of a `screen_w` x `screen_h` screen, a four-colour palette (red, green, blue, white) and
// the frames given.
std::vector<std::uint8_t> make_gif(int screen_w, int screen_h, const std::vector<Frame>& frames) {
    std::vector<std::uint8_t> out;
    int error = 0;
    GifFileType* gif = EGifOpen(&out, write_bytes, &error);
    REQUIRE(gif);
    const GifColorType colors[4] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {255, 255, 255}};
    ColorMapObject* map = GifMakeMapObject(4, colors);
    REQUIRE(EGifPutScreenDesc(gif, screen_w, screen_h, 2, 0, map) == GIF_OK);
    for (const Frame& f : frames) {
        if (f.transparent >= 0) {
            const GifByteType gce[4] = {1, 0, 0, static_cast<GifByteType>(f.transparent)};
            REQUIRE(EGifPutExtension(gif, GRAPHICS_EXT_FUNC_CODE, 4, gce) == GIF_OK);
        }
        REQUIRE(EGifPutImageDesc(gif, f.left, f.top, f.width, f.height, f.interlace, nullptr) == GIF_OK);
        // An interlaced image is written in its pass order: rows 0, 8, ..., 4, 12, ..., 2, 6, ..., 1, 3, ...
        static constexpr int kStart[4] = {0, 4, 2, 1}, kStep[4] = {8, 8, 4, 2};
        for (int pass = 0; pass < (f.interlace ? 4 : 1); ++pass)
            for (int y = f.interlace ? kStart[pass] : 0; y < f.height; y += f.interlace ? kStep[pass] : 1) {
                std::vector<GifPixelType> row(f.px.begin() + y * f.width, f.px.begin() + (y + 1) * f.width);
                REQUIRE(EGifPutLine(gif, row.data(), f.width) == GIF_OK);
            }
    }
    REQUIRE(EGifCloseFile(gif, &error) == GIF_OK);
    GifFreeMapObject(map);
    return out;
}

Frame pattern(int w, int h) {
    Frame f;
    f.width = w;
    f.height = h;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) f.px.push_back(static_cast<GifPixelType>((x + 2 * y) % 4));
    return f;
}

PremulPixel palette(int index) {
    static const PremulPixel p[4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
    return p[index];
}

}  // namespace

TEST_CASE("GIF: palette pixels, plain and interlaced, and the transparent index", "[image][gif]") {
    for (const bool interlace : {false, true}) {
        Frame f = pattern(5, 11);
        f.interlace = interlace;
        const std::vector<std::uint8_t> bytes = make_gif(5, 11, {f});
        REQUIRE(sniff_image(bytes) == ImageFormat::Gif);
        const Pixmap pm = decode_image(bytes);
        REQUIRE(pm.width() == 5);
        REQUIRE(pm.height() == 11);
        for (int y = 0; y < 11; ++y)
            for (int x = 0; x < 5; ++x) REQUIRE(pm.pixel(x, y) == palette((x + 2 * y) % 4));
    }
    Frame t = pattern(4, 3);
    t.transparent = 2;  // blue
    const Pixmap pm = decode_gif(make_gif(4, 3, {t}));
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            const int i = (x + 2 * y) % 4;
            CHECK(pm.pixel(x, y) == (i == 2 ? PremulPixel{0, 0, 0, 0} : palette(i)));
        }
}

TEST_CASE("GIF: the first image on its screen, cut at the screen's edge, later frames not drawn", "[image][gif]") {
    Frame first = pattern(4, 4);
    first.left = 6;  // two columns past the screen's right edge
    first.top = 1;
    Frame second = pattern(8, 6);  // would cover the whole screen
    const Pixmap pm = decode_gif(make_gif(8, 6, {first, second}));
    REQUIRE(pm.width() == 8);
    REQUIRE(pm.height() == 6);
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool inside = x >= 6 && y >= 1 && y < 5;
            CHECK(pm.pixel(x, y) == (inside ? palette((x - 6 + 2 * (y - 1)) % 4) : PremulPixel{0, 0, 0, 0}));
        }
}

TEST_CASE("GIF: truncated, corrupt and oversized data are errors", "[image][gif]") {
    const std::vector<std::uint8_t> bytes = make_gif(16, 16, {pattern(16, 16)});
    for (std::size_t cut : {std::size_t{6}, std::size_t{13}, bytes.size() / 2, bytes.size() - 2}) {
        const std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(cut));
        CHECK_THROWS_AS(decode_image(part), Error);
    }
    // A 16384 x 16384 screen (within the canvas limits) declared by a file of a few dozen bytes.
    std::vector<std::uint8_t> huge = make_gif(1, 1, {pattern(1, 1)});
    huge[6] = huge[8] = 0x00;
    huge[7] = huge[9] = 0x40;
    try {
        (void)decode_gif(huge);
        FAIL("an oversized screen was accepted");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::InvalidData);
        CHECK(std::string(e.what()).find("16384 x 16384") != std::string::npos);
    }
}

TEST_CASE("WebP: lossless pixels come back premultiplied, exactly", "[image][webp]") {
    const int w = 7, h = 5;
    std::vector<std::uint8_t> rgba;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t a = static_cast<std::uint8_t>(x == 0 ? 0 : 40 * x + 15);
            rgba.insert(rgba.end(), {static_cast<std::uint8_t>(30 * x), static_cast<std::uint8_t>(50 * y), 200, a});
        }
    std::uint8_t* out = nullptr;
    const std::size_t size = WebPEncodeLosslessRGBA(rgba.data(), w, h, 4 * w, &out);
    REQUIRE(size > 0);
    const std::vector<std::uint8_t> bytes(out, out + size);
    WebPFree(out);
    REQUIRE(sniff_image(bytes) == ImageFormat::Webp);
    const Pixmap pm = decode_image(bytes);
    REQUIRE(pm.width() == w);
    REQUIRE(pm.height() == h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t* s = &rgba[static_cast<std::size_t>(4 * (y * w + x))];
            const PremulPixel want = s[3] == 0 ? PremulPixel{0, 0, 0, 0} : premultiply(Color{s[0], s[1], s[2], s[3]});
            CHECK(pm.pixel(x, y) == want);
        }
    // Truncated or corrupt.
    for (std::size_t cut : {std::size_t{12}, std::size_t{20}, bytes.size() / 2}) {
        const std::vector<std::uint8_t> part(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(cut));
        CHECK_THROWS_AS(decode_image(part), Error);
    }
}
