// The clock of examples/clock.cpp, in a header so that the golden test (tests/figures/test_curves_golden.cpp)
// draws exactly the same picture and can check it.
//
// Everything is built from cubic Bézier arcs given as 13-point lists (4 arcs: P0..P3, P3..P6,
// P6..P9, P9..P12), as the classic clock program does:
// - the case: points 0 = 11 = 12, 3 = 4, 5 = 6 and 9 = 10 coincide. Arcs 1 (top) and 3 (bottom) are
//   true curves; arcs 2 and 4 have both control points on their end points, so they are the
//   straight sides: the outline of a rounded mantel clock.
// - the dial: a circle of 4 quarter arcs (control points at kappa = 4(sqrt 2 - 1)/3 of the radius
//   along the tangents, radial error 2.7e-4 of the radius), P12 = P0.
// Hands for a time HH:MM:SS, 60 tick marks, colours given as CSS hsl().
// Coordinates: pixels, y down; angles clockwise from 12 o'clock.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "casteljau/canvas.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"

namespace clock_face {

using casteljau::Color;
using casteljau::Point;

struct Time {
    int h = 10, m = 8, s = 30;
};

// "HH:MM:SS" (0..23, 0..59, 0..59); false when malformed.
inline bool parse_time(const std::string& text, Time& t) {
    int h = -1, m = -1, s = -1;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%d:%d:%d%c", &h, &m, &s, &tail) != 3) return false;
    if (h < 0 || h > 23 || m < 0 || m > 59 || s < 0 || s > 59) return false;
    t = {h, m, s};
    return true;
}

inline Color hsl(double h, double s, double l) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "hsl(%g, %g%%, %g%%)", h, s, l);
    return casteljau::parse_color(buf);
}

struct Colors {
    Color background = hsl(210, 30, 96);
    Color case_fill = hsl(24, 55, 32);
    Color dial = hsl(45, 70, 94);
    Color rim = hsl(30, 40, 20);
    Color minute_tick = hsl(220, 15, 55);
    Color hour_tick = hsl(220, 40, 25);
    Color hour_hand = hsl(220, 60, 22);
    Color minute_hand = hsl(200, 70, 35);
    Color second_hand = hsl(355, 80, 48);
    Color hub = hsl(220, 60, 15);
};

// The geometry for a square picture of side `size`.
struct Geometry {
    double size = 400;
    Point center() const { return {size / 2, size / 2}; }
    double dial_radius() const { return 0.38 * size; }
    double hour_length() const { return 0.20 * size; }
    double minute_length() const { return 0.29 * size; }
    double second_length() const { return 0.32 * size; }
    double hour_width() const { return 0.02 * size; }
    double minute_width() const { return 0.0125 * size; }
    double second_width() const { return 0.005 * size; }
    double hub_radius() const { return 0.018 * size; }
};

// Hand angles in radians, clockwise from 12 o'clock.
inline double hour_angle(const Time& t) { return (t.h % 12 + t.m / 60.0 + t.s / 3600.0) * (std::numbers::pi / 6); }
inline double minute_angle(const Time& t) { return (t.m + t.s / 60.0) * (std::numbers::pi / 30); }
inline double second_angle(const Time& t) { return t.s * (std::numbers::pi / 30); }

// The point at `radius` from the centre in the direction of `angle` (clockwise from 12, y down).
inline Point polar(const Geometry& g, double angle, double radius) {
    return {g.center().x + radius * std::sin(angle), g.center().y - radius * std::cos(angle)};
}

// The case outline's 13 points (see the header comment for the coincidences).
inline std::array<Point, 13> case_points(const Geometry& g) {
    const Point c = g.center();
    const double half_w = 0.44 * g.size, half_h = 0.2 * g.size, bulge = 0.36 * g.size;
    const double l = c.x - half_w, r = c.x + half_w, top = c.y - half_h, bottom = c.y + half_h;
    std::array<Point, 13> p;
    p[0] = {l, top};
    p[1] = {l, top - bulge};
    p[2] = {r, top - bulge};
    p[3] = {r, top};
    p[4] = p[3];
    p[5] = {r, bottom};
    p[6] = p[5];
    p[7] = {r, bottom + bulge};
    p[8] = {l, bottom + bulge};
    p[9] = {l, bottom};
    p[10] = p[9];
    p[11] = p[0];
    p[12] = p[0];
    return p;
}

