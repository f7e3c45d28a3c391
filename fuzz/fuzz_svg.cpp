// libFuzzer target: SVG documents. Parses the input and renders it into a canvas of at most
// 128 x 128 pixels (the document scaled to fit), so that large declared sizes stay fast. Text is
// drawn with the repository's fonts (fonts/, no system fonts: the same on every machine), read
// once for the whole run. Any casteljau::Error is an accepted outcome; crashes, leaks, sanitizer
// reports and hangs are not.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string_view>

#include "casteljau/error.hpp"
#include "casteljau/font_database.hpp"
#include "casteljau/svg.hpp"

namespace {

const casteljau::SvgOptions& options() {
    static const casteljau::SvgOptions o = [] {
        casteljau::FontDatabaseOptions fo;
        fo.font_dirs = {CASTELJAU_FONT_DIR};
        fo.system_fonts = false;
        casteljau::SvgOptions so;
        so.font_database = std::make_shared<const casteljau::FontDatabase>(fo);
        so.font_family = so.sans_serif_family = "DejaVu Sans";
        so.serif_family = "Linux Libertine O";
        return so;
    }();
    return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const casteljau::SvgDocument doc =
            casteljau::SvgDocument::parse(std::string_view(reinterpret_cast<const char*>(data), size), options());
        const int w = std::min(doc.width(), 128), h = std::min(doc.height(), 128);
        (void)doc.render_size(std::max(w, 1), std::max(h, 1));
    } catch (const casteljau::Error&) {}
    return 0;
}
