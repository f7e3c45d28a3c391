// casteljau/canvas.hpp: the drawing-backend face of casteljau.
//
// A Canvas draws onto a Pixmap it does not own (or straight into caller-owned memory): a state
// stack (transform, clip, opacity, blend mode) with save()/restore(); clips to rectangles and to
// any path with exact anti-aliased coverage; fills and strokes of Paths with a Paint (solid,
// gradients, image patterns; every Porter-Duff operator and CSS blend mode); images; A8 masks;
// layers. Every fill walks the pipeline: Path --transform--> flatten --> rasterize (exact area)
// --> x clip coverage --> paint stage (shade, blend, composite; src/paint).
// Coordinates: user space is mapped to pixel space (x right, y down, pixel (i, j) the square
// [i, i+1) x [j, j+1)) by the current transform.
// Ownership: the Canvas borrows its target and owns its layers; Paths, Paints and images passed to
// it are only read during the call.
// Thread-safety: a Canvas and its Pixmap belong to one thread at a time.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/round_stroke.hpp"
#include "casteljau/shader.hpp"
#include "casteljau/stroke.hpp"

namespace casteljau {

// Layers and masks (src/canvas/layer.cpp): a group with opacity, a clip path or a mask is drawn
// into a transparent layer of the target's size, multiplied by coverage masks, and composited once.
// A8 coverage of a layer: its alpha channel (clip paths, mask-type alpha)...
Mask mask_from_alpha(const Pixmap& layer);
// ...or the luminance 0.2125 R + 0.7154 G + 0.0721 B of its premultiplied colour, i.e. the
// colour's luminance times its alpha (luminance masks, sRGB values).
Mask mask_from_luminance(const Pixmap& layer);
// Multiplies every channel of `layer` by the mask's coverage (0 outside the mask's bounds).
void apply_mask(Pixmap& layer, const Mask& mask);

class Canvas {
public:
    // Draws into `target`, which must outlive the Canvas.
    explicit Canvas(Pixmap& target);
    // Draws straight into caller-owned premultiplied RGBA8 memory (see Pixmap::borrow): `pixels`,
    // `height` rows of `stride` bytes. Nothing is copied; the memory must outlive the Canvas.
    Canvas(std::uint8_t* pixels, int width, int height, std::size_t stride);
    Canvas(const Canvas&) = delete;
    Canvas& operator=(const Canvas&) = delete;
    ~Canvas();

    // The pixmap the Canvas was made for (layers are composited into it by end_layer()).
    Pixmap& target() { return *target_; }
    int width() const { return target_->width(); }
    int height() const { return target_->height(); }
    // Premultiplied RGBA8 pixels of the target, rows stride() bytes apart.
    std::uint8_t* pixels() { return target_->data(); }
    std::size_t stride() const { return target_->stride(); }

    // State stack: transform, clip (rectangle and coverage mask), opacity and blend mode.
    // Throws Error(Limit) past 1024 nested saves.
    void save();
    void restore();  // no-op when nothing was saved (or nothing since the innermost begin_layer)
    int save_count() const { return static_cast<int>(stack_.size()); }
    const Affine& transform() const { return state_.transform; }
    void set_transform(const Affine& m) { state_.transform = m; }
    void reset_transform() { state_.transform = Affine{}; }
    void concat(const Affine& m) { state_.transform = state_.transform * m; }  // m applies first
    void translate(double tx, double ty) { concat(Affine::translate(tx, ty)); }
    void scale(double sx, double sy) { concat(Affine::scale(sx, sy)); }
    void rotate(double radians) { concat(Affine::rotate(radians)); }
    // Skews x by tan(ax) y and y by tan(ay) x (radians).
    void skew(double ax, double ay) { concat(Affine{1, std::tan(ay), std::tan(ax), 1, 0, 0}); }

    // Clipping. The clip is the pixel rectangle clip() times an optional exact-area coverage mask
    // (clip_mask(), covering exactly clip()); every drawing operation is multiplied by it.
    // Intersects the clip with `r` mapped by the current transform: a rectangle that lands on whole
    // pixels only shrinks clip(), any other (fractional, rotated, skewed) is clipped as a path.
    void clip_rect(const Rect& r);
    // Intersects the clip with the exact coverage of `path` (current transform, `rule`): the new
    // coverage of a pixel is round(old x path coverage / 255), within 1/255 of the exact product.
    void clip_path(const Path& path, FillRule rule = FillRule::NonZero);
    const IRect& clip() const { return state_.clip; }
    const Mask* clip_mask() const { return state_.clip_mask.get(); }

