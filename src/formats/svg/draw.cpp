// Formats stage, SVG: draws a display list (display_list.hpp) onto a Canvas. Groups, clips, masks
// and filters become layers the size of the canvas; a pattern's tile is drawn at the resolution
// its fill needs and repeated through an image shader.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/filter.hpp"
#include "casteljau/shader.hpp"
#include "casteljau/text.hpp"
#include "formats/svg/display_list.hpp"

namespace casteljau::svg {

namespace {

// A colour glyph through the text stage, which draws it in its palette's colours.
void draw_color_glyph(const DisplayItem& it, Canvas& c, const Affine& base) {
    if (!it.font) return;
    TextLayout one;
    one.fonts = {it.font.get()};
    one.size = it.glyph_size;
    one.glyphs.push_back({it.glyph, 0, 0, Point{0, 0}});
    Paint paint = Paint::solid(it.color);
    paint.opacity = it.opacity;
    const Affine saved = c.transform();
    c.set_transform(base * it.transform);
    TextDrawOptions options;
    options.force_outlines = true;  // colour glyphs are drawn the same way either way
    draw_text(c, one, Point{0, 0}, paint, nullptr, options);
    c.set_transform(saved);
}

}  // namespace

void draw(const DisplayList& items, Canvas& canvas, const Affine& base) {
    // Layers: groups with opacity, clip paths or masks (BeginLayer .. EndLayer), and the content of
    // clip paths and masks (BeginClip/BeginMask .. EndMask), which becomes a coverage mask that
    // multiplies the layer it closes in.
    struct Frame {
        Pixmap pm;
        Canvas canvas;
        double opacity = 1;
        bool luminance = false;
        BlendMode blend = BlendMode::Normal;
        Frame(int w, int h) : pm(w, h), canvas(pm) {}
    };
    std::vector<std::unique_ptr<Frame>> frames;
    auto cur = [&]() -> Canvas& { return frames.empty() ? canvas : frames.back()->canvas; };
    for (const DisplayItem& it : items) {
        switch (it.kind) {
            case DisplayItem::BeginLayer:
            case DisplayItem::BeginClip:
            case DisplayItem::BeginMask: {
                frames.push_back(std::make_unique<Frame>(canvas.width(), canvas.height()));
                frames.back()->canvas.fill_options() = canvas.fill_options();
                frames.back()->opacity = it.opacity;
                frames.back()->luminance = it.kind == DisplayItem::BeginMask && it.luminance;
                frames.back()->blend = it.blend;
                continue;
            }
            case DisplayItem::BeginFilter:
                frames.push_back(std::make_unique<Frame>(canvas.width(), canvas.height()));
                frames.back()->canvas.fill_options() = canvas.fill_options();
                continue;
            case DisplayItem::EndFilter: {
                if (frames.empty()) continue;
                std::unique_ptr<Frame> f = std::move(frames.back());
                frames.pop_back();
                Pixmap result = std::move(f->pm);
                if (it.filters)
                    for (const filter::FilterGraph& g : *it.filters)
                        result = filter::apply_filter(g, base * it.transform, result);
                cur().draw_layer(result, 1.0);
                continue;
            }
            case DisplayItem::EndLayer: {
                if (frames.empty()) continue;
                std::unique_ptr<Frame> f = std::move(frames.back());
                frames.pop_back();
                cur().draw_layer(f->pm, f->opacity, f->blend);
                continue;
            }
            case DisplayItem::EndMask: {
                if (frames.size() < 2) continue;
                std::unique_ptr<Frame> f = std::move(frames.back());
                frames.pop_back();
                apply_mask(frames.back()->pm, f->luminance ? mask_from_luminance(f->pm) : mask_from_alpha(f->pm));
                continue;
            }
            case DisplayItem::PushClip: {
                Canvas& c = cur();
                c.save();
                const Affine saved = c.transform();
                c.set_transform(base * it.transform);
                c.clip_rect(it.path.bounds());
                c.set_transform(saved);
                continue;
            }
            case DisplayItem::PopClip: cur().restore(); continue;
            case DisplayItem::SvgImage:
                if (it.svg_image) it.svg_image->render(cur(), base * it.transform);
                continue;
            case DisplayItem::Bounds: continue;
            case DisplayItem::ColorGlyph: draw_color_glyph(it, cur(), base); continue;
            case DisplayItem::Fill:
            case DisplayItem::Stroke: break;
        }
        Canvas& c = cur();
        Paint paint = Paint::solid(it.color);
        paint.shader = it.shader;
        paint.opacity = it.opacity;
        if (it.pattern) {
            // The tile is drawn at the device resolution the fill needs, then repeated.
            const PatternTile& pt = *it.pattern;
            const Affine m = base * it.transform * pt.transform;
            const double sx = std::hypot(m.a, m.b) * pt.tile.width(), sy = std::hypot(m.c, m.d) * pt.tile.height();
            const int tw = static_cast<int>(std::clamp(std::ceil(sx), 1.0, 2048.0));
            const int th = static_cast<int>(std::clamp(std::ceil(sy), 1.0, 2048.0));
            auto tile = std::make_shared<Pixmap>(tw, th);
            Canvas tc(*tile);
            tc.fill_options() = c.fill_options();
            draw(pt.items, tc,
                 Affine::scale(tw / pt.tile.width(), th / pt.tile.height()) *
                     Affine::translate(-pt.tile.x0, -pt.tile.y0));
            paint.shader = std::make_shared<const Shader>(
                Shader::image(tile, true,
                              pt.transform * Affine::translate(pt.tile.x0, pt.tile.y0) *
                                  Affine::scale(pt.tile.width() / tw, pt.tile.height() / th),
                              true));
        }
        const Affine saved = c.transform();
        c.set_transform(base * it.transform);
        if (it.kind == DisplayItem::Stroke)
            c.stroke_path(it.path, it.stroke, paint);
        else
            c.fill_path(it.path, paint, it.rule);
        c.set_transform(saved);
    }
}

}  // namespace casteljau::svg
