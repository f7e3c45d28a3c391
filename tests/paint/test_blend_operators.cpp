// Every blend mode and Porter-Duff operator through the paint stage (blend_span and Canvas fills
// with Paint::blend) against its formula written here, on a grid of premultiplied colours and
// coverages: co = Fa cs + Fb cb for the operators, co = cs (1 - ab) + cb (1 - as) + as ab B(Cb, Cs)
// for the blend modes (B from blend_colors, which test_blend.cpp checks against its own formulas),
// and the coverage c as D + c (R - D). Every channel within 1/255.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/canvas.hpp"

using namespace casteljau;

namespace {

struct Factors {
    double fa, fb;
};

// Porter-Duff fractions, from the table in Compositing and Blending Level 1, section 9.1.
Factors porter_duff(BlendMode m, double as, double ab) {
    switch (m) {
        case BlendMode::Clear: return {0, 0};
        case BlendMode::Source: return {1, 0};
        case BlendMode::Destination: return {0, 1};
        case BlendMode::SourceOver: return {1, 1 - as};
        case BlendMode::DestinationOver: return {1 - ab, 1};
        case BlendMode::SourceIn: return {ab, 0};
        case BlendMode::DestinationIn: return {0, as};
        case BlendMode::SourceOut: return {1 - ab, 0};
        case BlendMode::DestinationOut: return {0, 1 - as};
        case BlendMode::SourceAtop: return {ab, 1 - as};
        case BlendMode::DestinationAtop: return {1 - ab, as};
        case BlendMode::Xor: return {1 - ab, 1 - as};
        default: return {1, 1};  // Plus, clamped below
    }
}

// The expected premultiplied result (0..255 scale) of mode on source s over destination d with
// coverage c (all 0..255).
void expected(BlendMode m, const int s[4], const int d[4], int c, double out[4]) {
    const double as = s[3] / 255.0, ab = d[3] / 255.0;
    double r[4];
    if (m == BlendMode::Plus) {
        for (int k = 0; k < 4; ++k) r[k] = std::min(1.0, (s[k] + d[k]) / 255.0);
    } else if (m == BlendMode::Normal || m >= BlendMode::Clear) {
        const Factors f = porter_duff(m, as, ab);
        for (int k = 0; k < 4; ++k) r[k] = f.fa * s[k] / 255.0 + f.fb * d[k] / 255.0;
    } else {
        float cs[3], cb[3], b[3];
        for (int k = 0; k < 3; ++k) {
            cs[k] = as > 0 ? static_cast<float>(s[k] / 255.0 / as) : 0.0f;
            cb[k] = ab > 0 ? static_cast<float>(d[k] / 255.0 / ab) : 0.0f;
        }
        blend_colors(m, cb, cs, b);
        for (int k = 0; k < 3; ++k)
            r[k] = s[k] / 255.0 * (1 - ab) + d[k] / 255.0 * (1 - as) + as * ab * std::clamp<double>(b[k], 0, 1);
        r[3] = as + ab - as * ab;
    }
    for (int k = 0; k < 4; ++k) out[k] = d[k] + c / 255.0 * (r[k] * 255 - d[k]);
}

std::vector<std::array<int, 4>> premul_grid() {
    std::vector<std::array<int, 4>> g;
    const int levels[] = {0, 64, 180, 255};
    const int alphas[] = {0, 90, 200, 255};
    for (int a : alphas)
        for (int r : levels)
            for (int gg : levels)
                for (int b : {0, 255}) g.push_back({r * a / 255, gg * a / 255, b * a / 255, a});
    return g;
}

}  // namespace

