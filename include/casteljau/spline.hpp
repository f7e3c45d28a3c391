// casteljau/spline.hpp: B-splines (Cox-de Boor basis, de Boor evaluation, derivatives, Boehm knot
// insertion, conversion to Bézier pieces), the uniform cubic B-spline <-> Bézier matrices, and the
// interpolating splines (Hermite, Cardinal, Catmull-Rom, Kochanek-Bartels, natural cubic), each
// convertible to cubic Béziers and to a Path. Rational curves (NURBS, conics) are in nurbs.hpp.
//
// Conventions: a B-spline of degree p (order p + 1) with n control points has n + p + 1
// non-decreasing knots u_0..u_(n+p); its domain is [u_p, u_n], where the basis functions sum to 1.
// Spans are half-open [u_k, u_(k+1)) except that the domain's end belongs to the last non-empty
// span. Knot vectors: clamped_knots (open uniform on [0, 1], the curve interpolates its end control
// points), uniform_knots (0, 1, ..., n + p: the curve starts and ends inside the polygon),
// BSpline::periodic (closed, uniform, p control points wrapped), or any non-decreasing vector with
// multiplicities up to p + 1 (multiplicity r gives continuity C^(p-r) at that knot).
// Interpolating splines: piece i runs from point i to point i + 1 over its own t in [0, 1].
// Limits: degree 1..limits::kMaxSplineDegree (64) for curves (0..64 for basis functions alone),
// at most limits::kMaxSplinePoints control points.
// Errors: Error(InvalidData) for fewer than 2 points (or fewer than degree + 1), a knot vector of
// the wrong length, decreasing or non-finite knots, a multiplicity above p + 1, an empty domain or
// non-finite points; Error(InvalidArgument) for degree 0, a parameter outside the domain or a bad
// tension; Error(Limit) for degree > 64 or too many points.
// Thread-safety: immutable values; concurrent const use is safe. No global state.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "casteljau/bezier.hpp"
#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/path.hpp"
#include "casteljau/vec.hpp"

namespace casteljau {

// ---- knot vectors and basis functions -----------------------------------------------------------

// Open uniform (clamped) knots on [0, 1] for `count` control points: p + 1 zeros, the interior knots
// i / (count - p), p + 1 ones.
std::vector<double> clamped_knots(int degree, std::size_t count);
// Uniform knots 0, 1, ..., count + degree (domain [degree, count]).
std::vector<double> uniform_knots(int degree, std::size_t count);
// Checks everything the Errors paragraph above lists for a knot vector of `count` control points
// (degree 0 is accepted here: basis functions of degree 0 are the span indicators).
void validate_knots(int degree, std::size_t count, std::span<const double> knots);

// N_(i,p)(t) by the Cox-de Boor recursion N_(i,p) = (t - u_i)/(u_(i+p) - u_i) N_(i,p-1)
// + (u_(i+p+1) - t)/(u_(i+p+1) - u_(i+1)) N_(i+1,p-1), with 0/0 taken as 0, evaluated bottom-up
// (O(m p), not the exponential literal recursion). t must lie in the domain [u_p, u_(m-p)].
double bspline_basis(int i, int degree, std::span<const double> knots, double t);
// All N_(0,p)(t) .. N_(count-1,p)(t), count = knots.size() - p - 1 (non-negative, sum 1 in the domain).
std::vector<double> bspline_basis_all(int degree, std::span<const double> knots, double t);

// ---- B-spline curves ----------------------------------------------------------------------------

template <CurvePoint P>
class BSpline {
public:
    using point_type = P;

    BSpline(int degree, std::vector<P> control_points, std::vector<double> knots);
    // Open uniform knots on [0, 1]: interpolates the first and last control points.
    static BSpline clamped(int degree, std::vector<P> control_points);
    // Uniform integer knots 0..n+p: domain [p, n].
    static BSpline uniform(int degree, std::vector<P> control_points);
    // Closed curve: the first `degree` control points are appended again and the knots are uniform,
    // so the curve is C^(p-1) everywhere including the seam. Domain [p, n + p].
    static BSpline periodic(int degree, std::vector<P> control_points);

    int degree() const { return degree_; }
    std::span<const P> points() const { return points_; }
    std::span<const double> knots() const { return knots_; }
    double domain_start() const { return knots_[static_cast<std::size_t>(degree_)]; }
    double domain_end() const { return knots_[points_.size()]; }
    // k with u_k <= t < u_(k+1), p <= k < n (the last non-empty span for t = domain_end()).
    std::size_t span_index(double t) const;

