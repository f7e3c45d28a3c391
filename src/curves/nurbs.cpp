// Curve toolkit: rational Bézier curves, NURBS, conics and their Path form
// (include/casteljau/nurbs.hpp).
#include "casteljau/limits.hpp"
#include "casteljau/nurbs.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "curves/bspline_core.hpp"

namespace casteljau {

using namespace curves_detail;

namespace {

// R^(k) from the homogeneous derivatives H[j] = (A^(j), w^(j)), j = 0..k (quotient rule, recursively).
template <CurvePoint P>
P rational_derivative(const Hom<P>* H, int k) {
    std::array<P, kBuf> R;
    R[0] = H[0].project();
    for (int j = 1; j <= k; ++j) {
        P acc = H[j].p;
        for (int i = 1; i <= j; ++i) acc -= R[static_cast<std::size_t>(j - i)] * (binomial(j, i) * H[i].w);
        R[static_cast<std::size_t>(j)] = acc / H[0].w;
    }
    return R[static_cast<std::size_t>(k)];
}

}  // namespace

// ---- RationalBezier -----------------------------------------------------------------------------

template <CurvePoint P>
RationalBezier<P>::RationalBezier(std::vector<P> control_points, std::vector<double> weights)
    : points_(std::move(control_points)), weights_(std::move(weights)) {
    // Reuse the polynomial checks (count, degree limit, finiteness).
    (void)Bezier<P>(points_);
    validate_weights(weights_, points_.size(), "rational Bezier curve");
}

template <CurvePoint P>
RationalBezier<P>::RationalBezier(const Bezier<P>& curve)
    : points_(curve.points().begin(), curve.points().end()), weights_(curve.points().size(), 1.0) {}

template <CurvePoint P>
P RationalBezier<P>::eval(double t) const {
    // The ends exactly (the homogeneous route would give w P / w, off by rounding).
    if (t == 0) return points_.front();
    if (t == 1) return points_.back();
    return derivative(0, t);
}

template <CurvePoint P>
P RationalBezier<P>::derivative(int k, double t) const {
    if (k < 0) throw Error(ErrorKind::InvalidArgument, "derivative order must be >= 0, got " + std::to_string(k));
    if (k > limits::kMaxBezierDegree) throw Error(ErrorKind::Limit, "derivative order above the degree limit");
    check_t(t);
    const int n = degree();
    std::array<Hom<P>, kBuf> H, b;
    for (int j = 0; j <= k; ++j) {
        // j-th derivative of the homogeneous curve: n!/(n-j)! Delta^j, then de Casteljau.
        if (j > n) {
            H[static_cast<std::size_t>(j)] = Hom<P>{};
            continue;
        }
        for (int i = 0; i <= n; ++i)
            b[static_cast<std::size_t>(i)] = {
                points_[static_cast<std::size_t>(i)] * weights_[static_cast<std::size_t>(i)],
                weights_[static_cast<std::size_t>(i)]};
        double scale = 1;
        for (int r = 1; r <= j; ++r) {
            for (int i = 0; i <= n - r; ++i)
                b[static_cast<std::size_t>(i)] = b[static_cast<std::size_t>(i) + 1] - b[static_cast<std::size_t>(i)];
            scale *= n - r + 1;
        }
        H[static_cast<std::size_t>(j)] = de_casteljau_inplace(b.data(), n - j, t) * scale;
    }
    return rational_derivative(H.data(), k);
}

template <CurvePoint P>
std::pair<RationalBezier<P>, RationalBezier<P>> RationalBezier<P>::split(double t) const {
    check_t(t);
    const std::size_t n = points_.size() - 1;
    std::vector<Hom<P>> b(n + 1), l(n + 1), r(n + 1);
    for (std::size_t i = 0; i <= n; ++i) b[i] = {points_[i] * weights_[i], weights_[i]};
    l[0] = b[0];
    r[n] = b[n];
    for (std::size_t k = 1; k <= n; ++k) {
        for (std::size_t i = 0; i <= n - k; ++i) b[i] = mix(b[i], b[i + 1], t);
        l[k] = b[0];
        r[n - k] = b[n - k];
    }
    auto unpack = [](const std::vector<Hom<P>>& h) {
        std::vector<P> pts;
        std::vector<double> w;
        for (const auto& x : h) {
            pts.push_back(x.project());
            w.push_back(x.w);
        }
        return RationalBezier(std::move(pts), std::move(w));
    };
    return {unpack(l), unpack(r)};
}

template <CurvePoint P>
RationalBezier<P> RationalBezier<P>::normalized() const {
    const std::size_t n = points_.size() - 1;
    const double rho = std::pow(weights_.front() / weights_.back(), 1.0 / static_cast<double>(n));
    std::vector<double> w(weights_.size());
    double f = 1;
    for (std::size_t i = 0; i <= n; ++i, f *= rho) w[i] = weights_[i] * f / weights_.front();
    w.front() = 1;
    w.back() = 1;
    return RationalBezier(points_, std::move(w));
}

template <CurvePoint P>
Box<P> RationalBezier<P>::control_bounds() const {
    Box<P> box{points_.front(), points_.front()};
    for (const P& p : points_) box.include(p);
    return box;
}

template class RationalBezier<Point>;
template class RationalBezier<Point3>;

// ---- Nurbs --------------------------------------------------------------------------------------

template <CurvePoint P>
Nurbs<P>::Nurbs(int degree, std::vector<P> control_points, std::vector<double> weights, std::vector<double> knots)
    : degree_(degree), points_(std::move(control_points)), weights_(std::move(weights)), knots_(std::move(knots)) {
    validate_curve_degree(degree_, "NURBS");
    validate_knots(degree_, points_.size(), knots_);
    validate_spline_points(points_, "NURBS");
    validate_weights(weights_, points_.size(), "NURBS");
}

template <CurvePoint P>
Nurbs<P>::Nurbs(const BSpline<P>& s)
    : degree_(s.degree()),
      points_(s.points().begin(), s.points().end()),
      weights_(s.points().size(), 1.0),
      knots_(s.knots().begin(), s.knots().end()) {}

template <CurvePoint P>
P Nurbs<P>::eval(double t) const {
    return derivative(0, t);
}

template <CurvePoint P>
P Nurbs<P>::derivative(int k, double t) const {
    if (k < 0) throw Error(ErrorKind::InvalidArgument, "derivative order must be >= 0, got " + std::to_string(k));
    if (k > limits::kMaxSplineDegree) throw Error(ErrorKind::Limit, "derivative order above the degree limit");
    check_domain(degree_, points_.size(), knots_, t);
    const std::size_t span = find_span(degree_, points_.size(), knots_, t);
    std::array<Hom<P>, kBuf> H;
    auto get = [&](std::size_t i) { return Hom<P>{points_[i] * weights_[i], weights_[i]}; };
    for (int j = 0; j <= k; ++j)
        H[static_cast<std::size_t>(j)] = j > degree_ ? Hom<P>{} : de_boor<Hom<P>>(degree_, knots_, span, j, t, get);
    return rational_derivative(H.data(), k);
}

template <CurvePoint P>
Nurbs<P> Nurbs<P>::with_knot(double u, int times) const {
    check_insertion(degree_, points_.size(), knots_, u, times);
    std::vector<Hom<P>> h(points_.size());
    for (std::size_t i = 0; i < h.size(); ++i) h[i] = {points_[i] * weights_[i], weights_[i]};
    std::vector<double> U = knots_;
    for (int i = 0; i < times; ++i) insert_knot(degree_, h, U, u);
    std::vector<P> pts;
    std::vector<double> w;
    for (const auto& x : h) {
        pts.push_back(x.project());
        w.push_back(x.w);
    }
    return Nurbs(degree_, std::move(pts), std::move(w), std::move(U));
}

template <CurvePoint P>
std::vector<RationalBezier<P>> Nurbs<P>::to_bezier() const {
    auto get = [&](std::size_t i) { return Hom<P>{points_[i] * weights_[i], weights_[i]}; };
    const auto pieces = spans_to_bezier<Hom<P>>(degree_, points_.size(), knots_, get);
    std::vector<RationalBezier<P>> out;
    for (const auto& piece : pieces) {
        std::vector<P> pts;
        std::vector<double> w;
        for (const auto& x : piece) {
            pts.push_back(x.project());
            w.push_back(x.w);
        }
        out.emplace_back(std::move(pts), std::move(w));
    }
    return out;
}

template <CurvePoint P>
std::vector<double> Nurbs<P>::breakpoints() const {
    return domain_breakpoints(degree_, points_.size(), knots_);
}

template class Nurbs<Point>;
template class Nurbs<Point3>;

// ---- conics -------------------------------------------------------------------------------------

ConicKind conic_kind(double w) {
    if (!(w > 0) || !std::isfinite(w))
        throw Error(ErrorKind::InvalidData, "conic weight must be positive and finite, got " + num(w));
    return w < 1 ? ConicKind::Ellipse : w == 1 ? ConicKind::Parabola : ConicKind::Hyperbola;
}

RationalBezier<Point> conic(Point p0, Point p1, Point p2, double w) {
    return RationalBezier<Point>({p0, p1, p2}, {1.0, w, 1.0});
}

namespace {
void check_radius(double r, const char* name) {
    if (!(r > 0) || !std::isfinite(r))
        throw Error(ErrorKind::InvalidArgument, std::string(name) + " must be positive and finite, got " + num(r));
}
void check_angle(double a, const char* name) {
    if (!std::isfinite(a))
        throw Error(ErrorKind::InvalidArgument, std::string(name) + " must be finite, got " + num(a));
}
}  // namespace

RationalBezier<Point> circular_arc(Point c, double radius, double start, double sweep) {
    check_radius(radius, "radius");
    check_angle(start, "start angle");
    check_angle(sweep, "sweep");
    if (!(std::abs(sweep) > 0 && std::abs(sweep) < kPi))
        throw Error(ErrorKind::InvalidArgument, "a single rational quadratic arc needs 0 < |sweep| < pi, got " +
                                                    num(sweep) + " (use nurbs_ellipse_arc for larger arcs)");
    const double h = sweep / 2, w = std::cos(h);
    const Point p0 = c + Point{std::cos(start), std::sin(start)} * radius;
    const Point p2 = c + Point{std::cos(start + sweep), std::sin(start + sweep)} * radius;
    // The end tangents meet at distance r / cos(h) from the centre, on the bisector.
    const Point p1 = c + Point{std::cos(start + h), std::sin(start + h)} * (radius / w);
    return RationalBezier<Point>({p0, p1, p2}, {1.0, w, 1.0});
}

Nurbs<Point> nurbs_ellipse_arc(Point c, double rx, double ry, double rotation, double start, double sweep) {
    check_radius(rx, "rx");
    check_radius(ry, "ry");
    check_angle(rotation, "rotation");
    check_angle(start, "start angle");
    check_angle(sweep, "sweep");
    if (!(std::abs(sweep) > 0 && std::abs(sweep) <= 2 * kPi))
        throw Error(ErrorKind::InvalidArgument, "arc sweep must satisfy 0 < |sweep| <= 2 pi, got " + num(sweep));
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (kPi / 2) - 1e-12)));
    const double step = sweep / pieces, w = std::cos(step / 2);
    // Unit circle arc pieces, then the affine map (scale by rx, ry; rotate; translate): rational
    // curves are affinely invariant when the control points are mapped and the weights kept.
    const double cr = std::cos(rotation), sr = std::sin(rotation);
    auto map = [&](Point u) { return Point{c.x + cr * rx * u.x - sr * ry * u.y, c.y + sr * rx * u.x + cr * ry * u.y}; };
    std::vector<Point> pts;
    std::vector<double> wts;
    std::vector<double> knots = {0, 0, 0};
    for (int i = 0; i < pieces; ++i) {
        const double a0 = start + step * i, am = a0 + step / 2;
        if (i == 0) {
            pts.push_back(map({std::cos(a0), std::sin(a0)}));
            wts.push_back(1);
        }
        pts.push_back(map(Point{std::cos(am), std::sin(am)} / w));
        wts.push_back(w);
        const double a1 = i + 1 == pieces ? start + sweep : a0 + step;
        pts.push_back(map({std::cos(a1), std::sin(a1)}));
        wts.push_back(1);
        if (i + 1 < pieces) {
            const double k = static_cast<double>(i + 1) / pieces;
            knots.push_back(k);
            knots.push_back(k);
        }
    }
    knots.insert(knots.end(), {1.0, 1.0, 1.0});
    return Nurbs<Point>(2, std::move(pts), std::move(wts), std::move(knots));
}

