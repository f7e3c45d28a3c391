// Tests for dashing (dash() and StrokeStyle::dashes, include/casteljau/stroke.hpp): the pattern's
// normalisation, the "on" length along lines, corners, closed contours and circles against a sum
// of interval overlaps worked out here, offsets, zero-length dashes, and the dash count limit.
#include <catch2/catch.hpp>

#include <cmath>
#include <span>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/stroke.hpp"
#include "stroke_test_util.hpp"

using namespace casteljau;
using namespace stroke_test;

namespace {}  // namespace

TEST_CASE("dash: pattern normalisation (odd counts, zero and negative values)", "[stroke]") {
    const Path p = line({0, 0}, {100, 0});
    const double odd[] = {10};
    const auto d = contours_of(dash(p, odd, 0));
    REQUIRE(d.size() == 5);  // 10 on, 10 off
    CHECK(d[1].pts.front().x == Approx(20));
    CHECK(d[1].pts.back().x == Approx(30));
    const double three[] = {3, 1, 2};  // becomes 3 1 2 3 1 2: period 12
    CHECK(total_length(dash(p, three, 0)) == Approx(expected_on_length({3, 1, 2}, 0, 100)));
    // No dashing: the path itself, and the same outline as a solid stroke.
    const double zeros[] = {0, 0}, neg[] = {5, -1};
    for (std::span<const double> pat : {std::span<const double>(zeros), std::span<const double>(neg)}) {
        const auto c = contours_of(dash(p, pat, 0));
        REQUIRE(c.size() == 1);
        CHECK(polyline_length(c[0]) == Approx(100));
        StrokeStyle s = style(4);
        s.dashes.assign(pat.begin(), pat.end());
        CHECK(stroke(p, s) == stroke(p, style(4)));
    }
}

TEST_CASE("dash: total on length along a line, positive and negative offsets", "[stroke]") {
    const Path p = line({10, 10}, {110, 10});
    const std::vector<std::vector<double>> patterns = {{10, 5}, {7, 3, 1, 4}, {2.5}, {0.5, 9}, {30, 1}};
    for (const auto& pat : patterns) {
        for (double off : {0.0, 3.0, 12.5, -4.0, -27.3, 1000.7}) {
            INFO("pattern[0] " << pat[0] << " offset " << off);
            CHECK(total_length(dash(p, pat, off)) == Approx(expected_on_length(pat, off, 100)).margin(1e-9));
            // Stroked with butt caps, the area is on-length x width.
            StrokeStyle s = style(2);
            s.dashes = pat;
            s.dash_offset = off;
            CHECK(std::abs(signed_area(stroke(p, s))) == Approx(2 * expected_on_length(pat, off, 100)).margin(1e-9));
        }
    }
    // The offset shifts the pattern backwards along the path: offset 3 starts 3 into the first dash.
    const double pat[] = {10, 5};
    const auto c = contours_of(dash(p, pat, 3));
    CHECK(c[0].pts.back().x == Approx(17));
    CHECK(c[1].pts.front().x == Approx(22));
    const auto n = contours_of(dash(p, pat, -3));  // starts in the gap, 3 before the next dash
    CHECK(n[0].pts.front().x == Approx(13));
}

TEST_CASE("dash: the offset is taken modulo the period, negative offsets and offsets past the pattern", "[stroke]") {
    // Pattern 6 on, 4 off (period 10) along a line from x = 0 to 100. With offset o the path starts
    // o into the pattern, so dashes begin at x = 10k - o (mod 10) and last 6.
    const Path p = line({0, 0}, {100, 0});
    const double pat[] = {6, 4};
    auto starts = [&](double off) {
        std::vector<double> xs;
        for (const Contour& c : contours_of(dash(p, pat, off))) xs.push_back(c.pts.front().x);
        return xs;
    };
    // Independent expectation: with m = offset mod 10 in [0, 10) the path starts m into the
    // pattern: inside a dash when m < 6 (a piece starts at x = 0), and whole dashes start at
    // x = 10 - m, 20 - m, ...
    auto expected_starts = [](double off) {
        double m = std::fmod(off, 10.0);
        if (m < 0) m += 10;
        std::vector<double> xs;
        if (m < 6) xs.push_back(0);
        for (double x = 10 - m; x < 100; x += 10) xs.push_back(x);
        return xs;
    };
    for (double off : {0.0, 3.0, 6.0, 7.0, 10.0, 13.0, 1003.0, -3.0, -13.0, -1007.0, -6.5}) {
        INFO("offset " << off);
        const auto got = starts(off);
        const auto want = expected_starts(off);
        REQUIRE(got.size() == want.size());
        for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(want[i]).margin(1e-9));
        // Offsets one period apart give the same dashes.
        CHECK(total_length(dash(p, pat, off)) == Approx(total_length(dash(p, pat, off + 10))).margin(1e-9));
    }
    // Offset 3: the first piece is the rest of the first dash, 3 long; offset -3: 3 of gap first,
    // so the path starts inside the gap and the first dash is whole.
    CHECK(contours_of(dash(p, pat, 3))[0].pts.back().x == Approx(3));
    CHECK(contours_of(dash(p, pat, -3))[0].pts.front().x == Approx(3));
    CHECK(contours_of(dash(p, pat, -3))[0].pts.back().x == Approx(9));
}

