// Formats stage: OpenType SVG glyphs ('SVG ' table) drawn by the SVG reader, as the text stage's
// SVG glyph drawer (casteljau/text.hpp, SvgGlyphDrawer; installed by enable_svg_glyphs()).
//
// A glyph's document is read with export_id "glyphN", so only the glyph's element is drawn when
// the document holds several glyphs, and with no system fonts (glyph documents draw shapes). The
// document has no viewport of its own here: its user units are font units with y down, mapped by
// the transform the text stage gives, and nothing clips it but the pixmap the text stage draws
// it into. currentColor and context-fill are the text's colour (the foreground the text stage
// gives), as OpenType's SVG table asks of glyph documents; a `color` or fill the document sets
// itself wins. A document that cannot be read (malformed, no element for the glyph, beyond the
// SVG limits) is reported as not drawable, and the text stage fills the glyph's outline instead.
//
// Converted documents are kept, by the document key the text stage gives (the font's serial
// number, never reused in a process), the glyph and the colour, in a cache of kCachedGlyphs
// entries per process (emptied when full), so a glyph repeated in a text, or drawn again, is
// converted once.
// Thread-safety: the cache is locked; converted documents are immutable and drawn concurrently.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "casteljau/error.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/text.hpp"

namespace casteljau {

namespace {

constexpr std::size_t kCachedGlyphs = 512;

struct GlyphCacheState {
    std::mutex mutex;
    // Null: the document cannot be drawn.
    std::map<std::tuple<std::uint64_t, std::uint32_t, std::uint32_t>, std::shared_ptr<const SvgDocument>> entries;
};

GlyphCacheState& cache() {
    static GlyphCacheState state;
    return state;
}

// The converted document of `glyph` in text of colour `color`, or null when it cannot be drawn.
std::shared_ptr<const SvgDocument> convert_glyph(std::string_view document, std::uint64_t key, std::uint32_t glyph,
                                                 Color color) {
    GlyphCacheState& c = cache();
    const auto id = std::make_tuple(key, glyph,
                                    std::uint32_t{color.r} << 24 | std::uint32_t{color.g} << 16 |
                                        std::uint32_t{color.b} << 8 | std::uint32_t{color.a});
    {
        std::lock_guard<std::mutex> lock(c.mutex);
        const auto it = c.entries.find(id);
        if (it != c.entries.end()) return it->second;
    }
    SvgOptions options;
    options.export_id = "glyph" + std::to_string(glyph);
    options.system_fonts = false;
    options.color = color;
    options.context_fill = color;
    std::shared_ptr<const SvgDocument> drawn;
    try {
        drawn = std::make_shared<const SvgDocument>(SvgDocument::parse(document, options));
    } catch (const Error&) { drawn = nullptr; }
    std::lock_guard<std::mutex> lock(c.mutex);
    if (c.entries.size() >= kCachedGlyphs) c.entries.clear();
    c.entries[id] = drawn;
    return drawn;
}

bool draw_svg_glyph(Canvas& canvas, std::string_view document, std::uint64_t key, std::uint32_t glyph,
                    const Affine& font_to_canvas, Color foreground) {
    const std::shared_ptr<const SvgDocument> drawn = convert_glyph(document, key, glyph, foreground);
    if (!drawn) return false;
    drawn->render(canvas, font_to_canvas);
    return true;
}

}  // namespace

void enable_svg_glyphs() {
    if (svg_glyph_drawer() != &draw_svg_glyph) set_svg_glyph_drawer(&draw_svg_glyph);
}

}  // namespace casteljau
