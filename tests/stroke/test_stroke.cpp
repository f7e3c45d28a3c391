// Tests for stroking (include/casteljau/stroke.hpp); dashing is tested in test_dash.cpp.
//
// The outline is checked geometrically, without the rasterizer: signed areas of the output polygon
// (exact for strokes that do not overlap themselves), the nonzero winding number of the output at
// sample points against an independent reference built from the SVG definition (segment
// rectangles, join and cap pieces).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/stroke.hpp"
#include "reference_area.hpp"
#include "stroke_test_util.hpp"

using namespace casteljau;
using namespace stroke_test;

namespace {

// ---- Independent reference for the stroke region, from the SVG definition -------------------
// Convex pieces; each reports a conservative signed distance (positive inside): sd_in > 0 proves a
// point is inside the true stroke region AND inside the polygonal output (round parts shrunk by the
// tolerance, since the output's arcs are inscribed), sd_out < 0 proves a point is outside both.
struct Piece {
    std::vector<Point> poly;  // convex polygon, either orientation (empty: a disk sector)
    Point c{};                // disk sector: centre, radius, half-planes (p - c) . n >= 0
    double r = 0;
    std::vector<Vec> halfplanes;

    void sd(Point p, double tol, double& in, double& out) const {
        if (!poly.empty()) {
            double area = 0;
            for (std::size_t i = 0; i < poly.size(); ++i) area += poly[i].cross(poly[(i + 1) % poly.size()]);
            const double s = area >= 0 ? 1 : -1;
            double m = 1e300;
            for (std::size_t i = 0; i < poly.size(); ++i) {
                const Point a = poly[i], b = poly[(i + 1) % poly.size()];
                const double l = distance(a, b);
                if (l == 0) continue;
                m = std::min(m, s * (b - a).cross(p - a) / l);
            }
            if (std::abs(area) < 1e-12) m = -1e300;  // degenerate: covers nothing
            in = out = m;
            return;
        }
        double hp = 1e300;
        for (Vec n : halfplanes) hp = std::min(hp, (p - c).dot(n));
        const double d = distance(p, c);
        in = std::min(hp, r - tol - d);
        out = std::min(hp, r - d);
    }
};

Vec unit(Vec v) { return v / v.length(); }
Vec lperp(Vec d) { return {-d.y, d.x}; }

std::vector<Piece> reference_pieces(std::vector<Point> pts, bool closed, const StrokeStyle& st) {
    // Drop exact repeats (zero-length segments have no direction).
    std::vector<Point> q;
    for (Point p : pts)
        if (q.empty() || !(p == q.back())) q.push_back(p);
    if (closed)
        while (q.size() > 1 && q.back() == q.front()) q.pop_back();
    const double h = st.width / 2;
    std::vector<Piece> pieces;
    const std::size_t n = q.size(), nseg = closed ? n : n - 1;
    auto seg_dir = [&](std::size_t i) { return unit(q[(i + 1) % n] - q[i]); };
    for (std::size_t i = 0; i < nseg; ++i) {
        Point a = q[i], b = q[(i + 1) % n];
        const Vec d = seg_dir(i), nn = lperp(d);
        if (!closed && st.cap == LineCap::Square) {
            if (i == 0) a = a - d * h;
            if (i == nseg - 1) b = b + d * h;
        }
        pieces.push_back({{a + nn * h, b + nn * h, b - nn * h, a - nn * h}, {}, 0, {}});
    }
    if (!closed && st.cap == LineCap::Round) {
        const Vec d0 = seg_dir(0), dn = seg_dir(nseg - 1);
        pieces.push_back({{}, q[0], h, {-d0}});
        pieces.push_back({{}, q[n - 1], h, {dn}});
    }
    const double limit = std::max(1.0, st.miter_limit);
    for (std::size_t v = closed ? 0 : 1; v < (closed ? n : n - 1); ++v) {
        const Vec d1 = seg_dir((v + nseg - 1) % nseg), d2 = seg_dir(v);
        const double cr = d1.cross(d2), dt = d1.dot(d2);
        if (cr == 0 && dt > 0) continue;
        const double s = cr <= 0 ? 1 : -1;
        const Vec n1 = lperp(d1) * s, n2 = lperp(d2) * s;
        const Point V = q[v], A = V + n1 * h, B = V + n2 * h;
        const double alpha = kPi - std::atan2(std::abs(cr), dt);  // angle between the segments
        const bool miter_ok = alpha > 1e-9 && 1 / std::sin(alpha / 2) <= limit;
        switch (st.join) {
            case LineJoin::Round: pieces.push_back({{}, V, h, {d1, -d2}}); break;
            case LineJoin::Bevel: pieces.push_back({{V, A, B}, {}, 0, {}}); break;
            case LineJoin::Miter:
            case LineJoin::MiterClip: {
                // The miter tip is where the two outer edges meet.
                if (miter_ok) {
                    const double t = (B - A).cross(-d2) / d1.cross(-d2);
                    pieces.push_back({{V, A, A + d1 * t, B}, {}, 0, {}});
                } else if (st.join == LineJoin::MiterClip) {
                    const Vec bis = (n1 + n2).length() > 1e-12 ? unit(n1 + n2) : d1;
                    // Outer edges cut by the line (p - V) . bis = limit * h.
                    const double t1 = (limit * h - (A - V).dot(bis)) / d1.dot(bis);
                    const double t2 = (limit * h - (B - V).dot(bis)) / (-d2).dot(bis);
                    pieces.push_back({{V, A, A + d1 * t1, B - d2 * t2, B}, {}, 0, {}});
                } else {
                    pieces.push_back({{V, A, B}, {}, 0, {}});
                }
                break;
            }
        }
    }
    return pieces;
}

// Compares the winding of `out` at random points around the polyline with the reference.
// Returns the number of points checked (ambiguous points within `margin` of a boundary are skipped).
int check_against_reference(const Path& out, const std::vector<Point>& pts, bool closed, const StrokeStyle& st,
                            double tol, std::mt19937& rng, int samples) {
    const auto pieces = reference_pieces(pts, closed, st);
    Rect box{pts[0].x, pts[0].y, pts[0].x, pts[0].y};
    for (Point p : pts) box.include(p);
    const double pad = st.width * std::max(2.0, st.miter_limit);
    std::uniform_real_distribution<double> ux(box.x0 - pad, box.x1 + pad), uy(box.y0 - pad, box.y1 + pad);
    const double margin = 1e-7 * (1 + box.width() + box.height() + pad);
    int checked = 0;
    for (int i = 0; i < samples; ++i) {
        const Point p{ux(rng), uy(rng)};
        double in = -1e300, outd = -1e300;
        for (const Piece& pc : pieces) {
            double a, b;
            pc.sd(p, tol, a, b);
            in = std::max(in, a);
            outd = std::max(outd, b);
        }
        if (in > margin) {
            INFO("point " << p.x << "," << p.y << " must be inside");
            REQUIRE(inside(out, p));
            ++checked;
        } else if (outd < -margin) {
            INFO("point " << p.x << "," << p.y << " must be outside");
            REQUIRE_FALSE(inside(out, p));
            ++checked;
        }
    }
    return checked;
}

}  // namespace

