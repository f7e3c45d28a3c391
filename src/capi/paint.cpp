// C API: paints, colours, images and fonts (casteljau.h).
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "capi/handles.hpp"
#include "casteljau/png.hpp"
#include "casteljau/shader.hpp"

using namespace casteljau;
using casteljau::capi::create;
using casteljau::capi::guard;
using casteljau::capi::need;

namespace {

constexpr std::size_t kMaxStops = 1u << 16;

std::vector<GradientStop> stops_of(const casteljau_gradient_stop* stops, size_t count) {
    if (count == 0) throw Error(ErrorKind::InvalidArgument, "a gradient needs at least one stop");
    if (count > kMaxStops) throw Error(ErrorKind::Limit, "more than 65536 gradient stops");
    need(stops, "stops");
    std::vector<GradientStop> out;
    out.reserve(count);
    for (size_t i = 0; i < count; ++i) out.push_back({stops[i].offset, casteljau::capi::color(stops[i].color)});
    return out;
}

SpreadMethod spread_of(int s) {
    if (s < CASTELJAU_SPREAD_PAD || s > CASTELJAU_SPREAD_REPEAT)
        throw Error(ErrorKind::InvalidArgument, "unknown spread method");
    return static_cast<SpreadMethod>(s);
}

Affine finite_matrix(const casteljau_matrix* m) {
    const Affine a = casteljau::capi::affine(m);
    if (!a.is_finite()) throw Error(ErrorKind::InvalidArgument, "the matrix is not finite");
    return a;
}

void check_finite(std::initializer_list<double> values) {
    for (double v : values)
        if (!std::isfinite(v)) throw Error(ErrorKind::InvalidArgument, "gradient geometry is not finite");
}

}  // namespace

namespace casteljau::capi {
ImageSampling sampling_of(int s) {
    if (s < CASTELJAU_SAMPLING_NEAREST || s > CASTELJAU_SAMPLING_BICUBIC)
        throw Error(ErrorKind::InvalidArgument, "unknown sampling");
    return static_cast<ImageSampling>(s);
}
BlendMode blend_of(int m) {
    if (m < CASTELJAU_BLEND_NORMAL || m > CASTELJAU_BLEND_PLUS)
        throw Error(ErrorKind::InvalidArgument, "unknown blend mode");
    return static_cast<BlendMode>(m);
}
}  // namespace casteljau::capi

