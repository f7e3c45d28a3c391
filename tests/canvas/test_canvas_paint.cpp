// Canvas paints checked against formulas worked out here: linear and radial gradients at sampled
// pixel centres (through a canvas transform), draw_image with an identity transform (exact), a
// half-pixel shift (bilinear computed here), nearest and bicubic sampling, layers with group
// opacity, and a Canvas over caller-owned memory with padding in every row.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "core/pixel_memory.hpp"
#include "casteljau/limits.hpp"

using namespace casteljau;

namespace {

// Premultiplied value of the straight colour lerp(a, b, t) at full opacity (opaque stops).
double lerp_channel(int a, int b, double t) { return a + (b - a) * t; }

}  // namespace

TEST_CASE("linear gradient: sampled pixels match the projection formula under a canvas transform",
          "[canvas][gradient]") {
    Pixmap pm(100, 40);
    Canvas c(pm);
    c.scale(2, 2);  // user (5, 0)..(45, 0) is pixels 10..90
    const Color a = Color::rgba(255, 0, 0), b = Color::rgba(0, 64, 255);
    c.fill_rect({0, 0, 50, 20}, Paint::shaded(Shader::linear({5, 0}, {45, 0}, {{0, a}, {1, b}})));
    int checked = 0;
    for (int x = 0; x < 100; x += 3) {
        const double t = std::clamp((x + 0.5 - 10) / 80, 0.0, 1.0);
        const PremulPixel p = pm.pixel(x, 17);
        CHECK(std::abs(p.r - lerp_channel(a.r, b.r, t)) <= 1);
        CHECK(std::abs(p.g - lerp_channel(a.g, b.g, t)) <= 1);
        CHECK(std::abs(p.b - lerp_channel(a.b, b.b, t)) <= 1);
        CHECK(p.a == 255);
        ++checked;
    }
    CHECK(checked > 30);
}

TEST_CASE("radial gradient: sampled pixels match t = distance / radius, with reflect spread", "[canvas][gradient]") {
    Pixmap pm(80, 80);
    Canvas c(pm);
    const Color a = Color::rgba(0, 0, 0), b = Color::rgba(255, 255, 255);
    c.fill_rect({0, 0, 80, 80},
                Paint::shaded(Shader::radial({40, 40}, 20, {40, 40}, 0, {{0, a}, {1, b}}, SpreadMethod::Reflect)));
    std::mt19937 rng(7);
    for (int i = 0; i < 200; ++i) {
        const int x = static_cast<int>(rng() % 80), y = static_cast<int>(rng() % 80);
        const double d = std::hypot(x + 0.5 - 40, y + 0.5 - 40) / 20;
        const double u = std::fmod(d, 2.0);
        const double t = u > 1 ? 2 - u : u;
        INFO("pixel " << x << "," << y);
        CHECK(std::abs(pm.pixel(x, y).g - 255 * t) <= 1);
    }
}

TEST_CASE("draw_image: identity is exact, a half-pixel shift is bilinear interpolation", "[canvas][image]") {
    const int w = 16, h = 12;
    Pixmap img(w, h);
    std::mt19937 rng(3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::uint8_t a = static_cast<std::uint8_t>(rng() % 256);
            auto ch = [&] { return static_cast<std::uint8_t>(a == 0 ? 0 : rng() % (a + 1u)); };
            const std::uint8_t r = ch(), g = ch(), bb = ch();
            img.set_pixel(x, y, {r, g, bb, a});
        }
    for (ImageSampling s : {ImageSampling::Nearest, ImageSampling::Bilinear, ImageSampling::Bicubic}) {
        Pixmap out(w, h);
        Canvas c(out);
        c.draw_image(img, Affine{}, s);
        int diff = 0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) diff += !(out.pixel(x, y) == img.pixel(x, y));
        INFO("sampling " << static_cast<int>(s));
        CHECK(diff == 0);
    }
    // Shifted by half a pixel: pixel (i, j) of the canvas samples image point (i, j), the corner
    // shared by image pixels (i-1..i, j-1..j): their average.
    Pixmap out(w + 1, h + 1);
    Canvas c(out);
    c.draw_image(img, Affine::translate(0.5, 0.5), ImageSampling::Bilinear);
    int bad = 0;
    for (int j = 1; j < h; ++j)
        for (int i = 1; i < w; ++i) {
            const PremulPixel p00 = img.pixel(i - 1, j - 1), p10 = img.pixel(i, j - 1), p01 = img.pixel(i - 1, j),
                              p11 = img.pixel(i, j);
            const double e[4] = {(p00.r + p10.r + p01.r + p11.r) / 4.0, (p00.g + p10.g + p01.g + p11.g) / 4.0,
                                 (p00.b + p10.b + p01.b + p11.b) / 4.0, (p00.a + p10.a + p01.a + p11.a) / 4.0};
            const PremulPixel g = out.pixel(i, j);
            const int got[4] = {g.r, g.g, g.b, g.a};
            for (int k = 0; k < 4; ++k) bad += std::abs(got[k] - e[k]) > 1.0;
        }
    CHECK(bad == 0);
    // The image's border pixels are half covered: the corner pixel (0, 0) gets a quarter of it.
    CHECK(std::abs(out.pixel(0, 0).a - img.pixel(0, 0).a / 4.0) <= 1.0);
}

