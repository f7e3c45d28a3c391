// Tests for PNG encoding and decoding (src/formats/png.cpp): every colour type and bit depth,
// interlacing, exact round trips, and corrupt, truncated or oversized input.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/png.hpp"
#include "png_test_util.hpp"

using casteljau::Color;
using casteljau::decode_png;
using casteljau::encode_png;
using casteljau::Error;
using casteljau::ErrorKind;
using casteljau::Pixmap;
using casteljau::PngEncodeOptions;
using casteljau::PngFilter;
using casteljau::PremulPixel;
using casteljau::premultiply;
using png_test::pack;
using png_test::Spec;

namespace {

// The expected Pixmap content as straight colours, one per pixel, row-major.
void check_pixels(const Pixmap& got, png_uint_32 width, png_uint_32 height, const std::vector<Color>& straight) {
    REQUIRE(got.width() == static_cast<int>(width));
    REQUIRE(got.height() == static_cast<int>(height));
    REQUIRE(straight.size() == static_cast<std::size_t>(width) * height);
    int wrong = 0;
    for (int y = 0; y < got.height(); ++y)
        for (int x = 0; x < got.width(); ++x) {
            const Color s = straight[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)];
            const PremulPixel want = premultiply(s);
            const PremulPixel p = got.pixel(x, y);
            if (p != want) {
                if (++wrong <= 5)
                    UNSCOPED_INFO("pixel (" << x << "," << y << ") is " << int(p.r) << "," << int(p.g) << ","
                                            << int(p.b) << "," << int(p.a) << ", expected " << int(want.r) << ","
                                            << int(want.g) << "," << int(want.b) << "," << int(want.a));
            }
        }
    CHECK(wrong == 0);
}

Color grey(unsigned v, unsigned a = 255) {
    return Color{static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v), static_cast<std::uint8_t>(v),
                 static_cast<std::uint8_t>(a)};
}

// 16 -> 8 bits, rounded to nearest: round(v * 255 / 65535) (v * 255 / 65535 never ends in .5).
unsigned to8(unsigned v16) { return static_cast<unsigned>(std::floor(v16 * 255.0 / 65535.0 + 0.5)); }

ErrorKind decode_error_kind(const std::vector<std::uint8_t>& bytes, std::string* message = nullptr) {
    try {
        decode_png(bytes);
    } catch (const Error& e) {
        if (message != nullptr) *message = e.what();
        return e.kind();
    }
    FAIL("decode_png did not throw");
    return ErrorKind::InvalidArgument;
}

Pixmap random_premultiplied(int w, int h, std::uint32_t seed) {
    std::mt19937 rng(seed);
    Pixmap pm(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned kind = rng() % 8;  // bias towards the edge cases 0 and 255
            const unsigned a = kind == 0 ? 0 : kind == 1 ? 255 : kind == 2 ? 1 + rng() % 3 : rng() % 256;
            auto chan = [&] { return static_cast<std::uint8_t>(a == 0 ? 0 : rng() % (a + 1)); };
            pm.set_pixel(x, y, PremulPixel{chan(), chan(), chan(), static_cast<std::uint8_t>(a)});
        }
    return pm;
}

bool same_pixels(const Pixmap& a, const Pixmap& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    return std::equal(a.data(), a.data() + a.stride() * static_cast<std::size_t>(a.height()), b.data());
}

}  // namespace

TEST_CASE("decode_png: grey at 1, 2, 4 and 8 bits expands to opaque RGBA8", "[png]") {
    for (int depth : {1, 2, 4, 8}) {
        INFO("bit depth " << depth);
        const unsigned levels = 1u << depth;
        Spec s;
        s.color_type = PNG_COLOR_TYPE_GRAY;
        s.bit_depth = depth;
        s.width = levels + 3;  // a partly filled last byte for the sub-byte depths
        s.height = 3;
        std::vector<Color> want;
        for (png_uint_32 y = 0; y < s.height; ++y) {
            std::vector<unsigned> samples;
            for (png_uint_32 x = 0; x < s.width; ++x) {
                const unsigned v = (x + y) % levels;
                samples.push_back(v);
                want.push_back(grey(v * 255 / (levels - 1)));  // exact: 255 divisible by 1, 3, 15, 255
            }
            s.rows.push_back(pack(samples, depth));
        }
        check_pixels(decode_png(png_test::write_spec(s)), s.width, s.height, want);
    }
}