TEST_CASE("stroke: horizontal line areas for butt, square and round caps", "[stroke]") {
    const Path p = line({10, 10}, {110, 10});
    CHECK(std::abs(signed_area(stroke(p, style(4, LineCap::Butt)))) == Approx(400).margin(1e-9));
    CHECK(std::abs(signed_area(stroke(p, style(4, LineCap::Square)))) == Approx(416).margin(1e-9));
    // Round caps: the two half disks, inscribed polygons whose sagitta is below the tolerance, so
    // the missing area is at most perimeter x tolerance = 2 pi r x 0.05.
    const double round = std::abs(signed_area(stroke(p, style(4, LineCap::Round))));
    CHECK(round <= 400 + kPi * 4 + 1e-9);
    CHECK(round >= 400 + kPi * 4 - 2 * kPi * 2 * 0.05);
    // The butt stroke is the rectangle itself.
    const Path b = stroke(p, style(4));
    CHECK(inside(b, {10.01, 8.01}));
    CHECK(inside(b, {109.99, 11.99}));
    CHECK_FALSE(inside(b, {9.99, 10}));
    CHECK_FALSE(inside(b, {60, 12.01}));
}

TEST_CASE("stroke: closed square gives outer minus inner, no caps", "[stroke]") {
    Path p;
    p.add_rect({0, 0, 100, 100});
    // Miter corners: 110^2 - 90^2; caps must not matter on a closed contour.
    for (LineCap cap : {LineCap::Butt, LineCap::Square, LineCap::Round}) {
        CHECK(std::abs(signed_area(stroke(p, style(10, cap, LineJoin::Miter)))) == Approx(4000).margin(1e-9));
    }
    // Bevel: each outer corner loses a right triangle with legs 5.
    CHECK(std::abs(signed_area(stroke(p, style(10, LineCap::Butt, LineJoin::Bevel)))) ==
          Approx(4000 - 4 * 12.5).margin(1e-9));
    // Round: each outer corner loses 25 - pi 25 / 4 (up to the arc tolerance).
    const double round = std::abs(signed_area(stroke(p, style(10, LineCap::Butt, LineJoin::Round))));
    CHECK(round == Approx(4000 - 4 * (25 - kPi * 25 / 4)).margin(2 * kPi * 5 * 0.05));
    // The same square drawn with an explicit closing segment back to the start.
    Path q;
    q.move_to(0, 0).line_to(100, 0).line_to(100, 100).line_to(0, 100).line_to(0, 0).close();
    CHECK(std::abs(signed_area(stroke(q, style(10)))) == Approx(4000).margin(1e-9));
    // Both orientations give the same sign (all pieces are oriented alike).
    CHECK(signed_area(stroke(p, style(10))) == Approx(signed_area(stroke(p.reversed(), style(10)))));
    // Hole in the middle, ring around.
    const Path s = stroke(p, style(10));
    CHECK_FALSE(inside(s, {50, 50}));
    CHECK(inside(s, {50, 4.9}));
    CHECK(inside(s, {-4.9, -4.9}));
    CHECK_FALSE(inside(s, {50, 5.1}));
}

TEST_CASE("stroke: right-angle joins add the exact corner", "[stroke]") {
    Path p;
    p.move_to(0, 0).line_to(100, 0).line_to(100, 100);
    // Rectangles 1000 + 1000 overlap in a 5 x 5 square: 1975, plus the outer corner piece.
    CHECK(std::abs(signed_area(stroke(p, style(10, LineCap::Butt, LineJoin::Miter)))) == Approx(2000).margin(1e-9));
    CHECK(std::abs(signed_area(stroke(p, style(10, LineCap::Butt, LineJoin::Bevel)))) == Approx(1987.5).margin(1e-9));
    const double round = std::abs(signed_area(stroke(p, style(10, LineCap::Butt, LineJoin::Round))));
    CHECK(round <= 1975 + kPi * 25 / 4 + 1e-9);
    CHECK(round >= 1975 + kPi * 25 / 4 - kPi / 2 * 5 * 0.05);
    // The miter corner's tip is covered, and nothing beyond it.
    const Path m = stroke(p, style(10));
    CHECK(inside(m, {104.9, -4.9}));
    CHECK_FALSE(inside(m, {105.1, -4.9}));
    CHECK_FALSE(inside(stroke(p, style(10, LineCap::Butt, LineJoin::Bevel)), {104.9, -4.9}));
}

