// Filter effects, feGaussianBlur: independent checks against the Gaussian itself. A single white
// pixel must spread as the sampled 2-D Gaussian density, a step edge as the Gaussian's cumulative
// distribution (1 - Phi), both within 2/255, for the exact kernel (small deviations) and the
// three-box approximation (large ones); plus the edge modes and the per-axis deviation.
#include <catch2/catch.hpp>

#include <cmath>

#include "casteljau/filter.hpp"

using namespace casteljau;

namespace {

filter::FilterGraph blur_graph(int w, int h, double sx, double sy, filter::EdgeMode edge = filter::EdgeMode::None) {
    filter::FilterGraph g;
    g.region = Rect::from_xywh(0, 0, w, h);
    filter::Primitive p;
    p.op = filter::Primitive::GaussianBlur;
    p.subregion = g.region;
    p.linear_rgb = false;
    p.std_x = sx;
    p.std_y = sy;
    p.edge = edge;
    g.primitives.push_back(p);
    return g;
}

double phi(double t, double sigma) { return std::exp(-t * t / (2 * sigma * sigma)) / (sigma * std::sqrt(2 * kPi)); }
double cdf(double t) { return 0.5 * std::erfc(-t / std::sqrt(2.0)); }

}  // namespace

TEST_CASE("filter blur: a single white pixel spreads as the sampled Gaussian within 2 of 255", "[filter][blur]") {
    for (double sigma : {0.8, 1.0, 2.5}) {
        const int n = 41, c = 20;
        Pixmap src(n, n);
        src.set_pixel(c, c, {255, 255, 255, 255});
        const Pixmap out = filter::apply_filter(blur_graph(n, n, sigma, sigma), Affine::identity(), src);
        double worst = 0;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                const double expect = 255 * phi(x - c, sigma) * phi(y - c, sigma);
                worst = std::max(worst, std::fabs(out.pixel(x, y).a - expect));
            }
        INFO("sigma " << sigma);
        CHECK(worst <= 2.0);
        CHECK(out.pixel(c, c).a > 5);  // the check above is not vacuous
    }
}

TEST_CASE("filter blur: a step edge follows the Gaussian distribution within 2 of 255 for exact and box blurs",
          "[filter][blur]") {
    for (double sigma : {3.0, 8.0, 10.5, 15.0, 40.0, 123.4}) {
        const int w = 400, h = 2, edge = 200;
        Pixmap src(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < edge; ++x) src.set_pixel(x, y, {255, 255, 255, 255});
        const Pixmap out =
            filter::apply_filter(blur_graph(w, h, sigma, 0, filter::EdgeMode::Duplicate), Affine::identity(), src);
        double worst = 0;
        for (int x = 0; x < w; ++x) {
            // Pixels 0 .. edge-1 are 1: the sum of the sampled Gaussian over them is (midpoint rule)
            // the integral up to edge - 0.5, i.e. 1 - Phi((x - edge + 0.5) / sigma).
            const double expect = 255 * (1 - cdf((x - edge + 0.5) / sigma));
            worst = std::max(worst, std::fabs(out.pixel(x, 0).a - expect));
        }
        INFO("sigma " << sigma);
        CHECK(worst <= 2.0);
        CHECK(out.pixel(edge, 0).a < 200);  // blurred
        CHECK(out.pixel(edge, 0).a > 55);
    }
}

TEST_CASE("filter blur: the deviation is per axis and scales with the transform", "[filter][blur]") {
    Pixmap src(40, 40);
    src.set_pixel(20, 20, {255, 255, 255, 255});
    // Horizontal only: the row spreads, the column does not.
    const Pixmap h = filter::apply_filter(blur_graph(40, 40, 2, 0), Affine::identity(), src);
    CHECK(h.pixel(22, 20).a > 0);
    CHECK(h.pixel(20, 22).a == 0);
    // User deviation 1 under a scale of 3 is a device deviation of 3.
    const Pixmap s = filter::apply_filter(blur_graph(40, 40, 1, 1), Affine::scale(3), src);
    const Pixmap d = filter::apply_filter(blur_graph(40, 40, 3, 3), Affine::identity(), src);
    CHECK(s.pixel(20, 20) == d.pixel(20, 20));
    CHECK(s.pixel(24, 19) == d.pixel(24, 19));
}

TEST_CASE("filter blur: edgeMode none fades at the region border, duplicate keeps a full field full",
          "[filter][blur]") {
    Pixmap src(30, 30);
    src.fill(Color::white());
    const Pixmap none = filter::apply_filter(blur_graph(30, 30, 4, 4, filter::EdgeMode::None), Affine::identity(), src);
    const Pixmap dup =
        filter::apply_filter(blur_graph(30, 30, 4, 4, filter::EdgeMode::Duplicate), Affine::identity(), src);
    const Pixmap wrap = filter::apply_filter(blur_graph(30, 30, 4, 4, filter::EdgeMode::Wrap), Affine::identity(), src);
    CHECK(none.pixel(0, 0).a < 100);
    CHECK(dup.pixel(0, 0).a == 255);
    CHECK(wrap.pixel(0, 0).a == 255);
    CHECK(none.pixel(15, 15).a == 255);
}

TEST_CASE("filter blur: a large region blurred by several threads equals its lines blurred alone", "[filter][blur]") {
    // 600 x 500 pixels is above the threading threshold (2^18); one row or one column is far below.
    const int w = 600, h = 500;
    Pixmap src(w, h);
    std::uint32_t seed = 12345;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            seed = seed * 1664525u + 1013904223u;
            const std::uint8_t a = static_cast<std::uint8_t>(seed >> 24);
            src.set_pixel(x, y, {static_cast<std::uint8_t>(a / 2), static_cast<std::uint8_t>(a / 3), a, a});
        }
    for (int axis = 0; axis < 2; ++axis) {
        const double sx = axis == 0 ? 14 : 0, sy = axis == 0 ? 0 : 14;
        const Pixmap all = filter::apply_filter(blur_graph(w, h, sx, sy), Affine::identity(), src);
        int mismatches = 0;
        for (int k : {0, 123, 299, 499}) {
            // Line k alone: a row (horizontal blur) or a column (vertical blur).
            const int lw = axis == 0 ? w : 1, lh = axis == 0 ? 1 : h;
            Pixmap line(lw, lh);
            for (int i = 0; i < (axis == 0 ? w : h); ++i)
                line.set_pixel(axis == 0 ? i : 0, axis == 0 ? 0 : i, axis == 0 ? src.pixel(i, k) : src.pixel(k, i));
            const Pixmap one = filter::apply_filter(blur_graph(lw, lh, sx, sy), Affine::identity(), line);
            for (int i = 0; i < (axis == 0 ? w : h); ++i)
                mismatches += !(one.pixel(axis == 0 ? i : 0, axis == 0 ? 0 : i) ==
                                (axis == 0 ? all.pixel(i, k) : all.pixel(k, i)));
        }
        INFO("axis " << axis);
        CHECK(mismatches == 0);
        CHECK(!(all.pixel(300, 250) == src.pixel(300, 250)));  // blurred at all
    }
}
