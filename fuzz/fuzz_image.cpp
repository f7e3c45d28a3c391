// libFuzzer target: image decoding (PNG through libpng, JPEG through libjpeg-turbo, GIF through
// giflib, WebP through libwebp, and the format sniffing in front of them). Invariants: bad bytes end in casteljau::Error; a decoded
// image has a size within the canvas limits and exactly width x height pixels.
#include <span>

#include "casteljau/image.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/png.hpp"
#include "harness.hpp"

using namespace casteljau;

namespace {

void check(const Pixmap& pm) {
    fuzz::require(pm.width() >= 1 && pm.height() >= 1 && pm.width() <= limits::kMaxCanvasDimension &&
                      pm.height() <= limits::kMaxCanvasDimension,
                  "decoded image size outside the canvas limits");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    fuzz::run([&] { check(decode_image(bytes)); });
    fuzz::run([&] { check(decode_png(bytes)); });
    fuzz::run([&] { check(decode_jpeg(bytes)); });
    fuzz::run([&] { check(decode_gif(bytes)); });
    fuzz::run([&] { check(decode_webp(bytes)); });
    return 0;
}
