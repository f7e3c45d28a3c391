// Text stage, colour glyphs: their kinds, CPAL palettes, and bitmap glyphs (CBDT/CBLC, sbix)
// scaled by area averaging (src/text/color_glyphs.hpp). COLR paint graphs: colr_paint.cpp.
#include "text/color_glyphs.hpp"

#include "casteljau/text.hpp"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_COLOR_H

#include <hb-ot.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <unordered_map>

#include "casteljau/error.hpp"
#include "text/font_impl.hpp"

namespace casteljau {

namespace {
std::atomic<SvgGlyphDrawer> g_svg_glyph_drawer{nullptr};
}  // namespace

void set_svg_glyph_drawer(SvgGlyphDrawer drawer) { g_svg_glyph_drawer.store(drawer, std::memory_order_release); }
SvgGlyphDrawer svg_glyph_drawer() { return g_svg_glyph_drawer.load(std::memory_order_acquire); }

}  // namespace casteljau

namespace casteljau::text_detail {

namespace {

// The SVG document of one glyph as the font's 'SVG ' table holds it (HarfBuzz finds it; empty
// when the glyph has none), alive as long as this object, and its key for the drawer's caches: the
// font's serial number (a glyph has one document, so the font and the glyph name it).
class SvgGlyphDocument {
public:
    SvgGlyphDocument(const Font::Impl& fi, std::uint32_t glyph)
        : blob_(hb_ot_color_glyph_reference_svg(hb_font_get_face(fi.hb), glyph)), key_(fi.serial) {}
    std::uint64_t key() const { return key_; }
    ~SvgGlyphDocument() { hb_blob_destroy(blob_); }
    SvgGlyphDocument(const SvgGlyphDocument&) = delete;
    SvgGlyphDocument& operator=(const SvgGlyphDocument&) = delete;
    std::string_view text() const {
        unsigned length = 0;
        const char* data = hb_blob_get_data(blob_, &length);
        return data ? std::string_view(data, length) : std::string_view();
    }

private:
    hb_blob_t* blob_;
    std::uint64_t key_;
};

// Bounds (font units, y up) of what an SVG glyph draws: see color_glyphs.hpp.
Rect svg_glyph_bounds(const Font& font, std::uint32_t glyph) {
    const GlyphMetrics g = font.glyph_metrics(glyph);
    const FontMetrics& m = font.metrics();
    Rect b{0, m.descender, std::max(g.advance, 0.0), m.ascender};
    if (!g.bounds.empty()) b = b.united(g.bounds);
    const double margin = 0.1 * font.units_per_em();
    return {b.x0 - margin, b.y0 - margin, b.x1 + margin, b.y1 + margin};
}

// The strike to draw at `ppem` device pixels per em: the smallest at least as large, else the largest.
FT_Int pick_strike(FT_Face face, double ppem) {
    FT_Int best = -1, largest = 0;
    for (FT_Int i = 0; i < face->num_fixed_sizes; ++i) {
        const FT_Pos p = face->available_sizes[i].y_ppem;
        if (p > face->available_sizes[largest].y_ppem) largest = i;
        if (p / 64.0 >= ppem && (best < 0 || p < face->available_sizes[best].y_ppem)) best = i;
    }
    return best >= 0 ? best : largest;
}

// A glyph's colour bitmap at one strike, premultiplied RGBA, and where it sits (strike pixels,
// y up from the baseline to the top row).
struct StrikeBitmap {
    int width = 0, height = 0;
    int left = 0, top = 0;
    double ppem = 0;
    std::vector<std::uint8_t> rgba;
};

// Loads the bitmap of `glyph` at `strike` (only its box and ppem with `metrics_only`: nothing is
// decoded); false when the glyph has none. A scalable face is put back at its em size afterwards.
bool load_strike_bitmap(const Font::Impl& fi, std::uint32_t glyph, FT_Int strike, StrikeBitmap& out,
                        bool metrics_only = false) {
    FT_Face face = fi.face;
    if (glyph >= static_cast<std::uint32_t>(face->num_glyphs) || strike < 0 || strike >= face->num_fixed_sizes)
        return false;
    if (FT_Select_Size(face, strike)) return false;
    const FT_Int32 flags = FT_LOAD_COLOR | FT_LOAD_NO_HINTING | (metrics_only ? FT_LOAD_BITMAP_METRICS_ONLY : 0);
    const FT_Error err = FT_Load_Glyph(face, glyph, flags);
    bool ok = !err && face->glyph->format == FT_GLYPH_FORMAT_BITMAP;
    if (ok && metrics_only) {
        const FT_Glyph_Metrics& m = face->glyph->metrics;
        out.width = static_cast<int>(m.width / 64);
        out.height = static_cast<int>(m.height / 64);
        out.left = static_cast<int>(m.horiBearingX / 64);
        out.top = static_cast<int>(m.horiBearingY / 64);
        out.ppem = face->available_sizes[strike].y_ppem / 64.0;
        ok = out.width > 0 && out.height > 0 && out.ppem > 0;
    } else if (ok && face->glyph->bitmap.pixel_mode != FT_PIXEL_MODE_BGRA) {
        ok = false;
    } else if (ok) {
        const FT_Bitmap& bm = face->glyph->bitmap;
        out.width = static_cast<int>(bm.width);
        out.height = static_cast<int>(bm.rows);
        out.left = face->glyph->bitmap_left;
        out.top = face->glyph->bitmap_top;
        out.ppem = face->available_sizes[strike].y_ppem / 64.0;
        out.rgba.assign(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 4, 0);
        for (int y = 0; y < out.height; ++y) {
            const unsigned char* src = bm.buffer + static_cast<std::ptrdiff_t>(y) * bm.pitch;
            std::uint8_t* dst = out.rgba.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) * 4;
            for (int x = 0; x < out.width; ++x) {
                const std::uint8_t a = src[4 * x + 3];
                // FreeType's BGRA is premultiplied; a malformed bitmap may not be: clamp to alpha.
                dst[4 * x + 0] = std::min(src[4 * x + 2], a);
                dst[4 * x + 1] = std::min(src[4 * x + 1], a);
                dst[4 * x + 2] = std::min(src[4 * x + 0], a);
                dst[4 * x + 3] = a;
            }
        }
        ok = out.width > 0 && out.height > 0 && out.ppem > 0;
    }
    if (!fi.bitmap_only) {
        const FT_F26Dot6 em = static_cast<FT_F26Dot6>(face->units_per_EM) * 64;
        FT_Set_Char_Size(face, em, em, 72, 72);
    }
    return ok;
}

// Four channels of a pixel as one value: GCC and Clang compile its arithmetic to vector
// instructions of the baseline instruction set, each lane as the scalar float operation.
using Float4 = float __attribute__((vector_size(16)));

// The vertical half of scaling a strike bitmap (draw_scaled_bitmap): for each device row, the
// weighted sum of the strike rows under it, one Float4 per strike pixel. It depends only on the
// bitmap, the scale and where the bitmap's top lies within a device pixel (`phase`), which every
// instance of a glyph on a line shares.
struct VerticalPass {
    std::uint64_t bitmap = 0;  // the (glyph, strike) key of BitmapCache
    double k = 0, phase = -1;
    int rows = 0;
    std::vector<Float4> sums;  // rows x bitmap width
};

// Decoded bitmaps of a font, per (glyph, strike), emptied past kMaxCachedBitmaps, and the last
// kKeptPasses vertical passes (about 120 KB each for an emoji at 48 px).
constexpr std::size_t kMaxCachedBitmaps = 256, kKeptPasses = 8;
struct BitmapCache {
    std::unordered_map<std::uint64_t, StrikeBitmap> bitmaps;
    VerticalPass passes[kKeptPasses];
    std::size_t next_pass = 0;
};

BitmapCache& bitmap_cache(Font::Impl& fi) {
    if (!fi.color_bitmap_cache) fi.color_bitmap_cache = std::make_shared<BitmapCache>();
    return *static_cast<BitmapCache*>(fi.color_bitmap_cache.get());
}

std::uint64_t bitmap_key(std::uint32_t glyph, FT_Int strike) {
    return static_cast<std::uint64_t>(glyph) << 16 | static_cast<std::uint16_t>(strike);
}

// The decoded bitmap of `glyph` at `strike`, or null; kept in the Font.
const StrikeBitmap* cached_bitmap(Font::Impl& fi, std::uint32_t glyph, FT_Int strike) {
    BitmapCache& cache = bitmap_cache(fi);
    const std::uint64_t key = bitmap_key(glyph, strike);
    if (auto it = cache.bitmaps.find(key); it != cache.bitmaps.end())
        return it->second.rgba.empty() ? nullptr : &it->second;
    if (cache.bitmaps.size() >= kMaxCachedBitmaps) {
        cache.bitmaps.clear();
        for (VerticalPass& p : cache.passes) p = VerticalPass{};
    }
    StrikeBitmap bm;
    if (!load_strike_bitmap(fi, glyph, strike, bm)) bm = StrikeBitmap{};
    const StrikeBitmap& stored = cache.bitmaps.emplace(key, std::move(bm)).first->second;
    return stored.rgba.empty() ? nullptr : &stored;
}

// Weights of the source pixels under destination pixels [0, n) of an axis on which source pixel i
// covers [origin + i k, origin + (i + 1) k): for each destination pixel, the first source
// pixel and the overlaps (in destination pixels) with it and the following ones, which are
// weights[begin[d]] to weights[begin[d + 1]] (exclusive).
struct AxisWeights {
    std::vector<int> first;
    std::vector<std::size_t> begin;
    std::vector<float> weights;
};
AxisWeights axis_weights(int n, double origin, double k, int src_count) {
    AxisWeights w;
    w.first.resize(static_cast<std::size_t>(n));
    w.begin.resize(static_cast<std::size_t>(n) + 1);
    for (int d = 0; d < n; ++d) {
        const double lo = d, hi = lo + 1;
        // Clamped as doubles: a malformed strike can make the quotients far beyond int.
        const double count = src_count;
        const int i0 = static_cast<int>(std::clamp(std::floor((lo - origin) / k), 0.0, count));
        const int i1 = static_cast<int>(std::clamp(std::ceil((hi - origin) / k), 0.0, count));
        w.first[static_cast<std::size_t>(d)] = i0;
        w.begin[static_cast<std::size_t>(d)] = w.weights.size();
        for (int i = i0; i < std::min(i1, src_count); ++i) {
            const double a = std::max(lo, origin + i * k), b = std::min(hi, origin + (i + 1) * k);
            w.weights.push_back(static_cast<float>(std::max(0.0, b - a)));
        }
    }
    w.begin[static_cast<std::size_t>(n)] = w.weights.size();
    return w;
}

// A non-negative sum of at most 255.x rounded half up to a byte, at most `limit`: x + 0.5 is exact
// below 256 and truncation cannot change above it, so this is std::round clamped.
std::uint8_t round_sum(float x, int limit) {
    const int r = static_cast<int>(x + 0.5f);
    return static_cast<std::uint8_t>(r < limit ? r : limit);
}

// The vertical pass of `bm` (key `key`) at scale `k` whose top lies `phase` into its first device
// row of `rows`, from the cache or computed into its oldest entry.
const VerticalPass& vertical_pass(BitmapCache& cache, std::uint64_t key, const StrikeBitmap& bm, double k, double phase,
                                  int rows) {
    for (const VerticalPass& p : cache.passes)
        if (p.bitmap == key && p.k == k && p.phase == phase && p.rows == rows) return p;
    VerticalPass& p = cache.passes[cache.next_pass];
    cache.next_pass = (cache.next_pass + 1) % kKeptPasses;
    p = VerticalPass{key, k, phase, rows, {}};
    const std::size_t width = static_cast<std::size_t>(bm.width);
    p.sums.assign(static_cast<std::size_t>(rows) * width, Float4{0, 0, 0, 0});
    const AxisWeights wy = axis_weights(rows, phase, k, bm.height);
    for (std::size_t d = 0; d < static_cast<std::size_t>(rows); ++d) {
        Float4* acc = p.sums.data() + d * width;
        const std::uint8_t* src = bm.rgba.data() + static_cast<std::size_t>(wy.first[d]) * width * 4;
        for (std::size_t j = wy.begin[d]; j < wy.begin[d + 1]; ++j) {
            const float wj = wy.weights[j];
            for (std::size_t i = 0; i < width; ++i, src += 4)
                acc[i] += wj * Float4{static_cast<float>(src[0]), static_cast<float>(src[1]),
                                      static_cast<float>(src[2]), static_cast<float>(src[3])};
        }
    }
    return p;
}

// Draws a strike bitmap (key `key` in `cache`) scaled by `k` (device pixels per strike pixel) with
// its top-left corner at device point (x, y), averaging the strike's pixels over each device
// pixel: the vertical pass (shared by the glyph's instances on a line), then a horizontal pass per
// instance, the four channels of a pixel at once.
void draw_scaled_bitmap(Canvas& canvas, BitmapCache& cache, std::uint64_t key, const StrikeBitmap& bm, double k,
                        double x, double y, double opacity) {
    // Scales and positions a malformed font can produce that no image could show.
    if (!(k >= 1e-4 && k <= 1e4) || !(std::abs(x) < 1e8 && std::abs(y) < 1e8)) return;
    const int dx0 = static_cast<int>(std::floor(x)), dy0 = static_cast<int>(std::floor(y));
    const int dx1 = static_cast<int>(std::ceil(x + bm.width * k)), dy1 = static_cast<int>(std::ceil(y + bm.height * k));
    const int w = dx1 - dx0, h = dy1 - dy0;
    if (w <= 0 || h <= 0 || w > 16384 || h > 16384) return;
    const VerticalPass& v = vertical_pass(cache, key, bm, k, y - dy0, h);
    const AxisWeights wx = axis_weights(w, x - dx0, k, bm.width);
    Pixmap image(w, h);
    for (int d = 0; d < h; ++d) {
        const Float4* row = v.sums.data() + static_cast<std::size_t>(d) * static_cast<std::size_t>(bm.width);
        std::uint8_t* out = image.row(d);
        for (std::size_t px = 0; px < static_cast<std::size_t>(w); ++px, out += 4) {
            const Float4* s = row + wx.first[px];
            Float4 sum = {0, 0, 0, 0};
            for (std::size_t j = wx.begin[px]; j < wx.begin[px + 1]; ++j, ++s) sum += wx.weights[j] * *s;
            // Overlaps are in device pixels: a fully covered device pixel sums to 1, so every sum
            // is at most 255.x and at least 0; colour is kept at most alpha (premultiplied).
            const std::uint8_t a = round_sum(sum[3], 255);
            out[3] = a;
            for (int c = 0; c < 3; ++c) out[c] = round_sum(sum[c], a);
        }
    }
    canvas.save();
    canvas.reset_transform();
    canvas.draw_image(image, Affine::translate(dx0, dy0), ImageSampling::Nearest, opacity);
    canvas.restore();
}

void draw_bitmap_glyph(Canvas& canvas, const Font& font, std::uint32_t glyph, double size, const Affine& to_device,
                       Point origin, double opacity) {
    Font::Impl& fi = font.impl();
    const bool axis_aligned = to_device.b == 0 && to_device.c == 0 && to_device.a > 0 && to_device.a == to_device.d;
    const double device_size =
        size *
        (axis_aligned ? to_device.a : std::sqrt(std::abs(to_device.a * to_device.d - to_device.b * to_device.c)));
    const FT_Int strike = pick_strike(fi.face, device_size);
    const StrikeBitmap* found = cached_bitmap(fi, glyph, strike);
    if (!found) return;
    const StrikeBitmap& bm = *found;
    if (axis_aligned) {
        const Point o = to_device.apply(origin);
        const double k = device_size / bm.ppem;
        draw_scaled_bitmap(canvas, bitmap_cache(fi), bitmap_key(glyph, strike), bm, k, o.x + bm.left * k,
                           o.y - bm.top * k, opacity);
        return;
    }
    Pixmap image(bm.width, bm.height);
    for (int y = 0; y < bm.height; ++y)
        std::copy_n(bm.rgba.data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(bm.width) * 4,
                    static_cast<std::size_t>(bm.width) * 4, image.row(y));
    const double k = size / bm.ppem;
    canvas.save();
    canvas.reset_transform();
    canvas.draw_image(image, to_device * Affine{k, 0, 0, k, origin.x + bm.left * k, origin.y - bm.top * k},
                      ImageSampling::Bilinear, opacity);
    canvas.restore();
}

}  // namespace

