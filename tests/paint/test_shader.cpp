// Gradient shaders against their formulas: a linear and a radial gradient filled over a canvas,
// sampled at pixel centres and compared with the colour computed here from the definition
// (projection / circle radius, the spread method, linear interpolation between stops), for all
// three spread methods; plus stop normalisation and compositing over a background.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/shader.hpp"
#include "simd_targets.hpp"

using namespace casteljau;

namespace {

// Stops: red at 0, blue (alpha 128) at 0.5, green at 1.
std::vector<GradientStop> three_stops() {
    return {{0, Color::rgba(255, 0, 0)}, {0.5, Color::rgba(0, 0, 255, 128)}, {1, Color::rgba(0, 255, 0)}};
}

double spread(double t, SpreadMethod m) {
    if (m == SpreadMethod::Pad) return std::min(1.0, std::max(0.0, t));
    if (m == SpreadMethod::Repeat) return t - std::floor(t);
    const double u = std::fmod(std::fabs(t), 2.0);
    return u > 1 ? 2 - u : u;
}

// Expected premultiplied pixel at parameter t (after spreading) for three_stops().
PremulPixel expected(double t) {
    double c0[4], c1[4], w;
    const double red[4] = {255, 0, 0, 255}, blue[4] = {0, 0, 255, 128}, green[4] = {0, 255, 0, 255};
    if (t <= 0.5) {
        std::copy(red, red + 4, c0);
        std::copy(blue, blue + 4, c1);
        w = t / 0.5;
    } else {
        std::copy(blue, blue + 4, c0);
        std::copy(green, green + 4, c1);
        w = (t - 0.5) / 0.5;
    }
    double c[4];
    for (int k = 0; k < 4; ++k) c[k] = c0[k] + (c1[k] - c0[k]) * w;
    const double a = c[3] / 255;
    return {static_cast<std::uint8_t>(std::lround(c[0] * a)), static_cast<std::uint8_t>(std::lround(c[1] * a)),
            static_cast<std::uint8_t>(std::lround(c[2] * a)), static_cast<std::uint8_t>(std::lround(c[3]))};
}

void check_close(const PremulPixel& got, const PremulPixel& want) {
    INFO("got " << int(got.r) << "," << int(got.g) << "," << int(got.b) << "," << int(got.a) << " want " << int(want.r)
                << "," << int(want.g) << "," << int(want.b) << "," << int(want.a));
    CHECK(std::abs(got.r - want.r) <= 1);
    CHECK(std::abs(got.g - want.g) <= 1);
    CHECK(std::abs(got.b - want.b) <= 1);
    CHECK(std::abs(got.a - want.a) <= 1);
}

Path full(int w, int h) {
    Path p;
    p.add_rect(Rect::from_xywh(0, 0, w, h));
    return p;
}

}  // namespace

TEST_CASE("shader: a linear gradient matches its formula for every spread method", "[shader]") {
    for (SpreadMethod m : {SpreadMethod::Pad, SpreadMethod::Reflect, SpreadMethod::Repeat}) {
        Pixmap pm(120, 40);
        Canvas canvas(pm);
        // Gradient space scaled by 2 and shifted: p0 = (10, 0) -> (30, 5), p1 = (30, 10) -> (70, 25).
        const Affine t = Affine::translate(10, 5) * Affine::scale(2);
        canvas.fill_path(full(120, 40), Paint::shaded(Shader::linear({10, 0}, {30, 10}, three_stops(), m, t)));
        const Point a{30, 5}, b{70, 25};
        for (int y = 1; y < 40; y += 7)
            for (int x = 0; x < 120; x += 9) {
                const double dx = b.x - a.x, dy = b.y - a.y;
                const double tt = ((x + 0.5 - a.x) * dx + (y + 0.5 - a.y) * dy) / (dx * dx + dy * dy);
                check_close(pm.pixel(x, y), expected(spread(tt, m)));
            }
    }
}

TEST_CASE("shader: a radial gradient matches its formula for every spread method", "[shader]") {
    for (SpreadMethod m : {SpreadMethod::Pad, SpreadMethod::Reflect, SpreadMethod::Repeat}) {
        Pixmap pm(100, 100);
        Canvas canvas(pm);
        canvas.fill_path(full(100, 100), Paint::shaded(Shader::radial({50, 50}, 20, {50, 50}, 0, three_stops(), m)));
        for (int y = 0; y < 100; y += 7)
            for (int x = 0; x < 100; x += 7) {
                const double r = std::hypot(x + 0.5 - 50, y + 0.5 - 50);
                check_close(pm.pixel(x, y), expected(spread(r / 20, m)));
            }
    }
}

