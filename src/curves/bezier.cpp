// Curve toolkit: Bézier curves of any degree (include/casteljau/bezier.hpp).
#include "casteljau/bezier.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "casteljau/limits.hpp"
#include "curves/curve_util.hpp"

namespace casteljau {

using namespace curves_detail;

namespace {

template <CurvePoint P>
void validate_points(const std::vector<P>& pts, const char* what) {
    if (pts.size() < 2)
        throw Error(ErrorKind::InvalidData,
                    std::string(what) + " needs at least 2 control points, got " + std::to_string(pts.size()));
    if (pts.size() > static_cast<std::size_t>(limits::kMaxBezierDegree) + 1)
        throw Error(ErrorKind::Limit, std::string(what) + " degree " + std::to_string(pts.size() - 1) +
                                          " exceeds the limit of " + std::to_string(limits::kMaxBezierDegree));
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (!pts[i].is_finite())
            throw Error(ErrorKind::InvalidData,
                        std::string(what) + " control point " + std::to_string(i) + " is not finite");
}

// Forward differences of order k of pts, scaled by n!/(n-k)!, into out[0..n-k].
template <CurvePoint P>
int derivative_into(std::span<const P> pts, int k, P* out) {
    const int n = static_cast<int>(pts.size()) - 1;
    if (k > n) {
        out[0] = P{};
        return 0;
    }
    for (int i = 0; i <= n; ++i) out[i] = pts[static_cast<std::size_t>(i)];
    double scale = 1;
    for (int r = 1; r <= k; ++r) {
        for (int i = 0; i <= n - r; ++i) out[i] = out[i + 1] - out[i];
        scale *= n - r + 1;
    }
    for (int i = 0; i <= n - k; ++i) out[i] *= scale;
    return n - k;
}

}  // namespace

// ---- PowerForm ----------------------------------------------------------------------------------

template <CurvePoint P>
P PowerForm<P>::eval(double t) const {
    if (coefficients.empty()) return P{};
    P acc = coefficients.back();
    for (std::size_t k = coefficients.size() - 1; k-- > 0;) acc = acc * t + coefficients[k];
    return acc;
}

// ---- Bezier -------------------------------------------------------------------------------------

template <CurvePoint P>
Bezier<P>::Bezier(std::vector<P> control_points) : points_(std::move(control_points)) {
    validate_points(points_, "Bezier curve");
}

template <CurvePoint P>
P Bezier<P>::eval(double t) const {
    check_t(t);
    std::array<P, kBuf> b;
    std::copy(points_.begin(), points_.end(), b.begin());
    return de_casteljau_inplace(b.data(), degree(), t);
}

template <CurvePoint P>
P Bezier<P>::eval_bernstein(double t) const {
    check_t(t);
    const int n = degree();
    const double s = 1 - t;
    if (t <= 0.5) {
        // s^n sum_i C(n,i) P_i u^i, u = t/s <= 1; Horner from i = n down, C(n,i-1) = C(n,i) i/(n-i+1).
        const double u = t / s;
        double c = 1;  // C(n, n)
        P acc = points_[static_cast<std::size_t>(n)];
        for (int i = n; i >= 1; --i) {
            c = c * i / (n - i + 1);
            acc = acc * u + points_[static_cast<std::size_t>(i - 1)] * c;
        }
        return acc * std::pow(s, n);
    }
    // t^n sum_i C(n,i) P_i v^(n-i), v = s/t < 1; Horner from i = 0 up.
    const double v = s / t;
    double c = 1;  // C(n, 0)
    P acc = points_[0];
    for (int i = 0; i < n; ++i) {
        c = c * (n - i) / (i + 1);
        acc = acc * v + points_[static_cast<std::size_t>(i + 1)] * c;
    }
    return acc * std::pow(t, n);
}

template <CurvePoint P>
std::vector<P> Bezier<P>::derivative_points(int k) const {
    if (k < 0) throw Error(ErrorKind::InvalidArgument, "derivative order must be >= 0, got " + std::to_string(k));
    std::array<P, kBuf> b;
    const int m = derivative_into(points(), k, b.data());
    return std::vector<P>(b.begin(), b.begin() + m + 1);
}

template <CurvePoint P>
P Bezier<P>::derivative(int k, double t) const {
    if (k < 0) throw Error(ErrorKind::InvalidArgument, "derivative order must be >= 0, got " + std::to_string(k));
    check_t(t);
    std::array<P, kBuf> b;
    const int m = derivative_into(points(), k, b.data());
    return de_casteljau_inplace(b.data(), m, t);
}

template <CurvePoint P>
double Bezier<P>::curvature(double t) const {
    const P d1 = derivative(1, t), d2 = derivative(2, t);
    const double speed = d1.length();
    if (speed == 0) return std::numeric_limits<double>::infinity();
    return cross_norm(d1, d2) / (speed * speed * speed);
}

template <CurvePoint P>
double Bezier<P>::signed_curvature(double t) const requires std::same_as<P, Point> {
    const P d1 = derivative(1, t), d2 = derivative(2, t);
    const double speed = d1.length();
    if (speed == 0) return std::numeric_limits<double>::infinity();
    // clang 14 instantiates this member for every P despite the requires clause; if constexpr
    // keeps the 2-D cross product out of the Point3 instantiation.
    if constexpr (std::same_as<P, Point>)
        return d1.cross(d2) / (speed * speed * speed);
    else
        return 0;
}

template <CurvePoint P>
std::vector<std::vector<P>> Bezier<P>::triangle(double t) const {
    check_t(t);
    const int n = degree();
    std::vector<std::vector<P>> rows;
    rows.reserve(static_cast<std::size_t>(n) + 1);
    rows.push_back(points_);
    for (int r = 1; r <= n; ++r) {
        const auto& prev = rows.back();
        std::vector<P> row(prev.size() - 1);
        for (std::size_t i = 0; i < row.size(); ++i) row[i] = mix(prev[i], prev[i + 1], t);
        rows.push_back(std::move(row));
    }
    return rows;
}

template <CurvePoint P>
std::pair<Bezier<P>, Bezier<P>> Bezier<P>::split(double t) const {
    check_t(t);
    const int n = degree();
    std::vector<P> b = points_, left(points_.size()), right(points_.size());
    const auto N = static_cast<std::size_t>(n);
    left[0] = b[0];
    right[N] = b[N];
    for (std::size_t r = 1; r <= N; ++r) {
        for (std::size_t i = 0; i <= N - r; ++i) b[i] = mix(b[i], b[i + 1], t);
        left[r] = b[0];
        right[N - r] = b[N - r];
    }
    return {Bezier(std::move(left), Unchecked{}), Bezier(std::move(right), Unchecked{})};
}

template <CurvePoint P>
P Bezier<P>::blossom(std::span<const double> args) const {
    const int n = degree();
    if (args.size() != static_cast<std::size_t>(n))
        throw Error(ErrorKind::InvalidArgument,
                    "blossom needs " + std::to_string(n) + " arguments, got " + std::to_string(args.size()));
    std::array<P, kBuf> b;
    std::copy(points_.begin(), points_.end(), b.begin());
    for (int r = 1; r <= n; ++r) {
        const double u = args[static_cast<std::size_t>(r - 1)];
        for (int i = 0; i <= n - r; ++i)
            b[static_cast<std::size_t>(i)] = mix(b[static_cast<std::size_t>(i)], b[static_cast<std::size_t>(i) + 1], u);
    }
    return b[0];
}

template <CurvePoint P>
Bezier<P> Bezier<P>::subcurve(double t0, double t1) const {
    check_parameter(t0, 0, 1, "t0");
    check_parameter(t1, 0, 1, "t1");
    const int n = degree();
    std::array<double, kBuf> args{};
    std::vector<P> out(points_.size());
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j < n; ++j) args[static_cast<std::size_t>(j)] = j < n - i ? t0 : t1;
        out[static_cast<std::size_t>(i)] = blossom(std::span<const double>(args.data(), static_cast<std::size_t>(n)));
    }
    return Bezier(std::move(out), Unchecked{});
}