Nurbs<Point> nurbs_circle(Point center, double radius) {
    check_radius(radius, "radius");
    const double s = std::numbers::sqrt2 / 2, r = radius;
    std::vector<Point> pts = {{r, 0}, {r, r}, {0, r}, {-r, r}, {-r, 0}, {-r, -r}, {0, -r}, {r, -r}, {r, 0}};
    for (Point& p : pts) p += center;
    return Nurbs<Point>(2, std::move(pts), {1, s, 1, s, 1, s, 1, s, 1},
                        {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1});
}

// ---- bridge to the rasterizer -------------------------------------------------------------------

namespace {

void check_tolerance(double tolerance) {
    if (!(tolerance > 0) || !std::isfinite(tolerance))
        throw Error(ErrorKind::InvalidArgument, "tolerance must be a positive finite number, got " + num(tolerance));
}

// The Hermite cubic of a rational piece and the proven bound of |R - C| (see nurbs.hpp).
double rational_hermite(const std::vector<Point>& p, const std::vector<double>& w, Point c[4]) {
    const std::size_t n = p.size() - 1;
    const double N = static_cast<double>(n);
    c[0] = p[0];
    c[3] = p[n];
    c[1] = p[0] + (p[1] - p[0]) * (N * w[1] / w[0] / 3);
    c[2] = p[n] - (p[n] - p[n - 1]) * (N * w[n - 1] / w[n] / 3);
    // A - w C = sum_k B_(k,n+3) sum_(i+j=k) C(n,i) C(3,j) / C(n+3,k) w_i (P_i - C_j).
    double bound = 0, wmin = w[0];
    for (double x : w) wmin = std::min(wmin, x);
    for (std::size_t k = 0; k <= n + 3; ++k) {
        Point acc{};
        for (std::size_t j = 0; j <= 3; ++j) {
            if (j > k || k - j > n) continue;
            const std::size_t i = k - j;
            const double coef = binomial(static_cast<int>(n), static_cast<int>(i)) * binomial(3, static_cast<int>(j)) /
                                binomial(static_cast<int>(n + 3), static_cast<int>(k));
            acc += (p[i] - c[j]) * (coef * w[i]);
        }
        bound = std::max(bound, acc.length());
    }
    return bound / wmin;
}

}  // namespace

