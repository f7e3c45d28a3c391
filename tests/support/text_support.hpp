// Test helpers for the text area: paths of the shipped fonts, an independent FreeType rendering of
// glyphs (the reference our coverage is checked against), image comparison, and a builder of font
// collections (.ttc) from single fonts.
#pragma once

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#include FT_MULTIPLE_MASTERS_H

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/font.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/text.hpp"

namespace text_test {

inline std::string source_path(const std::string& rel) { return std::string(CASTELJAU_SOURCE_DIR) + "/" + rel; }
inline std::string font_path(const std::string& name) { return source_path("fonts/" + name); }
inline const std::string kDejaVu = font_path("DejaVuSans.ttf");
inline const std::string kLibertine = font_path("LinLibertine_R.otf");
inline const std::string kNotoArabic = font_path("NotoSansArabic-Regular.ttf");
inline const std::string kInterVar = source_path("tests/data/Inter-roman.var.ttf");

// System fonts the fallback tests use (Debian fonts-noto-color-emoji, fonts-noto-cjk) and a line
// that needs both beside Latin and Greek.
inline const std::string kNotoEmoji = "/usr/share/fonts/truetype/noto/NotoColorEmoji.ttf";
inline const std::string kNotoCjk = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc";
inline const char* const kMixedLine =
    "Hello \U0001F44B world \u2713 \u65E5\u672C\u8A9E \u0395\u03BB\u03BB\u03B7\u03BD\u03B9\u03BA\u03AC";

// The whole file as text ("" when it cannot be read).
inline std::string read_text(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

inline std::vector<std::uint8_t> read_bytes(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error("test: cannot read " + path);
    return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

inline void write_bytes(const std::string& path, const std::vector<std::uint8_t>& b) {
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

// An A8 image over a pixel rectangle (like casteljau::Mask, but filled by FreeType).
struct Gray {
    casteljau::IRect bounds;
    std::vector<std::uint8_t> data;
    std::uint8_t at(int x, int y) const {
        if (x < bounds.x0 || x >= bounds.x1 || y < bounds.y0 || y >= bounds.y1) return 0;
        return data[static_cast<std::size_t>(y - bounds.y0) * static_cast<std::size_t>(bounds.width()) +
                    static_cast<std::size_t>(x - bounds.x0)];
    }
};

// FreeType's own rendering of unhinted outlines, through its smooth rasterizer: the reference.
class FtRenderer {
public:
    explicit FtRenderer(const std::string& path, int face_index = 0) {
        if (FT_Init_FreeType(&lib_)) throw std::runtime_error("FT_Init_FreeType");
        if (FT_New_Face(lib_, path.c_str(), face_index, &face_)) throw std::runtime_error("FT_New_Face " + path);
    }
    ~FtRenderer() {
        FT_Done_Face(face_);
        FT_Done_FreeType(lib_);
    }
    FtRenderer(const FtRenderer&) = delete;
    FtRenderer& operator=(const FtRenderer&) = delete;
    FT_Face face() const { return face_; }

    // Sets design coordinates (variable fonts), in axis order.
    void set_variation(const std::vector<double>& coords) {
        std::vector<FT_Fixed> f;
        for (double c : coords) f.push_back(static_cast<FT_Fixed>(std::lround(c * 65536.0)));
        FT_Set_Var_Design_Coordinates(face_, static_cast<FT_UInt>(f.size()), f.data());
    }

    // Coverage of `glyph` at `size` px (a multiple of 1/64) with its origin at `origin` (pixel
    // space, y down; coordinates multiples of 1/64), over the glyph's pixel bounds.
    Gray render(std::uint32_t glyph, double size, casteljau::Point origin) {
        return render(glyph, size, casteljau::Affine{1, 0, 0, -1, origin.x, origin.y});
    }

    // Same with any transform `m` from the glyph's scaled outline (pixels, y UP, origin at 0) to
    // pixel space (y down): FreeType applies m's linear part (16.16) and its translation (26.6).
    Gray render(std::uint32_t glyph, double size, const casteljau::Affine& m) {
        const FT_F26Dot6 sz = static_cast<FT_F26Dot6>(std::lround(size * 64));
        if (FT_Set_Char_Size(face_, sz, sz, 72, 72)) throw std::runtime_error("FT_Set_Char_Size");
        if (FT_Load_Glyph(face_, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
            throw std::runtime_error("FT_Load_Glyph");
        FT_Outline* o = &face_->glyph->outline;
        Gray g;
        if (o->n_points == 0) return g;
        // Bounds in pixel space from the transformed control box.
        FT_BBox box;
        FT_Outline_Get_CBox(o, &box);
        casteljau::Rect r =
            casteljau::transform_bounds(m, {box.xMin / 64.0, box.yMin / 64.0, box.xMax / 64.0, box.yMax / 64.0});
        const int x0 = static_cast<int>(std::floor(r.x0)) - 1, x1 = static_cast<int>(std::ceil(r.x1)) + 1;
        const int y0 = static_cast<int>(std::floor(r.y0)) - 1, y1 = static_cast<int>(std::ceil(r.y1)) + 1;
        const int w = x1 - x0, h = y1 - y0;
        g.bounds = {x0, y0, x1, y1};
        g.data.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
        // FreeType's bitmap has row 0 at the top with y up: bitmap coordinates are
        // (X - x0, h - (Y - y0)) for pixel-space (X, Y) = m(x, y).
        if (!(m.a == 1 && m.b == 0 && m.c == 0 && m.d == -1)) {
            FT_Matrix mat;
            mat.xx = static_cast<FT_Fixed>(std::lround(m.a * 65536.0));
            mat.xy = static_cast<FT_Fixed>(std::lround(m.c * 65536.0));
            mat.yx = static_cast<FT_Fixed>(std::lround(-m.b * 65536.0));
            mat.yy = static_cast<FT_Fixed>(std::lround(-m.d * 65536.0));
            FT_Outline_Transform(o, &mat);
        }
        FT_Outline_Translate(o, std::lround((m.e - x0) * 64), std::lround((h + y0 - m.f) * 64));
        FT_Bitmap bm = FT_Bitmap{};
        bm.rows = static_cast<unsigned>(h);
        bm.width = static_cast<unsigned>(w);
        bm.pitch = w;
        bm.buffer = g.data.data();
        bm.num_grays = 256;
        bm.pixel_mode = FT_PIXEL_MODE_GRAY;
        if (FT_Outline_Get_Bitmap(lib_, o, &bm)) throw std::runtime_error("FT_Outline_Get_Bitmap");
        return g;
    }

    // The same rendering made at `k` times the size and origin, then box-filtered k x k down to
    // the pixel grid: exact-area coverage of FreeType's flattening at k times finer resolution, so
    // FreeType's own flattening error (up to 1/16 px for conics, more for cubics) shrinks k-fold.
    Gray render_supersampled(std::uint32_t glyph, double size, casteljau::Point origin, int k) {
        return downsample(render(glyph, size * k, casteljau::Point{origin.x * k, origin.y * k}), k);
    }
    // Same for a transformed glyph (see render(glyph, size, m)).
    Gray render_supersampled(std::uint32_t glyph, double size, const casteljau::Affine& m, int k) {
        return downsample(render(glyph, size, casteljau::Affine::scale(k) * m), k);
    }

    static Gray downsample(const Gray& big, int k) {
        Gray g;
        if (big.bounds.empty()) return g;
        auto fdiv = [k](int v) { return v >= 0 ? v / k : -((-v + k - 1) / k); };
        g.bounds = {fdiv(big.bounds.x0), fdiv(big.bounds.y0), fdiv(big.bounds.x1 - 1) + 1, fdiv(big.bounds.y1 - 1) + 1};
        g.data.assign(static_cast<std::size_t>(g.bounds.width()) * static_cast<std::size_t>(g.bounds.height()), 0);
        for (int y = g.bounds.y0; y < g.bounds.y1; ++y)
            for (int x = g.bounds.x0; x < g.bounds.x1; ++x) {
                int sum = 0;
                for (int sy = 0; sy < k; ++sy)
                    for (int sx = 0; sx < k; ++sx) sum += big.at(x * k + sx, y * k + sy);
                g.data[static_cast<std::size_t>(y - g.bounds.y0) * static_cast<std::size_t>(g.bounds.width()) +
                       static_cast<std::size_t>(x - g.bounds.x0)] =
                    static_cast<std::uint8_t>((sum + k * k / 2) / (k * k));
            }
        return g;
    }

private:
    FT_Library lib_ = nullptr;
    FT_Face face_ = nullptr;
};

struct DiffStats {
    double mean = 0;  // mean absolute difference over the union of both bounds, in 1/255 units
    int max = 0;      // largest absolute difference, in 1/255 units
    int max_x = 0, max_y = 0;
    long pixels = 0;
    long sum = 0;

    void add(int d, int x, int y) {  // one compared value, difference d, at pixel (x, y)
        sum += d;
        if (d > max) {
            max = d;
            max_x = x;
            max_y = y;
        }
        ++pixels;
    }
    void finish() { mean = pixels ? static_cast<double>(sum) / static_cast<double>(pixels) : 0; }
};

// The kind of casteljau::Error that f throws (its message into *message); fails the test if none.
inline casteljau::ErrorKind error_kind_of(const std::function<void()>& f, std::string* message = nullptr) {
    try {
        f();
    } catch (const casteljau::Error& e) {
        if (message) *message = e.what();
        return e.kind();
    }
    FAIL("no casteljau::Error thrown");
    return casteljau::ErrorKind::InvalidArgument;
}

template <class A, class B>
DiffStats compare_coverage(const A& a, const B& b) {
    DiffStats s;
    casteljau::IRect u = a.bounds;
    if (u.empty())
        u = b.bounds;
    else if (!b.bounds.empty())
        u = {std::min(u.x0, b.bounds.x0), std::min(u.y0, b.bounds.y0), std::max(u.x1, b.bounds.x1),
             std::max(u.y1, b.bounds.y1)};
    // Shrink to the ink box: the pixels where either image is nonzero (so that empty margins do
    // not dilute the mean).
    casteljau::IRect ink{u.x1, u.y1, u.x0, u.y0};
    for (int y = u.y0; y < u.y1; ++y)
        for (int x = u.x0; x < u.x1; ++x)
            if (a.at(x, y) || b.at(x, y)) {
                ink.x0 = std::min(ink.x0, x);
                ink.y0 = std::min(ink.y0, y);
                ink.x1 = std::max(ink.x1, x + 1);
                ink.y1 = std::max(ink.y1, y + 1);
            }
    u = ink;
    for (int y = u.y0; y < u.y1; ++y)
        for (int x = u.x0; x < u.x1; ++x)
            s.add(std::abs(static_cast<int>(a.at(x, y)) - static_cast<int>(b.at(x, y))), x, y);
    s.finish();
    return s;
}

// The reference picture of a layout: every glyph rendered by FreeType (unhinted) and composited
// source-over with the same composite_span. With `transform` null: each glyph origin rounded to
// 1/steps px horizontally and 1/steps_y px vertically as draw_text's cached path does; otherwise glyphs are placed exactly under
// transform x translate(origin) (draw_text's outline path). `ft` holds one FreeType renderer per
// layout font (same variation). `supersample` > 1 renders each glyph that many times finer and
// box-filters it (see FtRenderer::render_supersampled).
inline casteljau::Pixmap reference_text_image(const casteljau::TextLayout& layout, std::vector<FtRenderer*> ft,
                                              int width, int height, casteljau::Point origin,
                                              casteljau::Color background, const casteljau::Paint& paint, int steps = 4,
                                              const casteljau::Affine* transform = nullptr, int supersample = 1,
                                              int steps_y = 1) {
    casteljau::Pixmap pm(width, height);
    pm.fill(background);
    for (const auto& g : layout.glyphs) {
        Gray gr;
        if (!transform) {
            const double px = std::round((g.position.x + origin.x) * steps) / steps;
            const double py = std::round((g.position.y + origin.y) * steps_y) / steps_y;
            gr = supersample > 1
                     ? ft[g.font]->render_supersampled(g.glyph, layout.size, casteljau::Point{px, py}, supersample)
                     : ft[g.font]->render(g.glyph, layout.size, casteljau::Point{px, py});
        } else {
            const casteljau::Affine m = *transform *
                                        casteljau::Affine::translate(origin.x + g.position.x, origin.y + g.position.y) *
                                        casteljau::Affine::scale(1, -1);
            gr = supersample > 1 ? ft[g.font]->render_supersampled(g.glyph, layout.size, m, supersample)
                                 : ft[g.font]->render(g.glyph, layout.size, m);
        }
        for (int y = std::max(gr.bounds.y0, 0); y < std::min(gr.bounds.y1, height); ++y) {
            const int x0 = std::max(gr.bounds.x0, 0), x1 = std::min(gr.bounds.x1, width);
            if (x0 >= x1) continue;
            const std::uint8_t* cov =
                gr.data.data() + static_cast<std::size_t>(y - gr.bounds.y0) * gr.bounds.width() + (x0 - gr.bounds.x0);
            casteljau::composite_span(pm.row(y) + 4 * x0, x1 - x0, cov, paint);
        }
    }
    return pm;
}

// Per-channel comparison of two pixmaps of the same size (1/255 units).
inline DiffStats compare_pixmaps(const casteljau::Pixmap& a, const casteljau::Pixmap& b) {
    DiffStats s;
    if (a.width() != b.width() || a.height() != b.height()) {
        s.max = 255;
        s.mean = 255;
        return s;
    }
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 4; ++c)
                s.add(std::abs(static_cast<int>(a.row(y)[4 * x + c]) - static_cast<int>(b.row(y)[4 * x + c])), x, y);
    s.finish();
    return s;
}

// Builds an OpenType collection ('ttcf' version 1.0) holding the given single fonts, tables copied
// and offsets rewritten (tables are not shared).
inline std::vector<std::uint8_t> make_collection(const std::vector<std::vector<std::uint8_t>>& fonts) {
    auto u16 = [](const std::vector<std::uint8_t>& b, std::size_t o) {
        return static_cast<std::uint32_t>(b[o] << 8 | b[o + 1]);
    };
    auto u32 = [](const std::vector<std::uint8_t>& b, std::size_t o) {
        return static_cast<std::uint32_t>(b[o]) << 24 | static_cast<std::uint32_t>(b[o + 1]) << 16 |
               static_cast<std::uint32_t>(b[o + 2]) << 8 | b[o + 3];
    };
    auto put32 = [](std::vector<std::uint8_t>& b, std::size_t o, std::uint32_t v) {
        b[o] = static_cast<std::uint8_t>(v >> 24);
        b[o + 1] = static_cast<std::uint8_t>(v >> 16);
        b[o + 2] = static_cast<std::uint8_t>(v >> 8);
        b[o + 3] = static_cast<std::uint8_t>(v);
    };
    std::vector<std::uint8_t> out(12 + 4 * fonts.size(), 0);
    put32(out, 0, 0x74746366u);
    put32(out, 4, 0x00010000u);
    put32(out, 8, static_cast<std::uint32_t>(fonts.size()));
    for (std::size_t f = 0; f < fonts.size(); ++f) {
        const auto& src = fonts[f];
        while (out.size() % 4) out.push_back(0);
        const std::size_t dir = out.size();
        put32(out, 12 + 4 * f, static_cast<std::uint32_t>(dir));
        const std::uint32_t n = u16(src, 4);
        out.insert(out.end(), src.begin(), src.begin() + 12 + 16 * n);
        for (std::uint32_t i = 0; i < n; ++i) {
            const std::size_t rec = 12 + 16 * i;
            const std::uint32_t off = u32(src, rec + 8), len = u32(src, rec + 12);
            while (out.size() % 4) out.push_back(0);
            put32(out, dir + rec + 8, static_cast<std::uint32_t>(out.size()));
            out.insert(out.end(), src.begin() + off, src.begin() + off + len);
        }
    }
    return out;
}

}  // namespace text_test