TEST_CASE("dash: dashes continue across segments and restart per subpath", "[stroke]") {
    Path p;
    p.move_to(0, 0).line_to(10, 0).line_to(10, 10).line_to(30, 10);  // length 40
    p.move_to(0, 50).line_to(40, 50);                                // length 40
    const double pat[] = {6, 4};
    const Path d = dash(p, pat, 0);
    CHECK(total_length(d) == Approx(2 * expected_on_length({6, 4}, 0, 40)));
    const auto c = contours_of(d);
    // The second dash (10..16 along the path) starts exactly at the corner (10, 0).
    REQUIRE(c.size() == 8);
    CHECK(c[1].pts.front() == Point(10, 0));
    CHECK(c[1].pts.back().x == Approx(10));
    CHECK(c[1].pts.back().y == Approx(6));
    // The second subpath restarts the pattern.
    CHECK(c[4].pts.front() == Point(0, 50));
    CHECK(c[4].pts.back().x == Approx(6));
    // A dash across a corner keeps the corner point.
    const double pat2[] = {5, 2};  // second dash 7..12 along the path
    const auto c2 = contours_of(dash(p, pat2, 0));
    REQUIRE(c2[1].pts.size() == 3);
    CHECK(c2[1].pts[1] == Point(10, 0));
}

TEST_CASE("dash: closed contours join the last and first dash at the wrap", "[stroke]") {
    Path sq;
    sq.add_rect({0, 0, 100, 100});  // perimeter 400
    // Period 30: 400 = 13 x 30 + 10, so the pattern is still "on" at the wrap: 14 starts, 13 dashes.
    const double on_wrap[] = {20, 10};
    const auto c = contours_of(dash(sq, on_wrap, 0));
    CHECK(c.size() == 13);
    CHECK(total_length(dash(sq, on_wrap, 0)) == Approx(expected_on_length({20, 10}, 0, 400)));
    // The joined dash runs from 390 through the corner (0, 0) to 20.
    bool found = false;
    for (const auto& k : c)
        if (k.pts.front() == Point(0, 10) && k.pts.back() == Point(20, 0)) found = k.pts.size() == 3;
    CHECK(found);
    for (const auto& k : c) CHECK_FALSE(k.closed);
    // "Off" at the wrap: 400 = 10 x 40, dash pattern 25 on 15 off: 10 separate dashes.
    const double off_wrap[] = {25, 15};
    CHECK(contours_of(dash(sq, off_wrap, 0)).size() == 10);
    // A pattern on all the way round keeps the contour closed: no caps, the same outline as solid.
    const double long_on[] = {1000, 10};
    const auto whole = contours_of(dash(sq, long_on, 0));
    REQUIRE(whole.size() == 1);
    CHECK(whole[0].closed);
    StrokeStyle s = style(10);
    s.dashes = {1000, 10};
    CHECK(std::abs(signed_area(stroke(sq, s))) == Approx(4000));
}

TEST_CASE("dash: a dash pattern on a circle", "[stroke]") {
    Path c;
    c.add_circle({0, 0}, 50);
    const double pat[] = {15, 5};
    const Path d = dash(c, pat, 0);
    const double perim = 2 * kPi * 50;  // 314.16 = 15 x 20 + 14.16: "on" at the wrap
    const auto k = contours_of(d);
    CHECK(k.size() == 15);
    CHECK(total_length(d) == Approx(expected_on_length({15, 5}, 0, perim)).epsilon(1e-3));
    for (const auto& dash_c : k)
        for (Point p : dash_c.pts) CHECK(p.length() == Approx(50).margin(0.07));
    // Stroked with butt caps, the area is on length x width up to the curvature of the dashes
    // (an annular sector of mean radius 50 has exactly that area).
    StrokeStyle s = style(4);
    s.dashes = {15, 5};
    CHECK(std::abs(signed_area(stroke(c, s))) == Approx(4 * expected_on_length({15, 5}, 0, perim)).epsilon(2e-3));
}

TEST_CASE("dash: zero-length dashes become dots or squares along the path", "[stroke]") {
    const Path p = line({0, 0}, {95, 0});
    StrokeStyle s = style(4, LineCap::Round);
    s.dashes = {0, 10};
    const Path dots = stroke(p, s);
    CHECK(contours_of(dots).size() == 10);
    const double area = std::abs(signed_area(dots));
    CHECK(area <= 10 * kPi * 4);
    CHECK(area >= 10 * (kPi * 4 - 2 * kPi * 2 * 0.05));
    s.cap = LineCap::Butt;
    CHECK(stroke(p, s).empty());
    // Square caps of zero-length dashes follow the path direction (here 45 degrees).
    Path diag;
    diag.move_to(0, 0).line_to(100, 100);
    StrokeStyle sq = style(4, LineCap::Square);
    sq.dashes = {0, 1000};
    const Path squares = stroke(diag, sq);
    CHECK(std::abs(signed_area(squares)) == Approx(16));
    CHECK(inside(squares, {2.6, 0}));          // along/across 1.84: inside the rotated square
    CHECK_FALSE(inside(squares, {1.9, 1.9}));  // along 2.69: outside it (inside an axis-aligned one)
}

TEST_CASE("regression: a dash pattern too fine for its path is refused before any dash is made",
          "[stroke][regression]") {
    // A 2000-segment path with a dash pattern of tiny values would make millions of dashes, each
    // stroked and filled, past the fuzzer's 10 s timeout. Limits::dashes (2^18 dashes per path by
    // default) is checked before dashing.
    Path p;
    p.move_to(0, 0);
    for (int i = 1; i <= 2000; ++i) p.line_to(i * 0.5, (i & 1) * 3.0);
    const double pattern[] = {1e-3, 1e-3};
    CHECK_THROWS_AS(dash(p, pattern, 0), Error);
    const double fine[] = {1, 1};
    CHECK_NOTHROW(dash(p, fine, 0));
}
