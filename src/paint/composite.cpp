// Paint stage, compositing: blend_span (any blend mode, float formula, include/casteljau/blend_mode.hpp)
// and source-over of a solid Paint or of premultiplied pixels, weighted by 8-bit coverage, onto
// premultiplied RGBA8 pixels. Source-over is source_over_span.cpp's SIMD kernel: each channel the
// exact value rounded once to the nearest 1/255 (tests/paint/test_composite.cpp checks every
// coverage against that formula). Optional linear-light blending converts through lookup tables
// (sRGB -> linear float, linear 12-bit -> sRGB) and blends there.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "casteljau/paint.hpp"
#include "paint/pixel_math.hpp"
#include "paint/source_over_span.hpp"

namespace casteljau {

namespace {

using pixel::unit_to_byte;

struct LinearTables {
    std::array<float, 256> to_linear{};
    std::array<std::uint8_t, 4097> to_srgb{};
    LinearTables() {
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            to_linear[static_cast<std::size_t>(i)] =
                static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        for (int i = 0; i <= 4096; ++i) {
            const double l = i / 4096.0;
            const double c = l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1 / 2.4) - 0.055;
            to_srgb[static_cast<std::size_t>(i)] =
                static_cast<std::uint8_t>(std::lround(std::clamp(c, 0.0, 1.0) * 255));
        }
    }
    std::uint8_t srgb(float linear) const {
        const int i = static_cast<int>(std::clamp(linear, 0.0f, 1.0f) * 4096.0f + 0.5f);
        return to_srgb[static_cast<std::size_t>(i)];
    }
};

const LinearTables& tables() {
    static const LinearTables t;  // immutable after construction (thread-safe static init)
    return t;
}

void composite_linear(std::uint8_t* dst, int length, const std::uint8_t* coverage, Color color) {
    const LinearTables& t = tables();
    const float sr = t.to_linear[color.r], sg = t.to_linear[color.g], sb = t.to_linear[color.b];
    for (int i = 0; i < length; ++i, dst += 4) {
        const unsigned c = coverage[i];
        if (c == 0) continue;
        const float a = static_cast<float>(c) * color.a / (255.0f * 255.0f);
        const float da = dst[3] / 255.0f;
        const float oa = a + da * (1 - a);
        if (oa <= 0) continue;
        // Straight destination colour in linear light.
        float dr = 0, dg = 0, db = 0;
        if (dst[3] != 0) {
            const Color d = unpremultiply({dst[0], dst[1], dst[2], dst[3]});
            dr = t.to_linear[d.r];
            dg = t.to_linear[d.g];
            db = t.to_linear[d.b];
        }
        const float wd = da * (1 - a) / oa, ws = a / oa;
        const Color out{t.srgb(sr * ws + dr * wd), t.srgb(sg * ws + dg * wd), t.srgb(sb * ws + db * wd),
                        static_cast<std::uint8_t>(std::lround(oa * 255))};
        const PremulPixel p = premultiply(out);
        dst[0] = p.r;
        dst[1] = p.g;
        dst[2] = p.b;
        dst[3] = p.a;
    }
}

}  // namespace

void composite_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const Paint& paint) {
    const Color color = paint.opacity >= 1.0 ? paint.color : paint.color.with_opacity(paint.opacity);
    if (color.a == 0) return;
    if (paint.linear_blend) return composite_linear(dst, length, coverage, color);
    const PremulPixel s = premultiply(color);
    const std::uint8_t solid[4] = {s.r, s.g, s.b, s.a};
    paint_simd::source_over_span(dst, length, coverage, solid, 0);
}

void composite_span_premul(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src) {
    blend_span(dst, length, coverage, src, BlendMode::SourceOver);
}

void blend_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src, BlendMode mode,
                int src_stride) {
    const int step = src_stride == 0 ? 0 : 4;
    if (mode == BlendMode::SourceOver) return paint_simd::source_over_span(dst, length, coverage, src, step);
    if (mode == BlendMode::Destination) return;
    for (int i = 0; i < length; ++i, dst += 4, src += step) {
        const unsigned c = coverage ? coverage[i] : 255u;
        if (c == 0) continue;
        const float s[4] = {src[0] / 255.0f, src[1] / 255.0f, src[2] / 255.0f, src[3] / 255.0f};
        const float d[4] = {dst[0] / 255.0f, dst[1] / 255.0f, dst[2] / 255.0f, dst[3] / 255.0f};
        float r[4];
        blend_pixel(mode, s, d, r);
        const float w = c / 255.0f;
        const std::uint8_t a = unit_to_byte(d[3] + w * (r[3] - d[3]));
        for (int k = 0; k < 3; ++k) dst[k] = std::min(unit_to_byte(d[k] + w * (r[k] - d[k])), a);
        dst[3] = a;
    }
}

}  // namespace casteljau