    // De Boor's algorithm. Throws Error(InvalidArgument) for t outside the domain.
    P eval(double t) const;
    P operator()(double t) const { return eval(t); }
    // k-th derivative (k >= 0; k > degree gives zero), from the derivative control points
    // p (P_(i+1) - P_i) / (u_(i+p+1) - u_(i+1)). At a knot the right-hand derivative is returned
    // (the left-hand one at the domain's end).
    P derivative(int k, double t) const;
    // Boehm's algorithm: inserts u (in the domain) `times` times; the curve is unchanged. Throws
    // Error(InvalidArgument) when the multiplicity would exceed p + 1.
    BSpline with_knot(double u, int times = 1) const;
    // One Bézier piece of degree p per non-empty knot span in the domain, in order. Piece j is the
    // spline over [breakpoints()[j], breakpoints()[j+1]] reparametrised to [0, 1]. Its control points
    // are the blossom values f(a^(p-i), b^i) of that span (de Boor's algorithm with a different
    // parameter at each level), which is what inserting every knot until multiplicity p yields.
    std::vector<Bezier<P>> to_bezier() const;
    // The distinct knot values in the domain, ascending (to_bezier().size() + 1 values).
    std::vector<double> breakpoints() const;

private:
    int degree_ = 0;
    std::vector<P> points_;
    std::vector<double> knots_;
};

// Uniform cubic B-spline segment <-> cubic Bézier (the textbook matrices, row-major, B = M D):
// M = 1/6 [1 4 1 0; 0 4 2 0; 0 2 4 0; 0 1 4 1] and its inverse [6 -7 2 0; 0 2 -1 0; 0 -1 2 0; 0 2 -7 6].
std::array<double, 16> uniform_cubic_bspline_to_bezier_matrix();
std::array<double, 16> bezier_to_uniform_cubic_bspline_matrix();
template <CurvePoint P>
std::array<P, 4> uniform_cubic_bspline_to_bezier(const std::array<P, 4>& d);
template <CurvePoint P>
std::array<P, 4> bezier_to_uniform_cubic_bspline(const std::array<P, 4>& b);

// ---- interpolating splines ----------------------------------------------------------------------

// Hermite basis matrix (row-major): P(t) = [t^3 t^2 t 1] Mh [p0 p1 m0 m1]^T,
// Mh = [2 -2 1 1; -3 3 -2 -1; 0 0 1 0; 1 0 0 0].
std::array<double, 16> hermite_matrix();
template <CurvePoint P>
P hermite_eval(const P& p0, const P& m0, const P& p1, const P& m1, double t);
// The same cubic in Bézier form: (p0, p0 + m0/3, p1 - m1/3, p1).
template <CurvePoint P>
Bezier<P> hermite_to_bezier(const P& p0, const P& m0, const P& p1, const P& m1);
// Pieces through points[i] with tangents[i] (equal sizes, at least 2).
template <CurvePoint P>
std::vector<Bezier<P>> hermite_spline(std::span<const P> points, std::span<const P> tangents);

// How a Cardinal / Catmull-Rom / Kochanek-Bartels spline treats its ends.
enum class EndCondition {
    Duplicate,  // through every point; the missing neighbours of the ends are the end points themselves
    Closed,     // through every point and back to the first (one more piece; needs 3 points)
    Inner,      // the textbook form: the first and last points only steer (needs 4 points)
};

// Tangent m_i = (1 - tension) (P_(i+1) - P_(i-1)) / 2; tension 0 is Catmull-Rom, 1 gives lines.
template <CurvePoint P>
std::vector<Bezier<P>> cardinal_spline(std::span<const P> points, double tension,
                                       EndCondition ends = EndCondition::Duplicate);
template <CurvePoint P>
std::vector<Bezier<P>> catmull_rom_spline(std::span<const P> points, EndCondition ends = EndCondition::Duplicate);

struct KbParams {
    double tension = 0, continuity = 0, bias = 0;
};
// Kochanek-Bartels: the piece from P_i to P_(i+1) leaves P_i with
//   (1-t)(1+b)(1+c)/2 (P_i - P_(i-1)) + (1-t)(1-b)(1-c)/2 (P_(i+1) - P_i)
// and arrives at P_(i+1) with
//   (1-t)(1+b)(1-c)/2 (P_(i+1) - P_i) + (1-t)(1-b)(1+c)/2 (P_(i+2) - P_(i+1)).
// t = c = b = 0 is Catmull-Rom; c = -1 gives straight pieces (box corners).
template <CurvePoint P>
std::vector<Bezier<P>> kochanek_bartels_spline(std::span<const P> points, const KbParams& params,
                                               EndCondition ends = EndCondition::Duplicate);

enum class Parametrization {
    Uniform,      // parameter steps 1
    ChordLength,  // steps |P_(i+1) - P_i|
    Centripetal,  // steps sqrt(|P_(i+1) - P_i|)
};
// The natural cubic spline through the points (second derivative 0 at both ends, C2 in the chosen
// parametrisation), from the tridiagonal system for the second derivatives (Thomas algorithm: the
// matrix is strictly diagonally dominant). Non-uniform parametrisations reject coincident
// consecutive points (Error(InvalidData)).
template <CurvePoint P>
std::vector<Bezier<P>> natural_spline(std::span<const P> points, Parametrization param = Parametrization::Uniform);

// ---- bridge to the rasterizer -------------------------------------------------------------------

// Degree <= 3 pieces map to verbs exactly; higher degrees use the proven cubic approximation of
// append_to_path in bezier.hpp.
Path to_path(const BSpline<Point>& spline, double tolerance = 0.01);

extern template class BSpline<Point>;
extern template class BSpline<Point3>;

}  // namespace casteljau