TEST_CASE("decode_png: 16-bit grey maps all 65536 values to round(v * 255 / 65535)", "[png]") {
    Spec s;
    s.color_type = PNG_COLOR_TYPE_GRAY;
    s.bit_depth = 16;
    s.width = 256;
    s.height = 256;
    std::vector<Color> want;
    for (unsigned y = 0; y < 256; ++y) {
        std::vector<unsigned> samples;
        for (unsigned x = 0; x < 256; ++x) {
            const unsigned v = y * 256 + x;
            samples.push_back(v);
            want.push_back(grey(to8(v)));
        }
        s.rows.push_back(pack(samples, 16));
    }
    check_pixels(decode_png(png_test::write_spec(s)), s.width, s.height, want);
}

TEST_CASE("decode_png: grey with tRNS, grey+alpha at 8 and 16 bits", "[png]") {
    SECTION("8-bit grey, tRNS marks grey 7 transparent") {
        Spec s;
        s.color_type = PNG_COLOR_TYPE_GRAY;
        s.width = 16;
        s.height = 2;
        s.has_trans_color = true;
        s.trans_color.gray = 7;
        std::vector<Color> want;
        for (unsigned y = 0; y < 2; ++y) {
            std::vector<unsigned> samples;
            for (unsigned x = 0; x < 16; ++x) {
                const unsigned v = x + y * 16 - (y * 16 > 0 ? 9 : 0);  // row 0: 0..15, row 1: 7..22
                samples.push_back(v);
                want.push_back(v == 7 ? Color{0, 0, 0, 0} : grey(v));
            }
            s.rows.push_back(pack(samples, 8));
        }
        check_pixels(decode_png(png_test::write_spec(s)), s.width, s.height, want);
    }
    SECTION("4-bit grey, tRNS marks grey 5 transparent") {
        Spec s;
        s.color_type = PNG_COLOR_TYPE_GRAY;
        s.bit_depth = 4;
        s.width = 16;
        s.height = 1;
        s.has_trans_color = true;
        s.trans_color.gray = 5;
        std::vector<unsigned> samples;
        std::vector<Color> want;
        for (unsigned x = 0; x < 16; ++x) {
            samples.push_back(x);
            want.push_back(x == 5 ? Color{0, 0, 0, 0} : grey(x * 17));
        }
        s.rows.push_back(pack(samples, 4));
        check_pixels(decode_png(png_test::write_spec(s)), s.width, s.height, want);
    }
    SECTION("grey+alpha 8-bit, every alpha") {
        Spec s;
        s.color_type = PNG_COLOR_TYPE_GRAY_ALPHA;
        s.width = 256;
        s.height = 4;
        std::vector<Color> want;
        for (unsigned y = 0; y < s.height; ++y) {
            std::vector<unsigned> samples;
            for (unsigned x = 0; x < 256; ++x) {
                const unsigned g = (x * 7 + y * 61) % 256;
                samples.push_back(g);
                samples.push_back(x);
                want.push_back(grey(g, x));
            }
            s.rows.push_back(pack(samples, 8));
        }
        check_pixels(decode_png(png_test::write_spec(s)), s.width, s.height, want);
    }
    SECTION("grey+alpha 16-bit") {
        Spec s;
        s.color_type = PNG_COLOR_TYPE_GRAY_ALPHA;
        s.bit_depth = 16;
        s.width = 97;
        s.height = 5;
        std::mt19937 rng(16);
        std::vector<Color> want;
        for (unsigned y = 0; y < s.height; ++y) {
            std::vector<unsigned> samples;
            for (unsigned x = 0; x < s.width; ++x) {
                const unsigned g = rng() % 65536, a = rng() % 65536;
                samples.push_back(g);
                samples.push_back(a);
                want.push_back(grey(to8(g), to8(a)));
            }
            s.rows.push_back(pack(samples, 16));
        }
        check_pixels(decode_png(png_test::write_spec(s)), s.width, s.height, want);
    }
}

