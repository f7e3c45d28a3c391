// C API: paragraph layout (casteljau_text.h), laid out and drawn the way `casteljau text` does.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "capi/handles.hpp"
#include "casteljau/svg.hpp"

using namespace casteljau;
using casteljau::capi::check_range;
using casteljau::capi::create;
using casteljau::capi::guard;
using casteljau::capi::need;

namespace {

template <class F>
casteljau_status edit(casteljau_text_style* style, F&& f) noexcept {
    return guard([&] { f(*need(style, "style")); });
}

void append_utf8(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
}

// Copies of the caller's fonts, each with the variations of the axes it has; a variation no font
// has is an error naming the fonts' axes, as --variation is.
std::vector<std::unique_ptr<Font>> fonts_with(const casteljau_font* const* fonts, size_t count,
                                              const std::vector<Variation>& variations) {
    if (count == 0) throw Error(ErrorKind::InvalidArgument, "a layout needs at least one font");
    need(fonts, "fonts");
    std::vector<std::unique_ptr<Font>> out;
    for (size_t i = 0; i < count; ++i) out.push_back(std::make_unique<Font>(need(fonts[i], "font")->font.clone()));
    std::vector<Font*> chain;
    for (const auto& f : out) chain.push_back(f.get());
    set_chain_variations(chain, variations);
    return out;
}

casteljau_text_layout make_layout(const char* text, const casteljau_font* const* fonts, size_t count,
                                  const casteljau_text_style* style) {
    need(text, "text");
    const casteljau_text_style defaults{};
    const casteljau_text_style& s = style ? *style : defaults;
    casteljau_text_layout out;
    out.fonts = fonts_with(fonts, count, s.variations);
    std::vector<const Font*> chain;
    for (const auto& f : out.fonts) chain.push_back(f.get());
    enable_svg_glyphs();  // colour glyphs of OpenType SVG fonts, measured in the layout too
    out.layout = layout_text(text, chain, s.style);
    out.palette = s.palette;
    for (const TextLine& line : out.layout.lines) {
        std::string utf8;
        const std::size_t end = std::min(line.text_end, out.layout.text.size());
        for (std::size_t i = std::min(line.text_begin, end); i < end; ++i) append_utf8(utf8, out.layout.text[i]);
        out.line_text.push_back(std::move(utf8));
    }
    return out;
}

TextDrawOptions draw_options(const casteljau_text_layout& layout) {
    TextDrawOptions options;
    options.palette = layout.palette;
    return options;
}

}  // namespace

