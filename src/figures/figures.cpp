// Pictures of curves, splines, basis functions and surfaces (include/casteljau/figures.hpp).
#include "casteljau/figures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/spline.hpp"
#include "casteljau/stroke.hpp"

namespace casteljau {

namespace {

Color hsl(double hue, double sat_percent, double light_percent) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "hsl(%.3f, %.3f%%, %.3f%%)", hue, sat_percent, light_percent);
    return parse_color(buf);
}

void check_options(const FigureOptions& o) {
    if (o.width <= 0 || o.height <= 0)
        throw Error(ErrorKind::InvalidArgument,
                    "figure size must be positive, got " + std::to_string(o.width) + "x" + std::to_string(o.height));
    check_canvas_size(o.width, o.height);
    if (!(o.margin >= 0) || 2 * o.margin >= std::min(o.width, o.height))
        throw Error(ErrorKind::InvalidArgument, "figure margin must be >= 0 and leave room for the drawing");
}

Pixmap blank(const FigureOptions& o) {
    Pixmap p(o.width, o.height);
    p.fill(figure_colors::kBackground);
    return p;
}

StrokeStyle solid(double width) {
    StrokeStyle s;
    s.width = width;
    s.cap = LineCap::Round;
    s.join = LineJoin::Round;
    return s;
}

StrokeStyle dashed(double width) {
    StrokeStyle s;
    s.width = width;
    s.dashes = {6, 4};
    return s;
}

Path polyline(std::span<const Point> pts, const Affine& m) {
    Path p;
    if (pts.size() < 2) return p;
    p.move_to(m.apply(pts[0]));
    for (std::size_t i = 1; i < pts.size(); ++i) p.line_to(m.apply(pts[i]));
    return p;
}

// A filled disk with a thin darker ring: the label-free marker of a point.
void marker(Canvas& c, Point at, double radius, Color fill) {
    Path disk;
    disk.add_circle(at, radius);
    c.fill_path(disk, Paint::solid(fill));
    c.stroke_path(disk, solid(1.0), Paint::solid(figure_colors::kCurve));
}

Rect box_of(std::span<const Point> pts) {
    Rect r{pts.front().x, pts.front().y, pts.front().x, pts.front().y};
    for (const Point& p : pts) r.include(p);
    return r;
}

}  // namespace

Color construction_color(int level, int levels) {
    const double n = std::max(1, levels);
    return hsl(std::fmod(200.0 + 360.0 * (level - 1) / n, 360.0), 70, 45);
}

Color basis_color(int i, int count) {
    const double n = std::max(1, count);
    return hsl(std::fmod(360.0 * i / n, 360.0), 75, 42);
}

Affine fit_transform(const Rect& b, int width, int height, double margin) {
    const double aw = width - 2 * margin, ah = height - 2 * margin;
    const double bw = b.x1 - b.x0, bh = b.y1 - b.y0;
    double s = 1;
    if (bw > 0 && bh > 0)
        s = std::min(aw / bw, ah / bh);
    else if (bw > 0)
        s = aw / bw;
    else if (bh > 0)
        s = ah / bh;
    if (!std::isfinite(s) || s <= 0)
        throw Error(ErrorKind::InvalidData, "the drawing's bounds cannot be fitted to the canvas");
    const double cx = 0.5 * (b.x0 + b.x1), cy = 0.5 * (b.y0 + b.y1);
    return Affine::translate(0.5 * width, 0.5 * height) * Affine::scale(s) * Affine::translate(-cx, -cy);
}

Figure draw_bezier_figure(const Bezier<Point>& curve, const FigureOptions& o, std::optional<double> construction_t) {
    check_options(o);
    if (construction_t && !(*construction_t >= 0 && *construction_t <= 1))
        throw Error(ErrorKind::InvalidArgument, "construction parameter must lie in [0, 1]");
    const std::vector<Point> ctrl(curve.points().begin(), curve.points().end());
    Figure f{blank(o), fit_transform(box_of(ctrl), o.width, o.height, o.margin)};
    Canvas c(f.image);
    const Affine& m = f.transform;

    c.stroke_path(polyline(ctrl, m), dashed(1.0), Paint::solid(figure_colors::kPolygon));
    std::vector<std::vector<Point>> rows;
    if (construction_t) {
        rows = curve.triangle(*construction_t);
        const int levels = curve.degree() - 1;  // rows 1 .. n-1 are polygons
        for (int r = 1; r <= levels; ++r)
            c.stroke_path(polyline(rows[static_cast<std::size_t>(r)], m), solid(1.5),
                          Paint::solid(construction_color(r, levels)));
    }
    c.stroke_path(to_path(curve).transformed(m), solid(2.5), Paint::solid(figure_colors::kCurve));
    if (construction_t) {
        const int levels = curve.degree() - 1;
        for (int r = 1; r <= levels; ++r)
            for (const Point& p : rows[static_cast<std::size_t>(r)])
                marker(c, m.apply(p), 2.5, construction_color(r, levels));
    }
    for (const Point& p : ctrl) marker(c, m.apply(p), 4.0, figure_colors::kControlPoint);
    if (construction_t) marker(c, m.apply(rows.back().front()), 5.5, figure_colors::kHighlight);
    return f;
}

