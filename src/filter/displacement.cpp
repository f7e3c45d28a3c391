// Filter stage: feDisplacementMap. P'(x, y) = P(x + sx (XC(x, y) - 0.5), y + sy (YC(x, y) - 0.5)),
// XC and YC the selected channels of the straight colour of the map (in2), sx and sy the scale in
// device pixels per axis; the displaced pixel is taken from the nearest source pixel, transparent
// outside the region.
#include "filter/image.hpp"

namespace casteljau::filter::detail {

Img displacement(const Img& in, const Img& map, double scale_x, double scale_y, int xc, int yc) {
    Img out(in.w, in.h, in.linear);
    xc = std::clamp(xc, 0, 3);
    yc = std::clamp(yc, 0, 3);
    for (int y = 0; y < in.h; ++y) {
        for (int x = 0; x < in.w; ++x) {
            const float* m = map.at(x, y);
            const float a = m[3];
            auto channel = [&](int c) { return c == 3 ? a : (a > 0 ? clamp01(m[c] / a) : 0.0f); };
            const double px = x + scale_x * (channel(xc) - 0.5), py = y + scale_y * (channel(yc) - 0.5);
            if (!(px >= 0 && px < in.w && py >= 0 && py < in.h)) continue;
            const float* s = in.at(static_cast<int>(px), static_cast<int>(py));
            std::copy(s, s + 4, out.at(x, y));
        }
    }
    return out;
}

}  // namespace casteljau::filter::detail
