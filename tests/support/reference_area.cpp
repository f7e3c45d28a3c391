// tests/support/reference_area.cpp: the independent exact-area reference (see reference_area.hpp).
#include "reference_area.hpp"

#include <algorithm>
#include <cmath>

namespace casteljau::ref {

// ---------------------------------------------------------------------------------------------
// Grid and small helpers

CoverageGrid::CoverageGrid(const IRect& r) : bounds(r) {
    const std::size_t w = r.empty() ? 0 : static_cast<std::size_t>(r.width());
    const std::size_t h = r.empty() ? 0 : static_cast<std::size_t>(r.height());
    v.assign(w * h, 0.0);
}

double CoverageGrid::at(int x, int y) const {
    if (x < bounds.x0 || x >= bounds.x1 || y < bounds.y0 || y >= bounds.y1) return 0.0;
    return v[static_cast<std::size_t>(y - bounds.y0) * bounds.width() + (x - bounds.x0)];
}

double CoverageGrid::sum() const {
    double s = 0;
    for (double x : v) s += x;
    return s;
}

double signed_area(const Contour& c) {
    if (c.size() < 3) return 0.0;
    // Relative to the first point, for precision far from the origin.
    const Point o = c[0];
    double s = 0;
    for (std::size_t i = 1; i + 1 < c.size(); ++i) {
        const double ax = c[i].x - o.x, ay = c[i].y - o.y;
        const double bx = c[i + 1].x - o.x, by = c[i + 1].y - o.y;
        s += ax * by - ay * bx;
    }
    return 0.5 * s;
}

Point apply(const Affine& m, Point p) { return {m.a * p.x + m.c * p.y + m.e, m.b * p.x + m.d * p.y + m.f}; }

Contour transformed(const Contour& c, const Affine& m) {
    Contour out;
    out.reserve(c.size());
    for (Point p : c) out.push_back(apply(m, p));
    return out;
}

Contours transformed(const Contours& cs, const Affine& m) {
    Contours out;
    out.reserve(cs.size());
    for (const Contour& c : cs) out.push_back(transformed(c, m));
    return out;
}

IRect pixel_bounds(const Contours& cs, int pad) {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const Contour& c : cs)
        for (Point p : c) {
            x0 = std::min(x0, p.x);
            x1 = std::max(x1, p.x);
            y0 = std::min(y0, p.y);
            y1 = std::max(y1, p.y);
        }
    if (!(x1 >= x0)) return {};
    return {static_cast<int>(std::floor(x0)) - pad, static_cast<int>(std::floor(y0)) - pad,
            static_cast<int>(std::ceil(x1)) + pad, static_cast<int>(std::ceil(y1)) + pad};
}

Path to_path(const Contours& cs) {
    Path p;
    for (const Contour& c : cs) {
        if (c.empty()) continue;
        p.move_to(c[0]);
        for (std::size_t i = 1; i < c.size(); ++i) p.line_to(c[i]);
        p.close();
    }
    return p;
}

// ---------------------------------------------------------------------------------------------
// (a) Sutherland-Hodgman

namespace {

// Keeps the part of `in` where s * (coord - k) >= 0, coord = x (axis 0) or y (axis 1).
void clip_half_plane(const std::vector<Point>& in, std::vector<Point>& out, int axis, double k, double s) {
    out.clear();
    const std::size_t n = in.size();
    if (n == 0) return;
    auto val = [&](Point p) { return s * ((axis == 0 ? p.x : p.y) - k); };
    for (std::size_t i = 0; i < n; ++i) {
        const Point cur = in[i], nxt = in[(i + 1) % n];
        const double vc = val(cur), vn = val(nxt);
        if (vc >= 0) out.push_back(cur);
        if ((vc >= 0) != (vn >= 0)) {
            const double t = vc / (vc - vn);
            Point q{cur.x + (nxt.x - cur.x) * t, cur.y + (nxt.y - cur.y) * t};
            // Put the intersection exactly on the clip line.
            if (axis == 0)
                q.x = k;
            else
                q.y = k;
            out.push_back(q);
        }
    }
}

}  // namespace

