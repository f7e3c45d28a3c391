// Filter stage: feColorMatrix. A 4x5 matrix on straight (unpremultiplied) RGBA in [0, 1]:
// R' = m0 R + m1 G + m2 B + m3 A + m4, and so on for G', B', A'; results are clamped to [0, 1]
// and premultiplied again.
#include "filter/image.hpp"

namespace casteljau::filter::detail {

void color_matrix(Img& img, const std::array<double, 20>& m) {
    float* p = img.px.data();
    for (std::size_t i = 0, n = img.count(); i < n; ++i, p += 4) {
        const double a = p[3];
        double c[4] = {0, 0, 0, a};
        if (a > 0)
            for (int k = 0; k < 3; ++k) c[k] = std::min(1.0, p[k] / a);
        double o[4];
        for (int r = 0; r < 4; ++r)
            o[r] = std::clamp(m[r * 5] * c[0] + m[r * 5 + 1] * c[1] + m[r * 5 + 2] * c[2] + m[r * 5 + 3] * c[3] + m[r * 5 + 4], 0.0, 1.0);
        for (int k = 0; k < 3; ++k) p[k] = static_cast<float>(o[k] * o[3]);
        p[3] = static_cast<float>(o[3]);
    }
}

}  // namespace casteljau::filter::detail
