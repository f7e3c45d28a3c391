// Golden images of the curve pictures (golden/curves/*.png): a Bézier with its de Casteljau
// construction, a B-spline with its knots, basis functions, a surface grid and the clock. Each
// picture is first checked independently in the same test (pixels where the mathematics puts the
// curve, the markers, the hands are drawn in the right colour; pixels far from everything are
// background), then compared with its golden file.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "../examples/clock_face.hpp"
#include "casteljau/figures.hpp"
#include "casteljau/spline.hpp"
#include "casteljau/surface.hpp"
#include "curves_golden.hpp"

using namespace casteljau;

namespace {

constexpr int kGoldenMax = 8;
constexpr double kGoldenMean = 0.25;

Color at(const Pixmap& p, Point q) {
    const int x = std::clamp(static_cast<int>(std::floor(q.x)), 0, p.width() - 1);
    const int y = std::clamp(static_cast<int>(std::floor(q.y)), 0, p.height() - 1);
    return unpremultiply(p.pixel(x, y));
}

int color_distance(Color a, Color b) {
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
}

// The closest match to `want` among the 3 x 3 pixels around q (thin lines cover no single pixel fully).
int near_distance(const Pixmap& p, Point q, Color want) {
    int best = 255;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) best = std::min(best, color_distance(at(p, {q.x + dx, q.y + dy}), want));
    return best;
}

bool is_background(Color c) { return color_distance(c, figure_colors::kBackground) == 0; }

double segment_distance(Point p, Point a, Point b) {
    const Point ab = b - a;
    const double len2 = ab.dot(ab);
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return distance(p, a + ab * t);
}

// Distance (pixels) from p to the nearest of the given pixel-space polylines.
double polyline_distance(Point p, const std::vector<std::vector<Point>>& lines) {
    double d = std::numeric_limits<double>::infinity();
    for (const auto& l : lines) {
        if (l.size() == 1) d = std::min(d, distance(p, l[0]));
        for (std::size_t i = 1; i < l.size(); ++i) d = std::min(d, segment_distance(p, l[i - 1], l[i]));
    }
    return d;
}

// Every 3rd pixel farther than `clearance` from all `lines` must be background; returns how many
// were checked (so a test can require that the check covered something).
int check_far_pixels_background(const Pixmap& img, const std::vector<std::vector<Point>>& lines, double clearance) {
    int checked = 0, bad = 0;
    for (int y = 1; y < img.height(); y += 3)
        for (int x = 1; x < img.width(); x += 3) {
            const Point c{x + 0.5, y + 0.5};
            if (polyline_distance(c, lines) <= clearance) continue;
            ++checked;
            if (!is_background(at(img, c))) {
                if (bad++ < 5) UNSCOPED_INFO("pixel (" << x << ", " << y << ") far from the drawing is not background");
            }
        }
    CHECK(bad == 0);
    return checked;
}

std::vector<Point> sample_curve(const Bezier<Point>& c, const Affine& m, int n) {
    std::vector<Point> out;
    for (int i = 0; i <= n; ++i) out.push_back(m.apply(c.eval(static_cast<double>(i) / n)));
    return out;
}

std::vector<Point> mapped(std::span<const Point> pts, const Affine& m) {
    std::vector<Point> out;
    for (const Point& p : pts) out.push_back(m.apply(p));
    return out;
}

}  // namespace

