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

// Images of up to 2^24 pixels (64 MiB): a few bytes can declare the canvas limit's 2^28 (a WebP
// of one flat colour, a GIF's logical screen), whose allocation and partial decoding would only
// measure the machine's memory. The decoders' paths are the same at any size.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    Limits limits = current_limits();
    limits.canvas_pixels = 1 << 24;
    set_limits(limits);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::span<const std::uint8_t> bytes(data, size);
    fuzz::run([&] { check(decode_image(bytes)); });
    fuzz::run([&] { check(decode_png(bytes)); });
    fuzz::run([&] { check(decode_jpeg(bytes)); });
    fuzz::run([&] { check(decode_gif(bytes)); });
    fuzz::run([&] { check(decode_webp(bytes)); });
    return 0;
}
