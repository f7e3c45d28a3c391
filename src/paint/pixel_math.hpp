// Paint stage, internal: the integer arithmetic of 8-bit premultiplied pixels, in one place.
#pragma once

#include <cstdint>

namespace casteljau::pixel {

// round(a * b / 255) for a, b in [0, 255], exact for all inputs.
inline std::uint8_t mul_div255(unsigned a, unsigned b) {
    const unsigned t = a * b + 128;
    return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}

// round(n / 65025) for n < 255 x 65025 + 1 (the compiler turns the constant division into a
// multiply and a shift).
inline std::uint8_t div65025(unsigned n) { return static_cast<std::uint8_t>((n + 32512u) / 65025u); }

// A value in [0, 1] as the nearest 8-bit level (NaN gives 0).
inline std::uint8_t unit_to_byte(float v) {
    return static_cast<std::uint8_t>(v > 0 ? (v < 1 ? v * 255.0f + 0.5f : 255.0f) : 0.0f);
}

// Source-over of premultiplied S x coverage c onto premultiplied D, in place:
// out = S c / 255 + D (1 - Sa c / 255^2), rounded once. Both terms are kept over the common
// denominator 255^2 = 65025; the numerator stays below 255 x 65025 < 2^24 and, 65025 being odd,
// never ends in exactly one half, so rounding is never a tie.
inline void source_over(std::uint8_t* d, const std::uint8_t* s, unsigned c) {
    const unsigned keep = 65025u - s[3] * c;
    const unsigned sc = 255u * c;
    d[0] = div65025(s[0] * sc + d[0] * keep);
    d[1] = div65025(s[1] * sc + d[1] * keep);
    d[2] = div65025(s[2] * sc + d[2] * keep);
    d[3] = div65025(s[3] * sc + d[3] * keep);
}

}  // namespace casteljau::pixel