TEST_CASE("Golden: Bezier cubic with its de Casteljau construction at t = 0.4", "[curves-render][golden]") {
    const Bezier<Point> curve{{0, 0}, {48, 96}, {120, 120}, {216, 72}};
    const double t = 0.4;
    const Figure f = draw_bezier_figure(curve, {}, t);
    const Pixmap& img = f.image;
    const Affine& m = f.transform;
    REQUIRE(img.width() == 400);
    REQUIRE(img.height() == 400);

    // The fit: the control box centred, 24 px margin on its long side.
    CHECK(m.apply({0, 0}).x == Approx(24));
    CHECK(m.apply({216, 0}).x == Approx(376));
    CHECK((m.apply({0, 0}).y + m.apply({0, 120}).y) / 2 == Approx(200));

    // P(t) (the textbook's 69.12, 80.64) carries the highlight.
    const Point pt = m.apply(curve.eval(t));
    CHECK(curve.eval(t).x == Approx(69.12));
    CHECK(color_distance(at(img, pt), figure_colors::kHighlight) <= 8);
    // The curve is dark along its length (away from the markers drawn over it).
    const auto rows = curve.triangle(t);
    std::vector<Point> markers;
    for (const auto& row : rows)
        for (const Point& p : row) markers.push_back(m.apply(p));
    int dark = 0, samples = 0;
    for (int i = 1; i < 40; ++i) {
        const double s = i / 40.0;
        const Point q = m.apply(curve.eval(s));
        bool near_marker = false;
        for (const Point& k : markers) near_marker |= distance(q, k) < 8;
        if (near_marker) continue;
        ++samples;
        dark += color_distance(at(img, q), figure_colors::kCurve) <= 40;
    }
    CHECK(samples > 30);
    CHECK(dark == samples);
    // Control points carry the marker colour at their centres.
    for (const Point& p : curve.points()) CHECK(color_distance(at(img, m.apply(p)), figure_colors::kControlPoint) <= 8);
    // Level-1 construction points carry their level's colour.
    for (const Point& p : rows[1]) CHECK(color_distance(at(img, m.apply(p)), construction_color(1, 2)) <= 8);
    // Far from the curve, the polygon and the construction: background.
    std::vector<std::vector<Point>> lines{sample_curve(curve, m, 400), mapped(curve.points(), m)};
    for (std::size_t r = 1; r < rows.size(); ++r) lines.push_back(mapped(rows[r], m));
    CHECK(check_far_pixels_background(img, lines, 8) > 10000);

    curves_test::check_golden("curves", "bezier-construction", img, kGoldenMax, kGoldenMean);
}

TEST_CASE("Golden: cubic B-spline with control polygon and knots", "[curves-render][golden]") {
    const BSpline<Point> s =
        BSpline<Point>::clamped(3, {{0, 60}, {40, 0}, {90, 20}, {120, 90}, {170, 100}, {200, 30}, {240, 50}});
    const auto pieces = s.to_bezier();
    std::vector<Point> knots;
    for (double u : s.breakpoints()) knots.push_back(s.eval(u));
    REQUIRE(knots.size() == 5);
    const Figure f = draw_spline_figure(to_path(pieces), s.points(), knots, {});
    const Pixmap& img = f.image;
    const Affine& m = f.transform;

    for (const Point& k : knots) CHECK(color_distance(at(img, m.apply(k)), figure_colors::kKnot) <= 8);
    int dark = 0, samples = 0;
    std::vector<Point> curve_px;
    for (int i = 0; i <= 400; ++i) {
        const double u = s.domain_start() + (s.domain_end() - s.domain_start()) * i / 400.0;
        const Point q = m.apply(s.eval(u));
        curve_px.push_back(q);
        bool near_marker = false;
        for (const Point& k : knots) near_marker |= distance(q, m.apply(k)) < 7;
        for (const Point& p : s.points()) near_marker |= distance(q, m.apply(p)) < 7;
        if (near_marker || i % 10) continue;
        ++samples;
        dark += color_distance(at(img, q), figure_colors::kCurve) <= 40;
    }
    CHECK(samples > 25);
    CHECK(dark == samples);
    CHECK(check_far_pixels_background(img, {curve_px, mapped(s.points(), m)}, 8) > 10000);

    curves_test::check_golden("curves", "spline", img, kGoldenMax, kGoldenMean);
}

