// Blend modes against the W3C Compositing and Blending formulas, written again here in double
// precision: a grid of backdrop and source colours (opaque backdrop, half-transparent source)
// composited with Canvas::draw_layer, each pixel within 2/255 of the formula.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "casteljau/canvas.hpp"

using namespace casteljau;

namespace {

double lum(const double c[3]) { return 0.3 * c[0] + 0.59 * c[1] + 0.11 * c[2]; }
void clip(double c[3]) {
    const double l = lum(c), n = std::min({c[0], c[1], c[2]}), x = std::max({c[0], c[1], c[2]});
    for (int k = 0; k < 3; ++k) {
        if (n < 0) c[k] = l + (c[k] - l) * l / (l - n);
        if (x > 1) c[k] = l + (c[k] - l) * (1 - l) / (x - l);
    }
}
void setlum(const double c[3], double l, double o[3]) {
    for (int k = 0; k < 3; ++k) o[k] = c[k] + (l - lum(c));
    clip(o);
}
double sat(const double c[3]) { return std::max({c[0], c[1], c[2]}) - std::min({c[0], c[1], c[2]}); }
void setsat(const double c[3], double s, double o[3]) {
    const double mx = std::max({c[0], c[1], c[2]}), mn = std::min({c[0], c[1], c[2]});
    for (int k = 0; k < 3; ++k) o[k] = mx > mn ? (c[k] - mn) * s / (mx - mn) : 0;
}
double sep(BlendMode m, double b, double s) {
    switch (m) {
        case BlendMode::Normal: return s;
        case BlendMode::Multiply: return b * s;
        case BlendMode::Screen: return 1 - (1 - b) * (1 - s);
        case BlendMode::Overlay: return b <= 0.5 ? 2 * s * b : 1 - 2 * (1 - s) * (1 - b);
        case BlendMode::Darken: return std::min(b, s);
        case BlendMode::Lighten: return std::max(b, s);
        case BlendMode::ColorDodge: return b == 0 ? 0 : s >= 1 ? 1 : std::min(1.0, b / (1 - s));
        case BlendMode::ColorBurn: return b >= 1 ? 1 : s <= 0 ? 0 : 1 - std::min(1.0, (1 - b) / s);
        case BlendMode::HardLight: return s <= 0.5 ? 2 * s * b : 1 - 2 * (1 - s) * (1 - b);
        case BlendMode::SoftLight: {
            if (s <= 0.5) return b - (1 - 2 * s) * b * (1 - b);
            const double d = b <= 0.25 ? ((16 * b - 12) * b + 4) * b : std::sqrt(b);
            return b + (2 * s - 1) * (d - b);
        }
        case BlendMode::Difference: return std::fabs(b - s);
        case BlendMode::Exclusion: return b + s - 2 * b * s;
        default: return s;
    }
}
void blend(BlendMode m, const double b[3], const double s[3], double o[3]) {
    double t[3];
    if (m == BlendMode::Hue) {
        setsat(s, sat(b), t);
        setlum(t, lum(b), o);
    } else if (m == BlendMode::Saturation) {
        setsat(b, sat(s), t);
        setlum(t, lum(b), o);
    } else if (m == BlendMode::Color)
        setlum(s, lum(b), o);
    else if (m == BlendMode::Luminosity)
        setlum(b, lum(s), o);
    else
        for (int k = 0; k < 3; ++k) o[k] = sep(m, b[k], s[k]);
}

}  // namespace

TEST_CASE("blend: every mode matches its formula on a grid of colours", "[blend]") {
    const int levels[] = {0, 40, 128, 200, 255};
    const int n = 5 * 5 * 5;  // colours per side
    for (int mi = 0; mi <= static_cast<int>(BlendMode::Luminosity); ++mi) {
        const BlendMode mode = static_cast<BlendMode>(mi);
        Pixmap dst(n, n), src(n, n);
        auto color = [&](int i) { return Color::rgba(levels[i % 5], levels[(i / 5) % 5], levels[i / 25]); };
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                dst.set_pixel(x, y, premultiply(color(y)));
                src.set_pixel(x, y, premultiply(color(x).with_opacity(128 / 255.0)));
            }
        Canvas canvas(dst);
        canvas.draw_layer(src, 1.0, mode);
        int bad = 0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const Color cb = color(y), cs = color(x);
                const double b[3] = {cb.r / 255.0, cb.g / 255.0, cb.b / 255.0},
                             s[3] = {cs.r / 255.0, cs.g / 255.0, cs.b / 255.0};
                double o[3];
                blend(mode, b, s, o);
                const double as = 128 / 255.0;  // ab = 1: co = cs as (1 - 1) + cb (1 - as) + as B
                const PremulPixel got = dst.pixel(x, y);
                const std::uint8_t g[3] = {got.r, got.g, got.b};
                for (int k = 0; k < 3; ++k)
                    bad += std::fabs(g[k] - 255 * (b[k] * (1 - as) + as * std::clamp(o[k], 0.0, 1.0))) > 2;
                bad += got.a != 255;
            }
        INFO("mode " << mi);
        CHECK(bad == 0);
    }
    BlendMode m;
    CHECK(parse_blend_mode("color-dodge", m));
    CHECK(m == BlendMode::ColorDodge);
    CHECK_FALSE(parse_blend_mode("plus-lighter", m));
}
