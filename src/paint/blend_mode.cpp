// Paint stage: blend modes and Porter-Duff operators (include/casteljau/blend_mode.hpp), the
// per-pixel formulas of W3C Compositing and Blending Level 1 in float.
#include "casteljau/blend_mode.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace casteljau {

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

constexpr std::pair<std::string_view, BlendMode> kNames[] = {{"normal", BlendMode::Normal},
                                                             {"multiply", BlendMode::Multiply},
                                                             {"screen", BlendMode::Screen},
                                                             {"overlay", BlendMode::Overlay},
                                                             {"darken", BlendMode::Darken},
                                                             {"lighten", BlendMode::Lighten},
                                                             {"color-dodge", BlendMode::ColorDodge},
                                                             {"color-burn", BlendMode::ColorBurn},
                                                             {"hard-light", BlendMode::HardLight},
                                                             {"soft-light", BlendMode::SoftLight},
                                                             {"difference", BlendMode::Difference},
                                                             {"exclusion", BlendMode::Exclusion},
                                                             {"hue", BlendMode::Hue},
                                                             {"saturation", BlendMode::Saturation},
                                                             {"color", BlendMode::Color},
                                                             {"luminosity", BlendMode::Luminosity},
                                                             {"clear", BlendMode::Clear},
                                                             {"copy", BlendMode::Source},
                                                             {"destination", BlendMode::Destination},
                                                             {"destination-over", BlendMode::DestinationOver},
                                                             {"source-in", BlendMode::SourceIn},
                                                             {"destination-in", BlendMode::DestinationIn},
                                                             {"source-out", BlendMode::SourceOut},
                                                             {"destination-out", BlendMode::DestinationOut},
                                                             {"source-atop", BlendMode::SourceAtop},
                                                             {"destination-atop", BlendMode::DestinationAtop},
                                                             {"xor", BlendMode::Xor},
                                                             {"plus-lighter", BlendMode::Plus},
                                                             // Aliases (parsed, never printed).
                                                             {"source-over", BlendMode::SourceOver},
                                                             {"source", BlendMode::Source},
                                                             {"lighter", BlendMode::Plus}};

bool parse_blend_mode(std::string_view name, BlendMode& out) {
    for (const auto& [n, m] : kNames)
        if (n == name && !(is_porter_duff(m) && m != BlendMode::Normal)) {
            out = m;
            return true;
        }
    return false;
}

bool parse_blend_operator(std::string_view name, BlendMode& out) {
    for (const auto& [n, m] : kNames)
        if (n == name && n != "normal") {
            out = m;
            return true;
        }
    return false;
}

std::string_view blend_mode_name(BlendMode mode) {
    for (const auto& [n, m] : kNames)
        if (m == mode) return n;
    return "normal";
}

bool is_porter_duff(BlendMode mode) { return mode == BlendMode::Normal || mode >= BlendMode::Clear; }

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

void blend_pixel(BlendMode mode, const float s[4], const float d[4], float out[4]) {
    const float as = s[3], ab = d[3];
    if (is_porter_duff(mode)) {
        float fa = 0, fb = 0;
        switch (mode) {
            case BlendMode::Plus:
                for (int k = 0; k < 4; ++k) out[k] = std::min(1.0f, s[k] + d[k]);
                return;
            case BlendMode::Clear: break;
            case BlendMode::Source: fa = 1; break;
            case BlendMode::Destination: fb = 1; break;
            case BlendMode::DestinationOver:
                fa = 1 - ab;
                fb = 1;
                break;
            case BlendMode::SourceIn: fa = ab; break;
            case BlendMode::DestinationIn: fb = as; break;
            case BlendMode::SourceOut: fa = 1 - ab; break;
            case BlendMode::DestinationOut: fb = 1 - as; break;
            case BlendMode::SourceAtop:
                fa = ab;
                fb = 1 - as;
                break;
            case BlendMode::DestinationAtop:
                fa = 1 - ab;
                fb = as;
                break;
            case BlendMode::Xor:
                fa = 1 - ab;
                fb = 1 - as;
                break;
            default:
                fa = 1;
                fb = 1 - as;
                break;  // source-over
        }
        for (int k = 0; k < 4; ++k) out[k] = fa * s[k] + fb * d[k];
        return;
    }
    // Straight colours of both sides (black where transparent: the term they enter is then 0).
    float cs[3], cb[3], b[3];
    for (int k = 0; k < 3; ++k) {
        cs[k] = as > 0 ? std::min(1.0f, s[k] / as) : 0.0f;
        cb[k] = ab > 0 ? std::min(1.0f, d[k] / ab) : 0.0f;
    }
    blend_colors(mode, cb, cs, b);
    for (int k = 0; k < 3; ++k) out[k] = s[k] * (1 - ab) + d[k] * (1 - as) + as * ab * std::clamp(b[k], 0.0f, 1.0f);
    out[3] = as + ab - as * ab;
}

}  // namespace casteljau
