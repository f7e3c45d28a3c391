// Filter stage, internal: the float image every primitive reads and writes, and the helpers they
// share. An Img covers the filter region (w x h device pixels, the region's top-left at 0, 0) and
// holds premultiplied RGBA in [0, 1], row-major, 4 floats per pixel, in linearRGB or sRGB.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/filter.hpp"

namespace casteljau::filter::detail {

struct Img {
    int w = 0, h = 0;
    bool linear = false;  // colour space of the values
    IRect sub;            // the rectangle feTile repeats (region-relative): the subregion, or for feOffset its input's
    std::vector<float> px;

    Img() = default;
    Img(int width, int height, bool lin)
        : w(width),
          h(height),
          linear(lin),
          sub{0, 0, width, height},
          px(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0.0f) {}
    float* at(int x, int y) {
        return px.data() +
               (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4;
    }
    const float* at(int x, int y) const {
        return px.data() +
               (static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x)) * 4;
    }
    std::size_t count() const { return static_cast<std::size_t>(w) * static_cast<std::size_t>(h); }
};

// The device parameters of one evaluation: the region's size and the user -> region-pixel map.
struct Context {
    int w = 0, h = 0;
    Affine to_region;       // user units -> region pixels
    double sx = 1, sy = 1;  // device pixels per user unit along x and y
};

inline float clamp01(float v) { return v < 0 ? 0.0f : (v > 1 ? 1.0f : v); }

// sRGB <-> linear light for one straight channel in [0, 1].
inline float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
inline float linear_to_srgb(float c) {
    return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

// Calls f(c) for every pixel with its straight (unpremultiplied) RGBA in [0, 1] as double c[4],
// then clamps what f left there to [0, 1] and stores it premultiplied.
template <class F>
void for_each_straight(Img& img, F&& f) {
    float* p = img.px.data();
    for (std::size_t i = 0, n = img.count(); i < n; ++i, p += 4) {
        const double a = p[3];
        double c[4] = {0, 0, 0, a};
        if (a > 0)
            for (int k = 0; k < 3; ++k) c[k] = std::min(1.0, p[k] / a);
        f(c);
        for (double& v : c) v = std::clamp(v, 0.0, 1.0);
        for (int k = 0; k < 3; ++k) p[k] = static_cast<float>(c[k] * c[3]);
        p[3] = static_cast<float>(c[3]);
    }
}

// Converts `img` to linearRGB (linear = true) or sRGB in place.
void convert(Img& img, bool linear);
// Gaussian blur with standard deviations in device pixels (0 on an axis leaves it unblurred).
void gaussian_blur(Img& img, double sigma_x, double sigma_y, EdgeMode edge);
// Shifts by whole device pixels (rounded); what comes in from outside is transparent.
Img offset(const Img& in, double dx, double dy);
// a over b (premultiplied), Porter-Duff and arithmetic operators.
Img composite(const Img& a, const Img& b, CompositeOp op, double k1, double k2, double k3, double k4);
Img blend(const Img& a, const Img& b, BlendMode mode);
void color_matrix(Img& img, const std::array<double, 20>& m);
void component_transfer(Img& img, const std::array<TransferFunction, 4>& f);
Img morphology(const Img& in, int rx, int ry, bool dilate);
Img convolve(const Img& in, const Primitive& p);
Img tile(const Img& in, const IRect& sub);
Img turbulence(const Context& ctx, const Primitive& p, bool linear);
Img displacement(const Img& in, const Img& map, double scale_x, double scale_y, int xc, int yc);
Img lighting(const Img& in, const Context& ctx, const Primitive& p, bool linear);

}  // namespace casteljau::filter::detail
