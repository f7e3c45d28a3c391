// Paint stage: premultiplication and the Pixmap container (include/casteljau/paint.hpp).
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/paint.hpp"

namespace casteljau {

namespace {
// round(a * b / 255) for a, b in [0, 255], exact for all inputs.
inline std::uint8_t mul_div255(unsigned a, unsigned b) {
    const unsigned t = a * b + 128;
    return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}
}  // namespace

Color Color::with_opacity(double opacity) const {
    const double o = std::clamp(std::isfinite(opacity) ? opacity : 0.0, 0.0, 1.0);
    Color c = *this;
    c.a = static_cast<std::uint8_t>(std::lround(a * o));
    return c;
}

PremulPixel premultiply(Color c) {
    return {mul_div255(c.r, c.a), mul_div255(c.g, c.a), mul_div255(c.b, c.a), c.a};
}

Color unpremultiply(PremulPixel p) {
    if (p.a == 0) return {0, 0, 0, 0};
    if (p.a == 255) return {p.r, p.g, p.b, 255};
    auto un = [&](std::uint8_t c) {
        const unsigned v = (static_cast<unsigned>(c) * 255u + p.a / 2u) / p.a;
        return static_cast<std::uint8_t>(std::min(v, 255u));
    };
    return {un(p.r), un(p.g), un(p.b), p.a};
}

void check_canvas_size(double width, double height) {
    if (!std::isfinite(width) || !std::isfinite(height))
        throw Error(ErrorKind::InvalidData, "canvas size must be finite");
    if (width < 1 || height < 1)
        throw Error(ErrorKind::InvalidData, "canvas size must be at least 1x1 pixels, got " +
                                                std::to_string(width) + "x" + std::to_string(height));
    if (width > limits::kMaxCanvasDimension || height > limits::kMaxCanvasDimension)
        throw Error(ErrorKind::Limit, "canvas side exceeds the limit of " +
                                          std::to_string(limits::kMaxCanvasDimension) + " pixels");
    if (width * height > static_cast<double>(limits::kMaxCanvasPixels))
        throw Error(ErrorKind::Limit,
                    "canvas area exceeds the limit of " + std::to_string(limits::kMaxCanvasPixels) + " pixels");
}

Pixmap::Pixmap(int width, int height) {
    if (width < 1 || height < 1)
        throw Error(ErrorKind::InvalidArgument, "a Pixmap needs at least 1x1 pixels");
    check_canvas_size(width, height);
    width_ = width;
    height_ = height;
    data_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
}

PremulPixel Pixmap::pixel(int x, int y) const {
    const std::uint8_t* p = row(y) + 4 * static_cast<std::size_t>(x);
    return {p[0], p[1], p[2], p[3]};
}

void Pixmap::set_pixel(int x, int y, PremulPixel px) {
    std::uint8_t* p = row(y) + 4 * static_cast<std::size_t>(x);
    p[0] = px.r;
    p[1] = px.g;
    p[2] = px.b;
    p[3] = px.a;
}

void Pixmap::fill(Color c) {
    const PremulPixel p = premultiply(c);
    const std::uint8_t px[4] = {p.r, p.g, p.b, p.a};
    for (std::size_t i = 0; i < data_.size(); i += 4) std::memcpy(&data_[i], px, 4);
}

}  // namespace casteljau
