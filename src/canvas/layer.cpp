// Canvas stage: layers and coverage masks (include/casteljau/canvas.hpp). A group with opacity,
// a clip path or a mask is drawn into a transparent layer the size of the target; clip paths and
// masks are themselves drawn into layers and turned into A8 coverage (the alpha channel, or the
// luminance for luminance masks) that multiplies the layer before it is composited once. Clip
// coverage so stays the exact-area coverage of the clip shapes, without supersampling.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "canvas/layer.hpp"
#include "paint/pixel_math.hpp"

namespace casteljau {

using pixel::mul_div255;

namespace {

Mask empty_mask(const Pixmap& layer) {
    Mask m;
    m.bounds = {0, 0, layer.width(), layer.height()};
    m.data.assign(static_cast<std::size_t>(layer.width()) * static_cast<std::size_t>(layer.height()), 0);
    return m;
}
}  // namespace

Mask mask_from_alpha(const Pixmap& layer) {
    Mask m = empty_mask(layer);
    std::uint8_t* v = m.data.data();
    for (int y = 0; y < layer.height(); ++y) {
        const std::uint8_t* p = layer.row(y);
        for (int x = 0; x < layer.width(); ++x, p += 4) *v++ = p[3];
    }
    return m;
}

Mask mask_from_luminance(const Pixmap& layer) {
    // Luminance of the premultiplied colour is the straight colour's luminance times its alpha.
    Mask m = empty_mask(layer);
    std::uint8_t* v = m.data.data();
    for (int y = 0; y < layer.height(); ++y) {
        const std::uint8_t* p = layer.row(y);
        for (int x = 0; x < layer.width(); ++x, p += 4) {
            const double l = 0.2125 * p[0] + 0.7154 * p[1] + 0.0721 * p[2];
            *v++ = static_cast<std::uint8_t>(std::min(255.0, l + 0.5));
        }
    }
    return m;
}

void apply_mask(Pixmap& layer, const Mask& mask) {
    for (int y = 0; y < layer.height(); ++y) {
        std::uint8_t* p = layer.row(y);
        for (int x = 0; x < layer.width(); ++x, p += 4) {
            const unsigned c = mask.at(x, y);
            if (c == 255) continue;
            if (c == 0) {
                p[0] = p[1] = p[2] = p[3] = 0;
                continue;
            }
            for (int k = 0; k < 4; ++k) p[k] = mul_div255(p[k], c);
        }
    }
}

Canvas::~Canvas() = default;

Pixmap& Canvas::layer_or_target() { return layers_.empty() ? *target_ : layers_.back()->pixels; }

void Canvas::restore() {
    const std::size_t floor = layers_.empty() ? 0 : layers_.back()->saved_depth;
    if (stack_.size() <= floor) return;
    state_ = std::move(stack_.back());
    stack_.pop_back();
}

void Canvas::begin_layer(double opacity, BlendMode mode) {
    if (const int max_depth = current_limits().nesting_depth; layers_.size() >= static_cast<std::size_t>(max_depth))
        throw Error(ErrorKind::Limit, "Canvas::begin_layer nested more than " + std::to_string(max_depth) + " deep");
    save();
    auto layer = std::make_unique<Layer>(Layer{
        Pixmap(width(), height()), std::isfinite(opacity) ? std::clamp(opacity, 0.0, 1.0) : 0.0, mode, stack_.size()});
    layers_.push_back(std::move(layer));
    // Inside the layer, drawing is plain: opacity and blend mode apply once, when it is composited.
    state_.opacity = 1;
    state_.blend = BlendMode::SourceOver;
}

void Canvas::end_layer() {
    if (layers_.empty()) return;
    std::unique_ptr<Layer> layer = std::move(layers_.back());
    layers_.pop_back();
    while (stack_.size() > layer->saved_depth) stack_.pop_back();
    state_ = std::move(stack_.back());
    stack_.pop_back();
    draw_layer(layer->pixels, layer->opacity, layer->mode);
}

void Canvas::draw_layer(const Pixmap& layer, double opacity, BlendMode mode) {
    const IRect& c = state_.clip;
    const int x1 = std::min(c.x1, layer.width()), y1 = std::min(c.y1, layer.height());
    const double o = (std::isfinite(opacity) ? std::clamp(opacity, 0.0, 1.0) : 0.0) * state_.opacity;
    const unsigned ob = static_cast<unsigned>(std::lround(o * 255));
    if (ob == 0 || x1 <= c.x0 || y1 <= c.y0) return;
    const int len = x1 - c.x0;
    if (coverage_.size() < static_cast<std::size_t>(len)) coverage_.resize(static_cast<std::size_t>(len));
    Pixmap& dst = layer_or_target();
    const Mask* clip = state_.clip_mask.get();
    for (int y = c.y0; y < y1; ++y) {
        const std::uint8_t* cov = nullptr;
        if (clip || ob != 255) {
            const std::uint8_t* m = clip ? clip->data.data() +
                                               static_cast<std::size_t>(y - clip->bounds.y0) * clip->bounds.width() +
                                               (c.x0 - clip->bounds.x0)
                                         : nullptr;
            for (int i = 0; i < len; ++i)
                coverage_[static_cast<std::size_t>(i)] = m ? mul_div255(m[i], ob) : static_cast<std::uint8_t>(ob);
            cov = coverage_.data();
        }
        blend_span(dst.row(y) + 4 * static_cast<std::size_t>(c.x0), len, cov,
                   layer.row(y) + 4 * static_cast<std::size_t>(c.x0), mode);
    }
}

}  // namespace casteljau
