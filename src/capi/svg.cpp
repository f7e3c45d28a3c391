// C API: SVG documents (casteljau_svg.h), read and drawn the way `casteljau svg` does.
#include <string_view>

#include "capi/handles.hpp"

using namespace casteljau;
using casteljau::capi::create;
using casteljau::capi::guard;
using casteljau::capi::need;

namespace {

template <class F>
casteljau_status edit(casteljau_svg_options* options, F&& f) noexcept {
    return guard([&] { f(need(options, "options")->options); });
}

// The options a document is read with (NULL: the defaults). The font folders and files must exist
// whether or not the document has text, as on the command line; the font database itself is built
// by the reader when the first text needs it.
SvgOptions options_of(const casteljau_svg_options* options) {
    SvgOptions so = options ? options->options : casteljau_svg_options{}.options;
    FontDatabaseOptions fo;
    fo.font_dirs = so.font_dirs;
    fo.font_files = so.font_files;
    check_font_sources(fo);
    return so;
}

std::string& family(SvgOptions& o, int generic) {
    switch (generic) {
        case CASTELJAU_FAMILY_DEFAULT: return o.font_family;
        case CASTELJAU_FAMILY_SERIF: return o.serif_family;
        case CASTELJAU_FAMILY_SANS_SERIF: return o.sans_serif_family;
        case CASTELJAU_FAMILY_CURSIVE: return o.cursive_family;
        case CASTELJAU_FAMILY_FANTASY: return o.fantasy_family;
        case CASTELJAU_FAMILY_MONOSPACE: return o.monospace_family;
    }
    throw Error(ErrorKind::InvalidArgument, "unknown generic font family");
}

// The output size of `casteljau svg` for -w, --height and -z (0 for an option not given).
std::pair<int, int> output_size(const SvgDocument& doc, int width, int height, double zoom) {
    if (width < 0 || height < 0)
        throw Error(ErrorKind::InvalidArgument, "the output width and height must be 0 or more");
    if (zoom != 0 && zoom != 1 && (width > 0 || height > 0))
        throw Error(ErrorKind::InvalidArgument, "a zoom excludes an output width or height");
    if (zoom != 0) casteljau::capi::check_range(zoom, 1e-3, 1e3, "zoom");
    std::pair<int, int> size;
    if (width > 0 && height > 0)
        size = {width, height};
    else if (width > 0)
        size = doc.output_size_for_width(width);
    else if (height > 0)
        size = doc.output_size_for_height(height);
    else
        size = doc.output_size_for_zoom(zoom == 0 ? 1 : zoom);
    check_canvas_size(size.first, size.second);
    return size;
}

}  // namespace

extern "C" {

casteljau_svg_options* casteljau_svg_options_create(void) {
    return casteljau::capi::create_default<casteljau_svg_options>();
}

void casteljau_svg_options_destroy(casteljau_svg_options* options) { delete options; }

casteljau_status casteljau_svg_options_set_resources(casteljau_svg_options* options, const char* folder) {
    return edit(options, [&](SvgOptions& o) { o.resource_root = casteljau::capi::text_or_empty(folder); });
}

casteljau_status casteljau_svg_options_add_font_dir(casteljau_svg_options* options, const char* folder) {
    return edit(options, [&](SvgOptions& o) { o.font_dirs.emplace_back(need(folder, "folder")); });
}

casteljau_status casteljau_svg_options_add_font_file(casteljau_svg_options* options, const char* file) {
    return edit(options, [&](SvgOptions& o) { o.font_files.emplace_back(need(file, "file")); });
}

casteljau_status casteljau_svg_options_set_system_fonts(casteljau_svg_options* options, int use) {
    return edit(options, [&](SvgOptions& o) { o.system_fonts = o.system_fallback = use != 0; });
}

casteljau_status casteljau_svg_options_set_font_family(casteljau_svg_options* options, casteljau_font_generic generic,
                                                       const char* name) {
    return edit(options, [&](SvgOptions& o) {
        std::string& f = family(o, casteljau::capi::raw_enum(generic));
        f = need(name, "family");
    });
}

casteljau_status casteljau_svg_options_set_dpi(casteljau_svg_options* options, double dpi) {
    return edit(options, [&](SvgOptions& o) {
        if (!(dpi >= SvgOptions::kMinDpi && dpi <= SvgOptions::kMaxDpi))
            throw Error(ErrorKind::InvalidArgument, "dpi must be a number from 1 to 10000");
        o.dpi = dpi;
    });
}

casteljau_status casteljau_svg_options_set_export_id(casteljau_svg_options* options, const char* id) {
    return edit(options, [&](SvgOptions& o) { o.export_id = casteljau::capi::text_or_empty(id); });
}

casteljau_status casteljau_svg_load(const char* path, const casteljau_svg_options* options, casteljau_svg** out) {
    return create(out, [&] {
        need(path, "path");
        return SvgDocument::load(path, options_of(options));
    });
}

casteljau_status casteljau_svg_parse(const uint8_t* data, size_t size, const casteljau_svg_options* options,
                                     casteljau_svg** out) {
    return create(out, [&] {
        if (size > 0) need(data, "data");
        SvgOptions so = options_of(options);
        // From memory, relative hrefs resolve against the resources folder (none: no file is read).
        so.base_dir = so.resource_root;
        const std::string_view text(reinterpret_cast<const char*>(data), size);
        return SvgDocument::parse(text, so);
    });
}

void casteljau_svg_destroy(casteljau_svg* svg) { delete svg; }

casteljau_status casteljau_svg_intrinsic_size(const casteljau_svg* svg, double* width, double* height) {
    return guard([&] {
        const SvgDocument& doc = need(svg, "svg")->document;
        if (width) *width = doc.intrinsic_width();
        if (height) *height = doc.intrinsic_height();
    });
}

casteljau_status casteljau_svg_output_size(const casteljau_svg* svg, int width, int height, double zoom, int* out_width,
                                           int* out_height) {
    return guard([&] {
        need(out_width, "out_width");
        need(out_height, "out_height");
        const std::pair<int, int> size = output_size(need(svg, "svg")->document, width, height, zoom);
        *out_width = size.first;
        *out_height = size.second;
    });
}

size_t casteljau_svg_warning_count(const casteljau_svg* svg) { return svg ? svg->document.warnings().size() : 0; }

const char* casteljau_svg_warning(const casteljau_svg* svg, size_t index) {
    if (!svg || index >= svg->document.warnings().size()) return nullptr;
    return svg->document.warnings()[index].c_str();
}

casteljau_status casteljau_svg_render(const casteljau_svg* svg, casteljau_canvas* canvas) {
    return guard([&] {
        const SvgDocument& doc = need(svg, "svg")->document;
        Canvas& c = *need(canvas, "canvas")->canvas;
        doc.render(c, c.transform());
    });
}

casteljau_status casteljau_svg_render_image(const casteljau_svg* svg, int width, int height, double zoom,
                                            casteljau_color background, casteljau_image** out) {
    return create(out, [&] {
        const SvgDocument& doc = need(svg, "svg")->document;
        const std::pair<int, int> size = output_size(doc, width, height, zoom);
        Pixmap pm(size.first, size.second);
        pm.fill(casteljau::capi::color(background));
        Canvas canvas(pm);
        doc.render(canvas, Affine::scale(size.first / doc.intrinsic_width(), size.second / doc.intrinsic_height()));
        return pm;
    });
}

}  // extern "C"
