// casteljau/path.hpp: the Path, a list of contours built from move/line/quad/cubic/conic/close.
//
// Coordinates are whatever space the caller works in (user space); the rasterizer receives the
// Path together with an Affine to pixel space, so a Path can be drawn at many sizes unchanged.
// A contour starts with move_to; a drawing verb without a preceding move_to starts a contour at
// the current point ((0, 0) for a new Path), and so does one right after close(), as in SVG.
// Filling closes every contour implicitly; close() matters for stroking.
// Thread-safety: a Path is a value; const access from many threads at once is safe.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "casteljau/geometry.hpp"

namespace casteljau {

enum class Verb : std::uint8_t {
    Move,   // 1 point
    Line,   // 1 point
    Quad,   // 2 points: control, end
    Cubic,  // 3 points: control 1, control 2, end
    Conic,  // 2 points: control, end; one weight (rational quadratic, weight of the control point)
    Close,  // 0 points
};

// Number of points a verb consumes.
constexpr int verb_point_count(Verb v) {
    switch (v) {
        case Verb::Move:
        case Verb::Line: return 1;
        case Verb::Quad:
        case Verb::Conic: return 2;
        case Verb::Cubic: return 3;
        case Verb::Close: return 0;
    }
    return 0;
}

class Path {
public:
    Path() = default;

    Path& move_to(Point p);
    Path& line_to(Point p);
    Path& quad_to(Point c, Point p);
    Path& cubic_to(Point c1, Point c2, Point p);
    // Rational quadratic with end weights 1 and control weight w > 0 (w = 1: a quadratic;
    // w < 1: an ellipse arc; w = 1: parabola; w > 1: hyperbola).
    Path& conic_to(Point c, Point p, double w);
    Path& close();

    Path& move_to(double x, double y) { return move_to({x, y}); }
    Path& line_to(double x, double y) { return line_to({x, y}); }

    // Convenience shapes (each adds closed contours).
    Path& add_rect(const Rect& r);
    Path& add_ellipse(Point center, double rx, double ry);  // four cubic arcs, clockwise in y-down
    Path& add_circle(Point center, double r) { return add_ellipse(center, r, r); }
    Path& add_round_rect(const Rect& r, double rx, double ry);
    Path& add_polygon(std::span<const Point> pts, bool close = true);
    Path& append(const Path& other);
    Path& append(const Path& other, const Affine& m);

    bool empty() const { return verbs_.empty(); }
    void clear();
    // Makes room for `points` points and `verbs` verbs in all, so that a builder that knows its
    // size does not regrow the storage as it appends (a hint: the path still grows past it).
    void reserve(std::size_t points, std::size_t verbs) {
        points_.reserve(points);
        verbs_.reserve(verbs);
    }
    std::span<const Verb> verbs() const { return verbs_; }
    std::span<const Point> points() const { return points_; }
    std::span<const double> weights() const { return weights_; }
    std::size_t contour_count() const;

    // Where the next segment starts: the last point, the contour's start after close(), (0, 0) for an empty path.
    Point current_point() const { return current_; }

    // Bounding box of all points (control points included): a conservative bound of the shape.
    // Kept up to date as the path is built (no pass over the points); NaN coordinates are left
    // out of it (is_finite() reports them).
    Rect control_bounds() const;
    // Tight bounding box of the curves (extrema of each segment).
    Rect bounds() const;
    bool is_finite() const;

    Path transformed(const Affine& m) const;
    void transform(const Affine& m);
    // The same shape traversed backwards, contour by contour.
    Path reversed() const;

    bool operator==(const Path&) const = default;

    // Walks the path segment by segment with absolute start points: the visitor gets
    // move(p), line(p0, p1), quad(p0, c, p1), cubic(p0, c1, c2, p1), conic(p0, c, p1, w), close(p_last, p_first).
    template <class V>
    void visit(V&& v) const;

private:
    void ensure_contour();
    bool append_whole(const Path& other, const Affine& m);
    void push_point(Point p) {
        points_.push_back(p);
        include(p);
    }
    void include(Point p) {
        if (!(p.x - p.x == 0 && p.y - p.y == 0)) finite_ = false;  // NaN or infinity
        cx0_ = p.x < cx0_ ? p.x : cx0_;
        cy0_ = p.y < cy0_ ? p.y : cy0_;
        cx1_ = p.x > cx1_ ? p.x : cx1_;
        cy1_ = p.y > cy1_ ? p.y : cy1_;
    }
    void recompute_cache();
    void include_all(std::span<const Point> pts);  // include() for each of pts
    std::vector<Verb> verbs_;
    std::vector<Point> points_;
    std::vector<double> weights_;
    bool open_ = false;  // a contour is in progress
    Point start_{};      // first point of the current contour
    Point current_{};
    // Derived from points_ (weights are checked when added): control bounds and finiteness.
    double cx0_ = INFINITY, cy0_ = INFINITY, cx1_ = -INFINITY, cy1_ = -INFINITY;
    bool finite_ = true;
};

template <class V>
void Path::visit(V&& v) const {
    std::size_t pi = 0, wi = 0;
    Point start{}, cur{};
    for (Verb verb : verbs_) {
        switch (verb) {
            case Verb::Move:
                cur = start = points_[pi++];
                v.move(cur);
                break;
            case Verb::Line:
                v.line(cur, points_[pi]);
                cur = points_[pi++];
                break;
            case Verb::Quad:
                v.quad(cur, points_[pi], points_[pi + 1]);
                cur = points_[pi + 1];
                pi += 2;
                break;
            case Verb::Cubic:
                v.cubic(cur, points_[pi], points_[pi + 1], points_[pi + 2]);
                cur = points_[pi + 2];
                pi += 3;
                break;
            case Verb::Conic:
                v.conic(cur, points_[pi], points_[pi + 1], weights_[wi++]);
                cur = points_[pi + 1];
                pi += 2;
                break;
            case Verb::Close:
                v.close(cur, start);
                cur = start;
                break;
        }
    }
}

}  // namespace casteljau
