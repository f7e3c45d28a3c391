// Formats stage, SVG conversion: the image element: raster images and SVG documents from data: URIs
// or files beside the document.
#include "formats/svg/context.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "casteljau/file_io.hpp"
#include "casteljau/image.hpp"

namespace casteljau::svg {

namespace {

// Base64 (standard or URL-safe alphabet); white space, padding and other characters are skipped.
std::vector<std::uint8_t> decode_base64(std::string_view payload) {
    std::vector<std::uint8_t> out;
    unsigned acc = 0;
    int bits = 0;
    for (char ch : payload) {
        int v;
        if (ch >= 'A' && ch <= 'Z')
            v = ch - 'A';
        else if (ch >= 'a' && ch <= 'z')
            v = ch - 'a' + 26;
        else if (ch >= '0' && ch <= '9')
            v = ch - '0' + 52;
        else if (ch == '+' || ch == '-')
            v = 62;
        else if (ch == '/' || ch == '_')
            v = 63;
        else
            continue;
        acc = (acc << 6) | static_cast<unsigned>(v);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out.push_back(static_cast<std::uint8_t>(acc >> bits));
            acc &= (1u << bits) - 1;
        }
    }
    return out;
}

// The bytes of a data: URI, base64 or plain; nothing without a comma.
std::optional<std::vector<std::uint8_t>> data_uri_bytes(std::string_view ref) {
    const std::size_t comma = ref.find(',');
    if (comma == std::string_view::npos) return std::nullopt;
    const std::string_view meta = ref.substr(5, comma - 5);
    const std::string_view payload = ref.substr(comma + 1);
    if (meta.size() >= 7 && meta.substr(meta.size() - 7) == ";base64") return decode_base64(payload);
    return std::vector<std::uint8_t>(payload.begin(), payload.end());
}

// A relative file inside the resource root (the document's folder unless set); nothing, with a
// warning, for any other reference or a file that cannot be read.
std::optional<std::vector<std::uint8_t>> file_bytes(Context& cx, std::string_view ref) {
    if (ref.find(':') != std::string_view::npos || ref.empty() || ref.front() == '/' || ref.front() == '#') {
        warn(cx, "image '" + std::string(ref.substr(0, 80)) + "' refused: only data: URIs and relative files are read");
        return std::nullopt;
    }
    if (cx.options.base_dir.empty()) {
        warn(cx, "image '" + std::string(ref) + "' refused: the document has no folder to resolve it against");
        return std::nullopt;
    }
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path root =
        fs::weakly_canonical(cx.options.resource_root.empty() ? cx.options.base_dir : cx.options.resource_root, ec);
    const fs::path file = fs::weakly_canonical(fs::path(cx.options.base_dir) / std::string(ref), ec);
    const std::string r = root.string(), f = file.string();
    if (ec || r.empty() || f.size() <= r.size() || f.compare(0, r.size(), r) != 0 ||
        (f[r.size()] != '/' && r.back() != '/')) {
        warn(cx, "image '" + std::string(ref) + "' refused: outside the document's folder");
        return std::nullopt;
    }
    try {
        return read_file(f);
    } catch (const Error& e) {
        warn(cx, std::string("image: ") + e.what());
        return std::nullopt;
    }
}

}  // namespace

// The bytes an <image> href names: a data: URI (base64 or plain), or a relative file inside
// the resource root; nullopt (with a warning) for anything refused or unreadable.
std::optional<std::vector<std::uint8_t>> image_bytes(Context& cx, std::string_view ref) {
    ref = trim(ref);
    if (ref.substr(0, 5) == "data:") return data_uri_bytes(ref);
    return file_bytes(cx, ref);
}

