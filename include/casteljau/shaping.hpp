// casteljau/shaping.hpp: the steps of text layout below layout_text() (text.hpp), for readers that
// place glyphs themselves (SVG text): bidi levels and visual order, HarfBuzz shaping of a
// paragraph with font fallback, and which scripts letter-spacing may pull apart.
//
// The bidi algorithm is the subset text.hpp describes (levels 0 to 2, no explicit embeddings).
// A TextShaper splits a paragraph into runs of one bidi level, one script and one font of its
// fallback chain (then of the system's fonts, through a SystemFontFallback), and shapes each run with the whole paragraph as context (so Arabic joining and
// kerning see across run edges), in the run's direction.
//
// Coordinates: ShapedGlyph advances and offsets are pixels at TextStyle::size, x right and y UP
// (HarfBuzz's convention); clusters and run bounds are code point indices into the paragraph.
//
// Thread-safety: the free functions may be called from any thread. A TextShaper belongs to one
// thread at a time and uses its Fonts (one thread per Font at a time, font.hpp), which must
// outlive it. A SystemFontFallback belongs to one thread at a time (with the shapers using it);
// its process-wide caches are those text.hpp describes, guarded by a mutex.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/font.hpp"
#include "casteljau/text.hpp"

namespace casteljau {

// Fills `levels` (one per code point of `paragraph`) with bidi levels 0 (LTR), 1 (RTL) or 2 (LTR
// numbers or Latin inside RTL) and returns the paragraph level (0 or 1).
int resolve_bidi_levels(std::u32string_view paragraph, TextDirection direction, std::vector<std::uint8_t>& levels);

// The visual order (left to right) of items with the given levels, by rule L2 of UAX #9: from the
// highest level down to the lowest odd level, every maximal run of items at that level or above is
// reversed. order[i] is the index of the item drawn i-th.
void bidi_visual_order(std::span<const std::uint8_t> levels, std::vector<std::size_t>& order);

// False for letters of scripts that join or hang from a line (Arabic, Devanagari, ...): letter
// spacing would break them apart (CSS Text 3, 8.2).
bool letter_spacing_allowed(char32_t c);

struct ShapedGlyph {
    std::uint32_t glyph = 0;
    std::uint16_t font = 0;     // index into TextShaper::fonts()
    std::uint32_t cluster = 0;  // code point index in the paragraph
    double advance = 0;         // px
    double x_offset = 0;        // px, x right
    double y_offset = 0;        // px, y UP (HarfBuzz's convention)
    double y_advance = 0;       // px, y UP: vertical text only (negative: the pen moves down)
};

struct ShapedRun {
    std::uint32_t begin = 0, end = 0;  // code point range in the paragraph
    std::uint8_t level = 0;
    std::uint16_t font = 0;
    std::vector<ShapedGlyph> glyphs;  // visual order
};

// The system font fallback of layout_text (TextStyle::system_fonts) for TextShapers: a cluster
// that no font of a shaper's chain has comes from the first face, in fontconfig's order for the
// base font's family (the generic family "emoji" for clusters in emoji presentation), the
// language and the base font's weight and slant, that has the whole cluster. One object serves any
// number of shapers with that base and language; the Fonts it loads live as long as it does.
class SystemFontFallback {
public:
    // `base`: the font whose family, weight and slant the fallback faces should match (read here
    // only); `language`: a BCP 47 tag or "".
    SystemFontFallback(const Font& base, std::string language);
    ~SystemFontFallback();
    SystemFontFallback(const SystemFontFallback&) = delete;
    SystemFontFallback& operator=(const SystemFontFallback&) = delete;

private:
    friend class TextShaper;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

class TextShaper {
public:
    // `fonts`: the fallback chain, first choice first (each character from the first font that has
    // it). Validates the style's script, language and features (Error(Parse)). `vertical`: shape
    // top to bottom (vertical metrics and the 'vert' feature) instead of by the bidi levels; glyphs
    // then advance by y_advance. `system`: where a cluster no font of the chain has finds a font
    // (it must outlive the shaper); null: nowhere, the cluster shows the first font's .notdef
    // (TextStyle::system_fonts is not read here).
    TextShaper(std::span<const Font* const> fonts, const TextStyle& style, bool vertical = false,
               SystemFontFallback* system = nullptr);
    ~TextShaper();
    TextShaper(const TextShaper&) = delete;
    TextShaper& operator=(const TextShaper&) = delete;

    // Shapes `paragraph` (tabs already replaced) with its bidi levels into `runs` (logical order).
    void shape_paragraph(std::u32string_view paragraph, std::span<const std::uint8_t> levels,
                         std::vector<ShapedRun>& runs);
    // The chain followed by the system fonts used so far, in the order first used:
    // ShapedGlyph::font and ShapedRun::font index it.
    const std::vector<const Font*>& fonts() const;

private:
    class Impl;  // the HarfBuzz buffer, features, script and language
    std::unique_ptr<Impl> impl_;
};

}  // namespace casteljau
