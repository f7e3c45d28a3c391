// tests/support/reference_area.hpp: an independent exact-area reference for the rasterizer tests.
//
// Test-only code, written from scratch; it shares nothing with src/raster/ or src/path/flatten.cpp
// (it reads Paths only through Path::visit and applies transforms with its own arithmetic), so
// that a bug in the code under test cannot hide in the reference.
//
// Conventions are those of the library: pixel space, x right, y down, pixel (i, j) is the square
// [i, i+1) x [j, j+1). Coverage is the exact covered area of that square in [0, 1], in double.
// A Contour is a closed polygon (the last point connects back to the first implicitly).
//
// Two independent methods:
//  (a) clip_area_simple: Sutherland-Hodgman clipping of ONE simple (non-self-intersecting) polygon
//      to each pixel square, then the shoelace area. Only valid for simple polygons.
//  (b) slab_area: exact integration by slabs for any set of contours under nonzero or even-odd.
//      For every pixel row, every y where the picture changes (edge end points, pairwise crossings
//      of edges inside the row, the row bounds) cuts the row into slabs; inside a slab no two edges
//      cross, so the crossings with a horizontal line keep their order and each covered interval
//      [L(y), R(y)] has linear sides. The area a covered interval leaves in a pixel column
//      [c, c+1] is the integral of clamp(R) - clamp(L) (clamp to [c, c+1]); clamp(X(y)) is
//      piecewise linear, so it is integrated exactly by splitting at the y where X crosses c and
//      c+1 and using the trapezoid rule on each linear piece.
//  fine_flatten + path_reference: curved paths are flattened by uniform parameter steps (direct
//      Bernstein evaluation, not de Casteljau) with a chord error below a tiny tolerance, then (b).
#pragma once

#include <cstddef>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/path.hpp"
#include "casteljau/raster.hpp"

namespace casteljau::ref {

using Contour = std::vector<Point>;
using Contours = std::vector<Contour>;

// Per-pixel coverage over a pixel rectangle.
struct CoverageGrid {
    IRect bounds;
    std::vector<double> v;  // row-major, bounds.width() x bounds.height()

    explicit CoverageGrid(const IRect& r);
    double at(int x, int y) const;  // 0 outside bounds
    double& cell(int x, int y) { return v[static_cast<std::size_t>(y - bounds.y0) * bounds.width() + (x - bounds.x0)]; }
    double sum() const;
};

// Signed shoelace area (positive when the contour runs clockwise on screen, y down).
double signed_area(const Contour& c);

// Applies x' = a x + c y + e, y' = b x + d y + f (own arithmetic, same formula as the library's).
Point apply(const Affine& m, Point p);
Contour transformed(const Contour& c, const Affine& m);
Contours transformed(const Contours& cs, const Affine& m);

// Pixel rectangle containing the contours (floor/ceil of their bounds), optionally grown by `pad`.
IRect pixel_bounds(const Contours& cs, int pad = 0);

// (a) Sutherland-Hodgman per pixel + shoelace. `poly` must be simple.
CoverageGrid clip_area_simple(const Contour& poly, const IRect& region);

// (b) Exact slab integration for any contours under `rule`.
CoverageGrid slab_area(const Contours& polys, FillRule rule, const IRect& region);

// Flattens `path` mapped by `m` into contours by uniform parameter steps chosen so that the chord
// error of every piece is at most `tolerance` pixels (bounds in reference_area.cpp).
Contours fine_flatten(const Path& path, const Affine& m, double tolerance = 1e-4);

// The reference coverage of a curved path: fine_flatten + slab_area.
CoverageGrid path_reference(const Path& path, const Affine& m, FillRule rule, const IRect& region,
                            double tolerance = 1e-4);

// A Path holding the contours (move/line/close): the form handed to the code under test.
Path to_path(const Contours& cs);

}  // namespace casteljau::ref