TEST_CASE("stroke: miter limit switches to bevel at 1/sin(alpha/2)", "[stroke]") {
    Path right;
    right.move_to(0, 0).line_to(100, 0).line_to(100, 100);
    // Right angle: miter length / width = sqrt(2) = 1.41421...
    CHECK(std::abs(signed_area(stroke(right, style(10, LineCap::Butt, LineJoin::Miter, 1.414)))) == Approx(1987.5));
    CHECK(std::abs(signed_area(stroke(right, style(10, LineCap::Butt, LineJoin::Miter, 1.415)))) == Approx(2000));
    // 60 degrees between the segments: ratio 1 / sin(30 deg) = 2.
    Path sharp;
    const Point v{100, 0};
    sharp.move_to(0, 0).line_to(v).line_to(v + Vec{-std::cos(kPi / 3), std::sin(kPi / 3)} * 100);
    const Path below = stroke(sharp, style(10, LineCap::Butt, LineJoin::Miter, 1.99));
    const Path above = stroke(sharp, style(10, LineCap::Butt, LineJoin::Miter, 2.01));
    // The miter tip lies on the outer bisector at distance ratio x h = 2 x 5 = 10 from the vertex.
    const Vec bis = unit(Vec{1, 0} + unit(Vec{-std::cos(kPi / 3), std::sin(kPi / 3)}) * -1);
    CHECK(inside(above, v + bis * 9.9));
    CHECK_FALSE(inside(above, v + bis * 10.1));
    CHECK_FALSE(inside(below, v + bis * 5.1));
    // Exact areas: the miter adds a kite of area h^2 / tan(alpha / 2) = 25 sqrt(3) beyond the
    // overlap-free part; the bevel adds the triangle V, A, B of area h^2 sin(pi - alpha) / 2.
    const double diff = std::abs(signed_area(above)) - std::abs(signed_area(below));
    const double kite = 25 / std::tan(kPi / 6), tri = 25 * std::sin(2 * kPi / 3) / 2;
    CHECK(diff == Approx(kite - tri));
}

TEST_CASE("stroke: miter-clip cuts the miter at miter_limit x width / 2", "[stroke]") {
    Path p;
    p.move_to(0, 0).line_to(100, 0).line_to(100, 100);
    // limit 1 on a right angle: bevel area + h^2/2 - h^2 (sqrt 2 - 1)^2.
    const double expect = 1987.5 + 12.5 - 25 * (std::sqrt(2.0) - 1) * (std::sqrt(2.0) - 1);
    CHECK(std::abs(signed_area(stroke(p, style(10, LineCap::Butt, LineJoin::MiterClip, 1)))) == Approx(expect));
    // Below the limit it is a plain miter.
    CHECK(std::abs(signed_area(stroke(p, style(10, LineCap::Butt, LineJoin::MiterClip, 4)))) == Approx(2000));
}

TEST_CASE("stroke: 180-degree turns", "[stroke]") {
    Path p;
    p.move_to(0, 0).line_to(50, 0).line_to(20, 0);
    const Path round = stroke(p, style(10, LineCap::Butt, LineJoin::Round));
    CHECK(inside(round, {54.8, 0}));
    CHECK(inside(round, {52, 3}));
    CHECK_FALSE(inside(round, {55.1, 0}));
    CHECK(inside(round, {25, 4.9}));
    CHECK(inside(round, {1, -4.9}));
    // Miter falls back to bevel: nothing beyond the vertex.
    const Path miter = stroke(p, style(10));
    CHECK_FALSE(inside(miter, {50.1, 0}));
    CHECK(inside(miter, {49.9, 4.9}));
    // Miter-clip extends straight ahead by miter_limit x h.
    const Path clip = stroke(p, style(10, LineCap::Butt, LineJoin::MiterClip, 2));
    CHECK(inside(clip, {59.9, 4.9}));
    CHECK_FALSE(inside(clip, {60.1, 0}));
}

TEST_CASE("stroke: zero-length subpaths draw dots with round and square caps", "[stroke]") {
    Path closed;
    closed.move_to(50, 50).close();
    Path degenerate;
    degenerate.move_to(50, 50).line_to(50, 50);
    for (const Path* p : {&closed, &degenerate}) {
        const double disk = std::abs(signed_area(stroke(*p, style(10, LineCap::Round))));
        CHECK(disk <= kPi * 25);
        CHECK(disk >= kPi * 25 - 2 * kPi * 5 * 0.05);
        CHECK(std::abs(signed_area(stroke(*p, style(10, LineCap::Square)))) == Approx(100));
        CHECK(stroke(*p, style(10, LineCap::Butt)).empty());
        // The square is aligned with the x axis.
        const Path sq = stroke(*p, style(10, LineCap::Square));
        CHECK(inside(sq, {54.9, 54.9}));
        CHECK_FALSE(inside(sq, {55.1, 50}));
    }
    Path lone;
    lone.move_to(50, 50);
    CHECK(stroke(lone, style(10, LineCap::Round)).empty());
    // Degenerate segments are skipped for direction: the square cap follows the real segment.
    Path p;
    p.move_to(0, 0).line_to(0, 0).line_to(100, 0).line_to(100, 0);
    CHECK(std::abs(signed_area(stroke(p, style(4, LineCap::Square)))) == Approx(416));
}

