// Strokes of curves: the sweep of the curve's normal, against coverage worked out by hand.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "casteljau/raster.hpp"
#include "casteljau/stroke.hpp"
#include "stroke_test_util.hpp"

using namespace casteljau;
using namespace stroke_test;

namespace {

// A quarter circle of radius r about (cx, cy), from angle 0 to 90 degrees (y down: from
// (cx + r, cy) to (cx, cy + r)), as one cubic.
Path quarter_arc(double cx, double cy, double r) {
    const double k = 0.5522847498 * r;
    Path p;
    p.move_to(cx + r, cy);
    p.cubic_to({cx + r, cy + k}, {cx + k, cy + r}, {cx, cy + r});
    return p;
}

Mask fill(const Path& outline) {
    Rasterizer r;
    return r.fill_mask(outline, Affine{}, FillOptions{});
}

// Coverage of pixel (x, y) by `in`, from 64 x 64 samples.
int sampled(const std::function<bool(double, double)>& in, int x, int y) {
    int n = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) n += in(x + (i + 0.5) / 64, y + (j + 0.5) / 64);
    return static_cast<int>(std::lround(n * 255.0 / 4096));
}

}  // namespace

TEST_CASE("stroke: a bend tighter than the pen covers the far side of its centre", "[stroke]") {
    // A quarter circle of radius 2 under a pen 16 wide. Its normals all pass through the centre C
    // and reach 8 on either side of the curve: the stroke is the quarter disk of radius 10 on the
    // curve's side of C and, past C, the opposite quarter disk of radius 6. Chord rectangles alone
    // cover that far quarter as a comb (about a third of each pixel).
    const double cx = 50, cy = 50;
    auto in = [&](double x, double y) {
        const double dx = x - cx, dy = y - cy, d2 = dx * dx + dy * dy;
        return (dx >= 0 && dy >= 0 && d2 <= 100) || (dx <= 0 && dy <= 0 && d2 <= 36);
    };
    for (double tol : {0.05, 0.015}) {
        const Mask m = fill(stroke(quarter_arc(cx, cy, 2), style(16, LineCap::Butt, LineJoin::Miter), {}, tol));
        int worst = 0;
        double sum = 0;
        for (int y = 38; y < 62; ++y)
            for (int x = 38; x < 62; ++x) {
                const int d = std::abs(m.at(x, y) - sampled(in, x, y));
                worst = std::max(worst, d);
                sum += d;
            }
        INFO("tolerance " << tol << ": mean " << sum / 576 << ", max " << worst);
        // Pixels well inside the far quarter are covered.
        CHECK(m.at(46, 46) == 255);
        CHECK(m.at(45, 47) == 255);
        // The polyline's normals turn about its vertices, not about C: near C and the ends the
        // stroke is off by a sliver about as wide as a chord's half turn times the radius,
        // sqrt(2 tol r), which shrinks with the tolerance.
        CHECK(sum / 576 < 1.5);
        CHECK(worst <= 255 * std::sqrt(2 * tol * 2));
    }
}

TEST_CASE("stroke: caps stand square to the curve, not to its last chord", "[stroke]") {
    // A quarter circle of radius 50 about (100, 100), pen 20 wide, flattened coarsely (0.5): the
    // chords turn by about 0.28 rad, so a cap square to the last chord would lean by 0.14 rad and
    // move its corners by 1.4 px. The curve ends at (100, 150) heading along -x and starts at
    // (150, 100) heading along +y: the caps lie on the lines x = 100 and y = 100.
    const Mask m = fill(stroke(quarter_arc(100, 100, 50), style(20), {}, 0.5));
    for (int k = 142; k < 158; ++k) {
        INFO("row or column " << k);
        CHECK(m.at(99, k) == 0);     // beyond the end
        CHECK(m.at(100, k) >= 250);  // the first column of the stroke
        CHECK(m.at(k, 99) == 0);     // before the start
        CHECK(m.at(k, 100) >= 250);
    }
}