bool may_have_color_glyphs(const Font& font) {
    const Font::Impl& fi = font.impl();
    return fi.has_colr || fi.has_color_bitmaps || (fi.has_svg && svg_glyph_drawer());
}

ColorGlyphKind color_glyph_kind(const Font& font, std::uint32_t glyph) {
    const Font::Impl& fi = font.impl();
    if (!may_have_color_glyphs(font)) return ColorGlyphKind::None;
    if (glyph >= font.glyph_count()) return ColorGlyphKind::None;
    if (fi.has_svg && svg_glyph_drawer() && SvgGlyphDocument(fi, glyph).text().size() > 0) return ColorGlyphKind::Svg;
    if (fi.has_colr) {
        if (has_colr_paint_graph(font, glyph)) return ColorGlyphKind::PaintGraph;
        FT_LayerIterator it{};
        it.p = nullptr;
        FT_UInt layer = 0, color = 0;
        if (FT_Get_Color_Glyph_Layer(fi.face, glyph, &layer, &color, &it)) return ColorGlyphKind::Layers;
    }
    if (fi.has_color_bitmaps) {
        StrikeBitmap bm;
        if (load_strike_bitmap(fi, glyph, pick_strike(fi.face, 0), bm, true)) return ColorGlyphKind::Bitmap;
    }
    return ColorGlyphKind::None;
}

