// Text stage, composite: positioned glyphs onto a Canvas (include/casteljau/text.hpp).
//
// Axis-aligned (translation + uniform scale): glyph origin in device space -> rounded to 1/4 px
// horizontally and a whole pixel vertically (TextDrawOptions) -> cached Mask at that subpixel
// offset (the masks a text lacks are made together, in parallel: GlyphCache::masks) ->
// Canvas::fill_mask at the glyph's pixel offset (the paint stage, inside the clip).
// Any other transform: each glyph's outline is filled with Canvas::fill_path under
// canvas transform x translate(origin + glyph position) x [s 0 0 -s].
// Colour glyphs (COLR layers and paint graphs, bitmaps) are drawn in their place, in order, by
// src/text/color_glyphs.cpp, in their palette's colours.
#include <cmath>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/text.hpp"
#include "text/color_glyphs.hpp"
#include "text/font_impl.hpp"

namespace casteljau {

namespace {

// Farthest glyph origin (device pixels) drawn through the cache; beyond it glyphs are off any
// canvas anyway and integer arithmetic stays far from overflow.
constexpr double kMaxCachedOrigin = 1e8;

// Whether a glyph is drawn in colour (SVG, COLR, CBDT, sbix) rather than as a coverage mask; a font
// without colour tables answers at once.
bool is_color(const Font& font, std::uint32_t glyph) {
    if (!text_detail::may_have_color_glyphs(font)) return false;
    return text_detail::color_glyph_kind(font, glyph) != text_detail::ColorGlyphKind::None;
}

// The fill options of glyph outlines drawn as paths: the canvas's, nonzero, at the text tolerance.
FillOptions outline_fill(Canvas& canvas, const TextDrawOptions& options) {
    FillOptions fill = canvas.fill_options();
    fill.rule = FillRule::NonZero;
    fill.tolerance = options.tolerance;
    return fill;
}

// Fills glyph g's outline (layout space of M, which maps it to the canvas's pixels).
void fill_outline(Canvas& canvas, GlyphCache& gc, const Font& font, const PositionedGlyph& g, double size,
                  const Affine& M, const Paint& paint, const FillOptions& fill) {
    const Path& outline = gc.outline(font, g.glyph);
    if (outline.empty()) return;
    const double s = size / font.units_per_em();
    canvas.save();
    canvas.set_transform(M * Affine{s, 0, 0, -s, g.position.x, g.position.y});
    try {
        canvas.fill_path(outline, paint, fill);
    } catch (...) {
        canvas.restore();
        throw;
    }
    canvas.restore();
}

}  // namespace

bool is_color_glyph(const Font& font, std::uint32_t glyph) { return is_color(font, glyph); }

void draw_text(Canvas& canvas, const TextLayout& layout, Point origin, const Paint& paint, GlyphCache* cache,
               const TextDrawOptions& options) {
    if (options.subpixel_steps < 1 || options.subpixel_steps > 64 || options.subpixel_steps_y < 1 ||
        options.subpixel_steps_y > 64)
        throw Error(ErrorKind::InvalidArgument, "subpixel steps must be 1 to 64");
    if (!origin.is_finite()) throw Error(ErrorKind::InvalidArgument, "text origin must be finite");
    if (layout.glyphs.empty()) return;
    for (const Font* f : layout.fonts)
        if (!f) throw Error(ErrorKind::InvalidArgument, "draw_text: the layout has a null font");
    const Affine M = canvas.transform() * Affine::translate(origin.x, origin.y);
    if (!M.is_finite()) throw Error(ErrorKind::InvalidData, "draw_text: the canvas transform is not finite");
    GlyphCache local(8u << 20, options.tolerance);
    GlyphCache& gc = cache ? *cache : local;

    const double device_size = layout.size * M.a;
    const bool cached = !options.force_outlines && M.b == 0 && M.c == 0 && M.a > 0 && M.a == M.d &&
                        device_size <= options.max_cached_size && device_size <= limits::kMaxFontSize;
    if (cached) {
        const int sx = options.subpixel_steps, sy = options.subpixel_steps_y;
        // Each glyph's pixel position and mask request; the masks not cached yet are then made
        // together (in parallel), and drawn in order.
        std::vector<GlyphCache::MaskRequest> requests;
        std::vector<std::pair<long long, long long>> at;
        requests.reserve(layout.glyphs.size());
        at.reserve(layout.glyphs.size());
        std::vector<const PositionedGlyph*> color;  // per request: the colour glyph drawn in its place, or null
        for (const PositionedGlyph& g : layout.glyphs) {
            const Point p = M.apply(g.position);
            if (!(std::abs(p.x) < kMaxCachedOrigin && std::abs(p.y) < kMaxCachedOrigin)) continue;
            if (is_color(*layout.fonts[g.font], g.glyph)) {
                color.resize(requests.size() + 1, nullptr);
                color.back() = &g;
                requests.push_back({layout.fonts[g.font], 0, device_size, {}});  // a placeholder, not rasterized
                at.emplace_back(0, 0);
                continue;
            }
            const long long qx = std::llround(p.x * sx), qy = std::llround(p.y * sy);
            // floor division, so that the subpixel offset is in [0, 1)
            const long long ix = (qx >= 0 ? qx : qx - (sx - 1)) / sx;
            const long long iy = (qy >= 0 ? qy : qy - (sy - 1)) / sy;
            const Point offset{static_cast<double>(qx - ix * sx) / sx, static_cast<double>(qy - iy * sy) / sy};
            requests.push_back({layout.fonts[g.font], g.glyph, device_size, offset});
            at.emplace_back(ix, iy);
        }
        color.resize(requests.size(), nullptr);
        std::vector<GlyphCache::MaskRequest> outline_requests;
        for (std::size_t i = 0; i < requests.size(); ++i)
            if (!color[i]) outline_requests.push_back(requests[i]);
        const std::vector<const Mask*> masks = gc.masks(outline_requests, canvas.rasterizer());
        std::size_t k = 0;  // index into outline_requests / masks
        for (std::size_t i = 0; i < requests.size(); ++i) {
            if (color[i]) {
                const PositionedGlyph& g = *color[i];
                const Font& font = *layout.fonts[g.font];
                if (!text_detail::draw_color_glyph(canvas, font, g.glyph, layout.size, M, g.position, paint,
                                                   options.palette))
                    fill_outline(canvas, gc, font, g, layout.size, M, paint, outline_fill(canvas, options));
                continue;
            }
            const std::size_t mi = k++;
            const GlyphCache::MaskRequest& r = requests[i];
            const Mask& m =
                masks.empty() ? gc.mask(*r.font, r.glyph, r.size, r.offset, canvas.rasterizer()) : *masks[mi];
            canvas.fill_mask(m, at[i].first, at[i].second, paint);
        }
        return;
    }
    if (!(options.tolerance >= 1e-4 && options.tolerance <= 10))
        throw Error(ErrorKind::InvalidArgument, "draw_text: tolerance must be in [1e-4, 10] px");
    const FillOptions fill = outline_fill(canvas, options);
    for (const PositionedGlyph& g : layout.glyphs) {
        const Font& font = *layout.fonts[g.font];
        if (is_color(font, g.glyph) &&
            text_detail::draw_color_glyph(canvas, font, g.glyph, layout.size, M, g.position, paint, options.palette))
            continue;
        fill_outline(canvas, gc, font, g, layout.size, M, paint, fill);
    }
}

TextLayout draw_text(Canvas& canvas, std::string_view utf8, const Font& font, double size, Point origin,
                     const Paint& paint) {
    TextStyle style;
    style.size = size;
    TextLayout layout = layout_text(utf8, font, style);
    draw_text(canvas, layout, origin, paint);
    return layout;
}

}  // namespace casteljau
