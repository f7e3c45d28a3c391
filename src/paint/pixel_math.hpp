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

}  // namespace casteljau::pixel