namespace {

// An image's content: a decoded raster, or a parsed SVG document, with its intrinsic size.
struct ImageContent {
    std::shared_ptr<const Pixmap> raster;
    std::shared_ptr<const SvgDocument> svg;
    double iw = 0, ih = 0;
};

// Decodes the bytes (an SVG document one level deeper, whose warnings become this document's;
// else PNG, JPEG, GIF or WebP); nothing, with a warning, when that fails or nests too deep.
std::optional<ImageContent> load_image(Context& cx, const std::vector<std::uint8_t>& bytes) {
    ImageContent c;
    try {
        if (sniff_image(bytes) == ImageFormat::Svg) {
            if (cx.options.nesting + 1 > cx.limits.svg_image_nesting) {
                warn(cx, "SVG images nested deeper than " + std::to_string(cx.limits.svg_image_nesting) + "; skipped");
                return std::nullopt;
            }
            SvgOptions inner = cx.options;
            inner.nesting++;
            inner.export_id.clear();  // an image is drawn whole
            c.svg = std::make_shared<const SvgDocument>(
                SvgDocument::parse(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), inner));
            // Its warnings are this document's too (a skipped image deep in a chain, a bad path
            // inside an icon): the reader of this file would otherwise never see them.
            for (const std::string& w : c.svg->warnings()) warn(cx, "in an SVG image: " + w);
            c.iw = c.svg->intrinsic_width();
            c.ih = c.svg->intrinsic_height();
        } else {
            c.raster = std::make_shared<const Pixmap>(decode_image(bytes));
            c.iw = c.raster->width();
            c.ih = c.raster->height();
        }
    } catch (const Error& e) {
        warn(cx, std::string("image not drawn: ") + e.what());
        return std::nullopt;
    }
    return c;
}

// The image's width and height: its attributes (or CSS properties), auto or missing ones from the
// intrinsic size, keeping its aspect ratio when only one is given.
std::pair<double, double> image_size(Context& cx, const pugi::xml_node& n, Viewport vp, double iw, double ih) {
    auto size_attr = [&](const char* name, double percent_of) -> std::optional<double> {
        std::string_view v = trim(n.attribute(name).value());
        for (const auto& [k, val] : properties(cx, n))
            if (k == name) v = trim(val);
        if (v.empty() || v == "auto") return std::nullopt;
        return parse_length(v, percent_of, kUnknownFontSize, cx.options.dpi);
    };
    std::optional<double> w = size_attr("width", vp.w), h = size_attr("height", vp.h);
    if (!w && !h) return {iw, ih};
    if (!w) return {*h * iw / ih, *h};
    if (!h) return {*w, *w * ih / iw};
    return {*w, *h};
}

}  // namespace

void image(Context& cx, const pugi::xml_node& n, const Style& st, const Affine& cm, Viewport vp, double opacity) {
    if (!st.visible) return;
    const std::optional<std::vector<std::uint8_t>> bytes = image_bytes(cx, href(n));
    if (!bytes) return;
    const std::optional<ImageContent> content = load_image(cx, *bytes);
    if (!content) return;
    // Named members rather than a structured binding, which the lambda below could not capture
    // under every compiler the build supports.
    const std::shared_ptr<const Pixmap>& raster = content->raster;
    const std::shared_ptr<const SvgDocument>& svg = content->svg;
    const double iw = content->iw, ih = content->ih;
    const auto [w, h] = image_size(cx, n, vp, iw, ih);
    if (!(w > 0) || !(h > 0) || !(iw > 0) || !(ih > 0)) return;
    const double x = length_attr(cx, n, "x", vp.w), y = length_attr(cx, n, "y", vp.h);
    const std::string_view par = n.attribute("preserveAspectRatio").value();
    const Affine m = cm * Affine::translate(x, y) * viewbox_transform(Rect::from_xywh(0, 0, iw, ih), par, w, h);
    const bool slice = par.find("slice") != std::string_view::npos;
    const std::string rendering = inherited(cx, n, "image-rendering");
    const bool smooth = !(rendering == "optimizeSpeed" || rendering == "pixelated" || rendering == "crisp-edges");
    auto draw = [&] {
        DisplayItem it;
        it.transform = m;
        it.opacity = opacity;
        if (svg) {
            it.kind = DisplayItem::SvgImage;
            it.svg_image = svg;
        } else {
            it.kind = DisplayItem::Fill;
            it.path.add_rect(Rect::from_xywh(0, 0, iw, ih));
            it.shader = std::make_shared<const Shader>(Shader::image(raster, smooth));
        }
        cx.items.push_back(std::move(it));
    };
    if (slice || svg)
        clipped(cx, Rect::from_xywh(x, y, w, h), cm, draw);
    else
        draw();
}

}  // namespace casteljau::svg