TEST_CASE("decode_png: RGB and RGBA at 8 and 16 bits, RGB with tRNS", "[png]") {
    std::mt19937 rng(42);
    for (int type : {PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA})
        for (int depth : {8, 16})
            for (bool trns : {false, true}) {
                if (trns && type == PNG_COLOR_TYPE_RGB_ALPHA) continue;  // tRNS is not allowed with alpha
                INFO("colour type " << type << ", depth " << depth << ", tRNS " << trns);
                Spec s;
                s.color_type = type;
                s.bit_depth = depth;
                s.width = 33;
                s.height = 9;
                const unsigned max = depth == 16 ? 65535 : 255;
                if (trns) {
                    s.has_trans_color = true;
                    s.trans_color.red = static_cast<png_uint_16>(max / 3);
                    s.trans_color.green = static_cast<png_uint_16>(max / 5);
                    s.trans_color.blue = static_cast<png_uint_16>(max / 7);
                }
                std::vector<Color> want;
                for (unsigned y = 0; y < s.height; ++y) {
                    std::vector<unsigned> samples;
                    for (unsigned x = 0; x < s.width; ++x) {
                        auto r = [&] { return static_cast<unsigned>(rng() % (max + 1)); };
                        unsigned v[4] = {r(), r(), r(), r()};
                        if (trns && x % 4 == 0) {  // hit the transparent colour exactly
                            v[0] = max / 3;
                            v[1] = max / 5;
                            v[2] = max / 7;
                        }
                        const int n = type == PNG_COLOR_TYPE_RGB ? 3 : 4;
                        for (int i = 0; i < n; ++i) samples.push_back(v[i]);
                        auto c8 = [&](unsigned u) { return static_cast<std::uint8_t>(depth == 16 ? to8(u) : u); };
                        Color c{c8(v[0]), c8(v[1]), c8(v[2]), n == 4 ? c8(v[3]) : std::uint8_t{255}};
                        if (trns && x % 4 == 0) c = Color{0, 0, 0, 0};
                        want.push_back(c);
                    }
                    s.rows.push_back(pack(samples, depth));
                }
                check_pixels(decode_png(png_test::write_spec(s)), s.width, s.height, want);
            }
}

TEST_CASE("decode_png: palette at 1, 2, 4 and 8 bits with a partial tRNS", "[png]") {
    std::mt19937 rng(7);
    for (int depth : {1, 2, 4, 8}) {
        INFO("bit depth " << depth);
        const unsigned entries = 1u << depth;
        Spec s;
        s.color_type = PNG_COLOR_TYPE_PALETTE;
        s.bit_depth = depth;
        s.width = 2 * entries + 5;
        s.height = 3;
        std::vector<Color> pal;
        for (unsigned i = 0; i < entries; ++i) {
            const png_color c{static_cast<png_byte>(rng()), static_cast<png_byte>(rng()), static_cast<png_byte>(rng())};
            s.palette.push_back(c);
            pal.push_back(Color{c.red, c.green, c.blue, 255});
        }
        // tRNS for the first half of the entries only; the others stay opaque. Entry 0 is fully
        // transparent, entry 1 (when there is one in the tRNS) half transparent.
        for (unsigned i = 0; i < std::max(1u, entries / 2); ++i) {
            const png_byte a = i == 0 ? 0 : i == 1 ? 128 : static_cast<png_byte>(rng());
            s.trans_alpha.push_back(a);
            pal[i].a = a;
        }
        std::vector<Color> want;
        for (png_uint_32 y = 0; y < s.height; ++y) {
            std::vector<unsigned> samples;
            for (png_uint_32 x = 0; x < s.width; ++x) {
                const unsigned idx = (x + 3 * y) % entries;
                samples.push_back(idx);
                want.push_back(pal[idx]);
            }
            s.rows.push_back(pack(samples, depth));
        }
        check_pixels(decode_png(png_test::write_spec(s)), s.width, s.height, want);
    }
}