extern "C" {

casteljau_status casteljau_paint_create_solid(casteljau_color color, casteljau_paint** out) {
    return create(out, [&] { return Paint::solid(casteljau::capi::color(color)); });
}

casteljau_status casteljau_paint_create_linear(double x0, double y0, double x1, double y1,
                                               const casteljau_gradient_stop* stops, size_t count,
                                               casteljau_spread spread, const casteljau_matrix* m,
                                               casteljau_paint** out) {
    return create(out, [&] {
        check_finite({x0, y0, x1, y1});
        return Paint::shaded(Shader::linear({x0, y0}, {x1, y1}, stops_of(stops, count),
                                            spread_of(casteljau::capi::raw_enum(spread)), finite_matrix(m)));
    });
}

casteljau_status casteljau_paint_create_radial(double cx, double cy, double r, double fx, double fy, double fr,
                                               const casteljau_gradient_stop* stops, size_t count,
                                               casteljau_spread spread, const casteljau_matrix* m,
                                               casteljau_paint** out) {
    return create(out, [&] {
        check_finite({cx, cy, r, fx, fy, fr});
        if (r < 0 || fr < 0) throw Error(ErrorKind::InvalidArgument, "gradient radii must be >= 0");
        return Paint::shaded(Shader::radial({cx, cy}, r, {fx, fy}, fr, stops_of(stops, count),
                                            spread_of(casteljau::capi::raw_enum(spread)), finite_matrix(m)));
    });
}

casteljau_status casteljau_paint_create_image(const casteljau_image* image, casteljau_sampling sampling,
                                              const casteljau_matrix* m, int repeat, casteljau_paint** out) {
    return create(out, [&] {
        auto copy = std::make_shared<const Pixmap>(need(image, "image")->pixmap);
        return Paint::shaded(Shader::image(std::move(copy),
                                           casteljau::capi::sampling_of(casteljau::capi::raw_enum(sampling)),
                                           finite_matrix(m), repeat != 0));
    });
}

void casteljau_paint_destroy(casteljau_paint* paint) { delete paint; }

casteljau_status casteljau_paint_set_opacity(casteljau_paint* paint, double opacity) {
    return guard([&] {
        if (!(opacity >= 0 && opacity <= 1)) throw Error(ErrorKind::InvalidArgument, "opacity must be in [0, 1]");
        need(paint, "paint")->paint.opacity = opacity;
    });
}

casteljau_status casteljau_paint_set_blend_mode(casteljau_paint* paint, casteljau_blend_mode mode) {
    return guard(
        [&] { need(paint, "paint")->paint.blend = casteljau::capi::blend_of(casteljau::capi::raw_enum(mode)); });
}

casteljau_status casteljau_paint_set_linear_blend(casteljau_paint* paint, int linear) {
    return guard([&] { need(paint, "paint")->paint.linear_blend = linear != 0; });
}

casteljau_status casteljau_color_parse(const char* text, casteljau_color* out) {
    return guard([&] {
        need(out, "out");
        const Color c = parse_color(need(text, "text"));
        *out = {c.r, c.g, c.b, c.a};
    });
}

casteljau_status casteljau_image_create(int width, int height, casteljau_image** out) {
    return create(out, [&] { return Pixmap(width, height); });
}

casteljau_status casteljau_image_read_png(const char* path, casteljau_image** out) {
    return create(out, [&] { return read_png(need(path, "path")); });
}

casteljau_status casteljau_image_decode_png(const uint8_t* bytes, size_t size, casteljau_image** out) {
    return create(out, [&] {
        if (size > 0) need(bytes, "bytes");
        return decode_png(std::span<const std::uint8_t>(bytes, size));
    });
}

casteljau_status casteljau_image_write_png(const casteljau_image* image, const char* path) {
    return guard([&] { write_png(need(image, "image")->pixmap, need(path, "path")); });
}

casteljau_status casteljau_image_encode_png(const casteljau_image* image, uint8_t** out, size_t* size) {
    if (out) *out = nullptr;
    if (size) *size = 0;
    return guard([&] {
        need(out, "out");
        need(size, "size");
        const std::vector<std::uint8_t> png = encode_png(need(image, "image")->pixmap);
        auto* bytes = static_cast<uint8_t*>(std::malloc(png.size()));
        if (!bytes) throw std::bad_alloc();
        std::memcpy(bytes, png.data(), png.size());
        *out = bytes;
        *size = png.size();
    });
}

void casteljau_image_destroy(casteljau_image* image) { delete image; }

int casteljau_image_width(const casteljau_image* image) { return image ? image->pixmap.width() : 0; }
int casteljau_image_height(const casteljau_image* image) { return image ? image->pixmap.height() : 0; }
size_t casteljau_image_stride(const casteljau_image* image) { return image ? image->pixmap.stride() : 0; }
uint8_t* casteljau_image_data(casteljau_image* image) { return image ? image->pixmap.data() : nullptr; }

casteljau_status casteljau_font_load(const char* path, casteljau_font** out) {
    return create(out, [&] { return Font::load(need(path, "path")); });
}

casteljau_status casteljau_font_load_face(const char* path, int face_index, casteljau_font** out) {
    return create(out, [&] {
        if (face_index < 0) throw Error(ErrorKind::InvalidArgument, "face index must be 0 or more");
        return Font::load(need(path, "path"), face_index);
    });
}

void casteljau_font_destroy(casteljau_font* font) { delete font; }

}  // extern "C"
