// casteljau/figures.hpp: pictures of the curve toolkit: a Bézier curve with its control polygon
// and (optionally) its de Casteljau construction, a spline with its control polygon and knots, a
// plot of B-spline basis functions, and a surface as a projected iso-parameter grid (optionally
// shaded quads). Used by the `bezier`, `spline` and `surface` CLI commands and the gallery.
//
// Coordinates: curve space is drawn with y DOWN as given (no flip), uniformly scaled and centred
// to fit the canvas inside `margin` pixels (fit_transform). Surfaces are projected by a View
// (surface.hpp: z recedes, larger z is farther) and the projection is fitted the same way. Each
// draw function returns the Pixmap and the Affine that maps its input space to pixels, so callers
// and tests can locate what was drawn. Stroke widths and marker sizes are in pixels.
// Colours: the figure_colors constants below (white background).
// Errors: Error(InvalidArgument) for a canvas size outside the canvas limits, a grid below 2 or
// above limits::kMaxGridLines, t outside [0, 1]; the curve classes validate their own input.
// Thread-safety: free functions, no shared state.
#pragma once

#include <optional>
#include <span>

#include "casteljau/bezier.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"
#include "casteljau/surface.hpp"

namespace casteljau {

namespace figure_colors {
inline constexpr Color kBackground = Color::rgba(255, 255, 255);
inline constexpr Color kCurve = Color::rgba(0x1b, 0x1f, 0x3a);         // the curve, 2.5 px
inline constexpr Color kPolygon = Color::rgba(0x9a, 0x9a, 0x9a);       // control polygon, 1 px dashed
inline constexpr Color kControlPoint = Color::rgba(0x2b, 0x6c, 0xc4);  // control point markers
inline constexpr Color kHighlight = Color::rgba(0xe0, 0x1b, 0x24);     // P(t) of the construction
inline constexpr Color kKnot = Color::rgba(0xf0, 0x8c, 0x00);          // knot points on a spline
inline constexpr Color kAxis = Color::rgba(0x40, 0x40, 0x40);          // basis plot axes
inline constexpr Color kGrid = Color::rgba(0x1b, 0x3f, 0x7a);          // surface iso curves
}  // namespace figure_colors

// Colour of construction level `level` (1 .. levels): hues spread over the wheel (HSL, s 70%, l 45%).
Color construction_color(int level, int levels);
// Colour of basis function `i` of `count`: hues spread over the wheel (HSL, s 75%, l 42%).
Color basis_color(int i, int count);

struct FigureOptions {
    int width = 400, height = 400;
    double margin = 24;  // pixels kept free on every side
};

struct Figure {
    Pixmap image;
    Affine transform;  // input space -> pixels
};

// Uniform scale + translation that maps `bounds` centred into the canvas minus `margin` on every
// side (y not flipped). A box of zero width or height is fitted by its other side; a single point
// is centred at scale 1.
Affine fit_transform(const Rect& bounds, int width, int height, double margin);

// The curve (2.5 px), its control polygon (1 px grey, dashed), the control points (disks), and with
// `construction_t` the intermediate polygons of each de Casteljau level in construction_color and
// P(t) as a kHighlight disk. Fitted to the control points' box.
Figure draw_bezier_figure(const Bezier<Point>& curve, const FigureOptions& options,
                          std::optional<double> construction_t = std::nullopt);

// Any curve given as a Path (a spline's Bézier pieces) with its control polygon (dashed; may be
// empty) and markers at `knot_points` (kKnot disks) and at the control points. Fitted to the box of
// the curve and the polygon.
Figure draw_spline_figure(const Path& curve, std::span<const Point> control_polygon, std::span<const Point> knot_points,
                          const FigureOptions& options);

// The B-spline basis functions N_(i,p)(t) of `knots` (validated as for `count = knots.size() - p - 1`
// control points) over the domain [u_p, u_count], one basis_color each, with axes, ticks at the
// knots and a dashed line at N = 1. Each graph t -> (t, N_i(t)) is drawn exactly: it is the B-spline
// whose control points are (Greville abscissa_j, delta_ij) (linear precision), so its Bézier pieces
// are the graph. Degree 0 draws the span indicators as steps. The Figure's transform maps (t, N)
// to pixels.
Figure draw_basis_figure(int degree, std::span<const double> knots, const FigureOptions& options);

struct SurfaceDrawing {
    Projection projection = Projection::Cavalier;
    int grid = 10;        // iso curves per direction (2 .. kMaxGridLines)
    bool shaded = false;  // Lambert-shaded quads (3 per grid cell and direction) back to front, grid on top
};

// The iso-parameter grid of the surface under the projection (View with no rotation); the
// Figure's transform maps View::apply(p) (scale 1, offset 0) to pixels. Fitted to the tight bounds
// of the projected grid (a silhouette between grid lines may reach a little beyond it, into the margin).
Figure draw_surface_figure(const BezierPatch<Point3>& s, const SurfaceDrawing& drawing, const FigureOptions& options);
Figure draw_surface_figure(const BSplineSurface<Point3>& s, const SurfaceDrawing& drawing,
                           const FigureOptions& options);
Figure draw_surface_figure(const NurbsSurface<Point3>& s, const SurfaceDrawing& drawing, const FigureOptions& options);

}  // namespace casteljau
