// Canvas: the drawing-backend face (include/casteljau/canvas.hpp). State stack, clipping (a pixel
// rectangle times an exact-area coverage mask), and every drawing call turned into rows of
// coverage handed to the paint stage's pipeline (src/paint/pipeline.hpp).
#include "casteljau/canvas.hpp"

#include <algorithm>
#include <cmath>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "canvas/layer.hpp"
#include "paint/pipeline.hpp"
#include "paint/pixel_math.hpp"

namespace casteljau {

namespace {

// Multiplies a row of coverage by the clip mask (when there is one) into `out`; returns the row
// to use.
const std::uint8_t* clip_coverage(const Mask* clip, int y, int x, int length, const std::uint8_t* coverage,
                                  std::vector<std::uint8_t>& out) {
    if (!clip) return coverage;
    if (out.size() < static_cast<std::size_t>(length)) out.resize(static_cast<std::size_t>(length));
    const std::uint8_t* m = clip->data.data() + static_cast<std::size_t>(y - clip->bounds.y0) * clip->bounds.width() +
                            (x - clip->bounds.x0);
    if (coverage)
        for (int i = 0; i < length; ++i) out[static_cast<std::size_t>(i)] = pixel::mul_div255(coverage[i], m[i]);
    else
        std::copy(m, m + length, out.begin());
    return out.data();
}

// Coverage rows from the rasterizer, times the clip, into the paint pipeline.
class PipelineSink final : public SpanSink {
public:
    PipelineSink(Pixmap& pm, PaintPipeline& pipe, const Mask* clip, std::vector<std::uint8_t>& scratch)
        : pm_(pm), pipe_(pipe), clip_(clip), scratch_(scratch) {}
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        pipe_.run(pm_, x, y, length, clip_coverage(clip_, y, x, length, coverage, scratch_));
    }

private:
    Pixmap& pm_;
    PaintPipeline& pipe_;
    const Mask* clip_;
    std::vector<std::uint8_t>& scratch_;
};

bool is_integer(double v) { return std::isfinite(v) && v == std::floor(v); }

// v clamped to [lo, hi], as an int.
int to_int(double v, int lo, int hi) {
    return static_cast<int>(std::clamp(v, static_cast<double>(lo), static_cast<double>(hi)));
}

}  // namespace

Canvas::Canvas(Pixmap& target) : target_(&target) { state_.clip = {0, 0, target.width(), target.height()}; }

Canvas::Canvas(std::uint8_t* pixels, int width, int height, std::size_t stride)
    : owned_(std::make_unique<Pixmap>(Pixmap::borrow(pixels, width, height, stride))), target_(owned_.get()) {
    state_.clip = {0, 0, width, height};
}

void Canvas::save() {
    if (const std::size_t max_depth = current_limits().canvas_save_depth; stack_.size() >= max_depth)
        throw Error(ErrorKind::Limit, "Canvas::save nested more than " + std::to_string(max_depth) + " deep");
    stack_.push_back(state_);
}

void Canvas::set_opacity(double opacity) {
    state_.opacity = std::isfinite(opacity) ? std::clamp(opacity, 0.0, 1.0) : 0.0;
}

void Canvas::clip_rect(const Rect& r) {
    const Affine& m = state_.transform;
    if ((m.b == 0 && m.c == 0) || (m.a == 0 && m.d == 0)) {
        const Rect b = transform_bounds(m, r);
        if (is_integer(b.x0) && is_integer(b.y0) && is_integer(b.x1) && is_integer(b.y1)) {
            // Whole pixels: the rectangle alone (the mask, if any, is cut to it).
            const IRect c{to_int(b.x0, 0, width()), to_int(b.y0, 0, height()), to_int(b.x1, 0, width()),
                          to_int(b.y1, 0, height())};
            IRect n{std::max(state_.clip.x0, c.x0), std::max(state_.clip.y0, c.y0), std::min(state_.clip.x1, c.x1),
                    std::min(state_.clip.y1, c.y1)};
            n.x1 = std::max(n.x1, n.x0);
            n.y1 = std::max(n.y1, n.y0);
            if (state_.clip_mask && !(n == state_.clip)) {
                auto cut = std::make_shared<Mask>();
                cut->bounds = n;
                cut->data.resize(static_cast<std::size_t>(n.width()) * static_cast<std::size_t>(n.height()));
                for (int y = n.y0; y < n.y1; ++y)
                    for (int x = n.x0; x < n.x1; ++x)
                        cut->data[static_cast<std::size_t>(y - n.y0) * n.width() + (x - n.x0)] =
                            state_.clip_mask->at(x, y);
                state_.clip_mask = std::move(cut);
            }
            state_.clip = n;
            return;
        }
    }
    Path p;
    p.add_rect(r);
    clip_path(p, FillRule::NonZero);
}