TEST_CASE("decode_png: Adam7-interlaced images decode like the same image non-interlaced", "[png]") {
    // Sizes include ones where some of the seven passes are empty (1x1, 2x1, 1x9, 5x3).
    const std::pair<png_uint_32, png_uint_32> sizes[] = {{1, 1}, {2, 1}, {1, 9}, {5, 3}, {8, 8}, {37, 23}};
    std::mt19937 rng(1234);
    for (const auto& [w, h] : sizes)
        for (int type : {PNG_COLOR_TYPE_RGB_ALPHA, PNG_COLOR_TYPE_PALETTE, PNG_COLOR_TYPE_GRAY}) {
            INFO(w << "x" << h << " colour type " << type);
            Spec s;
            s.color_type = type;
            s.bit_depth = type == PNG_COLOR_TYPE_GRAY ? 2 : 8;
            s.width = w;
            s.height = h;
            std::vector<Color> want;
            if (type == PNG_COLOR_TYPE_PALETTE) {
                for (int i = 0; i < 7; ++i)
                    s.palette.push_back(png_color{static_cast<png_byte>(rng()), static_cast<png_byte>(rng()),
                                                  static_cast<png_byte>(rng())});
                s.trans_alpha = {0, 77};
            }
            for (png_uint_32 y = 0; y < h; ++y) {
                std::vector<unsigned> samples;
                for (png_uint_32 x = 0; x < w; ++x) {
                    if (type == PNG_COLOR_TYPE_RGB_ALPHA) {
                        auto r = [&] { return static_cast<unsigned>(rng() % 256); };
                        const unsigned v[4] = {r(), r(), r(), r()};
                        samples.insert(samples.end(), v, v + 4);
                        want.push_back(Color{static_cast<std::uint8_t>(v[0]), static_cast<std::uint8_t>(v[1]),
                                             static_cast<std::uint8_t>(v[2]), static_cast<std::uint8_t>(v[3])});
                    } else if (type == PNG_COLOR_TYPE_PALETTE) {
                        const unsigned i = rng() % 7;
                        samples.push_back(i);
                        const png_color& c = s.palette[i];
                        want.push_back(Color{c.red, c.green, c.blue,
                                             static_cast<std::uint8_t>(i == 0   ? 0
                                                                       : i == 1 ? 77
                                                                                : 255)});
                    } else {
                        const unsigned g = rng() % 4;
                        samples.push_back(g);
                        want.push_back(grey(g * 85));
                    }
                }
                s.rows.push_back(pack(samples, s.bit_depth));
            }
            const Pixmap plain = decode_png(png_test::write_spec(s));
            s.interlace = true;
            const auto interlaced_bytes = png_test::write_spec(s);
            REQUIRE(interlaced_bytes[8 + 8 + 12] == 1);  // IHDR interlace method byte: Adam7
            const Pixmap interlaced = decode_png(interlaced_bytes);
            check_pixels(interlaced, w, h, want);
            CHECK(same_pixels(plain, interlaced));
        }
}

TEST_CASE("encode_png/decode_png: random premultiplied pixmaps round-trip exactly", "[png]") {
    // Exact because premultiply(unpremultiply(p)) == p for every valid premultiplied pixel
    // (tests/paint/test_premultiply.cpp checks that for all 32896 (c, a) pairs with c <= a).
    const std::pair<int, int> sizes[] = {{1, 1}, {1, 100}, {100, 1}, {61, 47}, {256, 16}};
    std::uint32_t seed = 1;
    for (const auto& [w, h] : sizes) {
        INFO(w << "x" << h << " seed " << seed);
        const Pixmap original = random_premultiplied(w, h, seed++);
        const auto bytes = encode_png(original);
        const Pixmap back = decode_png(bytes);
        CHECK(same_pixels(original, back));
    }
    // Fully transparent and fully opaque extremes.
    Pixmap clear(3, 2);
    CHECK(same_pixels(clear, decode_png(encode_png(clear))));
    Pixmap white(2, 3);
    white.fill(Color::white());
    CHECK(same_pixels(white, decode_png(encode_png(white))));
}

