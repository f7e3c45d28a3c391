// round_stroke_mask against the exact-area reference: the union of round-joined, round-capped
// strokes (stroke() at a fine tolerance, then the slab reference of tests/support) on random
// polylines with short segments, sharp and reversing turns, repeated and overlapping copies,
// widths 0.1 to 20 px; the bound of casteljau/round_stroke.hpp on horizontal boundaries; bad input.
#include <catch2/catch.hpp>
#include "simd_targets.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/round_stroke.hpp"
#include "casteljau/stroke.hpp"

#include "reference_area.hpp"

using namespace casteljau;

namespace {

struct Error255 {
    double max = 0, sum = 0;
    std::size_t pixels = 0;
};

// The exact union of the round strokes of `lines` (width 2 r), as coverage in [0, 1].
ref::CoverageGrid reference(const std::vector<std::vector<Point>>& lines, double r, const IRect& clip) {
    Path p;
    for (const auto& l : lines) {
        p.move_to(l[0]);
        for (std::size_t i = 1; i < l.size(); ++i) p.line_to(l[i]);
    }
    StrokeStyle st;
    st.width = 2 * r;
    st.join = LineJoin::Round;
    st.cap = LineCap::Round;
    // Arcs within 1e-4 px of the circle: the reference is the union to well under 1/255.
    const Path outline = stroke(p, st, Affine{}, 1e-4);
    return ref::slab_area(ref::fine_flatten(outline, Affine{}), FillRule::NonZero, clip);
}

Error255 compare(const Mask& m, const ref::CoverageGrid& truth) {
    Error255 e;
    for (int y = m.bounds.y0; y < m.bounds.y1; ++y)
        for (int x = m.bounds.x0; x < m.bounds.x1; ++x) {
            const double d = std::abs(m.at(x, y) - 255 * truth.at(x, y));
            e.max = std::max(e.max, d);
            e.sum += d;
            ++e.pixels;
        }
    return e;
}

std::vector<LineSegment> segments_of(const std::vector<std::vector<Point>>& lines) {
    std::vector<LineSegment> segs;
    for (const auto& l : lines) {
        if (l.size() == 1) segs.push_back({l[0], l[0]});
        for (std::size_t i = 1; i < l.size(); ++i) segs.push_back({l[i - 1], l[i]});
    }
    return segs;
}

}  // namespace

TEST_CASE("round_stroke_mask: random thin polylines against the exact union", "[raster][round_stroke]") {
    std::mt19937 rng(41);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0, mean_worst = 0;
    for (int trial = 0; trial < 120; ++trial) {
        const double width = trial < 100 ? 0.1 + 2.4 * u(rng) * u(rng) : 2 + 18 * u(rng);
        const double r = width / 2;
        std::vector<std::vector<Point>> lines(1 + trial % 3);
        for (auto& l : lines) {
            Point p{4 + 16 * u(rng), 4 + 16 * u(rng)};
            double heading = 2 * kPi * u(rng);
            const int n = 2 + static_cast<int>(u(rng) * 40);
            l.push_back(p);
            for (int i = 0; i < n; ++i) {
                // Short steps (down to 0.01 px), sharp turns, and now and then a reversal.
                const double turn = u(rng) < 0.15 ? kPi : (u(rng) - 0.5) * 2.6;
                heading += turn;
                const double step = u(rng) < 0.5 ? 0.01 + 0.3 * u(rng) : 0.3 + 3 * u(rng);
                p = {std::clamp(p.x + step * std::cos(heading), 2.0, 22.0),
                     std::clamp(p.y + step * std::sin(heading), 2.0, 22.0)};
                l.push_back(p);
            }
        }
        const IRect clip{-20, -20, 45, 45};
        const Mask m = round_stroke_mask(segments_of(lines), r, clip);
        const Error255 e = compare(m, reference(lines, r, clip));
        INFO("trial " << trial << " width " << width << ": max " << e.max << "/255");
        CHECK(e.max <= 8.0);
        worst = std::max(worst, e.max);
        mean_worst = std::max(mean_worst, e.sum / static_cast<double>(e.pixels));
    }
    WARN("round strokes: worst pixel " << worst << "/255, worst mean " << mean_worst << "/255");
    CHECK(mean_worst <= 0.2);
}

TEST_CASE("round_stroke_mask: a horizontal line of 0.8 px at every phase stays within the bound",
          "[raster][round_stroke]") {
    // Both sides of the line run horizontally through one pixel row: 1/(2 lines) each at most.
    for (int k = 0; k < 64; ++k) {
        const double y = 5 + k / 64.0 + 0.003;
        const std::vector<std::vector<Point>> lines{{{2.2, y}, {14.7, y}}};
        const IRect clip{0, 0, 18, 10};
        const Mask m = round_stroke_mask(segments_of(lines), 0.4, clip);
        const Error255 e = compare(m, reference(lines, 0.4, clip));
        INFO("y " << y);
        CHECK(e.max <= 255.0 / kRoundStrokeLines + 0.5);  // both sides, and the rounding to 1/255
    }
}

