// bench/glyph_set.hpp: the glyph outlines every benchmark renders, loaded once with FreeType.
//
// The set is DejaVu Sans (fonts/DejaVuSans.ttf), every glyph for U+0021..U+007E and U+00A1..U+017F,
// loaded unhinted (FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) at a pixel size. Each glyph keeps
//   - its FreeType outline (26.6 pixels, y up), translated so that its box starts at (0, 0), ready
//     for FT_Outline_Render into a bitmap of the box;
//   - the same outline as a casteljau::Path (conic -> quad_to, cubic -> cubic_to) in 26.6 units,
//     y up, untranslated, plus the Affine that maps it onto the box in pixel space (x right, y down,
//     origin at the box's top-left corner), so every renderer sees exactly the same geometry;
//   - its box: the control box of the outline rounded outwards to whole pixels (FreeType's rule),
//     relative to the pen origin with y down.
// All conversion happens here, outside any timed region.
// Thread-safety: a GlyphSet is not shared between threads.
#pragma once

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "casteljau/path.hpp"
#include "casteljau/raster.hpp"

namespace bench {

// Codepoints of the benchmark set: U+0021..U+007E and U+00A1..U+017F.
std::vector<std::uint32_t> benchmark_codepoints();

// The font file: an FT_Library with the face opened on it, plus the file's bytes (stb_truetype
// reads the font from memory). Not copyable.
class Font {
public:
    explicit Font(const std::string& path = CASTELJAU_BENCH_FONT);
    ~Font();
    Font(const Font&) = delete;
    Font& operator=(const Font&) = delete;

    FT_Library library() const { return lib_; }
    FT_Face face() const { return face_; }
    const std::vector<unsigned char>& bytes() const { return bytes_; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::vector<unsigned char> bytes_;
    FT_Library lib_ = nullptr;
    FT_Face face_ = nullptr;
};

struct Box {
    int x0 = 0, y0 = 0;  // top-left pixel relative to the pen origin, y down
    int width = 0, height = 0;
    std::size_t pixels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
};

struct Glyph {
    std::uint32_t codepoint = 0;
    unsigned glyph_index = 0;
    Box box;
    FT_Outline outline{};      // owned copy, translated: box's bottom-left corner at (0, 0)
    casteljau::Path path;      // 26.6 units, y up, as loaded
    casteljau::Affine to_box;  // path -> box pixels (y down, origin at the box's top-left)
    std::size_t curves = 0;    // quadratic + cubic segments in the outline
};

// All glyphs of the benchmark set at one pixel size (ppem). Glyphs with an empty outline are left out.
class GlyphSet {
public:
    GlyphSet(const Font& font, int pixel_size);
    ~GlyphSet();
    GlyphSet(const GlyphSet&) = delete;
    GlyphSet& operator=(const GlyphSet&) = delete;

    int pixel_size() const { return px_; }
    const std::vector<Glyph>& glyphs() const { return glyphs_; }
    std::size_t size() const { return glyphs_.size(); }
    std::size_t max_box_pixels() const { return max_pixels_; }
    int max_width() const { return max_w_; }
    int max_height() const { return max_h_; }
    std::size_t total_box_pixels() const { return total_pixels_; }
    const Font& font() const { return font_; }

private:
    const Font& font_;
    int px_;
    std::vector<Glyph> glyphs_;
    std::size_t max_pixels_ = 0, total_pixels_ = 0;
    int max_w_ = 0, max_h_ = 0;
};

// A rendered glyph as some renderer left it: `data` covers `box` with `stride` bytes per row.
struct Coverage {
    const std::uint8_t* data = nullptr;
    int stride = 0;
    Box box;
    std::uint8_t at(int x, int y) const {  // x, y relative to the pen origin, y down; 0 outside
        const int lx = x - box.x0, ly = y - box.y0;
        if (lx < 0 || ly < 0 || lx >= box.width || ly >= box.height) return 0;
        return data[static_cast<std::size_t>(ly) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(lx)];
    }
};

// Per-pixel comparison of two renders of one glyph over the union of their boxes.
struct DiffStats {
    double sum = 0;          // sum of |a - b| in 1/255 units
    std::size_t pixels = 0;  // pixels compared
    int max = 0;
    std::size_t over1 = 0;    // pixels with |a - b| > 1
    std::size_t changed = 0;  // pixels with a != b
    void add(const Coverage& a, const Coverage& b);
    void merge(const DiffStats& o);
    double mean() const { return pixels ? sum / static_cast<double>(pixels) : 0.0; }
};

// FreeType's smooth rasterizer (FT_Outline_Render, FT_RASTER_FLAG_AA) of `outline` (26.6, y up, box
// corner at (0, 0)) into a gray8 bitmap of width x height at buf (width bytes per row; FreeType only
// writes covered spans, so clear it first).
void render_freetype(FT_Library lib, const FT_Outline& outline, int width, int height, std::uint8_t* buf);

// A comma-separated list of pixel sizes ("12,24,48"); empty when an entry is not in 1..1000.
std::vector<int> parse_sizes(const std::string& list);

// The options every side-by-side program takes: --quick (one run of one pass: a smoke test, no
// timing claims), --runs R (best of R rounds), --min-time S (seconds per round at least),
// --sizes 12,24,... Programs derive their Options from it.
struct CommonOptions {
    bool quick = false;
    int runs = 7;
    double min_time = 0.15;
    std::vector<int> sizes{12, 24, 48, 96, 256};
    // When argv[i] is one of these options, reads it (and its value: i moves past it) and returns
    // true; a missing or bad value goes to usage(), which does not return.
    bool parse_common(int argc, char** argv, int& i, void (*usage)(const char*));
};

// Copies the rasterizer's rows into a caller's 8-bit buffer (`stride` bytes per row, pixel
// (0, 0) at buf[0]). Given its height, it offers the buffer as the fill's direct target, as
// Rasterizer::fill_mask's sink does (the buffer must then be zeroed before each fill).
class BufferSink final : public casteljau::SpanSink {
public:
    BufferSink() = default;
    BufferSink(std::uint8_t* b, int s) : buf(b), stride(s) {}
    std::uint8_t* buf = nullptr;
    int stride = 0;
    int height = 0;  // 0: no direct target
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        std::memcpy(buf + static_cast<std::size_t>(y) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(x),
                    coverage, static_cast<std::size_t>(length));
    }
    casteljau::CoverageTarget target() override {
        if (height <= 0) return {};
        return {buf, stride, casteljau::IRect{0, 0, stride, height}};
    }
};

}  // namespace bench
