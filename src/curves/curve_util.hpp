// Internal helpers shared by the curve toolkit sources (src/curves/): parameter checks, error
// messages, homogeneous points for rational curves, and in-place de Casteljau.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/vec.hpp"

namespace casteljau::curves_detail {

inline std::string num(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// Throws Error(InvalidArgument) unless lo <= t <= hi (NaN fails too).
inline void check_parameter(double t, double lo, double hi, const char* what) {
    if (!(t >= lo && t <= hi))
        throw Error(ErrorKind::InvalidArgument,
                    std::string(what) + " = " + num(t) + " is outside [" + num(lo) + ", " + num(hi) + "]");
}
inline void check_t(double t) { check_parameter(t, 0.0, 1.0, "t"); }

// (1 - t) a + t b: exact at t = 0 and t = 1, the form de Casteljau's algorithm uses.
template <class T>
inline T mix(const T& a, const T& b, double t) {
    return a * (1 - t) + b * t;
}

// A point with its weight, in homogeneous form (w P, w): rational curves run de Casteljau and de Boor
// on these and divide at the end.
template <CurvePoint P>
struct Hom {
    P p{};  // weighted point w P
    double w = 0;

    Hom operator+(const Hom& o) const { return {p + o.p, w + o.w}; }
    Hom operator-(const Hom& o) const { return {p - o.p, w - o.w}; }
    Hom operator*(double s) const { return {p * s, w * s}; }
    P project() const { return p / w; }
};

template <CurvePoint P>
inline bool finite(const P& p) {
    return p.is_finite();
}

// De Casteljau in place on b[0..n]: returns P(t), destroys b.
template <class T>
inline T de_casteljau_inplace(T* b, int n, double t) {
    for (int r = 1; r <= n; ++r)
        for (int i = 0; i <= n - r; ++i) b[i] = mix(b[i], b[i + 1], t);
    return b[0];
}

// Largest Bézier degree plus one: the size of the stack buffers used for evaluation.
inline constexpr int kBuf = 65;

// Cross-product magnitude of two vectors (2-D: |a x b|; 3-D: |a x b|).
inline double cross_norm(const Point& a, const Point& b) { return std::abs(a.cross(b)); }
inline double cross_norm(const Point3& a, const Point3& b) { return a.cross(b).length(); }

}  // namespace casteljau::curves_detail