TEST_CASE("shader: a radial gradient with a focal circle solves the two-point conical equation", "[shader]") {
    Pixmap pm(100, 100);
    Canvas canvas(pm);
    const Point c{50, 50}, f{40, 50};
    const double r = 40, fr = 5;
    canvas.fill_path(full(100, 100), Paint::shaded(Shader::radial(c, r, f, fr, three_stops(), SpreadMethod::Pad)));
    for (int y = 10; y < 90; y += 9)
        for (int x = 10; x < 90; x += 9) {
            // Bisection on t in [0, 1] for |p - c(t)| - r(t) = 0 (the function grows with t in this
            // configuration: the focal circle lies inside the end circle).
            const Point p{x + 0.5, y + 0.5};
            auto g = [&](double t) {
                const double cx = f.x + t * (c.x - f.x), cy = f.y + t * (c.y - f.y), rr = fr + t * (r - fr);
                return std::hypot(p.x - cx, p.y - cy) - rr;
            };
            double t;
            if (g(0) <= 0)
                t = 0;
            else if (g(1) >= 0)
                t = 1;
            else {
                double lo = 0, hi = 1;
                for (int i = 0; i < 60; ++i) (g((lo + hi) / 2) > 0 ? lo : hi) = (lo + hi) / 2;
                t = (lo + hi) / 2;
            }
            if (g(0) <= 0) continue;  // inside the focal circle t < 0: padded, checked above
            check_close(pm.pixel(x, y), expected(t));
        }
}

TEST_CASE("shader: stops are clamped and made non-decreasing, and no stops is an error", "[shader]") {
    const Shader s =
        Shader::linear({0, 0}, {1, 0}, {{0.7, Color::white()}, {0.2, Color::black()}, {1.5, Color::white()}});
    REQUIRE(s.stops().size() == 3);
    CHECK(s.stops()[0].offset == 0.7);
    CHECK(s.stops()[1].offset == 0.7);
    CHECK(s.stops()[2].offset == 1.0);
    CHECK_THROWS_AS(Shader::linear({0, 0}, {1, 0}, {}), Error);
}

TEST_CASE("shader: a shaded fill composites over the background with coverage and opacity", "[shader]") {
    Pixmap pm(10, 1);
    pm.fill(Color::white());
    Canvas canvas(pm);
    Paint p = Paint::shaded(Shader::linear({0, 0}, {10, 0}, {{0, Color::black()}, {1, Color::black()}}));
    p.opacity = 0.5;
    Path half;
    half.add_rect(Rect::from_xywh(0, 0, 10, 0.5));
    canvas.fill_path(half, p);
    // Coverage 0.5 x opacity 0.5 of black over white: 255 * 0.75.
    CHECK(std::abs(pm.pixel(4, 0).r - 191) <= 1);
    CHECK(pm.pixel(4, 0).a == 255);
}

TEST_CASE("shader: every SIMD target shades the same bytes", "[shader]") {
    // Gradient colours are computed several pixels at a time; every target must give the scalar
    // formula's bytes (no fused multiply-add, the same stop found for every parameter). Random
    // linear and focal radial gradients, one to five stops with repeated offsets, every spread
    // method and opacity, rows crossing regions where a radial gradient is undefined.
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    auto colour = [&] {
        return Color::rgba(static_cast<std::uint8_t>(rng() % 256), static_cast<std::uint8_t>(rng() % 256),
                           static_cast<std::uint8_t>(rng() % 256), static_cast<std::uint8_t>(rng() % 256));
    };
    std::vector<Shader> shaders;
    for (int i = 0; i < 60; ++i) {
        std::vector<GradientStop> stops;
        double offset = 0;
        for (int k = 0, n = 1 + i % 5; k < n; ++k) {
            if (k > 0 && rng() % 4 != 0) offset += u(rng) * 0.5;  // some offsets repeat
            stops.push_back({offset, colour()});
        }
        const SpreadMethod m = static_cast<SpreadMethod>(i % 3);
        const Point a{200 * u(rng), 100 * u(rng)}, b{200 * u(rng), 100 * u(rng)};
        shaders.push_back(i % 2 ? Shader::linear(a, b, stops, m)
                                : Shader::radial(a, 10 + 60 * u(rng), b, 20 * u(rng), stops, m));
    }
    const Affine inv = Affine::scale(1.3, 0.9) * Affine::rotate(0.2);
    const std::vector<std::uint8_t> first = test::same_bytes_on_every_target([&] {
        Pixmap pm(400, 300);
        Canvas canvas(pm);
        const std::vector<GradientStop> stops{
            {0, Color::rgba(10, 200, 30)}, {0.4, Color::rgba(250, 20, 130, 200)}, {1, Color::rgba(0, 0, 255)}};
        canvas.fill_path(Path().add_rect({0, 0, 400, 300}),
                         Paint::shaded(Shader::radial({200, 150}, 130, {170, 140}, 0, stops)));
        canvas.fill_path(Path().add_rect({0, 0, 400, 100}),
                         Paint::shaded(Shader::linear({13, 0}, {377, 50}, {stops[0], stops[1]})));
        std::vector<std::uint8_t> all(pm.data(), pm.data() + 400 * 300 * 4);
        for (std::size_t i = 0; i < shaders.size(); ++i)
            for (int y = 0; y < 150; ++y) {
                std::vector<std::uint8_t> row(4 * 331);
                shaders[i].shade_row(inv, -50, y, 331, 0.25 + 0.75 * static_cast<double>(i % 4) / 3, row.data());
                all.insert(all.end(), row.begin(), row.end());
            }
        return all;
    });
    std::size_t transparent = 0;
    for (std::size_t k = 3; k < first.size(); k += 4) transparent += first[k] == 0;
    CHECK(transparent > 1000);  // undefined radial regions and transparent stops were reached
}