CoverageGrid clip_area_simple(const Contour& poly, const IRect& region) {
    CoverageGrid g(region);
    if (region.empty() || poly.size() < 3) return g;
    const IRect pb = pixel_bounds({poly});
    const int x0 = std::max(region.x0, pb.x0), x1 = std::min(region.x1, pb.x1);
    const int y0 = std::max(region.y0, pb.y0), y1 = std::min(region.y1, pb.y1);
    std::vector<Point> a, b;
    for (int py = y0; py < y1; ++py) {
        for (int px = x0; px < x1; ++px) {
            // Work relative to the pixel's corner: the square becomes [0, 1]^2.
            a.clear();
            for (Point p : poly) a.push_back({p.x - px, p.y - py});
            clip_half_plane(a, b, 0, 0.0, 1.0);
            clip_half_plane(b, a, 0, 1.0, -1.0);
            clip_half_plane(a, b, 1, 0.0, 1.0);
            clip_half_plane(b, a, 1, 1.0, -1.0);
            double s = 0;
            for (std::size_t i = 0; i < a.size(); ++i) {
                const Point p = a[i], q = a[(i + 1) % a.size()];
                s += p.x * q.y - p.y * q.x;
            }
            g.cell(px, py) = std::min(1.0, std::abs(0.5 * s));
        }
    }
    return g;
}

// ---------------------------------------------------------------------------------------------
// (b) Slab integration

namespace {

struct RefEdge {
    double x0, y0, x1, y1;  // y0 < y1 after orientation
    int dir;                // +1 when the original edge goes down (y increasing)
    double x_at(double y) const {
        if (y <= y0) return x0;
        if (y >= y1) return x1;
        return x0 + (y - y0) * ((x1 - x0) / (y1 - y0));
    }
};

struct Crossing {
    double xt, xb, xm;  // x at the slab's top, bottom and middle
    int dir;
};

// Mean over the slab of clamp(X - col, 0, 1) where X runs linearly from xt (top) to xb (bottom).
double column_mean(double xt, double xb, double col) {
    auto u = [&](double x) { return std::clamp(x - col, 0.0, 1.0); };
    if (std::max(xt, xb) <= col) return 0.0;
    if (std::min(xt, xb) >= col + 1) return 1.0;
    double ts[4] = {0.0, 1.0, 0.0, 0.0};
    int n = 2;
    if (xt != xb) {
        for (double c : {col, col + 1.0}) {
            const double t = (c - xt) / (xb - xt);
            if (t > 0 && t < 1) ts[n++] = t;
        }
    }
    for (int i = 1; i < n; ++i)  // insertion sort of at most 4 values
        for (int j = i; j > 0 && ts[j - 1] > ts[j]; --j) std::swap(ts[j - 1], ts[j]);
    double s = 0;
    for (int i = 0; i + 1 < n; ++i) {
        const double ta = ts[i], tb = ts[i + 1];
        // clamp(X) is linear inside [ta, tb], so the trapezoid rule is exact there.
        const double xa = xt + (xb - xt) * ta, xbb = xt + (xb - xt) * tb;
        s += (tb - ta) * 0.5 * (u(xa) + u(xbb));
    }
    return s;
}

inline bool filled(int w, FillRule rule) { return rule == FillRule::NonZero ? w != 0 : (w & 1) != 0; }

}  // namespace

