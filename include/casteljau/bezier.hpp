// casteljau/bezier.hpp: Bézier curves of any degree (2-D Point or 3-D Point3), the Bernstein basis,
// and the bridge from Bézier curves to Path.
//
//   P(t) = sum_{i=0..n} P_i B_{i,n}(t),  B_{i,n}(t) = C(n,i) t^i (1-t)^(n-i),  t in [0, 1].
//
// What is here: de Casteljau evaluation (the reference) and the Bernstein form with Horner's rule;
// derivatives of any order (forward differences: the hodograph); curvature; the complete de Casteljau
// triangle; split, sub-curve, blossom; exact degree elevation; degree reduction (forward, backward,
// combined), each reporting its deviation; power (monomial / matrix) form both ways; tight bounding
// boxes from the roots of the derivative (robust Bernstein root isolation, any degree); cubic
// interpolation through 4 points; G0/G1/G2 joins; conversion to Path.
//
// Conventions: the parameter is t in [0, 1]; methods that take t throw Error(InvalidArgument)
// outside it (and for NaN). Points use whatever space the caller works in; nothing here assumes
// y-up or y-down, except that signed_curvature is positive where the curve turns from +x towards +y.
// Limits: 2 to limits::kMaxBezierDegree + 1 control points (degree 1..64). De Casteljau and the
// Bernstein-Horner form are stable at every degree; the power form is ill-conditioned (its
// coefficients grow like 2^n C(n,k)) and agrees with de Casteljau to 1e-12 relative only for low
// degrees (about 8 and below); use it for display and algebra, not evaluation of high degrees.
// Errors: Error(InvalidData) for fewer than 2 or non-finite control points, Error(Limit) for degree
// > 64, Error(InvalidArgument) for a parameter outside its domain.
// Thread-safety: Bezier is an immutable value; concurrent const use is safe. No global state.
#pragma once

#include <initializer_list>
#include <span>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/path.hpp"
#include "casteljau/vec.hpp"

namespace casteljau {

// ---- Bernstein basis --------------------------------------------------------------------------

// C(n, k) as a double (exact up to n = 56 or so, then correctly rounded to 1 ulp or two).
double binomial(int n, int k);
// B_{i,n}(t) for 0 <= i <= n; 0 outside that range. Any t (no domain check: the basis is a polynomial).
double bernstein(int i, int n, double t);
// All n + 1 values B_{0,n}(t) .. B_{n,n}(t) computed by the de Casteljau triangle (non-negative and
// summing to 1 up to rounding for t in [0, 1]). out.size() must be n + 1.
void bernstein_all(int n, double t, std::span<double> out);
// The (n+1) x (n+1) row-major matrix M with a_k = sum_i M[k][i] P_i, where P(t) = sum_k a_k t^k:
// M[k][i] = (-1)^(k-i) C(n,k) C(k,i) for i <= k. For n = 3 the rows are the textbook's
// (1 0 0 0), (-3 3 0 0), (3 -6 3 0), (-1 3 -3 1) (in ascending powers of t).
std::vector<double> bernstein_to_power_matrix(int n);
// Real roots in [0, 1] of the scalar polynomial sum c_i B_{i,n}(t), n = c.size() - 1, ascending.
// Method: Descartes' rule of signs on Bernstein coefficients (the number of sign changes bounds the
// number of roots and has the same parity), de Casteljau subdivision at 1/2 to isolate roots, then
// bisection on an interval with exactly one sign change. Depth-limited (intervals of width 2^-52),
// so clusters and multiple roots are reported as one root at the cluster; an identically zero
// polynomial (all |c_i| <= 1e-300) reports no roots. Never loops without end.
std::vector<double> bernstein_roots(std::span<const double> c);

// ---- Bézier curves ----------------------------------------------------------------------------

// Power (monomial) form P(t) = sum_k a_k t^k, k = 0..n.
template <CurvePoint P>
struct PowerForm {
    std::vector<P> coefficients;  // a_0 .. a_n

    int degree() const { return static_cast<int>(coefficients.size()) - 1; }
    // Horner's rule; any t.
    P eval(double t) const;
};

template <CurvePoint P>
class Bezier {
public:
    using point_type = P;

    // Throws Error(InvalidData) for fewer than 2 points or a non-finite coordinate, Error(Limit)
    // for more than kMaxBezierDegree + 1 points.
    explicit Bezier(std::vector<P> control_points);
    Bezier(std::initializer_list<P> control_points) : Bezier(std::vector<P>(control_points)) {}

