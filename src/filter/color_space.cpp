// Filter stage: colour spaces of filter images (color-interpolation-filters). Values are
// premultiplied, so each pixel is unpremultiplied, its colour channels converted between sRGB and
// linear light, and premultiplied again.
#include "filter/image.hpp"

namespace casteljau::filter::detail {

void convert(Img& img, bool linear) {
    if (img.linear == linear) return;
    float* p = img.px.data();
    for (std::size_t i = 0, n = img.count(); i < n; ++i, p += 4) {
        const float a = p[3];
        if (a <= 0) continue;
        for (int k = 0; k < 3; ++k) {
            const float c = clamp01(p[k] / a);
            p[k] = (linear ? srgb_to_linear(c) : linear_to_srgb(c)) * a;
        }
    }
    img.linear = linear;
}

}  // namespace casteljau::filter::detail
