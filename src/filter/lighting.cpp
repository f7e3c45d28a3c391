// Filter stage: feDiffuseLighting and feSpecularLighting. The input's alpha times surfaceScale is
// a height map; its normal comes from the Sobel kernels of the SVG specification (interior form,
// with edge pixels repeated at the region's border). The light vector is the distant direction
// (azimuth, elevation) or points from the surface point to the point/spot light (positions mapped
// to device pixels, z scaled by the mean device scale); a spot light scales the light colour by
// pow(-L.S, specularExponent) inside its cone. Diffuse: kd N.L colour, opaque. Specular:
// ks pow(N.H, specularExponent) colour with H = L + (0, 0, 1) normalised, alpha the largest
// channel, the colour taken as premultiplied.
#include <cmath>

#include "filter/image.hpp"

namespace casteljau::filter::detail {

namespace {

struct V3 {
    double x, y, z;
};
V3 normalize(V3 v) {
    const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return n > 0 ? V3{v.x / n, v.y / n, v.z / n} : V3{0, 0, 0};
}
double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
}  // namespace

Img lighting(const Img& in, const Context& ctx, const Primitive& p, bool linear) {
    Img out(in.w, in.h, linear);
    const bool specular = p.op == Primitive::SpecularLighting;
    float colour[3] = {p.color.r / 255.0f, p.color.g / 255.0f, p.color.b / 255.0f};
    if (linear)
        for (float& c : colour) c = srgb_to_linear(c);
    const Light& l = p.light;
    const double zscale = (ctx.sx + ctx.sy) / 2;
    const Point lp = ctx.to_region.apply(Point{l.x, l.y});
    const Point tp = ctx.to_region.apply(Point{l.tx, l.ty});
    const V3 light_pos{lp.x, lp.y, l.z * zscale};
    const V3 spot_dir = normalize({tp.x - lp.x, tp.y - lp.y, l.tz * zscale - light_pos.z});
    const double cone_cos = l.cone_angle ? std::cos(std::min(90.0, std::fabs(*l.cone_angle)) * kPi / 180) : -2.0;
    const double az = l.azimuth * kPi / 180, el = l.elevation * kPi / 180;
    const V3 distant{std::cos(az) * std::cos(el), std::sin(az) * std::cos(el), std::sin(el)};
    auto alpha = [&](int x, int y) {
        x = std::clamp(x, 0, in.w - 1);
        y = std::clamp(y, 0, in.h - 1);
        return static_cast<double>(in.at(x, y)[3]);
    };
    const double ss = p.surface_scale;
    for (int y = 0; y < in.h; ++y) {
        for (int x = 0; x < in.w; ++x) {
            const double a00 = alpha(x - 1, y - 1), a10 = alpha(x, y - 1), a20 = alpha(x + 1, y - 1);
            const double a01 = alpha(x - 1, y), a21 = alpha(x + 1, y);
            const double a02 = alpha(x - 1, y + 1), a12 = alpha(x, y + 1), a22 = alpha(x + 1, y + 1);
            const double nx = -ss / 4 * ((a20 + 2 * a21 + a22) - (a00 + 2 * a01 + a02));
            const double ny = -ss / 4 * ((a02 + 2 * a12 + a22) - (a00 + 2 * a10 + a20));
            const V3 n = normalize({nx, ny, 1});
            V3 lv = distant;
            double lc[3] = {colour[0], colour[1], colour[2]};
            if (l.type != Light::Distant) {
                const V3 surf{static_cast<double>(x), static_cast<double>(y), ss * alpha(x, y)};
                lv = normalize({light_pos.x - surf.x, light_pos.y - surf.y, light_pos.z - surf.z});
                if (l.type == Light::Spot) {
                    const double minus_ls = -dot(lv, spot_dir);
                    const double f =
                        minus_ls <= 0 || minus_ls < cone_cos ? 0.0 : std::pow(minus_ls, l.specular_exponent);
                    for (double& c : lc) c *= f;
                }
            }
            float* o = out.at(x, y);
            if (!specular) {
                const double f = p.diffuse_constant * std::max(0.0, dot(n, lv));
                for (int k = 0; k < 3; ++k) o[k] = clamp01(static_cast<float>(f * lc[k]));
                o[3] = 1;
            } else {
                const V3 hv = normalize({lv.x, lv.y, lv.z + 1});
                const double f = p.specular_constant * std::pow(std::max(0.0, dot(n, hv)), p.specular_exponent);
                float c[3];
                for (int k = 0; k < 3; ++k) c[k] = clamp01(static_cast<float>(f * lc[k]));
                // The colour is already premultiplied by the largest channel (as resvg and Chrome
                // treat it): no channel exceeds alpha.
                for (int k = 0; k < 3; ++k) o[k] = c[k];
                o[3] = std::max({c[0], c[1], c[2]});
            }
        }
    }
    return out;
}

}  // namespace casteljau::filter::detail
