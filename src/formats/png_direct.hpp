// Internal (formats): PNG encoding without libpng for the default row filters: the rows libpng 1.6
// would write for the same settings, deflated by libdeflate.
//
// encode_png (png.cpp) hands libpng every row and lets it choose each row's filter; for the filter
// sets casteljau uses by default (none, or a per-row choice of none and Paeth) that choice is a
// sum over the row that png_paeth.cpp computes with SIMD. This file filters the rows as libpng
// would and deflates them in one piece with libdeflate, which at the same level takes a third to
// a quarter of zlib's time and writes a slightly smaller stream; it needs the filtered image in
// memory, so an image larger than `whole_limit` bytes filtered goes to zlib a row at a time with
// libpng's parameters instead (level, strategy). The chunks are laid out as libpng does (IHDR,
// gAMA, sRGB, cHRM, IDAT chunks of 8 KiB, IEND). The tests compare the inflated rows with
// libpng's byte for byte, and the streaming path's file with libpng's.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "casteljau/paint.hpp"

namespace casteljau::png_detail {

// PNG colour types (PNG specification, table 11.1), as libpng numbers them.
constexpr int kGrey = 0, kRgb = 2, kGreyAlpha = 4, kRgba = 6;

// Encodes `pixmap` (premultiplied) as 8-bit `colour_type` samples with straight alpha, zlib level
// `level` (0 to 9), and rows unfiltered or, with `paeth`, each row Paeth-filtered when that makes
// libpng's heuristic sum (the row's bytes as signed magnitudes) smaller. Images of at most
// `whole_limit` filtered bytes are deflated in one piece, larger ones a row at a time. Throws
// std::bad_alloc, or Error(InvalidData) when deflating fails.
constexpr std::size_t kWholeImageLimit = std::size_t{64} << 20;
std::vector<std::uint8_t> encode_png_direct(const Pixmap& pixmap, int colour_type, int level, bool paeth,
                                            std::size_t whole_limit = kWholeImageLimit);

// The same through libpng (png.cpp), with `filters` a set of libpng's PNG_FILTER_* flags: every
// filter choice PngEncodeOptions offers, and the reference the direct encoder is tested against.
std::vector<std::uint8_t> encode_png_libpng(const Pixmap& pixmap, int colour_type, int level, int filters);

}  // namespace casteljau::png_detail