// The part of the current clip that `path` (under the current transform) can cover: its transformed
// control bounds, which hold its curves, in whole pixels. The current clip itself when the bounds are
// not finite (the rasterizer then refuses the path).
IRect Canvas::reach(const Path& path) const {
    const Rect b = transform_bounds(state_.transform, path.control_bounds());
    const IRect& c = state_.clip;
    if (!std::isfinite(b.x0) || !std::isfinite(b.y0) || !std::isfinite(b.x1) || !std::isfinite(b.y1)) return c;
    return IRect{to_int(std::floor(b.x0), c.x0, c.x1), to_int(std::floor(b.y0), c.y0, c.y1),
                 to_int(std::ceil(b.x1), c.x0, c.x1), to_int(std::ceil(b.y1), c.y0, c.y1)};
}

void Canvas::clip_path(const Path& path, FillRule rule) {
    FillOptions opts = fill_options_;
    opts.rule = rule;
    Mask m;
    if (!state_.clip.empty() && !path.empty()) m = raster_.fill_mask(path, state_.transform, opts, reach(path));
    if (m.bounds.empty()) {
        state_.clip = {state_.clip.x0, state_.clip.y0, state_.clip.x0, state_.clip.y0};
        state_.clip_mask.reset();
        return;
    }
    if (state_.clip_mask)
        for (int y = m.bounds.y0; y < m.bounds.y1; ++y)
            for (int x = m.bounds.x0; x < m.bounds.x1; ++x) {
                std::uint8_t& v =
                    m.data[static_cast<std::size_t>(y - m.bounds.y0) * m.bounds.width() + (x - m.bounds.x0)];
                v = pixel::mul_div255(v, state_.clip_mask->at(x, y));
            }
    state_.clip = m.bounds;
    state_.clip_mask = std::make_shared<const Mask>(std::move(m));
}

void Canvas::clear(Color c) {
    const IRect& r = state_.clip;
    if (r.empty()) return;
    Pixmap& pm = layer_or_target();
    if (!state_.clip_mask && r == IRect{0, 0, width(), height()}) return pm.fill(c);
    const PremulPixel p = premultiply(c);
    const std::uint8_t px[4] = {p.r, p.g, p.b, p.a};
    for (int y = r.y0; y < r.y1; ++y) {
        const std::uint8_t* cov = clip_coverage(state_.clip_mask.get(), y, r.x0, r.width(), nullptr, coverage_);
        blend_span(pm.row(y) + 4 * static_cast<std::size_t>(r.x0), r.width(), cov, px, BlendMode::Source, 0);
    }
}

void Canvas::fill_path(const Path& path, const Paint& paint, FillRule rule) {
    FillOptions opts = fill_options_;
    opts.rule = rule;
    fill_path(path, paint, opts);
}

void Canvas::fill_path(const Path& path, const Paint& paint, const FillOptions& options) {
    if (state_.clip.empty() || path.empty()) return;
    PaintPipeline pipe(paint, state_.transform, state_.opacity, state_.blend, scratch_);
    if (pipe.paints_nothing()) return;
    PipelineSink sink(layer_or_target(), pipe, state_.clip_mask.get(), coverage_);
    raster_.fill(path, state_.transform, options, state_.clip, sink);
}

void Canvas::fill_rect(const Rect& r, const Paint& paint) {
    Path p;
    p.add_rect(r);
    fill_path(p, paint, FillRule::NonZero);
}

void Canvas::stroke_path(const Path& path, const StrokeStyle& style, const Paint& paint) {
    stroke_path(path, style, paint, fill_options_);
}