TEST_CASE("encode_png: 8-bit RGBA with straight alpha and an sRGB chunk, readable by stb_image", "[png]") {
    const Pixmap pm = random_premultiplied(29, 17, 99);  // translucent colour: written as RGBA
    const auto bytes = encode_png(pm);

    // Walk the chunks: IHDR first, sRGB (rendering intent 0) before IDAT, IEND last.
    REQUIRE(bytes.size() > 8 + 25 + 12);
    REQUIRE(png_sig_cmp(bytes.data(), 0, 8) == 0);
    std::vector<std::string> order;
    std::size_t pos = 8;
    auto be32 = [&](std::size_t at) {
        return (std::uint32_t(bytes[at]) << 24) | (std::uint32_t(bytes[at + 1]) << 16) |
               (std::uint32_t(bytes[at + 2]) << 8) | std::uint32_t(bytes[at + 3]);
    };
    while (pos + 12 <= bytes.size()) {
        const std::uint32_t len = be32(pos);
        const std::string type(reinterpret_cast<const char*>(&bytes[pos + 4]), 4);
        if (order.empty() || order.back() != type) order.push_back(type);
        if (type == "IHDR") {
            CHECK(be32(pos + 8) == 29);
            CHECK(be32(pos + 12) == 17);
            CHECK(bytes[pos + 16] == 8);  // bit depth
            CHECK(bytes[pos + 17] == 6);  // colour type RGBA
            CHECK(bytes[pos + 20] == 0);  // not interlaced
        }
        if (type == "sRGB") {
            CHECK(len == 1);
            CHECK(bytes[pos + 8] == 0);  // perceptual
        }
        pos += 12 + len;
    }
    CHECK(pos == bytes.size());
    REQUIRE(order.size() >= 4);
    CHECK(order.front() == "IHDR");
    CHECK(order.back() == "IEND");
    const auto srgb = std::find(order.begin(), order.end(), "sRGB");
    const auto idat = std::find(order.begin(), order.end(), "IDAT");
    CHECK(srgb < idat);
    CHECK(idat != order.end());

    // An independent decoder sees the straight-alpha values.
    int w = 0, h = 0;
    const auto rgba = png_test::stb_decode_rgba8(bytes, w, h);
    REQUIRE(w == 29);
    REQUIRE(h == 17);
    int wrong = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const Color s = casteljau::unpremultiply(pm.pixel(x, y));
            const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * 29 + static_cast<std::size_t>(x)) * 4];
            if (p[0] != s.r || p[1] != s.g || p[2] != s.b || p[3] != s.a) ++wrong;
        }
    CHECK(wrong == 0);
    // A worked pixel: premultiplied (64, 0, 32, 128) is stored as straight (128, 0, 64, 128).
    Pixmap one(1, 1);
    one.set_pixel(0, 0, PremulPixel{64, 0, 32, 128});
    const auto one_rgba = png_test::stb_decode_rgba8(encode_png(one), w, h);
    REQUIRE(one_rgba.size() == 4);
    CHECK(one_rgba == std::vector<std::uint8_t>{128, 0, 64, 128});
}

TEST_CASE("encode_png: the smallest colour type that holds the pixels, every filter and level round-trips", "[png]") {
    // Four pictures, one per colour type: grey and opaque, grey with alpha, colour and opaque,
    // colour with alpha (random pixels of each kind).
    std::uint32_t seed = 7;
    auto next = [&] {
        seed = seed * 1664525u + 1013904223u;
        return static_cast<std::uint8_t>(seed >> 24);
    };
    auto picture = [&](bool grey, bool opaque) {
        Pixmap pm(37, 23);
        for (int y = 0; y < pm.height(); ++y)
            for (int x = 0; x < pm.width(); ++x) {
                const std::uint8_t a = opaque ? 255 : next();
                const std::uint8_t r = next();
                const Color c = grey ? Color::rgba(r, r, r, a) : Color::rgba(r, next(), next(), a);
                pm.set_pixel(x, y, premultiply(c));
            }
        return pm;
    };
    struct Case {
        bool grey, opaque;
        int colour_type;  // PNG IHDR colour type expected
    };
    const Case cases[] = {{true, true, 0}, {true, false, 4}, {false, true, 2}, {false, false, 6}};
    const PngFilter filters[] = {PngFilter::Auto,    PngFilter::None,  PngFilter::Sub,     PngFilter::Up,
                                 PngFilter::Average, PngFilter::Paeth, PngFilter::Adaptive};
    for (const Case& c : cases) {
        const Pixmap pm = picture(c.grey, c.opaque);
        for (PngFilter f : filters)
            for (int level : {0, 1, 4, 9})
                for (bool reduce : {true, false}) {
                    INFO("grey " << c.grey << " opaque " << c.opaque << " filter " << int(f) << " level " << level
                                 << " reduce " << reduce);
                    PngEncodeOptions o;
                    o.filter = f;
                    o.compression_level = level;
                    o.smallest_colour_type = reduce;
                    const auto bytes = encode_png(pm, o);
                    REQUIRE(bytes.size() > 26);
                    CHECK(int(bytes[8 + 4 + 4 + 9]) == (reduce ? c.colour_type : 6));  // IHDR colour type
                    CHECK(same_pixels(pm, decode_png(bytes)));
                    // The independent decoder agrees with the straight-alpha values.
                    int w = 0, h = 0;
                    const auto rgba = png_test::stb_decode_rgba8(bytes, w, h);
                    REQUIRE(rgba.size() == std::size_t(37 * 23 * 4));
                    bool same = true;
                    for (int y = 0; y < 23; ++y)
                        for (int x = 0; x < 37; ++x) {
                            const Color s = casteljau::unpremultiply(pm.pixel(x, y));
                            const std::uint8_t* p =
                                &rgba[(static_cast<std::size_t>(y) * 37 + static_cast<std::size_t>(x)) * 4];
                            same = same && p[0] == s.r && p[1] == s.g && p[2] == s.b && p[3] == s.a;
                        }
                    CHECK(same);
                }
    }
    // Levels outside zlib's 0..9 are refused.
    for (int level : {-1, 10}) {
        PngEncodeOptions o;
        o.compression_level = level;
        try {
            (void)encode_png(picture(true, true), o);
            FAIL("no error for level " << level);
        } catch (const Error& e) { CHECK(e.kind() == ErrorKind::InvalidArgument); }
    }
}

