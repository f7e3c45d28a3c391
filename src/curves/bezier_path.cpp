// Curve toolkit: Bézier curves to Path (include/casteljau/bezier.hpp, "bridge to the rasterizer").
//
// Degree <= 3 maps to a verb exactly. Higher degrees: the Hermite cubic C of a piece (same end points,
// same end derivatives: C1 = P0 + (n/3)(P1 - P0), C2 = Pn - (n/3)(Pn - Pn-1)) is accepted when the
// proven bound max_i |P_i - E_i| <= tolerance, E = C elevated to degree n: P - C is then a degree-n
// Bézier with control points P_i - E_i, and its values lie in their convex hull. Otherwise the piece
// is halved by de Casteljau; an explicit stack and limits::kMaxCubicApproxDepth bound the work.
#include <algorithm>
#include <cmath>
#include <vector>

#include "casteljau/bezier.hpp"
#include "curves/curve_util.hpp"
#include "casteljau/limits.hpp"

namespace casteljau {

using namespace curves_detail;

namespace {

void check_tolerance(double tolerance) {
    if (!(tolerance > 0) || !std::isfinite(tolerance))
        throw Error(ErrorKind::InvalidArgument, "tolerance must be a positive finite number, got " + num(tolerance));
}

// Hermite cubic of a degree-n piece and the hull bound of its deviation.
double hermite_cubic(const std::vector<Point>& p, Point c[4]) {
    const std::size_t n = p.size() - 1;
    const double k = static_cast<double>(n) / 3.0;
    c[0] = p[0];
    c[1] = p[0] + (p[1] - p[0]) * k;
    c[2] = p[n] - (p[n] - p[n - 1]) * k;
    c[3] = p[n];
    // Elevate the cubic to degree n.
    std::vector<Point> e(c, c + 4);
    while (e.size() < p.size()) {
        const std::size_t m = e.size() - 1;
        std::vector<Point> next(e.size() + 1);
        next.front() = e.front();
        next.back() = e.back();
        for (std::size_t i = 1; i <= m; ++i) {
            const double a = static_cast<double>(i) / static_cast<double>(m + 1);
            next[i] = e[i - 1] * a + e[i] * (1 - a);
        }
        e = std::move(next);
    }
    double bound = 0;
    for (std::size_t i = 0; i <= n; ++i) bound = std::max(bound, (p[i] - e[i]).length());
    return bound;
}

void halve(const std::vector<Point>& p, std::vector<Point>& left, std::vector<Point>& right) {
    const std::size_t n = p.size() - 1;
    std::vector<Point> b = p;
    left.resize(p.size());
    right.resize(p.size());
    left[0] = b[0];
    right[n] = b[n];
    for (std::size_t r = 1; r <= n; ++r) {
        for (std::size_t i = 0; i <= n - r; ++i) b[i] = midpoint(b[i], b[i + 1]);
        left[r] = b[0];
        right[n - r] = b[n - r];
    }
}

}  // namespace

double append_to_path(Path& path, const Bezier<Point>& curve, double tolerance) {
    check_tolerance(tolerance);
    const auto pts = curve.points();
    if (path.empty() || path.current_point() != pts.front()) path.move_to(pts.front());
    switch (curve.degree()) {
        case 1: path.line_to(pts[1]); return 0;
        case 2: path.quad_to(pts[1], pts[2]); return 0;
        case 3: path.cubic_to(pts[1], pts[2], pts[3]); return 0;
        default: break;
    }
    struct Item {
        std::vector<Point> p;
        int depth;
    };
    std::vector<Item> stack;
    stack.push_back({std::vector<Point>(pts.begin(), pts.end()), 0});
    double achieved = 0;
    std::vector<Point> left, right;
    while (!stack.empty()) {
        Item it = std::move(stack.back());
        stack.pop_back();
        Point c[4];
        const double bound = hermite_cubic(it.p, c);
        if (bound <= tolerance || it.depth >= limits::kMaxCubicApproxDepth) {
            path.cubic_to(c[1], c[2], c[3]);
            achieved = std::max(achieved, bound);
            continue;
        }
        halve(it.p, left, right);
        stack.push_back({right, it.depth + 1});
        stack.push_back({left, it.depth + 1});
    }
    return achieved;
}

Path to_path(const Bezier<Point>& curve, double tolerance) {
    Path p;
    append_to_path(p, curve, tolerance);
    return p;
}

Path to_path(std::span<const Bezier<Point>> pieces, double tolerance) {
    check_tolerance(tolerance);
    Path p;
    for (const auto& b : pieces) append_to_path(p, b, tolerance);
    return p;
}

}  // namespace casteljau
