// Paint stage, internal: source-over of one premultiplied colour onto a span of premultiplied
// RGBA8 pixels, weighted by 8-bit coverage, vectorised (solid_over.cpp). Every pixel is the exact
// formula of pixel::source_over, rounded once, on every instruction set.
#pragma once

#include <cstdint>

namespace casteljau::paint_simd {

// 1 / 65025 in float: trunc(t x kInv65025) = floor(t / 65025) for every integer 0 <= t < 2^24.
inline constexpr float kInv65025 = 1.0f / 65025.0f;

// dst: `length` pixels; coverage: `length` bytes; solid: the colour, premultiplied, 4 bytes.
void solid_over_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* solid);

}  // namespace casteljau::paint_simd
