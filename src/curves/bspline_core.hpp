// Internal B-spline algorithms shared by BSpline, Nurbs and the spline surfaces: span search,
// de Boor evaluation (with derivatives), the blossom of a span, Boehm knot insertion. Templates over
// the control value type T (Point, Point3 or a homogeneous Hom<P>), reading control values through
// a getter so callers need not copy their arrays.
#pragma once

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/spline.hpp"
#include "curves/curve_util.hpp"

namespace casteljau::curves_detail {

// Span index k with U_k <= t < U_(k+1), p <= k < n; the last non-empty span for t = U_n.
// Requires U_p <= t <= U_n (checked by the callers).
inline std::size_t find_span(int p, std::size_t n, std::span<const double> U, double t) {
    const auto P = static_cast<std::size_t>(p);
    if (t >= U[n]) {
        std::size_t k = n - 1;
        while (k > P && U[k] == U[k + 1]) --k;
        return k;
    }
    const auto it =
        std::upper_bound(U.begin() + static_cast<std::ptrdiff_t>(P), U.begin() + static_cast<std::ptrdiff_t>(n) + 1, t);
    return static_cast<std::size_t>(it - U.begin()) - 1;
}

inline void check_domain(int p, std::size_t n, std::span<const double> U, double t) {
    check_parameter(t, U[static_cast<std::size_t>(p)], U[n], "t");
}

// The `order`-th derivative at t of the spline of degree p with control values get(i) and knots U,
// span k. Derivative control values p (P_(i+1) - P_i) / (U_(i+p+1) - U_(i+1)) are formed locally
// for the p + 1 values of the span only; no allocation.
template <class T, class Get>
T de_boor(int p, std::span<const double> U, std::size_t k, int order, double t, Get&& get) {
    std::array<T, kBuf> d;
    for (int j = 0; j <= p; ++j)
        d[static_cast<std::size_t>(j)] = get(k - static_cast<std::size_t>(p) + static_cast<std::size_t>(j));
    int deg = p;
    for (int r = 1; r <= order; ++r) {
        if (deg == 0) return T{};
        // Level r-1: degree deg, knots U shifted by r-1, span k-(r-1); local j <-> index kk - deg + j.
        const std::size_t kk = k - static_cast<std::size_t>(r - 1);
        for (int j = 0; j < deg; ++j) {
            const std::size_t i = kk - static_cast<std::size_t>(deg) + static_cast<std::size_t>(j);
            const std::size_t sh = static_cast<std::size_t>(r - 1);
            const double den = U[i + static_cast<std::size_t>(deg) + 1 + sh] - U[i + 1 + sh];
            d[static_cast<std::size_t>(j)] =
                (d[static_cast<std::size_t>(j) + 1] - d[static_cast<std::size_t>(j)]) * (deg / den);
        }
        --deg;
    }
    // De Boor at level `order`: knots U shifted by `order`, span kk = k - order.
    const std::size_t sh = static_cast<std::size_t>(order), kk = k - sh;
    for (int r = 1; r <= deg; ++r) {
        for (int j = deg; j >= r; --j) {
            const std::size_t i = kk - static_cast<std::size_t>(deg) + static_cast<std::size_t>(j);
            const double a = U[i + sh], b = U[i + static_cast<std::size_t>(deg + 1 - r) + sh];
            const double alpha = (t - a) / (b - a);
            d[static_cast<std::size_t>(j)] =
                mix(d[static_cast<std::size_t>(j) - 1], d[static_cast<std::size_t>(j)], alpha);
        }
    }
    return d[static_cast<std::size_t>(deg)];
}

// The blossom f_k(x_1, ..., x_p) of the polynomial piece on span k (de Boor with x_r at level r).
template <class T, class Get>
T de_boor_blossom(int p, std::span<const double> U, std::size_t k, const double* x, Get&& get) {
    std::array<T, kBuf> d;
    for (int j = 0; j <= p; ++j)
        d[static_cast<std::size_t>(j)] = get(k - static_cast<std::size_t>(p) + static_cast<std::size_t>(j));
    for (int r = 1; r <= p; ++r) {
        for (int j = p; j >= r; --j) {
            const std::size_t i = k - static_cast<std::size_t>(p) + static_cast<std::size_t>(j);
            const double a = U[i], b = U[i + static_cast<std::size_t>(p + 1 - r)];
            const double alpha = (x[r - 1] - a) / (b - a);
            d[static_cast<std::size_t>(j)] =
                mix(d[static_cast<std::size_t>(j) - 1], d[static_cast<std::size_t>(j)], alpha);
        }
    }
    return d[static_cast<std::size_t>(p)];
}

// Bézier control values of every non-empty span in the domain (blossoms f_k(a^(p-i), b^i)).
template <class T, class Get>
std::vector<std::vector<T>> spans_to_bezier(int p, std::size_t n, std::span<const double> U, Get&& get) {
    std::vector<std::vector<T>> out;
    std::array<double, kBuf> x{};
    for (std::size_t k = static_cast<std::size_t>(p); k < n; ++k) {
        if (!(U[k] < U[k + 1])) continue;
        std::vector<T> piece(static_cast<std::size_t>(p) + 1);
        for (int i = 0; i <= p; ++i) {
            for (int r = 0; r < p; ++r) x[static_cast<std::size_t>(r)] = r < p - i ? U[k] : U[k + 1];
            piece[static_cast<std::size_t>(i)] = de_boor_blossom<T>(p, U, k, x.data(), get);
        }
        // Where the knot's multiplicity is at most p the curve is continuous, so the piece starts
        // exactly where the previous one ended (the two blossoms differ only by rounding); this
        // keeps Paths built from the pieces in one contour.
        if (!out.empty() && std::count(U.begin(), U.end(), U[k]) <= p) piece.front() = out.back().back();
        out.push_back(std::move(piece));
    }
    return out;
}

inline std::vector<double> domain_breakpoints(int p, std::size_t n, std::span<const double> U) {
    std::vector<double> b;
    for (std::size_t k = static_cast<std::size_t>(p); k <= n; ++k)
        if (b.empty() || U[k] > b.back()) b.push_back(U[k]);
    return b;
}

// Boehm: inserts u once into (ctrl, U) of degree p. u must lie in [U_p, U_n] with multiplicity < p + 1
// after insertion (checked by the caller).
template <class T>
void insert_knot(int p, std::vector<T>& ctrl, std::vector<double>& U, double u) {
    const std::size_t n = ctrl.size();
    const std::size_t k = find_span(p, n, U, u);
    const auto P = static_cast<std::size_t>(p);
    std::vector<T> q(n + 1);
    for (std::size_t i = 0; i <= n; ++i) {
        if (i + P <= k) {
            q[i] = ctrl[i];
        } else if (i >= k + 1) {
            q[i] = ctrl[i - 1];
        } else {
            const double alpha = (u - U[i]) / (U[i + P] - U[i]);
            q[i] = mix(ctrl[i - 1], ctrl[i], alpha);
        }
    }
    U.insert(U.begin() + static_cast<std::ptrdiff_t>(k) + 1, u);
    ctrl = std::move(q);
}

inline void check_insertion(int p, std::size_t n, std::span<const double> U, double u, int times) {
    if (times < 0) throw Error(ErrorKind::InvalidArgument, "knot insertion count must be >= 0");
    check_parameter(u, U[static_cast<std::size_t>(p)], U[n], "inserted knot");
    const auto mult = static_cast<int>(std::count(U.begin(), U.end(), u));
    if (mult + times > p + 1)
        throw Error(ErrorKind::InvalidArgument,
                    "inserting knot " + num(u) + " " + std::to_string(times) +
                        " time(s) would raise its multiplicity above degree + 1 = " + std::to_string(p + 1));
    if (n + static_cast<std::size_t>(times) > limits::kMaxSplinePoints)
        throw Error(ErrorKind::Limit, "knot insertion would exceed the limit of " +
                                          std::to_string(limits::kMaxSplinePoints) + " control points");
}

void validate_curve_degree(int degree, const char* what);

template <CurvePoint P>
void validate_spline_points(const std::vector<P>& pts, const char* what) {
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (!pts[i].is_finite())
            throw Error(ErrorKind::InvalidData,
                        std::string(what) + " control point " + std::to_string(i) + " is not finite");
}

void validate_weights(std::span<const double> w, std::size_t count, const char* what);

}  // namespace casteljau::curves_detail