TEST_CASE("stroke: width <= 0 gives nothing, bad input throws", "[stroke]") {
    const Path p = line({0, 0}, {10, 10});
    CHECK(stroke(p, style(0)).empty());
    CHECK(stroke(p, style(-3)).empty());
    CHECK(stroke(Path{}, style(3)).empty());

    Path nan = line({0, 0}, {std::nan(""), 1});
    try {
        (void)stroke(nan, style(1));
        FAIL("no error for NaN");
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::InvalidData); }
    auto kind_of = [](auto&& f) {
        try {
            f();
        } catch (const Error& e) { return static_cast<int>(e.kind()); }
        return -1;
    };
    const double inf = std::numeric_limits<double>::infinity();
    CHECK(kind_of([&] { (void)stroke(p, style(1), Affine{inf, 0, 0, 1, 0, 0}); }) == int(ErrorKind::InvalidData));
    CHECK(kind_of([&] { (void)stroke(p, style(inf)); }) == int(ErrorKind::InvalidData));
    CHECK(kind_of([&] { (void)stroke(p, style(1, LineCap::Butt, LineJoin::Miter, std::nan(""))); }) ==
          int(ErrorKind::InvalidData));
    CHECK(kind_of([&] { (void)stroke(p, style(1), {}, 0); }) == int(ErrorKind::InvalidArgument));
    CHECK(kind_of([&] { (void)stroke(p, style(1), {}, -1); }) == int(ErrorKind::InvalidArgument));
    StrokeStyle s = style(1);
    s.dashes = {1, std::nan("")};
    CHECK(kind_of([&] { (void)stroke(p, s); }) == int(ErrorKind::InvalidData));
    s.dashes = {1, 1};
    s.dash_offset = inf;
    CHECK(kind_of([&] { (void)stroke(p, s); }) == int(ErrorKind::InvalidData));
    const double d[] = {1, inf};
    CHECK(kind_of([&] { (void)dash(p, d, 0); }) == int(ErrorKind::InvalidData));
    // Too many dashes for the limit.
    const double tiny[] = {1e-6, 1e-6};
    CHECK(kind_of([&] { (void)dash(line({0, 0}, {1e6, 0}), tiny, 0); }) == int(ErrorKind::Limit));
}

TEST_CASE("stroke: hostile but finite inputs finish with finite output or a clear error", "[stroke]") {
    auto all_finite = [](const Path& p) {
        for (Point q : p.points())
            if (!q.is_finite()) return false;
        return true;
    };
    Path c;
    c.add_circle({0, 0}, 50);
    c.move_to(0, 0).cubic_to({100, 100}, {-100, 100}, {0, 0});  // a loop with a cusp-like end
    c.move_to(5, 5).close();
    for (LineCap cap : {LineCap::Butt, LineCap::Round, LineCap::Square}) {
        for (LineJoin join : {LineJoin::Miter, LineJoin::MiterClip, LineJoin::Round, LineJoin::Bevel}) {
            StrokeStyle st = style(3, cap, join, 0.5);  // limit below 1: treated as 1
            CHECK(all_finite(stroke(c, st, Affine::scale(1e-300))));
            CHECK(all_finite(stroke(c, st, Affine{0, 0, 0, 0, 0, 0})));  // singular transform
            st.dashes = {7, 3, 0};
            st.dash_offset = -1e300;
            CHECK(all_finite(stroke(c, st)));
            CHECK(all_finite(stroke(c.transformed(Affine::scale(1e14)), style(1e14, cap, join), Affine::scale(1e-14))));
        }
    }
    // A tolerance far below double precision: the flattening depth limit and the arc step limit
    // (65536 steps per turn) bound the work.
    CHECK(all_finite(stroke(c, style(3, LineCap::Round, LineJoin::Round), {}, 1e-300)));
    try {
        const Path huge = stroke(line({0, 0}, {1, 1}), style(1e308, LineCap::Round, LineJoin::Miter));
        CHECK(all_finite(huge));
    } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Limit); }
}

TEST_CASE("stroke: curves are flattened in user space with tolerance / max_scale", "[stroke]") {
    Path c;
    c.add_circle({0, 0}, 50);
    // Annulus 50 +- 5: area pi (55^2 - 45^2) = 1000 pi, the circle itself flattened.
    const double a1 = std::abs(signed_area(stroke(c, style(10))));
    CHECK(a1 == Approx(1000 * kPi).epsilon(2e-3));
    // A 20x zoom needs a finer outline: more points, closer area, still in user space.
    const Path fine = stroke(c, style(10), Affine::scale(20));
    CHECK(contours_of(fine)[0].pts.size() > 3 * contours_of(stroke(c, style(10)))[0].pts.size());
    CHECK(std::abs(signed_area(fine)) == Approx(1000 * kPi).epsilon(5e-4));
    // A non-uniform transform only changes the tolerance (the pen stays circular in user space:
    // elliptical after the transform), so the user-space outline is still the annulus.
    const Path ell = stroke(c, style(10), Affine::scale(1, 20));
    CHECK(std::abs(signed_area(ell)) == Approx(1000 * kPi).epsilon(5e-4));
    CHECK(inside(ell, {0, 54.5}));
    CHECK(inside(ell, {54.5, 0}));
    CHECK_FALSE(inside(ell, {0, 55.5}));
    CHECK_FALSE(inside(ell, {44.5, 0}));
}

