// Paint stage: the image (pattern) shader (include/casteljau/shader.hpp). Each pixel centre is
// mapped back into the image's pixel space and sampled there: nearest, bilinear (2x2) or bicubic
// (Catmull-Rom, 4x4), on premultiplied values, then multiplied by the opacity.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "casteljau/error.hpp"
#include "casteljau/shader.hpp"

namespace casteljau {

namespace {

// Catmull-Rom weights of the four samples around a point at fraction t in [0, 1) past the second.
void catmull_rom(float t, float w[4]) {
    const float t2 = t * t, t3 = t2 * t;
    w[0] = 0.5f * (-t3 + 2 * t2 - t);
    w[1] = 0.5f * (3 * t3 - 5 * t2 + 2);
    w[2] = 0.5f * (-3 * t3 + 4 * t2 + t);
    w[3] = 0.5f * (t3 - t2);
}

int wrap_or_clamp(int i, int n, bool repeat) { return repeat ? ((i % n) + n) % n : std::clamp(i, 0, n - 1); }

// Nearest sampling at full opacity of a row along which the image coordinate y stays `p.y` and x
// steps by `step` from `p.x`: one image row, each pixel copied as it is (what the general loop
// computes: an integer sample times 1, plus 0.5, truncated), transparent outside the image.
void shade_nearest_along_row(const Pixmap& im, Point p, double step, int length, std::uint8_t* out) {
    const int w = im.width(), h = im.height();
    const std::uint8_t* row = p.y >= 0 && p.y <= h ? im.row(std::min(static_cast<int>(p.y), h - 1)) : nullptr;
    for (int i = 0; i < length; ++i, out += 4, p.x += step) {
        if (row && p.x >= 0 && p.x <= w)
            std::memcpy(out, row + 4 * static_cast<std::size_t>(std::min(static_cast<int>(p.x), w - 1)), 4);
        else
            std::memset(out, 0, 4);
    }
}

}  // namespace

Shader Shader::image(std::shared_ptr<const Pixmap> image, bool smooth, const Affine& transform, bool repeat) {
    return Shader::image(std::move(image), smooth ? ImageSampling::Bilinear : ImageSampling::Nearest, transform,
                         repeat);
}

Shader Shader::image(std::shared_ptr<const Pixmap> image, ImageSampling sampling, const Affine& transform,
                     bool repeat) {
    if (!image || image->width() < 1 || image->height() < 1)
        throw Error(ErrorKind::InvalidArgument, "an image shader needs an image");
    Shader s;
    s.kind_ = Kind::Image;
    s.image_ = std::move(image);
    s.sampling_ = sampling;
    s.repeat_ = repeat;
    s.transform_ = transform;
    s.set_stops({{0, Color::transparent()}});
    return s;
}

void Shader::sample_bicubic(double u, double v, float c[4]) const {
    const Pixmap& im = *image_;
    const double fu = std::floor(u), fv = std::floor(v);
    float wx[4], wy[4];
    catmull_rom(static_cast<float>(u - fu), wx);
    catmull_rom(static_cast<float>(v - fv), wy);
    const int x0 = static_cast<int>(fu) - 1, y0 = static_cast<int>(fv) - 1;
    c[0] = c[1] = c[2] = c[3] = 0;
    for (int j = 0; j < 4; ++j) {
        const std::uint8_t* row = im.row(wrap_or_clamp(y0 + j, im.height(), repeat_));
        float r[4] = {0, 0, 0, 0};
        for (int i = 0; i < 4; ++i) {
            const std::uint8_t* p = row + 4 * static_cast<std::size_t>(wrap_or_clamp(x0 + i, im.width(), repeat_));
            for (int k = 0; k < 4; ++k) r[k] += wx[i] * p[k];
        }
        for (int k = 0; k < 4; ++k) c[k] += wy[j] * r[k];
    }
    // Catmull-Rom overshoots: keep a valid premultiplied pixel.
    c[3] = std::clamp(c[3], 0.0f, 255.0f);
    for (int k = 0; k < 3; ++k) c[k] = std::clamp(c[k], 0.0f, c[3]);
}

void Shader::shade_image_row(const Affine& inv, int x, int y, int length, double opacity, std::uint8_t* out) const {
    const Pixmap& im = *image_;
    const int w = im.width(), h = im.height();
    const float op = static_cast<float>(std::clamp(std::isfinite(opacity) ? opacity : 0.0, 0.0, 1.0));
    Point p = inv.apply({x + 0.5, y + 0.5});
    if (sampling_ == ImageSampling::Nearest && !repeat_ && inv.b == 0 && op == 1.0f) {
        shade_nearest_along_row(im, p, inv.a, length, out);
        return;
    }
    for (int i = 0; i < length; ++i, out += 4, p.x += inv.a, p.y += inv.b) {
        Point q = p;
        if (repeat_) {
            q.x -= std::floor(q.x / w) * w;
            q.y -= std::floor(q.y / h) * h;
        }
        if (!(q.x >= 0 && q.y >= 0 && q.x <= w && q.y <= h)) {
            out[0] = out[1] = out[2] = out[3] = 0;
            continue;
        }
        float c[4];
        if (sampling_ == ImageSampling::Nearest) {
            const int ix = std::min(static_cast<int>(q.x), w - 1), iy = std::min(static_cast<int>(q.y), h - 1);
            const std::uint8_t* s = im.row(iy) + 4 * static_cast<std::size_t>(ix);
            for (int k = 0; k < 4; ++k) c[k] = s[k];
        } else if (sampling_ == ImageSampling::Bicubic) {
            sample_bicubic(q.x - 0.5, q.y - 0.5, c);
        } else {
            const double u = q.x - 0.5, v = q.y - 0.5;
            const double fu = std::floor(u), fv = std::floor(v);
            const float au = static_cast<float>(u - fu), av = static_cast<float>(v - fv);
            const int x0 = wrap_or_clamp(static_cast<int>(fu), w, repeat_),
                      x1 = wrap_or_clamp(static_cast<int>(fu) + 1, w, repeat_);
            const int y0 = wrap_or_clamp(static_cast<int>(fv), h, repeat_),
                      y1 = wrap_or_clamp(static_cast<int>(fv) + 1, h, repeat_);
            const std::uint8_t* a = im.row(y0) + 4 * static_cast<std::size_t>(x0);
            const std::uint8_t* b = im.row(y0) + 4 * static_cast<std::size_t>(x1);
            const std::uint8_t* cc = im.row(y1) + 4 * static_cast<std::size_t>(x0);
            const std::uint8_t* d = im.row(y1) + 4 * static_cast<std::size_t>(x1);
            for (int k = 0; k < 4; ++k) {
                const float top = a[k] + (b[k] - a[k]) * au, bottom = cc[k] + (d[k] - cc[k]) * au;
                c[k] = top + (bottom - top) * av;
            }
        }
        for (int k = 0; k < 4; ++k) out[k] = static_cast<std::uint8_t>(std::min(255.0f, c[k] * op + 0.5f));
    }
}

}  // namespace casteljau
