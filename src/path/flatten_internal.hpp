// Internal: the flattener itself, templated on where its points go, so the rasterizer can stream
// points straight into edge building while the public flatten() fills a Polyline. The bound and
// its derivation are documented at the top of flatten.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/flatten.hpp"
#include "casteljau/limits.hpp"

namespace casteljau {

namespace flatten_detail {

// The same bounds squared (no square root in the loop; an overflow to infinity only subdivides).
inline double sq(Point v) { return v.x * v.x + v.y * v.y; }
inline double bound2_quad(Point p0, Point p1, Point p2) { return 0.0625 * sq(p0 - p1 * 2 + p2); }
inline double bound2_cubic(Point p0, Point p1, Point p2, Point p3) {
    return 0.5625 * std::max(sq(p0 - p1 * 2 + p2), sq(p1 - p2 * 2 + p3));
}
inline double bound2_conic(Point p0, Point p1, Point p2, double w) {
    const double k = w / (1 + w);
    return k * k * sq(p1 - (p0 * 0.5 + p2 * 0.5));
}

// Midpoint written so that it cannot overflow for finite inputs.
inline Point mid(Point a, Point b) { return {a.x * 0.5 + b.x * 0.5, a.y * 0.5 + b.y * 0.5}; }

// Collects the flattened contours into a Polyline, within Limits::flattened_segments points.
struct PolylineSink {
    Polyline& out;
    std::size_t max_points = current_limits().flattened_segments;
    bool open = false;
    bool closed_flag = false;

    void begin(Point p) {
        end();
        open = true;
        point(p);
    }
    void point(Point p) {
        if (out.points.size() >= max_points)
            throw Error(ErrorKind::Limit, "path too complex: more than " + std::to_string(max_points) +
                                              " line segments after flattening");
        out.points.push_back(p);
    }
    void mark_closed() { closed_flag = true; }
    void end() {
        if (!open) return;
        out.contour_ends.push_back(static_cast<std::uint32_t>(out.points.size()));
        out.closed.push_back(closed_flag);
        open = false;
        closed_flag = false;
    }
};

template <class Sink>
struct Flattener {
    const Affine& m;
    double tol2;       // tolerance squared
    const Rect* cull;  // when set, curves whose control box misses it become their chord
    Sink& out;
    bool balanced = false;  // area-balanced pieces (see quad() and balanced_cubic()); only for filling
    double tol = std::sqrt(tol2);
    // The current point and the contour's start, transformed: every segment starts where the one
    // before it ended (the visitor calls move, line, ... close in path order), so its first control
    // point needs no second transform.
    Point last{}, start{};

    void emit(Point p) { out.point(p); }
    void finish_contour() { out.end(); }

    bool culled(std::initializer_list<Point> pts) const {
        if (!cull) return false;
        double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
        for (Point p : pts) {
            x0 = std::min(x0, p.x);
            x1 = std::max(x1, p.x);
            y0 = std::min(y0, p.y);
            y1 = std::max(y1, p.y);
        }
        return x1 < cull->x0 || x0 > cull->x1 || y1 < cull->y0 || y0 > cull->y1;
    }

    // Each segment's transformed end point is kept in a local and copied into `last`, never read
    // back from it: `x = last = m(p)` reloads last as one 16-byte load just after its two 8-byte
    // stores, which cannot be forwarded and waits for the stores to reach the cache (a quarter of
    // a 12 px glyph's flattening time).
    void move(Point p) {
        const Point q = m(p);
        last = start = q;
        out.begin(q);
    }
    void line(Point, Point p) {
        const Point q = m(p);
        last = q;
        emit(q);
    }
    void close(Point, Point) {
        out.mark_closed();
        last = start;
    }

    // The smallest n >= 2 with n^4 tol^2 >= need: n pieces whose error is at most
    // sqrt(need) / n^2 meet the tolerance. Counted up for the common small n (no square roots or
    // divisions on the glyph path), closed form beyond.
    int piece_count(double need) const {
        int n = 2;
        while (n < 16 && double(n * n) * double(n * n) * tol2 < need) ++n;
        if (n == 16 && 65536.0 * tol2 < need) {
            const double q = std::sqrt(std::sqrt(need / tol2));  // sqrt(bound / tolerance)
            constexpr int kMaxPieces = 1 << limits::kMaxFlattenDepth;
            n = q < kMaxPieces ? static_cast<int>(std::ceil(q)) : kMaxPieces;
        }
        return n;
    }