TEST_CASE("encode_png: an empty Pixmap is an InvalidArgument error", "[png]") {
    try {
        encode_png(Pixmap{});
        FAIL("no error");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::InvalidArgument); }
}

TEST_CASE("decode_png: empty, garbage and non-PNG data are InvalidData errors", "[png]") {
    std::string msg;
    CHECK(decode_error_kind({}, &msg) == ErrorKind::InvalidData);
    CHECK_THAT(msg, Catch::Contains("empty"));
    CHECK(decode_error_kind({'h', 'e', 'l', 'l', 'o'}, &msg) == ErrorKind::InvalidData);
    CHECK_THAT(msg, Catch::Contains("signature"));
    const std::string gif = "GIF89a\x01\x00\x01\x00\x00\x00\x00;";
    CHECK(decode_error_kind(std::vector<std::uint8_t>(gif.begin(), gif.end()), &msg) == ErrorKind::InvalidData);
    CHECK_THAT(msg, Catch::Contains("signature"));
    // The signature alone, and the signature followed by garbage.
    std::vector<std::uint8_t> sig = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    CHECK(decode_error_kind(sig, &msg) == ErrorKind::InvalidData);
    CHECK_THAT(msg, Catch::StartsWith("invalid PNG: "));
    std::mt19937 rng(5);
    for (int i = 0; i < 200; ++i) sig.push_back(static_cast<std::uint8_t>(rng()));
    CHECK(decode_error_kind(sig, &msg) == ErrorKind::InvalidData);
    CHECK_THAT(msg, Catch::StartsWith("invalid PNG: "));
    // A header with no image data.
    CHECK(decode_error_kind(png_test::header_only_png(4, 4), &msg) == ErrorKind::InvalidData);
}

TEST_CASE("decode_png: every truncation of a valid PNG is an error or the complete image", "[png]") {
    const Pixmap original = random_premultiplied(13, 11, 77);
    const auto bytes = encode_png(original);
    int errors = 0, complete = 0;
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        const std::vector<std::uint8_t> cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n));
        try {
            const Pixmap p = decode_png(cut);
            // Only a cut inside the final IEND chunk leaves the image intact.
            INFO("prefix of " << n << " of " << bytes.size() << " bytes decoded");
            CHECK(n >= bytes.size() - 12);
            CHECK(same_pixels(p, original));
            ++complete;
        } catch (const Error& e) {
            INFO("prefix of " << n << " bytes: " << e.what());
            CHECK(e.kind() == ErrorKind::InvalidData);
            ++errors;
        }
    }
    CHECK(errors >= static_cast<int>(bytes.size()) - 12);
}

