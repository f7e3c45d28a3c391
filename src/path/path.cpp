// Path stage: building, bounds, transforms and reversal of Paths (include/casteljau/path.hpp).
#include "casteljau/path.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "casteljau/error.hpp"

namespace casteljau {

void Path::ensure_contour() {
    if (!open_) {
        verbs_.push_back(Verb::Move);
        push_point(current_);
        start_ = current_;
        open_ = true;
    }
}

Path& Path::move_to(Point p) {
    // Consecutive moves: the last one wins (an empty contour draws nothing).
    if (!verbs_.empty() && verbs_.back() == Verb::Move) {
        points_.back() = p;
        recompute_cache();  // the replaced point may have been an extreme
    } else {
        verbs_.push_back(Verb::Move);
        push_point(p);
    }
    start_ = current_ = p;
    open_ = true;
    return *this;
}

Path& Path::line_to(Point p) {
    ensure_contour();
    verbs_.push_back(Verb::Line);
    push_point(p);
    current_ = p;
    return *this;
}

Path& Path::quad_to(Point c, Point p) {
    ensure_contour();
    verbs_.push_back(Verb::Quad);
    push_point(c);
    push_point(p);
    current_ = p;
    return *this;
}

Path& Path::cubic_to(Point c1, Point c2, Point p) {
    ensure_contour();
    verbs_.push_back(Verb::Cubic);
    push_point(c1);
    push_point(c2);
    push_point(p);
    current_ = p;
    return *this;
}

Path& Path::conic_to(Point c, Point p, double w) {
    if (!(w > 0) || !std::isfinite(w))
        throw Error(ErrorKind::InvalidArgument, "conic weight must be a positive finite number");
    ensure_contour();
    verbs_.push_back(Verb::Conic);
    push_point(c);
    push_point(p);
    weights_.push_back(w);
    current_ = p;
    return *this;
}

Path& Path::close() {
    if (open_ && !verbs_.empty() && verbs_.back() != Verb::Close) { verbs_.push_back(Verb::Close); }
    open_ = false;
    current_ = start_;
    return *this;
}

void Path::clear() {
    verbs_.clear();
    points_.clear();
    weights_.clear();
    open_ = false;
    start_ = current_ = {};
    recompute_cache();
}

void Path::recompute_cache() {
    cx0_ = cy0_ = INFINITY;
    cx1_ = cy1_ = -INFINITY;
    finite_ = true;
    include_all(points_);
}

void Path::include_all(std::span<const Point> pts) {
    // include() for each point, with the running values in registers. A coordinate times zero is
    // zero when it is finite and NaN when it is not, so their sum says whether all were finite.
    double x0 = cx0_, y0 = cy0_, x1 = cx1_, y1 = cy1_, zero = 0;
    for (const Point& p : pts) {
        zero += p.x * 0.0 + p.y * 0.0;
        x0 = p.x < x0 ? p.x : x0;
        y0 = p.y < y0 ? p.y : y0;
        x1 = p.x > x1 ? p.x : x1;
        y1 = p.y > y1 ? p.y : y1;
    }
    cx0_ = x0;
    cy0_ = y0;
    cx1_ = x1;
    cy1_ = y1;
    finite_ = finite_ && zero == 0;
}

std::size_t Path::contour_count() const {
    return static_cast<std::size_t>(std::count(verbs_.begin(), verbs_.end(), Verb::Move));
}

Path& Path::add_rect(const Rect& r) {
    move_to({r.x0, r.y0});
    line_to({r.x1, r.y0});
    line_to({r.x1, r.y1});
    line_to({r.x0, r.y1});
    return close();
}

// Quarter ellipse arcs as cubics: control distance kappa = 4/3 (sqrt(2) - 1); the radial error is
// 2.7e-4 of the radius at most.
static constexpr double kKappa = 0.5522847498307936;

Path& Path::add_ellipse(Point c, double rx, double ry) {
    const double kx = rx * kKappa, ky = ry * kKappa;
    move_to({c.x + rx, c.y});
    cubic_to({c.x + rx, c.y + ky}, {c.x + kx, c.y + ry}, {c.x, c.y + ry});
    cubic_to({c.x - kx, c.y + ry}, {c.x - rx, c.y + ky}, {c.x - rx, c.y});
    cubic_to({c.x - rx, c.y - ky}, {c.x - kx, c.y - ry}, {c.x, c.y - ry});
    cubic_to({c.x + kx, c.y - ry}, {c.x + rx, c.y - ky}, {c.x + rx, c.y});
    return close();
}

Path& Path::add_round_rect(const Rect& r, double rx, double ry) {
    rx = std::clamp(rx, 0.0, r.width() / 2);
    ry = std::clamp(ry, 0.0, r.height() / 2);
    if (rx <= 0 || ry <= 0) return add_rect(r);
    const double kx = rx * kKappa, ky = ry * kKappa;
    move_to({r.x0 + rx, r.y0});
    line_to({r.x1 - rx, r.y0});
    cubic_to({r.x1 - rx + kx, r.y0}, {r.x1, r.y0 + ry - ky}, {r.x1, r.y0 + ry});
    line_to({r.x1, r.y1 - ry});
    cubic_to({r.x1, r.y1 - ry + ky}, {r.x1 - rx + kx, r.y1}, {r.x1 - rx, r.y1});
    line_to({r.x0 + rx, r.y1});
    cubic_to({r.x0 + rx - kx, r.y1}, {r.x0, r.y1 - ry + ky}, {r.x0, r.y1 - ry});
    line_to({r.x0, r.y0 + ry});
    cubic_to({r.x0, r.y0 + ry - ky}, {r.x0 + rx - kx, r.y0}, {r.x0 + rx, r.y0});
    return close();
}

Path& Path::add_polygon(std::span<const Point> pts, bool close_it) {
    if (pts.empty()) return *this;
    move_to(pts[0]);
    // The lines in one piece: what line_to does for each point once the contour is open, with the
    // bounds and finiteness taken in one loop over the new points.
    verbs_.insert(verbs_.end(), pts.size() - 1, Verb::Line);
    points_.insert(points_.end(), pts.begin() + 1, pts.end());
    include_all(pts.subspan(1));
    current_ = pts.back();
    if (close_it) close();
    return *this;
}

Path& Path::append(const Path& other) { return append(other, Affine{}); }

Path& Path::append(const Path& other, const Affine& m) {
    // Appending a path to itself reads what the appending grows (and may move): a copy first.
    if (&other == this) {
        const Path copy = other;
        return append(copy, m);
    }
    if (append_whole(other, m)) return *this;
    struct V {
        Path& p;
        const Affine& m;
        void move(Point a) { p.move_to(m(a)); }
        void line(Point, Point b) { p.line_to(m(b)); }
        void quad(Point, Point c, Point b) { p.quad_to(m(c), m(b)); }
        void cubic(Point, Point c1, Point c2, Point b) { p.cubic_to(m(c1), m(c2), m(b)); }
        void conic(Point, Point c, Point b, double w) { p.conic_to(m(c), m(b), w); }
        void close(Point, Point) { p.close(); }
    } v{*this, m};
    // A new contour always starts with a move, so appended contours never join ours.
    open_ = false;
    other.visit(v);
    return *this;
}

// append() in one piece: when `other` is as the builder methods make paths (every contour opens
// with one move, segments and closes only inside a contour) and this path does not end on a lone
// move (which other's first move would replace), appending segment by segment adds exactly other's
// verbs, its points mapped by m and its weights. False (nothing done) otherwise.
bool Path::append_whole(const Path& other, const Affine& m) {
    if (!verbs_.empty() && verbs_.back() == Verb::Move) return false;
    bool open = false;
    Verb prev = Verb::Close;
    std::size_t pi = 0, start = 0, cur = 0;
    for (const Verb v : other.verbs_) {
        switch (v) {
            case Verb::Move:
                if (prev == Verb::Move) return false;
                start = cur = pi++;
                open = true;
                break;
            case Verb::Close:
                if (!open) return false;
                cur = start;
                open = false;
                break;
            default:
                if (!open) return false;
                pi += static_cast<std::size_t>(verb_point_count(v));
                cur = pi - 1;
                break;
        }
        prev = v;
    }
    if (pi != other.points_.size()) return false;
    if (other.verbs_.empty()) {
        open_ = false;
        return true;
    }
    const std::size_t base = points_.size();
    verbs_.insert(verbs_.end(), other.verbs_.begin(), other.verbs_.end());
    for (const Point& p : other.points_) push_point(m(p));
    weights_.insert(weights_.end(), other.weights_.begin(), other.weights_.end());
    open_ = open;
    start_ = points_[base + start];
    current_ = points_[base + cur];
    return true;
}

Rect Path::control_bounds() const {
    if (points_.empty()) return {};
    if (!(cx0_ <= cx1_ && cy0_ <= cy1_)) {  // only NaN points: computed point by point from the first
        Rect r{points_[0].x, points_[0].y, points_[0].x, points_[0].y};
        for (const Point& p : points_) r.include(p);
        return r;
    }
    return {cx0_, cy0_, cx1_, cy1_};
}

namespace {

// Roots in (0, 1) of a t^2 + b t + c (numerically stable form; a tiny a degrades to linear).
int roots_in_unit_interval(double a, double b, double c, double out[2]) {
    int n = 0;
    auto push = [&](double t) {
        if (t > 0 && t < 1) out[n++] = t;
    };
    if (std::abs(a) < 1e-12 * (std::abs(b) + std::abs(c) + 1e-300)) {
        if (b != 0) push(-c / b);
        return n;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    const double sq = std::sqrt(disc);
    const double q = -0.5 * (b + (b < 0 ? -sq : sq));
    push(q / a);
    if (q != 0) push(c / q);
    return n;
}

// Roots in (0, 1) of the derivative of a 1-D quadratic/cubic Bezier, for tight bounds.
int quad_extrema(double a, double b, double c, double out[1]) {
    const double den = a - 2 * b + c;
    if (den == 0) return 0;
    const double t = (a - b) / den;
    if (t > 0 && t < 1) {
        out[0] = t;
        return 1;
    }
    return 0;
}

int cubic_extrema(double p0, double p1, double p2, double p3, double out[2]) {
    // Derivative / 3: a t^2 + b t + c with a = -p0 + 3p1 - 3p2 + p3, b = 2(p0 - 2p1 + p2), c = p1 - p0.
    const double a = -p0 + 3 * p1 - 3 * p2 + p3, b = 2 * (p0 - 2 * p1 + p2), c = p1 - p0;
    return roots_in_unit_interval(a, b, c, out);
}

// Extrema in (0, 1) of x(t) = N(t) / D(t) for a conic: with N = a2 t^2 + a1 t + a0 and
// D = b2 t^2 + b1 t + b0, N'D - ND' = (a2 b1 - a1 b2) t^2 + 2 (a2 b0 - a0 b2) t + (a1 b0 - a0 b1)
// (the cubic terms cancel).
int conic_extrema(double p0, double p1, double p2, double w, double out[2]) {
    const double a0 = p0, a1 = 2 * (w * p1 - p0), a2 = p0 - 2 * w * p1 + p2;
    const double b0 = 1, b1 = 2 * (w - 1), b2 = 2 - 2 * w;
    const double A = a2 * b1 - a1 * b2, B = 2 * (a2 * b0 - a0 * b2), C = a1 * b0 - a0 * b1;
    return roots_in_unit_interval(A, B, C, out);
}

Point eval_quad(Point p0, Point p1, Point p2, double t) {
    const double mt = 1 - t;
    return p0 * (mt * mt) + p1 * (2 * mt * t) + p2 * (t * t);
}

Point eval_cubic(Point p0, Point p1, Point p2, Point p3, double t) {
    const double mt = 1 - t;
    return p0 * (mt * mt * mt) + p1 * (3 * mt * mt * t) + p2 * (3 * mt * t * t) + p3 * (t * t * t);
}

Point eval_conic(Point p0, Point p1, Point p2, double w, double t) {
    const double mt = 1 - t;
    const double b0 = mt * mt, b1 = 2 * w * mt * t, b2 = t * t;
    return (p0 * b0 + p1 * b1 + p2 * b2) / (b0 + b1 + b2);
}

}  // namespace

Rect Path::bounds() const {
    if (points_.empty()) return {};
    Rect r{points_[0].x, points_[0].y, points_[0].x, points_[0].y};
    struct V {
        Rect& r;
        void move(Point a) { r.include(a); }
        void line(Point, Point b) { r.include(b); }
        void quad(Point a, Point c, Point b) {
            r.include(b);
            double t[1];
            if (quad_extrema(a.x, c.x, b.x, t)) r.include(eval_quad(a, c, b, t[0]));
            if (quad_extrema(a.y, c.y, b.y, t)) r.include(eval_quad(a, c, b, t[0]));
        }
        void cubic(Point a, Point c1, Point c2, Point b) {
            r.include(b);
            double t[2];
            for (int i = 0, n = cubic_extrema(a.x, c1.x, c2.x, b.x, t); i < n; ++i)
                r.include(eval_cubic(a, c1, c2, b, t[i]));
            for (int i = 0, n = cubic_extrema(a.y, c1.y, c2.y, b.y, t); i < n; ++i)
                r.include(eval_cubic(a, c1, c2, b, t[i]));
        }
        void conic(Point a, Point c, Point b, double w) {
            r.include(b);
            double t[2];
            for (int i = 0, n = conic_extrema(a.x, c.x, b.x, w, t); i < n; ++i) r.include(eval_conic(a, c, b, w, t[i]));
            for (int i = 0, n = conic_extrema(a.y, c.y, b.y, w, t); i < n; ++i) r.include(eval_conic(a, c, b, w, t[i]));
        }
        void close(Point, Point) {}
    } v{r};
    visit(v);
    return r;
}

bool Path::is_finite() const { return finite_; }  // weights are checked by conic_to

Path Path::transformed(const Affine& m) const {
    Path p = *this;
    p.transform(m);
    return p;
}

void Path::transform(const Affine& m) {
    for (Point& p : points_) p = m.apply(p);
    start_ = m.apply(start_);
    current_ = m.apply(current_);
    recompute_cache();
}

Path Path::reversed() const {
    Path out;
    std::size_t pi = 0, wi = 0;
    std::size_t vi = 0;
    while (vi < verbs_.size()) {
        // One contour: Move, segments..., optional Close.
        std::size_t vstart = vi, pstart = pi, wstart = wi;
        ++vi;
        ++pi;
        while (vi < verbs_.size() && verbs_[vi] != Verb::Move && verbs_[vi] != Verb::Close) {
            pi += static_cast<std::size_t>(verb_point_count(verbs_[vi]));
            if (verbs_[vi] == Verb::Conic) ++wi;
            ++vi;
        }
        const bool closed = vi < verbs_.size() && verbs_[vi] == Verb::Close;
        const std::size_t vend = vi;
        if (closed) ++vi;
        // Walk the segments backwards.
        out.move_to(points_[pi - 1]);
        std::size_t p = pi, w = wi;
        for (std::size_t k = vend; k-- > vstart + 1;) {
            const Verb v = verbs_[k];
            const std::size_t n = static_cast<std::size_t>(verb_point_count(v));
            p -= n;
            const Point prev = points_[p - 1];
            switch (v) {
                case Verb::Line: out.line_to(prev); break;
                case Verb::Quad: out.quad_to(points_[p], prev); break;
                case Verb::Cubic: out.cubic_to(points_[p + 1], points_[p], prev); break;
                case Verb::Conic: out.conic_to(points_[p], prev, weights_[--w]); break;
                default: break;
            }
        }
        (void)pstart;
        (void)wstart;
        if (closed) out.close();
    }
    return out;
}

}  // namespace casteljau