    // Multiplies the alpha of everything drawn (fills, strokes, masks, images, layers).
    void set_opacity(double opacity);
    double opacity() const { return state_.opacity; }
    // The blend mode of drawing operations whose Paint says SourceOver.
    void set_blend_mode(BlendMode mode) { state_.blend = mode; }
    BlendMode blend_mode() const { return state_.blend; }

    // Default options (tolerance, exactness) of the calls that take none; calls that take
    // FillOptions use theirs and leave these alone.
    FillOptions& fill_options() { return fill_options_; }

    // Replaces the pixels inside the clip with `c` (the clip's coverage blends the edges).
    void clear(Color c);
    void fill_path(const Path& path, const Paint& paint, FillRule rule = FillRule::NonZero);
    void fill_path(const Path& path, const Paint& paint, const FillOptions& options);
    void fill_rect(const Rect& r, const Paint& paint);
    // Strokes `path` with `style` in user space (so a non-uniform transform gives an elliptical
    // pen, as SVG requires) and fills the outline with the nonzero rule.
    void stroke_path(const Path& path, const StrokeStyle& style, const Paint& paint);
    void stroke_path(const Path& path, const StrokeStyle& style, const Paint& paint, const FillOptions& options);
    // Composites an A8 mask (pixel space, the current transform is not applied to the mask; it
    // is to a shader's coordinates) with `paint`, the mask moved by (dx, dy) pixels.
    void fill_mask(const Mask& mask, const Paint& paint);
    void fill_mask(const Mask& mask, long long dx, long long dy, const Paint& paint);
    // Composites the union of the round strokes of radius `radius` around `segments` (pixel space:
    // the transform applies to a shader's coordinates only, as for masks) with `paint`: the rows of
    // round_stroke_spans() go straight to the pixels, only near the strokes.
    void fill_round_stroke(std::span<const LineSegment> segments, double radius, const Paint& paint);
    // Composites recorded coverage rows (pixel space, as fill_mask) with `paint`, inside the clip.
    void fill_coverage(const CoverageRows& rows, const Paint& paint);

    // Draws `image` (premultiplied, its pixel space [0, w] x [0, h]) mapped by `m` and then by the
    // current transform, sampled at pixel centres. The image is only read during the call.
    void draw_image(const Pixmap& image, const Affine& m = {}, ImageSampling sampling = ImageSampling::Bilinear,
                    double opacity = 1.0);

    // Composites `layer` (same size as the target, pixel space) times `opacity` with `mode`, inside
    // the current clip (its mask included). Opacity acts as coverage: D + o c (B(S, D) - D).
    void draw_layer(const Pixmap& layer, double opacity = 1.0, BlendMode mode = BlendMode::Normal);
    // Layers: save(), then draw into a transparent pixmap of the target's size until end_layer(),
    // which restores the state and composites the layer with `opacity` and `mode` (and the
    // restored state's clip and opacity). Layers nest; end_layer() without a layer does nothing.
    void begin_layer(double opacity = 1.0, BlendMode mode = BlendMode::Normal);
    void end_layer();
    int layer_depth() const { return static_cast<int>(layers_.size()); }

    Rasterizer& rasterizer() { return raster_; }

private:
    IRect reach(const Path& path) const;

    struct State {
        Affine transform;
        IRect clip;
        std::shared_ptr<const Mask> clip_mask;  // null: the rectangle alone
        double opacity = 1;
        BlendMode blend = BlendMode::SourceOver;
    };
    struct Layer;
    Pixmap& layer_or_target();       // the innermost layer, or the target
    std::unique_ptr<Pixmap> owned_;  // the borrowed-memory pixmap of the raw-pointer constructor
    Pixmap* target_;
    State state_;
    std::vector<State> stack_;
    std::vector<std::unique_ptr<Layer>> layers_;
    FillOptions fill_options_;
    Rasterizer raster_;
    std::vector<std::uint8_t> scratch_;   // shader colours of one row
    std::vector<std::uint8_t> coverage_;  // coverage x clip of one row
    StrokeOutline stroke_;                // the outline of the stroke being drawn
};

}  // namespace casteljau
