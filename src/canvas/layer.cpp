// Canvas stage: layers and coverage masks (include/casteljau/canvas.hpp). A group with opacity,
// a clip path or a mask is drawn into a transparent layer the size of the target; clip paths and
// masks are themselves drawn into layers and turned into A8 coverage (the alpha channel, or the
// luminance for luminance masks) that multiplies the layer before it is composited once. Clip
// coverage so stays the exact-area coverage of the clip shapes, without supersampling.
#include <algorithm>
#include <cmath>

#include "casteljau/canvas.hpp"

namespace casteljau {

namespace {
inline std::uint8_t mul_div255(unsigned a, unsigned b) {
    const unsigned t = a * b + 128;
    return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}

Mask empty_mask(const Pixmap& layer) {
    Mask m;
    m.bounds = {0, 0, layer.width(), layer.height()};
    m.data.assign(static_cast<std::size_t>(layer.width()) * static_cast<std::size_t>(layer.height()), 0);
    return m;
}
}  // namespace

Mask mask_from_alpha(const Pixmap& layer) {
    Mask m = empty_mask(layer);
    const std::uint8_t* p = layer.data();
    for (std::uint8_t& v : m.data) {
        v = p[3];
        p += 4;
    }
    return m;
}

Mask mask_from_luminance(const Pixmap& layer) {
    // Luminance of the premultiplied colour is the straight colour's luminance times its alpha.
    Mask m = empty_mask(layer);
    const std::uint8_t* p = layer.data();
    for (std::uint8_t& v : m.data) {
        const double l = 0.2125 * p[0] + 0.7154 * p[1] + 0.0721 * p[2];
        v = static_cast<std::uint8_t>(std::min(255.0, l + 0.5));
        p += 4;
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

void Canvas::draw_layer(const Pixmap& layer, double opacity) {
    const IRect& c = state_.clip;
    const int x1 = std::min(c.x1, layer.width()), y1 = std::min(c.y1, layer.height());
    const unsigned o = static_cast<unsigned>(std::lround(std::clamp(opacity, 0.0, 1.0) * 255));
    if (o == 0) return;
    for (int y = c.y0; y < y1; ++y) {
        const std::uint8_t* s = layer.row(y) + 4 * static_cast<std::size_t>(c.x0);
        std::uint8_t* d = target_->row(y) + 4 * static_cast<std::size_t>(c.x0);
        for (int x = c.x0; x < x1; ++x, s += 4, d += 4) {
            if (s[3] == 0) continue;
            unsigned sc[4];
            for (int k = 0; k < 4; ++k) sc[k] = o == 255 ? s[k] : mul_div255(s[k], o);
            const unsigned inv = 255 - sc[3];
            for (int k = 0; k < 4; ++k) d[k] = static_cast<std::uint8_t>(sc[k] + mul_div255(d[k], inv));
        }
    }
}

}  // namespace casteljau
