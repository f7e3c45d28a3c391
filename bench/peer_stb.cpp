// bench/peer_stb.cpp: stb_truetype (rasterizer version 2, exact-area like casteljau; flattening
// at its own default of 0.35 px) as a peer, in two forms:
//   "stb_truetype": stbtt_Rasterize on glyph shapes parsed in prepare() (stbtt_GetGlyphShape),
//        scaled by ppem / unitsPerEm (the same unhinted scaling FreeType uses) into the same box as
//        every other renderer: the rasterizer alone, comparable to the others.
//   "stb (from font)": stbtt_MakeGlyphBitmap as an stb user calls it: it parses the glyph from the
//        font bytes on every call and renders into its own box (stbtt_GetGlyphBitmapBox, computed in
//        prepare()); it includes the font parsing the others do not pay for.
// stb_truetype writes every pixel of the bitmap, so no clearing is needed. The implementation is
// compiled in this file with the same compiler and flags as casteljau.
#define STB_TRUETYPE_IMPLEMENTATION
#include <stb/stb_truetype.h>

#include <algorithm>
#include <stdexcept>

#include "renderer.hpp"

namespace bench {
namespace {

constexpr float kStbFlatness = 0.35f;  // what stbtt_MakeGlyphBitmap passes to stbtt_Rasterize

class StbRenderer final : public Renderer {
public:
    explicit StbRenderer(bool from_font) : from_font_(from_font) {}
    ~StbRenderer() override { release(); }
    std::string name() const override { return from_font_ ? "stb (from font)" : "stb_truetype"; }
    std::string version() const override { return "rasterizer v" + std::to_string(STBTT_RASTERIZER_VERSION); }

    void prepare(const GlyphSet& set) override {
        release();
        set_ = &set;
        const auto& bytes = set.font().bytes();
        if (!stbtt_InitFont(&info_, bytes.data(), stbtt_GetFontOffsetForIndex(bytes.data(), 0)))
            throw std::runtime_error("stbtt_InitFont failed");
        scale_ = stbtt_ScaleForMappingEmToPixels(&info_, static_cast<float>(set.pixel_size()));
        std::size_t max_pixels = 0;
        for (const Glyph& g : set.glyphs()) {
            Shape s;
            const int gi = static_cast<int>(g.glyph_index);
            if (from_font_) {
                int x0, y0, x1, y1;
                stbtt_GetGlyphBitmapBox(&info_, gi, scale_, scale_, &x0, &y0, &x1, &y1);
                s.box = {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
            } else {
                s.count = stbtt_GetGlyphShape(&info_, gi, &s.vertices);
                s.box = g.box;
            }
            max_pixels = std::max(max_pixels, s.box.pixels());
            shapes_.push_back(s);
        }
        buf_.assign(max_pixels, 0);
    }

    Coverage render(std::size_t i) override {
        const Shape& s = shapes_[i];
        const int gi = static_cast<int>(set_->glyphs()[i].glyph_index);
        if (s.box.width > 0 && s.box.height > 0) {
            if (from_font_) {
                stbtt_MakeGlyphBitmap(&info_, buf_.data(), s.box.width, s.box.height, s.box.width, scale_, scale_, gi);
            } else {
                stbtt__bitmap bm{s.box.width, s.box.height, s.box.width, buf_.data()};
                stbtt_Rasterize(&bm, kStbFlatness, s.vertices, s.count, scale_, scale_, 0, 0, s.box.x0, s.box.y0, 1,
                                nullptr);
            }
        }
        return {buf_.data(), s.box.width, s.box};
    }

private:
    struct Shape {
        stbtt_vertex* vertices = nullptr;
        int count = 0;
        Box box;
    };
    void release() {
        for (Shape& s : shapes_) stbtt_FreeShape(&info_, s.vertices);
        shapes_.clear();
    }

    bool from_font_;
    const GlyphSet* set_ = nullptr;
    stbtt_fontinfo info_{};
    float scale_ = 1;
    std::vector<Shape> shapes_;
    std::vector<std::uint8_t> buf_;
};

}  // namespace

std::unique_ptr<Renderer> make_stb_renderer(bool from_font) { return std::make_unique<StbRenderer>(from_font); }

}  // namespace bench
