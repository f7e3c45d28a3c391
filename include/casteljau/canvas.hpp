// casteljau/canvas.hpp: the drawing-backend face of casteljau.
//
// A Canvas draws onto a Pixmap it does not own: a current transform (user space -> pixel space)
// with save()/restore(), a rectangular device clip, and fills of Paths with a Paint under a fill
// rule. Every fill walks the pipeline: Path --transform--> flatten --> rasterize (exact area) -->
// composite (source-over of premultiplied colour x coverage).
// Thread-safety: a Canvas and its Pixmap belong to one thread at a time.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/shader.hpp"
#include "casteljau/stroke.hpp"

namespace casteljau {

// What a fill paints: a solid colour, or a Shader (gradient) evaluated per pixel when `shader` is
// set (then `color` is ignored). The shader's own transform maps its space to the user space of
// the fill; the Canvas's current transform at the time of the fill goes on top.
struct Paint {
    Color color = Color::black();
    double opacity = 1.0;        // multiplies the colour's alpha
    bool linear_blend = false;   // blend coverage in linear light (gamma-correct) instead of sRGB; solid colours only
    std::shared_ptr<const Shader> shader;

    static Paint solid(Color c) { Paint p; p.color = c; return p; }
    static Paint shaded(Shader s) { Paint p; p.shader = std::make_shared<const Shader>(std::move(s)); return p; }
};

// Source-over of `paint` x coverage onto one row of premultiplied pixels (exposed for tests and
// for callers that rasterize themselves). `dst` points at pixel x of the row. With S the paint
// colour premultiplied (alpha = round(a x opacity), channels round(x a / 255)), coverage c and
// destination D, every channel becomes round((S c 255 + D (255^2 - Sa c)) / 255^2): the exact
// source-over value rounded once. With linear_blend the colour channels are blended in linear
// light and re-encoded to sRGB (within one level of the exact value). A shader paint is not handled here (see
// composite_span_premul).
void composite_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const Paint& paint);
// Source-over of per-pixel premultiplied RGBA8 colours `src` x coverage onto one row, each channel
// round((S c 255 + D (255^2 - Sa c)) / 255^2) as for composite_span.
void composite_span_premul(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src);

// Layers and masks (src/canvas/layer.cpp): a group with opacity, a clip path or a mask is drawn
// into a transparent layer of the target's size, multiplied by coverage masks, and composited once.
// A8 coverage of a layer: its alpha channel (clip paths, mask-type alpha)...
Mask mask_from_alpha(const Pixmap& layer);
// ...or the luminance 0.2125 R + 0.7154 G + 0.0721 B of its premultiplied colour, i.e. the
// colour's luminance times its alpha (luminance masks, sRGB values).
Mask mask_from_luminance(const Pixmap& layer);
// Multiplies every channel of `layer` by the mask's coverage (0 outside the mask's bounds).
void apply_mask(Pixmap& layer, const Mask& mask);

// How a layer combines with what is under it (W3C Compositing and Blending Level 1): the blend
// function B(Cb, Cs) on straight colours, then source-over:
// co = cs (1 - ab) + cb (1 - as) + as ab B(Cb, Cs), ao = as + ab - as ab (premultiplied c).
enum class BlendMode {
    Normal, Multiply, Screen, Overlay, Darken, Lighten, ColorDodge, ColorBurn, HardLight, SoftLight,
    Difference, Exclusion, Hue, Saturation, Color, Luminosity
};
// Parses the CSS names (normal, multiply, ..., color-dodge, ..., luminosity); false when unknown.
bool parse_blend_mode(std::string_view name, BlendMode& out);
// The blended straight colour B(cb, cs) of one pixel, channels in [0, 1] (for tests and callers
// that blend themselves).
void blend_colors(BlendMode mode, const float cb[3], const float cs[3], float out[3]);

class Canvas {
public:
    explicit Canvas(Pixmap& target);

    Pixmap& target() { return *target_; }
    int width() const { return target_->width(); }
    int height() const { return target_->height(); }

    // State stack: transform and clip.
    void save();
    void restore();  // no-op when nothing was saved
    const Affine& transform() const { return state_.transform; }
    void set_transform(const Affine& m) { state_.transform = m; }
    void concat(const Affine& m) { state_.transform = state_.transform * m; }  // m applies first
    void translate(double tx, double ty) { concat(Affine::translate(tx, ty)); }
    void scale(double sx, double sy) { concat(Affine::scale(sx, sy)); }
    void rotate(double radians) { concat(Affine::rotate(radians)); }
    // Intersects the clip with the pixel bounds of `r` mapped by the current transform.
    void clip_rect(const Rect& r);
    const IRect& clip() const { return state_.clip; }

    FillOptions& fill_options() { return fill_options_; }  // tolerance, exactness

    void clear(Color c);
    void fill_path(const Path& path, const Paint& paint, FillRule rule = FillRule::NonZero);
    // Strokes `path` with `style` in user space (so a non-uniform transform gives an elliptical
    // pen, as SVG requires) and fills the outline with the nonzero rule.
    void stroke_path(const Path& path, const StrokeStyle& style, const Paint& paint);
    // Composites an A8 mask (pixel space, the current transform is not applied to the mask; it
    // is to a shader's coordinates) with `paint`.
    void fill_mask(const Mask& mask, const Paint& paint);

    // Source-over of `layer` (same size as the target, pixel space) times `opacity`, inside the
    // current clip rectangle.
    void draw_layer(const Pixmap& layer, double opacity = 1.0, BlendMode mode = BlendMode::Normal);

    Rasterizer& rasterizer() { return raster_; }

private:
    struct State {
        Affine transform;
        IRect clip;
    };
    Pixmap* target_;
    State state_;
    std::vector<State> stack_;
    FillOptions fill_options_;
    Rasterizer raster_;
    std::vector<std::uint8_t> scratch_;  // a row of shader colours
};

}  // namespace casteljau
