// Formats stage: raster images (include/casteljau/image.hpp): the format named by the bytes'
// signature, and decoding by it (PNG in png.cpp, JPEG in jpeg.cpp, GIF in gif.cpp, WebP in
// webp.cpp).
#include "casteljau/image.hpp"

#include <algorithm>
#include <cstring>
#include <initializer_list>

#include "casteljau/error.hpp"
#include "casteljau/png.hpp"

namespace casteljau {

ImageFormat sniff_image(std::span<const std::uint8_t> b) {
    auto starts = [&](std::initializer_list<std::uint8_t> sig) {
        return b.size() >= sig.size() && std::equal(sig.begin(), sig.end(), b.begin());
    };
    if (starts({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'})) return ImageFormat::Png;
    if (starts({0xff, 0xd8, 0xff})) return ImageFormat::Jpeg;
    if (starts({'G', 'I', 'F', '8'})) return ImageFormat::Gif;
    if (b.size() >= 12 && starts({'R', 'I', 'F', 'F'}) && std::memcmp(b.data() + 8, "WEBP", 4) == 0)
        return ImageFormat::Webp;
    if (starts({0x1f, 0x8b})) return ImageFormat::Svg;  // gzip: an .svgz
    std::size_t i = starts({0xef, 0xbb, 0xbf}) ? 3 : 0;
    while (i < b.size() && (b[i] == ' ' || b[i] == '\t' || b[i] == '\r' || b[i] == '\n')) ++i;
    if (i < b.size() && b[i] == '<') return ImageFormat::Svg;
    return ImageFormat::Unknown;
}

Pixmap decode_image(std::span<const std::uint8_t> bytes) {
    switch (sniff_image(bytes)) {
        case ImageFormat::Png: return decode_png(bytes);
        case ImageFormat::Jpeg: return decode_jpeg(bytes);
        case ImageFormat::Gif: return decode_gif(bytes);
        case ImageFormat::Webp: return decode_webp(bytes);
        case ImageFormat::Svg: throw Error(ErrorKind::InvalidData, "an SVG image is not a raster image");
        case ImageFormat::Unknown: break;
    }
    throw Error(ErrorKind::InvalidData, "unrecognised image data (not PNG, JPEG, GIF or WebP)");
}

}  // namespace casteljau
