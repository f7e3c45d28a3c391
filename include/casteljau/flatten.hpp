// casteljau/flatten.hpp: curves to polylines by recursive de Casteljau subdivision.
//
// Each piece satisfies a bound that provably keeps curve and chord within `tolerance` pixels (see
// src/path/flatten.cpp for the bound and its derivation). Quadratics are cut into the smallest
// sufficient number of equal pieces; cubics and conics are halved at t = 1/2 until the bound holds
// (a cubic's halving tree is walked in order without splitting its control points, a conic is
// split on an explicit stack; area-balanced cubics are cut into equal pieces like quadratics),
// with a depth limit (limits::kMaxFlattenDepth), so cusps, loops,
// coincident control points and huge values cannot subdivide without end. Flattening happens after
// the transform, so the tolerance is in pixels. Non-finite input is rejected with Error(InvalidData).
// Thread-safety: free functions; no shared state.
#pragma once

#include <cstdint>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/path.hpp"

namespace casteljau {

// Default flattening tolerance in pixels, chosen by measurement against the exact-area reference
// (tests/raster/test_raster_accuracy.cpp and bench/tolerance_study print the tables). Fills use
// area-balanced curves (FlattenMode::AreaBalanced); at 0.015 px DejaVu Sans at 12 px has a
// mean error of 0.17/255 and every size a maximum of at most 6/255, while 0.025 px already
// reaches 9/255 at 256 px. Every case of the suite is within 0.5/255 mean and 8/255 max.
inline constexpr double kDefaultTolerance = 0.015;

// Where the vertices of a flattened quadratic or cubic go.
enum class FlattenMode {
    // Chords: every vertex lies on the curve. Chords cut the concave side of each piece, so a
    // filled polygon is slightly thinner than the curve (a bias of 2/3 of the chord error).
    Chords,
    // Area-balanced (what Rasterizer::fill uses): a quadratic or cubic is cut into n pieces of
    // equal parameter length h, and each interior vertex B(t) is moved off the curve by
    // -(h^2 / 12) B''(t), towards its convex side, so the interior pieces cross the curve and lose
    // no area; the polyline still stays within `tolerance` of the curve
    // (src/path/flatten_internal.hpp has the derivation), with fewer pieces. Conics are flattened
    // to chords in both modes.
    AreaBalanced,
};

// A flattened path: the points of all contours, with contour i spanning
// points[contour_ends[i-1] .. contour_ends[i]). Contours are open polylines; a fill closes them.
struct Polyline {
    std::vector<Point> points;
    std::vector<std::uint32_t> contour_ends;
    // Per contour: whether the source contour was explicitly closed (matters to strokes only).
    std::vector<bool> closed;

    void clear() {
        points.clear();
        contour_ends.clear();
        closed.clear();
    }
    std::size_t contour_count() const { return contour_ends.size(); }
};

// Flattens `path` mapped by `m` into `out` (cleared first). Throws Error(InvalidData) for a
// non-finite point or transform, Error(Limit) beyond Limits::flattened_segments. With
// FlattenMode::AreaBalanced the result is exactly the polygon Rasterizer::fill scan-converts.
void flatten(const Path& path, const Affine& m, double tolerance, Polyline& out,
             FlattenMode mode = FlattenMode::Chords);

// The a-priori flatness bound used for each curve kind: the maximum distance between the curve and
// its chord is at most this value (exposed for tests).
double flatness_bound_quad(Point p0, Point p1, Point p2);
double flatness_bound_cubic(Point p0, Point p1, Point p2, Point p3);
double flatness_bound_conic(Point p0, Point p1, Point p2, double w);

}  // namespace casteljau
