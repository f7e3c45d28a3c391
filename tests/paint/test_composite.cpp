// Compositing: composite_span against the exactly rounded source-over formula, computed here
// independently (straight colour -> premultiplied -> weighted sum in double precision, rounded
// once), for every coverage value, a grid of colours, alphas and opacities, onto opaque and
// translucent destinations; and the linear-light mode against the same blend done in double
// precision.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "casteljau/canvas.hpp"
#include "core/simd_dispatch.hpp"
#include "paint/pixel_math.hpp"
#include "paint/source_over_span.hpp"

using namespace casteljau;

namespace {

struct Rgba {
    double r, g, b, a;
};

// The paint's premultiplied colour as the formula defines it, in exact integers.
Rgba premultiplied_source(Color c, double opacity) {
    const double a = std::floor(c.a * opacity + 0.5);
    auto pre = [&](double x) { return std::floor(x * a / 255.0 + 0.5); };
    return {pre(c.r), pre(c.g), pre(c.b), a};
}

// Source-over of S x coverage onto D, one rounding at the end.
std::array<int, 4> source_over(const Rgba& s, int coverage, const std::array<int, 4>& d) {
    const double c = coverage / 255.0;
    const double keep = 1.0 - (s.a / 255.0) * c;
    auto ch = [&](double sx, int dx) { return static_cast<int>(std::floor(sx * c + dx * keep + 0.5)); };
    return {ch(s.r, d[0]), ch(s.g, d[1]), ch(s.b, d[2]), ch(s.a, d[3])};
}

// Premultiplied destinations: opaque, translucent and empty, with channels up to their alpha.
std::vector<std::array<int, 4>> destinations() {
    std::vector<std::array<int, 4>> out;
    for (int a : {255, 254, 200, 128, 64, 1, 0})
        for (const auto& frac : {std::array<double, 3>{0, 0, 0}, std::array<double, 3>{1, 1, 1},
                                 std::array<double, 3>{0.3, 0.7, 1.0}, std::array<double, 3>{0.9, 0.05, 0.5}})
            out.push_back(
                {static_cast<int>(a * frac[0]), static_cast<int>(a * frac[1]), static_cast<int>(a * frac[2]), a});
    return out;
}

const std::vector<Color>& source_colours() {
    static const std::vector<Color> colours = [] {
        std::vector<Color> v;
        const std::array<std::uint8_t, 6> rgb{0, 1, 37, 128, 254, 255};
        const std::array<std::uint8_t, 9> alphas{0, 1, 2, 64, 127, 128, 129, 254, 255};
        for (std::uint8_t a : alphas)
            for (std::size_t i = 0; i < rgb.size(); ++i)
                v.push_back(Color::rgba(rgb[i], rgb[(i + 2) % rgb.size()], rgb[(i + 4) % rgb.size()], a));
        return v;
    }();
    return colours;
}

// A span of 256 pixels, pixel i with coverage i, all starting as `d`.
struct Span {
    std::array<std::uint8_t, 256> coverage{};
    std::vector<std::uint8_t> px;
    explicit Span(const std::array<int, 4>& d) : px(256 * 4) {
        for (int i = 0; i < 256; ++i) {
            coverage[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
            for (int k = 0; k < 4; ++k)
                px[static_cast<std::size_t>(4 * i + k)] = static_cast<std::uint8_t>(d[static_cast<std::size_t>(k)]);
        }
    }
    std::array<int, 4> at(int i) const {
        const std::uint8_t* p = px.data() + 4 * i;
        return {p[0], p[1], p[2], p[3]};
    }
};

}  // namespace

TEST_CASE("composite_span is source-over rounded once, for every coverage, colour, alpha and destination",
          "[composite]") {
    long checked = 0, wrong = 0;
    for (double opacity : {1.0, 0.5, 0.25, 0.999}) {
        for (const Color& colour : source_colours()) {
            Paint paint = Paint::solid(colour);
            paint.opacity = opacity;
            const Rgba s = premultiplied_source(colour, opacity);
            for (const auto& d : destinations()) {
                Span span(d);
                composite_span(span.px.data(), 256, span.coverage.data(), paint);
                for (int c = 0; c < 256; ++c) {
                    const auto want = source_over(s, c, d);
                    const auto got = span.at(c);
                    ++checked;
                    if (got != want) {
                        if (++wrong <= 5) {
                            INFO("colour " << int(colour.r) << "," << int(colour.g) << "," << int(colour.b) << ","
                                           << int(colour.a) << " opacity " << opacity << " coverage " << c << " dst "
                                           << d[0] << "," << d[1] << "," << d[2] << "," << d[3] << ": got " << got[0]
                                           << "," << got[1] << "," << got[2] << "," << got[3] << " want " << want[0]
                                           << "," << want[1] << "," << want[2] << "," << want[3]);
                            CHECK(got == want);
                        }
                    }
                }
            }
        }
    }
    INFO(wrong << " of " << checked << " pixels differ from the exactly rounded formula");
    CHECK(wrong == 0);
    CHECK(checked == 4L * 54 * 28 * 256);
}

TEST_CASE("composite_span_premul is source-over rounded once, for every coverage, source and destination",
          "[composite]") {
    // Per-pixel premultiplied sources (gradients, images, layers): every valid premultiplied
    // source of a grid, every coverage, every destination of the grid.
    long checked = 0, wrong = 0;
    for (const Color& colour : source_colours()) {
        const Rgba s = premultiplied_source(colour, 1.0);
        for (const auto& d : destinations()) {
            Span span(d);
            std::vector<std::uint8_t> src(256 * 4);
            for (int i = 0; i < 256; ++i) {
                src[static_cast<std::size_t>(4 * i)] = static_cast<std::uint8_t>(s.r);
                src[static_cast<std::size_t>(4 * i + 1)] = static_cast<std::uint8_t>(s.g);
                src[static_cast<std::size_t>(4 * i + 2)] = static_cast<std::uint8_t>(s.b);
                src[static_cast<std::size_t>(4 * i + 3)] = static_cast<std::uint8_t>(s.a);
            }
            composite_span_premul(span.px.data(), 256, span.coverage.data(), src.data());
            for (int c = 0; c < 256; ++c) {
                ++checked;
                if (span.at(c) != source_over(s, c, d) && ++wrong <= 5) CHECK(span.at(c) == source_over(s, c, d));
            }
        }
    }
    INFO(wrong << " of " << checked << " pixels differ from the exactly rounded formula");
    CHECK(wrong == 0);
    CHECK(checked == 54L * 28 * 256);
}

TEST_CASE("composite_span: zero coverage and a transparent paint leave the destination untouched", "[composite]") {
    for (const auto& d : destinations()) {
        Span span(d);
        const std::array<std::uint8_t, 256> zero{};
        composite_span(span.px.data(), 256, zero.data(), Paint::solid(Color::rgba(200, 10, 30, 255)));
        Paint clear = Paint::solid(Color::rgba(200, 10, 30, 255));
        clear.opacity = 0;
        composite_span(span.px.data(), 256, span.coverage.data(), clear);
        for (int i = 0; i < 256; ++i) REQUIRE(span.at(i) == d);
    }
}

TEST_CASE("composite_span with linear_blend is the blend in linear light within one level", "[composite]") {
    auto to_linear = [](double v) {
        const double c = v / 255.0;
        return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    };
    auto to_srgb = [](double l) {
        l = std::clamp(l, 0.0, 1.0);
        return 255.0 * (l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1 / 2.4) - 0.055);
    };
    int worst = 0;
    long checked = 0;
    for (const Color& colour : source_colours()) {
        if (colour.a == 0) continue;
        Paint paint = Paint::solid(colour);
        paint.linear_blend = true;
        for (const auto& d : destinations()) {
            Span span(d);
            composite_span(span.px.data(), 256, span.coverage.data(), paint);
            for (int c = 1; c < 256; ++c) {
                // Straight colours blended in linear light with weights from the alphas.
                const double sa = colour.a / 255.0 * c / 255.0, da = d[3] / 255.0;
                const double oa = sa + da * (1 - sa);
                const double ws = sa / oa, wd = da * (1 - sa) / oa;
                const std::array<std::uint8_t, 3> src{colour.r, colour.g, colour.b};
                std::array<int, 4> want{};
                const double out_a = std::floor(oa * 255 + 0.5);
                for (int k = 0; k < 3; ++k) {
                    const double dst_straight =
                        d[3] ? std::min(255.0, std::floor(d[static_cast<std::size_t>(k)] * 255.0 / d[3] + 0.5)) : 0;
                    const double straight =
                        to_srgb(to_linear(src[static_cast<std::size_t>(k)]) * ws + to_linear(dst_straight) * wd);
                    want[static_cast<std::size_t>(k)] = static_cast<int>(std::floor(straight * out_a / 255.0 + 0.5));
                }
                want[3] = static_cast<int>(out_a);
                const auto got = span.at(c);
                for (int k = 0; k < 4; ++k)
                    worst =
                        std::max(worst, std::abs(got[static_cast<std::size_t>(k)] - want[static_cast<std::size_t>(k)]));
                ++checked;
            }
        }
    }
    INFO("largest difference over " << checked << " pixels: " << worst);
    CHECK(checked > 100000);
    CHECK(worst <= 1);
}

