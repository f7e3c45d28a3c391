// casteljau/image.hpp: raster images for drawing (SVG <image>): PNG through libpng and JPEG
// through libjpeg(-turbo), recognised by their signatures, decoded to a premultiplied Pixmap.
// JPEG: 8-bit greyscale, RGB and CMYK/YCCK (Adobe inverted) files; no colour management.
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

// Throws Error(InvalidData) for corrupt or truncated data, Error(InvalidData) for a format this
// build does not decode (GIF, WebP), Error(Limit) past the canvas limits.
Pixmap decode_jpeg(std::span<const std::uint8_t> bytes);
Pixmap decode_image(std::span<const std::uint8_t> bytes);

}  // namespace casteljau