TEST_CASE("decode_png: a bad CRC or damaged compressed data in IDAT is an InvalidData error", "[png]") {
    const auto good = encode_png(random_premultiplied(8, 8, 3));
    // Find the first IDAT chunk rather than trusting the layout of the chunks before it.
    std::size_t pos = 8, len = 0;
    for (;;) {
        REQUIRE(pos + 12 <= good.size());
        len = (std::size_t(good[pos]) << 24) | (std::size_t(good[pos + 1]) << 16) | (std::size_t(good[pos + 2]) << 8) |
              good[pos + 3];
        if (std::string(reinterpret_cast<const char*>(&good[pos + 4]), 4) == "IDAT") break;
        pos += 12 + len;
    }
    REQUIRE(len > 4);
    std::string msg;
    auto bad_crc = good;
    bad_crc[pos + 8 + len + 3] ^= 0x01;  // last byte of the chunk's CRC
    CHECK(decode_error_kind(bad_crc, &msg) == ErrorKind::InvalidData);
    CHECK_THAT(msg, Catch::Contains("CRC"));
    // A damaged byte in the zlib stream is reported by the decompressor, before the CRC is read.
    auto bad_data = good;
    bad_data[pos + 8 + 3] ^= 0x10;
    CHECK(decode_error_kind(bad_data, &msg) == ErrorKind::InvalidData);
    CHECK_THAT(msg, Catch::StartsWith("invalid PNG: IDAT"));
}

TEST_CASE("decode_png: randomly corrupted files never crash", "[png]") {
    // Seeded byte flips anywhere in a palette PNG and an RGBA PNG; each decode either fails with
    // InvalidData or yields an image of the original size (a flip in an ignored ancillary chunk).
    Spec s;
    s.color_type = PNG_COLOR_TYPE_PALETTE;
    s.bit_depth = 4;
    s.width = 20;
    s.height = 20;
    for (int i = 0; i < 16; ++i)
        s.palette.push_back(png_color{static_cast<png_byte>(i * 16), 0, static_cast<png_byte>(255 - i * 16)});
    s.trans_alpha = {0, 100};
    for (int y = 0; y < 20; ++y) {
        std::vector<unsigned> samples;
        for (int x = 0; x < 20; ++x) samples.push_back(static_cast<unsigned>(x * y) % 16);
        s.rows.push_back(pack(samples, 4));
    }
    const std::vector<std::vector<std::uint8_t>> inputs = {png_test::write_spec(s),
                                                           encode_png(random_premultiplied(20, 20, 8))};
    std::mt19937 rng(2024);
    int failures = 0, decoded = 0;
    for (const auto& good : inputs)
        for (int trial = 0; trial < 400; ++trial) {
            auto bad = good;
            const int flips = 1 + static_cast<int>(rng() % 3);
            for (int f = 0; f < flips; ++f)
                bad[8 + rng() % (bad.size() - 8)] ^= static_cast<std::uint8_t>(1 + rng() % 255);
            try {
                const Pixmap p = decode_png(bad);
                CHECK(p.width() == 20);
                CHECK(p.height() == 20);
                ++decoded;
            } catch (const Error& e) {
                CHECK(e.kind() == ErrorKind::InvalidData);
                ++failures;
            }
        }
    CHECK(failures > 600);  // nearly every flip breaks a CRC
    CHECK(failures + decoded == 800);
}

TEST_CASE("decode_png: a chunk declaring more data than the file holds is refused before libpng allocates it",
          "[png]") {
    // libpng allocates an ancillary chunk at its declared length before reading it: a text chunk
    // declaring 2 GB in a small file (found by fuzz_image) must fail on the length, up front.
    const auto good = encode_png(random_premultiplied(4, 4, 9));
    std::vector<std::uint8_t> bad(good.begin(), good.begin() + 33);  // signature and IHDR
    const std::uint8_t text[] = {0x74, 0xff, 0x00, 0x19, 't', 'E', 'X', 't', 'S', 'o', 'f', 't'};
    bad.insert(bad.end(), std::begin(text), std::end(text));
    bad.insert(bad.end(), good.begin() + 33, good.end());
    std::string msg;
    CHECK(decode_error_kind(bad, &msg) == ErrorKind::InvalidData);
    CHECK_THAT(msg, Catch::Contains("chunk 'tEXt' at byte 33 declares 1962868761 bytes"));
}