    void quad(Point, Point b, Point c) {
        const Point p0 = last, p1 = m(b), p2 = m(c);
        last = p2;
        if (culled({p0, p1, p2})) return emit(p2);
        // For a quadratic the second difference of the piece over any parameter interval of
        // length h is h^2 times the whole curve's, so n uniform pieces each stay within
        // bound / n^2 of their chords: n = ceil(sqrt(bound / tolerance)) pieces meet the bound.
        // (Recursive halving reaches the same depth on every branch and so emits the points
        // B(i / 2^k) for the smallest sufficient power of two; any n >= sqrt(bound / tolerance)
        // keeps the same proof, and the smallest one saves a third of the edges on average.)
        // We produce the points B(i / n) by forward differencing (exact for degree 2).
        //
        // Area-balanced pieces (`balanced`, used by the rasterizer). With A = P0 - 2 P1 + P2, on a
        // piece the curve minus its chord is -A h^2 u (1 - u) (u in [0, 1] along the piece): always
        // on the same side, so chords lose area on every piece and the fill is biased thin. Moving
        // every interior vertex by v = -A h^2 / 6 makes the difference A h^2 (1/6 - u (1 - u)),
        // whose integral over u is zero: no area error on interior pieces. The distance is at most
        // |A| h^2 / 6 there and |A| h^2 max|u^2 - 5u/6| = (25/144) |A| h^2 on the two end pieces
        // (one end fixed); both are within (25/36) of the chord bound |A| h^2 / 4, which is what
        // `balanced` measures n against. The end pieces keep half a chord's area error each.
        // (classify_topology's verdict for similarity maps treats a quadratic's chords as lying
        // anywhere in its hull, which the area-balanced vertices keep to as well.)
        const double b2 = bound2_quad(p0, p1, p2);
        if (!(b2 > tol2)) return emit(p2);
        const int n = piece_count(balanced ? b2 * (625.0 / 1296.0) : b2);  // (25/36)^2 of the bound squared
        const double h = 1.0 / n;
        // B(t) = p0 + 2 t (p1 - p0) + t^2 (p0 - 2 p1 + p2): first and second forward differences.
        const Point A = p0 - p1 * 2 + p2, B = (p1 - p0) * 2;
        Point d1 = B * h + A * (h * h), pt = p0;
        const Point d2 = A * (2 * h * h);
        if (balanced) pt -= A * (h * h * (1.0 / 6.0));
        for (int i = 1; i < n; ++i) {
            pt += d1;
            d1 += d2;
            emit(pt);
        }
        emit(p2);
    }

    // Cubics and conics are halved at t = 1/2 while their bound exceeds the tolerance, so every
    // chord joins the ends of one node of the halving tree. Area-balanced cubics (the fill's) are
    // cut into equal pieces instead (balanced_cubic): classify_topology (src/raster/topology.cpp)
    // takes a conic's chords from its halving tree and a quadratic's or cubic's from anywhere in
    // its hull, and checks that a cubic's balanced pieces cannot cross; change them together.
    //
    // A cubic's halving tree is walked without computing the halves. With D0 = P0 - 2 P1 + P2,
    // D1 = P1 - 2 P2 + P3 and L(t) = (1 - t) D0 + t D1 (B''(t) = 6 L(t)), the node over
    // [t0, t0 + h] has the second differences h^2 L(t0) and h^2 L(t0 + h), so its bound is
    // (3/4) h^2 max(|L(t0)|, |L(t0 + h)|): one new value of L per node, since consecutive nodes
    // share an end. The nodes are visited in order (depth-first, left half first) and each leaf
    // emits B(t0 + h), evaluated in the power basis; the last one emits P3 itself. This is the
    // same rule and the same chords as de Casteljau halving, at a fraction of its cost (no control
    // points are split or stacked), up to rounding in the last bits of the points and bounds.
    [[gnu::always_inline]] inline void cubic(Point, Point b, Point c, Point d) {
        const Point p0 = last, p1 = m(b), p2 = m(c), p3 = m(d);
        last = p3;
        if (culled({p0, p1, p2, p3})) return emit(p3);
        const Point D0 = p0 - p1 * 2 + p2, D1 = p1 - p2 * 2 + p3;
        const double s0 = sq(D0), s1 = sq(D1);
        if (!(0.5625 * std::max(s0, s1) > tol2)) return emit(p3);
        if (balanced) return balanced_cubic(p0, p1, p3, D0, D1, std::max(s0, s1));
        // B(t) = p0 + t (3 (p1 - p0) + t (3 D0 + t (D1 - D0))); L(t) = D0 + t (D1 - D0).
        const Point E = D1 - D0, C1 = (p1 - p0) * 3, C2 = D0 * 3;
        // Node (k, j) covers [t0, t0 + h] with h = 2^-k, t0 = j h; it is halved while |L|^2 at
        // one of its ends exceeds lim = tol^2 / (9/16) * 16^k. Its left end's value needs no
        // recomputing while it is halved (halving keeps t0), so that test comes first.
        int k = 0;
        std::uint32_t j = 0;
        double t0 = 0, h = 1, lim = tol2 * (16.0 / 9.0);
        double sa = s0;  // |L(t0)|^2
        for (;;) {
            while (sa > lim && k < limits::kMaxFlattenDepth) {
                ++k;
                j *= 2;
                h *= 0.5;
                lim *= 16;
            }
            double t1, sb;
            for (;;) {
                t1 = t0 + h;  // exact: dyadic
                sb = sq(D0 + E * t1);
                if (!(sb > lim) || k >= limits::kMaxFlattenDepth) break;
                ++k;
                j *= 2;
                h *= 0.5;
                lim *= 16;
            }
            if (t1 >= 1) return emit(p3);
            emit(p0 + (C1 + (C2 + E * t1) * t1) * t1);
            t0 = t1;
            sa = sb;
            // The next node in order: the right sibling of the lowest left child on the way up.
            ++j;
            while ((j & 1) == 0) {
                j >>= 1;
                --k;
                h *= 2;
                lim *= 0.0625;
            }
        }
    }