TEST_CASE("draw_image: nearest sampling at 2x repeats every pixel", "[canvas][image]") {
    Pixmap img(3, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            img.set_pixel(x, y, {static_cast<std::uint8_t>(40 * x), static_cast<std::uint8_t>(100 * y), 7, 255});
    Pixmap out(6, 4);
    Canvas c(out);
    c.draw_image(img, Affine::scale(2, 2), ImageSampling::Nearest);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x) CHECK(out.pixel(x, y) == img.pixel(x / 2, y / 2));
}

TEST_CASE("layers: group opacity applies once to overlapping shapes, layers nest", "[canvas][layer]") {
    Pixmap pm(20, 10);
    pm.fill(Color::white());
    Canvas c(pm);
    c.begin_layer(0.5);
    c.fill_rect({0, 0, 12, 10}, Paint::solid(Color::rgba(255, 0, 0)));
    c.fill_rect({8, 0, 20, 10}, Paint::solid(Color::rgba(255, 0, 0)));  // overlaps 8..12
    c.begin_layer(1.0, BlendMode::Multiply);
    c.fill_rect({0, 0, 4, 10}, Paint::solid(Color::rgba(0, 0, 255)));  // red x blue = black
    CHECK(c.layer_depth() == 2);
    c.end_layer();
    c.end_layer();
    c.end_layer();  // no layer open: nothing
    CHECK(c.layer_depth() == 0);
    // Red at half opacity over white: (255, 128, 128), the overlap no darker.
    CHECK(std::abs(pm.pixel(10, 5).g - 127.5) <= 1);
    CHECK(pm.pixel(10, 5) == pm.pixel(6, 5));
    CHECK(pm.pixel(10, 5).r == 255);
    // Black at half opacity over white.
    CHECK(std::abs(pm.pixel(1, 5).r - 127.5) <= 1);
    CHECK(std::abs(pm.pixel(1, 5).b - 127.5) <= 1);
}

TEST_CASE("Canvas opacity multiplies fills, restore inside a layer stops at the layer", "[canvas][layer]") {
    Pixmap pm(4, 1);
    Canvas c(pm);
    c.set_opacity(0.5);
    c.fill_rect({0, 0, 4, 1}, Paint::solid(Color::black()));
    CHECK(std::abs(pm.pixel(0, 0).a - 127.5) <= 1);
    c.set_opacity(1);
    c.save();
    c.translate(1, 0);
    c.begin_layer();
    c.restore();  // belongs to the outer save: ignored inside the layer
    CHECK(c.transform() == Affine::translate(1, 0));
    c.end_layer();
    c.restore();
    CHECK(c.transform() == Affine{});
}

TEST_CASE("Canvas over caller-owned memory draws into it with its stride and leaves the padding alone",
          "[canvas][pixmap]") {
    const int w = 5, h = 3;
    const std::size_t stride = 4 * w + 12;
    std::vector<std::uint8_t> buf(stride * h, 0xAB);
    Canvas c(buf.data(), w, h, stride);
    c.clear(Color::transparent());
    c.fill_rect({1, 1, 3, 2}, Paint::solid(Color::rgba(10, 20, 30)));
    CHECK(c.stride() == stride);
    CHECK(c.pixels() == buf.data());
    CHECK(buf[stride * 1 + 4 * 1 + 0] == 10);
    CHECK(buf[stride * 1 + 4 * 2 + 3] == 255);
    CHECK(buf[stride * 1 + 4 * 3 + 3] == 0);
    for (int y = 0; y < h; ++y)
        for (std::size_t k = 4 * w; k < stride; ++k) CHECK(buf[stride * static_cast<std::size_t>(y) + k] == 0xAB);
    // A copy of the borrowed pixmap owns a tightly packed copy.
    const Pixmap copy = c.target();
    CHECK_FALSE(copy.borrowed());
    CHECK(copy.stride() == 4 * static_cast<std::size_t>(w));
    CHECK(copy.pixel(1, 1) == PremulPixel{10, 20, 30, 255});
    CHECK_THROWS_AS(Pixmap::borrow(buf.data(), w, h, 4 * w - 1), Error);
    CHECK_THROWS_AS(Pixmap::borrow(nullptr, w, h, stride), Error);
}

