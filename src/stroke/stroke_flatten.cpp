// Stroke stage: flattening for the stroker, which needs to know where the path is smooth.
//
// The flattener's chords turn at every point it emits, but only the path's own corners take a join.
// A point inside a curve, or where two segments meet with the same tangent, is smooth: there the
// stroke is the sweep of the pen's normal turning with the curve. The path's own directions at the
// ends of each open contour are kept too, so that caps stand square to the curve, not to its last
// chord. Directions come from the control points: a curve leaves its start towards the first
// control point that lies more than `near` from it, and arrives at its end from the last such one.
// A control point nearer than that turns the curve over a length the output cannot show (a "line
// drawn as a curve" with a control point a hair from its end): the stroke then follows the chords,
// as every renderer that strokes flattened curves does.
#include <cmath>

#include "path/flatten_internal.hpp"
#include "stroke/stroke_internal.hpp"

namespace casteljau::stroke_detail {
namespace {

// The flattener's points into a Polyline, each with a smoothness flag (0 until the visitor knows).
struct SmoothSink {
    flatten_detail::PolylineSink poly;
    std::vector<std::uint8_t>& smooth;

    void begin(Point p) {
        poly.begin(p);
        smooth.push_back(0);
    }
    void point(Point p) {
        poly.point(p);
        smooth.push_back(0);
    }
    void mark_closed() { poly.mark_closed(); }
    void end() { poly.end(); }
};

// The unit vector of the first of `vs` longer than `near`, or (0, 0).
Vec first_direction(double near, std::initializer_list<Vec> vs) {
    for (Vec v : vs) {
        const double l = length_of(v);
        if (l > near && std::isfinite(l)) return v / l;
    }
    return {0, 0};
}

// Same direction, to rounding: where two segments meet without a corner.
bool same_direction(Vec a, Vec b) { return a.dot(b) > 0 && std::abs(a.cross(b)) <= 1e-9; }

class StrokeFlattener {
public:
    StrokeFlattener(double tol, double near, FlatContours& out)
        : near_(near), sink_{{out.poly}, out.smooth}, out_(out), f_{identity_, tol * tol, nullptr, sink_} {}

    void move(Point p) {
        finish();
        f_.move(p);
        open_ = true;
        first_ = out_.poly.points.size() - 1;
        head_ = tail_ = {0, 0};
    }
    void line(Point a, Point b) {
        segment(b - a, b - a);
        f_.line(a, b);
    }
    void quad(Point a, Point b, Point c) {
        curve(first_direction(near_, {b - a, c - a}), first_direction(near_, {c - b, c - a}),
              [&] { f_.quad(a, b, c); });
    }
    void cubic(Point a, Point b, Point c, Point d) {
        curve(first_direction(near_, {b - a, c - a, d - a}), first_direction(near_, {d - c, d - b, d - a}),
              [&] { f_.cubic(a, b, c, d); });
    }
    void conic(Point a, Point b, Point c, double w) {
        curve(first_direction(near_, {b - a, c - a}), first_direction(near_, {c - b, c - a}),
              [&] { f_.conic(a, b, c, w); });
    }
    void close(Point last, Point start) {
        if (!(last == start)) segment(start - last, start - last);
        f_.close(last, start);
        // The contour's start is where its last segment meets its first.
        if (has_head_ && same_direction(tail_, head_)) out_.smooth[first_] = 1;
    }
    void finish() {
        if (!open_) return;
        f_.finish_contour();
        out_.head.push_back(head_);
        out_.tail.push_back(tail_);
        open_ = false;
        has_head_ = false;
    }

private:
    // Notes a segment leaving the current point in direction `in` and arriving in direction `out`.
    void segment(Vec in, Vec out) {
        const Vec u = first_direction(0, {in}), w = first_direction(0, {out});
        if (u == Vec{0, 0}) return;  // zero length: no direction, no corner
        if (!has_head_) {
            head_ = u;
            has_head_ = true;
        } else if (same_direction(tail_, u)) {
            out_.smooth.back() = 1;
        }
        tail_ = w;
    }

    template <class Flatten>
    void curve(Vec in, Vec out, Flatten&& flatten) {
        segment(in, out);
        const std::size_t before = out_.poly.points.size();
        flatten();
        // Every point but the curve's end lies inside the curve.
        for (std::size_t i = before; i + 1 < out_.poly.points.size(); ++i) out_.smooth[i] = 1;
    }

    double near_;
    Affine identity_{};
    SmoothSink sink_;
    FlatContours& out_;
    flatten_detail::Flattener<SmoothSink> f_;
    bool open_ = false, has_head_ = false;
    std::size_t first_ = 0;
    Vec head_{0, 0}, tail_{0, 0};
};

}  // namespace

void flatten_for_stroke(const Path& path, double tol, double near, FlatContours& out) {
    out.clear();
    check_flatten_input(path, Affine{}, tol);
    StrokeFlattener f(tol, near, out);
    path.visit(f);
    f.finish();
}

}  // namespace casteljau::stroke_detail
