// Geometry stage: Rect and Affine helpers (see include/casteljau/geometry.hpp).
#include "casteljau/geometry.hpp"

#include <algorithm>
#include <cmath>

namespace casteljau {

Rect Rect::united(const Rect& o) const {
    return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
}

Rect Rect::intersected(const Rect& o) const {
    return {std::max(x0, o.x0), std::max(y0, o.y0), std::min(x1, o.x1), std::min(y1, o.y1)};
}

void Rect::include(Point p) {
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
}

Rect Affine::map_bounds(const Rect& r) const {
    const Point p = apply({r.x0, r.y0});
    Rect out{p.x, p.y, p.x, p.y};
    out.include(apply({r.x1, r.y0}));
    out.include(apply({r.x0, r.y1}));
    out.include(apply({r.x1, r.y1}));
    return out;
}

Affine Affine::rotate(double radians) {
    const double c = std::cos(radians), s = std::sin(radians);
    return {c, s, -s, c, 0, 0};
}

Affine Affine::rotate_degrees(double degrees) {
    // Exact values for the quarter turns so that rotate(90) maps the grid onto itself.
    double r = std::fmod(degrees, 360.0);
    if (r < 0) r += 360.0;
    if (r == 0) return {};
    if (r == 90) return {0, 1, -1, 0, 0, 0};
    if (r == 180) return {-1, 0, 0, -1, 0, 0};
    if (r == 270) return {0, -1, 1, 0, 0, 0};
    return rotate(degrees * kPi / 180.0);
}

Affine Affine::skew_x(double radians) { return {1, 0, std::tan(radians), 1, 0, 0}; }
Affine Affine::skew_y(double radians) { return {1, std::tan(radians), 0, 1, 0, 0}; }

bool Affine::is_finite() const {
    return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d) && std::isfinite(e) &&
           std::isfinite(f);
}

std::optional<Affine> Affine::inverse() const {
    const double det = determinant();
    if (!is_finite() || !std::isfinite(det) || std::abs(det) < 1e-300) return std::nullopt;
    const double id = 1.0 / det;
    Affine r{d * id, -b * id, -c * id, a * id, 0, 0};
    r.e = -(r.a * e + r.c * f);
    r.f = -(r.b * e + r.d * f);
    if (!r.is_finite()) return std::nullopt;
    return r;
}

double Affine::max_scale() const {
    // Largest singular value of [a c; b d].
    const double s1 = a * a + b * b + c * c + d * d;
    const double det = a * d - b * c;
    const double disc = std::sqrt(std::max(0.0, s1 * s1 - 4 * det * det));
    return std::sqrt(0.5 * (s1 + disc));
}

double Affine::min_scale() const {
    // Smaller singular value of [a c; b d]: |det| / max_scale, which stays accurate when the two
    // singular values are far apart.
    const double top = max_scale();
    return top > 0 ? std::abs(a * d - b * c) / top : 0.0;
}

double distance_squared_to_segment(Point p, Point a, Point b) {
    // The foot of the perpendicular, clamped to the segment's ends.
    const Vec ab = b - a, ap = p - a;
    const double len2 = ab.dot(ab);
    const double t = len2 > 0 ? std::clamp(ap.dot(ab) / len2, 0.0, 1.0) : 0.0;
    const Vec d = ap - ab * t;
    return d.dot(d);
}

bool Capsule::contains(Point p) const { return distance_squared_to_segment(p, a, b) <= radius * radius; }

bool CutCapsule::contains(Point p) const {
    for (int k = 0; k < cut_count; ++k)
        if (!cuts[k].contains(p)) return false;
    return capsule.contains(p);
}

Rect transform_bounds(const Affine& m, const Rect& r) {
    const Point p[4] = {m.apply({r.x0, r.y0}), m.apply({r.x1, r.y0}), m.apply({r.x0, r.y1}), m.apply({r.x1, r.y1})};
    Rect out{p[0].x, p[0].y, p[0].x, p[0].y};
    for (const Point& q : p) out.include(q);
    return out;
}

}  // namespace casteljau