TEST_CASE("fill_path with per-call options leaves the canvas defaults alone", "[canvas]") {
    Pixmap pm(10, 10);
    Canvas c(pm);
    FillOptions o;
    o.tolerance = 0.5;
    o.rule = FillRule::EvenOdd;
    Path p;
    p.add_rect({1, 1, 9, 9});
    p.add_rect({3, 3, 7, 7});
    c.fill_path(p, Paint::solid(Color::black()), o);
    CHECK(pm.pixel(5, 5).a == 0);
    CHECK(pm.pixel(2, 2).a == 255);
    CHECK(c.fill_options().tolerance == kDefaultTolerance);
    CHECK(c.fill_options().rule == FillRule::NonZero);
}

TEST_CASE("canvas limits: save() nests 1024 deep and layers 64 deep, one more is Error(Limit)", "[canvas][limits]") {
    Pixmap pm(4, 4);
    Canvas c(pm);
    for (int i = 0; i < 1024; ++i) c.save();
    try {
        c.save();
        FAIL("save 1025 deep succeeded");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Limit); }
    for (int i = 0; i < 1024; ++i) c.restore();
    for (int i = 0; i < limits::kMaxNestingDepth; ++i) c.begin_layer(0.5);
    try {
        c.begin_layer(0.5);
        FAIL("a layer 65 deep was begun");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Limit); }
    // The canvas still works once the layers are unwound.
    for (int i = 0; i < limits::kMaxNestingDepth; ++i) c.end_layer();
    Path r;
    r.add_rect(Rect{0, 0, 4, 4});
    c.fill_path(r, Paint::solid(Color::black()));
    CHECK(pm.pixel(1, 1) == PremulPixel{0, 0, 0, 255});
}

TEST_CASE(
    "Pixmap: a new pixmap is transparent, fill_rows replaces rows in range only, copies and moves own their pixels",
    "[pixmap]") {
    Pixmap p(3, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 3; ++x) CHECK(p.pixel(x, y) == PremulPixel{0, 0, 0, 0});
    p.fill_rows(1, 3, Color::rgba(255, 0, 0, 128));
    p.fill_rows(-5, 0, Color::black());  // clamped: nothing
    p.fill_rows(4, 9, Color::black());   // clamped: nothing
    for (int x = 0; x < 3; ++x) {
        CHECK(p.pixel(x, 0) == PremulPixel{0, 0, 0, 0});
        CHECK(p.pixel(x, 1) == PremulPixel{128, 0, 0, 128});
        CHECK(p.pixel(x, 2) == PremulPixel{128, 0, 0, 128});
        CHECK(p.pixel(x, 3) == PremulPixel{0, 0, 0, 0});
    }
    Pixmap copy = p;
    CHECK_FALSE(copy.borrowed());
    CHECK(copy.data() != p.data());
    CHECK(copy.pixel(2, 2) == PremulPixel{128, 0, 0, 128});
    Pixmap moved = std::move(copy);
    CHECK(moved.pixel(0, 1) == PremulPixel{128, 0, 0, 128});
    CHECK(copy.data() == nullptr);
    copy = moved;
    CHECK(copy.pixel(0, 2) == PremulPixel{128, 0, 0, 128});
    p.fill(Color::white());
    CHECK(p.pixel(1, 3) == PremulPixel{255, 255, 255, 255});
    // Rows with padding (a borrowed pixmap): every pixel of the rows in range, none of the padding,
    // for a colour of one byte value (written by memset) and for any other (eight pixels at a time).
    std::vector<std::uint8_t> mem(60 * 5, 7);
    Pixmap b = Pixmap::borrow(mem.data(), 13, 5, 60);
    b.fill_rows(0, 5, Color::rgba(0, 0, 0, 0));
    b.fill_rows(1, 4, Color::rgba(10, 20, 30, 255));
    for (int y = 0; y < 5; ++y) {
        for (int x = 0; x < 13; ++x)
            CHECK(b.pixel(x, y) == (y >= 1 && y < 4 ? PremulPixel{10, 20, 30, 255} : PremulPixel{0, 0, 0, 0}));
        for (int k = 52; k < 60; ++k) CHECK(mem[static_cast<std::size_t>(y) * 60 + k] == 7);
    }
}

