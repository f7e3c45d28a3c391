// casteljau/geometry.hpp: points, vectors, affine transforms and rectangles.
//
// Conventions: pixel space has x to the right and y down; pixel (i, j) is the square
// [i, i+1) x [j, j+1) with its centre at (i + 0.5, j + 0.5). Affine uses the SVG/PostScript
// matrix [a c e; b d f; 0 0 1]: x' = a x + c y + e, y' = b x + d y + f.
// Thread-safety: plain value types.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace casteljau {

inline constexpr double kPi = std::numbers::pi;

struct Point {
    double x = 0, y = 0;

    constexpr Point() = default;
    constexpr Point(double x_, double y_) : x(x_), y(y_) {}

    constexpr Point operator+(Point o) const { return {x + o.x, y + o.y}; }
    constexpr Point operator-(Point o) const { return {x - o.x, y - o.y}; }
    constexpr Point operator-() const { return {-x, -y}; }
    constexpr Point operator*(double s) const { return {x * s, y * s}; }
    constexpr Point operator/(double s) const { return {x / s, y / s}; }
    constexpr Point& operator+=(Point o) {
        x += o.x;
        y += o.y;
        return *this;
    }
    constexpr Point& operator-=(Point o) {
        x -= o.x;
        y -= o.y;
        return *this;
    }
    constexpr Point& operator*=(double s) {
        x *= s;
        y *= s;
        return *this;
    }
    constexpr bool operator==(const Point&) const = default;

    double length() const { return std::hypot(x, y); }
    constexpr double dot(Point o) const { return x * o.x + y * o.y; }
    constexpr double cross(Point o) const { return x * o.y - y * o.x; }
    bool is_finite() const { return std::isfinite(x) && std::isfinite(y); }
};
using Vec = Point;

constexpr Point operator*(double s, Point p) { return {p.x * s, p.y * s}; }
constexpr Point lerp(Point a, Point b, double t) { return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t}; }
constexpr Point midpoint(Point a, Point b) { return {(a.x + b.x) * 0.5, (a.y + b.y) * 0.5}; }
inline double distance(Point a, Point b) { return (a - b).length(); }

struct Rect {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // min corner (x0, y0), max corner (x1, y1)

    static Rect from_xywh(double x, double y, double w, double h) { return {x, y, x + w, y + h}; }
    double width() const { return x1 - x0; }
    double height() const { return y1 - y0; }
    bool empty() const { return !(x1 > x0 && y1 > y0); }
    bool contains(Point p) const { return p.x >= x0 && p.x < x1 && p.y >= y0 && p.y < y1; }
    Rect united(const Rect& o) const;
    Rect intersected(const Rect& o) const;
    void include(Point p);
    bool operator==(const Rect&) const = default;
};

// An integer rectangle of pixels [x0, x1) x [y0, y1).
struct IRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int width() const { return x1 - x0; }
    int height() const { return y1 - y0; }
    bool empty() const { return x1 <= x0 || y1 <= y0; }
    bool operator==(const IRect&) const = default;
};

struct Affine {
    double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;

    static constexpr Affine identity() { return {}; }
    static constexpr Affine translate(double tx, double ty) { return {1, 0, 0, 1, tx, ty}; }
    static constexpr Affine scale(double sx, double sy) { return {sx, 0, 0, sy, 0, 0}; }
    static constexpr Affine scale(double s) { return {s, 0, 0, s, 0, 0}; }
    static Affine rotate(double radians);
    static Affine rotate_degrees(double degrees);
    static Affine skew_x(double radians);
    static Affine skew_y(double radians);

    constexpr Point apply(Point p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
    constexpr Vec apply_vector(Vec v) const { return {a * v.x + c * v.y, b * v.x + d * v.y}; }
    constexpr Point operator()(Point p) const { return apply(p); }
    // The bounds of rectangle r's four corners mapped (the mapped rectangle's bounds).
    Rect map_bounds(const Rect& r) const;

    // (*this * o).apply(p) == this->apply(o.apply(p)): o is applied first.
    constexpr Affine operator*(const Affine& o) const {
        return {a * o.a + c * o.b, b * o.a + d * o.b,     a * o.c + c * o.d,
                b * o.c + d * o.d, a * o.e + c * o.f + e, b * o.e + d * o.f + f};
    }
    // Applies `then` after this transform.
    constexpr Affine then(const Affine& next) const { return next * (*this); }

    constexpr double determinant() const { return a * d - b * c; }
    bool is_finite() const;
    bool is_identity() const { return *this == Affine{}; }
    // The inverse, or nothing when the matrix is singular (|det| below 1e-300) or not finite.
    std::optional<Affine> inverse() const;
    // Largest factor by which the transform stretches any vector (the matrix 2-norm).
    double max_scale() const;
    // Smallest factor by which it stretches any vector (the smaller singular value; 0 when singular).
    double min_scale() const;
    bool operator==(const Affine&) const = default;
};

Rect transform_bounds(const Affine& m, const Rect& r);

// The squared distance from p to the segment from a to b (to a when a == b).
double distance_squared_to_segment(Point p, Point a, Point b);

// A segment swept by a disc: the points within `radius` of the segment from a to b (a disc when
// a == b).
struct Capsule {
    Point a, b;
    double radius = 0;

    // Whether p lies in the capsule, its boundary included.
    bool contains(Point p) const;
};

// The points p with (p - at) . out <= 0: the side of the line through `at` that `out` points away
// from.
struct HalfPlane {
    Point at;
    Vec out;
    bool contains(Point p) const { return (p - at).dot(out) <= 0; }
};

// A capsule less what lies beyond up to two lines: the points of `capsule` in every one of
// cuts[0 .. cut_count). Convex, as both its parts are.
struct CutCapsule {
    Capsule capsule;
    HalfPlane cuts[2] = {};
    int cut_count = 0;

    CutCapsule() = default;
    CutCapsule(const Capsule& c) : capsule(c) {}  // NOLINT: a capsule is a cut capsule with no cut
    bool contains(Point p) const;
};

}  // namespace casteljau