    // Area-balanced cubic pieces (`balanced`): n pieces of equal parameter length h = 1 / n, every
    // interior vertex B(t) moved by -(h^2 / 2) L(t). On a piece whose ends have L0 and L1 (L is
    // linear), the curve minus the line between the moved vertices is, for u in [0, 1] along it,
    //   e(u) = h^2 (a(u) L0 + a(1 - u) L1),  a(u) = 1/2 - 5u/2 + 3u^2 - u^3,
    // which integrates to zero: interior pieces lose no area, as the balanced quadratic pieces (the
    // quadratic is the case L0 = L1). |a(u)| + |a(1 - u)| is at most 1/2 (at the ends; 1/4 at the
    // middle), so |e| <= (h^2 / 2) max(|L0|, |L1|). On the two end pieces (one end fixed, not
    // moved) the weight of the fixed end's L becomes u (1 - u) (2 - u) and the sum of the two
    // weights' sizes is at most 25/48 (at u = 5/12). |L| is at most M = max(|D0|, |D1|)
    // everywhere, so n is the smallest with (25/48) M h^2 <= tol: the quadratic's count, with
    // M in place of |A| / 3 (a quadratic raised to a cubic has D0 = D1 = A / 3). The moved
    // vertices keep non-negative Bernstein weights, so they stay in the control points' hull.
    void balanced_cubic(Point p0, Point p1, Point p3, Point D0, Point D1, double m2) {
        const Point E = D1 - D0, C1 = (p1 - p0) * 3, C2 = D0 * 3;
        const int n = piece_count(m2 * (625.0 / 2304.0));  // ((25/48) M)^2
        const double h = 1.0 / n, k = 0.5 * h * h;
        const Point base = p0 - D0 * k, slope = E * k;
        for (int i = 1; i < n; ++i) {
            const double t = i * h;
            emit(base + (C1 + (C2 + E * t) * t) * t - slope * t);
        }
        emit(p3);
    }

    void conic(Point, Point b, Point c, double w) {
        const Point p0 = last, p1 = m(b), p2 = m(c);
        last = p2;
        if (culled({p0, p1, p2})) return emit(p2);
        struct K {
            Point p0, p1, p2;
            double w;
            int depth;
        };
        K stack[limits::kMaxFlattenDepth + 2];
        int n = 0;
        stack[n++] = {p0, p1, p2, w, 0};
        while (n > 0) {
            const K q = stack[--n];
            if (q.depth >= limits::kMaxFlattenDepth || !(bound2_conic(q.p0, q.p1, q.p2, q.w) > tol2)) {
                // A sink that must not see a point far outside the control points (which an
                // extreme weight can make, or NaN) checks each one the halving made.
                if constexpr (requires { Sink::check_rational(q.p2); }) Sink::check_rational(q.p2);
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

}  // namespace flatten_detail

// Validates a flatten call: finite transform, points and weights (also after the transform),
// a positive tolerance; throws Error. Returns the bounds of the transformed points (control
// points included; empty with infinite corners for an empty path).
Rect check_flatten_input(const Path& path, const Affine& m, double tolerance);

// Flattens `path` mapped by `m` into `sink`, which receives begin(p) for each contour start,
// point(p) for each following polyline vertex, mark_closed() for an explicit close and end().
// A sink may also define a static check_rational(Point), called with every point the halving of a
// conic makes (the only points that can fall outside the control points' hull), before point().
//
// `balanced`: quadratic pieces are moved off the curve so that they lose no area (see
// Flattener::quad), still within `tolerance` of it. Right for filling; the public flatten(), whose
// vertices lie on the curve, does not use it.
template <class Sink>
void flatten_into(const Path& path, const Affine& m, double tolerance, const Rect* cull, Sink& sink,
                  bool balanced = false) {
    flatten_detail::Flattener<Sink> f{m, tolerance * tolerance, cull, sink, balanced};
    path.visit(f);
    f.finish_contour();
}

// As flatten(), but a curve whose transformed control points all lie outside `cull` (when given) is
// replaced by its chord: outside the clip rectangle only a segment's end points matter to coverage.
void flatten_culled(const Path& path, const Affine& m, double tolerance, const Rect* cull, Polyline& out,
                    FlattenMode mode = FlattenMode::Chords);

}  // namespace casteljau
