// Helpers shared by the curve toolkit tests (test_bezier.cpp, test_spline.cpp, test_nurbs.cpp,
// test_surface.cpp): seeded random points and point comparisons.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "casteljau/vec.hpp"

namespace curve_test {

using casteljau::Point;
using casteljau::Point3;

template <class P> P random_point(std::mt19937& rng, double lo = -100, double hi = 100) {
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

template <class P> std::vector<P> random_points(std::mt19937& rng, std::size_t n, double lo = -100, double hi = 100) {
    std::vector<P> v;
    v.reserve(n);
    for (std::size_t i = 0; i < n; ++i) v.push_back(random_point<P>(rng, lo, hi));
    return v;
}

inline double uniform(std::mt19937& rng, double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}

template <class P> double dist(const P& a, const P& b) { return (a - b).length(); }

template <class P> double max_norm(const std::vector<P>& v) {
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

}  // namespace curve_test
