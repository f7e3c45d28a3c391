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

// A pattern fill's shader: the tile drawn at the device resolution the fill needs (at most 2048
// pixels a side), repeated.
std::shared_ptr<const Shader> pattern_shader(const PatternTile& pt, const Affine& to_device, Canvas& c) {
    const Affine m = to_device * pt.transform;
    const double sx = std::hypot(m.a, m.b) * pt.tile.width(), sy = std::hypot(m.c, m.d) * pt.tile.height();
    const int tw = static_cast<int>(std::clamp(std::ceil(sx), 1.0, 2048.0));
    const int th = static_cast<int>(std::clamp(std::ceil(sy), 1.0, 2048.0));
    auto tile = std::make_shared<Pixmap>(tw, th);
    Canvas tc(*tile);
    tc.fill_options() = c.fill_options();
    draw(pt.items, tc,
         Affine::scale(tw / pt.tile.width(), th / pt.tile.height()) * Affine::translate(-pt.tile.x0, -pt.tile.y0));
    return std::make_shared<const Shader>(Shader::image(tile, true,
                                                        pt.transform * Affine::translate(pt.tile.x0, pt.tile.y0) *
                                                            Affine::scale(pt.tile.width() / tw, pt.tile.height() / th),
                                                        true));
}

// One display list drawn onto a canvas. Layers: groups with opacity, clip paths or masks
// (BeginLayer .. EndLayer), filtered content (BeginFilter .. EndFilter), and the content of clip
// paths and masks (BeginClip/BeginMask .. EndMask), which becomes a coverage mask that multiplies
// the layer it closes in. Each is a frame the size of the canvas, drawn into until it ends.
class Drawing {
public:
    Drawing(Canvas& canvas, const Affine& base) : canvas_(canvas), base_(base) {}

    void item(const DisplayItem& it) {
        switch (it.kind) {
            case DisplayItem::BeginLayer:
            case DisplayItem::BeginClip:
            case DisplayItem::BeginMask:
                begin_frame(it.opacity, it.kind == DisplayItem::BeginMask && it.luminance, it.blend);
                return;
            case DisplayItem::BeginFilter: begin_frame(1, false, BlendMode::Normal); return;
            case DisplayItem::EndFilter: end_filter(it); return;
            case DisplayItem::EndLayer: end_layer(); return;
            case DisplayItem::EndMask: end_mask(); return;
            case DisplayItem::PushClip: push_clip(it); return;
            case DisplayItem::PopClip: current().restore(); return;
            case DisplayItem::SvgImage:
                if (it.svg_image) it.svg_image->render(current(), base_ * it.transform);
                return;
            case DisplayItem::Bounds: return;
            case DisplayItem::ColorGlyph: draw_color_glyph(it, current(), base_); return;
            case DisplayItem::Fill:
            case DisplayItem::Stroke: shape(it); return;
        }
    }

private:
    struct Frame {
        Pixmap pm;
        Canvas canvas;
        double opacity = 1;
        bool luminance = false;
        BlendMode blend = BlendMode::Normal;
        Frame(int w, int h) : pm(w, h), canvas(pm) {}
    };

    Canvas& current() { return frames_.empty() ? canvas_ : frames_.back()->canvas; }

    void begin_frame(double opacity, bool luminance, BlendMode blend) {
        frames_.push_back(std::make_unique<Frame>(canvas_.width(), canvas_.height()));
        Frame& f = *frames_.back();
        f.canvas.fill_options() = canvas_.fill_options();
        f.opacity = opacity;
        f.luminance = luminance;
        f.blend = blend;
    }

    std::unique_ptr<Frame> pop_frame() {
        std::unique_ptr<Frame> f = std::move(frames_.back());
        frames_.pop_back();
        return f;
    }

    void end_filter(const DisplayItem& it) {
        if (frames_.empty()) return;
        Pixmap result = std::move(pop_frame()->pm);
        if (it.filters)
            for (const filter::FilterGraph& g : *it.filters)
                result = filter::apply_filter(g, base_ * it.transform, result);
        current().draw_layer(result, 1.0);
    }

    void end_layer() {
        if (frames_.empty()) return;
        const std::unique_ptr<Frame> f = pop_frame();
        current().draw_layer(f->pm, f->opacity, f->blend);
    }

    void end_mask() {
        if (frames_.size() < 2) return;
        const std::unique_ptr<Frame> f = pop_frame();
        apply_mask(frames_.back()->pm, f->luminance ? mask_from_luminance(f->pm) : mask_from_alpha(f->pm));
    }

    void push_clip(const DisplayItem& it) {
        Canvas& c = current();
        c.save();
        const Affine saved = c.transform();
        c.set_transform(base_ * it.transform);
        c.clip_rect(it.path.bounds());
        c.set_transform(saved);
    }

    void shape(const DisplayItem& it) {
        Canvas& c = current();
        Paint paint = Paint::solid(it.color);
        paint.shader = it.pattern ? pattern_shader(*it.pattern, base_ * it.transform, c) : it.shader;
        paint.opacity = it.opacity;
        const Affine saved = c.transform();
        c.set_transform(base_ * it.transform);
        if (it.kind == DisplayItem::Stroke)
            c.stroke_path(it.path, it.stroke, paint);
        else
            c.fill_path(it.path, paint, it.rule);
        c.set_transform(saved);
    }

    Canvas& canvas_;
    const Affine base_;
    std::vector<std::unique_ptr<Frame>> frames_;
};

}  // namespace

void draw(const DisplayList& items, Canvas& canvas, const Affine& base) {
    Drawing drawing(canvas, base);
    for (const DisplayItem& it : items) drawing.item(it);
}

}  // namespace casteljau::svg
