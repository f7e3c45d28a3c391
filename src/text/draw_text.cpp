// Text stage, composite: positioned glyphs onto a Canvas (include/casteljau/text.hpp).
//
// Axis-aligned (translation + uniform scale): glyph origin in device space -> rounded to 1/4 px
// horizontally and a whole pixel vertically (TextDrawOptions) -> cached Mask at that subpixel
// offset (the masks a text lacks are made together, in parallel: GlyphCache::masks) ->
// Canvas::fill_mask at the glyph's pixel offset (the paint stage, inside the clip).
// Any other transform: each glyph's outline is filled with Canvas::fill_path under
// canvas transform x translate(origin + glyph position) x [s 0 0 -s].
#include <cmath>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/text.hpp"

namespace casteljau {

namespace {

// Farthest glyph origin (device pixels) drawn through the cache; beyond it glyphs are off any
// canvas anyway and integer arithmetic stays far from overflow.
constexpr double kMaxCachedOrigin = 1e8;

}  // namespace

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
        for (const PositionedGlyph& g : layout.glyphs) {
            const Point p = M.apply(g.position);
            if (!(std::abs(p.x) < kMaxCachedOrigin && std::abs(p.y) < kMaxCachedOrigin)) continue;
            const long long qx = std::llround(p.x * sx), qy = std::llround(p.y * sy);
            // floor division, so that the subpixel offset is in [0, 1)
            const long long ix = (qx >= 0 ? qx : qx - (sx - 1)) / sx;
            const long long iy = (qy >= 0 ? qy : qy - (sy - 1)) / sy;
            const Point offset{static_cast<double>(qx - ix * sx) / sx, static_cast<double>(qy - iy * sy) / sy};
            requests.push_back({layout.fonts[g.font], g.glyph, device_size, offset});
            at.emplace_back(ix, iy);
        }
        const std::vector<const Mask*> masks = gc.masks(requests, canvas.rasterizer());
        for (std::size_t i = 0; i < requests.size(); ++i) {
            const GlyphCache::MaskRequest& r = requests[i];
            const Mask& m = masks.empty() ? gc.mask(*r.font, r.glyph, r.size, r.offset, canvas.rasterizer()) : *masks[i];
            canvas.fill_mask(m, at[i].first, at[i].second, paint);
        }
        return;
    }
    if (!(options.tolerance >= 1e-4 && options.tolerance <= 10))
        throw Error(ErrorKind::InvalidArgument, "draw_text: tolerance must be in [1e-4, 10] px");
    FillOptions fill = canvas.fill_options();
    fill.rule = FillRule::NonZero;
    fill.tolerance = options.tolerance;
    for (const PositionedGlyph& g : layout.glyphs) {
        const Font& font = *layout.fonts[g.font];
        const Path& outline = gc.outline(font, g.glyph);
        if (outline.empty()) continue;
        const double s = layout.size / font.units_per_em();
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
