// casteljau/nurbs.hpp: rational curves: rational Bézier curves (rational de Casteljau), NURBS
// (non-uniform rational B-splines), exact conics, circles and elliptical arcs, and their Path form.
//
//   R(t) = sum w_i P_i B_i(t) / sum w_i B_i(t),  all weights w_i > 0.
//
// Evaluation runs de Casteljau / de Boor on homogeneous points (w P, w) and divides once at the end.
// Conics: a rational quadratic with end weights 1 and middle weight w is an ellipse arc for w < 1, a
// parabola for w = 1 and a hyperbola for w > 1; a circular arc of sweep theta has its middle control
// point where the end tangents meet and w = cos(theta / 2).
//
// Path route: rational quadratics go to the rasterizer as Path's Conic verb
// (Path::conic_to, after reparametrising to end weights 1); the flattener bounds the conic's
// flatness itself. Rational lines become Line verbs. Rational curves of degree >= 3 are approximated
// by polynomial cubics with a proven bound: for a piece R = A / w and its Hermite cubic C (same ends,
// same end derivatives), A - w C is a polynomial of degree n + 3 whose Bernstein coefficients
// bound it, and w(t) >= min w_i, so |R - C| <= max_k |coef_k| / min_i w_i. Pieces are halved
// until that is below the tolerance (depth limited by limits::kMaxCubicApproxDepth).
//
// Conventions and limits as in bezier.hpp (t in [0, 1], degree <= 64) and spline.hpp (knots).
// Errors: Error(InvalidData) for zero, negative or non-finite weights, or weight and point counts
// that differ, plus everything Bezier and BSpline reject.
// Thread-safety: immutable values; concurrent const use is safe. No global state.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "casteljau/bezier.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/path.hpp"
#include "casteljau/spline.hpp"
#include "casteljau/vec.hpp"

namespace casteljau {

template <CurvePoint P>
class RationalBezier {
public:
    using point_type = P;

    RationalBezier(std::vector<P> control_points, std::vector<double> weights);
    // All weights 1: the polynomial curve.
    explicit RationalBezier(const Bezier<P>& curve);

    int degree() const { return static_cast<int>(points_.size()) - 1; }
    std::span<const P> points() const { return points_; }
    std::span<const double> weights() const { return weights_; }

    // Rational de Casteljau (on (w P, w)).
    P eval(double t) const;
    P operator()(double t) const { return eval(t); }
    // k-th derivative by the quotient rule on the homogeneous derivatives:
    // R^(k) = (A^(k) - sum_{i=1..k} C(k,i) w^(i) R^(k-i)) / w.
    P derivative(int k, double t) const;
    std::pair<RationalBezier, RationalBezier> split(double t) const;
    // The same point set with w_0 = w_n = 1 (a Möbius reparametrisation w_i -> w_i rho^i / w_0 with
    // rho = (w_0 / w_n)^(1/n)); a conic in this form has the single weight Path::conic_to expects.
    RationalBezier normalized() const;
    Box<P> control_bounds() const;

private:
    std::vector<P> points_;
    std::vector<double> weights_;
};

template <CurvePoint P>
class Nurbs {
public:
    using point_type = P;

    Nurbs(int degree, std::vector<P> control_points, std::vector<double> weights, std::vector<double> knots);
    // Unit weights.
    explicit Nurbs(const BSpline<P>& spline);

    int degree() const { return degree_; }
    std::span<const P> points() const { return points_; }
    std::span<const double> weights() const { return weights_; }
    std::span<const double> knots() const { return knots_; }
    double domain_start() const { return knots_[static_cast<std::size_t>(degree_)]; }
    double domain_end() const { return knots_[points_.size()]; }

    // De Boor on homogeneous points; t must lie in the domain.
    P eval(double t) const;
    P operator()(double t) const { return eval(t); }
    P derivative(int k, double t) const;
    // Boehm insertion on homogeneous points (the curve is unchanged).
    Nurbs with_knot(double u, int times = 1) const;
    // One rational Bézier of degree p per non-empty span of the domain.
    std::vector<RationalBezier<P>> to_bezier() const;
    std::vector<double> breakpoints() const;

private:
    int degree_ = 0;
    std::vector<P> points_;
    std::vector<double> weights_;
    std::vector<double> knots_;
};

// ---- conics -------------------------------------------------------------------------------------

enum class ConicKind { Ellipse, Parabola, Hyperbola };
// For a conic in standard form (end weights 1, middle weight w > 0).
ConicKind conic_kind(double w);

// The rational quadratic (p0, p1, p2) with weights (1, w, 1).
RationalBezier<Point> conic(Point p0, Point p1, Point p2, double w);
// A circular arc as one rational quadratic: centre, radius, start angle and sweep in radians
// (0 < |sweep| < pi; positive sweeps turn from +x towards +y). Middle weight cos(sweep / 2).
RationalBezier<Point> circular_arc(Point center, double radius, double start, double sweep);
// An elliptical arc (radii rx, ry, the ellipse rotated by `rotation` radians) as a quadratic NURBS
// made of ceil(|sweep| / (pi/2)) equal pieces, each an exact rational quadratic; |sweep| <= 2 pi.
Nurbs<Point> nurbs_ellipse_arc(Point center, double rx, double ry, double rotation, double start, double sweep);
// The full circle: 9 control points on the square around it, weights 1 and sqrt(2)/2, knots
// {0,0,0, 1/4,1/4, 1/2,1/2, 3/4,3/4, 1,1,1}; starts at angle 0 and turns from +x towards +y.
Nurbs<Point> nurbs_circle(Point center, double radius);

// ---- bridge to the rasterizer (see the header comment for the routes) -------------------------

// Appends like the Bézier version (continues the contour when the path's current point is the
// curve's start). Returns the proven error bound achieved (0 for degree <= 2).
double append_to_path(Path& path, const RationalBezier<Point>& curve, double tolerance = 0.01);
Path to_path(const RationalBezier<Point>& curve, double tolerance = 0.01);
Path to_path(const Nurbs<Point>& curve, double tolerance = 0.01);

extern template class RationalBezier<Point>;
extern template class RationalBezier<Point3>;
extern template class Nurbs<Point>;
extern template class Nurbs<Point3>;

}  // namespace casteljau
