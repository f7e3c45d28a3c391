// casteljau/text.hpp: text. UTF-8 in, positioned glyphs out (shaping and layout), and drawing them
// on a Canvas through a glyph coverage cache or through outlines.
//
// Pipeline: UTF-8 --decode (invalid -> U+FFFD)--> paragraphs (split at \n, \r\n, \r, U+2029)
//   --> bidi levels (base direction from the first strong character or TextStyle::direction)
//   --> runs of one level, script and font (fallback: each character from the first font that has
//       it; marks, spaces and joiners stay with their base's font; with TextStyle::system_fonts a
//       cluster no font has comes from a system font found through fontconfig; .notdef of the
//       first font only when no font has it) --> HarfBuzz shaping per run (kerning, ligatures, marks, joining forms)
//   --> greedy line breaking at the opportunities of the Unicode line breaking algorithm (UAX #14,
//       ICU's line break iterator, tailored by TextStyle::language: CJK between characters, Thai
//       between words)
//   --> visual order per line (right-to-left runs reversed) --> alignment --> PositionedGlyphs.
// Drawing: glyph Paths (font.hpp) --glyph Affine--> Rasterizer::fill_mask --> GlyphCache --> the
//   Canvas's Pixmap (source-over of Paint x coverage); or, when the Canvas transform rotates, skews or
//   scales unevenly, each outline is filled with Canvas::fill_path under the full Affine. Colour
//   glyphs (COLR v0/v1 through the Canvas, CBDT/sbix bitmaps scaled by area averaging) are drawn in
//   their place in their palette's colours (TextDrawOptions::palette).
//
// Coordinates: a TextLayout is in "layout space": pixels, x right, y down, (0, 0) the top-left corner
// of the logical text box; line i's baseline is at ascender + i * line advance of the first font.
// draw_text() maps layout space by the Canvas's current transform after a translation to `origin`.
//
// Simplifications (documented limits): bidi is a subset of the Unicode algorithm (levels 0 to 2:
// strong letters, numbers, neutrals between them; no explicit embeddings/isolates); lines break only
// at the opportunities listed above (a word longer than the wrap width overflows its line); glyphs
// are not reshaped at line breaks (breaks fall between clusters, mostly at spaces);
// horizontal text only.
//
// Process-wide state: with TextStyle::system_fonts, fontconfig's configuration, its sorted font
// lists and the answers per cluster are cached for the life of the process (guarded by a mutex);
// each layout gets its own Font objects for the faces found.
//
// Thread-safety: layout_text() and draw_text() use the Fonts they are given (see font.hpp: one
// thread per Font at a time); a GlyphCache belongs to one thread at a time. TextLayouts are values
// but point at their Fonts, which must outlive them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/flatten.hpp"
#include "casteljau/font.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/raster.hpp"