extern "C" {

casteljau_text_style* casteljau_text_style_create(void) {
    return casteljau::capi::create_default<casteljau_text_style>();
}

void casteljau_text_style_destroy(casteljau_text_style* style) { delete style; }

casteljau_status casteljau_text_style_set_size(casteljau_text_style* style, double size) {
    return edit(style, [&](casteljau_text_style& s) {
        check_font_size(size);
        s.style.size = size;
    });
}

casteljau_status casteljau_text_style_set_line_height(casteljau_text_style* style, double line_height) {
    return edit(style, [&](casteljau_text_style& s) {
        if (!(line_height > 0 && line_height <= 100))
            throw Error(ErrorKind::InvalidArgument, "line height must be above 0 and at most 100");
        s.style.line_height = line_height;
    });
}

casteljau_status casteljau_text_style_set_width(casteljau_text_style* style, double width) {
    return edit(style, [&](casteljau_text_style& s) {
        if (width != 0) check_range(width, 1, limits::kMaxCanvasDimension, "wrap width");
        s.style.max_width = width;
    });
}

casteljau_status casteljau_text_style_set_align(casteljau_text_style* style, casteljau_text_align align) {
    return edit(style, [&](casteljau_text_style& s) {
        const int a = casteljau::capi::raw_enum(align);
        if (a < CASTELJAU_ALIGN_START || a > CASTELJAU_ALIGN_RIGHT)
            throw Error(ErrorKind::InvalidArgument, "unknown alignment");
        s.style.align = static_cast<TextAlign>(a);
    });
}

casteljau_status casteljau_text_style_set_direction(casteljau_text_style* style, casteljau_text_direction direction) {
    return edit(style, [&](casteljau_text_style& s) {
        const int d = casteljau::capi::raw_enum(direction);
        if (d < CASTELJAU_DIRECTION_AUTO || d > CASTELJAU_DIRECTION_RTL)
            throw Error(ErrorKind::InvalidArgument, "unknown direction");
        s.style.direction = static_cast<TextDirection>(d);
    });
}

casteljau_status casteljau_text_style_set_script(casteljau_text_style* style, const char* script) {
    return edit(style, [&](casteljau_text_style& s) { s.style.script = casteljau::capi::text_or_empty(script); });
}

casteljau_status casteljau_text_style_set_language(casteljau_text_style* style, const char* language) {
    return edit(style, [&](casteljau_text_style& s) { s.style.language = casteljau::capi::text_or_empty(language); });
}

casteljau_status casteljau_text_style_add_feature(casteljau_text_style* style, const char* feature) {
    return edit(style, [&](casteljau_text_style& s) { s.style.features.emplace_back(need(feature, "feature")); });
}

casteljau_status casteljau_text_style_add_variation(casteljau_text_style* style, const char* variation) {
    return edit(
        style, [&](casteljau_text_style& s) { s.variations.push_back(parse_variation(need(variation, "variation"))); });
}

casteljau_status casteljau_text_style_set_system_fonts(casteljau_text_style* style, int use) {
    return edit(style, [&](casteljau_text_style& s) { s.style.system_fonts = use != 0; });
}

casteljau_status casteljau_text_style_set_palette(casteljau_text_style* style, int palette) {
    return edit(style, [&](casteljau_text_style& s) {
        if (palette < 0 || palette > 65535)
            throw Error(ErrorKind::InvalidArgument, "palette must be 0 to 65535, got " + std::to_string(palette));
        s.palette = palette;
    });
}

casteljau_status casteljau_text_layout_create(const char* text, const casteljau_font* const* fonts, size_t count,
                                              const casteljau_text_style* style, casteljau_text_layout** out) {
    if (out) *out = nullptr;
    return guard([&] {
        need(out, "out");
        *out = new casteljau_text_layout(make_layout(text, fonts, count, style));
    });
}

void casteljau_text_layout_destroy(casteljau_text_layout* layout) { delete layout; }

casteljau_status casteljau_text_layout_size(const casteljau_text_layout* layout, double* width, double* height) {
    return guard([&] {
        const TextLayout& l = need(layout, "layout")->layout;
        if (width) *width = l.width;
        if (height) *height = l.height;
    });
}

casteljau_status casteljau_text_layout_bounds(const casteljau_text_layout* layout, double* x0, double* y0, double* x1,
                                              double* y1) {
    return guard([&] {
        const Rect b = need(layout, "layout")->layout.bounds();
        if (x0) *x0 = b.x0;
        if (y0) *y0 = b.y0;
        if (x1) *x1 = b.x1;
        if (y1) *y1 = b.y1;
    });
}

size_t casteljau_text_layout_line_count(const casteljau_text_layout* layout) {
    return layout ? layout->layout.lines.size() : 0;
}

casteljau_status casteljau_text_layout_line(const casteljau_text_layout* layout, size_t index,
                                            casteljau_text_line* out) {
    return guard([&] {
        const casteljau_text_layout& l = *need(layout, "layout");
        need(out, "out");
        if (index >= l.layout.lines.size()) throw Error(ErrorKind::InvalidArgument, "line index past the last line");
        const TextLine& line = l.layout.lines[index];
        const std::string& text = l.line_text[index];
        *out = {text.c_str(), text.size(), line.x, line.baseline, line.width, line.rtl ? 1 : 0};
    });
}

casteljau_status casteljau_text_layout_draw(casteljau_text_layout* layout, casteljau_canvas* canvas, double x, double y,
                                            const casteljau_paint* paint) {
    return guard([&] {
        const TextLayout& l = need(layout, "layout")->layout;
        Canvas& c = *need(canvas, "canvas")->canvas;
        if (!std::isfinite(x) || !std::isfinite(y))
            throw Error(ErrorKind::InvalidArgument, "text origin is not finite");
        draw_text(c, l, {x, y}, need(paint, "paint")->paint, nullptr, draw_options(*layout));
    });
}

casteljau_status casteljau_text_layout_render_image(casteljau_text_layout* layout, const casteljau_paint* paint,
                                                    casteljau_color background, int padding, casteljau_image** out) {
    return create(out, [&] {
        const casteljau_text_layout& held = *need(layout, "layout");
        const TextLayout& l = held.layout;
        const Paint& p = need(paint, "paint")->paint;
        check_range(padding, 0, limits::kMaxCanvasDimension, "padding");
        const Rect b = l.bounds();
        const double x0 = std::floor(b.x0), y0 = std::floor(b.y0), x1 = std::ceil(b.x1), y1 = std::ceil(b.y1);
        const double w = std::max(1.0, x1 - x0) + 2.0 * padding, h = std::max(1.0, y1 - y0) + 2.0 * padding;
        check_canvas_size(w, h);
        Pixmap pm(static_cast<int>(w), static_cast<int>(h));
        pm.fill(casteljau::capi::color(background));
        Canvas canvas(pm);
        draw_text(canvas, l, {padding - x0, padding - y0}, p, nullptr, draw_options(held));
        return pm;
    });
}

}  // extern "C"