TEST_CASE("stroke: a line drawn as a cubic with control points on its ends strokes as the line", "[stroke]") {
    Path curve;
    curve.move_to(20, 160);
    curve.cubic_to({20.0001, 160}, {160, 20}, {160.0001, 20});
    const StrokeStyle st = style(20);
    const Mask a = fill(stroke(curve, st, {}, 0.05)), b = fill(stroke(line({20, 160}, {160.0001, 20}), st, {}, 0.05));
    int worst = 0;
    for (int y = 0; y < 190; ++y)
        for (int x = 0; x < 190; ++x) worst = std::max(worst, std::abs(a.at(x, y) - b.at(x, y)));
    CHECK(worst <= 2);
}

TEST_CASE("stroke: where curves meet with one tangent the join style does not matter", "[stroke]") {
    // A circle of radius 30 as four cubics, open (caps at its start), pen 40 wide, coarse chords:
    // at the three junctions the chords turn as they do inside each cubic, and the stroke turns
    // with the curve there as well, whatever the join.
    const double cx = 60, cy = 60, r = 30, k = 0.5522847498 * r;
    Path p;
    p.move_to(cx + r, cy);
    p.cubic_to({cx + r, cy + k}, {cx + k, cy + r}, {cx, cy + r});
    p.cubic_to({cx - k, cy + r}, {cx - r, cy + k}, {cx - r, cy});
    p.cubic_to({cx - r, cy - k}, {cx - k, cy - r}, {cx, cy - r});
    p.cubic_to({cx + k, cy - r}, {cx + r, cy - k}, {cx + r, cy - 0.5});
    const Mask round = fill(stroke(p, style(40, LineCap::Butt, LineJoin::Round), {}, 0.5));
    for (LineJoin j : {LineJoin::Bevel, LineJoin::Miter}) {
        const Mask other = fill(stroke(p, style(40, LineCap::Butt, j), {}, 0.5));
        int worst = 0;
        for (int y = 0; y < 130; ++y)
            for (int x = 0; x < 130; ++x) worst = std::max(worst, std::abs(round.at(x, y) - other.at(x, y)));
        CHECK(worst == 0);
    }
}

TEST_CASE("stroke: dashes are measured along the curve, not its chords", "[stroke]") {
    // A circle of radius 20 about the origin as four cubics, flattened coarsely (0.5): its chords
    // are about 0.8 % shorter than the arcs they stand for. With dashes of an eighth of the
    // circumference each, on and off, the dashes start at 0, 90, 180 and 270 degrees; measured
    // along the chords they would drift by about 2 degrees by the last one. Points inside a chord
    // lie on it, off the arc by up to 0.1 degree here. (The contour is closed
    // and the pattern off where it wraps, so there are four dashes.)
    const double r = 20, k = 0.5522847498 * r, quarter = 0.5 * kPi * r;
    Path p;
    p.move_to(r, 0);
    p.cubic_to({r, k}, {k, r}, {0, r});
    p.cubic_to({-k, r}, {-r, k}, {-r, 0});
    p.cubic_to({-r, -k}, {-k, -r}, {0, -r});
    p.cubic_to({k, -r}, {r, -k}, {r, 0});
    p.close();
    const std::vector<double> pattern = {quarter / 2, quarter / 2};
    const Path d = dash(p, pattern, 0, {}, 0.5);
    std::vector<double> starts;
    for (std::size_t i = 0, pi = 0; i < d.verbs().size(); ++i) {
        if (d.verbs()[i] == Verb::Move) {
            const double a = std::atan2(d.points()[pi].y, d.points()[pi].x) * 180 / kPi;
            starts.push_back(a < -1 ? a + 360 : a);
        }
        if (d.verbs()[i] != Verb::Close) ++pi;
    }
    REQUIRE(starts.size() == 4);
    std::sort(starts.begin(), starts.end());
    for (std::size_t i = 0; i < 4; ++i) {
        const double expected = 90.0 * static_cast<double>(i);
        INFO("dash " << i << " starts at " << starts[i] << " degrees");
        CHECK(std::abs(starts[i] - expected) < 0.25);
    }
}
