// Filter stage: feColorMatrix. A 4x5 matrix on straight (unpremultiplied) RGBA in [0, 1]:
// R' = m0 R + m1 G + m2 B + m3 A + m4, and so on for G', B', A'; results are clamped to [0, 1]
// and premultiplied again.
#include "filter/image.hpp"

namespace casteljau::filter::detail {

void color_matrix(Img& img, const std::array<double, 20>& m) {
    for_each_straight(img, [&m](double c[4]) {
        double o[4];
        for (int r = 0; r < 4; ++r)
            o[r] = m[r * 5] * c[0] + m[r * 5 + 1] * c[1] + m[r * 5 + 2] * c[2] + m[r * 5 + 3] * c[3] + m[r * 5 + 4];
        std::copy(o, o + 4, c);
    });
}

}  // namespace casteljau::filter::detail