Figure draw_spline_figure(const Path& curve, std::span<const Point> polygon, std::span<const Point> knots,
                          const FigureOptions& o) {
    check_options(o);
    if (curve.empty() && polygon.empty())
        throw Error(ErrorKind::InvalidData, "nothing to draw: empty curve and polygon");
    Rect b = curve.empty() ? box_of(polygon) : curve.bounds();
    if (!polygon.empty()) b = b.united(box_of(polygon));
    Figure f{blank(o), fit_transform(b, o.width, o.height, o.margin)};
    Canvas c(f.image);
    const Affine& m = f.transform;
    c.stroke_path(polyline(polygon, m), dashed(1.0), Paint::solid(figure_colors::kPolygon));
    c.stroke_path(curve.transformed(m), solid(2.5), Paint::solid(figure_colors::kCurve));
    for (const Point& p : polygon) marker(c, m.apply(p), 4.0, figure_colors::kControlPoint);
    for (const Point& p : knots) marker(c, m.apply(p), 3.5, figure_colors::kKnot);
    return f;
}

namespace {

// The number of basis functions of `degree` over `knots`, checked (Error for a bad degree, too few
// or decreasing knots, or an empty domain).
std::size_t basis_count(int degree, std::span<const double> knots) {
    if (degree < 0 || degree > limits::kMaxSplineDegree)
        throw Error(ErrorKind::InvalidArgument,
                    "basis degree must lie in 0.." + std::to_string(limits::kMaxSplineDegree));
    if (knots.size() < static_cast<std::size_t>(degree) + 2)
        throw Error(ErrorKind::InvalidData, "a knot vector of degree " + std::to_string(degree) + " needs at least " +
                                                std::to_string(degree + 2) + " knots, got " +
                                                std::to_string(knots.size()));
    const std::size_t count = knots.size() - static_cast<std::size_t>(degree) - 1;
    validate_knots(degree, count, knots);
    if (!(knots[count] > knots[static_cast<std::size_t>(degree)]))
        throw Error(ErrorKind::InvalidData, "the basis functions' domain is empty");
    return count;
}

// The axes of a basis plot over [t0, t1] (m: plot to pixels), a tick at each knot inside, and the
// dashed line N = 1.
void draw_basis_axes(Canvas& c, const Affine& m, std::span<const double> knots, double t0, double t1) {
    const Paint axis = Paint::solid(figure_colors::kAxis);
    Path axes;
    axes.move_to(m.apply({t0, 1.08})).line_to(m.apply({t0, 0})).line_to(m.apply({t1, 0}));
    c.stroke_path(axes, solid(1.0), axis);
    Path ticks;
    for (double u : knots) {
        if (u < t0 || u > t1) continue;
        const Point p = m.apply({u, 0});
        ticks.move_to(p).line_to({p.x, p.y + 6});
    }
    const Point one = m.apply({t0, 1});
    ticks.move_to(one).line_to({one.x - 6, one.y});
    c.stroke_path(ticks, solid(1.0), axis);
    Path unit;
    unit.move_to(one).line_to(m.apply({t1, 1}));
    c.stroke_path(unit, dashed(0.75), Paint::solid(figure_colors::kPolygon));
}

// Degree 0: each basis function is a step, 1 over its knot span.
void draw_steps(Canvas& c, const Affine& m, std::span<const double> knots, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
        const double a = knots[i], b = knots[i + 1];
        if (!(b > a)) continue;
        Path step;
        step.move_to(m.apply({a, 0})).line_to(m.apply({a, 1})).line_to(m.apply({b, 1})).line_to(m.apply({b, 0}));
        c.stroke_path(step, solid(2.0), Paint::solid(basis_color(static_cast<int>(i), static_cast<int>(count))));
    }
}