CoverageGrid slab_area(const Contours& polys, FillRule rule, const IRect& region) {
    CoverageGrid g(region);
    if (region.empty()) return g;
    std::vector<RefEdge> edges;
    for (const Contour& c : polys) {
        const std::size_t n = c.size();
        if (n < 2) continue;
        for (std::size_t i = 0; i < n; ++i) {
            const Point p = c[i], q = c[(i + 1) % n];
            if (p.y == q.y) continue;  // horizontal: no crossing with any horizontal line
            if (p.y < q.y)
                edges.push_back({p.x, p.y, q.x, q.y, +1});
            else
                edges.push_back({q.x, q.y, p.x, p.y, -1});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const RefEdge& a, const RefEdge& b) { return a.y0 < b.y0; });

    std::vector<const RefEdge*> row_edges;
    std::vector<double> breaks;
    std::vector<Crossing> cross;
    std::vector<const RefEdge*> active;  // edges with y0 < current row bottom, pruned lazily
    std::size_t next = 0;
    const double W = region.width();
    for (int row = region.y0; row < region.y1; ++row) {
        const double ry0 = row, ry1 = row + 1.0;
        while (next < edges.size() && edges[next].y0 < ry1) active.push_back(&edges[next++]);
        active.erase(std::remove_if(active.begin(), active.end(), [&](const RefEdge* e) { return e->y1 <= ry0; }),
                     active.end());
        row_edges.clear();
        for (const RefEdge* e : active)
            if (e->y1 > ry0 && e->y0 < ry1) row_edges.push_back(e);
        if (row_edges.empty()) continue;

        breaks.clear();
        breaks.push_back(ry0);
        breaks.push_back(ry1);
        for (const RefEdge* e : row_edges) {
            if (e->y0 > ry0) breaks.push_back(e->y0);
            if (e->y1 < ry1) breaks.push_back(e->y1);
        }
        // Pairwise crossings inside the row: where x_a(y) - x_b(y) changes sign strictly.
        for (std::size_t i = 0; i < row_edges.size(); ++i) {
            const RefEdge& a = *row_edges[i];
            for (std::size_t j = i + 1; j < row_edges.size(); ++j) {
                const RefEdge& b = *row_edges[j];
                const double lo = std::max({a.y0, b.y0, ry0}), hi = std::min({a.y1, b.y1, ry1});
                if (!(hi > lo)) continue;
                const double dlo = a.x_at(lo) - b.x_at(lo), dhi = a.x_at(hi) - b.x_at(hi);
                if ((dlo < 0 && dhi > 0) || (dlo > 0 && dhi < 0)) {
                    const double y = lo + (hi - lo) * (dlo / (dlo - dhi));
                    if (y > lo && y < hi) breaks.push_back(y);
                }
            }
        }
        std::sort(breaks.begin(), breaks.end());
        breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());

        for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
            const double s0 = breaks[k], s1 = breaks[k + 1];
            const double h = s1 - s0;
            if (!(h > 0)) continue;
            const double ym = 0.5 * (s0 + s1);
            cross.clear();
            for (const RefEdge* e : row_edges)
                if (e->y0 < ym && ym < e->y1) cross.push_back({e->x_at(s0), e->x_at(s1), e->x_at(ym), e->dir});
            std::sort(cross.begin(), cross.end(), [](const Crossing& a, const Crossing& b) { return a.xm < b.xm; });
            int w = 0;
            bool inside = false;
            const Crossing* left = nullptr;
            for (const Crossing& c : cross) {
                w += c.dir;
                const bool now = filled(w, rule);
                if (!inside && now) left = &c;
                if (inside && !now) {
                    // Covered interval between *left and c: columns it can touch.
                    const double lx = std::min(left->xt, left->xb) - region.x0;
                    const double rx = std::max(c.xt, c.xb) - region.x0;
                    const int c0 = static_cast<int>(std::floor(std::clamp(lx, 0.0, W)));
                    const int c1 = static_cast<int>(std::ceil(std::clamp(rx, 0.0, W)));
                    for (int col = c0; col < c1; ++col) {
                        const double cx = region.x0 + col;
                        const double area = h * (column_mean(c.xt, c.xb, cx) - column_mean(left->xt, left->xb, cx));
                        g.cell(region.x0 + col, row) += area;
                    }
                }
                inside = now;
            }
        }
    }
    for (double& x : g.v) x = std::clamp(x, 0.0, 1.0);
    return g;
}

