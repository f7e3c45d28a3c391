// casteljau/vec.hpp: Point3, the 3-D point of the curve toolkit, and the traits that let the curve
// templates (bezier.hpp, spline.hpp, nurbs.hpp, surface.hpp) work on 2-D Point and 3-D Point3 alike.
//
// Conventions: double precision; Point3 is a plain (x, y, z) triple with no implied orientation.
// The curve classes are templates over CurvePoint (exactly Point and Point3) and are instantiated
// for both in the library, so user code includes headers only.
// Thread-safety: plain value types and pure functions.
#pragma once

#include <cmath>
#include <concepts>

#include "casteljau/geometry.hpp"

namespace casteljau {

struct Point3 {
    double x = 0, y = 0, z = 0;

    constexpr Point3() = default;
    constexpr Point3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

    constexpr Point3 operator+(Point3 o) const { return {x + o.x, y + o.y, z + o.z}; }
    constexpr Point3 operator-(Point3 o) const { return {x - o.x, y - o.y, z - o.z}; }
    constexpr Point3 operator-() const { return {-x, -y, -z}; }
    constexpr Point3 operator*(double s) const { return {x * s, y * s, z * s}; }
    constexpr Point3 operator/(double s) const { return {x / s, y / s, z / s}; }
    constexpr Point3& operator+=(Point3 o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
    constexpr Point3& operator-=(Point3 o) {
        x -= o.x;
        y -= o.y;
        z -= o.z;
        return *this;
    }
    constexpr Point3& operator*=(double s) {
        x *= s;
        y *= s;
        z *= s;
        return *this;
    }
    constexpr bool operator==(const Point3&) const = default;

    double length() const { return std::sqrt(x * x + y * y + z * z); }
    constexpr double dot(Point3 o) const { return x * o.x + y * o.y + z * o.z; }
    constexpr Point3 cross(Point3 o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
    bool is_finite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
};

constexpr Point3 operator*(double s, Point3 p) { return p * s; }

// The point types the curve templates accept.
template <class P>
concept CurvePoint = std::same_as<P, Point> || std::same_as<P, Point3>;

// Dimension and coordinate access by axis index (0 = x, 1 = y, 2 = z).
template <CurvePoint P>
inline constexpr int point_dimension = std::same_as<P, Point> ? 2 : 3;

template <CurvePoint P>
constexpr double coord(const P& p, int axis) {
    if constexpr (std::same_as<P, Point>) {
        return axis == 0 ? p.x : p.y;
    } else {
        return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
    }
}

template <CurvePoint P>
constexpr void set_coord(P& p, int axis, double v) {
    if constexpr (std::same_as<P, Point>) {
        (axis == 0 ? p.x : p.y) = v;
    } else {
        (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = v;
    }
}

template <CurvePoint P>
constexpr double dot(const P& a, const P& b) {
    return a.dot(b);
}
template <CurvePoint P>
inline double norm(const P& a) {
    return a.length();
}

// Axis-aligned box of 2-D or 3-D points: lo is the minimum corner, hi the maximum corner.
template <CurvePoint P>
struct Box {
    P lo{}, hi{};

    void include(const P& p) {
        for (int k = 0; k < point_dimension<P>; ++k) {
            set_coord(lo, k, std::fmin(coord(lo, k), coord(p, k)));
            set_coord(hi, k, std::fmax(coord(hi, k), coord(p, k)));
        }
    }
    bool contains(const P& p, double slack = 0) const {
        for (int k = 0; k < point_dimension<P>; ++k)
            if (coord(p, k) < coord(lo, k) - slack || coord(p, k) > coord(hi, k) + slack) return false;
        return true;
    }
    bool operator==(const Box&) const = default;
};

inline Rect to_rect(const Box<Point>& b) { return {b.lo.x, b.lo.y, b.hi.x, b.hi.y}; }

}  // namespace casteljau
