// Golden images of text (golden/text/*.png). Each picture is first checked, in the same test,
// against FreeType's rendering of the same glyph run (each glyph rendered by FreeType at 8x,
// box-filtered, placed where draw_text places it, composited the same way), then against its
// golden file.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "casteljau/canvas.hpp"
#include "casteljau/text.hpp"
#include "text_golden.hpp"
#include "text_support.hpp"

using namespace casteljau;
using namespace text_test;

namespace {

constexpr int kPad = 6;
constexpr int kSupersample = 8;
// Against FreeType supersampled: the per-glyph accuracy of test_font.cpp, composited.
constexpr int kFtMax = 16;
constexpr double kFtMean = 0.5;
// Against the golden files: rounding-level changes only.
constexpr int kGoldenMax = 8;
constexpr double kGoldenMean = 0.25;

// Draws `layout` black on white with its bounds plus padding, checks it against FreeType, then
// against golden/text/NAME.png.
void golden_layout(const std::string& name, const TextLayout& layout, std::vector<FtRenderer*> ft,
                   const Affine* transform = nullptr, int width = 0, int height = 0) {
    const Rect b = layout.bounds();
    int w = width, h = height;
    Point origin{0, 0};
    if (!transform) {
        w = static_cast<int>(std::ceil(b.x1) - std::floor(b.x0)) + 2 * kPad;
        h = static_cast<int>(std::ceil(b.y1) - std::floor(b.y0)) + 2 * kPad;
        origin = {kPad - std::floor(b.x0), kPad - std::floor(b.y0)};
    }
    const Paint black = Paint::solid(Color::black());
    Pixmap ours(w, h);
    ours.fill(Color::white());
    Canvas canvas(ours);
    if (transform) canvas.set_transform(*transform);
    draw_text(canvas, layout, origin, black);
    const Pixmap ref =
        reference_text_image(layout, ft, w, h, origin, Color::white(), black, 4, transform, kSupersample);
    const DiffStats d = compare_pixmaps(ours, ref);
    INFO(name << " vs FreeType: max " << d.max << "/255 at (" << d.max_x << ", " << d.max_y << "), mean " << d.mean);
    CHECK(d.max <= kFtMax);
    CHECK(d.mean <= kFtMean);
    long ink = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) ink += ours.pixel(x, y).r < 128;
    CHECK(ink > 50);
    check_golden(name, ours, kGoldenMax, kGoldenMean);
}

TextStyle sized(double px) {
    TextStyle s;
    s.size = px;
    return s;
}

}  // namespace

TEST_CASE("Golden: kerning AV To Wa (DejaVu Sans 32 px)", "[text][golden]") {
    const Font f = Font::load(kDejaVu);
    FtRenderer ft(kDejaVu);
    golden_layout("kerning", layout_text("AV To Wa AVATAR Toyota", f, sized(32)), {&ft});
}

TEST_CASE("Golden: ligatures fi fl (Linux Libertine 36 px)", "[text][golden]") {
    const Font f = Font::load(kLibertine);
    FtRenderer ft(kLibertine);
    const TextLayout l = layout_text("fi fl office waffle", f, sized(36));
    // The ligature glyphs are there: fewer glyphs than characters.
    CHECK(l.glyphs.size() < l.text.size() - 2);
    golden_layout("ligatures", l, {&ft});
}

TEST_CASE("Golden: combining marks (DejaVu Sans 40 px)", "[text][golden]") {
    const Font f = Font::load(kDejaVu);
    FtRenderer ft(kDejaVu);
    // a + U+0302 + U+0309 (-> U+1EA9), x + U+0323 + U+0302, q + U+0303, e + U+0301 + U+0327.
    golden_layout("marks", layout_text("a\xCC\x82\xCC\x89 x\xCC\xA3\xCC\x82 q\xCC\x83 e\xCC\x81\xCC\xA7", f, sized(40)),
                  {&ft});
}

TEST_CASE("Golden: right-to-left line (Noto Sans Arabic, Hebrew from DejaVu Sans, 32 px)", "[text][golden]") {
    const Font ar = Font::load(kNotoArabic), dv = Font::load(kDejaVu);
    FtRenderer ft_ar(kNotoArabic), ft_dv(kDejaVu);
    const std::vector<const Font*> chain{&ar, &dv};
    // "as-salamu alaykum 2024" then "shalom": an RTL paragraph with a number and a Hebrew word.
    const TextLayout l = layout_text(
        "\xD8\xA7\xD9\x84\xD8\xB3\xD9\x84\xD8\xA7\xD9\x85 \xD8\xB9\xD9\x84\xD9\x8A\xD9\x83\xD9\x85 "
        "2024 \xD7\xA9\xD7\x9C\xD7\x95\xD7\x9D",
        chain, sized(32));
    REQUIRE(l.lines.size() == 1);
    CHECK(l.lines[0].rtl);
    golden_layout("rtl", l, {&ft_ar, &ft_dv});
}

TEST_CASE("Golden: wrapped centred paragraph (DejaVu Sans 16 px, 260 px wide)", "[text][golden]") {
    const Font f = Font::load(kDejaVu);
    FtRenderer ft(kDejaVu);
    TextStyle st = sized(16);
    st.max_width = 260;
    st.align = TextAlign::Center;
    st.line_height = 1.1;
    const TextLayout l = layout_text(
        "Sphinx of black quartz, judge my vow. The five boxing wizards jump quickly; pack my box with five dozen "
        "liquor jugs.\nA second paragraph, centred as well.",
        f, st);
    CHECK(l.lines.size() >= 5);
    golden_layout("paragraph", l, {&ft});
}

TEST_CASE("Golden: CFF outlines (Linux Libertine 28 px)", "[text][golden]") {
    const Font f = Font::load(kLibertine);
    REQUIRE(f.outline_format() == OutlineFormat::CFF);
    FtRenderer ft(kLibertine);
    golden_layout("cff", layout_text("Quirky spud boys can jam after zapping five worthy Polysixes.", f, sized(28)),
                  {&ft});
}

TEST_CASE("Golden: variable font weights 100, 400, 900 (Inter 28 px)", "[text][golden]") {
    const double weights[] = {100, 400, 900};
    std::vector<Pixmap> parts;
    for (double wght : weights) {
        Font f = Font::load(kInterVar);
        const Variation v{"wght", wght};
        f.set_variations({&v, 1});
        FtRenderer ft(kInterVar);
        ft.set_variation({wght});
        INFO("wght " << wght);
        golden_layout("variable-wght" + std::to_string(static_cast<int>(wght)),
                      layout_text("Variable weight", f, sized(28)), {&ft});
    }
}

TEST_CASE("Golden: rotated text (DejaVu Sans 24 px, 30 degrees)", "[text][golden]") {
    const Font f = Font::load(kDejaVu);
    FtRenderer ft(kDejaVu);
    const TextLayout l = layout_text("Rotated text, 30\xC2\xB0", f, sized(24));
    const Affine m = Affine::translate(20, 150) * Affine::rotate(-std::numbers::pi / 6);
    golden_layout("rotated", l, {&ft}, &m, 260, 180);
}
