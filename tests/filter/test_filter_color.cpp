// Filter effects, colour primitives: feColorMatrix and feComposite arithmetic against their
// formulas worked out here on a grid of premultiplied colours, feComponentTransfer's functions,
// the Porter-Duff operators, and color-interpolation-filters (a linearRGB round trip).
#include <catch2/catch.hpp>

#include <cmath>

#include "casteljau/filter.hpp"

using namespace casteljau;

namespace {

// A pixmap whose pixels run through a grid of straight colours and alphas.
Pixmap colour_grid() {
    const int levels[] = {0, 37, 128, 200, 255};
    Pixmap pm(25, 25);
    int i = 0;
    for (int r : levels)
        for (int g : levels)
            for (int b : levels)
                for (int a : levels) {
                    pm.set_pixel(i % 25, i / 25,
                                 premultiply(Color::rgba(static_cast<std::uint8_t>(r), static_cast<std::uint8_t>(g),
                                                         static_cast<std::uint8_t>(b), static_cast<std::uint8_t>(a))));
                    ++i;
                }
    return pm;
}

filter::FilterGraph one(const filter::Primitive& p0, int w, int h) {
    filter::FilterGraph g;
    g.region = Rect::from_xywh(0, 0, w, h);
    filter::Primitive p = p0;
    p.subregion = g.region;
    g.primitives.push_back(p);
    return g;
}

}  // namespace

TEST_CASE("filter feColorMatrix: every pixel of a colour grid equals the matrix formula within 1", "[filter][color]") {
    const Pixmap src = colour_grid();
    filter::Primitive p;
    p.op = filter::Primitive::ColorMatrix;
    p.linear_rgb = false;
    p.matrix = {0.5, 0.3, -0.2, 0.1, 0.05, 0.1, 0.9, 0.2, 0, -0.1, -0.3, 0.4, 1.1, 0, 0.2, 0.2, 0.1, 0.1, 0.7, 0.05};
    const Pixmap out = filter::apply_filter(one(p, 25, 25), Affine::identity(), src);
    int worst = 0;
    for (int y = 0; y < 25; ++y)
        for (int x = 0; x < 25; ++x) {
            const PremulPixel s = src.pixel(x, y);
            // The formula on straight values in [0, 1], clamped, premultiplied.
            const double a = s.a / 255.0;
            const double c[4] = {a > 0 ? s.r / 255.0 / a : 0, a > 0 ? s.g / 255.0 / a : 0, a > 0 ? s.b / 255.0 / a : 0,
                                 a};
            double o[4];
            for (int r = 0; r < 4; ++r) {
                double v = p.matrix[r * 5 + 4];
                for (int k = 0; k < 4; ++k) v += p.matrix[r * 5 + k] * c[k];
                o[r] = std::clamp(v, 0.0, 1.0);
            }
            const int expect[4] = {
                static_cast<int>(std::lround(o[0] * o[3] * 255)), static_cast<int>(std::lround(o[1] * o[3] * 255)),
                static_cast<int>(std::lround(o[2] * o[3] * 255)), static_cast<int>(std::lround(o[3] * 255))};
            const PremulPixel d = out.pixel(x, y);
            const int got[4] = {d.r, d.g, d.b, d.a};
            for (int k = 0; k < 4; ++k) worst = std::max(worst, std::abs(got[k] - expect[k]));
        }
    CHECK(worst <= 1);
}

TEST_CASE("filter feComposite arithmetic: k1 i1 i2 + k2 i1 + k3 i2 + k4 on a colour grid within 1", "[filter][color]") {
    const Pixmap src = colour_grid();
    const Color flood = Color::rgba(40, 180, 90, 160);
    filter::FilterGraph g;
    g.region = Rect::from_xywh(0, 0, 25, 25);
    filter::Primitive f;
    f.op = filter::Primitive::Flood;
    f.color = flood;
    f.linear_rgb = false;
    f.subregion = g.region;
    g.primitives.push_back(f);
    filter::Primitive c;
    c.op = filter::Primitive::Composite;
    c.composite = filter::CompositeOp::Arithmetic;
    c.k1 = 0.7;
    c.k2 = 0.6;
    c.k3 = 0.4;
    c.k4 = -0.1;
    c.linear_rgb = false;
    c.subregion = g.region;
    c.inputs = {filter::Input::source_graphic(), filter::Input::result(0)};
    g.primitives.push_back(c);
    const Pixmap out = filter::apply_filter(g, Affine::identity(), src);
    const double fa = flood.a / 255.0;
    const double i2[4] = {flood.r / 255.0 * fa, flood.g / 255.0 * fa, flood.b / 255.0 * fa, fa};
    int worst = 0;
    for (int y = 0; y < 25; ++y)
        for (int x = 0; x < 25; ++x) {
            const PremulPixel s = src.pixel(x, y);
            const double i1[4] = {s.r / 255.0, s.g / 255.0, s.b / 255.0, s.a / 255.0};
            double o[4];
            for (int k = 0; k < 4; ++k)
                o[k] = std::clamp(c.k1 * i1[k] * i2[k] + c.k2 * i1[k] + c.k3 * i2[k] + c.k4, 0.0, 1.0);
            for (int k = 0; k < 3; ++k) o[k] = std::min(o[k], o[3]);
            const PremulPixel d = out.pixel(x, y);
            const int got[4] = {d.r, d.g, d.b, d.a};
            for (int k = 0; k < 4; ++k)
                worst = std::max(worst, std::abs(got[k] - static_cast<int>(std::lround(o[k] * 255))));
        }
    CHECK(worst <= 1);
}

