// Filter stage: feComposite (Porter-Duff operators on premultiplied colour, the arithmetic
// k1 i1 i2 + k2 i1 + k3 i2 + k4 clamped to [0, 1] with colour <= alpha, and lighter) and feBlend
// (the blend modes of Compositing and Blending Level 1, `in` the source over `in2` the backdrop).
#include "filter/image.hpp"

namespace casteljau::filter::detail {

namespace {
// out = f(a pixel, b pixel, out pixel) over the image, out in a's colour space.
template <class F>
Img combine(const Img& a, const Img& b, F&& f) {
    Img out(a.w, a.h, a.linear);
    const float* s = a.px.data();
    const float* d = b.px.data();
    float* o = out.px.data();
    for (std::size_t i = 0, n = a.count(); i < n; ++i, s += 4, d += 4, o += 4) f(s, d, o);
    return out;
}
}  // namespace

Img composite(const Img& a, const Img& b, CompositeOp op, double k1, double k2, double k3, double k4) {
    return combine(a, b, [&](const float* s, const float* d, float* o) {
        const float as = s[3], ab = d[3];
        switch (op) {
            case CompositeOp::Over:
                for (int k = 0; k < 4; ++k) o[k] = s[k] + d[k] * (1 - as);
                break;
            case CompositeOp::In:
                for (int k = 0; k < 4; ++k) o[k] = s[k] * ab;
                break;
            case CompositeOp::Out:
                for (int k = 0; k < 4; ++k) o[k] = s[k] * (1 - ab);
                break;
            case CompositeOp::Atop:
                for (int k = 0; k < 4; ++k) o[k] = s[k] * ab + d[k] * (1 - as);
                break;
            case CompositeOp::Xor:
                for (int k = 0; k < 4; ++k) o[k] = s[k] * (1 - ab) + d[k] * (1 - as);
                break;
            case CompositeOp::Lighter:
                for (int k = 0; k < 4; ++k) o[k] = std::min(1.0f, s[k] + d[k]);
                break;
            case CompositeOp::Arithmetic: {
                for (int k = 0; k < 4; ++k)
                    o[k] = static_cast<float>(std::clamp(k1 * s[k] * d[k] + k2 * s[k] + k3 * d[k] + k4, 0.0, 1.0));
                for (int k = 0; k < 3; ++k) o[k] = std::min(o[k], o[3]);
                break;
            }
        }
    });
}

Img blend(const Img& a, const Img& b, BlendMode mode) {
    return combine(a, b, [mode](const float* s, const float* d, float* o) {
        const float as = s[3], ab = d[3];
        float cs[3] = {0, 0, 0}, cb[3] = {0, 0, 0}, bl[3];
        for (int k = 0; k < 3; ++k) {
            if (as > 0) cs[k] = clamp01(s[k] / as);
            if (ab > 0) cb[k] = clamp01(d[k] / ab);
        }
        blend_colors(mode, cb, cs, bl);
        for (int k = 0; k < 3; ++k) o[k] = s[k] * (1 - ab) + d[k] * (1 - as) + as * ab * clamp01(bl[k]);
        o[3] = as + ab - as * ab;
    });
}

}  // namespace casteljau::filter::detail