namespace casteljau {

// Flattening tolerance (px) used for glyphs: the fills' default. Chosen from the coverage error it
// causes (tests/text/test_font.cpp, "The text tolerance keeps glyph masks ..."): against the exact
// area of DejaVu Sans and Linux Libertine glyphs at subpixel origins, from 9 to 256 px, the masks'
// mean error over the glyph set must stay within a quarter of FreeType's smooth rendering's and no
// pixel may be off by more than 6/255. Worst size at each tolerance (mean as a share of FreeType's,
// max): 0.005 px 0.12 / 2, 0.01 px 0.17 / 3, 0.015 px 0.22 / 6, 0.02 px 0.28 / 7. So 0.015 px is
// the largest that meets the bound. What it costs on single glyphs is small: the rendering furthest
// from FreeType's supersampled one, DejaVu's "(" at 9 px, is 0.49/255 from the exact area on
// average over its box (FreeType's own 0.30/255), at most 3/255. (The rasterizer's curve pieces are
// area-balanced, so small dots and rings do not come out thin.)
inline constexpr double kTextTolerance = kDefaultTolerance;

// Decodes UTF-8; each maximal invalid subsequence (and each encoded surrogate or value above
// U+10FFFF) becomes one U+FFFD, following the Unicode / WHATWG recommendation.
std::u32string decode_utf8(std::string_view utf8);

enum class TextDirection { Auto, LeftToRight, RightToLeft };
enum class TextAlign { Start, Left, Center, Right };  // Start: left for LTR paragraphs, right for RTL

struct TextStyle {
    double size = 16;          // pixels per em (check_font_size: 0 < size <= limits::kMaxFontSize)
    double line_height = 1.0;  // line advance as a multiple of the first font's line spacing (> 0)
    TextAlign align = TextAlign::Start;
    double max_width = 0;                           // wrap lines at word boundaries to this width in px; 0: no wrapping
    TextDirection direction = TextDirection::Auto;  // base direction of every paragraph
    std::string script;                             // ISO 15924 tag ("Latn", "Arab", "Hebr") for every run; "": detect
    std::string language;                           // BCP 47 tag ("en", "ar", "tr"); "": none
    std::vector<std::string> features;              // HarfBuzz feature strings, e.g. "kern=0", "liga=0", "smcp"
    // A cluster that no font of the chain has is looked for in the system's fonts (fontconfig):
    // the first face, in fontconfig's order for the first font's family (the generic family
    // "emoji" for clusters in emoji presentation), `language`, and the first font's weight and
    // slant, that has the whole cluster. Off: such clusters show the first font's .notdef, and the
    // output depends on the given fonts only.
    bool system_fonts = false;
};

struct PositionedGlyph {
    std::uint32_t glyph = 0;    // glyph id in the font
    std::uint16_t font = 0;     // index into TextLayout::fonts
    std::uint32_t cluster = 0;  // index into TextLayout::text of the first code point it shows
    Point position;             // glyph origin on the baseline, layout space
};

struct TextLine {
    std::size_t first_glyph = 0, glyph_count = 0;  // glyphs in visual order, left to right
    double baseline = 0;                           // y of the baseline
    double x = 0;                                  // left end of the line after alignment
    double width = 0;                              // advance width, trailing spaces excluded
    bool rtl = false;                              // the paragraph's base direction
    std::size_t text_begin = 0, text_end = 0;      // code point range of TextLayout::text on this line
};

struct TextLayout {
    // The chain given to layout_text (not owned: must outlive the layout), then the system fonts
    // fallback found (owned by the layout, through `system_fonts`).
    std::vector<const Font*> fonts;
    std::vector<std::shared_ptr<const Font>> system_fonts;
    double size = 0;
    std::u32string text;  // the decoded input (line breaks included)
    std::vector<PositionedGlyph> glyphs;
    std::vector<TextLine> lines;
    double width = 0;   // the box: the wrap width, or the widest line without wrapping
    double height = 0;  // first ascender to last descender, line advances between
    Rect ink;           // union of the glyph outlines' bounds; empty when nothing inks
    // The box united with the ink (both in layout space): what an image must hold to show it all.
    Rect bounds() const;
};

// Shapes and lays out `utf8` with a fallback chain of fonts (fonts[0] first; at least one). Throws
// Error(InvalidArgument) for no fonts, a bad size or line height, Error(Limit) past
// Limits::text_bytes or limits::kMaxFontSize, Error(Parse) for a bad feature or script string.
// Empty text gives a layout with no lines.
TextLayout layout_text(std::string_view utf8, std::span<const Font* const> fonts, const TextStyle& style);
TextLayout layout_text(std::string_view utf8, const Font& font, const TextStyle& style);

struct GlyphCacheStats {
    std::size_t hits = 0, misses = 0, entries = 0, bytes = 0, flushes = 0;
};

// Coverage masks of glyphs, keyed by (font, variation, glyph, size, subpixel offset), rasterized by
// casteljau's Rasterizer from the unhinted outline. When the masks exceed `max_bytes` the cache is
// emptied (cheap and predictable; a text's working set is small). Also keeps glyph outlines for the
// transformed-drawing path. An entry made for a Font that has been destroyed is never reused.
class GlyphCache {
public:
    // `tolerance`: flattening tolerance in pixels for the masks made by this cache.
    explicit GlyphCache(std::size_t max_bytes = 32u << 20, double tolerance = kTextTolerance);
    ~GlyphCache();
    GlyphCache(GlyphCache&&) noexcept;
    GlyphCache& operator=(GlyphCache&&) noexcept;

    // The glyph's coverage with its origin at `offset` (each coordinate in [0, 1) px): the mask's
    // bounds are relative to the integer pixel grid the origin sits in. Draw code passes offsets
    // quantized to a few steps per pixel, so that entries are reused. The reference stays valid
    // until the next call on this cache.
    const Mask& mask(const Font& font, std::uint32_t glyph, double size, Point offset, Rasterizer& raster);