TEST_CASE("stroke: points near the centre line are inside, points far away outside (circle)", "[stroke]") {
    Path c;
    c.add_circle({100, 100}, 50);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> ang(0, 2 * kPi), rad(30, 70);
    const Path s = stroke(c, style(8, LineCap::Butt, LineJoin::Round));
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const double a = ang(rng), r = rad(rng);
        const Point p{100 + r * std::cos(a), 100 + r * std::sin(a)};
        // Cubic circle radial error (2.7e-4 r) + flattening tolerance 0.05.
        const double slack = 50 * 2.8e-4 + 0.05 + 1e-9;
        if (std::abs(r - 50) < 4 - slack) {
            CHECK(inside(s, p));
            ++checked;
        } else if (std::abs(r - 50) > 4 + slack) {
            CHECK_FALSE(inside(s, p));
            ++checked;
        }
    }
    CHECK(checked > 1900);
}

TEST_CASE("stroke: random polylines agree with the reference region at sample points", "[stroke]") {
    std::mt19937 rng(20240611);
    std::uniform_real_distribution<double> coord(0, 100), wdist(0.5, 25), u01(0, 1);
    const LineCap caps[] = {LineCap::Butt, LineCap::Round, LineCap::Square};
    const LineJoin joins[] = {LineJoin::Miter, LineJoin::MiterClip, LineJoin::Round, LineJoin::Bevel};
    int total = 0;
    for (int iter = 0; iter < 300; ++iter) {
        const int n = 2 + static_cast<int>(u01(rng) * 7);
        std::vector<Point> pts;
        for (int i = 0; i < n; ++i) {
            const double r = u01(rng);
            if (i > 0 && r < 0.1) {
                pts.push_back(pts.back());  // zero-length segment
            } else if (i > 1 && r < 0.2) {
                pts.push_back(lerp(pts[i - 2], pts[i - 1], 0.3));  // a 180-degree turn
            } else if (i > 1 && r < 0.25) {
                pts.push_back(pts[i - 1] + (pts[i - 1] - pts[i - 2]) * 0.5);  // straight on
            } else if (i > 0 && r < 0.4) {
                const double a = u01(rng) * 2 * kPi, l = 0.01 + 2 * u01(rng);  // a short segment
                pts.push_back(pts[i - 1] + Vec{std::cos(a), std::sin(a)} * l);
            } else {
                pts.push_back({coord(rng), coord(rng)});
            }
        }
        // Skip degenerate polylines (all points equal); they are tested separately.
        if (std::all_of(pts.begin(), pts.end(), [&](Point p) { return p == pts[0]; })) continue;
        const bool closed = u01(rng) < 0.3;
        StrokeStyle st = style(wdist(rng), caps[iter % 3], joins[(iter / 3) % 4], 1 + u01(rng) * 5);
        Path path;
        path.add_polygon(pts, closed);
        const double tol = 0.05;
        const Path out = stroke(path, st, {}, tol);
        INFO("iteration " << iter << " closed " << closed << " width " << st.width << " cap " << int(st.cap) << " join "
                          << int(st.join) << " limit " << st.miter_limit);
        total += check_against_reference(out, pts, closed, st, tol, rng, 200);
    }
    CHECK(total > 40000);
}

namespace {

// The reference pieces as polygons, counter-clockwise: convex polygons as they are, disc sectors
// cut from a circle of 4096 sides by their half-planes (through the centre). Their union under
// nonzero is the stroke region, to 1e-6 of the radius.
ref::Contours piece_polygons(const std::vector<Piece>& pieces) {
    ref::Contours out;
    for (const Piece& pc : pieces) {
        ref::Contour poly = pc.poly;
        if (poly.empty()) {
            constexpr int kSides = 4096;
            for (int i = 0; i < kSides; ++i) {
                const double a = 2 * kPi * i / kSides;
                poly.push_back(pc.c + Vec{std::cos(a), std::sin(a)} * pc.r);
            }
            for (Vec n : pc.halfplanes) {  // keep (p - c) . n >= 0 (Sutherland-Hodgman)
                ref::Contour cut;
                for (std::size_t i = 0; i < poly.size(); ++i) {
                    const Point a = poly[i], b = poly[(i + 1) % poly.size()];
                    const double da = (a - pc.c).dot(n), db = (b - pc.c).dot(n);
                    if (da >= 0) cut.push_back(a);
                    if ((da >= 0) != (db >= 0)) cut.push_back(a + (b - a) * (da / (da - db)));
                }
                poly = std::move(cut);
            }
        }
        if (poly.size() < 3) continue;
        if (ref::signed_area(poly) < 0) std::reverse(poly.begin(), poly.end());
        out.push_back(std::move(poly));
    }
    return out;
}

}  // namespace