namespace {

// `png` with `chunks` inserted after IHDR (the signature and IHDR are its first 33 bytes).
std::vector<std::uint8_t> with_chunks_after_ihdr(
    const std::vector<std::uint8_t>& png,
    const std::vector<std::pair<std::string, std::vector<std::uint8_t>>>& chunks) {
    std::vector<std::uint8_t> out(png.begin(), png.begin() + 33);
    for (const auto& [type, data] : chunks) png_test::append_chunk(out, type.c_str(), data);
    out.insert(out.end(), png.begin() + 33, png.end());
    return out;
}

}  // namespace

TEST_CASE("decode_png: ancillary chunks past the limits are skipped, the image still decodes", "[png]") {
    const Pixmap original = random_premultiplied(6, 5, 31);
    const auto good = encode_png(original);
    // A zTXt chunk inflating to 17 MiB (above limits::kMaxPngChunkBytes): libpng refuses to
    // inflate it and skips the chunk; the image is unaffected.
    std::vector<std::uint8_t> text = {'C', 'o', 'm', 'm', 'e', 'n', 't', 0, 0};  // keyword, NUL, method 0
    {
        const std::vector<std::uint8_t> zeros(17u << 20, 'a');
        uLongf len = compressBound(static_cast<uLong>(zeros.size()));
        std::vector<std::uint8_t> z(len);
        REQUIRE(compress2(z.data(), &len, zeros.data(), static_cast<uLong>(zeros.size()), 9) == Z_OK);
        REQUIRE(len < 100000);
        text.insert(text.end(), z.begin(), z.begin() + static_cast<std::ptrdiff_t>(len));
    }
    static_assert(casteljau::limits::kMaxPngChunkBytes == 16u << 20);
    const Pixmap a = decode_png(with_chunks_after_ihdr(good, {{"zTXt", text}}));
    CHECK(same_pixels(a, original));
    // 1,500 text chunks (above limits::kMaxPngAncillaryChunks): the ones past the limit are skipped.
    std::vector<std::pair<std::string, std::vector<std::uint8_t>>> many;
    for (int i = 0; i < 1500; ++i) many.push_back({"tEXt", {'k', 0, 'v', static_cast<std::uint8_t>('0' + i % 10)}});
    static_assert(casteljau::limits::kMaxPngAncillaryChunks == 1000);
    const Pixmap b = decode_png(with_chunks_after_ihdr(good, many));
    CHECK(same_pixels(b, original));
}

TEST_CASE("decode_png: a declared size beyond the limits is rejected before allocating", "[png]") {
    // Hand-made headers (signature, IHDR, IEND; no image data): the size check must come first,
    // or these would be reported as missing data, or try to allocate 40 GB.
    std::string msg;
    CHECK(decode_error_kind(png_test::header_only_png(100000, 100000), &msg) == ErrorKind::Limit);
    CHECK_THAT(msg, Catch::Contains("100000x100000"));
    CHECK(decode_error_kind(png_test::header_only_png(0x7fffffff, 1), &msg) == ErrorKind::Limit);
    CHECK(decode_error_kind(png_test::header_only_png(1, 32769), &msg) == ErrorKind::Limit);
    CHECK(decode_error_kind(png_test::header_only_png(20000, 20000), &msg) == ErrorKind::Limit);  // area
    // At the limits the header is accepted and decoding fails later, on the missing data.
    CHECK(decode_error_kind(png_test::header_only_png(32768, 1), &msg) == ErrorKind::InvalidData);
    CHECK(decode_error_kind(png_test::header_only_png(1, 32768), &msg) == ErrorKind::InvalidData);
    // ... and before the image is allocated: deflate expands at most 1032:1, so the 9 bytes of
    // image data these headers carry cannot hold 32768 rows (fuzz_image: small files declaring
    // 2^28 pixels each cost a 1 GiB allocation).
    CHECK_THAT(msg, Catch::Contains("1x32768 pixels need at least 159 bytes of compressed data, the file has 9"));
    // A zero or out-of-range (>= 2^31) size is invalid data, not a limit.
    CHECK(decode_error_kind(png_test::header_only_png(0, 5), &msg) == ErrorKind::InvalidData);
    CHECK(decode_error_kind(png_test::header_only_png(0x80000000u, 5), &msg) == ErrorKind::InvalidData);
}
