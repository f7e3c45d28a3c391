// Filter stage: the primitives that move pixels without changing them: feOffset (a shift by whole
// device pixels, the nearest, halves toward zero) and feTile (the input's subregion repeated over
// the plane).
#include "filter/image.hpp"

namespace casteljau::filter::detail {

Img offset(const Img& in, double dx, double dy) {
    Img out(in.w, in.h, in.linear);
    if (!std::isfinite(dx) || !std::isfinite(dy)) return out;
    // The nearest whole pixel, half a pixel toward zero (a shift of 7.5 pixels moves 7, as resvg
    // does).
    auto nearest = [](double d) { return std::clamp(d >= 0 ? std::ceil(d - 0.5) : std::floor(d + 0.5), -1e9, 1e9); };
    const double cx = nearest(dx), cy = nearest(dy);
    const long long ox = static_cast<long long>(cx), oy = static_cast<long long>(cy);
    for (int y = 0; y < in.h; ++y) {
        const long long sy = y - oy;
        if (sy < 0 || sy >= in.h) continue;
        for (int x = 0; x < in.w; ++x) {
            const long long sx = x - ox;
            if (sx < 0 || sx >= in.w) continue;
            const float* s = in.at(static_cast<int>(sx), static_cast<int>(sy));
            std::copy(s, s + 4, out.at(x, y));
        }
    }
    return out;
}

Img tile(const Img& in, const IRect& sub) {
    Img out(in.w, in.h, in.linear);
    const int tw = sub.x1 - sub.x0, th = sub.y1 - sub.y0;
    if (tw <= 0 || th <= 0) return out;
    for (int y = 0; y < in.h; ++y) {
        const int sy = sub.y0 + (((y - sub.y0) % th) + th) % th;
        for (int x = 0; x < in.w; ++x) {
            const int sx = sub.x0 + (((x - sub.x0) % tw) + tw) % tw;
            const float* s = in.at(sx, sy);
            std::copy(s, s + 4, out.at(x, y));
        }
    }
    return out;
}

}  // namespace casteljau::filter::detail