TEST_CASE("composite_span: runs of empty and full coverage at every offset and length match the per-pixel formula",
          "[composite]") {
    // Spans mostly made of runs of 0 and 255 with partial values between them, starting at every
    // offset and cut at every length, so that runs begin, end and straddle every multiple of eight.
    std::array<std::uint8_t, 80> coverage{};
    unsigned seed = 12345;
    auto next = [&] { return seed = seed * 1103515245u + 12345u, (seed >> 16) & 0x7fff; };
    for (std::size_t i = 0; i < coverage.size();) {
        const std::size_t run = 1 + next() % 17;
        const unsigned kind = next() % 3;
        for (std::size_t k = 0; k < run && i < coverage.size(); ++k, ++i)
            coverage[i] = static_cast<std::uint8_t>(kind == 0 ? 0 : kind == 1 ? 255 : 1 + next() % 254);
    }
    long wrong = 0, checked = 0;
    for (const Color& colour : {Color::rgba(10, 200, 30, 255), Color::rgba(10, 200, 30, 128)}) {
        const Paint paint = Paint::solid(colour);
        const Rgba s = premultiplied_source(colour, 1.0);
        const std::array<int, 4> d{20, 40, 60, 200};
        for (int offset = 0; offset < 9; ++offset)
            for (int length = 0; offset + length <= static_cast<int>(coverage.size()); ++length) {
                std::vector<std::uint8_t> px(4 * coverage.size());
                for (std::size_t i = 0; i < coverage.size(); ++i)
                    for (int k = 0; k < 4; ++k)
                        px[4 * i + static_cast<std::size_t>(k)] =
                            static_cast<std::uint8_t>(d[static_cast<std::size_t>(k)]);
                composite_span(px.data() + 4 * offset, length, coverage.data() + offset, paint);
                for (int i = 0; i < static_cast<int>(coverage.size()); ++i) {
                    const bool inside = i >= offset && i < offset + length;
                    const auto want = inside ? source_over(s, coverage[static_cast<std::size_t>(i)], d) : d;
                    const std::uint8_t* p = px.data() + 4 * i;
                    ++checked;
                    if (std::array<int, 4>{p[0], p[1], p[2], p[3]} != want) ++wrong;
                }
            }
    }
    INFO(wrong << " of " << checked << " pixels differ");
    CHECK(wrong == 0);
}