// ---------------------------------------------------------------------------------------------
// Fine flattening by uniform parameter steps
//
// Bounds used (for a curve B of degree n on [0, 1] cut into N equal parameter steps, each chord is
// the linear interpolant of B on its step, so the chord error is at most (1/8) dt^2 max|B''| with
// dt = 1/N):
//   quadratic: B'' = 2 (P0 - 2 P1 + P2), so N = ceil(sqrt(|P0 - 2 P1 + P2| / (4 tol)));
//   cubic: |B''| <= 6 max(|P0 - 2 P1 + P2|, |P1 - 2 P2 + P3|), so N = ceil(sqrt(0.75 M / tol)).
//   conic (weights 1, w, 1): no simple closed bound is used; N is the quadratic's count times
//   4 max(w, 1/w), generous for the weights the tests use (w in [0.5, 2]).

namespace {

constexpr int kMaxSteps = 1 << 16;

int steps_for(double need) {
    if (!(need > 1)) return 1;
    return static_cast<int>(std::min<double>(kMaxSteps, std::ceil(need)));
}

struct FineFlattener {
    const Affine& m;
    double tol;
    Contours& out;

    void move(Point p) { out.push_back({ref::apply(m, p)}); }
    void line(Point, Point p) { out.back().push_back(ref::apply(m, p)); }
    void close(Point, Point) {}
    void quad(Point a, Point b, Point c) {
        const Point p0 = ref::apply(m, a), p1 = ref::apply(m, b), p2 = ref::apply(m, c);
        const double d = std::hypot(p0.x - 2 * p1.x + p2.x, p0.y - 2 * p1.y + p2.y);
        const int n = steps_for(std::sqrt(d / (4 * tol)));
        for (int i = 1; i < n; ++i) {
            const double t = static_cast<double>(i) / n, s = 1 - t;
            const double b0 = s * s, b1 = 2 * s * t, b2 = t * t;
            out.back().push_back({b0 * p0.x + b1 * p1.x + b2 * p2.x, b0 * p0.y + b1 * p1.y + b2 * p2.y});
        }
        out.back().push_back(p2);
    }
    void cubic(Point a, Point b, Point c, Point d) {
        const Point p0 = ref::apply(m, a), p1 = ref::apply(m, b), p2 = ref::apply(m, c), p3 = ref::apply(m, d);
        const double m0 = std::hypot(p0.x - 2 * p1.x + p2.x, p0.y - 2 * p1.y + p2.y);
        const double m1 = std::hypot(p1.x - 2 * p2.x + p3.x, p1.y - 2 * p2.y + p3.y);
        const int n = steps_for(std::sqrt(0.75 * std::max(m0, m1) / tol));
        for (int i = 1; i < n; ++i) {
            const double t = static_cast<double>(i) / n, s = 1 - t;
            const double b0 = s * s * s, b1 = 3 * s * s * t, b2 = 3 * s * t * t, b3 = t * t * t;
            out.back().push_back(
                {b0 * p0.x + b1 * p1.x + b2 * p2.x + b3 * p3.x, b0 * p0.y + b1 * p1.y + b2 * p2.y + b3 * p3.y});
        }
        out.back().push_back(p3);
    }
    void conic(Point a, Point b, Point c, double w) {
        const Point p0 = ref::apply(m, a), p1 = ref::apply(m, b), p2 = ref::apply(m, c);
        const double d = std::hypot(p0.x - 2 * p1.x + p2.x, p0.y - 2 * p1.y + p2.y);
        const int n = steps_for(4 * std::max(w, 1 / w) * std::sqrt(d / (4 * tol)));
        for (int i = 1; i < n; ++i) {
            const double t = static_cast<double>(i) / n, s = 1 - t;
            const double b0 = s * s, b1 = 2 * s * t * w, b2 = t * t;
            const double den = b0 + b1 + b2;
            out.back().push_back(
                {(b0 * p0.x + b1 * p1.x + b2 * p2.x) / den, (b0 * p0.y + b1 * p1.y + b2 * p2.y) / den});
        }
        out.back().push_back(p2);
    }
};

}  // namespace

Contours fine_flatten(const Path& path, const Affine& m, double tolerance) {
    Contours out;
    path.visit(FineFlattener{m, tolerance, out});
    return out;
}

CoverageGrid path_reference(const Path& path, const Affine& m, FillRule rule, const IRect& region, double tolerance) {
    return slab_area(fine_flatten(path, m, tolerance), rule, region);
}

}  // namespace casteljau::ref
