// Paint stage, internal: source-over of premultiplied RGBA8 pixels onto premultiplied RGBA8
// pixels, weighted by 8-bit coverage, vectorised (source_over_span.cpp). Every pixel is the exact
// formula of pixel::source_over, rounded once, on every instruction set.
#pragma once

#include <cstdint>

namespace casteljau::paint_simd {

// 1 / 65025 in float: trunc(t x kInv65025) = floor(t / 65025) for every integer 0 <= t < 2^24.
inline constexpr float kInv65025 = 1.0f / 65025.0f;

// dst: `length` pixels. src: one pixel for the whole span (src_step 0) or `length` pixels
// (src_step 4). coverage: `length` bytes, or null for full coverage everywhere.
void source_over_span(std::uint8_t* dst, int length, const std::uint8_t* coverage, const std::uint8_t* src,
                      int src_step);

}  // namespace casteljau::paint_simd