TEST_CASE(
    "blend_span source-over of a whole layer (no coverage): runs of transparent and opaque pixels at every offset",
    "[composite]") {
    // A layer as the SeamlessCompositor leaves it: runs of transparent pixels, of opaque ones and of
    // translucent ones, composited at every offset and length onto a translucent destination.
    constexpr std::size_t kPixels = 80;
    std::vector<std::uint8_t> layer(4 * kPixels);
    unsigned seed = 777;
    auto next = [&] { return seed = seed * 1103515245u + 12345u, (seed >> 16) & 0x7fff; };
    for (std::size_t i = 0; i < kPixels;) {
        const std::size_t run = 1 + next() % 19;
        const unsigned kind = next() % 3;
        for (std::size_t k = 0; k < run && i < kPixels; ++k, ++i) {
            const unsigned a = kind == 0 ? 0 : kind == 1 ? 255 : 1 + next() % 254;
            for (int c = 0; c < 3; ++c)
                layer[4 * i + static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(next() % (a + 1));
            layer[4 * i + 3] = static_cast<std::uint8_t>(a);
        }
    }
    const std::array<int, 4> d{20, 40, 60, 200};
    long wrong = 0, checked = 0;
    for (int offset = 0; offset < 9; ++offset)
        for (int length = 0; offset + length <= static_cast<int>(kPixels); ++length) {
            std::vector<std::uint8_t> px(4 * kPixels);
            for (std::size_t i = 0; i < kPixels; ++i)
                for (int k = 0; k < 4; ++k)
                    px[4 * i + static_cast<std::size_t>(k)] = static_cast<std::uint8_t>(d[static_cast<std::size_t>(k)]);
            blend_span(px.data() + 4 * offset, length, nullptr, layer.data() + 4 * offset, BlendMode::SourceOver);
            for (int i = 0; i < static_cast<int>(kPixels); ++i) {
                const std::uint8_t* s = layer.data() + 4 * i;
                const Rgba src{double(s[0]), double(s[1]), double(s[2]), double(s[3])};
                const bool inside = i >= offset && i < offset + length;
                const auto want = inside ? source_over(src, 255, d) : d;
                const std::uint8_t* p = px.data() + 4 * i;
                ++checked;
                if (std::array<int, 4>{p[0], p[1], p[2], p[3]} != want) ++wrong;
            }
        }
    INFO(wrong << " of " << checked << " pixels differ");
    CHECK(wrong == 0);
}

TEST_CASE("solid source-over: the float quotient is floor(t / 65025) for every t below 2^24", "[composite]") {
    long wrong = 0;
    for (std::int32_t t = 0; t < (1 << 24); ++t) {
        const auto q = static_cast<std::int32_t>(static_cast<float>(t) * paint_simd::kInv65025);
        wrong += q != t / 65025;
    }
    CHECK(wrong == 0);
}

TEST_CASE("solid source-over: every instruction set gives the scalar formula for every coverage and destination",
          "[composite]") {
    // Pixel i of the span has coverage i mod 256 and destination channels (i / 256) mod 256 with
    // alpha 255 - that: every (coverage, destination) pair once, in every lane position, and a
    // tail shorter than a vector at the end.
    constexpr int kLength = 65536 + 7;
    std::vector<std::uint8_t> coverage(kLength), start(4 * std::size_t{kLength});
    for (int i = 0; i < kLength; ++i) {
        const auto v = static_cast<std::uint8_t>((i >> 8) & 255);
        coverage[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i & 255);
        for (int k = 0; k < 3; ++k) start[4 * static_cast<std::size_t>(i) + static_cast<std::size_t>(k)] = v;
        start[4 * static_cast<std::size_t>(i) + 3] = static_cast<std::uint8_t>(255 - v);
    }
    const std::uint8_t colours[][4] = {{0, 0, 0, 0},         {0, 0, 0, 255},     {255, 255, 255, 255}, {1, 2, 3, 4},
                                       {127, 64, 0, 128},    {200, 10, 90, 200}, {254, 0, 253, 254},   {0, 255, 1, 255},
                                       {100, 100, 100, 101}, {3, 250, 7, 251}};
    for (std::int64_t target : simd::available_targets()) {
        simd::restrict_targets(target);
        long wrong = 0;
        for (const auto& s : colours) {
            std::vector<std::uint8_t> got = start, want = start;
            paint_simd::source_over_span(got.data(), kLength, coverage.data(), s, 0);
            for (int i = 0; i < kLength; ++i)
                if (coverage[static_cast<std::size_t>(i)] != 0)
                    pixel::source_over(want.data() + 4 * static_cast<std::size_t>(i), s,
                                       coverage[static_cast<std::size_t>(i)]);
            wrong += std::count_if(got.begin(), got.end(),
                                   [&, k = std::size_t{0}](std::uint8_t g) mutable { return g != want[k++]; });
        }
        INFO(simd::target_name(target) << ": " << wrong << " channels differ");
        CHECK(wrong == 0);
    }
    simd::restrict_targets(0);
}

TEST_CASE("source-over of per-pixel sources: every instruction set gives the scalar formula, with and without coverage",
          "[composite]") {
    // Sources cycle through alphas 0, 255 and values between (premultiplied: channels <= alpha),
    // coverage through every value, runs of empty and full pixels included; null coverage is full.
    constexpr int kLength = 4096 + 5;
    std::vector<std::uint8_t> coverage(kLength), src(4 * std::size_t{kLength}), start(4 * std::size_t{kLength});
    unsigned seed = 99;
    auto next = [&] { return seed = seed * 1103515245u + 12345u, (seed >> 16) & 0x7fff; };
    for (std::size_t i = 0; i < static_cast<std::size_t>(kLength); ++i) {
        const unsigned kind = (i / 16) % 4;  // whole vectors of transparent or opaque sources too
        const unsigned a = kind == 0 ? 0u : kind == 1 ? 255u : next() % 256;
        for (std::size_t k = 0; k < 3; ++k) src[4 * i + k] = static_cast<std::uint8_t>(a == 0 ? 0 : next() % (a + 1));
        src[4 * i + 3] = static_cast<std::uint8_t>(a);
        coverage[i] = static_cast<std::uint8_t>((i / 32) % 3 == 0 ? 255 : i % 256);
        for (std::size_t k = 0; k < 4; ++k) start[4 * i + k] = static_cast<std::uint8_t>(next() % 256);
    }
    for (std::int64_t target : simd::available_targets()) {
        simd::restrict_targets(target);
        long wrong = 0;
        for (const std::uint8_t* cov : std::array<const std::uint8_t*, 2>{coverage.data(), nullptr}) {
            std::vector<std::uint8_t> got = start, want = start;
            paint_simd::source_over_span(got.data(), kLength, cov, src.data(), 4);
            for (std::size_t i = 0; i < static_cast<std::size_t>(kLength); ++i)
                pixel::source_over(want.data() + 4 * i, src.data() + 4 * i, cov ? cov[i] : 255u);
            for (std::size_t k = 0; k < got.size(); ++k) wrong += got[k] != want[k];
        }
        INFO(simd::target_name(target) << ": " << wrong << " channels differ");
        CHECK(wrong == 0);
    }
    simd::restrict_targets(0);
}