// Each basis function N_i as the graph (t, N_i(t)): the B-spline whose control points sit at the
// Greville abscissae with heights 0, except 1 at i.
void draw_basis_curves(Canvas& c, const Affine& m, int degree, std::span<const double> knots, std::size_t count) {
    std::vector<double> greville(count);
    for (std::size_t j = 0; j < count; ++j) {
        double s = 0;
        for (int k = 1; k <= degree; ++k) s += knots[j + static_cast<std::size_t>(k)];
        greville[j] = s / degree;
    }
    const std::vector<double> kv(knots.begin(), knots.end());
    for (std::size_t i = 0; i < count; ++i) {
        std::vector<Point> ctrl(count);
        for (std::size_t j = 0; j < count; ++j) ctrl[j] = {greville[j], i == j ? 1.0 : 0.0};
        const BSpline<Point> graph(degree, std::move(ctrl), kv);
        const auto pieces = graph.to_bezier();
        c.stroke_path(to_path(pieces, 1e-4).transformed(m), solid(2.0),
                      Paint::solid(basis_color(static_cast<int>(i), static_cast<int>(count))));
    }
}

}  // namespace

Figure draw_basis_figure(int degree, std::span<const double> knots, const FigureOptions& o) {
    check_options(o);
    const std::size_t count = basis_count(degree, knots);
    const double t0 = knots[static_cast<std::size_t>(degree)], t1 = knots[count];
    // Plot area: extra room at the left and bottom for the axes; N in [0, 1] plus headroom.
    const double left = o.margin + 8, right = o.width - o.margin, top = o.margin, bottom = o.height - o.margin - 8;
    if (!(right - left > 4 && bottom - top > 4))
        throw Error(ErrorKind::InvalidArgument, "figure too small for a basis plot");
    const double sx = (right - left) / (t1 - t0), sy = (bottom - top) / 1.08;
    Figure f{blank(o), Affine{sx, 0, 0, -sy, left - sx * t0, bottom}};
    Canvas c(f.image);
    draw_basis_axes(c, f.transform, knots, t0, t1);
    if (degree == 0)
        draw_steps(c, f.transform, knots, count);
    else
        draw_basis_curves(c, f.transform, degree, knots, count);
    return f;
}

namespace {

template <class S>
Figure surface_figure(const S& s, const SurfaceDrawing& d, const FigureOptions& o) {
    check_options(o);
    if (d.grid < 2 || d.grid > limits::kMaxGridLines)
        throw Error(ErrorKind::InvalidArgument,
                    "grid must lie in 2.." + std::to_string(limits::kMaxGridLines) + ", got " + std::to_string(d.grid));
    View view;
    view.projection = d.projection;
    const Path grid = iso_grid(s, view, d.grid, d.grid);
    Figure f{blank(o), fit_transform(grid.bounds(), o.width, o.height, o.margin)};
    Canvas c(f.image);
    const Affine& m = f.transform;
    if (d.shaded) {
        const int cells = std::min(3 * (d.grid - 1), 256);
        for (const ShadedQuad& q : shaded_quads(s, view, cells, cells)) {
            Path quad;
            quad.move_to(m.apply(q.corners[0]));
            for (int k = 1; k < 4; ++k) quad.line_to(m.apply(q.corners[static_cast<std::size_t>(k)]));
            quad.close();
            const Paint paint = Paint::solid(hsl(205, 55, 30 + 50 * q.shade));
            c.fill_path(quad, paint);
            c.stroke_path(quad, solid(0.6), paint);  // hides the hairline seams between quads
        }
    }
    c.stroke_path(grid.transformed(m), solid(d.shaded ? 0.8 : 1.2), Paint::solid(figure_colors::kGrid));
    return f;
}

}  // namespace

Figure draw_surface_figure(const BezierPatch<Point3>& s, const SurfaceDrawing& d, const FigureOptions& o) {
    return surface_figure(s, d, o);
}
Figure draw_surface_figure(const BSplineSurface<Point3>& s, const SurfaceDrawing& d, const FigureOptions& o) {
    return surface_figure(s, d, o);
}
Figure draw_surface_figure(const NurbsSurface<Point3>& s, const SurfaceDrawing& d, const FigureOptions& o) {
    return surface_figure(s, d, o);
}

}  // namespace casteljau