TEST_CASE("blend_span: every Porter-Duff operator and blend mode matches its formula on a colour grid",
          "[blend][paint]") {
    const auto grid = premul_grid();
    const std::uint8_t coverages[] = {255, 128, 17};
    for (int mi = 0; mi < kBlendModeCount; ++mi) {
        const BlendMode mode = static_cast<BlendMode>(mi);
        int bad = 0;
        double worst = 0;
        for (const auto& s : grid) {
            std::vector<std::uint8_t> dst, src, cov;
            for (const auto& d : grid)
                for (std::uint8_t c : coverages) {
                    dst.insert(dst.end(), {static_cast<std::uint8_t>(d[0]), static_cast<std::uint8_t>(d[1]),
                                           static_cast<std::uint8_t>(d[2]), static_cast<std::uint8_t>(d[3])});
                    src.insert(src.end(), {static_cast<std::uint8_t>(s[0]), static_cast<std::uint8_t>(s[1]),
                                           static_cast<std::uint8_t>(s[2]), static_cast<std::uint8_t>(s[3])});
                    cov.push_back(c);
                }
            blend_span(dst.data(), static_cast<int>(cov.size()), cov.data(), src.data(), mode);
            std::size_t i = 0;
            for (const auto& d : grid)
                for (std::uint8_t c : coverages) {
                    double e[4];
                    expected(mode, s.data(), d.data(), c, e);
                    for (int k = 0; k < 4; ++k) {
                        const double diff = std::abs(dst[4 * i + static_cast<std::size_t>(k)] - e[k]);
                        worst = std::max(worst, diff);
                        bad += diff > 1.0;
                    }
                    ++i;
                }
        }
        INFO("mode " << blend_mode_name(mode) << " worst " << worst);
        CHECK(bad == 0);
    }
}

TEST_CASE("Canvas fills with Paint::blend and with the state's blend mode follow the same formulas",
          "[blend][canvas]") {
    const auto grid = premul_grid();
    const int n = static_cast<int>(grid.size());
    const Color src = Color::rgba(200, 30, 120, 180);
    const PremulPixel sp = premultiply(src);
    const int s[4] = {sp.r, sp.g, sp.b, sp.a};
    for (int mi = 0; mi < kBlendModeCount; ++mi) {
        const BlendMode mode = static_cast<BlendMode>(mi);
        for (bool via_state : {false, true}) {
            Pixmap pm(n, 1);
            for (int x = 0; x < n; ++x)
                pm.set_pixel(x, 0,
                             {static_cast<std::uint8_t>(grid[static_cast<std::size_t>(x)][0]),
                              static_cast<std::uint8_t>(grid[static_cast<std::size_t>(x)][1]),
                              static_cast<std::uint8_t>(grid[static_cast<std::size_t>(x)][2]),
                              static_cast<std::uint8_t>(grid[static_cast<std::size_t>(x)][3])});
            Canvas c(pm);
            Paint p = Paint::solid(src);
            if (via_state)
                c.set_blend_mode(mode);
            else
                p.blend = mode;
            c.fill_rect({0, 0, static_cast<double>(n), 1}, p);
            int bad = 0;
            for (int x = 0; x < n; ++x) {
                double e[4];
                expected(mode, s, grid[static_cast<std::size_t>(x)].data(), 255, e);
                const PremulPixel g = pm.pixel(x, 0);
                const int got[4] = {g.r, g.g, g.b, g.a};
                for (int k = 0; k < 4; ++k) bad += std::abs(got[k] - e[k]) > 1.0;
            }
            INFO("mode " << blend_mode_name(mode) << (via_state ? " (canvas state)" : " (paint)"));
            CHECK(bad == 0);
        }
    }
}

TEST_CASE("blend mode names read back", "[blend]") {
    for (int mi = 0; mi < kBlendModeCount; ++mi) {
        const BlendMode mode = static_cast<BlendMode>(mi);
        BlendMode back = BlendMode::Xor;
        const bool ok = mode == BlendMode::Normal ? parse_blend_mode(blend_mode_name(mode), back)
                                                  : parse_blend_operator(blend_mode_name(mode), back);
        CHECK(ok);
        CHECK(back == mode);
    }
    BlendMode m;
    CHECK(parse_blend_operator("source-over", m));
    CHECK(m == BlendMode::SourceOver);
    CHECK_FALSE(parse_blend_mode("xor", m));
    CHECK_FALSE(parse_blend_operator("nonsense", m));
}