void Canvas::stroke_path(const Path& path, const StrokeStyle& style, const Paint& paint, const FillOptions& options) {
    if (state_.clip.empty() || path.empty()) return;
    FillOptions opts = options;
    opts.rule = FillRule::NonZero;
    // The outline goes into a list the canvas keeps, unless it grew past kKeptStrokePoints.
    constexpr std::size_t kKeptStrokePoints = std::size_t(1) << 18;
    struct Release {
        StrokeOutline& s;
        ~Release() {
            if (s.outline.points().size() > kKeptStrokePoints) s = StrokeOutline{};
        }
    } release{stroke_};
    stroke_outline(path, style, state_.transform, options.tolerance, stroke_);
    opts.inside = stroke_.inside;
    fill_path(stroke_.outline, paint, opts);
}

void Canvas::fill_mask(const Mask& mask, const Paint& paint) { fill_mask(mask, 0, 0, paint); }

void Canvas::fill_mask(const Mask& mask, long long dx, long long dy, const Paint& paint) {
    if (mask.bounds.empty() || state_.clip.empty()) return;
    const IRect& c = state_.clip;
    const long long x0 = std::max<long long>(mask.bounds.x0 + dx, c.x0),
                    x1 = std::min<long long>(mask.bounds.x1 + dx, c.x1);
    const long long y0 = std::max<long long>(mask.bounds.y0 + dy, c.y0),
                    y1 = std::min<long long>(mask.bounds.y1 + dy, c.y1);
    if (x1 <= x0 || y1 <= y0) return;
    PaintPipeline pipe(paint, state_.transform, state_.opacity, state_.blend, scratch_);
    if (pipe.paints_nothing()) return;
    Pixmap& pm = layer_or_target();
    const long long w = mask.bounds.width();
    for (long long y = y0; y < y1; ++y) {
        const std::uint8_t* cov = mask.data.data() + (y - dy - mask.bounds.y0) * w + (x0 - dx - mask.bounds.x0);
        const int yi = static_cast<int>(y), xi = static_cast<int>(x0), len = static_cast<int>(x1 - x0);
        pipe.run(pm, xi, yi, len, clip_coverage(state_.clip_mask.get(), yi, xi, len, cov, coverage_));
    }
}

void Canvas::fill_round_stroke(std::span<const LineSegment> segments, double radius, const Paint& paint) {
    if (state_.clip.empty() || segments.empty()) return;
    PaintPipeline pipe(paint, state_.transform, state_.opacity, state_.blend, scratch_);
    if (pipe.paints_nothing()) return;
    PipelineSink sink(layer_or_target(), pipe, state_.clip_mask.get(), coverage_);
    round_stroke_spans(segments, radius, state_.clip, sink);
}

void Canvas::fill_coverage(const CoverageRows& rows, const Paint& paint) {
    if (state_.clip.empty() || rows.empty()) return;
    PaintPipeline pipe(paint, state_.transform, state_.opacity, state_.blend, scratch_);
    if (pipe.paints_nothing()) return;
    PipelineSink pixels(layer_or_target(), pipe, state_.clip_mask.get(), coverage_);
    // The rows' parts inside the clip rectangle.
    class Clipped final : public SpanSink {
    public:
        Clipped(const IRect& clip, SpanSink& to) : clip_(clip), to_(to) {}
        void row(int y, int x, int length, const std::uint8_t* coverage) override {
            if (y < clip_.y0 || y >= clip_.y1) return;
            const int x0 = std::max(x, clip_.x0), x1 = std::min(x + length, clip_.x1);
            if (x1 > x0) to_.row(y, x0, x1 - x0, coverage + (x0 - x));
        }

    private:
        const IRect& clip_;
        SpanSink& to_;
    } clipped(state_.clip, pixels);
    rows.replay(clipped);
}

void Canvas::draw_image(const Pixmap& image, const Affine& m, ImageSampling sampling, double opacity) {
    if (image.width() < 1 || image.height() < 1) throw Error(ErrorKind::InvalidArgument, "draw_image: empty image");
    // The shader only reads the image during this call: share it without owning it.
    std::shared_ptr<const Pixmap> view(std::shared_ptr<const Pixmap>{}, &image);
    Paint paint = Paint::shaded(Shader::image(std::move(view), sampling));
    paint.opacity = opacity;
    Path rect;
    rect.add_rect({0, 0, static_cast<double>(image.width()), static_cast<double>(image.height())});
    const Affine saved = state_.transform;
    state_.transform = saved * m;
    try {
        fill_path(rect, paint, FillRule::NonZero);
    } catch (...) {
        state_.transform = saved;
        throw;
    }
    state_.transform = saved;
}

}  // namespace casteljau
