// Curve toolkit: interpolating splines (Hermite, Cardinal, Catmull-Rom, Kochanek-Bartels, natural
// cubic), all produced as cubic Bézier pieces (include/casteljau/spline.hpp).
#include <cmath>
#include <string>

#include "casteljau/limits.hpp"
#include "casteljau/spline.hpp"
#include "curves/bspline_core.hpp"

namespace casteljau {

using namespace curves_detail;

namespace {

template <CurvePoint P>
void validate_through_points(std::span<const P> pts, std::size_t minimum, const char* what) {
    if (pts.size() < minimum)
        throw Error(ErrorKind::InvalidData, std::string(what) + " needs at least " + std::to_string(minimum) +
                                                " points, got " + std::to_string(pts.size()));
    if (pts.size() > limits::kMaxSplinePoints)
        throw Error(ErrorKind::Limit, std::string(what) + " has " + std::to_string(pts.size()) +
                                          " points; the limit is " + std::to_string(limits::kMaxSplinePoints));
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (!pts[i].is_finite())
            throw Error(ErrorKind::InvalidData, std::string(what) + " point " + std::to_string(i) + " is not finite");
}

// A cubic piece, with a clear error when the construction overflowed (huge coordinates).
template <CurvePoint P>
Bezier<P> piece(const P& a, const P& b, const P& c, const P& d, const char* what) {
    if (!a.is_finite() || !b.is_finite() || !c.is_finite() || !d.is_finite())
        throw Error(ErrorKind::InvalidData, std::string(what) + ": coordinates too large (the construction overflows)");
    return Bezier<P>({a, b, c, d});
}

void check_finite_param(double v, const char* name) {
    if (!std::isfinite(v))
        throw Error(ErrorKind::InvalidArgument, std::string(name) + " must be finite, got " + num(v));
}

// Neighbour access with the end condition: index i may be -1 or n (one past the end).
template <CurvePoint P>
P neighbour(std::span<const P> pts, long i, EndCondition ends) {
    const long n = static_cast<long>(pts.size());
    if (ends == EndCondition::Closed) return pts[static_cast<std::size_t>(((i % n) + n) % n)];
    return pts[static_cast<std::size_t>(std::clamp(i, 0L, n - 1))];
}

// Shared driver: `out_tangent(i)` leaves point i, `in_tangent(i)` arrives at point i.
template <CurvePoint P, class Out, class In>
std::vector<Bezier<P>> tangent_spline(std::span<const P> pts, EndCondition ends, const char* what, Out&& out_tangent,
                                      In&& in_tangent) {
    const std::size_t minimum = ends == EndCondition::Inner ? 4 : ends == EndCondition::Closed ? 3 : 2;
    validate_through_points(pts, minimum, what);
    const long n = static_cast<long>(pts.size());
    long first = 0, last = n - 1;  // pieces from point i to i + 1 for first <= i < last
    if (ends == EndCondition::Inner) first = 1, last = n - 2;
    if (ends == EndCondition::Closed) last = n;
    std::vector<Bezier<P>> out;
    out.reserve(static_cast<std::size_t>(last - first));
    for (long i = first; i < last; ++i) {
        const P p0 = neighbour(pts, i, ends), p1 = neighbour(pts, i + 1, ends);
        const P m0 = out_tangent(i), m1 = in_tangent(i + 1);
        out.push_back(piece(p0, p0 + m0 / 3.0, p1 - m1 / 3.0, p1, what));
    }
    return out;
}

}  // namespace

std::array<double, 16> hermite_matrix() { return {2, -2, 1, 1, -3, 3, -2, -1, 0, 0, 1, 0, 1, 0, 0, 0}; }

template <CurvePoint P>
P hermite_eval(const P& p0, const P& m0, const P& p1, const P& m1, double t) {
    check_t(t);
    const auto M = hermite_matrix();
    const double T[4] = {t * t * t, t * t, t, 1};
    double h[4] = {0, 0, 0, 0};  // [t^3 t^2 t 1] Mh
    for (std::size_t c = 0; c < 4; ++c)
        for (std::size_t r = 0; r < 4; ++r) h[c] += T[r] * M[r * 4 + c];
    return p0 * h[0] + p1 * h[1] + m0 * h[2] + m1 * h[3];
}

template <CurvePoint P>
Bezier<P> hermite_to_bezier(const P& p0, const P& m0, const P& p1, const P& m1) {
    return Bezier<P>({p0, p0 + m0 / 3.0, p1 - m1 / 3.0, p1});
}

template <CurvePoint P>
std::vector<Bezier<P>> hermite_spline(std::span<const P> points, std::span<const P> tangents) {
    validate_through_points(points, 2, "Hermite spline");
    if (tangents.size() != points.size())
        throw Error(ErrorKind::InvalidData, "Hermite spline has " + std::to_string(points.size()) + " points but " +
                                                std::to_string(tangents.size()) + " tangents");
    validate_through_points(tangents, 2, "Hermite spline tangents");
    std::vector<Bezier<P>> out;
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        out.push_back(piece(points[i], points[i] + tangents[i] / 3.0, points[i + 1] - tangents[i + 1] / 3.0,
                            points[i + 1], "Hermite spline"));
    return out;
}

template <CurvePoint P>
std::vector<Bezier<P>> cardinal_spline(std::span<const P> points, double tension, EndCondition ends) {
    check_finite_param(tension, "tension");
    const double s = (1 - tension) / 2;
    auto tangent = [&](long i) { return (neighbour(points, i + 1, ends) - neighbour(points, i - 1, ends)) * s; };
    return tangent_spline(points, ends, "Cardinal spline", tangent, tangent);
}

template <CurvePoint P>
std::vector<Bezier<P>> catmull_rom_spline(std::span<const P> points, EndCondition ends) {
    return cardinal_spline(points, 0.0, ends);
}

template <CurvePoint P>
std::vector<Bezier<P>> kochanek_bartels_spline(std::span<const P> points, const KbParams& kb, EndCondition ends) {
    check_finite_param(kb.tension, "tension");
    check_finite_param(kb.continuity, "continuity");
    check_finite_param(kb.bias, "bias");
    const double t = kb.tension, c = kb.continuity, b = kb.bias;
    auto out_tangent = [&](long i) {  // leaving P_i
        const P back = neighbour(points, i, ends) - neighbour(points, i - 1, ends);
        const P fwd = neighbour(points, i + 1, ends) - neighbour(points, i, ends);
        return back * ((1 - t) * (1 + b) * (1 + c) / 2) + fwd * ((1 - t) * (1 - b) * (1 - c) / 2);
    };
    auto in_tangent = [&](long i) {  // arriving at P_i
        const P back = neighbour(points, i, ends) - neighbour(points, i - 1, ends);
        const P fwd = neighbour(points, i + 1, ends) - neighbour(points, i, ends);
        return back * ((1 - t) * (1 + b) * (1 - c) / 2) + fwd * ((1 - t) * (1 - b) * (1 + c) / 2);
    };
    return tangent_spline(points, ends, "Kochanek-Bartels spline", out_tangent, in_tangent);
}

template <CurvePoint P>
std::vector<Bezier<P>> natural_spline(std::span<const P> points, Parametrization param) {
    validate_through_points(points, 2, "natural spline");
    const std::size_t n = points.size() - 1;  // pieces
    std::vector<double> h(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double d = (points[i + 1] - points[i]).length();
        switch (param) {
            case Parametrization::Uniform: h[i] = 1; break;
            case Parametrization::ChordLength: h[i] = d; break;
            case Parametrization::Centripetal: h[i] = std::sqrt(d); break;
        }
        if (!(h[i] > 0) || !std::isfinite(h[i]))
            throw Error(ErrorKind::InvalidData, "natural spline: points " + std::to_string(i) + " and " +
                                                    std::to_string(i + 1) + " coincide (or are too far apart) for " +
                                                    "this parametrisation");
    }
    // Second derivatives M_0 = M_n = 0 and, for 0 < i < n,
    // h_(i-1) M_(i-1) + 2 (h_(i-1) + h_i) M_i + h_i M_(i+1) = 6 (D_i - D_(i-1)), D_i = (P_(i+1) - P_i) / h_i.
    std::vector<P> M(n + 1, P{});
    if (n >= 2) {
        const std::size_t m = n - 1;  // unknowns M_1 .. M_(n-1)
        std::vector<double> diag(m), upper(m);
        std::vector<P> rhs(m);
        for (std::size_t j = 0; j < m; ++j) {
            const std::size_t i = j + 1;
            diag[j] = 2 * (h[i - 1] + h[i]);
            upper[j] = h[i];
            rhs[j] = ((points[i + 1] - points[i]) / h[i] - (points[i] - points[i - 1]) / h[i - 1]) * 6.0;
        }
        // Thomas algorithm (lower diagonal entries: h_(i-1) for row i, i.e. h[j] for row j >= 1).
        for (std::size_t j = 1; j < m; ++j) {
            const double w = h[j] / diag[j - 1];
            diag[j] -= w * upper[j - 1];
            rhs[j] -= rhs[j - 1] * w;
        }
        M[m] = rhs[m - 1] / diag[m - 1];
        for (std::size_t j = m - 1; j-- > 0;) M[j + 1] = (rhs[j] - M[j + 2] * upper[j]) / diag[j];
    }
    std::vector<Bezier<P>> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        // On [0, h]: derivative at the start D - h (2 M_i + M_(i+1)) / 6, at the end
        // D + h (M_i + 2 M_(i+1)) / 6; the Bézier handles are h/3 times the derivatives.
        const P D = (points[i + 1] - points[i]) / h[i];
        const P d0 = D - (M[i] * 2.0 + M[i + 1]) * (h[i] / 6);
        const P d1 = D + (M[i] + M[i + 1] * 2.0) * (h[i] / 6);
        out.push_back(piece(points[i], points[i] + d0 * (h[i] / 3), points[i + 1] - d1 * (h[i] / 3), points[i + 1],
                            "natural spline"));
    }
    return out;
}

#define CASTELJAU_INSTANTIATE(P)                                                                                \
    template P hermite_eval(const P&, const P&, const P&, const P&, double);                                    \
    template Bezier<P> hermite_to_bezier(const P&, const P&, const P&, const P&);                               \
    template std::vector<Bezier<P>> hermite_spline(std::span<const P>, std::span<const P>);                     \
    template std::vector<Bezier<P>> cardinal_spline(std::span<const P>, double, EndCondition);                  \
    template std::vector<Bezier<P>> catmull_rom_spline(std::span<const P>, EndCondition);                       \
    template std::vector<Bezier<P>> kochanek_bartels_spline(std::span<const P>, const KbParams&, EndCondition); \
    template std::vector<Bezier<P>> natural_spline(std::span<const P>, Parametrization);
CASTELJAU_INSTANTIATE(Point)
CASTELJAU_INSTANTIATE(Point3)
#undef CASTELJAU_INSTANTIATE

}  // namespace casteljau