TEST_CASE("filter feComposite: the Porter-Duff operators on two opaque halves", "[filter][color]") {
    // Source: left half red; flood input: top half blue (both opaque).
    Pixmap src(10, 10);
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 5; ++x) src.set_pixel(x, y, {255, 0, 0, 255});
    auto run = [&](filter::CompositeOp op) {
        filter::FilterGraph g;
        g.region = Rect::from_xywh(0, 0, 10, 10);
        filter::Primitive f;
        f.op = filter::Primitive::Flood;
        f.color = Color::rgba(0, 0, 255);
        f.subregion = Rect::from_xywh(0, 0, 10, 5);
        g.primitives.push_back(f);
        filter::Primitive c;
        c.op = filter::Primitive::Composite;
        c.composite = op;
        c.subregion = g.region;
        c.inputs = {filter::Input::source_graphic(), filter::Input::result(0)};
        g.primitives.push_back(c);
        return filter::apply_filter(g, Affine::identity(), src);
    };
    const PremulPixel red{255, 0, 0, 255}, blue{0, 0, 255, 255}, none{0, 0, 0, 0};
    // Quadrants: (2,2) both, (7,2) blue only, (2,7) red only, (7,7) neither.
    const Pixmap over = run(filter::CompositeOp::Over);
    CHECK(over.pixel(2, 2) == red);
    CHECK(over.pixel(7, 2) == blue);
    const Pixmap in = run(filter::CompositeOp::In);
    CHECK(in.pixel(2, 2) == red);
    CHECK(in.pixel(2, 7) == none);
    const Pixmap out = run(filter::CompositeOp::Out);
    CHECK(out.pixel(2, 2) == none);
    CHECK(out.pixel(2, 7) == red);
    const Pixmap atop = run(filter::CompositeOp::Atop);
    CHECK(atop.pixel(2, 2) == red);
    CHECK(atop.pixel(7, 2) == blue);
    CHECK(atop.pixel(2, 7) == none);
    const Pixmap x = run(filter::CompositeOp::Xor);
    CHECK(x.pixel(2, 2) == none);
    CHECK(x.pixel(7, 2) == blue);
    CHECK(x.pixel(2, 7) == red);
    CHECK(x.pixel(7, 7) == none);
}

TEST_CASE("filter feComponentTransfer: table, discrete, linear and gamma follow their definitions", "[filter][color]") {
    filter::TransferFunction t;
    t.type = filter::TransferFunction::Table;
    t.table = {0, 1, 0};
    CHECK(t.apply(0.25) == Approx(0.5));
    CHECK(t.apply(0.75) == Approx(0.5));
    t.type = filter::TransferFunction::Discrete;
    t.table = {0.2, 0.4, 0.9};
    CHECK(t.apply(0.1) == Approx(0.2));
    CHECK(t.apply(0.5) == Approx(0.4));
    CHECK(t.apply(1.0) == Approx(0.9));
    t.type = filter::TransferFunction::Linear;
    t.slope = 2;
    t.intercept = 0.1;
    CHECK(t.apply(0.3) == Approx(0.7));
    t.type = filter::TransferFunction::Gamma;
    t.amplitude = 2;
    t.exponent = 3;
    t.offset = 0.05;
    CHECK(t.apply(0.5) == Approx(0.3));
}

TEST_CASE("filter color-interpolation-filters: an identity primitive in linearRGB returns the source within 1",
          "[filter][color]") {
    const Pixmap src = colour_grid();
    filter::Primitive p;
    p.op = filter::Primitive::Offset;  // dx = dy = 0
    p.linear_rgb = true;
    const Pixmap out = filter::apply_filter(one(p, 25, 25), Affine::identity(), src);
    int worst = 0;
    for (int y = 0; y < 25; ++y)
        for (int x = 0; x < 25; ++x) {
            const PremulPixel a = src.pixel(x, y), b = out.pixel(x, y);
            worst =
                std::max({worst, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
        }
    CHECK(worst <= 1);
}