    int degree() const { return static_cast<int>(points_.size()) - 1; }
    std::span<const P> points() const { return points_; }
    const P& operator[](std::size_t i) const { return points_[i]; }
    const P& front() const { return points_.front(); }
    const P& back() const { return points_.back(); }

    // De Casteljau's algorithm: the reference evaluation, O(n^2), no allocation.
    P eval(double t) const;
    P operator()(double t) const { return eval(t); }
    // Bernstein form with Horner's rule: s^n sum C(n,i) P_i (t/s)^i for t <= 1/2 (s = 1 - t) and the
    // mirrored form in s/t above 1/2, so the ratio never exceeds 1. O(n), agrees with eval to 1e-12
    // relative (measured over random curves up to degree 64 in tests/curves/test_bezier.cpp).
    P eval_bernstein(double t) const;
    // The k-th derivative (k >= 0; k > degree gives the zero vector):
    // n!/(n-k)! sum_i Delta^k P_i B_{i,n-k}(t).
    P derivative(int k, double t) const;
    // Control points of the k-th derivative curve (degree n - k): n!/(n-k)! Delta^k P_i,
    // i = 0..n-k; a single zero point for k > n. k = 1 is the hodograph.
    std::vector<P> derivative_points(int k = 1) const;
    // Curvature |P' x P''| / |P'|^3 (any dimension: sqrt(|P'|^2 |P''|^2 - (P'.P'')^2) / |P'|^3).
    // +infinity where the speed |P'(t)| is exactly 0 (a cusp or a coincident end control point).
    double curvature(double t) const;
    // 2-D only: (x' y'' - y' x'') / |P'|^3, positive where the curve turns from +x towards +y.
    double signed_curvature(double t) const requires std::same_as<P, Point>;

    // The complete de Casteljau triangle at t: row r (r = 0..n) holds the n + 1 - r points
    // P_i^r = (1-t) P_i^(r-1) + t P_(i+1)^(r-1); row 0 is the control polygon, row n is P(t).
    std::vector<std::vector<P>> triangle(double t) const;
    // The two halves at t: the left edge of the triangle (P_0^0, P_0^1, ..., P_0^n) and the right
    // edge (P_0^n, P_1^(n-1), ..., P_n^0). t = 0 or 1 gives a degenerate (single-point) half.
    std::pair<Bezier, Bezier> split(double t) const;
    // The curve restricted to [t0, t1] and reparametrised to [0, 1]; t0 > t1 gives it reversed.
    // Control points are blossom values f(t0^(n-i), t1^i), computed directly (no repeated splits).
    Bezier subcurve(double t0, double t1) const;
    // The blossom (polar form) f(u_1, ..., u_n): symmetric, multi-affine, f(t, ..., t) = P(t).
    // args.size() must equal degree(); arguments may lie outside [0, 1].
    P blossom(std::span<const double> args) const;
    // The same curve traversed backwards: P*(t) = P(1 - t).
    Bezier reversed() const;

    // Exact degree elevation, `times` times: P*_i = (i/(n+1)) P_(i-1) + (1 - i/(n+1)) P_i.
    Bezier elevated(int times = 1) const;

    PowerForm<P> to_power() const;
    // Throws Error(InvalidData) for fewer than 2 coefficients (as the constructor).
    static Bezier from_power(const PowerForm<P>& power);

    // Tight axis-aligned bounds: the end points and the curve at every root of each coordinate of
    // the derivative (bernstein_roots on the hodograph).
    Box<P> bounds() const;
    // The box of the control points (contains the curve: convex hull property).
    Box<P> control_bounds() const;
    // Parameters in (0, 1) where coordinate `axis` of the derivative vanishes, ascending.
    std::vector<double> extrema(int axis) const;

