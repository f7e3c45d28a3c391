// C API: the canvas (casteljau.h), one function per casteljau::Canvas call.
#include <cmath>

#include "capi/handles.hpp"
#include "casteljau/svg.hpp"
#include "casteljau/text.hpp"

using namespace casteljau;
using casteljau::capi::create;
using casteljau::capi::guard;
using casteljau::capi::need;

namespace {

template <class F>
casteljau_status with(casteljau_canvas* canvas, F&& f) noexcept {
    return guard([&] { f(*need(canvas, "canvas")->canvas); });
}

void check_finite(std::initializer_list<double> values, const char* what) {
    for (double v : values)
        if (!std::isfinite(v)) throw Error(ErrorKind::InvalidArgument, std::string(what) + " is not finite");
}

FillRule rule_of(const casteljau_fill_rule& rule) {
    const int r = casteljau::capi::raw_enum(rule);
    if (r != CASTELJAU_FILL_NONZERO && r != CASTELJAU_FILL_EVENODD)
        throw Error(ErrorKind::InvalidArgument, "unknown fill rule");
    return r == CASTELJAU_FILL_EVENODD ? FillRule::EvenOdd : FillRule::NonZero;
}

Affine finite(const casteljau_matrix* m) {
    const Affine a = casteljau::capi::affine(need(m, "matrix"));
    if (!a.is_finite()) throw Error(ErrorKind::InvalidArgument, "the matrix is not finite");
    return a;
}

}  // namespace

