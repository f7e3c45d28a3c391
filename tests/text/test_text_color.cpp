// Colour glyphs: COLR v1 paint graphs and v0 layers against renderings computed here from the
// test font's paint graphs (tests/data/make_colr_font.py builds tests/data/colr_test.ttf), and
// CBDT bitmap emoji against the font's bitmap downscaled here by area averaging.
#include <catch2/catch.hpp>

#include <ft2build.h>
#include FT_FREETYPE_H

#include <array>
#include <cmath>
#include <filesystem>
#include <functional>

#include "casteljau/canvas.hpp"
#include "casteljau/text.hpp"
#include "text_support.hpp"

using namespace casteljau;

namespace {

const std::string kColrFont = text_test::source_path("tests/data/colr_test.ttf");
// Three emoji of Noto Color Emoji as CBDT and as sbix bitmaps (tests/data/make_color_fonts.py).
const std::string kCbdtFont = text_test::source_path("tests/data/emoji_cbdt_test.ttf");
const std::string kSbixFont = text_test::source_path("tests/data/emoji_sbix_test.ttf");

using Rgba = std::array<double, 4>;  // straight, 0..255

const Rgba kRed{255, 0, 0, 255}, kBlue{0, 0, 255, 255}, kYellow{255, 255, 0, 255}, kGreen{0, 128, 0, 255};

Rgba mix(const Rgba& a, const Rgba& b, double t) {
    t = std::clamp(t, 0.0, 1.0);
    Rgba r;
    for (int i = 0; i < 4; ++i) r[i] = a[i] + t * (b[i] - a[i]);
    return r;
}

// Draws `text` from the test font at 100 px (one pixel per 10 font units) on a transparent
// 100 x 100 image, the glyph's origin at (0, 100): font point (fx, fy) is at pixel (fx / 10, 100 - fy / 10).
Pixmap draw_colr(const std::string& text, Color color = Color::black(), int palette = 0) {
    const Font font = Font::load(kColrFont);
    TextStyle st;
    st.size = 100;
    const TextLayout layout = layout_text(text, font, st);
    REQUIRE(layout.glyphs.size() == 1);
    REQUIRE(layout.glyphs[0].position.x == 0);
    REQUIRE(layout.glyphs[0].position.y == 100);
    Pixmap pm(100, 100);
    Canvas canvas(pm);
    TextDrawOptions options;
    options.palette = palette;
    draw_text(canvas, layout, {0, 0}, Paint::solid(color), nullptr, options);
    return pm;
}

// Compares every pixel with `expected(fx, fy)` at the pixel's centre in font units (straight
// colour; alpha 0 outside the glyph); the largest channel difference, premultiplied, must be <= 2.
void check_against(const Pixmap& pm, const std::function<Rgba(double, double)>& expected) {
    int worst = 0, wx = 0, wy = 0;
    for (int y = 0; y < pm.height(); ++y)
        for (int x = 0; x < pm.width(); ++x) {
            const Rgba e = expected((x + 0.5) * 10, (100 - (y + 0.5)) * 10);
            const PremulPixel want = premultiply(Color::rgba(
                static_cast<std::uint8_t>(std::lround(e[0])), static_cast<std::uint8_t>(std::lround(e[1])),
                static_cast<std::uint8_t>(std::lround(e[2])), static_cast<std::uint8_t>(std::lround(e[3]))));
            const PremulPixel got = pm.pixel(x, y);
            const int d = std::max({std::abs(got.r - want.r), std::abs(got.g - want.g), std::abs(got.b - want.b),
                                    std::abs(got.a - want.a)});
            if (d > worst) {
                worst = d;
                wx = x;
                wy = y;
            }
        }
    INFO("worst pixel (" << wx << ", " << wy << ")");
    CHECK(worst <= 2);
}

bool in_box(double fx, double fy, double lo, double hi) { return fx >= lo && fx < hi && fy >= lo && fy < hi; }

const Rgba kNone{0, 0, 0, 0};

}  // namespace

TEST_CASE("COLR v1: a linear and a radial gradient in glyph layers match the paint graph", "[text][color]") {
    check_against(draw_colr("A"), [](double fx, double fy) {
        if (in_box(fx, fy, 300, 700)) return mix(kYellow, kGreen, std::hypot(fx - 500, fy - 500) / 300);
        if (in_box(fx, fy, 100, 900)) return mix(kRed, kBlue, (fx - 100) / 800);
        return kNone;
    });
}

