// Curve toolkit: knot vectors, B-spline basis functions and B-spline curves
// (include/casteljau/spline.hpp).
#include <algorithm>
#include <cmath>
#include <string>

#include "casteljau/limits.hpp"
#include "casteljau/spline.hpp"
#include "curves/bspline_core.hpp"

namespace casteljau {

using namespace curves_detail;

namespace curves_detail {

void validate_curve_degree(int degree, const char* what) {
    if (degree < 1)
        throw Error(ErrorKind::InvalidArgument,
                    std::string(what) + " degree must be at least 1, got " + std::to_string(degree));
    if (degree > limits::kMaxSplineDegree)
        throw Error(ErrorKind::Limit, std::string(what) + " degree " + std::to_string(degree) +
                                          " exceeds the limit of " + std::to_string(limits::kMaxSplineDegree));
}

void validate_weights(std::span<const double> w, std::size_t count, const char* what) {
    if (w.size() != count)
        throw Error(ErrorKind::InvalidData, std::string(what) + " has " + std::to_string(w.size()) + " weights for " +
                                                std::to_string(count) + " control points");
    for (std::size_t i = 0; i < w.size(); ++i)
        if (!(w[i] > 0) || !std::isfinite(w[i]))
            throw Error(ErrorKind::InvalidData, std::string(what) + " weight " + std::to_string(i) + " is " +
                                                    num(w[i]) + "; weights must be positive and finite");
}

}  // namespace curves_detail

// ---- knot vectors -------------------------------------------------------------------------------

void validate_knots(int degree, std::size_t count, std::span<const double> knots) {
    if (degree < 0)
        throw Error(ErrorKind::InvalidArgument, "B-spline degree must be >= 0, got " + std::to_string(degree));
    if (degree > limits::kMaxSplineDegree)
        throw Error(ErrorKind::Limit, "B-spline degree " + std::to_string(degree) + " exceeds the limit of " +
                                          std::to_string(limits::kMaxSplineDegree));
    if (count > limits::kMaxSplinePoints)
        throw Error(ErrorKind::Limit, "B-spline has " + std::to_string(count) + " control points; the limit is " +
                                          std::to_string(limits::kMaxSplinePoints));
    const auto p = static_cast<std::size_t>(degree);
    if (count < 2 || count < p + 1)
        throw Error(ErrorKind::InvalidData, "a degree-" + std::to_string(degree) + " B-spline needs at least " +
                                                std::to_string(std::max<std::size_t>(2, p + 1)) +
                                                " control points, got " + std::to_string(count));
    if (knots.size() != count + p + 1)
        throw Error(ErrorKind::InvalidData, "knot vector has " + std::to_string(knots.size()) + " knots; " +
                                                std::to_string(count) + " control points of degree " +
                                                std::to_string(degree) + " need " + std::to_string(count + p + 1));
    std::size_t mult = 0;
    for (std::size_t i = 0; i < knots.size(); ++i) {
        if (!std::isfinite(knots[i]))
            throw Error(ErrorKind::InvalidData, "knot " + std::to_string(i) + " is not finite");
        if (i > 0 && knots[i] < knots[i - 1])
            throw Error(ErrorKind::InvalidData, "knots must be non-decreasing: knot " + std::to_string(i) + " = " +
                                                    num(knots[i]) + " follows " + num(knots[i - 1]));
        mult = (i > 0 && knots[i] == knots[i - 1]) ? mult + 1 : 1;
        if (mult > p + 1)
            throw Error(ErrorKind::InvalidData, "knot " + num(knots[i]) + " has multiplicity " + std::to_string(mult) +
                                                    ", more than degree + 1 = " + std::to_string(p + 1));
    }
    if (!(knots[p] < knots[count]))
        throw Error(ErrorKind::InvalidData, "the knot vector's domain [u_p, u_n] = [" + num(knots[p]) + ", " +
                                                num(knots[count]) + "] is empty");
}

std::vector<double> clamped_knots(int degree, std::size_t count) {
    if (degree < 0 || count < static_cast<std::size_t>(degree) + 1 || count < 2 || degree > limits::kMaxSplineDegree ||
        count > limits::kMaxSplinePoints) {
        validate_knots(degree, count, std::vector<double>{});  // throws the matching error
    }
    const auto p = static_cast<std::size_t>(degree);
    std::vector<double> u(count + p + 1);
    const std::size_t spans = count - p;
    for (std::size_t i = 0; i < u.size(); ++i) {
        if (i <= p)
            u[i] = 0;
        else if (i >= count)
            u[i] = 1;
        else
            u[i] = static_cast<double>(i - p) / static_cast<double>(spans);
    }
    return u;
}

std::vector<double> uniform_knots(int degree, std::size_t count) {
    if (degree < 0 || count < static_cast<std::size_t>(degree) + 1 || count < 2 || degree > limits::kMaxSplineDegree ||
        count > limits::kMaxSplinePoints) {
        validate_knots(degree, count, std::vector<double>{});
    }
    std::vector<double> u(count + static_cast<std::size_t>(degree) + 1);
    for (std::size_t i = 0; i < u.size(); ++i) u[i] = static_cast<double>(i);
    return u;
}

// ---- basis functions ----------------------------------------------------------------------------

std::vector<double> bspline_basis_all(int degree, std::span<const double> knots, double t) {
    if (degree < 0 || knots.size() < static_cast<std::size_t>(degree) + 3)
        throw Error(ErrorKind::InvalidData, "a degree-" + std::to_string(degree) + " basis needs at least " +
                                                std::to_string(degree + 3) + " knots, got " +
                                                std::to_string(knots.size()));
    const std::size_t count = knots.size() - static_cast<std::size_t>(degree) - 1;
    validate_knots(degree, count, knots);
    check_domain(degree, count, knots, t);
    const std::size_t m = knots.size() - 1;
    const std::size_t k = find_span(degree, count, knots, t);
    std::vector<double> N(m, 0.0);
    N[k] = 1;  // degree 0: the indicator of the span containing t
    for (std::size_t r = 1; r <= static_cast<std::size_t>(degree); ++r) {
        for (std::size_t j = 0; j + r < m; ++j) {
            const double d1 = knots[j + r] - knots[j], d2 = knots[j + r + 1] - knots[j + 1];
            const double a = d1 > 0 ? (t - knots[j]) / d1 : 0.0;
            const double b = d2 > 0 ? (knots[j + r + 1] - t) / d2 : 0.0;
            N[j] = a * N[j] + b * N[j + 1];
        }
    }
    N.resize(count);
    return N;
}

double bspline_basis(int i, int degree, std::span<const double> knots, double t) {
    const std::vector<double> N = bspline_basis_all(degree, knots, t);
    if (i < 0 || static_cast<std::size_t>(i) >= N.size()) return 0;
    return N[static_cast<std::size_t>(i)];
}

// ---- BSpline ------------------------------------------------------------------------------------

template <CurvePoint P>
BSpline<P>::BSpline(int degree, std::vector<P> control_points, std::vector<double> knots)
    : degree_(degree), points_(std::move(control_points)), knots_(std::move(knots)) {
    validate_curve_degree(degree_, "B-spline");
    validate_knots(degree_, points_.size(), knots_);
    validate_spline_points(points_, "B-spline");
}

template <CurvePoint P>
BSpline<P> BSpline<P>::clamped(int degree, std::vector<P> control_points) {
    validate_curve_degree(degree, "B-spline");
    auto knots = clamped_knots(degree, control_points.size());
    return BSpline(degree, std::move(control_points), std::move(knots));
}

template <CurvePoint P>
BSpline<P> BSpline<P>::uniform(int degree, std::vector<P> control_points) {
    validate_curve_degree(degree, "B-spline");
    auto knots = uniform_knots(degree, control_points.size());
    return BSpline(degree, std::move(control_points), std::move(knots));
}

template <CurvePoint P>
BSpline<P> BSpline<P>::periodic(int degree, std::vector<P> control_points) {
    validate_curve_degree(degree, "B-spline");
    if (control_points.size() < 2)
        throw Error(ErrorKind::InvalidData, "a periodic B-spline needs at least 2 control points, got " +
                                                std::to_string(control_points.size()));
    if (control_points.size() > limits::kMaxSplinePoints)
        throw Error(ErrorKind::Limit, "B-spline has too many control points");
    const std::size_t n = control_points.size();
    for (std::size_t i = 0; i < static_cast<std::size_t>(degree); ++i) control_points.push_back(control_points[i % n]);
    auto knots = uniform_knots(degree, control_points.size());
    return BSpline(degree, std::move(control_points), std::move(knots));
}

template <CurvePoint P>
std::size_t BSpline<P>::span_index(double t) const {
    check_domain(degree_, points_.size(), knots_, t);
    return find_span(degree_, points_.size(), knots_, t);
}

template <CurvePoint P>
P BSpline<P>::eval(double t) const {
    return derivative(0, t);
}

template <CurvePoint P>
P BSpline<P>::derivative(int k, double t) const {
    if (k < 0) throw Error(ErrorKind::InvalidArgument, "derivative order must be >= 0, got " + std::to_string(k));
    const std::size_t span = span_index(t);
    if (k > degree_) return P{};
    return de_boor<P>(degree_, knots_, span, k, t, [&](std::size_t i) { return points_[i]; });
}

template <CurvePoint P>
BSpline<P> BSpline<P>::with_knot(double u, int times) const {
    check_insertion(degree_, points_.size(), knots_, u, times);
    std::vector<P> ctrl = points_;
    std::vector<double> U = knots_;
    for (int i = 0; i < times; ++i) insert_knot(degree_, ctrl, U, u);
    return BSpline(degree_, std::move(ctrl), std::move(U));
}

template <CurvePoint P>
std::vector<Bezier<P>> BSpline<P>::to_bezier() const {
    auto pieces = spans_to_bezier<P>(degree_, points_.size(), knots_, [&](std::size_t i) { return points_[i]; });
    std::vector<Bezier<P>> out;
    out.reserve(pieces.size());
    for (auto& p : pieces) out.emplace_back(std::move(p));
    return out;
}

template <CurvePoint P>
std::vector<double> BSpline<P>::breakpoints() const {
    return domain_breakpoints(degree_, points_.size(), knots_);
}

template class BSpline<Point>;
template class BSpline<Point3>;

Path to_path(const BSpline<Point>& spline, double tolerance) {
    const auto pieces = spline.to_bezier();
    return to_path(std::span<const Bezier<Point>>(pieces), tolerance);
}

// ---- uniform cubic B-spline <-> Bézier ------------------------------------------------------------

std::array<double, 16> uniform_cubic_bspline_to_bezier_matrix() {
    constexpr double s = 1.0 / 6.0;
    return {1 * s, 4 * s, 1 * s, 0, 0, 4 * s, 2 * s, 0, 0, 2 * s, 4 * s, 0, 0, 1 * s, 4 * s, 1 * s};
}

std::array<double, 16> bezier_to_uniform_cubic_bspline_matrix() {
    return {6, -7, 2, 0, 0, 2, -1, 0, 0, -1, 2, 0, 0, 2, -7, 6};
}

namespace {
template <CurvePoint P>
std::array<P, 4> apply4(const std::array<double, 16>& M, const std::array<P, 4>& v) {
    std::array<P, 4> out{};
    for (std::size_t r = 0; r < 4; ++r)
        for (std::size_t c = 0; c < 4; ++c) out[r] += v[c] * M[r * 4 + c];
    return out;
}
}  // namespace

template <CurvePoint P>
std::array<P, 4> uniform_cubic_bspline_to_bezier(const std::array<P, 4>& d) {
    // B0 = (D0 + 4 D1 + D2)/6, B1 = (2 D1 + D2)/3, B2 = (D1 + 2 D2)/3, B3 = (D1 + 4 D2 + D3)/6.
    return apply4(uniform_cubic_bspline_to_bezier_matrix(), d);
}

template <CurvePoint P>
std::array<P, 4> bezier_to_uniform_cubic_bspline(const std::array<P, 4>& b) {
    return apply4(bezier_to_uniform_cubic_bspline_matrix(), b);
}

template std::array<Point, 4> uniform_cubic_bspline_to_bezier(const std::array<Point, 4>&);
template std::array<Point3, 4> uniform_cubic_bspline_to_bezier(const std::array<Point3, 4>&);
template std::array<Point, 4> bezier_to_uniform_cubic_bspline(const std::array<Point, 4>&);
template std::array<Point3, 4> bezier_to_uniform_cubic_bspline(const std::array<Point3, 4>&);

}  // namespace casteljau