    bool operator==(const Bezier&) const = default;

private:
    struct Unchecked {};
    // For results of convex combinations of valid control points (always finite, same count rules).
    Bezier(std::vector<P> pts, Unchecked) : points_(std::move(pts)) {}
    std::vector<P> points_;
};

// ---- degree reduction -------------------------------------------------------------------------

enum class ReductionMethod {
    Forward,   // P*_i = (n P_i - i P*_(i-1)) / (n - i), i = 0..n-1: exact at and near P_0
    Backward,  // P*_(i-1) = (n P_i - (n-i) P*_i) / i, i = n..1: exact at and near P_n
    Combined,  // forward for the first half, backward for the second, the middle point averaged
};

template <CurvePoint P>
struct Reduction {
    Bezier<P> curve;  // degree n - 1
    // Largest |P(t) - Q(t)| measured at 64 n + 1 equally spaced parameters.
    double max_deviation = 0;
    // A proven bound of the same quantity over all t: the largest distance between the control
    // points of P and of Q elevated back to degree n (convex hull of the difference curve).
    double deviation_bound = 0;
};

// Degree n -> n - 1. Throws Error(InvalidArgument) for a line (degree 1: nothing to reduce to).
// Reducing a curve that was elevated from degree n - 1 returns the original up to rounding.
template <CurvePoint P>
Reduction<P> reduce_degree(const Bezier<P>& curve, ReductionMethod method);

// ---- interpolation ----------------------------------------------------------------------------

// The cubic through q0, q1, q2, q3 at t = 0, 1/3, 2/3, 1:
// P1 = (-5 q0 + 18 q1 - 9 q2 + 2 q3) / 6, P2 = (2 q0 - 9 q1 + 18 q2 - 5 q3) / 6.
template <CurvePoint P>
Bezier<P> interpolate_cubic(const P& q0, const P& q1, const P& q2, const P& q3);

// ---- joins ------------------------------------------------------------------------------------

enum class Continuity { None, G0, G1, G2 };

struct JoinTolerance {
    double position = 1e-9;   // |P_n - Q_0| (absolute, in the curve's units)
    double angle = 1e-9;      // angle between the end tangent and the start tangent (radians)
    double curvature = 1e-9;  // |k_a - k_b| <= curvature x max(|k_a|, |k_b|) for the curvature vectors
};

// The highest geometric continuity with which `b` continues `a` at a's end and b's start.
// G1: the tangent directions agree (the first non-zero forward difference at each end is used, so a
// coincident control point does not hide a tangent); G2: additionally the curvature vectors agree.
template <CurvePoint P>
Continuity join_continuity(const Bezier<P>& a, const Bezier<P>& b, const JoinTolerance& tolerance = {});

// The first control points of the next curve (degree m; m = 0 means a's degree n) for a G1 join with
// Q'(0) = alpha P'(1), alpha > 0: Q0 = P_n, Q1 = P_n + alpha (n/m) (P_n - P_(n-1)). Returns {Q0, Q1}.
template <CurvePoint P>
std::vector<P> g1_join_points(const Bezier<P>& a, double alpha, int next_degree = 0);
// ... and for a G2 join with Q''(0) = alpha^2 P''(1) + beta P'(1) (a needs degree >= 2). For m = n
// this is the textbook Q2 - P_n = (alpha^2 + 2 alpha + beta/(n-1)) (P_n - P_(n-1))
//                                 - alpha^2 (P_(n-1) - P_(n-2)). Returns {Q0, Q1, Q2}.
template <CurvePoint P>
std::vector<P> g2_join_points(const Bezier<P>& a, double alpha, double beta, int next_degree = 0);

// ---- bridge to the rasterizer -----------------------------------------------------------------
//
// Degree 1, 2 and 3 map to Line, Quad and Cubic verbs exactly. Higher degrees are approximated by
// cubics: each piece gets the Hermite cubic with the same end points and end derivatives, and the
// piece is halved (de Casteljau) until the proven bound max_i |P_i - E_i| <= tolerance, where E is
// that cubic elevated to the piece's degree (the difference curve lies in the convex hull of
// P_i - E_i, so |P(t) - C(t)| <= the bound for every t). Tolerance is in the curve's units.

// Appends `curve` to `path`, continuing the current contour when the path's current point equals
// the curve's start and starting a new contour (move_to) otherwise. Returns the error bound
// achieved (0 for degree <= 3). Throws Error(InvalidArgument) for a tolerance that is not > 0.
double append_to_path(Path& path, const Bezier<Point>& curve, double tolerance = 0.01);
Path to_path(const Bezier<Point>& curve, double tolerance = 0.01);
// Consecutive pieces share a contour when one ends where the next begins.
Path to_path(std::span<const Bezier<Point>> pieces, double tolerance = 0.01);

extern template class Bezier<Point>;
extern template class Bezier<Point3>;

}  // namespace casteljau
