// casteljau/image.hpp: raster images for drawing (SVG <image>): PNG through libpng, JPEG through
// libjpeg(-turbo), GIF through giflib and WebP through libwebp, recognised by their signatures,
// decoded to a premultiplied Pixmap.
// JPEG: 8-bit greyscale, RGB and CMYK/YCCK (Adobe inverted) files; no colour management.
// GIF: the first image on its logical screen (transparent elsewhere), interlaced or not, with the
// transparent colour of its graphic control extension; animation frames after it are not read.
// WebP: still images, lossy or lossless, with or without alpha; animated files are refused.
// Limits: the declared size is checked against the canvas limits before pixels are allocated.
// Ownership: the bytes are only read during the call; the decoded Pixmap belongs to the caller.
// Thread-safety: free functions on values.
#pragma once

#include <cstdint>
#include <span>

#include "casteljau/paint.hpp"

namespace casteljau {

enum class ImageFormat { Unknown, Png, Jpeg, Gif, Webp, Svg };

// The format the bytes' signature names (SVG: text starting with '<' after optional whitespace
// or a BOM, or gzip data, which an .svgz is).
ImageFormat sniff_image(std::span<const std::uint8_t> bytes);

// Throws Error(InvalidData) for corrupt or truncated data and for what is not decoded (an
// animated WebP, an SVG or unknown data given to decode_image), Error(Limit) past the canvas
// limits.
Pixmap decode_jpeg(std::span<const std::uint8_t> bytes);
Pixmap decode_gif(std::span<const std::uint8_t> bytes);
Pixmap decode_webp(std::span<const std::uint8_t> bytes);
Pixmap decode_image(std::span<const std::uint8_t> bytes);

}  // namespace casteljau