TEST_CASE("stroke: rasterized strokes of random polylines against the exact area of the reference region", "[stroke]") {
    // Every join and cap, widths 0.1 to 20 px, short segments, sharp and reversing turns: the
    // outline (flattened at 0.01 px) filled with its interior capsules, as a canvas fills it, against
    // the exact area of the union of the definition's pieces in every pixel.
    std::mt19937 rng(20261130);
    std::uniform_real_distribution<double> u(0, 1);
    const LineCap caps[] = {LineCap::Butt, LineCap::Round, LineCap::Square};
    const LineJoin joins[] = {LineJoin::Miter, LineJoin::MiterClip, LineJoin::Round, LineJoin::Bevel};
    Rasterizer raster;
    double worst = 0, worst_mean = 0;
    for (int iter = 0; iter < 120; ++iter) {
        std::vector<Point> pts{{10 + 20 * u(rng), 10 + 20 * u(rng)}};
        const int n = 2 + static_cast<int>(u(rng) * 10);
        for (int i = 1; i < n; ++i) {
            const double r = u(rng);
            if (i > 1 && r < 0.15) {
                pts.push_back(lerp(pts[i - 2], pts[i - 1], 0.3));  // a reversal
            } else if (r < 0.5) {
                const double a = 2 * kPi * u(rng), l = 0.05 + 1.5 * u(rng);  // a short segment
                pts.push_back(pts[i - 1] + Vec{std::cos(a), std::sin(a)} * l);
            } else {
                pts.push_back({10 + 20 * u(rng), 10 + 20 * u(rng)});
            }
        }
        if (std::all_of(pts.begin(), pts.end(), [&](Point p) { return p == pts[0]; })) continue;
        const bool closed = u(rng) < 0.25;
        const double width = 0.1 + 19.9 * u(rng) * u(rng);
        const StrokeStyle st = style(width, caps[iter % 3], joins[(iter / 3) % 4], 1 + 4 * u(rng));
        Path path;
        path.add_polygon(pts, closed);
        const StrokeOutline so = stroke_outline(path, st, {}, 0.01);
        FillOptions fo;
        fo.inside = so.inside;
        const IRect clip{-30, -30, 70, 70};
        const Mask m = raster.fill_mask(so.outline, Affine{}, fo, clip);
        const ref::CoverageGrid truth =
            ref::slab_area(piece_polygons(reference_pieces(pts, closed, st)), FillRule::NonZero, clip);
        double max = 0, sum = 0;
        for (int y = clip.y0; y < clip.y1; ++y)
            for (int x = clip.x0; x < clip.x1; ++x) {
                const double d = std::abs(m.at(x, y) - 255 * truth.at(x, y));
                max = std::max(max, d);
                sum += d;
            }
        const double mean = sum / (clip.width() * clip.height());
        INFO("iteration " << iter << " closed " << closed << " width " << width << " cap " << int(st.cap) << " join "
                          << int(st.join) << ": max " << max << "/255, mean " << mean);
        CHECK(max <= 3.0);
        worst = std::max(worst, max);
        worst_mean = std::max(worst_mean, mean);
    }
    WARN("strokes against the exact area: worst pixel " << worst << "/255, worst mean " << worst_mean << "/255");
    CHECK(worst_mean <= 0.2);
}

TEST_CASE("stroke: a self-overlapping stroke still fills its union under nonzero", "[stroke]") {
    // A zig-zag with short segments and a wide pen: the inner joins go through the pivots.
    std::vector<Point> pts;
    for (int i = 0; i < 20; ++i) pts.push_back({i * 3.0, (i % 2) * 4.0});
    Path p;
    p.add_polygon(pts, false);
    std::mt19937 rng(3);
    for (LineJoin j : {LineJoin::Miter, LineJoin::Round, LineJoin::Bevel})
        CHECK(check_against_reference(stroke(p, style(12, LineCap::Round, j)), pts, false, style(12, LineCap::Round, j),
                                      0.05, rng, 3000) > 2500);
}

TEST_CASE("stroke: inner join goes through the pivot when the next segment is short", "[stroke]") {
    // Regression guard: the triangle (end of segment 1, vertex, start of segment 2) on the inner
    // side is covered only by the first segment's rectangle here; skipping the vertex on the inner
    // side would cut it out.
    Path p;
    p.move_to(0, 0).line_to(100, 0).line_to(100, 0.5);
    for (LineJoin j : {LineJoin::Miter, LineJoin::Round, LineJoin::Bevel}) {
        const Path s = stroke(p, style(10, LineCap::Butt, j));
        CHECK(inside(s, {99, 3}));
        CHECK(inside(s, {96, 0.5}));
        CHECK_FALSE(inside(s, {99, 5.1}));
    }
}

TEST_CASE("stroke: small closed polygon under a wide pen has no hole", "[stroke]") {
    // Equilateral triangle of side 9 under a pen of radius 5: every point of the triangle is within
    // 5 of a side. Skipping the pivots on the inner side at all three corners would subtract the
    // centre three times from the three rectangles that cover it.
    for (double side : {9.0, 12.0, 17.0, 20.0}) {
        const Point a{0, 0}, b{side, 0}, c{side / 2, side * std::sqrt(3.0) / 2};
        const Point pts[] = {a, b, c};
        Path p;
        p.add_polygon(pts, true);
        const Point centre = (a + b + c) / 3;
        const double inradius = side / (2 * std::sqrt(3.0));
        for (LineJoin j : {LineJoin::Miter, LineJoin::Bevel, LineJoin::Round}) {
            INFO("side " << side);
            CHECK(inside(stroke(p, style(10, LineCap::Butt, j)), centre) == (inradius < 5));
        }
    }
}