template <CurvePoint P>
Bezier<P> Bezier<P>::reversed() const {
    std::vector<P> r(points_.rbegin(), points_.rend());
    return Bezier(std::move(r), Unchecked{});
}

template <CurvePoint P>
Bezier<P> Bezier<P>::elevated(int times) const {
    if (times < 0) throw Error(ErrorKind::InvalidArgument, "elevation count must be >= 0");
    if (degree() + times > limits::kMaxBezierDegree)
        throw Error(ErrorKind::Limit, "elevating degree " + std::to_string(degree()) + " by " + std::to_string(times) +
                                          " exceeds the limit of " + std::to_string(limits::kMaxBezierDegree));
    std::vector<P> cur = points_;
    for (int k = 0; k < times; ++k) {
        const int n = static_cast<int>(cur.size()) - 1;
        std::vector<P> next(cur.size() + 1);
        next.front() = cur.front();
        next.back() = cur.back();
        for (int i = 1; i <= n; ++i) {
            const double a = static_cast<double>(i) / (n + 1);
            next[static_cast<std::size_t>(i)] =
                cur[static_cast<std::size_t>(i - 1)] * a + cur[static_cast<std::size_t>(i)] * (1 - a);
        }
        cur = std::move(next);
    }
    return Bezier(std::move(cur), Unchecked{});
}