TEST_CASE("COLR v1: a rotated linear gradient matches the paint graph", "[text][color]") {
    check_against(draw_colr("B"), [](double fx, double fy) {
        return in_box(fx, fy, 100, 900) ? mix(kBlue, kRed, (fy - 100) / 800) : kNone;
    });
}

TEST_CASE("COLR v1: a sweep gradient matches the paint graph", "[text][color]") {
    check_against(draw_colr("C"), [](double fx, double fy) {
        if (!in_box(fx, fy, 100, 900)) return kNone;
        double a = std::atan2(fy - 500, fx - 500) * 180 / 3.14159265358979323846;
        if (a < 0) a += 360;
        const double t = a / 360;
        return t < 0.5 ? mix(kRed, kBlue, t / 0.5) : mix(kBlue, kRed, (t - 0.5) / 0.5);
    });
}

TEST_CASE("COLR v0: layers in palette colours, entry 0xFFFF in the text colour", "[text][color]") {
    check_against(draw_colr("D", Color::rgba(0, 200, 0)), [](double fx, double fy) {
        if (in_box(fx, fy, 300, 700)) return Rgba{0, 200, 0, 255};
        return in_box(fx, fy, 100, 900) ? kBlue : kNone;
    });
}

TEST_CASE("COLR v1: a dest-out composite cuts the source out of the backdrop", "[text][color]") {
    check_against(draw_colr("E"), [](double fx, double fy) {
        if (in_box(fx, fy, 300, 700)) return kNone;
        return in_box(fx, fy, 100, 900) ? kBlue : kNone;
    });
}

TEST_CASE("COLR v1: the clip box bounds the glyph and the palette option picks the CPAL palette", "[text][color]") {
    for (int palette : {0, 1, 7}) {
        INFO("palette " << palette);
        const Rgba colour = palette == 1 ? kGreen : kRed;  // 7 is out of range: palette 0
        check_against(draw_colr("F", Color::black(), palette),
                      [&](double fx, double fy) { return in_box(fx, fy, 100, 500) ? colour : kNone; });
    }
}

TEST_CASE("COLR glyphs give the layout their ink box", "[text][color]") {
    const Font font = Font::load(kColrFont);
    TextStyle st;
    st.size = 100;
    const TextLayout layout = layout_text("AF", font, st);
    CHECK(layout.ink.x0 == Approx(10));
    CHECK(layout.ink.y0 == Approx(10));
    CHECK(layout.ink.x1 == Approx(150));  // F's clip box ends at x 500 of the second em
    CHECK(layout.ink.y1 == Approx(90));
}

TEST_CASE("Bitmap emoji: the scaling kept for a glyph's next instances draws what a fresh font draws",
          "[text][color]") {
    // One font draws the waving hand and the next glyph at origins sharing and not sharing where
    // the bitmap's top falls within a pixel, at two sizes; each picture must equal the one a
    // font loaded for that drawing alone makes.
    const std::string path = GENERATE(kCbdtFont, kSbixFont);
    INFO(path);
    const Font shared = Font::load(path);
    const std::uint32_t hand = shared.glyph_index(0x1f44b);
    REQUIRE(hand != 0);
    struct Draw {
        double size;
        Point origin;
        std::uint32_t glyph;
    };
    const std::uint32_t other = hand + 1 < shared.glyph_count() ? hand + 1 : hand - 1;
    const Draw draws[] = {{40, {3.25, 2}, hand},  {40, {10.5, 2}, hand},   {40, {3.25, 2.5}, hand},
                          {40, {7.75, 2}, other}, {40, {3.25, 2.5}, hand}, {31, {3.25, 2}, hand},
                          {40, {3.25, 3}, hand},  {40, {1, 2.25}, hand}};
    auto draw = [](const Font& font, const Draw& d) {
        TextStyle st;
        st.size = d.size;
        TextLayout layout = layout_text("\U0001F44B", font, st);
        REQUIRE(layout.glyphs.size() == 1);
        layout.glyphs[0].glyph = d.glyph;
        Pixmap pm(64, 64);
        Canvas canvas(pm);
        draw_text(canvas, layout, d.origin, Paint::solid(Color::black()));
        return pm;
    };
    for (const Draw& d : draws) {
        INFO("size " << d.size << ", origin " << d.origin.x << ", " << d.origin.y << ", glyph " << d.glyph);
        const Pixmap kept = draw(shared, d), fresh = draw(Font::load(path), d);
        bool same = true;
        for (int y = 0; y < 64 && same; ++y)
            for (int x = 0; x < 64 && same; ++x) same = kept.pixel(x, y) == fresh.pixel(x, y);
        CHECK(same);
    }
}