TEST_CASE("Pixmap: large pixmaps (mapped on huge pages) read as zero, copy, move and free like small ones",
          "[pixmap]") {
    // 2048 x 1100 x 4 bytes is past platform::kHugeBlock (2 MiB) and not a multiple of 2 MiB.
    const int w = 2048, h = 1100;
    REQUIRE(std::size_t(w) * h * 4 >= platform::kHugeBlock);
    Pixmap p(w, h);
    std::size_t nonzero = 0;
    for (int y = 0; y < h; ++y)
        for (std::size_t k = 0; k < std::size_t(w) * 4; ++k) nonzero += p.row(y)[k] != 0;
    CHECK(nonzero == 0);
#if defined(__linux__)
    CHECK(reinterpret_cast<std::uintptr_t>(p.data()) % (std::uintptr_t(2) << 20) == 0);
#endif
    p.fill_rows(h - 2, h, Color::rgba(0, 0, 255, 255));  // the last bytes of the block
    p.set_pixel(0, 0, PremulPixel{1, 2, 3, 4});
    Pixmap copy = p;
    CHECK(copy.data() != p.data());
    CHECK(copy.pixel(w - 1, h - 1) == PremulPixel{0, 0, 255, 255});
    CHECK(copy.pixel(0, 0) == PremulPixel{1, 2, 3, 4});
    CHECK(copy.pixel(5, 5) == PremulPixel{0, 0, 0, 0});
    Pixmap moved = std::move(copy);
    CHECK(moved.pixel(w - 1, h - 2) == PremulPixel{0, 0, 255, 255});
    p = Pixmap(3, 3);  // the large block is released, a small one takes its place
    CHECK(p.pixel(2, 2) == PremulPixel{0, 0, 0, 0});
    moved = Pixmap(w, h);  // and a large one replaces a large one
    CHECK(moved.pixel(w - 1, h - 1) == PremulPixel{0, 0, 0, 0});
}

TEST_CASE("Pixmap: a large pixmap made in the memory of a released one reads as zero", "[pixmap]") {
    const int w = 2048, h = 1100;
    auto nonzero_bytes = [&](const Pixmap& p) {
        std::size_t n = 0;
        for (int y = 0; y < h; ++y)
            for (std::size_t k = 0; k < std::size_t(w) * 4; ++k) n += p.row(y)[k] != 0;
        return n;
    };
    { Pixmap flush(w, h + 300); }  // another size: unmaps any blocks waiting from earlier tests
    const std::uint8_t* first = nullptr;
    {
        Pixmap p(w, h);
        p.fill(Color::rgba(10, 20, 30, 255));  // every byte non-zero, to the block's last
        first = p.data();
    }
    Pixmap q(w, h);
#if defined(__linux__)
    CHECK(q.data() == first);  // the released block was kept and taken again
#endif
    CHECK(nonzero_bytes(q) == 0);
    // A copy takes a block of any content: its pixels are the source's.
    q.fill_rows(0, 1, Color::rgba(1, 2, 3, 255));
    {
        Pixmap dirty(w, h);
        dirty.fill(Color::rgba(200, 0, 0, 255));
    }
    const Pixmap copy = q;
    CHECK(copy.pixel(w - 1, 0) == PremulPixel{1, 2, 3, 255});
    CHECK(copy.pixel(w - 1, h - 1) == PremulPixel{0, 0, 0, 0});
    // A block of another size unmaps the waiting ones and maps its own.
    {
        Pixmap dirty(w, h);
        dirty.fill(Color::rgba(0, 200, 0, 255));
    }
    Pixmap other(w, h + 600);
    CHECK(other.pixel(w - 1, h + 599) == PremulPixel{0, 0, 0, 0});
    Pixmap again(w, h);
    CHECK(nonzero_bytes(again) == 0);
}
