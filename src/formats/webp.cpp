// Formats stage: WebP decoding through libwebp (decode_webp, include/casteljau/image.hpp): still
// images, lossy or lossless, with or without alpha. An animated WebP is refused (libwebp's simple
// decoder does not read animations). The size is checked against the canvas limits before the
// pixels are allocated; libwebp writes straight RGBA rows into the Pixmap, which are then
// premultiplied in place.
#include <webp/decode.h>

#include <string>

#include "casteljau/error.hpp"
#include "casteljau/image.hpp"
#include "formats/straight_alpha.hpp"

namespace casteljau {

Pixmap decode_webp(std::span<const std::uint8_t> bytes) {
    WebPBitstreamFeatures features;
    if (WebPGetFeatures(bytes.data(), bytes.size(), &features) != VP8_STATUS_OK)
        throw Error(ErrorKind::InvalidData, "invalid WebP: cannot read its header");
    if (features.has_animation) throw Error(ErrorKind::InvalidData, "animated WebP images are not supported");
    if (features.width <= 0 || features.height <= 0) throw Error(ErrorKind::InvalidData, "invalid WebP: no size");
    check_canvas_size(features.width, features.height);
    Pixmap pixmap(features.width, features.height);
    const std::size_t size = pixmap.stride() * static_cast<std::size_t>(pixmap.height());
    if (!WebPDecodeRGBAInto(bytes.data(), bytes.size(), pixmap.data(), size, static_cast<int>(pixmap.stride())))
        throw Error(ErrorKind::InvalidData, "invalid WebP: corrupt or truncated image data");
    formats_detail::premultiply_in_place(pixmap);
    return pixmap;
}

}  // namespace casteljau
