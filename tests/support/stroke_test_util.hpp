// Helpers shared by the stroke and dash tests (test_stroke.cpp, test_dash.cpp): the contours of a
// stroked or dashed Path (lines only), their signed area, winding number and length, the expected
// "on" length of a dash pattern, and short constructors of a line and a StrokeStyle.
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "casteljau/stroke.hpp"

namespace stroke_test {

using casteljau::LineCap;
using casteljau::LineJoin;
using casteljau::Path;
using casteljau::Point;
using casteljau::StrokeStyle;

struct Contour {
    std::vector<Point> pts;
    bool closed = false;
};

// The contours of a Path made of lines only (what stroke() and dash() produce).
inline std::vector<Contour> contours_of(const Path& p) {
    std::vector<Contour> out;
    struct V {
        std::vector<Contour>& out;
        void move(Point a) { out.push_back({{a}, false}); }
        void line(Point, Point b) { out.back().pts.push_back(b); }
        void quad(Point, Point, Point) { FAIL("stroke output has a quad"); }
        void cubic(Point, Point, Point, Point) { FAIL("stroke output has a cubic"); }
        void conic(Point, Point, Point, double) { FAIL("stroke output has a conic"); }
        void close(Point, Point) { out.back().closed = true; }
    } v{out};
    p.visit(v);
    return out;
}

// Signed area (shoelace) of all contours, each closed implicitly as a fill does.
inline double signed_area(const Path& p) {
    double a = 0;
    for (const Contour& c : contours_of(p))
        for (std::size_t i = 0; i < c.pts.size(); ++i) a += c.pts[i].cross(c.pts[(i + 1) % c.pts.size()]);
    return a / 2;
}

// Nonzero winding number of the (implicitly closed) contours around q.
inline int winding(const Path& p, Point q) {
    int w = 0;
    for (const Contour& c : contours_of(p)) {
        for (std::size_t i = 0; i < c.pts.size(); ++i) {
            const Point a = c.pts[i], b = c.pts[(i + 1) % c.pts.size()];
            const double side = (b - a).cross(q - a);
            if (a.y <= q.y && b.y > q.y && side > 0) ++w;
            if (b.y <= q.y && a.y > q.y && side < 0) --w;
        }
    }
    return w;
}

inline bool inside(const Path& p, Point q) { return winding(p, q) != 0; }

inline double polyline_length(const Contour& c) {
    double l = 0;
    for (std::size_t i = 1; i < c.pts.size(); ++i) l += distance(c.pts[i - 1], c.pts[i]);
    if (c.closed && c.pts.size() > 1) l += distance(c.pts.back(), c.pts.front());
    return l;
}

inline double total_length(const Path& p) {
    double l = 0;
    for (const Contour& c : contours_of(p)) l += polyline_length(c);
    return l;
}

// Independent expectation: the "on" length of an (even, positive) pattern over [0, len) of a path,
// starting `offset` into the pattern, by summing interval overlaps period by period.
inline double expected_on_length(std::vector<double> pat, double offset, double len) {
    if (pat.size() % 2) {
        const auto copy = pat;
        pat.insert(pat.end(), copy.begin(), copy.end());
    }
    double period = 0;
    for (double d : pat) period += d;
    const double a = offset, b = offset + len;  // the window in pattern coordinates
    double on = 0;
    for (double k = std::floor(a / period) - 1; k * period <= b; ++k) {
        double s = k * period;
        for (std::size_t i = 0; i < pat.size(); ++i) {
            if (i % 2 == 0) on += std::max(0.0, std::min(b, s + pat[i]) - std::max(a, s));
            s += pat[i];
        }
    }
    return on;
}

inline Path line(Point a, Point b) {
    Path p;
    p.move_to(a).line_to(b);
    return p;
}

inline StrokeStyle style(double w, LineCap cap = LineCap::Butt, LineJoin join = LineJoin::Miter, double limit = 4) {
    StrokeStyle s;
    s.width = w;
    s.cap = cap;
    s.join = join;
    s.miter_limit = limit;
    return s;
}

}  // namespace stroke_test