template <CurvePoint P>
PowerForm<P> Bezier<P>::to_power() const {
    // a_k = C(n,k) Delta^k P_0.
    const int n = degree();
    std::vector<P> d = points_;
    PowerForm<P> pf;
    pf.coefficients.resize(d.size());
    pf.coefficients[0] = d[0];
    for (int k = 1; k <= n; ++k) {
        for (int i = 0; i <= n - k; ++i)
            d[static_cast<std::size_t>(i)] = d[static_cast<std::size_t>(i) + 1] - d[static_cast<std::size_t>(i)];
        pf.coefficients[static_cast<std::size_t>(k)] = d[0] * binomial(n, k);
    }
    return pf;
}

template <CurvePoint P>
Bezier<P> Bezier<P>::from_power(const PowerForm<P>& power) {
    // P_i = sum_{k <= i} C(i,k) / C(n,k) a_k.
    const auto& a = power.coefficients;
    if (a.size() < 2 || a.size() > static_cast<std::size_t>(limits::kMaxBezierDegree) + 1) {
        validate_points(a, "power form");  // throws the matching error
    }
    const int n = static_cast<int>(a.size()) - 1;
    std::vector<P> pts(a.size());
    for (int i = 0; i <= n; ++i) {
        P acc{};
        for (int k = 0; k <= i; ++k) acc += a[static_cast<std::size_t>(k)] * (binomial(i, k) / binomial(n, k));
        pts[static_cast<std::size_t>(i)] = acc;
    }
    return Bezier(std::move(pts));
}

template <CurvePoint P>
std::vector<double> Bezier<P>::extrema(int axis) const {
    if (axis < 0 || axis >= point_dimension<P>)
        throw Error(ErrorKind::InvalidArgument, "axis " + std::to_string(axis) + " is outside the point's dimension");
    const int n = degree();
    std::array<double, kBuf> c{};
    for (int i = 0; i < n; ++i)
        c[static_cast<std::size_t>(i)] =
            coord(points_[static_cast<std::size_t>(i) + 1], axis) - coord(points_[static_cast<std::size_t>(i)], axis);
    for (int i = 0; i < n; ++i)
        if (!std::isfinite(c[static_cast<std::size_t>(i)]))
            throw Error(ErrorKind::InvalidData, "Bezier curve: coordinates too large (the derivative overflows)");
    std::vector<double> roots = bernstein_roots(std::span<const double>(c.data(), static_cast<std::size_t>(n)));
    std::erase_if(roots, [](double t) { return !(t > 0 && t < 1); });
    return roots;
}

template <CurvePoint P>
Box<P> Bezier<P>::bounds() const {
    Box<P> box{points_.front(), points_.front()};
    box.include(points_.back());
    for (int axis = 0; axis < point_dimension<P>; ++axis)
        for (double t : extrema(axis)) box.include(eval(t));
    return box;
}

template <CurvePoint P>
Box<P> Bezier<P>::control_bounds() const {
    Box<P> box{points_.front(), points_.front()};
    for (const P& p : points_) box.include(p);
    return box;
}

template class Bezier<Point>;
template class Bezier<Point3>;
template struct PowerForm<Point>;
template struct PowerForm<Point3>;

// ---- degree reduction ---------------------------------------------------------------------------

