// libFuzzer target: casteljau's own text glue over FreeType and HarfBuzz (src/text: font loading,
// variations, bidi, shaping, line layout, glyph outlines and masks). The first byte picks a
// shipped font (TrueType, CFF, Arabic, variable) or, at 255, reads the rest of the input as a font
// file; then come the style (size, direction, alignment, wrap width, features, script, language,
// variation settings) and the text, which may be any bytes (invalid UTF-8 included). FreeType's
// own parsing is FreeType's business; what is checked here is that our code ends every input in
// casteljau::Error or a layout whose glyphs all index its fonts.
#include <memory>
#include <string>
#include <vector>

#include "casteljau/font.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/text.hpp"
#include "harness.hpp"

using namespace casteljau;

namespace {

Font* shipped(int which) {
    static const char* kFiles[] = {"/fonts/DejaVuSans.ttf", "/fonts/LinLibertine_R.otf",
                                   "/fonts/NotoSansArabic-Regular.ttf", "/tests/data/Inter-roman.var.ttf"};
    static std::unique_ptr<Font> fonts[4];
    if (!fonts[which]) fonts[which] = std::make_unique<Font>(Font::load(std::string(CASTELJAU_SOURCE_DIR) + kFiles[which]));
    return fonts[which].get();
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
    });
    font.reset_variations();
}

}  // namespace

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
    Font* font = shipped(which % 4);
    exercise(*font, in);
    return 0;
}