Rect color_glyph_bounds(const Font& font, std::uint32_t glyph) {
    const Font::Impl& fi = font.impl();
    const ColorGlyphKind kind = color_glyph_kind(font, glyph);
    if (kind == ColorGlyphKind::Svg) return svg_glyph_bounds(font, glyph);
    if (kind == ColorGlyphKind::PaintGraph || kind == ColorGlyphKind::Layers) return colr_glyph_bounds(font, glyph);
    StrikeBitmap bm;
    FT_Int largest = 0;
    for (FT_Int i = 1; i < fi.face->num_fixed_sizes; ++i)
        if (fi.face->available_sizes[i].y_ppem > fi.face->available_sizes[largest].y_ppem) largest = i;
    if (!fi.has_color_bitmaps || !load_strike_bitmap(fi, glyph, largest, bm, true)) return {};
    const double s = font.units_per_em() / bm.ppem;
    return {bm.left * s, (bm.top - bm.height) * s, (bm.left + bm.width) * s, bm.top * s};
}

std::vector<Color> font_palette(const Font& font, int palette) {
    FT_Face face = font.impl().face;
    FT_Palette_Data data;
    std::vector<Color> out;
    if (FT_Palette_Data_Get(face, &data) || data.num_palettes == 0) return out;
    if (palette < 0 || palette >= data.num_palettes) palette = 0;
    FT_Color* colors = nullptr;
    if (FT_Palette_Select(face, static_cast<FT_UShort>(palette), &colors) || !colors) return out;
    for (FT_UShort i = 0; i < data.num_palette_entries; ++i)
        out.push_back(Color::rgba(colors[i].red, colors[i].green, colors[i].blue, colors[i].alpha));
    return out;
}