template <CurvePoint P>
Reduction<P> reduce_degree(const Bezier<P>& curve, ReductionMethod method) {
    const int n = curve.degree();
    if (n < 2) throw Error(ErrorKind::InvalidArgument, "degree reduction needs degree >= 2 (a line cannot be reduced)");
    const auto pts = curve.points();
    const auto N = static_cast<std::size_t>(n);
    std::vector<P> fwd(N), bwd(N);
    // Forward: Q_i = (n P_i - i Q_(i-1)) / (n - i).
    fwd[0] = pts[0];
    for (std::size_t i = 1; i < N; ++i)
        fwd[i] = (pts[i] * static_cast<double>(n) - fwd[i - 1] * static_cast<double>(i)) / static_cast<double>(N - i);
    // Backward: Q_(i-1) = (n P_i - (n - i) Q_i) / i.
    bwd[N - 1] = pts[N];
    for (std::size_t i = N - 1; i >= 1; --i)
        bwd[i - 1] = (pts[i] * static_cast<double>(n) - bwd[i] * static_cast<double>(N - i)) / static_cast<double>(i);

    std::vector<P> q;
    switch (method) {
        case ReductionMethod::Forward: q = fwd; break;
        case ReductionMethod::Backward: q = bwd; break;
        case ReductionMethod::Combined: {
            // n points Q_0..Q_(n-1): forward below the middle, backward above it; with an odd count
            // the middle point is the average of the two recursions. Symmetric under reversal.
            q.resize(N);
            for (std::size_t i = 0; i < N; ++i) {
                if (N % 2 == 0) {
                    q[i] = i < N / 2 ? fwd[i] : bwd[i];
                } else {
                    const std::size_t r = (N - 1) / 2;
                    q[i] = i < r ? fwd[i] : i > r ? bwd[i] : (fwd[i] + bwd[i]) * 0.5;
                }
            }
            break;
        }
    }
    Bezier<P> reduced(std::move(q));
    Reduction<P> out{reduced, 0, 0};
    const Bezier<P> back = reduced.elevated();
    for (std::size_t i = 0; i <= N; ++i)
        out.deviation_bound = std::max(out.deviation_bound, (back[i] - pts[i]).length());
    const int samples = 64 * n;
    for (int s = 0; s <= samples; ++s) {
        const double t = static_cast<double>(s) / samples;
        out.max_deviation = std::max(out.max_deviation, (curve.eval(t) - reduced.eval(t)).length());
    }
    return out;
}

template Reduction<Point> reduce_degree(const Bezier<Point>&, ReductionMethod);
template Reduction<Point3> reduce_degree(const Bezier<Point3>&, ReductionMethod);

// ---- interpolation ------------------------------------------------------------------------------

template <CurvePoint P>
Bezier<P> interpolate_cubic(const P& q0, const P& q1, const P& q2, const P& q3) {
    // P(1/3) = (8 P0 + 12 P1 + 6 P2 + P3) / 27 and P(2/3) = (P0 + 6 P1 + 12 P2 + 8 P3) / 27, solved
    // for P1, P2 with P0 = q0, P3 = q3.
    const P p1 = (q0 * -5.0 + q1 * 18.0 - q2 * 9.0 + q3 * 2.0) / 6.0;
    const P p2 = (q0 * 2.0 - q1 * 9.0 + q2 * 18.0 - q3 * 5.0) / 6.0;
    return Bezier<P>({q0, p1, p2, q3});
}

template Bezier<Point> interpolate_cubic(const Point&, const Point&, const Point&, const Point&);
template Bezier<Point3> interpolate_cubic(const Point3&, const Point3&, const Point3&, const Point3&);

// ---- joins --------------------------------------------------------------------------------------

namespace {

// Direction in which the curve leaves its start (at_end = false) or arrives at its end (at_end =
// true): the first P_j - P_0 (or P_n - P_(n-j)) longer than eps; zero if all points coincide.
template <CurvePoint P>
P end_direction(const Bezier<P>& c, bool at_end, double eps) {
    const auto pts = c.points();
    const std::size_t n = pts.size() - 1;
    for (std::size_t j = 1; j <= n; ++j) {
        const P d = at_end ? pts[n] - pts[n - j] : pts[j] - pts[0];
        if (d.length() > eps) return d;
    }
    return P{};
}

// Curvature vector (P'' - (P''.T) T) / |P'|^2 at t; ok = false when the speed is zero.
template <CurvePoint P>
P curvature_vector(const Bezier<P>& c, double t, bool& ok) {
    const P d1 = c.derivative(1, t), d2 = c.derivative(2, t);
    const double s2 = dot(d1, d1);
    ok = s2 > 0;
    if (!ok) return P{};
    return (d2 - d1 * (dot(d2, d1) / s2)) / s2;
}

}  // namespace