TEST_CASE("CBDT and sbix emoji: drawn in colour, the font's bitmap averaged over each pixel", "[text][color]") {
    const std::string path = GENERATE(kCbdtFont, kSbixFont);
    INFO(path);
    const Font font = Font::load(path);
    const std::uint32_t gid = font.glyph_index(0x1f44b);  // waving hand
    REQUIRE(gid != 0);
    TextStyle st;
    st.size = 40;
    const TextLayout layout = layout_text("\U0001F44B", font, st);
    REQUIRE(layout.glyphs.size() == 1);
    REQUIRE(layout.glyphs[0].glyph == gid);
    const Point origin{3.25, 2};  // a fractional origin: the bitmap straddles pixel edges
    Pixmap pm(64, 64);
    Canvas canvas(pm);
    draw_text(canvas, layout, origin, Paint::solid(Color::black()));

    // The reference: the strike's bitmap through FreeType, each pixel the overlap-weighted mean of
    // the strike pixels under it.
    FT_Library lib = nullptr;
    FT_Face face = nullptr;
    REQUIRE(FT_Init_FreeType(&lib) == 0);
    REQUIRE(FT_New_Face(lib, path.c_str(), 0, &face) == 0);
    REQUIRE(FT_Select_Size(face, 0) == 0);
    REQUIRE(FT_Load_Glyph(face, gid, FT_LOAD_COLOR) == 0);
    const FT_Bitmap& bm = face->glyph->bitmap;
    REQUIRE(bm.pixel_mode == FT_PIXEL_MODE_BGRA);
    const double ppem = face->available_sizes[0].y_ppem / 64.0;
    const double k = 40 / ppem;
    const Point p{origin.x + layout.glyphs[0].position.x, origin.y + layout.glyphs[0].position.y};
    const double left = p.x + face->glyph->bitmap_left * k, top = p.y - face->glyph->bitmap_top * k;
    double total = 0;
    long count = 0;
    for (int y = 0; y < pm.height(); ++y)
        for (int x = 0; x < pm.width(); ++x) {
            double acc[4] = {0, 0, 0, 0};
            const int sx0 = std::max(0, static_cast<int>(std::floor((x - left) / k)));
            const int sx1 = std::min<int>(static_cast<int>(bm.width), static_cast<int>(std::ceil((x + 1 - left) / k)));
            const int sy0 = std::max(0, static_cast<int>(std::floor((y - top) / k)));
            const int sy1 = std::min<int>(static_cast<int>(bm.rows), static_cast<int>(std::ceil((y + 1 - top) / k)));
            for (int sy = sy0; sy < sy1; ++sy)
                for (int sx = sx0; sx < sx1; ++sx) {
                    const double ox = std::min(x + 1.0, left + (sx + 1) * k) - std::max(double(x), left + sx * k);
                    const double oy = std::min(y + 1.0, top + (sy + 1) * k) - std::max(double(y), top + sy * k);
                    if (ox <= 0 || oy <= 0) continue;
                    const unsigned char* s = bm.buffer + sy * bm.pitch + 4 * sx;
                    const double w = ox * oy;
                    acc[0] += w * s[2];
                    acc[1] += w * s[1];
                    acc[2] += w * s[0];
                    acc[3] += w * s[3];
                }
            const PremulPixel got = pm.pixel(x, y);
            if (acc[3] == 0 && got.a == 0) continue;
            total += (std::abs(got.r - acc[0]) + std::abs(got.g - acc[1]) + std::abs(got.b - acc[2]) +
                      std::abs(got.a - acc[3])) /
                     4;
            ++count;
        }
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
    REQUIRE(count > 1000);  // the emoji covers about 50 x 47 pixels
    INFO("mean error " << total / count << " over " << count << " pixels");
    CHECK(total / count <= 2.0);
    // In colour: some pixel is far from grey.
    bool colourful = false;
    for (int y = 0; y < pm.height(); ++y)
        for (int x = 0; x < pm.width(); ++x) {
            const PremulPixel q = pm.pixel(x, y);
            colourful = colourful || std::abs(q.r - q.b) > 100;
        }
    CHECK(colourful);
}