TEST_CASE("stroke: a small pentagram under a wide pen keeps its centre", "[stroke]") {
    // A five-pointed star {5/2} turns the same way at every point (twice round in all), so it is
    // not outlined as a convex contour. With edge 16 and a pen of radius 5, each inner shortcut's
    // reach (5 tan 72 deg = 15.4) fits in its two edges, and the centre lies inside all five quads
    // the shortcuts would cut out, as it lies inside all five edge rectangles (0.16 x 16 = 2.6
    // from each edge line): five shortcuts would leave it with winding 0. The two joins at the
    // ends of the first edge share its length, so one of them goes through its pivot.
    const double edge = 16, radius = edge / (2 * std::sin(0.4 * kPi));
    std::vector<Point> pts;
    for (int k = 0; k < 5; ++k) {
        const double a = 0.5 * kPi + k * 0.8 * kPi;
        pts.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
    Path p;
    p.add_polygon(pts, true);
    for (LineJoin j : {LineJoin::Miter, LineJoin::Bevel, LineJoin::Round}) {
        const StrokeStyle st = style(10, LineCap::Butt, j);
        const Path s = stroke(p, st);
        CHECK(inside(s, {0, 0}));
        std::mt19937 rng(5);
        CHECK(check_against_reference(s, pts, true, st, 0.05, rng, 2000) > 1500);
    }
}

TEST_CASE("stroke: inner shortcuts within each segment's shared length keep the union", "[stroke]") {
    // Small non-convex closed polygons and polylines under wide pens: inner shortcuts whose reach
    // takes most of a segment at one end and the pivot route at the other, against the union of
    // the pieces at sample points.
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> u(0, 1);
    int checked = 0;
    for (int iter = 0; iter < 400; ++iter) {
        std::vector<Point> pts;
        const int n = 4 + iter % 5;
        for (int i = 0; i < n; ++i) {
            const double a = 2 * kPi * i / n, r = (i % 2 ? 2.0 : 5.0) * (0.7 + 0.6 * u(rng));
            pts.push_back({r * std::cos(a), r * std::sin(a)});
        }
        const bool closed = iter % 3 != 0;
        const StrokeStyle st = style(4 + 10 * u(rng), LineCap::Butt, iter % 2 ? LineJoin::Round : LineJoin::Bevel);
        Path p;
        p.add_polygon(pts, closed);
        INFO("iteration " << iter << " width " << st.width);
        checked += check_against_reference(stroke(p, st, {}, 0.05), pts, closed, st, 0.05, rng, 300);
    }
    CHECK(checked > 60000);
}

TEST_CASE("stroke: rasterized overlapping outline matches the supersampled reference region", "[stroke]") {
    // The whole pipeline: stroke -> nonzero fill with exact overlaps. The zig-zag's pieces overlap
    // heavily (inner joins through the pivots); coverage must still be the union's area per pixel.
    std::vector<Point> pts;
    for (int i = 0; i < 12; ++i) pts.push_back({4.3 + i * 3.1, 10.2 + (i % 2) * 5.3});
    Path p;
    p.add_polygon(pts, false);
    for (LineJoin j : {LineJoin::Miter, LineJoin::Round}) {
        const StrokeStyle st = style(7, LineCap::Square, j);
        const auto pieces = reference_pieces(pts, false, st);
        Rasterizer r;
        const Mask m = r.fill_mask(stroke(p, st), Affine{});
        REQUIRE(!m.bounds.empty());
        constexpr int kSub = 16;
        double sum_err = 0, max_err = 0;
        int n = 0;
        for (int y = m.bounds.y0 - 1; y < m.bounds.y1 + 1; ++y) {
            for (int x = m.bounds.x0 - 1; x < m.bounds.x1 + 1; ++x) {
                int hits = 0;
                for (int sy = 0; sy < kSub; ++sy)
                    for (int sx = 0; sx < kSub; ++sx) {
                        const Point q{x + (sx + 0.5) / kSub, y + (sy + 0.5) / kSub};
                        bool in = false;
                        for (const Piece& pc : pieces) {
                            double a, b;
                            pc.sd(q, 0, a, b);
                            if (b >= 0) {
                                in = true;
                                break;
                            }
                        }
                        hits += in;
                    }
                const double err = std::abs(m.at(x, y) / 255.0 - hits / double(kSub * kSub));
                sum_err += err;
                max_err = std::max(max_err, err);
                ++n;
            }
        }
        INFO("join " << int(j) << " mean " << sum_err / n * 255 << "/255 max " << max_err * 255 << "/255");
        // Supersampling error on boundary pixels, plus for round joins the arc tolerance (inscribed
        // polygons lose up to 0.05 px of width along an arc).
        const double arc = j == LineJoin::Round ? 0.05 : 0;
        CHECK(sum_err / n < 0.5 / 255 + arc / 10);
        CHECK(max_err < 8.0 / 255 + arc);
    }
}

TEST_CASE("parse_line_cap and parse_line_join read the SVG names and refuse others", "[stroke]") {
    LineCap cap = LineCap::Butt;
    CHECK(parse_line_cap("round", cap));
    CHECK(cap == LineCap::Round);
    CHECK(parse_line_cap("square", cap));
    CHECK(cap == LineCap::Square);
    CHECK(parse_line_cap("butt", cap));
    CHECK(cap == LineCap::Butt);
    CHECK_FALSE(parse_line_cap("Round", cap));
    CHECK_FALSE(parse_line_cap("", cap));
    CHECK(cap == LineCap::Butt);  // unchanged by a refused name
    LineJoin join = LineJoin::Round;
    const std::pair<const char*, LineJoin> joins[] = {{"miter", LineJoin::Miter},
                                                      {"miter-clip", LineJoin::MiterClip},
                                                      {"round", LineJoin::Round},
                                                      {"bevel", LineJoin::Bevel}};
    for (const auto& [name, want] : joins) {
        INFO(name);
        CHECK(parse_line_join(name, join));
        CHECK(join == want);
    }
    CHECK_FALSE(parse_line_join("arcs", join));
    CHECK(join == LineJoin::Bevel);
}

TEST_CASE("regression: round joins at a huge width stop at the path size limit, not after gigabytes",
          "[stroke][regression]") {
    // At a width of 1e12 against a 0.05 px tolerance every round join takes up to 32,768 arc
    // points (the cap of 65,536 per turn), so a 2000-segment zig-zag would grow one contour's sides
    // to a 2 GiB vector if the size limit were checked only at its end. It is checked as the sides
    // grow (fuzz/regressions/stroke/round-joins-at-huge-width-* fails the replay's 1 GiB
    // allocation limit without that).
    Path p;
    p.move_to(0, 0);
    for (int i = 1; i <= 2000; ++i) p.line_to(i * 0.5, (i & 1) * 3.0);
    StrokeStyle st;
    st.width = 1e12;
    st.join = LineJoin::Round;
    try {
        (void)stroke(p, st, Affine{}, 0.05);
        FAIL("the outline was made");
    } catch (const Error& e) {
        CHECK(e.kind() == ErrorKind::Limit);
        CHECK_THAT(e.what(), Catch::Contains("path size limit"));
    }
    // The same path at an ordinary width strokes.
    st.width = 2;
    CHECK_FALSE(stroke(p, st, Affine{}, 0.05).empty());
}

TEST_CASE("regression: round joins and caps of segments whose length overflows end in Error(Limit), without a NaN arc",
          "[stroke][regression]") {
    // fuzz_stroke (UBSan): directions of segments longer than the double range are NaN, and the
    // join's arc converted NaN pieces to int (undefined behaviour; the sanitizer build aborts).
    for (double b : {1e308, 1.7e308})
        for (LineJoin join : {LineJoin::Round, LineJoin::Miter, LineJoin::Bevel})
            for (LineCap cap : {LineCap::Round, LineCap::Butt, LineCap::Square}) {
                Path p;
                p.move_to({0, 0});
                p.line_to({b, 0});
                p.line_to({-b, b});
                p.line_to({b, -b});
                StrokeStyle st;
                st.width = 2;
                st.join = join;
                st.cap = cap;
                try {
                    (void)stroke(p, st);
                    FAIL("no error");
                } catch (const Error& e) { CHECK(e.kind() == ErrorKind::Limit); }
            }
}

namespace {

std::size_t move_count(const Path& p) {
    return static_cast<std::size_t>(std::count(p.verbs().begin(), p.verbs().end(), Verb::Move));
}

// Largest |difference| between two masks over the union of their bounds, in 1/255.
int mask_difference(const Mask& a, const Mask& b) {
    const IRect u{std::min(a.bounds.x0, b.bounds.x0), std::min(a.bounds.y0, b.bounds.y0),
                  std::max(a.bounds.x1, b.bounds.x1), std::max(a.bounds.y1, b.bounds.y1)};
    auto at = [](const Mask& m, int x, int y) -> int {
        if (x < m.bounds.x0 || x >= m.bounds.x1 || y < m.bounds.y0 || y >= m.bounds.y1) return 0;
        return m.data[static_cast<std::size_t>(y - m.bounds.y0) * static_cast<std::size_t>(m.bounds.width()) +
                      static_cast<std::size_t>(x - m.bounds.x0)];
    };
    int worst = 0;
    for (int y = u.y0; y < u.y1; ++y)
        for (int x = u.x0; x < u.x1; ++x) worst = std::max(worst, std::abs(at(a, x, y) - at(b, x, y)));
    return worst;
}

}  // namespace

TEST_CASE("stroke: a convex closed contour with no room for a hole is outlined by its outer side alone", "[stroke]") {
    // A circle of radius 4 stroked 8 wide (an icon's dot): the inner side would only pivot through
    // the centre, over area the outer side covers, and make the centre pixels exact cells.
    Rasterizer r;
    StrokeStyle st;
    st.width = 8;
    for (LineJoin join : {LineJoin::Round, LineJoin::Miter, LineJoin::Bevel}) {
        st.join = join;
        Path dot;
        dot.add_circle({20.3, 20.6}, 4);
        const Path out = stroke(dot, st, Affine{}, 0.01);
        INFO("join " << static_cast<int>(join));
        CHECK(move_count(out) == 1);
        if (join == LineJoin::Round) {
            // The stroke of a circle of radius 4 and half-width 4 is the disk of radius 8. The
            // outline stays within the tolerance (0.01 px) of its circle on either side, which
            // moves a pixel's coverage by at most 0.01 x sqrt(2) x 255 < 4 (the disk itself is
            // flattened 100 times finer).
            Path disk;
            disk.add_circle({20.3, 20.6}, 8);
            FillOptions fine;
            fine.tolerance = 1e-4;
            CHECK(mask_difference(r.fill_mask(out, Affine{}), r.fill_mask(disk, Affine{}, fine)) <= 3);
        }
    }
    // A rounded rectangle 3 high stroked 4 wide: no hole either.
    Path bar;
    bar.add_round_rect(Rect::from_xywh(2, 2, 30, 3), 1, 1);
    CHECK(move_count(stroke(bar, st)) == 1);

    // Room for a hole (radius 5 at half-width 4: a hole of radius 1): both sides stay, and the
    // centre pixel is empty.
    st.join = LineJoin::Round;
    Path ring;
    ring.add_circle({20.5, 20.5}, 5);
    st.width = 8;
    const Path out = stroke(ring, st, Affine{}, 0.01);
    CHECK(move_count(out) == 2);
    const Mask m = r.fill_mask(out, Affine{});
    CHECK(m.data[static_cast<std::size_t>(20 - m.bounds.y0) * static_cast<std::size_t>(m.bounds.width()) +
                 static_cast<std::size_t>(20 - m.bounds.x0)] == 0);
    // A concave contour keeps its inner side whatever the width.
    Path l;
    l.move_to({0, 0});
    l.line_to({10, 0});
    l.line_to({10, 3});
    l.line_to({3, 3});
    l.line_to({3, 10});
    l.line_to({0, 10});
    l.close();
    st.width = 20;
    CHECK(move_count(stroke(l, st)) == 2);
}
