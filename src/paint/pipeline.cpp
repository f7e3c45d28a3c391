// Paint stage: the per-call pipeline (src/paint/pipeline.hpp): shade -> blend -> composite.
#include "paint/pipeline.hpp"

#include <algorithm>
#include <cmath>

#include "casteljau/shader.hpp"

namespace casteljau {

PaintPipeline::PaintPipeline(const Paint& paint, const Affine& user_to_pixel, double opacity, BlendMode mode,
                             std::vector<std::uint8_t>& scratch)
    : solid_(paint), scratch_(scratch) {
    const double po = std::isfinite(paint.opacity) ? std::clamp(paint.opacity, 0.0, 1.0) : 0.0;
    const double so = std::isfinite(opacity) ? std::clamp(opacity, 0.0, 1.0) : 0.0;
    opacity_ = po * so;
    solid_.opacity = opacity_;
    solid_.shader.reset();
    mode_ = paint.blend != BlendMode::SourceOver ? paint.blend : mode;
    if (paint.shader) {
        shader_ = paint.shader.get();
        if (auto inv = (user_to_pixel * shader_->transform()).inverse())
            inverse_ = *inv;
        else
            skip_ = true;  // a singular shader transform paints nothing
    } else {
        const PremulPixel p = premultiply(paint.color.with_opacity(opacity_));
        premul_[0] = p.r;
        premul_[1] = p.g;
        premul_[2] = p.b;
        premul_[3] = p.a;
    }
    // A transparent source changes nothing under source-over (other operators may clear).
    if (mode_ == BlendMode::SourceOver && opacity_ <= 0) skip_ = true;
    if (mode_ == BlendMode::Destination) skip_ = true;
}

void PaintPipeline::run(Pixmap& pm, int x, int y, int length, const std::uint8_t* coverage) {
    if (skip_ || length <= 0) return;
    std::uint8_t* dst = pm.row(y) + 4 * static_cast<std::size_t>(x);
    if (!shader_) {
        if (mode_ == BlendMode::SourceOver) return composite_span(dst, length, coverage, solid_);
        return blend_span(dst, length, coverage, premul_, mode_, 0);
    }
    if (scratch_.size() < 4 * static_cast<std::size_t>(length)) scratch_.resize(4 * static_cast<std::size_t>(length));
    if (!coverage || mode_ != BlendMode::SourceOver) {
        shader_->shade_row(inverse_, x, y, length, opacity_, scratch_.data());
        return blend_span(dst, length, coverage, scratch_.data(), mode_);
    }
    // Source-over leaves pixels of zero coverage unchanged: only the runs between them are shaded
    // (a star or an ellipse leaves much of its box empty).
    for (int i = 0; i < length;) {
        while (i < length && coverage[i] == 0) ++i;
        const int from = i;
        while (i < length && coverage[i] != 0) ++i;
        if (i == from) break;
        shader_->shade_row(inverse_, x + from, y, i - from, opacity_, scratch_.data());
        blend_span(dst + 4 * static_cast<std::size_t>(from), i - from, coverage + from, scratch_.data(), mode_);
    }
}

}  // namespace casteljau