template <CurvePoint P>
Continuity join_continuity(const Bezier<P>& a, const Bezier<P>& b, const JoinTolerance& tolerance) {
    if ((a.back() - b.front()).length() > tolerance.position) return Continuity::None;
    const P ta = end_direction(a, true, tolerance.position), tb = end_direction(b, false, tolerance.position);
    const double la = ta.length(), lb = tb.length();
    if (la == 0 || lb == 0) return Continuity::G0;
    const double angle = std::atan2(cross_norm(ta, tb), dot(ta, tb));
    if (!(angle <= tolerance.angle)) return Continuity::G0;
    bool oka = false, okb = false;
    const P ka = curvature_vector(a, 1.0, oka), kb = curvature_vector(b, 0.0, okb);
    if (!oka || !okb) return Continuity::G1;
    Box<P> box = a.control_bounds();
    for (const P& p : b.points()) box.include(p);
    const double size = (box.hi - box.lo).length();
    const double floor = size > 0 ? tolerance.curvature / size : 0;
    const double diff = (ka - kb).length();
    if (diff <= tolerance.curvature * std::max(ka.length(), kb.length()) + floor) return Continuity::G2;
    return Continuity::G1;
}

template Continuity join_continuity(const Bezier<Point>&, const Bezier<Point>&, const JoinTolerance&);
template Continuity join_continuity(const Bezier<Point3>&, const Bezier<Point3>&, const JoinTolerance&);

namespace {
int next_degree_or(int m, int n) {
    if (m == 0) return n;
    if (m < 1 || m > limits::kMaxBezierDegree)
        throw Error(ErrorKind::InvalidArgument, "next curve degree " + std::to_string(m) + " is outside [1, " +
                                                    std::to_string(limits::kMaxBezierDegree) + "]");
    return m;
}
void check_alpha(double alpha) {
    if (!(alpha > 0) || !std::isfinite(alpha))
        throw Error(ErrorKind::InvalidArgument, "join: alpha must be a positive finite number, got " + num(alpha));
}
}  // namespace

template <CurvePoint P>
std::vector<P> g1_join_points(const Bezier<P>& a, double alpha, int next_degree) {
    check_alpha(alpha);
    const int n = a.degree(), m = next_degree_or(next_degree, n);
    const auto pts = a.points();
    const auto N = static_cast<std::size_t>(n);
    const P q0 = pts[N];
    const P q1 = q0 + (pts[N] - pts[N - 1]) * (alpha * n / m);
    return {q0, q1};
}

template <CurvePoint P>
std::vector<P> g2_join_points(const Bezier<P>& a, double alpha, double beta, int next_degree) {
    check_alpha(alpha);
    if (!std::isfinite(beta)) throw Error(ErrorKind::InvalidArgument, "join: beta must be finite");
    const int n = a.degree(), m = next_degree_or(next_degree, n);
    if (n < 2 || m < 2) throw Error(ErrorKind::InvalidArgument, "a G2 join needs both curves of degree >= 2");
    const auto pts = a.points();
    const auto N = static_cast<std::size_t>(n);
    std::vector<P> q = g1_join_points(a, alpha, m);
    // Q''(0) = alpha^2 P''(1) + beta P'(1), with Q''(0) = m(m-1)(Q2 - 2 Q1 + Q0),
    // P''(1) = n(n-1)(P_n - 2 P_(n-1) + P_(n-2)) and P'(1) = n (P_n - P_(n-1)).
    const P second =
        (pts[N] - pts[N - 1] * 2.0 + pts[N - 2]) * (alpha * alpha * n * (n - 1.0)) + (pts[N] - pts[N - 1]) * (beta * n);
    q.push_back(q[1] * 2.0 - q[0] + second / (m * (m - 1.0)));
    return q;
}

template std::vector<Point> g1_join_points(const Bezier<Point>&, double, int);
template std::vector<Point3> g1_join_points(const Bezier<Point3>&, double, int);
template std::vector<Point> g2_join_points(const Bezier<Point>&, double, double, int);
template std::vector<Point3> g2_join_points(const Bezier<Point3>&, double, double, int);

}  // namespace casteljau
