// tests/support/glyph_outline.hpp: DejaVu Sans glyph outlines as casteljau Paths, loaded with FreeType
// directly (FT_Outline_Decompose, unhinted, font units), for the accuracy tests. Test-only.
//
// Font units are y-up; glyph_path() maps them to pixel space (y down) with the given size and
// baseline origin using its own arithmetic, so the Path handed to the rasterizer is in pixels.
#pragma once

#include <string>
#include <string_view>

#include "casteljau/path.hpp"

namespace casteljau::testing {

class GlyphFont {
public:
    explicit GlyphFont(const std::string& file);  // throws std::runtime_error when FreeType refuses
    ~GlyphFont();
    GlyphFont(const GlyphFont&) = delete;
    GlyphFont& operator=(const GlyphFont&) = delete;

    int units_per_em() const;
    // Appends the outline of `codepoint` at `px` pixels per em with its origin at `origin`
    // (baseline, pixel space) to `out`; returns the advance in pixels.
    double append_glyph(char32_t codepoint, double px, Point origin, Path& out) const;
    // A line of text (code points from UTF-32), advancing along the baseline; no kerning.
    Path text(std::u32string_view s, double px, Point origin) const;

private:
    struct Impl;
    Impl* impl_;
};

std::string dejavu_sans_path();  // CASTELJAU_SOURCE_DIR/fonts/DejaVuSans.ttf

}  // namespace casteljau::testing
