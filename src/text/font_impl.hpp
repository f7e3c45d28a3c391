// Internal: what a casteljau::Font holds (include/casteljau/font.hpp). Used by the text module only.
//
// A Font owns one FreeType library object, one face over the file bytes, and one HarfBuzz font
// built on that face with hb-ft. The face is sized once at `units_per_em` pixels per em, so that
// FreeType's 26.6 outlines and HarfBuzz's positions come out in 1/64 font units.
#pragma once

#include <ft2build.h>
#include FT_FREETYPE_H
#include <hb.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/font.hpp"

namespace casteljau {

struct Font::Impl {
    std::shared_ptr<const std::uint8_t> bytes;  // the font file: mapped, or a vector's data (from_memory)
    std::size_t size = 0;
    std::string source;
    int face_index = 0;
    int face_count = 1;
    FT_Library library = nullptr;
    FT_Face face = nullptr;
    hb_font_t* hb = nullptr;  // hb-ft font on `face` (hb-ot for bitmap_only); positions in 1/64 font units
    // Colour: a face with colour bitmaps and no outlines (CBDT, sbix) has its largest strike
    // selected instead of the em size; has_colr / has_color_bitmaps say which tables exist.
    bool bitmap_only = false;
    bool has_colr = false;
    bool has_color_bitmaps = false;
    bool has_svg = false;  // an 'SVG ' table (OpenType SVG glyph documents)
    // Decoded colour bitmaps, kept by src/text/color_glyphs.cpp (a Font serves one thread at a
    // time, so this needs no lock).
    std::shared_ptr<void> color_bitmap_cache;
    // The COLR table as src/text/colr_table.cpp reads it, loaded on first use.
    std::shared_ptr<void> colr_table;
    OutlineFormat format = OutlineFormat::Other;
    FontMetrics metrics;
    std::vector<VariationAxis> axes;
    std::vector<NamedInstance> instances;
    std::vector<double> coords;  // current design coordinates
    std::uint64_t var_key = 0;
    // Identity of this Font for caches: a cache holds a weak_ptr to it, so an entry made for a
    // destroyed Font is never mistaken for one of a new Font at the same address.
    std::shared_ptr<const int> token = std::make_shared<const int>(0);
    // A number no other Font of this process has had or will have (cache keys that outlive it).
    std::uint64_t serial = next_serial();

    Impl() = default;
    Impl(const Impl&) = delete;
    Impl& operator=(const Impl&) = delete;
    ~Impl();

    // Re-reads metrics and the variation key after the variation coordinates changed.
    void variations_changed();
    // Loads a glyph's unhinted outline into face->glyph; throws Error(Font).
    void load_glyph(std::uint32_t glyph) const;

private:
    static std::uint64_t next_serial();
};

// Font units per 1/64 unit: FreeType and HarfBuzz values are divided by this.
inline constexpr double kUnits26_6 = 64.0;

}  // namespace casteljau