extern "C" {

casteljau_status casteljau_canvas_create(casteljau_image* image, casteljau_canvas** out) {
    return create(out, [&] { return std::make_unique<Canvas>(need(image, "image")->pixmap); });
}

casteljau_status casteljau_canvas_create_for_pixels(uint8_t* pixels, int width, int height, size_t stride,
                                                    casteljau_canvas** out) {
    return create(out, [&] { return std::make_unique<Canvas>(pixels, width, height, stride); });
}

void casteljau_canvas_destroy(casteljau_canvas* canvas) { delete canvas; }

int casteljau_canvas_width(const casteljau_canvas* canvas) { return canvas ? canvas->canvas->width() : 0; }
int casteljau_canvas_height(const casteljau_canvas* canvas) { return canvas ? canvas->canvas->height() : 0; }
uint8_t* casteljau_canvas_pixels(casteljau_canvas* canvas) { return canvas ? canvas->canvas->pixels() : nullptr; }
size_t casteljau_canvas_stride(const casteljau_canvas* canvas) { return canvas ? canvas->canvas->stride() : 0; }

casteljau_status casteljau_canvas_save(casteljau_canvas* canvas) {
    return with(canvas, [](Canvas& c) { c.save(); });
}
casteljau_status casteljau_canvas_restore(casteljau_canvas* canvas) {
    return with(canvas, [](Canvas& c) { c.restore(); });
}
casteljau_status casteljau_canvas_translate(casteljau_canvas* canvas, double tx, double ty) {
    return with(canvas, [&](Canvas& c) {
        check_finite({tx, ty}, "translation");
        c.translate(tx, ty);
    });
}
casteljau_status casteljau_canvas_scale(casteljau_canvas* canvas, double sx, double sy) {
    return with(canvas, [&](Canvas& c) {
        check_finite({sx, sy}, "scale");
        c.scale(sx, sy);
    });
}
casteljau_status casteljau_canvas_rotate(casteljau_canvas* canvas, double radians) {
    return with(canvas, [&](Canvas& c) {
        check_finite({radians}, "angle");
        c.rotate(radians);
    });
}
casteljau_status casteljau_canvas_skew(casteljau_canvas* canvas, double ax, double ay) {
    return with(canvas, [&](Canvas& c) {
        check_finite({ax, ay}, "skew angle");
        c.skew(ax, ay);
    });
}
casteljau_status casteljau_canvas_concat(casteljau_canvas* canvas, const casteljau_matrix* m) {
    return with(canvas, [&](Canvas& c) { c.concat(finite(m)); });
}
casteljau_status casteljau_canvas_set_transform(casteljau_canvas* canvas, const casteljau_matrix* m) {
    return with(canvas, [&](Canvas& c) { c.set_transform(finite(m)); });
}
casteljau_status casteljau_canvas_get_transform(const casteljau_canvas* canvas, casteljau_matrix* out) {
    return guard([&] {
        const Affine& m = need(canvas, "canvas")->canvas->transform();
        *need(out, "out") = {m.a, m.b, m.c, m.d, m.e, m.f};
    });
}
casteljau_status casteljau_canvas_clip_rect(casteljau_canvas* canvas, double x, double y, double w, double h) {
    return with(canvas, [&](Canvas& c) {
        check_finite({x, y, w, h}, "clip rectangle");
        c.clip_rect(Rect::from_xywh(x, y, w, h));
    });
}
casteljau_status casteljau_canvas_clip_path(casteljau_canvas* canvas, const casteljau_path* path,
                                            casteljau_fill_rule rule) {
    return with(canvas, [&](Canvas& c) { c.clip_path(need(path, "path")->path, rule_of(rule)); });
}
casteljau_status casteljau_canvas_set_opacity(casteljau_canvas* canvas, double opacity) {
    return with(canvas, [&](Canvas& c) {
        if (!(opacity >= 0 && opacity <= 1)) throw Error(ErrorKind::InvalidArgument, "opacity must be in [0, 1]");
        c.set_opacity(opacity);
    });
}
casteljau_status casteljau_canvas_set_blend_mode(casteljau_canvas* canvas, casteljau_blend_mode mode) {
    return with(canvas,
                [&](Canvas& c) { c.set_blend_mode(casteljau::capi::blend_of(casteljau::capi::raw_enum(mode))); });
}
casteljau_status casteljau_canvas_set_tolerance(casteljau_canvas* canvas, double tolerance) {
    return with(canvas, [&](Canvas& c) {
        if (!(tolerance >= 1e-4 && tolerance <= 10))
            throw Error(ErrorKind::InvalidArgument, "tolerance must be in [1e-4, 10] px");
        c.fill_options().tolerance = tolerance;
    });
}
casteljau_status casteljau_canvas_clear(casteljau_canvas* canvas, casteljau_color color) {
    return with(canvas, [&](Canvas& c) { c.clear(casteljau::capi::color(color)); });
}
casteljau_status casteljau_canvas_fill_path(casteljau_canvas* canvas, const casteljau_path* path,
                                            const casteljau_paint* paint, casteljau_fill_rule rule) {
    return with(canvas,
                [&](Canvas& c) { c.fill_path(need(path, "path")->path, need(paint, "paint")->paint, rule_of(rule)); });
}
casteljau_status casteljau_canvas_fill_rect(casteljau_canvas* canvas, double x, double y, double w, double h,
                                            const casteljau_paint* paint) {
    return with(canvas, [&](Canvas& c) {
        check_finite({x, y, w, h}, "rectangle");
        c.fill_rect(Rect::from_xywh(x, y, w, h), need(paint, "paint")->paint);
    });
}
casteljau_status casteljau_canvas_stroke_path(casteljau_canvas* canvas, const casteljau_path* path,
                                              const casteljau_stroke* stroke, const casteljau_paint* paint) {
    return with(canvas, [&](Canvas& c) {
        c.stroke_path(need(path, "path")->path, need(stroke, "stroke")->style, need(paint, "paint")->paint);
    });
}
casteljau_status casteljau_canvas_draw_image(casteljau_canvas* canvas, const casteljau_image* image,
                                             const casteljau_matrix* m, casteljau_sampling sampling, double opacity) {
    return with(canvas, [&](Canvas& c) {
        if (!(opacity >= 0 && opacity <= 1)) throw Error(ErrorKind::InvalidArgument, "opacity must be in [0, 1]");
        c.draw_image(need(image, "image")->pixmap, m ? finite(m) : Affine{},
                     casteljau::capi::sampling_of(casteljau::capi::raw_enum(sampling)), opacity);
    });
}
casteljau_status casteljau_canvas_draw_text(casteljau_canvas* canvas, const casteljau_font* font, const char* text,
                                            double size, double x, double y, const casteljau_paint* paint) {
    return with(canvas, [&](Canvas& c) {
        check_finite({x, y}, "text origin");
        enable_svg_glyphs();
        draw_text(c, need(text, "text"), need(font, "font")->font, size, {x, y}, need(paint, "paint")->paint);
    });
}
casteljau_status casteljau_canvas_begin_layer(casteljau_canvas* canvas, double opacity, casteljau_blend_mode mode) {
    return with(canvas, [&](Canvas& c) {
        if (!(opacity >= 0 && opacity <= 1)) throw Error(ErrorKind::InvalidArgument, "opacity must be in [0, 1]");
        c.begin_layer(opacity, casteljau::capi::blend_of(casteljau::capi::raw_enum(mode)));
    });
}
casteljau_status casteljau_canvas_end_layer(casteljau_canvas* canvas) {
    return with(canvas, [](Canvas& c) { c.end_layer(); });
}

}  // extern "C"