double append_to_path(Path& path, const RationalBezier<Point>& curve, double tolerance) {
    check_tolerance(tolerance);
    const auto pts = curve.points();
    if (path.empty() || path.current_point() != pts.front()) path.move_to(pts.front());
    if (curve.degree() == 1) {
        path.line_to(pts[1]);
        return 0;
    }
    if (curve.degree() == 2) {
        const RationalBezier<Point> s = curve.normalized();
        path.conic_to(s.points()[1], s.points()[2], s.weights()[1]);
        return 0;
    }
    struct Item {
        RationalBezier<Point> c;
        int depth;
    };
    std::vector<Item> stack;
    stack.push_back({curve, 0});
    double achieved = 0;
    while (!stack.empty()) {
        Item it = std::move(stack.back());
        stack.pop_back();
        const std::vector<Point> p(it.c.points().begin(), it.c.points().end());
        const std::vector<double> w(it.c.weights().begin(), it.c.weights().end());
        Point c[4];
        const double bound = rational_hermite(p, w, c);
        if (bound <= tolerance || it.depth >= limits::kMaxCubicApproxDepth) {
            path.cubic_to(c[1], c[2], c[3]);
            achieved = std::max(achieved, bound);
            continue;
        }
        auto halves = it.c.split(0.5);
        stack.push_back({std::move(halves.second), it.depth + 1});
        stack.push_back({std::move(halves.first), it.depth + 1});
    }
    return achieved;
}

Path to_path(const RationalBezier<Point>& curve, double tolerance) {
    Path p;
    append_to_path(p, curve, tolerance);
    return p;
}

Path to_path(const Nurbs<Point>& curve, double tolerance) {
    check_tolerance(tolerance);
    Path p;
    for (const auto& piece : curve.to_bezier()) append_to_path(p, piece, tolerance);
    return p;
}

}  // namespace casteljau