TEST_CASE("Golden: quadratic B-spline basis functions with a double knot", "[curves-render][golden]") {
    const std::vector<double> knots{0, 0, 0, 1, 2, 2, 3, 4, 4, 4};
    const int p = 2;
    const FigureOptions o{480, 240, 24};
    const Figure f = draw_basis_figure(p, knots, o);
    const Pixmap& img = f.image;
    const Affine& m = f.transform;
    const int count = static_cast<int>(knots.size()) - p - 1;

    // At sampled t, each N_i(t) (computed by Cox-de Boor, not by the drawing) is drawn in its colour
    // wherever no other function passes within 4 px and the graph is clear of the axis.
    int checked = 0, good = 0;
    std::vector<std::vector<Point>> graphs(static_cast<std::size_t>(count));
    for (int k = 0; k <= 200; ++k) {
        const double t = 4.0 * k / 200.0;
        const std::vector<double> n = bspline_basis_all(p, knots, t);
        double sum = 0;
        for (double v : n) sum += v;
        CHECK(sum == Approx(1).margin(1e-12));
        for (int i = 0; i < count; ++i)
            graphs[static_cast<std::size_t>(i)].push_back(m.apply({t, n[static_cast<std::size_t>(i)]}));
        if (k % 4) continue;
        for (int i = 0; i < count; ++i) {
            const Point q = m.apply({t, n[static_cast<std::size_t>(i)]});
            bool alone = n[static_cast<std::size_t>(i)] > 0.05;
            for (int j = 0; j < count; ++j)
                if (j != i && std::abs(m.apply({t, n[static_cast<std::size_t>(j)]}).y - q.y) < 4) alone = false;
            if (!alone) continue;
            ++checked;
            good += color_distance(at(img, q), basis_color(i, count)) <= 40;
        }
    }
    CHECK(checked > 40);
    CHECK(good == checked);
    // The double knot at t = 2 makes N_3 reach exactly 1 there (C0 peak).
    CHECK(bspline_basis(3, p, knots, 2.0) == Approx(1));
    // Far from the graphs, the axes and the N = 1 line: background.
    std::vector<std::vector<Point>> lines = graphs;
    lines.push_back({m.apply({0, 1.08}), m.apply({0, 0}), m.apply({4, 0})});
    lines.push_back({m.apply({0, 1}), m.apply({4, 1})});
    lines.push_back({m.apply({0, 1}) - Point{8, 0}, m.apply({0, 1})});
    for (double u : knots) lines.push_back({m.apply({u, 0}), m.apply({u, 0}) + Point{0, 8}});
    CHECK(check_far_pixels_background(img, lines, 6) > 3000);

    curves_test::check_golden("curves", "basis", img, kGoldenMax, kGoldenMean);
}

TEST_CASE("Golden: bicubic hill under the cabinet projection", "[surface-cli][curves-render][golden]") {
    std::vector<Point3> net;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const bool inner_i = i == 1 || i == 2, inner_j = j == 1 || j == 2;
            const double y = inner_i && inner_j ? -160 : (inner_i || inner_j ? -20 : 0);
            net.push_back({100.0 * i, y, 100.0 * j});
        }
    const BezierPatch<Point3> s(3, 3, net);
    SurfaceDrawing d;
    d.projection = Projection::Cabinet;
    d.grid = 12;
    const Figure f = draw_surface_figure(s, d, {});
    const Pixmap& img = f.image;
    const Affine& m = f.transform;
    View view;
    view.projection = Projection::Cabinet;

    // The projected corners are covered by grid lines.
    for (const Point3& c : {s.at(0, 0), s.at(0, 3), s.at(3, 0), s.at(3, 3)})
        CHECK(near_distance(img, m.apply(view.apply(c)), figure_colors::kGrid) <= 100);
    // Points on the iso-parameter lines (evaluated by de Casteljau, not the drawing) are ink.
    int samples = 0, ink = 0;
    std::vector<std::vector<Point>> lines;
    for (int k = 0; k < 12; ++k) {
        const double u = k / 11.0;
        std::vector<Point> lu, lv;
        for (int i = 0; i <= 100; ++i) {
            const double v = i / 100.0;
            lu.push_back(m.apply(view.apply(s.eval(u, v))));
            lv.push_back(m.apply(view.apply(s.eval(v, u))));
            if (i % 10 == 5) {
                samples += 2;
                ink += near_distance(img, lu.back(), figure_colors::kGrid) <= 100;
                ink += near_distance(img, lv.back(), figure_colors::kGrid) <= 100;
            }
        }
        lines.push_back(lu);
        lines.push_back(lv);
    }
    CHECK(samples == 240);
    CHECK(ink == samples);
    CHECK(check_far_pixels_background(img, lines, 5) > 10000);

    curves_test::check_golden("curves", "surface", img, kGoldenMax, kGoldenMean);
}