TEST_CASE("round_stroke_mask: a disc, repeated segments and a clip cutting the stroke", "[raster][round_stroke]") {
    // A zero-length segment is a disc; ten copies of a segment cover what one covers.
    const std::vector<LineSegment> disc{{{5.3, 5.6}, {5.3, 5.6}}};
    const Mask d = round_stroke_mask(disc, 2.5, {0, 0, 11, 11});
    double area = 0;
    for (std::uint8_t v : d.data) area += v / 255.0;
    CHECK(std::abs(area - kPi * 2.5 * 2.5) < 0.05);
    const LineSegment s{{1.2, 3.3}, {9.7, 6.1}};
    const Mask one = round_stroke_mask(std::vector<LineSegment>{s}, 0.6, {0, 0, 12, 10});
    const Mask ten = round_stroke_mask(std::vector<LineSegment>(10, s), 0.6, {0, 0, 12, 10});
    CHECK(one.data == ten.data);
    // A clip that cuts the stroke gives the same pixels as the whole, inside it.
    const Mask part = round_stroke_mask(std::vector<LineSegment>{s}, 0.6, {3, 2, 7, 5});
    for (int y = 2; y < 5; ++y)
        for (int x = 3; x < 7; ++x) CHECK(part.at(x, y) == one.at(x, y));
}

TEST_CASE("round_stroke_spans: strokes far apart on a wide row, one reaching the right edge",
          "[raster][round_stroke]") {
    // Rows are handed out in runs of touched 64-pixel blocks: clusters with empty blocks between
    // them, a stroke across a block boundary and one ending past the clip's right edge must all
    // come out as the exact union, every run inside the clip, rows in order.
    const std::vector<std::vector<Point>> lines{{{3.3, 2.2}, {9.1, 7.6}},     {{60.2, 4.1}, {70.7, 5.3}},
                                                {{190.5, 3.4}, {191.2, 8.8}}, {{250.3, 1.6}, {300.0, 6.2}},
                                                {{127.6, 9.5}, {128.4, 9.5}}, {{40.0, 6.5}, {40.0, 6.5}}};
    const IRect clip{0, 0, 263, 12};
    struct Collect final : SpanSink {
        Mask mask;
        int last_y = -1, last_end = 0;
        bool ordered = true, inside = true;
        void row(int y, int x, int length, const std::uint8_t* coverage) override {
            ordered = ordered && (y > last_y || (y == last_y && x > last_end));
            inside = inside && length > 0 && x >= mask.bounds.x0 && x + length <= mask.bounds.x1 &&
                     y >= mask.bounds.y0 && y < mask.bounds.y1;
            if (!inside) return;
            last_y = y;
            last_end = x + length;
            std::copy(coverage, coverage + length,
                      mask.data.begin() + (y - mask.bounds.y0) * mask.bounds.width() + (x - mask.bounds.x0));
        }
    } sink;
    sink.mask.bounds = clip;
    sink.mask.data.assign(static_cast<std::size_t>(clip.width() * clip.height()), 0);
    round_stroke_spans(segments_of(lines), 0.7, clip, sink);
    CHECK(sink.ordered);
    CHECK(sink.inside);
    const Error255 e = compare(sink.mask, reference(lines, 0.7, clip));
    CHECK(e.max <= 8.0);
    CHECK(e.sum / static_cast<double>(e.pixels) <= 0.2);
    std::size_t touched = 0;
    for (std::uint8_t v : sink.mask.data) touched += v != 0;
    CHECK(touched > 100);
}

TEST_CASE("round_stroke_mask: bad input is an error", "[raster][round_stroke]") {
    const std::vector<LineSegment> ok{{{1, 1}, {5, 5}}};
    CHECK_THROWS_AS(round_stroke_mask(ok, 0, {0, 0, 8, 8}), Error);
    CHECK_THROWS_AS(round_stroke_mask(ok, NAN, {0, 0, 8, 8}), Error);
    CHECK_THROWS_AS(round_stroke_mask(ok, INFINITY, {0, 0, 8, 8}), Error);
    CHECK_THROWS_AS(round_stroke_mask(ok, 1, {0, 0, 8, 8}, 0), Error);
    CHECK_THROWS_AS(round_stroke_mask(ok, 1, {0, 0, 8, 8}, kMaxRoundStrokeLines + 1), Error);
    const std::vector<LineSegment> bad{{{1, NAN}, {5, 5}}};
    CHECK_THROWS_AS(round_stroke_mask(bad, 1, {0, 0, 8, 8}), Error);
    CHECK_THROWS_AS(round_stroke_mask(ok, 1, {0, 0, limits::kMaxCanvasDimension + 1, 8}), Error);
    CHECK(round_stroke_mask(ok, 1, {0, 0, 0, 0}).data.empty());
}

