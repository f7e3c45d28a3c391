// Canvas: the drawing-backend face. Transform stack, device clip, fills through the pipeline
// (flatten -> rasterize -> composite). See include/casteljau/canvas.hpp.
#include "casteljau/canvas.hpp"

#include <algorithm>
#include <cmath>

#include "casteljau/error.hpp"

namespace casteljau {

namespace {

// Composites coverage rows with a solid paint, or with a shader's colours computed for the row
// into `scratch` (which grows to the widest row once, not per pixel).
class CompositeSink final : public SpanSink {
public:
    CompositeSink(Pixmap& pm, const Paint& paint, const Affine& ctm, std::vector<std::uint8_t>& scratch)
        : pm_(pm), paint_(paint), scratch_(scratch) {
        if (paint.shader) {
            if (auto inv = (ctm * paint.shader->transform()).inverse()) inverse_ = *inv;
            else skip_ = true;  // a singular gradient transform paints nothing
        }
    }
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        std::uint8_t* dst = pm_.row(y) + 4 * static_cast<std::size_t>(x);
        if (!paint_.shader) return composite_span(dst, length, coverage, paint_);
        if (skip_) return;
        if (scratch_.size() < 4 * static_cast<std::size_t>(length)) scratch_.resize(4 * static_cast<std::size_t>(length));
        paint_.shader->shade_row(inverse_, x, y, length, paint_.opacity, scratch_.data());
        composite_span_premul(dst, length, coverage, scratch_.data());
    }

private:
    Pixmap& pm_;
    const Paint& paint_;
    std::vector<std::uint8_t>& scratch_;
    Affine inverse_;
    bool skip_ = false;
};

}  // namespace

Canvas::Canvas(Pixmap& target) : target_(&target) {
    state_.clip = {0, 0, target.width(), target.height()};
}

void Canvas::save() {
    if (stack_.size() >= static_cast<std::size_t>(limits::kMaxNestingDepth) * 16)
        throw Error(ErrorKind::Limit, "Canvas::save nested too deeply");
    stack_.push_back(state_);
}

void Canvas::restore() {
    if (stack_.empty()) return;
    state_ = stack_.back();
    stack_.pop_back();
}

void Canvas::clip_rect(const Rect& r) {
    const Rect b = transform_bounds(state_.transform, r);
    auto to_int = [](double v, int lo, int hi) {
        if (!(v == v)) return lo;
        return static_cast<int>(std::clamp(std::round(v), static_cast<double>(lo), static_cast<double>(hi)));
    };
    IRect c{to_int(b.x0, 0, width()), to_int(b.y0, 0, height()), to_int(b.x1, 0, width()), to_int(b.y1, 0, height())};
    state_.clip = {std::max(state_.clip.x0, c.x0), std::max(state_.clip.y0, c.y0), std::min(state_.clip.x1, c.x1),
                   std::min(state_.clip.y1, c.y1)};
    if (state_.clip.x1 < state_.clip.x0) state_.clip.x1 = state_.clip.x0;
    if (state_.clip.y1 < state_.clip.y0) state_.clip.y1 = state_.clip.y0;
}

void Canvas::clear(Color c) { target_->fill(c); }

void Canvas::fill_path(const Path& path, const Paint& paint, FillRule rule) {
    if (state_.clip.empty() || path.empty()) return;
    FillOptions opts = fill_options_;
    opts.rule = rule;
    CompositeSink sink(*target_, paint, state_.transform, scratch_);
    raster_.fill(path, state_.transform, opts, state_.clip, sink);
}

void Canvas::stroke_path(const Path& path, const StrokeStyle& style, const Paint& paint) {
    if (state_.clip.empty() || path.empty()) return;
    fill_path(stroke(path, style, state_.transform, fill_options_.tolerance), paint, FillRule::NonZero);
}

void Canvas::fill_mask(const Mask& mask, const Paint& paint) {
    const IRect& c = state_.clip;
    const int x0 = std::max(mask.bounds.x0, c.x0), x1 = std::min(mask.bounds.x1, c.x1);
    const int y0 = std::max(mask.bounds.y0, c.y0), y1 = std::min(mask.bounds.y1, c.y1);
    if (x1 <= x0 || y1 <= y0) return;
    CompositeSink sink(*target_, paint, state_.transform, scratch_);
    for (int y = y0; y < y1; ++y) {
        const std::uint8_t* cov =
            mask.data.data() + static_cast<std::size_t>(y - mask.bounds.y0) * mask.bounds.width() + (x0 - mask.bounds.x0);
        sink.row(y, x0, x1 - x0, cov);
    }
}

}  // namespace casteljau
