// bench/renderer.hpp: one glyph renderer in the side-by-side comparison (compare_glyphs.cpp).
//
// prepare() runs outside the timed region: it converts the outlines into the renderer's own path
// type and allocates every buffer. render(i) is what is timed: it produces the complete 8-bit
// coverage of glyph i's box (clearing its buffer first when the library only writes covered spans)
// and returns where that coverage is. Each renderer owns its buffers and reuses them.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "glyph_set.hpp"

namespace bench {

class Renderer {
public:
    virtual ~Renderer() = default;
    virtual std::string name() const = 0;
    virtual std::string version() const { return {}; }
    virtual void prepare(const GlyphSet& set) = 0;
    virtual Coverage render(std::size_t i) = 0;
};

// Peers, each compiled only when the library was found (see bench/CMakeLists.txt).
std::unique_ptr<Renderer> make_agg_renderer();
std::unique_ptr<Renderer> make_cairo_renderer();
// `from_font`: stbtt_MakeGlyphBitmap (reads the glyph from the font file on every call, its own
// box, its own unhinted scaling); otherwise stbtt_Rasterize on shapes parsed in prepare(), into
// the same box as everybody else.
std::unique_ptr<Renderer> make_stb_renderer(bool from_font);

}  // namespace bench
