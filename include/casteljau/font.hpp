// casteljau/font.hpp: fonts. A Font reads one face of a font file through FreeType and hands out
// glyph outlines as casteljau Paths, glyph and font metrics, and variable-font settings.
//
// Formats: TrueType (glyf, quadratic outlines), OpenType CFF and CFF2 (cubic outlines), collections
// (.ttc/.otc, pick a face with `face_index`), variable fonts (fvar/gvar/CFF2 blends: named
// instances or axis values such as wght=700). Outlines are read unhinted
// (FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) and are never grid-fitted. A font of colour bitmaps
// without outlines (CBDT/CBLC or sbix, e.g. Noto Color Emoji) loads too: its glyphs have empty
// outlines, and their metrics are the bitmaps' boxes (text.hpp draws them in colour).
//
// Coordinates: glyph outlines and all metrics are in FONT UNITS, y up, the glyph origin at (0, 0) on
// the baseline (precision 1/64 unit). glyph_transform() gives the one Affine that maps font units to
// pixel space (x right, y down) for a size in pixels per em and an origin on the baseline: the y flip
// lives in that Affine only.
//
// Errors: a missing or unreadable file throws Error(Io); a file that is not a font, a truncated or
// corrupt font, a face index out of range, an unknown variation axis throw Error(Font), each with
// a one-line message naming the file.
//
// Thread-safety: a Font owns its own FreeType library object and face (no state is shared between
// Fonts), so distinct Fonts may be used from distinct threads at the same time. One Font is NOT
// safe to use from two threads at once, not even through const member functions (FreeType faces
// keep per-face scratch state). Font is move-only; clone() makes an independent copy that shares
// only the (immutable) file bytes.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/path.hpp"

namespace casteljau {

// Checks a font size in pixels per em: Error(InvalidArgument) when not finite or <= 0,
// Error(Limit) above limits::kMaxFontSize.
void check_font_size(double size_px);

enum class OutlineFormat { TrueType, CFF, CFF2, Other };

// Font-wide metrics in font units, y up, for the current variation.
struct FontMetrics {
    int units_per_em = 1000;
    double ascender = 0;   // top of the line box above the baseline (> 0)
    double descender = 0;  // bottom of the line box (usually < 0)
    double line_gap = 0;
    double underline_position = 0, underline_thickness = 0;
    double strikeout_position = 0, strikeout_thickness = 0;  // line-through: centre above the baseline
    double x_height = 0, cap_height = 0;                     // OS/2 values, or HarfBuzz's estimates from the glyphs
    double subscript_offset = 0, superscript_offset = 0;     // OS/2: baseline shift down / up
    // Distance between consecutive baselines: ascender - descender + line_gap.
    double line_spacing() const { return ascender - descender + line_gap; }
};

// Metrics of one glyph in font units, y up, for the current variation.
struct GlyphMetrics {
    double advance = 0;        // horizontal advance
    double left_bearing = 0;   // bounds.x0: from the origin to the left edge of the outline
    double right_bearing = 0;  // advance - bounds.x1
    Rect bounds;               // tight bounds of the outline (y0 = bottom, y1 = top); empty for blanks
};

struct VariationAxis {
    std::string tag;   // four characters, e.g. "wght"
    std::string name;  // e.g. "Weight"
    double minimum = 0, default_value = 0, maximum = 0;
    bool hidden = false;
};

struct NamedInstance {
    std::string name;                 // e.g. "Bold" (subfamily name from the name table)
    std::vector<double> coordinates;  // one per axis, in design units
};

// One axis setting, e.g. {"wght", 700}.
struct Variation {
    std::string tag;
    double value = 0;
    bool operator==(const Variation&) const = default;
};

// Parses "TAG=VALUE" (tag of 1 to 4 printable ASCII characters, padded with spaces as OpenType
// does; value a finite number). Throws Error(Parse).
Variation parse_variation(std::string_view text);

class Font {
public:
    // Reads a font file; `face_index` picks the face in a collection. A regular file is mapped
    // read-only rather than copied (FIFOs and other files are read whole): as with FreeType's own
    // FT_New_Face, it must not be truncated or rewritten in place while the Font or its clones live
    // (replacing it by rename is safe).
    static Font load(const std::string& path, int face_index = 0);
    // Same from bytes in memory; `name` is used in error messages.
    static Font from_memory(std::vector<std::uint8_t> bytes, int face_index = 0, std::string name = "<memory>");

    Font(Font&&) noexcept;
    Font& operator=(Font&&) noexcept;
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;
    ~Font();

    // An independent Font over the same bytes and face, with the same variation settings.
    Font clone() const;

    const std::string& source() const;  // file path (or the name given to from_memory)
    int face_index() const;
    int face_count() const;  // faces in the file (1 unless it is a collection)
    std::string family_name() const;
    std::string style_name() const;
    OutlineFormat outline_format() const;
    int units_per_em() const;
    std::uint32_t glyph_count() const;
    const FontMetrics& metrics() const;

    // Glyph id of a Unicode code point through the font's cmap; 0 (.notdef) when the font lacks it.
    std::uint32_t glyph_index(char32_t codepoint) const;
    bool has_glyph(char32_t codepoint) const { return glyph_index(codepoint) != 0; }

    // Unhinted outline of a glyph in font units (y up); contours closed. Throws Error(Font) for a
    // glyph id >= glyph_count() or a glyph FreeType cannot load.
    Path glyph_path(std::uint32_t glyph) const;
    void glyph_path(std::uint32_t glyph, Path& out) const;  // same, into `out` (cleared first)
    GlyphMetrics glyph_metrics(std::uint32_t glyph) const;

    // Font units -> pixels: scale by size_px / units_per_em, flip y, put the glyph origin at `origin`.
    // Checks the size (check_font_size).
    Affine glyph_transform(double size_px, Point origin = {}) const;

    // Variable fonts. set_variations() sets the listed axes (others go back to their defaults);
    // values outside an axis's range are clamped to it (as CSS and FreeType do); an axis the font
    // does not have, or any variation on a font that is not variable, throws Error(Font) listing
    // the font's axes.
    bool is_variable() const;
    const std::vector<VariationAxis>& axes() const;
    const std::vector<NamedInstance>& named_instances() const;
    void set_variations(std::span<const Variation> settings);
    void set_named_instance(std::size_t index);      // Error(Font) when out of range
    void set_named_instance(std::string_view name);  // case-insensitive; Error(Font) when absent
    void reset_variations();
    std::vector<double> variation_coordinates() const;  // design coordinates, one per axis
    // A hash of the current coordinates; 0 for a font that is not variable. Changes whenever the
    // outlines may change: glyph caches key on it.
    std::uint64_t variation_key() const;

    // Internal: the FreeType/HarfBuzz objects, for the text module (src/text/font_impl.hpp).
    struct Impl;
    Impl& impl() const { return *impl_; }

private:
    explicit Font(std::unique_ptr<Impl> impl);
    static Font from_shared_bytes(std::shared_ptr<const std::uint8_t> bytes, std::size_t size, int face_index,
                                  std::string name);
    std::unique_ptr<Impl> impl_;
};

// Sets each of `settings` on every font of `fonts` that has its axis, as a fallback chain shares
// them (a font without the axis is left as it is). A setting whose axis none of the fonts has
// throws Error(Font) naming the fonts' axes, before any font changes.
void set_chain_variations(std::span<Font* const> fonts, std::span<const Variation> settings);

}  // namespace casteljau