TEST_CASE("round_stroke_mask: long crossing segments give the same pixels in any order", "[raster][round_stroke]") {
    // Hundreds of long segments crossing every which way: each line's intervals arrive far from
    // sorted (the line's union is sorted and merged at the end), and it must not depend on their
    // order.
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 64);
    std::vector<LineSegment> segs;
    for (int i = 0; i < 400; ++i) segs.push_back({{u(rng), u(rng)}, {u(rng), u(rng)}});
    const Mask a = round_stroke_mask(segs, 0.3, {0, 0, 64, 64});
    std::reverse(segs.begin(), segs.end());
    const Mask b = round_stroke_mask(segs, 0.3, {0, 0, 64, 64});
    std::shuffle(segs.begin(), segs.end(), rng);
    const Mask c = round_stroke_mask(segs, 0.3, {0, 0, 64, 64});
    CHECK(a.data == b.data);
    CHECK(a.data == c.data);
    std::size_t full = 0;
    for (std::uint8_t v : a.data) full += v == 255;
    CHECK(full > 500);
}

TEST_CASE("round_stroke_mask: every SIMD target gives the same pixels", "[raster][round_stroke]") {
    // Sections are computed one line per lane; every target must give the scalar formula's values.
    // Vertical, horizontal and zero-length segments take the band's and the disc's special cases.
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(1, 39);
    std::vector<LineSegment> segs;
    for (int i = 0; i < 300; ++i) {
        const Point a{u(rng), u(rng)};
        const double len = i % 2 ? 0.05 * u(rng) : u(rng) / 3;
        switch (i % 5) {
            case 0: segs.push_back({a, {a.x, a.y + len}}); break;
            case 1: segs.push_back({a, {a.x + len, a.y}}); break;
            case 2: segs.push_back({a, a}); break;
            default: segs.push_back({a, {a.x + len * std::cos(i), a.y + len * std::sin(i)}}); break;
        }
    }
    // Every line count on every target, 64 (the default) first.
    const std::vector<std::uint8_t> first = test::same_bytes_on_every_target([&] {
        std::vector<std::uint8_t> all;
        for (int lines : {64, 1, 7, kMaxRoundStrokeLines}) {
            const Mask m = round_stroke_mask(segs, 0.45, {0, 0, 40, 40}, lines);
            all.insert(all.end(), m.data.begin(), m.data.end());
        }
        return all;
    });
    std::size_t covered = 0;
    for (std::size_t k = 0; k < 40 * 40; ++k) covered += first[k] > 0;
    CHECK(covered > 400);
}

TEST_CASE("round_stroke_mask: segments reaching far outside the clip", "[raster][round_stroke]") {
    // Segments from far away (coordinates of 1e7 px) cover the clip as their parts near it do:
    // only those parts are swept, in the clip's coordinates. One passing the clip by more than the
    // radius covers nothing.
    const IRect clip{-30, 20, 70, 60};
    const std::vector<LineSegment> far{{{-1e7, 31.3}, {1e7, 31.3}},
                                       {{-1e7, -1e7 + 0.37}, {1e7, 1e7 + 0.37}},
                                       {{25.6, -1e7}, {25.6, 1e7}},
                                       {{-1e7, 1e7}, {1e7, 1e7 - 15}}};
    // The same lines between points just outside the clip.
    const std::vector<LineSegment> near{
        {{-40, 31.3}, {80, 31.3}}, {{-50, -50 + 0.37}, {90, 90 + 0.37}}, {{25.6, 10}, {25.6, 70}}};
    for (double r : {0.4, 3.0}) {
        const Mask a = round_stroke_mask(far, r, clip);
        const Mask b = round_stroke_mask(near, r, clip);
        int worst = 0;
        for (std::size_t k = 0; k < a.data.size(); ++k) worst = std::max(worst, std::abs(a.data[k] - b.data[k]));
        INFO("radius " << r);
        CHECK(worst <= 1);
        std::size_t covered = 0;
        for (std::uint8_t v : a.data) covered += v > 0;
        CHECK(covered > 200);
    }
}

