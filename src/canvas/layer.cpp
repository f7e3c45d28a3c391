// Canvas stage: layers and coverage masks (include/casteljau/canvas.hpp). A group with opacity,
// a clip path or a mask is drawn into a transparent layer the size of the target; clip paths and
// masks are themselves drawn into layers and turned into A8 coverage (the alpha channel, or the
// luminance for luminance masks) that multiplies the layer before it is composited once. Clip
// coverage so stays the exact-area coverage of the clip shapes, without supersampling.
#include <algorithm>
#include <cmath>
#include <utility>

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

namespace {

float lum(const float c[3]) { return 0.3f * c[0] + 0.59f * c[1] + 0.11f * c[2]; }

void clip_color(float c[3]) {
    const float l = lum(c);
    const float n = std::min({c[0], c[1], c[2]}), x = std::max({c[0], c[1], c[2]});
    for (int k = 0; k < 3; ++k) {
        if (n < 0) c[k] = l + (c[k] - l) * l / (l - n);
        if (x > 1) c[k] = l + (c[k] - l) * (1 - l) / (x - l);
    }
}

void set_lum(const float c[3], float l, float out[3]) {
    const float d = l - lum(c);
    for (int k = 0; k < 3; ++k) out[k] = c[k] + d;
    clip_color(out);
}

float sat(const float c[3]) { return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}); }

void set_sat(const float c[3], float s, float out[3]) {
    int imax = 0, imin = 0;
    for (int k = 1; k < 3; ++k) {
        if (c[k] > c[imax]) imax = k;
        if (c[k] < c[imin]) imin = k;
    }
    if (imax == imin) {
        out[0] = out[1] = out[2] = 0;
        return;
    }
    const int imid = 3 - imax - imin;
    out[imid] = (c[imid] - c[imin]) * s / (c[imax] - c[imin]);
    out[imax] = s;
    out[imin] = 0;
}

float separable(BlendMode m, float b, float s) {
    switch (m) {
        case BlendMode::Multiply: return b * s;
        case BlendMode::Screen: return b + s - b * s;
        case BlendMode::Overlay: return separable(BlendMode::HardLight, s, b);
        case BlendMode::Darken: return std::min(b, s);
        case BlendMode::Lighten: return std::max(b, s);
        case BlendMode::ColorDodge:
            if (b == 0) return 0;
            if (s >= 1) return 1;
            return std::min(1.0f, b / (1 - s));
        case BlendMode::ColorBurn:
            if (b >= 1) return 1;
            if (s <= 0) return 0;
            return 1 - std::min(1.0f, (1 - b) / s);
        case BlendMode::HardLight: return s <= 0.5f ? b * 2 * s : separable(BlendMode::Screen, b, 2 * s - 1);
        case BlendMode::SoftLight: {
            if (s <= 0.5f) return b - (1 - 2 * s) * b * (1 - b);
            const float d = b <= 0.25f ? ((16 * b - 12) * b + 4) * b : std::sqrt(b);
            return b + (2 * s - 1) * (d - b);
        }
        case BlendMode::Difference: return std::fabs(b - s);
        case BlendMode::Exclusion: return b + s - 2 * b * s;
        default: return s;
    }
}

}  // namespace

bool parse_blend_mode(std::string_view name, BlendMode& out) {
    static const std::pair<std::string_view, BlendMode> kNames[] = {
        {"normal", BlendMode::Normal},         {"multiply", BlendMode::Multiply},     {"screen", BlendMode::Screen},
        {"overlay", BlendMode::Overlay},       {"darken", BlendMode::Darken},         {"lighten", BlendMode::Lighten},
        {"color-dodge", BlendMode::ColorDodge}, {"color-burn", BlendMode::ColorBurn}, {"hard-light", BlendMode::HardLight},
        {"soft-light", BlendMode::SoftLight},  {"difference", BlendMode::Difference}, {"exclusion", BlendMode::Exclusion},
        {"hue", BlendMode::Hue},               {"saturation", BlendMode::Saturation}, {"color", BlendMode::Color},
        {"luminosity", BlendMode::Luminosity}};
    for (const auto& [n, m] : kNames)
        if (n == name) {
            out = m;
            return true;
        }
    return false;
}

void blend_colors(BlendMode mode, const float cb[3], const float cs[3], float out[3]) {
    float t[3];
    switch (mode) {
        case BlendMode::Hue:
            set_sat(cs, sat(cb), t);
            set_lum(t, lum(cb), out);
            return;
        case BlendMode::Saturation:
            set_sat(cb, sat(cs), t);
            set_lum(t, lum(cb), out);
            return;
        case BlendMode::Color: set_lum(cs, lum(cb), out); return;
        case BlendMode::Luminosity: set_lum(cb, lum(cs), out); return;
        default:
            for (int k = 0; k < 3; ++k) out[k] = separable(mode, cb[k], cs[k]);
    }
}

void Canvas::draw_layer(const Pixmap& layer, double opacity, BlendMode mode) {
    const IRect& c = state_.clip;
    const int x1 = std::min(c.x1, layer.width()), y1 = std::min(c.y1, layer.height());
    const unsigned o = static_cast<unsigned>(std::lround(std::clamp(opacity, 0.0, 1.0) * 255));
    if (o == 0) return;
    if (mode != BlendMode::Normal) {
        for (int y = c.y0; y < y1; ++y) {
            const std::uint8_t* s = layer.row(y) + 4 * static_cast<std::size_t>(c.x0);
            std::uint8_t* d = target_->row(y) + 4 * static_cast<std::size_t>(c.x0);
            for (int x = c.x0; x < x1; ++x, s += 4, d += 4) {
                if (s[3] == 0) continue;
                const float as = s[3] * (o / 255.0f) / 255.0f, ab = d[3] / 255.0f;
                float cs[3], cb[3], bl[3];
                for (int k = 0; k < 3; ++k) {
                    cs[k] = s[k] / static_cast<float>(s[3]);
                    cb[k] = d[3] ? d[k] / static_cast<float>(d[3]) : 0.0f;
                }
                blend_colors(mode, cb, cs, bl);
                for (int k = 0; k < 3; ++k) {
                    const float v = cs[k] * as * (1 - ab) + cb[k] * ab * (1 - as) + as * ab * std::clamp(bl[k], 0.0f, 1.0f);
                    d[k] = static_cast<std::uint8_t>(std::clamp(v * 255.0f + 0.5f, 0.0f, 255.0f));
                }
                d[3] = static_cast<std::uint8_t>(std::clamp((as + ab - as * ab) * 255.0f + 0.5f, 0.0f, 255.0f));
                for (int k = 0; k < 3; ++k) d[k] = std::min(d[k], d[3]);
            }
        }
        return;
    }
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
