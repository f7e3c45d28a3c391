// libFuzzer target: casteljau's own text glue over FreeType, HarfBuzz, fontconfig and ICU
// (src/text: font loading, variations, bidi, shaping, system font fallback, line breaking, line
// layout, glyph outlines and masks, colour glyphs, OpenType SVG glyphs through the SVG reader). The
// first byte picks a font: a shipped one (TrueType, CFF, Arabic, variable), the colour test fonts
// (COLR v0/v1, CBDT, sbix, SVG), one of those with bytes of its colour tables (COLR, CPAL, CBDT,
// CBLC, sbix, SVG: its documents, compressed or not) overwritten by the input, or, at
// 255, the rest of the input as a font file; then come the style (size, direction, alignment, wrap
// width, features, script, language, variation settings, system fallback on or off) and the text,
// which may be any bytes (invalid UTF-8 included), laid out against the fonts installed. FreeType's
// own parsing is FreeType's business; what is checked here is that our code ends every input in
// casteljau::Error or a layout whose glyphs all index its fonts, and draws it (colour glyphs
// included) without fault.
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/font.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/text.hpp"
#include "harness.hpp"

using namespace casteljau;

namespace {

constexpr int kFontFiles = 8;
const char* const kFiles[kFontFiles] = {
    "/fonts/DejaVuSans.ttf",           "/fonts/LinLibertine_R.otf", "/fonts/NotoSansArabic-Regular.ttf",
    "/tests/data/Inter-roman.var.ttf", "/tests/data/colr_test.ttf", "/tests/data/emoji_cbdt_test.ttf",
    "/tests/data/emoji_sbix_test.ttf", "/tests/data/svg_test.ttf"};
constexpr int kFirstColorFont = 4, kColorFonts = 4;

Font* shipped(int which) {
    static std::unique_ptr<Font> fonts[kFontFiles];
    if (!fonts[which])
        fonts[which] = std::make_unique<Font>(Font::load(std::string(CASTELJAU_SOURCE_DIR) + kFiles[which]));
    return fonts[which].get();
}

const std::vector<std::uint8_t>& file_bytes(int which) {
    static std::vector<std::uint8_t> bytes[kFontFiles];
    if (bytes[which].empty()) {
        std::ifstream f(std::string(CASTELJAU_SOURCE_DIR) + kFiles[which], std::ios::binary);
        bytes[which].assign(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
    }
    return bytes[which];
}

std::uint32_t be32(const std::vector<std::uint8_t>& b, std::size_t o) {
    return static_cast<std::uint32_t>(b[o]) << 24 | static_cast<std::uint32_t>(b[o + 1]) << 16 |
           static_cast<std::uint32_t>(b[o + 2]) << 8 | b[o + 3];
}

// A colour test font with up to 32 bytes of its colour tables replaced: each patch is a table
// (of those the font has), an offset into it and a value.
std::vector<std::uint8_t> mutated_color_font(int which, fuzz::Bytes& in) {
    std::vector<std::uint8_t> font = file_bytes(which);
    std::vector<std::pair<std::size_t, std::size_t>> tables;  // offset, length
    const std::size_t count = font.size() >= 12 ? (font[4] << 8 | font[5]) : 0;
    for (std::size_t i = 0; i < count && 12 + 16 * i + 16 <= font.size(); ++i) {
        const std::size_t rec = 12 + 16 * i;
        const std::uint32_t tag = be32(font, rec), off = be32(font, rec + 8), len = be32(font, rec + 12);
        const bool color = tag == 0x434f4c52u /*COLR*/ || tag == 0x4350414cu /*CPAL*/ || tag == 0x43424454u /*CBDT*/ ||
                           tag == 0x43424c43u /*CBLC*/ || tag == 0x73626978u /*sbix*/ || tag == 0x53564720u /*SVG */;
        if (color && len > 0 && off + len <= font.size()) tables.emplace_back(off, len);
    }
    if (tables.empty()) return font;
    const int patches = in.range(0, 32);
    for (int p = 0; p < patches; ++p) {
        const auto& [off, len] = tables[static_cast<std::size_t>(in.range(0, static_cast<int>(tables.size()) - 1))];
        const std::size_t at = off + static_cast<std::size_t>(in.range(0, 1 << 20)) % len;
        font[at] = in.byte();
    }
    return font;
}

std::string token(fuzz::Bytes& in, std::size_t max) {
    std::string s;
    const std::size_t n = static_cast<std::size_t>(in.range(0, static_cast<int>(max)));
    for (std::size_t i = 0; i < n; ++i) s += static_cast<char>(in.byte());
    return s;
}

void exercise(Font& font, fuzz::Bytes& in) {
    TextStyle style;
    style.size = in.flag() ? in.number(200) : in.range(1, 200);
    style.line_height = in.flag() ? in.number(4) : 1.0;
    style.align = static_cast<TextAlign>(in.range(0, 3));
    style.direction = static_cast<TextDirection>(in.range(0, 2));
    style.max_width = in.flag() ? in.range(0, 400) : 0;
    if (in.flag()) style.features.push_back(token(in, 12));
    if (in.flag()) style.script = token(in, 5);
    if (in.flag()) style.language = token(in, 6);
    style.system_fonts = in.flag();
    const int palette = in.range(0, 3);
    if (font.is_variable() && in.flag()) {
        fuzz::run([&] {
            const Variation v = parse_variation(token(in, 16));
            font.set_variations(std::span<const Variation>(&v, 1));
        });
    }
    const std::string_view text = in.rest().substr(0, 4096);
    fuzz::run([&] {
        const TextLayout layout = layout_text(text, font, style);
        for (const PositionedGlyph& g : layout.glyphs)
            fuzz::require(g.font < layout.fonts.size() && g.glyph < layout.fonts[g.font]->glyph_count(),
                          "a laid-out glyph does not index its font");
        GlyphCache cache(1u << 20);
        Rasterizer raster;
        std::size_t drawn = 0;
        for (const PositionedGlyph& g : layout.glyphs) {
            if (++drawn > 64) break;
            (void)cache.mask(*layout.fonts[g.font], g.glyph, std::min(style.size, 256.0), Point{0.25, 0.5}, raster);
        }
        // Drawn too (colour glyphs go through their own path), on a small canvas, when short.
        if (layout.glyphs.size() <= 32) {
            Pixmap pm(160, 96);
            Canvas canvas(pm);
            TextDrawOptions options;
            options.palette = palette;
            draw_text(canvas, layout, {-layout.ink.x0, -layout.ink.y0}, Paint::solid(Color::rgba(20, 40, 200)), &cache,
                      options);
            canvas.rotate(0.3);
            draw_text(canvas, layout, {0, 0}, Paint::solid(Color::black()), &cache, options);
        }
    });
    font.reset_variations();
}

}  // namespace

// LeakSanitizer (sanitizer builds): fontconfig 2.14 loses a pattern while parsing its
// configuration files, once per configuration loaded (288 bytes here); system font fallback loads
// one per process. Not casteljau's memory, so not reported.
extern "C" const char* __lsan_default_suppressions() { return "leak:libfontconfig.so\n"; }

// fontconfig is started by a system fallback layout before any input runs, so that the per-input
// leak check sees only what the inputs allocate, not fontconfig's configuration and caches.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    enable_svg_glyphs();
    TextStyle style;
    style.system_fonts = true;
    try {
        (void)layout_text("a\u65e5\U0001F600", *shipped(0), style);
    } catch (const Error&) {}
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    fuzz::Bytes in(data, size);
    const std::uint8_t which = in.byte();
    if (which == 255) {
        fuzz::run([&] {
            const std::string_view bytes = in.rest();
            Font font = Font::from_memory(std::vector<std::uint8_t>(bytes.begin(), bytes.end()));
            fuzz::Bytes style(reinterpret_cast<const std::uint8_t*>("\x10\x00\x00\x00Hello"), 9);
            exercise(font, style);
        });
        return 0;
    }
    if (which >= 200 && which < 230) {
        // A colour font with patched colour tables.
        fuzz::run([&] {
            Font font = Font::from_memory(mutated_color_font(kFirstColorFont + (which - 200) % kColorFonts, in));
            exercise(font, in);
        });
        return 0;
    }
    Font* font = shipped(which % kFontFiles);
    exercise(*font, in);
    return 0;
}
