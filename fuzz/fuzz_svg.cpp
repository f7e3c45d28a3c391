// libFuzzer target: SVG documents. Parses the input and renders it into a canvas of at most
// 128 x 128 pixels (the document scaled to fit), so that large declared sizes stay fast. Any
// casteljau::Error is an accepted outcome; crashes, leaks, sanitizer reports and hangs are not.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "casteljau/error.hpp"
#include "casteljau/svg.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const casteljau::SvgDocument doc =
            casteljau::SvgDocument::parse(std::string_view(reinterpret_cast<const char*>(data), size));
        const int w = std::min(doc.width(), 128), h = std::min(doc.height(), 128);
        (void)doc.render_size(std::max(w, 1), std::max(h, 1));
    } catch (const casteljau::Error&) {
    }
    return 0;
}
