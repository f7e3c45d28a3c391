// Internal (formats): PNG encoding straight through zlib for the default row filters, writing the
// bytes libpng 1.6 writes for the same settings.
//
// encode_png (png.cpp) hands libpng every row and lets it choose each row's filter; for the filter
// sets casteljau uses by default (none, or a per-row choice of none and Paeth) that choice is a
// sum over the row that png_paeth.cpp computes with SIMD; this file then feeds the chosen
// rows to zlib with the parameters libpng would pick (level, window size for small images,
// strategy) and lays the stream out in chunks as libpng does (IHDR, gAMA, sRGB, cHRM, IDAT chunks
// of 8 KiB, IEND). The tests compare its output with libpng's byte for byte.
#pragma once

#include <cstdint>
#include <vector>

#include "casteljau/paint.hpp"

namespace casteljau::png_detail {

// PNG colour types (PNG specification, table 11.1), as libpng numbers them.
constexpr int kGrey = 0, kRgb = 2, kGreyAlpha = 4, kRgba = 6;

// Encodes `pixmap` (premultiplied) as 8-bit `colour_type` samples with straight alpha, zlib level
// `level`, and rows unfiltered or, with `paeth`, each row Paeth-filtered when that makes libpng's
// heuristic sum (the row's bytes as signed magnitudes) smaller. Throws std::bad_alloc, or
// Error(InvalidData) when zlib fails.
std::vector<std::uint8_t> encode_png_direct(const Pixmap& pixmap, int colour_type, int level, bool paeth);

// The same through libpng (png.cpp), with `filters` a set of libpng's PNG_FILTER_* flags: every
// filter choice PngEncodeOptions offers, and the reference the direct encoder is tested against.
std::vector<std::uint8_t> encode_png_libpng(const Pixmap& pixmap, int colour_type, int level, int filters);

}  // namespace casteljau::png_detail
