// Paint stage, compositing: blend_span (any blend mode, float formula, include/casteljau/blend_mode.hpp)
// and source-over of a solid Paint, weighted by 8-bit coverage, onto premultiplied
// RGBA8 pixels. Each channel is the exact source-over value rounded once to the nearest 1/255
// (tests/paint/test_composite.cpp checks every coverage against that formula); runs of full coverage with
// an opaque colour are plain stores. Optional linear-light blending converts
// through lookup tables (sRGB -> linear float, linear 12-bit -> sRGB) and blends there.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

#include "casteljau/paint.hpp"
#include "paint/pixel_math.hpp"
#include "paint/solid_over.hpp"

namespace casteljau {

namespace {

using pixel::source_over;
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
    paint_simd::solid_over_span(dst, length, coverage, solid);
}

void composite_span_premul(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src) {
    blend_span(dst, length, coverage, src, BlendMode::SourceOver);
}

void blend_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src, BlendMode mode,
                int src_stride) {
    const std::size_t step = src_stride == 0 ? 0 : 4;
    if (mode == BlendMode::SourceOver) {
        // One pixel at coverage c: nothing for c = 0 or a transparent source, a copy for an opaque
        // source at full coverage, the formula otherwise.
        auto over = [](std::uint8_t* d, const std::uint8_t* sp, unsigned c) {
            if (c == 0 || sp[3] == 0) return;
            if (c == 255 && sp[3] == 255)
                std::memcpy(d, sp, 4);
            else
                source_over(d, sp, c);
        };
        if (!coverage && step == 4) {
            // A whole layer (SeamlessCompositor, groups) is mostly runs of transparent pixels, which
            // change nothing, and of opaque ones, which replace the destination: eight at a time.
            // The alpha bytes of two pixels as a 64-bit mask, whatever the byte order.
            constexpr std::uint8_t kAlphaBytes[8] = {0, 0, 0, 0xff, 0, 0, 0, 0xff};
            std::uint64_t alpha_mask;
            std::memcpy(&alpha_mask, kAlphaBytes, 8);
            int i = 0;
            for (; i + 8 <= length; i += 8) {
                std::uint64_t w[4];
                std::memcpy(w, src + 4 * static_cast<std::size_t>(i), 32);
                std::uint8_t* d = dst + 4 * static_cast<std::size_t>(i);
                if ((w[0] | w[1] | w[2] | w[3]) == 0) continue;
                if ((w[0] & w[1] & w[2] & w[3] & alpha_mask) == alpha_mask) {
                    std::memcpy(d, w, 32);
                    continue;
                }
                const std::uint8_t* s8 = src + 4 * static_cast<std::size_t>(i);
                for (int k = 0; k < 8; ++k) over(d + 4 * k, s8 + 4 * k, 255u);
            }
            dst += 4 * static_cast<std::size_t>(i);
            src += 4 * static_cast<std::size_t>(i);
            length -= i;
        }
        for (int i = 0; i < length; ++i, dst += 4, src += step) over(dst, src, coverage ? coverage[i] : 255u);
        return;
    }
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
