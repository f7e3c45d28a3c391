// Paint stage: premultiplication and the Pixmap container (include/casteljau/paint.hpp).
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/paint.hpp"
#include "core/pixel_memory.hpp"
#include "paint/pixel_math.hpp"
#include "paint/pixmap_memory.hpp"

namespace casteljau {

using pixel::mul_div255;

Color Color::with_opacity(double opacity) const {
    const double o = std::clamp(std::isfinite(opacity) ? opacity : 0.0, 0.0, 1.0);
    Color c = *this;
    c.a = static_cast<std::uint8_t>(std::lround(a * o));
    return c;
}

PremulPixel premultiply(Color c) { return {mul_div255(c.r, c.a), mul_div255(c.g, c.a), mul_div255(c.b, c.a), c.a}; }

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
        throw Error(ErrorKind::InvalidData, "canvas size must be at least 1x1 pixels, got " + std::to_string(width) +
                                                "x" + std::to_string(height));
    const Limits lim = current_limits();
    if (width > lim.canvas_dimension || height > lim.canvas_dimension)
        throw Error(ErrorKind::Limit,
                    "canvas side exceeds the limit of " + std::to_string(lim.canvas_dimension) + " pixels");
    if (width * height > static_cast<double>(lim.canvas_pixels))
        throw Error(ErrorKind::Limit,
                    "canvas area exceeds the limit of " + std::to_string(lim.canvas_pixels) + " pixels");
}

Pixmap::Pixmap(int width, int height) {
    bool zero = false;
    *this = PixmapMemory::uncleared(width, height, zero);
    if (!zero) std::memset(pixels_, 0, stride_ * static_cast<std::size_t>(height_));
}

Pixmap PixmapMemory::uncleared(int width, int height, bool& zero) {
    if (width < 1 || height < 1) throw Error(ErrorKind::InvalidArgument, "a Pixmap needs at least 1x1 pixels");
    check_canvas_size(width, height);
    Pixmap p;
    p.width_ = width;
    p.height_ = height;
    p.stride_ = static_cast<std::size_t>(width) * 4;
    const std::size_t bytes = p.stride_ * static_cast<std::size_t>(height);
    p.storage_ = std::unique_ptr<std::uint8_t[], Pixmap::Free>(
        static_cast<std::uint8_t*>(platform::allocate_uncleared(bytes, zero)), Pixmap::Free{bytes});
    if (!p.storage_) throw std::bad_alloc();
    p.pixels_ = p.storage_.get();
    return p;
}

void Pixmap::Free::operator()(std::uint8_t* p) const noexcept { platform::release(p, bytes); }

Pixmap Pixmap::borrow(std::uint8_t* pixels, int width, int height, std::size_t stride) {
    if (!pixels) throw Error(ErrorKind::InvalidArgument, "Pixmap::borrow needs pixel memory");
    if (width < 1 || height < 1) throw Error(ErrorKind::InvalidArgument, "a Pixmap needs at least 1x1 pixels");
    check_canvas_size(width, height);
    if (stride < static_cast<std::size_t>(width) * 4)
        throw Error(ErrorKind::InvalidArgument, "Pixmap::borrow: stride " + std::to_string(stride) +
                                                    " is below 4 x width (" + std::to_string(4LL * width) + ")");
    Pixmap p;
    p.width_ = width;
    p.height_ = height;
    p.stride_ = stride;
    p.pixels_ = pixels;
    return p;
}

Pixmap::Pixmap(const Pixmap& o)
    : width_(o.width_), height_(o.height_), stride_(static_cast<std::size_t>(o.width_) * 4) {
    if (!o.pixels_) {
        stride_ = 0;
        return;
    }
    const std::size_t bytes = stride_ * static_cast<std::size_t>(height_);
    storage_ = std::unique_ptr<std::uint8_t[], Free>(static_cast<std::uint8_t*>(platform::allocate(bytes, false)),
                                                     Free{bytes});
    if (!storage_) throw std::bad_alloc();
    for (int y = 0; y < height_; ++y)
        std::memcpy(storage_.get() + stride_ * static_cast<std::size_t>(y), o.row(y), stride_);
    pixels_ = storage_.get();
}

Pixmap& Pixmap::operator=(const Pixmap& o) {
    if (this != &o) *this = Pixmap(o);
    return *this;
}

Pixmap::Pixmap(Pixmap&& o) noexcept
    : width_(o.width_), height_(o.height_), stride_(o.stride_), storage_(std::move(o.storage_)), pixels_(o.pixels_) {
    o.width_ = o.height_ = 0;
    o.stride_ = 0;
    o.pixels_ = nullptr;
}

Pixmap& Pixmap::operator=(Pixmap&& o) noexcept {
    if (this == &o) return *this;
    width_ = o.width_;
    height_ = o.height_;
    stride_ = o.stride_;
    storage_ = std::move(o.storage_);
    pixels_ = o.pixels_;
    o.width_ = o.height_ = 0;
    o.stride_ = 0;
    o.pixels_ = nullptr;
    return *this;
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

void Pixmap::fill(Color c) { fill_rows(0, height_, c); }

void Pixmap::fill_rows(int y0, int y1, Color c) {
    const PremulPixel p = premultiply(c);
    const std::size_t bytes = 4 * static_cast<std::size_t>(width_);
    y0 = std::max(y0, 0);
    y1 = std::min(y1, height_);
    if (y0 >= y1) return;
    if (p.r == p.g && p.g == p.b && p.b == p.a) {  // transparent, opaque black or white: one byte value
        if (stride_ == bytes)
            std::memset(row(y0), p.r, bytes * static_cast<std::size_t>(y1 - y0));
        else
            for (int y = y0; y < y1; ++y) std::memset(row(y), p.r, bytes);
        return;
    }
    // Any other colour: the first row pixel by pixel (eight at a time), then copies of it.
    const std::uint8_t px[4] = {p.r, p.g, p.b, p.a};
    std::uint8_t eight[32];
    for (int k = 0; k < 8; ++k) std::memcpy(eight + 4 * k, px, 4);
    std::uint8_t* first = row(y0);
    std::size_t x = 0;
    for (; x + 32 <= bytes; x += 32) std::memcpy(first + x, eight, 32);
    for (; x < bytes; x += 4) std::memcpy(first + x, px, 4);
    for (int y = y0 + 1; y < y1; ++y) std::memcpy(row(y), first, bytes);
}

}  // namespace casteljau