TEST_CASE("round_stroke_mask: a wide clip (double) and a narrow one (float) agree", "[raster][round_stroke]") {
    // Clips up to 8192 px per side are swept in float, wider ones in double: the same strokes
    // give the same pixels within the rounding of 1/255.
    std::mt19937 rng(17);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<LineSegment> segs;
    Point p{10, 10};
    for (int i = 0; i < 400; ++i) {
        const Point q{std::clamp(p.x + 6 * (u(rng) - 0.5), 1.0, 99.0), std::clamp(p.y + 6 * (u(rng) - 0.5), 1.0, 39.0)};
        segs.push_back({p, q});
        p = q;
    }
    for (double r : {0.25, 0.4, 1.7}) {
        const Mask narrow = round_stroke_mask(segs, r, {0, 0, 100, 40});
        const Mask wide = round_stroke_mask(segs, r, {0, 0, 9000, 40});
        int worst = 0;
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 100; ++x) worst = std::max(worst, std::abs(narrow.at(x, y) - wide.at(x, y)));
        INFO("radius " << r);
        CHECK(worst <= 1);
    }
}

TEST_CASE("round_stroke_mask: rows far down the image give the pixels of rows near the top", "[raster][round_stroke]") {
    // Heights are taken from each row's top: the same strokes 30,000 rows further down (nearly
    // horizontal segments, where a height error moves the section most) give the same pixels.
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<LineSegment> top, low;
    constexpr double kDown = 30000;
    for (int i = 0; i < 60; ++i) {
        const Point a{2 + 90 * u(rng), 2 + 26 * u(rng)};
        const Point b{std::clamp(a.x + 40 * (u(rng) - 0.5), 1.0, 99.0),
                      std::clamp(a.y + 2 * (u(rng) - 0.5), 1.0, 29.0)};
        top.push_back({a, b});
        low.push_back({{a.x, a.y + kDown}, {b.x, b.y + kDown}});
    }
    for (double r : {0.3, 0.8}) {
        const Mask a = round_stroke_mask(top, r, {0, 0, 100, 30});
        const Mask b = round_stroke_mask(low, r, {0, 30000, 100, 30030});
        int worst = 0;
        for (std::size_t k = 0; k < a.data.size(); ++k) worst = std::max(worst, std::abs(a.data[k] - b.data[k]));
        INFO("radius " << r);
        CHECK(worst <= 1);
    }
}

TEST_CASE("round_stroke_mask: long crossing segments against the exact union", "[raster][round_stroke]") {
    // Long segments crossing every which way: a capsule's section may reach back over intervals
    // that earlier capsules closed on its line, which then goes out of order; a closed interval
    // must not be settled while an interval kept out of order may still overlap it.
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> u(0, 1);
    double worst = 0;
    for (int trial = 0; trial < 60; ++trial) {
        std::vector<std::vector<Point>> lines;
        const int n = 8 + trial % 20;
        for (int i = 0; i < n; ++i)
            lines.push_back({{2 + 60 * u(rng), 2 + 60 * u(rng)}, {2 + 60 * u(rng), 2 + 60 * u(rng)}});
        const double r = 0.15 + 0.4 * u(rng);
        const IRect clip{0, 0, 64, 64};
        const Mask m = round_stroke_mask(segments_of(lines), r, clip);
        const Error255 e = compare(m, reference(lines, r, clip));
        INFO("trial " << trial << " radius " << r << ": max " << e.max << "/255");
        CHECK(e.max <= 8.0);
        worst = std::max(worst, e.max);
    }
    WARN("long crossing segments: worst pixel " << worst << "/255");
}

TEST_CASE("round_stroke_mask: a line's intervals out of order are never settled early", "[raster][round_stroke]") {
    // Ten long diagonals, all starting at x = 1 (so they come first), cross row 30 side by side
    // near x = 60; their intervals on its lines stay open to later capsules. A short vertical stroke
    // at x = 10 then reaches back over all of them (the lines' intervals go out of order), a short
    // horizontal stroke merges with the rightmost and spans two others, and a last vertical stroke
    // closes that interval: it must not be settled at once, or the points it shares with the two
    // diagonals count twice.
    std::vector<std::vector<Point>> lines;
    for (int i = 0; i < 10; ++i) {
        const Point p{60 + 0.8 * i, 30.5};
        const Point a{1, 10}, d = p - a;
        lines.push_back({a, a + d * (24.0 / 20.5)});
    }
    lines.push_back({{10, 28}, {10, 33}});
    lines.push_back({{65.5, 30.5}, {68, 30.5}});
    lines.push_back({{70, 28}, {70, 33}});
    const IRect clip{0, 8, 80, 38};
    const double r = 0.1;
    const Mask m = round_stroke_mask(segments_of(lines), r, clip);
    const Error255 e = compare(m, reference(lines, r, clip));
    INFO("max " << e.max << "/255");
    CHECK(e.max <= 8.0);
}
