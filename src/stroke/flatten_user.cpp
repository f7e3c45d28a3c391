// Stroke stage: flattening of the stroked path in user space.
//
// TEMPORARY local flattener, used until the shared casteljau::flatten (src/path/flatten.cpp) lands
// on main; then flatten_user() becomes a call to it with the identity transform.
// Each curve is cut into n equal parameter steps, n chosen from the second-difference bound: a
// polynomial Bezier of degree d stays within d(d-1)/8 * max|P_i - 2P_(i+1) + P_(i+2)| of its chord,
// and cutting into n pieces divides the second differences by n^2.
#include <algorithm>
#include <cmath>

#include "casteljau/error.hpp"
#include "stroke/stroke_internal.hpp"

namespace casteljau::stroke_detail {
namespace {

constexpr int kMaxPieces = 1 << 12;

int pieces_for(double bound, double tol) {
    if (!(bound > tol)) return 1;
    const double n = std::ceil(std::sqrt(bound / tol));
    return static_cast<int>(std::min<double>(n, kMaxPieces));
}

struct Flattener {
    double tol;
    Polyline& out;
    bool open = false;

    void begin(Point p) {
        end_contour(false);
        out.points.push_back(p);
        open = true;
    }
    void end_contour(bool closed) {
        if (!open) return;
        const std::size_t start = out.contour_ends.empty() ? 0 : out.contour_ends.back();
        const std::size_t n = out.points.size() - start;
        if (n < 2 && !closed) {
            out.points.resize(start);  // a lone move draws nothing
        } else {
            out.contour_ends.push_back(static_cast<std::uint32_t>(out.points.size()));
            out.closed.push_back(closed);
        }
        open = false;
    }
    void push(Point p) {
        if (out.points.size() >= limits::kMaxFlattenedSegments)
            throw Error(ErrorKind::Limit, "stroke: path flattens to too many segments");
        out.points.push_back(p);
    }

    void move(Point p) { begin(p); }
    void line(Point, Point b) { push(b); }
    void quad(Point a, Point c, Point b) {
        const int n = pieces_for(0.25 * (a - c * 2 + b).length(), tol);
        for (int i = 1; i < n; ++i) {
            const double t = double(i) / n, mt = 1 - t;
            push(a * (mt * mt) + c * (2 * mt * t) + b * (t * t));
        }
        push(b);
    }
    void cubic(Point a, Point c1, Point c2, Point b) {
        const double dd = std::max((a - c1 * 2 + c2).length(), (c1 - c2 * 2 + b).length());
        const int n = pieces_for(0.75 * dd, tol);
        for (int i = 1; i < n; ++i) {
            const double t = double(i) / n, mt = 1 - t;
            push(a * (mt * mt * mt) + c1 * (3 * mt * mt * t) + c2 * (3 * mt * t * t) + b * (t * t * t));
        }
        push(b);
    }
    void conic(Point a, Point c, Point b, double w) {
        // Heuristic (temporary): the quadratic bound, scaled up for heavy weights.
        const int n = std::max(4, pieces_for(0.25 * std::max(w, 1.0) * (a - c * 2 + b).length(), tol / 2));
        for (int i = 1; i < n; ++i) {
            const double t = double(i) / n, mt = 1 - t;
            const double b0 = mt * mt, b1 = 2 * w * mt * t, b2 = t * t;
            push((a * b0 + c * b1 + b * b2) / (b0 + b1 + b2));
        }
        push(b);
    }
    void close(Point, Point) { end_contour(true); }
};

}  // namespace

void flatten_user(const Path& path, double tol, Polyline& out) {
    out.clear();
    Flattener f{tol, out};
    path.visit(f);
    f.end_contour(false);
}

}  // namespace casteljau::stroke_detail
