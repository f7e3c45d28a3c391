// tests/support/raster_check.hpp: run the rasterizer under test and compare its 8-bit coverage with the
// independent reference (reference_area.hpp). Test-only.
//
// Errors are measured in units of 1/255: err = |actual_u8 - 255 * reference|. Correct rounding
// of the exact area gives err <= 0.5; the acceptance bound for polygons is err <= 1.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "casteljau/paint.hpp"
#include "casteljau/raster.hpp"
#include "reference_area.hpp"

namespace casteljau::testing {

// Coverage delivered through Rasterizer::fill(..., clip, sink), kept densely over `window`
// (default: the clip). The SpanSink contract is checked as rows arrive.
struct Rendered {
    IRect clip, window;
    std::vector<std::uint8_t> cov;  // window, row-major
    std::size_t rows_delivered = 0;
    std::size_t nonzero_outside_window = 0;  // covered pixels delivered outside `window`
    std::string contract_violation;          // first violation (row outside clip, y not increasing, ...)
    RasterStats stats;

    int at(int x, int y) const;  // 0 outside the window
};

Rendered render(Rasterizer& r, const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip);
Rendered render(Rasterizer& r, const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip,
                const IRect& window);

struct Comparison {
    double max_err = 0;           // in 1/255 units, over every pixel of the union of both rects
    double mean_err = 0;          // mean over edge pixels (see below)
    double mean_all = 0;          // mean over every compared pixel
    std::size_t pixels = 0;       // pixels compared
    std::size_t edge_pixels = 0;  // reference strictly inside (0, 1), or actual not 0/255, or err > 0.5
    std::size_t misrounded = 0;   // pixels with err > 0.5 + 1e-3 (not the correctly rounded value)
    int worst_x = 0, worst_y = 0;
    double worst_ref = 0;  // reference coverage at the worst pixel (0..1)
    int worst_actual = 0;  // actual u8 at the worst pixel

    std::string text() const;  // one line: max, mean, worst pixel
};

Comparison compare(const Rendered& actual, const ref::CoverageGrid& reference);

// Opaque grey picture of coverage (r = g = b = coverage, a = 255) over the rendered window.
Pixmap coverage_pixmap(const Rendered& r);

}  // namespace casteljau::testing

#include <initializer_list>
#include <random>

namespace casteljau::testing {

// A closed polygon through `pts`.
inline Path polygon(std::initializer_list<Point> pts) {
    Path p;
    bool first = true;
    for (Point q : pts) {
        if (first)
            p.move_to(q);
        else
            p.line_to(q);
        first = false;
    }
    p.close();
    return p;
}

// An axis-aligned square of side s from (x0, y0), clockwise on screen (y down) or not.
inline Path square(double x0, double y0, double s, bool clockwise = true) {
    if (clockwise) return polygon({{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}});
    return polygon({{x0, y0}, {x0, y0 + s}, {x0 + s, y0 + s}, {x0 + s, y0}});
}

// The contours of a, then those of b.
inline Path join(const Path& a, const Path& b) {
    Path p = a;
    p.append(b);
    return p;
}

// Seeded shape generators.
// A simple polygon (n >= 3): n vertices at jittered angles and random radii in [rmin, rmax] around c.
ref::Contour random_simple_polygon(std::mt19937& rng, Point c, double rmin, double rmax, int n);
// Any polygon (usually self-intersecting): n uniform random vertices in `box`.
ref::Contour random_polygon(std::mt19937& rng, const Rect& box, int n);
// The regular star polygon {p/q}: p vertices on a circle, joined every q-th (one contour).
ref::Contour star_polygon(Point c, double r, int p, int q, double rotation = 0.0);
// A regular n-gon (clockwise on screen when `clockwise`).
ref::Contour regular_polygon(Point c, double r, int n, bool clockwise = true, double rotation = 0.0);
ref::Contour reversed(ref::Contour c);
// The axis-aligned rectangle [x0, x1] x [y0, y1], clockwise on screen.
inline ref::Contour rect(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}
// Three squares in one path overlapping each other ([20.6, 30.3] x [20.6, 30.3] is in all three): the
// overlap check has cells to recompute, where plain accumulation adds the stacked windings.
inline Path overlapping_squares() {
    Path p;
    p.add_rect(Rect{0.3, 0.3, 30.3, 30.3});
    p.add_rect(Rect{20.6, 20.6, 50.6, 50.6});
    p.add_rect(Rect{10.2, 10.2, 40.7, 40.7});
    return p;
}

}  // namespace casteljau::testing
