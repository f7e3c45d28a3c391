// Helpers shared by the curve toolkit tests (test_bezier.cpp, test_spline.cpp, test_nurbs.cpp,
// test_surface.cpp): seeded random points and point comparisons.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/path.hpp"
#include "casteljau/vec.hpp"

namespace curve_test {

using casteljau::Point;
using casteljau::Point3;

template <class P>
P random_point(std::mt19937& rng, double lo = -100, double hi = 100) {
    std::uniform_real_distribution<double> d(lo, hi);
    if constexpr (std::is_same_v<P, Point>) {
        const double x = d(rng);
        return Point{x, d(rng)};
    } else {
        const double x = d(rng);
        const double y = d(rng);
        return Point3{x, y, d(rng)};
    }
}

template <class P>
std::vector<P> random_points(std::mt19937& rng, std::size_t n, double lo = -100, double hi = 100) {
    std::vector<P> v;
    v.reserve(n);
    for (std::size_t i = 0; i < n; ++i) v.push_back(random_point<P>(rng, lo, hi));
    return v;
}

inline double uniform(std::mt19937& rng, double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

template <class P>
double dist(const P& a, const P& b) {
    return (a - b).length();
}

template <class P>
double max_norm(const std::vector<P>& v) {
    double m = 0;
    for (const auto& p : v) m = std::max(m, p.length());
    return m;
}

// Is p inside the convex hull of pts (2-D), with slack eps? Andrew's monotone chain, then edge tests.
inline bool in_convex_hull(const std::vector<Point>& pts, Point p, double eps) {
    std::vector<Point> s = pts;
    std::sort(s.begin(), s.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (s.size() < 3) {
        // Segment: distance to it.
        const Point a = s.front(), b = s.back(), d = b - a;
        const double l2 = d.dot(d);
        const double t = l2 > 0 ? std::clamp((p - a).dot(d) / l2, 0.0, 1.0) : 0.0;
        return ((a + d * t) - p).length() <= eps;
    }
    std::vector<Point> h(2 * s.size());
    std::size_t k = 0;
    auto cross = [](Point o, Point a, Point b) { return (a - o).cross(b - o); };
    for (std::size_t i = 0; i < s.size(); ++i) {
        while (k >= 2 && cross(h[k - 2], h[k - 1], s[i]) <= 0) --k;
        h[k++] = s[i];
    }
    for (std::size_t i = s.size() - 1, t = k + 1; i-- > 0;) {
        while (k >= t && cross(h[k - 2], h[k - 1], s[i]) <= 0) --k;
        h[k++] = s[i];
    }
    h.resize(k - 1);
    if (h.size() < 3) return in_convex_hull({h.front(), h.back()}, p, eps);
    for (std::size_t i = 0; i < h.size(); ++i) {
        const Point a = h[i], b = h[(i + 1) % h.size()];
        const Point e = b - a;
        // Counter-clockwise hull: p must be left of every edge (signed distance >= -eps).
        if (e.cross(p - a) / e.length() < -eps) return false;
    }
    return true;
}

// The kind of Error that f throws, or ErrorKind::Io as a "did not throw" marker.
inline casteljau::ErrorKind kind_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const casteljau::Error& e) { return e.kind(); }
    return casteljau::ErrorKind::Io;
}

// Largest distance from points of the cubic pieces of `p` (per_piece + 1 samples each) to the
// curve `c` (anything with eval(t) on [0, 1]), found by a coarse search over `coarse` samples of
// c refined with `refine` steps around the nearest sample.
template <class C>
double max_cubic_path_deviation(const casteljau::Path& p, const C& c, int coarse, int per_piece, int refine) {
    using casteljau::Point;
    std::vector<Point> orig;
    for (int k = 0; k <= coarse; ++k) orig.push_back(c.eval(static_cast<double>(k) / coarse));
    double worst = 0;
    struct V {
        const C& c;
        const std::vector<Point>& orig;
        int per_piece, refine;
        double& worst;
        void move(Point) {}
        void line(Point, Point) {}
        void quad(Point, Point, Point) {}
        void conic(Point, Point, Point, double) {}
        void close(Point, Point) {}
        void cubic(Point a, Point b, Point cc, Point d) {
            for (int k = 0; k <= per_piece; ++k) {
                const double t = static_cast<double>(k) / per_piece, u = 1 - t;
                const Point q = a * (u * u * u) + b * (3 * u * u * t) + cc * (3 * u * t * t) + d * (t * t * t);
                std::size_t bi = 0;
                for (std::size_t i = 0; i < orig.size(); ++i)
                    if (dist(orig[i], q) < dist(orig[bi], q)) bi = i;
                const double n = static_cast<double>(orig.size() - 1);
                const double lo = std::max(0.0, (static_cast<double>(bi) - 1) / n);
                const double hi = std::min(1.0, (static_cast<double>(bi) + 1) / n);
                double best = dist(orig[bi], q);
                for (int j = 0; j <= refine; ++j) best = std::min(best, dist(c.eval(lo + (hi - lo) * j / refine), q));
                worst = std::max(worst, best);
            }
        }
    } v{c, orig, per_piece, refine, worst};
    p.visit(v);
    return worst;
}

}  // namespace curve_test
