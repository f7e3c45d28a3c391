// Curve toolkit: tensor-product Bézier patches, B-spline and NURBS surfaces
// (include/casteljau/surface.hpp).
#include "casteljau/limits.hpp"
#include "casteljau/surface.hpp"

#include <cmath>
#include <string>

#include "curves/bspline_core.hpp"

namespace casteljau {

using namespace curves_detail;

namespace {

void check_net_size(std::size_t got, std::size_t rows, std::size_t cols, const char* what) {
    if (rows * cols > limits::kMaxSurfacePoints)
        throw Error(ErrorKind::Limit, std::string(what) + " has " + std::to_string(rows) + " x " +
                                          std::to_string(cols) + " control points; the limit is " +
                                          std::to_string(limits::kMaxSurfacePoints));
    if (got != rows * cols)
        throw Error(ErrorKind::InvalidData, std::string(what) + " needs " + std::to_string(rows) + " x " +
                                                std::to_string(cols) + " = " + std::to_string(rows * cols) +
                                                " control points, got " + std::to_string(got));
}

void check_bezier_degree(int d, const char* dir) {
    if (d < 1)
        throw Error(ErrorKind::InvalidArgument,
                    std::string("Bezier patch degree in ") + dir + " must be at least 1, got " + std::to_string(d));
    if (d > limits::kMaxBezierDegree)
        throw Error(ErrorKind::Limit, std::string("Bezier patch degree in ") + dir + " is " + std::to_string(d) +
                                          "; the limit is " + std::to_string(limits::kMaxBezierDegree));
}

// k-th derivative control values of one row/column (scaled forward differences) evaluated at t.
template <class T, class Get>
T bezier_derivative_1d(int n, int k, double t, Get&& get) {
    if (k > n) return T{};
    std::array<T, kBuf> b;
    for (int i = 0; i <= n; ++i) b[static_cast<std::size_t>(i)] = get(i);
    double scale = 1;
    for (int r = 1; r <= k; ++r) {
        for (int i = 0; i <= n - r; ++i)
            b[static_cast<std::size_t>(i)] = b[static_cast<std::size_t>(i) + 1] - b[static_cast<std::size_t>(i)];
        scale *= n - r + 1;
    }
    return de_casteljau_inplace(b.data(), n - k, t) * scale;
}

}  // namespace

// ---- BezierPatch --------------------------------------------------------------------------------

template <CurvePoint P>
BezierPatch<P>::BezierPatch(int degree_u, int degree_v, std::vector<P> net)
    : m_(degree_u), n_(degree_v), net_(std::move(net)) {
    check_bezier_degree(m_, "u");
    check_bezier_degree(n_, "v");
    check_net_size(net_.size(), static_cast<std::size_t>(m_) + 1, static_cast<std::size_t>(n_) + 1, "Bezier patch");
    for (std::size_t i = 0; i < net_.size(); ++i)
        if (!net_[i].is_finite())
            throw Error(ErrorKind::InvalidData, "Bezier patch control point " + std::to_string(i) + " is not finite");
}

template <CurvePoint P>
P BezierPatch<P>::eval(double u, double v) const {
    return derivative(0, 0, u, v);
}

template <CurvePoint P>
P BezierPatch<P>::derivative(int ku, int kv, double u, double v) const {
    if (ku < 0 || kv < 0) throw Error(ErrorKind::InvalidArgument, "derivative orders must be >= 0");
    check_parameter(u, 0, 1, "u");
    check_parameter(v, 0, 1, "v");
    if (ku > m_ || kv > n_) return P{};
    // In u for every column j, then in v over the results.
    std::array<P, kBuf> q;
    for (int j = 0; j <= n_; ++j)
        q[static_cast<std::size_t>(j)] = bezier_derivative_1d<P>(m_, ku, u, [&](int i) { return at(i, j); });
    return bezier_derivative_1d<P>(n_, kv, v, [&](int j) { return q[static_cast<std::size_t>(j)]; });
}

std::array<double, 16> bezier_cubic_matrix() { return {-1, 3, -3, 1, 3, -6, 3, 0, -3, 3, 0, 0, 1, 0, 0, 0}; }

template <CurvePoint P>
P BezierPatch<P>::eval_matrix(double u, double v) const {
    if (m_ != 3 || n_ != 3)
        throw Error(ErrorKind::InvalidArgument, "the matrix form U M P M^T V^T needs a bicubic patch");
    check_parameter(u, 0, 1, "u");
    check_parameter(v, 0, 1, "v");
    const auto M = bezier_cubic_matrix();
    const double U[4] = {u * u * u, u * u, u, 1}, V[4] = {v * v * v, v * v, v, 1};
    double um[4] = {0, 0, 0, 0}, vm[4] = {0, 0, 0, 0};  // U M and V M (so M^T V^T = (V M)^T)
    for (std::size_t c = 0; c < 4; ++c)
        for (std::size_t r = 0; r < 4; ++r) {
            um[c] += U[r] * M[r * 4 + c];
            vm[c] += V[r] * M[r * 4 + c];
        }
    P acc{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) acc += at(i, j) * (um[i] * vm[j]);
    return acc;
}

template <CurvePoint P>
Bezier<P> BezierPatch<P>::iso_u(double u) const {
    check_parameter(u, 0, 1, "u");
    std::vector<P> pts(static_cast<std::size_t>(n_) + 1);
    for (int j = 0; j <= n_; ++j)
        pts[static_cast<std::size_t>(j)] = bezier_derivative_1d<P>(m_, 0, u, [&](int i) { return at(i, j); });
    return Bezier<P>(std::move(pts));
}

template <CurvePoint P>
Bezier<P> BezierPatch<P>::iso_v(double v) const {
    check_parameter(v, 0, 1, "v");
    std::vector<P> pts(static_cast<std::size_t>(m_) + 1);
    for (int i = 0; i <= m_; ++i)
        pts[static_cast<std::size_t>(i)] = bezier_derivative_1d<P>(n_, 0, v, [&](int j) { return at(i, j); });
    return Bezier<P>(std::move(pts));
}

template <CurvePoint P>
Box<P> BezierPatch<P>::control_bounds() const {
    Box<P> b{net_.front(), net_.front()};
    for (const P& p : net_) b.include(p);
    return b;
}

template class BezierPatch<Point>;
template class BezierPatch<Point3>;

// ---- BSplineSurface -----------------------------------------------------------------------------

namespace {
void validate_surface(int pu, int pv, std::size_t nu, std::size_t nv, std::size_t net, std::span<const double> ku,
                      std::span<const double> kv, const char* what) {
    validate_curve_degree(pu, what);
    validate_curve_degree(pv, what);
    check_net_size(net, nu, nv, what);
    validate_knots(pu, nu, ku);
    validate_knots(pv, nv, kv);
}

// S^(ku,kv) of a tensor-product spline with control values get(i, j): de Boor in v for the p_u + 1
// rows that matter, then in u.
template <class T, class Get>
T surface_deboor(int pu, int pv, std::size_t nu, std::size_t nv, std::span<const double> Ku, std::span<const double> Kv,
                 int ku, int kv, double u, double v, Get&& get) {
    check_domain(pu, nu, Ku, u);
    check_domain(pv, nv, Kv, v);
    if (ku > pu || kv > pv) return T{};
    const std::size_t su = find_span(pu, nu, Ku, u), sv = find_span(pv, nv, Kv, v);
    std::array<T, kBuf> rows;
    const std::size_t first = su - static_cast<std::size_t>(pu);
    for (std::size_t r = 0; r <= static_cast<std::size_t>(pu); ++r)
        rows[r] = de_boor<T>(pv, Kv, sv, kv, v, [&](std::size_t j) { return get(first + r, j); });
    return de_boor<T>(pu, Ku, su, ku, u, [&](std::size_t i) { return rows[i - first]; });
}
}  // namespace

template <CurvePoint P>
BSplineSurface<P>::BSplineSurface(int degree_u, int degree_v, std::size_t count_u, std::size_t count_v,
                                  std::vector<P> net, std::vector<double> knots_u, std::vector<double> knots_v)
    : pu_(degree_u),
      pv_(degree_v),
      nu_(count_u),
      nv_(count_v),
      net_(std::move(net)),
      ku_(std::move(knots_u)),
      kv_(std::move(knots_v)) {
    validate_surface(pu_, pv_, nu_, nv_, net_.size(), ku_, kv_, "B-spline surface");
    validate_spline_points(net_, "B-spline surface");
}

template <CurvePoint P>
BSplineSurface<P> BSplineSurface<P>::clamped(int degree_u, int degree_v, std::size_t count_u, std::size_t count_v,
                                             std::vector<P> net) {
    validate_curve_degree(degree_u, "B-spline surface");
    validate_curve_degree(degree_v, "B-spline surface");
    return BSplineSurface(degree_u, degree_v, count_u, count_v, std::move(net), clamped_knots(degree_u, count_u),
                          clamped_knots(degree_v, count_v));
}

template <CurvePoint P>
P BSplineSurface<P>::derivative(int ku, int kv, double u, double v) const {
    if (ku < 0 || kv < 0) throw Error(ErrorKind::InvalidArgument, "derivative orders must be >= 0");
    return surface_deboor<P>(pu_, pv_, nu_, nv_, ku_, kv_, ku, kv, u, v,
                             [&](std::size_t i, std::size_t j) { return net_[i * nv_ + j]; });
}

template <CurvePoint P>
BSpline<P> BSplineSurface<P>::iso_u(double u) const {
    check_domain(pu_, nu_, ku_, u);
    const std::size_t su = find_span(pu_, nu_, ku_, u);
    std::vector<P> pts(nv_);
    for (std::size_t j = 0; j < nv_; ++j)
        pts[j] = de_boor<P>(pu_, ku_, su, 0, u, [&](std::size_t i) { return net_[i * nv_ + j]; });
    return BSpline<P>(pv_, std::move(pts), kv_);
}

template <CurvePoint P>
BSpline<P> BSplineSurface<P>::iso_v(double v) const {
    check_domain(pv_, nv_, kv_, v);
    const std::size_t sv = find_span(pv_, nv_, kv_, v);
    std::vector<P> pts(nu_);
    for (std::size_t i = 0; i < nu_; ++i)
        pts[i] = de_boor<P>(pv_, kv_, sv, 0, v, [&](std::size_t j) { return net_[i * nv_ + j]; });
    return BSpline<P>(pu_, std::move(pts), ku_);
}

template class BSplineSurface<Point>;
template class BSplineSurface<Point3>;

// ---- NurbsSurface -------------------------------------------------------------------------------

template <CurvePoint P>
NurbsSurface<P>::NurbsSurface(int degree_u, int degree_v, std::size_t count_u, std::size_t count_v, std::vector<P> net,
                              std::vector<double> weights, std::vector<double> knots_u, std::vector<double> knots_v)
    : pu_(degree_u),
      pv_(degree_v),
      nu_(count_u),
      nv_(count_v),
      net_(std::move(net)),
      w_(std::move(weights)),
      ku_(std::move(knots_u)),
      kv_(std::move(knots_v)) {
    validate_surface(pu_, pv_, nu_, nv_, net_.size(), ku_, kv_, "NURBS surface");
    validate_spline_points(net_, "NURBS surface");
    validate_weights(w_, net_.size(), "NURBS surface");
}

template <CurvePoint P>
P NurbsSurface<P>::derivative(int ku, int kv, double u, double v) const {
    if (ku < 0 || kv < 0 || ku > 1 || kv > 1)
        throw Error(ErrorKind::InvalidArgument,
                    "NURBS surface derivatives are available for orders 0 and 1 in u and v");
    auto get = [&](std::size_t i, std::size_t j) {
        const std::size_t k = i * nv_ + j;
        return Hom<P>{net_[k] * w_[k], w_[k]};
    };
    auto H = [&](int a, int b) { return surface_deboor<Hom<P>>(pu_, pv_, nu_, nv_, ku_, kv_, a, b, u, v, get); };
    const Hom<P> h = H(0, 0);
    const P S = h.project();
    if (ku == 0 && kv == 0) return S;
    if (ku == 1 && kv == 0) {
        const Hom<P> a = H(1, 0);
        return (a.p - S * a.w) / h.w;
    }
    const Hom<P> b = H(0, 1);
    const P Sv = (b.p - S * b.w) / h.w;
    if (ku == 0) return Sv;
    const Hom<P> a = H(1, 0), c = H(1, 1);
    const P Su = (a.p - S * a.w) / h.w;
    // A_uv = (w S)_uv = w_uv S + w_u S_v + w_v S_u + w S_uv.
    return (c.p - S * c.w - Sv * a.w - Su * b.w) / h.w;
}

template <CurvePoint P>
Nurbs<P> NurbsSurface<P>::iso_u(double u) const {
    check_domain(pu_, nu_, ku_, u);
    const std::size_t su = find_span(pu_, nu_, ku_, u);
    std::vector<P> pts(nv_);
    std::vector<double> w(nv_);
    for (std::size_t j = 0; j < nv_; ++j) {
        const Hom<P> h = de_boor<Hom<P>>(pu_, ku_, su, 0, u, [&](std::size_t i) {
            const std::size_t k = i * nv_ + j;
            return Hom<P>{net_[k] * w_[k], w_[k]};
        });
        pts[j] = h.project();
        w[j] = h.w;
    }
    return Nurbs<P>(pv_, std::move(pts), std::move(w), kv_);
}

template <CurvePoint P>
Nurbs<P> NurbsSurface<P>::iso_v(double v) const {
    check_domain(pv_, nv_, kv_, v);
    const std::size_t sv = find_span(pv_, nv_, kv_, v);
    std::vector<P> pts(nu_);
    std::vector<double> w(nu_);
    for (std::size_t i = 0; i < nu_; ++i) {
        const Hom<P> h = de_boor<Hom<P>>(pv_, kv_, sv, 0, v, [&](std::size_t j) {
            const std::size_t k = i * nv_ + j;
            return Hom<P>{net_[k] * w_[k], w_[k]};
        });
        pts[i] = h.project();
        w[i] = h.w;
    }
    return Nurbs<P>(pu_, std::move(pts), std::move(w), ku_);
}

template class NurbsSurface<Point>;
template class NurbsSurface<Point3>;

}  // namespace casteljau
