// Flatten stage: curves to polylines by recursive de Casteljau subdivision (flatten.hpp).
//
// The flatness bound. For a Bezier curve B(t) of degree n with control points P_i, let L(t) be
// the chord traversed at the same parameter, L(t) = (1 - t) P_0 + t P_n. Writing B - L in the
// Bernstein basis of degree n and bounding its second derivative, which is
// n (n - 1) sum_i (P_i - 2 P_(i+1) + P_(i+2)) B_(i,n-2)(t), gives (one line):
//     |B(t) - L(t)| <= t (1 - t) / 2 * max_t |B''(t)| <= (1/8) n (n - 1) max_i |P_i - 2 P_(i+1) + P_(i+2)|
// because B - L vanishes at t = 0 and t = 1 (interpolation error of a linear fit, t(1 - t)/2 f'').
// So a quadratic stays within |P0 - 2 P1 + P2| / 4 of its chord and a cubic within
// 3/4 max(|P0 - 2 P1 + P2|, |P1 - 2 P2 + P3|). Every point of the curve is within that distance
// of a point of the chord segment, so emitting the chord keeps the polyline within the bound.
// Halving a curve at t = 1/2 divides these second differences by at least 4 (for the left half of
// a cubic they become D0 / 4 and (D0 + D1) / 8), so the bound shrinks 4x per level: depth
// ceil(log4(bound / tolerance)) suffices and the depth limit is only reached for absurd ratios.
//
// For a conic (rational quadratic, weights 1, w, 1) in standard form the point farthest from the
// chord line is at t = 1/2 (its tangent there is parallel to the chord), at distance
// w / (1 + w) * dist(P1, chord line), which we bound by w / (1 + w) * |P1 - (P0 + P2) / 2|.
// Halving a conic gives two conics of weight sqrt((1 + w) / 2).
#include "casteljau/flatten.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "casteljau/error.hpp"
#include "path/flatten_internal.hpp"

namespace casteljau {

double flatness_bound_quad(Point p0, Point p1, Point p2) { return 0.25 * (p0 - p1 * 2 + p2).length(); }

double flatness_bound_cubic(Point p0, Point p1, Point p2, Point p3) {
    return 0.75 * std::max((p0 - p1 * 2 + p2).length(), (p1 - p2 * 2 + p3).length());
}

double flatness_bound_conic(Point p0, Point p1, Point p2, double w) {
    const Point m = p0 * 0.5 + p2 * 0.5;
    return w / (1 + w) * (p1 - m).length();
}

namespace {

// Midpoint written so that it cannot overflow for finite inputs.
inline Point mid(Point a, Point b) { return {a.x * 0.5 + b.x * 0.5, a.y * 0.5 + b.y * 0.5}; }

struct Flattener {
    const Affine& m;
    double tol;
    const Rect* cull;  // when set, curves whose control box misses it become their chord
    Polyline& out;
    bool open = false;
    bool closed_flag = false;

    void emit(Point p) {
        if (out.points.size() >= limits::kMaxFlattenedSegments)
            throw Error(ErrorKind::Limit, "path too complex: more than " +
                                              std::to_string(limits::kMaxFlattenedSegments) + " line segments after flattening");
        out.points.push_back(p);
    }

    void finish_contour() {
        if (!open) return;
        out.contour_ends.push_back(static_cast<std::uint32_t>(out.points.size()));
        out.closed.push_back(closed_flag);
        open = false;
        closed_flag = false;
    }

    bool culled(std::initializer_list<Point> pts) const {
        if (!cull) return false;
        double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
        for (Point p : pts) {
            x0 = std::min(x0, p.x); x1 = std::max(x1, p.x);
            y0 = std::min(y0, p.y); y1 = std::max(y1, p.y);
        }
        return x1 < cull->x0 || x0 > cull->x1 || y1 < cull->y0 || y0 > cull->y1;
    }

    void move(Point p) {
        finish_contour();
        open = true;
        emit(m(p));
    }
    void line(Point, Point p) { emit(m(p)); }
    void close(Point, Point) { closed_flag = true; }

