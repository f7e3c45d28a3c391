// Filter stage: feConvolveMatrix. RESULT(x, y) = sum over the kernel of
// SOURCE(x - targetX + j, y - targetY + i) x kernel[orderX - 1 - j, orderY - 1 - i] / divisor + bias,
// on premultiplied RGBA, or with preserveAlpha on the straight colour with alpha kept; pixels
// outside the region come from the edge mode. Results are clamped, colour to at most alpha.
#include "filter/image.hpp"

namespace casteljau::filter::detail {

Img convolve(const Img& in, const Primitive& p) {
    Img out(in.w, in.h, in.linear);
    const int ox = p.order_x, oy = p.order_y;
    auto fetch = [&](int x, int y, float v[4]) {
        if (x < 0 || x >= in.w || y < 0 || y >= in.h) {
            if (p.edge == EdgeMode::None) {
                v[0] = v[1] = v[2] = v[3] = 0;
                return;
            }
            if (p.edge == EdgeMode::Duplicate) {
                x = std::clamp(x, 0, in.w - 1);
                y = std::clamp(y, 0, in.h - 1);
            } else {
                x = ((x % in.w) + in.w) % in.w;
                y = ((y % in.h) + in.h) % in.h;
            }
        }
        const float* s = in.at(x, y);
        for (int k = 0; k < 4; ++k) v[k] = s[k];
        if (p.preserve_alpha && v[3] > 0)
            for (int k = 0; k < 3; ++k) v[k] /= v[3];
    };
    const double div = p.divisor == 0 ? 1 : p.divisor;
    for (int y = 0; y < in.h; ++y) {
        for (int x = 0; x < in.w; ++x) {
            double acc[4] = {0, 0, 0, 0};
            for (int i = 0; i < oy; ++i) {
                for (int j = 0; j < ox; ++j) {
                    const double k = p.kernel[static_cast<std::size_t>((oy - 1 - i) * ox + (ox - 1 - j))];
                    if (k == 0) continue;
                    float v[4];
                    fetch(x - p.target_x + j, y - p.target_y + i, v);
                    for (int c = 0; c < 4; ++c) acc[c] += k * v[c];
                }
            }
            float* o = out.at(x, y);
            if (p.preserve_alpha) {
                const float a = in.at(x, y)[3];
                for (int c = 0; c < 3; ++c) o[c] = clamp01(static_cast<float>(acc[c] / div + p.bias)) * a;
                o[3] = a;
            } else {
                o[3] = clamp01(static_cast<float>(acc[3] / div + p.bias));
                for (int c = 0; c < 3; ++c)
                    o[c] = std::min(o[3], clamp01(static_cast<float>(acc[c] / div + p.bias * o[3])));
            }
        }
    }
    return out;
}

}  // namespace casteljau::filter::detail
