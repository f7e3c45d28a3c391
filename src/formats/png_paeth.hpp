// Internal (formats): the Paeth filter of one PNG row and the sums libpng chooses filters by, with
// Highway's runtime dispatch (core/simd_dispatch.hpp). Used by png_direct.cpp.
#pragma once

#include <cstddef>
#include <cstdint>

namespace casteljau::png_detail {

// libpng's measure of a row of filter output: the sum of its bytes read as signed magnitudes,
// min(v, 256 - v).
struct RowSums {
    std::uint64_t none = 0;   // of `row` itself (the filter "none")
    std::uint64_t paeth = 0;  // of the Paeth-filtered row
};

// Writes the Paeth filter of `row` (n bytes, `bpp` bytes per pixel) over `prev` (the row above, zeros
// above the first) to `out`, and returns both sums. Every target gives the same bytes and sums.
RowSums paeth_row(const std::uint8_t* row, const std::uint8_t* prev, std::size_t n, std::size_t bpp, std::uint8_t* out);

}  // namespace casteljau::png_detail