    // The masks of several glyphs at once, in the order asked, as mask() gives them one by one.
    // Those not cached yet are rasterized in parallel on the process-wide pool
    // (casteljau/threads.hpp; `raster` serves the calling thread), their outlines read from the
    // fonts on the calling thread. The pointers stay valid until the next call on this cache.
    // Empty when the masks do not fit in the cache together (it was emptied while adding them):
    // then ask mask() for one glyph at a time.
    struct MaskRequest {
        const Font* font;
        std::uint32_t glyph;
        double size;
        Point offset;
    };
    std::vector<const Mask*> masks(std::span<const MaskRequest> requests, Rasterizer& raster);
    // The glyph's outline in font units (font.hpp), cached.
    const Path& outline(const Font& font, std::uint32_t glyph);

    void clear();
    std::size_t max_bytes() const;
    double tolerance() const;
    const GlyphCacheStats& stats() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

struct TextDrawOptions {
    // On the cached path glyph origins are rounded to 1/subpixel_steps px horizontally (1 to 64)
    // and to 1/subpixel_steps_y px vertically. The default snaps baselines to whole pixels: every
    // glyph of a line moves by the same amount, and each glyph needs 4 masks instead of 16.
    int subpixel_steps = 4;
    int subpixel_steps_y = 1;
    // Draw every glyph through its outline (Canvas::fill_path) even when the cache could be used.
    bool force_outlines = false;
    // Glyphs drawn through the cache up to this size in device pixels per em; larger ones go through
    // outlines (their masks would be large and rarely reused).
    double max_cached_size = 256;
    // Flattening tolerance (px) for glyphs drawn through outlines; cached masks use the cache's own.
    double tolerance = kTextTolerance;
    // CPAL palette of colour glyphs (palette 0 when the font has fewer). Colour glyphs (COLR v0
    // layers, COLR v1 paint graphs, CBDT/CBLC and sbix bitmaps) keep their palette's colours; the
    // Paint's colour stands for palette entry 0xFFFF and colours ordinary glyphs, its opacity
    // multiplies both.
    int palette = 0;
};

// Draws a layout with its box's top-left corner at `origin` (user space of the Canvas). When the
// Canvas transform is a translation plus a uniform positive scale, glyph masks come from `cache`
// (a temporary cache when null) and are composited directly; otherwise (rotation, skew, uneven or
// mirroring scale) each glyph's outline is filled with the full transform. `paint` supplies colour,
// opacity and Paint::linear_blend (gamma-correct coverage blending).
void draw_text(Canvas& canvas, const TextLayout& layout, Point origin, const Paint& paint, GlyphCache* cache = nullptr,
               const TextDrawOptions& options = {});

// Whether glyph `glyph` of `font` is a colour glyph (an OpenType SVG document while an SVG glyph
// drawer is set, COLR v0 layers, a COLR v1 paint graph, a CBDT/CBLC or sbix bitmap), which
// draw_text draws in its own colours instead of filling its outline. False for every glyph of a
// font without colour tables.
bool is_color_glyph(const Font& font, std::uint32_t glyph);

// OpenType SVG glyphs ('SVG ' table: Twitter Color Emoji, Twemoji Mozilla and other colour fonts)
// are SVG documents, which the text stage does not read itself: the SVG reader sits above it
// (casteljau/svg.hpp). draw_text hands them to the drawer set here, which enable_svg_glyphs()
// (casteljau/svg.hpp) installs; SvgDocument and the casteljau command install it. With no drawer
// set, such glyphs are drawn by their outlines (every SVG font has them).
// The drawer draws glyph `glyph` of `document` (the font's document for it, as stored: possibly
// gzip-compressed, possibly holding other glyphs; the glyph is its element with id "glyphN") on
// `canvas`, whose transform it leaves alone; `font_to_canvas` maps the document's user units
// (font units, y down, the glyph origin at 0,0) to the canvas's pixels; `foreground` is the
// text's colour (what the document's currentColor and context-fill mean). `document_key` and
// `glyph` name the document for caches: two calls with the same pair have the same document, for
// the life of the process (the key is the font's serial number, which no other font of the
// process gets). It returns false when it cannot draw the
// document (then the outline is filled).
// Thread-safety: set the drawer before drawing text on several threads; it must be callable from
// any thread.
using SvgGlyphDrawer = bool (*)(Canvas& canvas, std::string_view document, std::uint64_t document_key,
                                std::uint32_t glyph, const Affine& font_to_canvas, Color foreground);
void set_svg_glyph_drawer(SvgGlyphDrawer drawer);
SvgGlyphDrawer svg_glyph_drawer();

// Lays out `utf8` in one font with default style at `size` px and draws it with the box's top-left
// corner at `origin`. Returns the layout.
TextLayout draw_text(Canvas& canvas, std::string_view utf8, const Font& font, double size, Point origin,
                     const Paint& paint);

}  // namespace casteljau