TEST_CASE("Golden: clock at 10:08:30", "[clock][golden]") {
    const clock_face::Time t{10, 8, 30};
    const clock_face::Geometry g{400};
    const clock_face::Colors col;
    const Pixmap img = clock_face::draw(t, 400, col);

    // The 13-point case outline has the classic coincidences.
    const auto p = clock_face::case_points(g);
    CHECK(p[0] == p[11]);
    CHECK(p[11] == p[12]);
    CHECK(p[3] == p[4]);
    CHECK(p[5] == p[6]);
    CHECK(p[9] == p[10]);
    const auto circle = clock_face::circle_points(g.center(), g.dial_radius());
    CHECK(circle[0] == circle[12]);
    // The cubic quarter arcs stay within 2.8e-4 of the radius.
    for (int k = 0; k < 4; ++k) {
        const Bezier<Point> arc{circle[3 * k], circle[3 * k + 1], circle[3 * k + 2], circle[3 * k + 3]};
        for (int i = 0; i <= 20; ++i)
            CHECK(distance(arc.eval(i / 20.0), g.center()) == Approx(g.dial_radius()).epsilon(2.8e-4));
    }

    // Hand angles: 10:08:30 -> hour 304.25 deg, minute 51 deg, second 180 deg.
    CHECK(clock_face::hour_angle(t) * 180 / std::numbers::pi == Approx(304.25));
    CHECK(clock_face::minute_angle(t) * 180 / std::numbers::pi == Approx(51));
    CHECK(clock_face::second_angle(t) * 180 / std::numbers::pi == Approx(180));
    // Near each hand's tip the pixel has that hand's colour.
    CHECK(color_distance(at(img, clock_face::polar(g, clock_face::hour_angle(t), 0.9 * g.hour_length())),
                         col.hour_hand) <= 24);
    CHECK(color_distance(at(img, clock_face::polar(g, clock_face::minute_angle(t), 0.9 * g.minute_length())),
                         col.minute_hand) <= 24);
    CHECK(color_distance(at(img, clock_face::polar(g, clock_face::second_angle(t), 0.9 * g.second_length())),
                         col.second_hand) <= 24);
    // Where no hand points (3 o'clock, half-way out) the dial shows.
    CHECK(color_distance(at(img, clock_face::polar(g, std::numbers::pi / 2, 0.5 * g.dial_radius())), col.dial) <= 4);
    // The centre is covered by the hub; the corner is background; the case shows above the dial.
    CHECK(color_distance(at(img, g.center()), col.hub) <= 4);
    CHECK(color_distance(at(img, {1, 1}), col.background) == 0);
    CHECK(color_distance(at(img, {g.center().x, g.center().y - 0.43 * g.size}), col.case_fill) <= 4);
    // 12 hour ticks: at radius 0.32 size each is the hour-tick colour, except where a hand covers it.
    for (int h = 0; h < 12; ++h) {
        if (h == 6) continue;  // under the second hand at :30
        CHECK(color_distance(at(img, clock_face::polar(g, h * std::numbers::pi / 6, 0.32 * g.size)), col.hour_tick) <=
              24);
    }

    curves_test::check_golden("curves", "clock", img, kGoldenMax, kGoldenMean);
}