bool draw_color_glyph(Canvas& canvas, const Font& font, std::uint32_t glyph, double size, const Affine& to_device,
                      Point origin, const Paint& paint, int palette) {
    const ColorGlyphKind kind = color_glyph_kind(font, glyph);
    const double opacity = std::clamp(paint.opacity, 0.0, 1.0);
    if (kind == ColorGlyphKind::Bitmap) {
        draw_bitmap_glyph(canvas, font, glyph, size, to_device, origin, opacity);
        return true;
    }
    if (kind != ColorGlyphKind::PaintGraph && kind != ColorGlyphKind::Layers && kind != ColorGlyphKind::Svg)
        return true;
    // The glyph's device bounds, drawn into a pixmap of that size and composited with the opacity.
    const double s = size / font.units_per_em();
    const Affine to_pixels = to_device * Affine{s, 0, 0, -s, origin.x, origin.y};
    const Rect b = kind == ColorGlyphKind::Svg ? svg_glyph_bounds(font, glyph) : colr_glyph_bounds(font, glyph);
    if (b.empty()) return true;
    const Rect device = to_pixels.map_bounds(b);
    const IRect& clip = canvas.clip();
    const double x0 = std::max(std::floor(device.x0), static_cast<double>(clip.x0));
    const double y0 = std::max(std::floor(device.y0), static_cast<double>(clip.y0));
    const double x1 = std::min(std::ceil(device.x1), static_cast<double>(clip.x1));
    const double y1 = std::min(std::ceil(device.y1), static_cast<double>(clip.y1));
    if (!(x1 > x0 && y1 > y0)) return true;
    Pixmap layer(static_cast<int>(x1 - x0), static_cast<int>(y1 - y0));
    {
        Canvas sub(layer);
        sub.fill_options() = canvas.fill_options();
        if (kind == ColorGlyphKind::Svg) {
            // The document's user units are font units with y down.
            const Affine flip = Affine::translate(-x0, -y0) * to_pixels * Affine::scale(1, -1);
            const SvgGlyphDocument doc(font.impl(), glyph);
            if (!svg_glyph_drawer()(sub, doc.text(), doc.key(), glyph, flip, paint.color)) return false;
        } else {
            sub.set_transform(Affine::translate(-x0, -y0) * to_pixels);
            paint_colr_glyph(sub, font, glyph, font_palette(font, palette), paint.color);
        }
    }
    canvas.save();
    canvas.reset_transform();
    canvas.draw_image(layer, Affine::translate(x0, y0), ImageSampling::Nearest, opacity);
    canvas.restore();
    return true;
}

}  // namespace casteljau::text_detail