    void quad(Point a, Point b, Point c) {
        const Point p0 = m(a), p1 = m(b), p2 = m(c);
        if (culled({p0, p1, p2})) return emit(p2);
        struct Q { Point p0, p1, p2; int depth; };
        Q stack[limits::kMaxFlattenDepth + 2];
        int n = 0;
        stack[n++] = {p0, p1, p2, 0};
        while (n > 0) {
            const Q q = stack[--n];
            if (q.depth >= limits::kMaxFlattenDepth || !(flatness_bound_quad(q.p0, q.p1, q.p2) > tol)) {
                emit(q.p2);
                continue;
            }
            const Point l1 = mid(q.p0, q.p1), r1 = mid(q.p1, q.p2), c = mid(l1, r1);
            stack[n++] = {c, r1, q.p2, q.depth + 1};   // right half, processed second
            stack[n++] = {q.p0, l1, c, q.depth + 1};   // left half first
        }
    }

    void cubic(Point a, Point b, Point c, Point d) {
        const Point p0 = m(a), p1 = m(b), p2 = m(c), p3 = m(d);
        if (culled({p0, p1, p2, p3})) return emit(p3);
        struct C { Point p0, p1, p2, p3; int depth; };
        C stack[limits::kMaxFlattenDepth + 2];
        int n = 0;
        stack[n++] = {p0, p1, p2, p3, 0};
        while (n > 0) {
            const C q = stack[--n];
            if (q.depth >= limits::kMaxFlattenDepth || !(flatness_bound_cubic(q.p0, q.p1, q.p2, q.p3) > tol)) {
                emit(q.p3);
                continue;
            }
            // de Casteljau at t = 1/2: three rounds of midpoints.
            const Point a1 = mid(q.p0, q.p1), b1 = mid(q.p1, q.p2), c1 = mid(q.p2, q.p3);
            const Point a2 = mid(a1, b1), b2 = mid(b1, c1);
            const Point a3 = mid(a2, b2);
            stack[n++] = {a3, b2, c1, q.p3, q.depth + 1};
            stack[n++] = {q.p0, a1, a2, a3, q.depth + 1};
        }
    }

    void conic(Point a, Point b, Point c, double w) {
        const Point p0 = m(a), p1 = m(b), p2 = m(c);
        if (culled({p0, p1, p2})) return emit(p2);
        struct K { Point p0, p1, p2; double w; int depth; };
        K stack[limits::kMaxFlattenDepth + 2];
        int n = 0;
        stack[n++] = {p0, p1, p2, w, 0};
        while (n > 0) {
            const K q = stack[--n];
            if (q.depth >= limits::kMaxFlattenDepth || !(flatness_bound_conic(q.p0, q.p1, q.p2, q.w) > tol)) {
                emit(q.p2);
                continue;
            }
            // Rational de Casteljau at t = 1/2 in homogeneous coordinates, renormalised.
            const double s = 1.0 / (1.0 + q.w);
            const Point l1 = (q.p0 + q.p1 * q.w) * s, r1 = (q.p1 * q.w + q.p2) * s;
            const Point c = mid(l1, r1);
            const double w2 = std::sqrt(0.5 * (1.0 + q.w));
            stack[n++] = {c, r1, q.p2, w2, q.depth + 1};
            stack[n++] = {q.p0, l1, c, w2, q.depth + 1};
        }
    }
};

}  // namespace

void flatten_culled(const Path& path, const Affine& m, double tolerance, const Rect* cull, Polyline& out) {
    out.clear();
    if (!m.is_finite()) throw Error(ErrorKind::InvalidData, "transform has a non-finite entry");
    if (!path.is_finite()) throw Error(ErrorKind::InvalidData, "path has a non-finite coordinate (NaN or infinity)");
    if (!(tolerance > 0) || !std::isfinite(tolerance))
        throw Error(ErrorKind::InvalidArgument, "flattening tolerance must be a positive number of pixels");
    // Transformed points must stay finite too (1e300 scaled by 1e10 overflows).
    for (Point p : path.points())
        if (!m.apply(p).is_finite())
            throw Error(ErrorKind::InvalidData, "path coordinate overflows after the transform");
    out.points.reserve(path.points().size() * 2);
    Flattener f{m, tolerance, cull, out};
    path.visit(f);
    f.finish_contour();
}

void flatten(const Path& path, const Affine& m, double tolerance, Polyline& out) {
    flatten_culled(path, m, tolerance, nullptr, out);
}

}  // namespace casteljau
