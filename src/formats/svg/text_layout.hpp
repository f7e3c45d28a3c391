// Internal (formats): SVG text layout. The SVG conversion (text.cpp) turns a <text> element into a
// TextInput (characters after white-space processing, grouped into spans of one style, with the
// per-character x/y/dx/dy/rotate values, text paths and textLength ranges); layout() shapes it
// with casteljau's text engine (HarfBuzz through casteljau/shaping.hpp, fonts from a FontDatabase,
// optionally the system fallback of casteljau text)
// and returns glyph outlines and decoration lines in the text's user space, which the reader
// paints like any shape.
//
// Coordinates: user units of the <text> element, y down; glyph outlines are font units scaled by
// font-size / units-per-em and flipped.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "casteljau/font.hpp"
#include "casteljau/font_database.hpp"
#include "casteljau/path.hpp"
#include "casteljau/shaping.hpp"
#include "casteljau/text.hpp"

namespace casteljau::svg_text {

enum class Anchor { Start, Middle, End };
enum class Baseline { Alphabetic, Middle, Central, Hanging, Mathematical, TextTop, TextBottom, Ideographic };

struct FontSpec {
    std::vector<std::string> families;  // generic names already replaced by real ones
    int weight = 400;
    FontSlant slant = FontSlant::Normal;
    double stretch = 100;
    double size = 12;                   // px per em in user units
    std::vector<std::string> features;  // HarfBuzz feature strings
    std::vector<Variation> variations;  // font-variation-settings
};

struct Decoration {
    enum Kind { Underline, Overline, LineThrough } kind = Underline;
    std::size_t style = 0;  // paint of the element that declared it
};

// Characters of one text node, with the computed style of its element.
struct Span {
    std::size_t style = 0;  // the reader's paint style for this span
    FontSpec font;
    std::u32string text;
    double letter_spacing = 0, word_spacing = 0;
    Anchor anchor = Anchor::Start;
    Baseline baseline = Baseline::Alphabetic;
    // baseline-shift of the tspans around the span (outermost first): a length in px (positive
    // up), or the font's subscript (kind 1) or superscript (kind 2) offset.
    struct Shift {
        int kind = 0;
        double value = 0;
    };
    std::vector<Shift> baseline_shifts;
    std::vector<Decoration> decorations;
    int path = -1;          // index into TextInput::paths, or -1
    int path_element = -1;  // which textPath element (each starts a new chunk)
};

struct CharPos {
    std::optional<double> x, y, dx, dy, rotate;  // rotate in degrees
};

struct TextPath {
    Path path;                // user space of the text
    double start_offset = 0;  // px along the path (percentages resolved)
};

struct LengthRange {
    std::size_t begin = 0, end = 0;  // character range
    double length = 0;
    bool spacing_and_glyphs = false;
};

struct TextInput {
    std::vector<Span> spans;
    std::vector<CharPos> pos;  // one per character of all spans, in order
    std::vector<TextPath> paths;
    std::vector<LengthRange> lengths;
    TextDirection direction = TextDirection::LeftToRight;
    bool vertical = false;
};

struct Outline {
    enum Layer { Under, Glyphs, Over } layer = Glyphs;  // underline/overline, glyphs, line-through
    std::size_t style = 0;
    Path path;
};

// A colour glyph (COLR layers or paint graph, CBDT or sbix bitmap), drawn in its own colours
// rather than filled and stroked: `transform` maps its origin-relative layout space (y down,
// px of `size` per em) to the text's user space.
struct ColorGlyph {
    std::size_t style = 0;
    std::shared_ptr<const Font> font;
    std::uint32_t glyph = 0;
    double size = 0;
    Affine transform;
};

// The fonts of one document: faces from a FontDatabase, opened once each (per variation), and,
// with `system_fallback`, the system's fonts through fontconfig for characters none of them has.
class FontSet {
public:
    explicit FontSet(std::shared_ptr<const FontDatabase> db, bool system_fallback = false)
        : db_(std::move(db)), system_fallback_(system_fallback) {}
    // Fonts for `spec` that together cover `text` as far as the database can: the faces of the
    // listed families, then per-character fallback faces (with system fallback, only the faces
    // of the folders and files given: fontconfig's fallback comes after them, see system()).
    // Empty when the database has no fonts.
    std::vector<const Font*> chain(const FontSpec& spec, std::u32string_view text);
    // The system fallback for chains whose first font is `base` (null without system fallback),
    // the same object for every chain with that first font: the faces it loads are loaded once
    // per document and live as long as this FontSet.
    SystemFontFallback* system(const Font& base);
    // `font` as a shared pointer when it is one of this set's faces (null for a system fallback
    // face), so that what is drawn later can keep it alive.
    std::shared_ptr<const Font> shared(const Font* font) const;

private:
    const Font* face(std::size_t index, const FontSpec& spec);
    std::shared_ptr<const FontDatabase> db_;
    bool system_fallback_ = false;
    std::map<std::pair<std::size_t, std::string>, std::shared_ptr<Font>> fonts_;
    std::vector<std::size_t> broken_;
    std::map<const Font*, std::unique_ptr<SystemFontFallback>> system_;
};

// Lays out and outlines `in`. Warnings (missing fonts) go to `warnings`. `box`, when given,
// receives the union of the glyph cells (advance by ascender to descender): the text's bounding
// box for objectBoundingBox units, as resvg and browsers take it (not the ink's).
// Colour glyphs go to `color` when it is given (their outlines, if any, are then left out), else
// their outlines are filled like any glyph's.
std::vector<Outline> layout(const TextInput& in, FontSet& fonts, std::vector<std::string>& warnings,
                            std::optional<Rect>* box = nullptr, std::vector<ColorGlyph>* color = nullptr);

}  // namespace casteljau::svg_text