// A circle of radius r around c as 4 cubic quarter arcs, 13 points, P12 = P0, clockwise (y down).
inline std::array<Point, 13> circle_points(Point c, double r) {
    const double k = 4 * (std::numbers::sqrt2 - 1) / 3 * r;
    return {{{c.x, c.y - r},
             {c.x + k, c.y - r},
             {c.x + r, c.y - k},
             {c.x + r, c.y},
             {c.x + r, c.y + k},
             {c.x + k, c.y + r},
             {c.x, c.y + r},
             {c.x - k, c.y + r},
             {c.x - r, c.y + k},
             {c.x - r, c.y},
             {c.x - r, c.y - k},
             {c.x - k, c.y - r},
             {c.x, c.y - r}}};
}

// The closed path of a 13-point list: 4 cubic arcs.
inline casteljau::Path arcs_path(const std::array<Point, 13>& p) {
    casteljau::Path path;
    path.move_to(p[0]);
    for (int k = 0; k < 4; ++k) path.cubic_to(p[3 * k + 1], p[3 * k + 2], p[3 * k + 3]);
    path.close();
    return path;
}

inline void hand(casteljau::Canvas& c, const Geometry& g, double angle, double length, double tail, double width,
                 Color color) {
    casteljau::Path p;
    p.move_to(polar(g, angle + std::numbers::pi, tail)).line_to(polar(g, angle, length));
    casteljau::StrokeStyle st;
    st.width = width;
    st.cap = casteljau::LineCap::Round;
    c.stroke_path(p, st, casteljau::Paint::solid(color));
}

// Draws the clock on `c` (whose pixels it replaces: the background first), `size` pixels square.
inline void draw_into(casteljau::Canvas& c, const Time& t, int size, const Colors& col = {}) {
    using namespace casteljau;
    const Geometry g{static_cast<double>(size)};
    c.clear(col.background);
    const Path case_outline = arcs_path(case_points(g));
    c.fill_path(case_outline, Paint::solid(col.case_fill));
    const Path dial = arcs_path(circle_points(g.center(), g.dial_radius()));
    c.fill_path(dial, Paint::solid(col.dial));
    StrokeStyle rim;
    rim.width = 0.015 * size;
    c.stroke_path(dial, rim, Paint::solid(col.rim));

    // Ticks: 60, every fifth longer and thicker.
    Path minor, major;
    for (int i = 0; i < 60; ++i) {
        const double a = i * std::numbers::pi / 30;
        const bool hour = i % 5 == 0;
        Path& p = hour ? major : minor;
        p.move_to(polar(g, a, (hour ? 0.29 : 0.32) * size)).line_to(polar(g, a, 0.35 * size));
    }
    StrokeStyle thin, thick;
    thin.width = 0.005 * size;
    thick.width = 0.015 * size;
    c.stroke_path(minor, thin, Paint::solid(col.minute_tick));
    c.stroke_path(major, thick, Paint::solid(col.hour_tick));

    hand(c, g, hour_angle(t), g.hour_length(), 0.03 * size, g.hour_width(), col.hour_hand);
    hand(c, g, minute_angle(t), g.minute_length(), 0.04 * size, g.minute_width(), col.minute_hand);
    hand(c, g, second_angle(t), g.second_length(), 0.06 * size, g.second_width(), col.second_hand);
    Path hub;
    hub.add_circle(g.center(), g.hub_radius());
    c.fill_path(hub, Paint::solid(col.hub));
}

inline casteljau::Pixmap draw(const Time& t, int size = 400, const Colors& col = {}) {
    casteljau::Pixmap pix(size, size);
    casteljau::Canvas c(pix);
    draw_into(c, t, size, col);
    return pix;
}

}  // namespace clock_face
