// casteljau/png.hpp: PNG files through libpng (reading, and writing with the less common filters)
// and libdeflate (writing with the default filters).
//
// Files hold 8-bit samples with straight alpha (sRGB chunk written) in the smallest colour type
// that holds every pixel exactly: grey, grey + alpha, RGB or RGBA; Pixmaps hold premultiplied RGBA,
// converted on the way in and out. write_png writes through write_file_atomic
// (casteljau/file_io.hpp), so a failure never leaves a half-written file. Ownership: decoded Pixmaps are values owned by the caller; encoders only
// read the Pixmap they are given. Thread-safety: free functions; distinct files from distinct threads.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/paint.hpp"

namespace casteljau {

// PNG row filters (PNG specification, section 9). Adaptive lets libpng pick one of the five per
// row; Auto uses none for grey pictures and a per-row choice of none or Paeth for colour ones.
enum class PngFilter { Auto, None, Sub, Up, Average, Paeth, Adaptive };

// How to encode. The defaults were chosen with bench/png_encode (BENCHMARKS.md, "PNG encoding"):
// against libpng's defaults (zlib level 6, adaptive filtering, RGBA) they write rendered text 18%
// and flat drawings 8% smaller, gradients 21% larger, in a fifth of the time.
struct PngEncodeOptions {
    int compression_level = 4;  // deflate level, 0 (store) to 9 (smallest)
    PngFilter filter = PngFilter::Auto;
    bool smallest_colour_type = true;  // false: always RGBA
};

// Un-premultiplies exactly (straight = round(p * 255 / a)), so that decode_png(encode_png(p))
// returns p for every valid premultiplied pixmap. Throws Error(InvalidArgument) for an empty Pixmap
// or a compression level outside 0..9.
std::vector<std::uint8_t> encode_png(const Pixmap& pixmap, const PngEncodeOptions& options = {});
// Any PNG colour type and bit depth (palette, tRNS, grey, 16-bit, interlaced) -> RGBA8, then
// premultiplied. No gamma or colour conversion is applied (gAMA/cHRM/sRGB/iCCP are ignored).
// Throws Error(InvalidData) for empty, truncated or corrupt data, Error(Limit) when the declared
// size exceeds casteljau::limits (checked before any pixel memory is allocated).
Pixmap decode_png(std::span<const std::uint8_t> bytes);

// Throws Error(Io) when the file cannot be written/read, Error(InvalidData) for a corrupt PNG.
void write_png(const Pixmap& pixmap, const std::string& path, const PngEncodeOptions& options = {});
Pixmap read_png(const std::string& path);

}  // namespace casteljau
