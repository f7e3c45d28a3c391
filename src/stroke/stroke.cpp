// Stroke stage: outlines of flattened contours with joins and caps, and the public stroke()/dash().
//
// Construction. The stroke of a polyline is the union of pieces: one rectangle per segment (the
// segment swept by the pen's diameter perpendicular to it), one join piece per vertex on the outer
// side of the turn (bevel triangle, miter quadrilateral, clipped miter, or circular sector), and
// one cap piece per open end. Instead of emitting every piece, we emit the sum of their boundaries,
// with every piece oriented the same way: shared edges cancel and what is left is
//   open contour:   left offset side forward (with outer joins) -> end cap -> right side backward
//                   (with inner joins) -> start cap;
//   closed contour: the left side as one loop and the right side, reversed, as another.
// On the inner side of a join the boundary goes end-of-segment -> vertex -> start-of-next-segment
// (through the pivot). Since this chain equals the sum of the piece boundaries, its winding number
// at any point counts the pieces covering it (all with one sign), and the NONZERO fill is exactly
// the union, whatever the widths, angles and segment lengths.
// Shortcut: the inner side may go end -> X -> start, X where the two inner offset lines meet,
// instead of through the pivot. As chains, pivot route = shortcut route + boundary of the
// quadrilateral Q = (X, end, vertex, start), so the shortcut subtracts 1 from the winding inside Q.
// Q reaches h * max(tan(theta/2), sin(theta)) back along each segment (theta: the turn angle). A
// shortcut is taken when that reach fits in the length of both segments: then Q lies inside both
// rectangles, Q_j inside rect(j-1) and rect(j). A point inside the quads of k distinct joins then
// lies in the rectangles of every segment next to those joins, and k vertices of a chain touch at
// least k + 1 segments: its winding stays >= 1. A closed contour is a cycle, where all n vertices
// touch only n segments, so a point inside every quad would lose its winding (a small closed
// polygon under a wide pen would lose its centre, tested). There the two quads at the ends of the
// first segment must not meet: their reaches along it are kept within its length together, and no
// point lies in every quad. Smooth curves then take the shortcut wherever their radius of
// curvature exceeds about h, and simple strokes come out as simple polygons, whose signed area is
// the exact stroke area.
// Curves. The vertices the flattener puts inside a curve (and where two segments meet with the same
// tangent) are no corners: the stroke of a curve is the sweep of its normal, which turns with the
// curve. There the outer side always gets the circular sector the normal sweeps (a round join,
// whatever the style; at a turn gentle enough that the offset lines' corner lies within the
// tolerance of that sector's arc, the corner stands for it, as the chords stand for the curve),
// and the inner side the sector it sweeps there too, as one more piece where
// the two rectangles leave part of it: in a bend tighter than half the pen's radius the normals
// cross past the centre of curvature and cover a sector on the far side, which rectangles alone
// would leave as a comb of slivers. Ends of curves take their caps square to the curve's own
// direction, not to the last chord (start_end() and finish_end() below).
// Round joins and caps are inscribed polygons of the circle, with a step angle chosen so that the
// sagitta stays below the tolerance: r (1 - cos(phi/2)) <= tol, i.e. phi = 4 asin(sqrt(tol / 2r)).
#include <algorithm>
#include <cmath>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "stroke/stroke_internal.hpp"

namespace casteljau::stroke_detail {
namespace {

// Points closer than this times the tolerance to the previous kept point are merged into it.
constexpr double kMergeFactor = 1e-3;
// At most this many arc steps per full turn, whatever the radius / tolerance ratio.
constexpr double kMaxArcStepsPerTurn = 65536;

Vec perp(Vec d) { return {-d.y, d.x}; }  // "left" of d (counter-clockwise when y points up)

// The outliner's working lists, kept from one stroke to the next by the thread that draws them.
struct OutlineBuffers {
    std::vector<Point> q, left, right, wedges, piece;
    std::vector<std::size_t> wedge_ends;
    std::vector<std::uint8_t> smooth;
    std::vector<Vec> dir;
    std::vector<double> len;
};

class Outliner {
public:
    Outliner(const StrokeStyle& st, double tol, Path& out, OutlineBuffers& b)
        : st_(st),
          h_(st.width / 2),
          out_(out),
          miter_limit_(std::max(1.0, st.miter_limit)),
          q_(b.q),
          left_(b.left),
          right_(b.right),
          wedges_(b.wedges),
          piece_(b.piece),
          wedge_ends_(b.wedge_ends),
          smooth_(b.smooth),
          dir_(b.dir),
          len_(b.len) {
        wedges_.clear();
        wedge_ends_.clear();
        // Drop points closer than this to their predecessor: their direction is noise.
        eps_ = tol * kMergeFactor;
        tol_ = tol;
        const double ratio = std::min(1.0, tol / h_);
        step_ = std::max(4 * std::asin(std::sqrt(ratio / 2)), 2 * kPi / kMaxArcStepsPerTurn);
        step_ = std::min(step_, kPi / 2);
        sin_step_ = std::sin(step_);
        // 1 + cos(turn) >= 2 (h / (h + tol))^2  <=>  h / cos(turn / 2) - h <= tol.
        const double c = h_ / (h_ + tol);
        smooth_corner_min_ = 2 * c * c - 1;
    }

    void contour(std::span<const Point> pts, std::span<const std::uint8_t> smooth, bool closed, Point dir_hint,
                 Vec head, Vec tail) {
        if (pts.empty()) return;
        if (pts.size() == 1 && !closed) return;  // a lone move draws nothing
        q_.clear();
        smooth_.clear();
        q_.push_back(pts[0]);
        smooth_.push_back(smooth[0]);
        auto apart = [this](Point a, Point b) { return stroke_keeps_apart(a, b, eps_); };
        for (std::size_t i = 1; i < pts.size(); ++i) {
            if (apart(pts[i], q_.back())) {
                q_.push_back(pts[i]);
                smooth_.push_back(smooth[i]);
            } else {
                smooth_.back() &= smooth[i];  // a corner merged into a point keeps it a corner
            }
        }
        if (closed) {
            while (q_.size() > 1 && !apart(q_.back(), q_.front())) {
                smooth_.front() &= smooth_.back();
                q_.pop_back();
                smooth_.pop_back();
            }
        }
        if (q_.size() == 1) {
            dot(q_[0], dir_hint);
            return;
        }
        const std::size_t np = q_.size();
        const std::size_t nseg = closed ? np : np - 1;
        dir_.resize(nseg);
        len_.resize(nseg);
        closed_ = closed;
        first_reach_ = 0;
        last_reach_ = 0;
        for (std::size_t i = 0; i < nseg; ++i) {
            const Vec v = q_[(i + 1) % np] - q_[i];
            len_[i] = std::sqrt(v.dot(v));  // points are apart by more than eps_: no underflow
            dir_[i] = v / len_[i];
        }
        left_.clear();
        right_.clear();
        if (closed) {
            for (std::size_t i = 0; i < nseg; ++i) join(q_[i], (i + nseg - 1) % nseg, i);
            // A convex contour whose inside lies entirely within h of its sides (a dot drawn as a
            // small stroked circle, a thin rounded rectangle) leaves no hole: its inner side would
            // only add pivots over area the outer side already covers, and cost exact cells.
            const int turn = convex_turn();
            if (turn != 0 && no_hole(turn)) {
                if (turn > 0) {  // left turns: the outer side is the right one
                    std::reverse(right_.begin(), right_.end());
                    emit(right_);
                } else {
                    emit(left_);
                }
                wedges_.clear();  // inside the outer side too
                wedge_ends_.clear();
                return;
            }
            emit(left_);
            std::reverse(right_.begin(), right_.end());
            emit(right_);
            emit_wedges();
            return;
        }
        const Vec d0 = dir_[0], dn = dir_[nseg - 1];
        Vec cap0;
        first_reach_ = start_end(q_[0], d0, head, len_[0], cap0);
        for (std::size_t i = 1; i < nseg; ++i) join(q_[i], i - 1, i);
        const Point end = q_[np - 1];
        const double room = len_[nseg - 1] - (nseg == 1 ? first_reach_ : last_reach_);
        const Vec cap1 = finish_end(end, dn, tail, len_[nseg - 1], room);
        // End cap: from the left end point to the right end point.
        cap(left_, end, cap1);
        // Right side backwards, then the start cap back to the first left point.
        left_.insert(left_.end(), right_.rbegin(), right_.rend());
        cap(left_, q_[0], -cap0);
        emit(left_);
        emit_wedges();
    }

private:
    // Points strictly between c + h u and c + h rot(u, sweep), on the circle of radius h.
    void arc(std::vector<Point>& dst, Point c, Vec u, double sweep) {
        // A NaN sweep (directions of segments whose length overflows) draws no arc: the outline is
        // refused as non-finite by emit(). Converting NaN to int would be undefined.
        const double pieces = std::ceil(std::abs(sweep) / step_ - 1e-9);
        if (!(pieces > 1)) return;
        const int n = static_cast<int>(std::min(pieces, kMaxArcStepsPerTurn));
        check_size(static_cast<std::size_t>(n));
        const double a = sweep / n, ca = std::cos(a), sa = std::sin(a);
        Vec v = u;
        for (int k = 1; k < n; ++k) {
            v = {v.x * ca - v.y * sa, v.x * sa + v.y * ca};
            dst.push_back(c + v * h_);
        }
    }

    // Cap at `p` for a contour leaving it in direction `d`: the chain is at p + h perp(d) and
    // continues to p - h perp(d) (not emitted: the caller's next point).
    void cap(std::vector<Point>& dst, Point p, Vec d) {
        switch (st_.cap) {
            case LineCap::Butt: break;
            case LineCap::Square:
                dst.push_back(p + (perp(d) + d) * h_);
                dst.push_back(p + (d - perp(d)) * h_);
                break;
            case LineCap::Round: arc(dst, p, perp(d), -kPi); break;
        }
    }

    // Zero-length contour: a disk or a square (along dir, default x), nothing for butt caps.
    void dot(Point p, Vec dir) {
        if (st_.cap == LineCap::Butt) return;
        const double dl = dir.length();
        const Vec d = dl > 0 && std::isfinite(dl) ? dir / dl : Vec{1, 0};
        left_.clear();
        if (st_.cap == LineCap::Square) {
            left_.push_back(p + (perp(d) - d) * h_);
            left_.push_back(p + (perp(d) + d) * h_);
            left_.push_back(p + (d - perp(d)) * h_);
            left_.push_back(p - (perp(d) + d) * h_);
        } else {
            left_.push_back(p + perp(d) * h_);
            arc(left_, p, perp(d), -kPi);
            left_.push_back(p - perp(d) * h_);
            arc(left_, p, -perp(d), -kPi);
        }
        emit(left_);
    }

    // +1 when the closed contour q_ is convex and turns left at every vertex (its inside on the
    // left), -1 when it turns right at every vertex, 0 otherwise (mixed or reversing turns, or a
    // total turn other than one revolution).
    int convex_turn() const {
        const std::size_t n = dir_.size();
        int sign = 0;
        double total = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const Vec a = dir_[(i + n - 1) % n], b = dir_[i];
            const double cr = a.cross(b), dt = a.dot(b);
            if (!(std::isfinite(cr) && std::isfinite(dt))) return 0;
            if (cr == 0 && dt <= 0) return 0;
            const int s = cr > 0 ? 1 : cr < 0 ? -1 : 0;
            if (s != 0 && sign != 0 && s != sign) return 0;
            if (s != 0) sign = s;
            total += std::atan2(cr, dt);
        }
        return std::abs(std::abs(total) - 2 * kPi) < 1e-6 ? sign : 0;
    }

    // Whether the convex contour's inside, eroded by h, is empty: the half-planes at distance h
    // inside every side clip the contour's bounding box to nothing. They are taken at h (1 - 1e-9):
    // a smaller distance leaves a larger region, so rounding can only keep a hole that is not
    // there, never drop one that is. Contours of more than 512 sides are not tried.
    bool no_hole(int turn) const {
        const std::size_t n = dir_.size();
        if (n > 512) return false;
        double x0 = q_[0].x, y0 = q_[0].y, x1 = x0, y1 = y0;
        for (const Point& p : q_) {
            x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
        }
        std::vector<Point> poly = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, next;
        const double d = h_ * (1 - 1e-9);
        for (std::size_t i = 0; i < n && !poly.empty(); ++i) {
            const Vec in = perp(dir_[i]) * static_cast<double>(turn);  // towards the inside
            const double c = in.dot(q_[i]) + d;                        // keep in . x >= c
            next.clear();
            for (std::size_t k = 0; k < poly.size(); ++k) {
                const Point a = poly[k], b = poly[(k + 1) % poly.size()];
                const double fa = in.dot(a) - c, fb = in.dot(b) - c;
                if (fa >= 0) next.push_back(a);
                if ((fa >= 0) != (fb >= 0)) next.push_back(a + (b - a) * (fa / (fa - fb)));
            }
            poly.swap(next);
        }
        return poly.empty();
    }

    // Join at vertex q_[out] between segment `in` (ending there) and segment `out` (starting there).
    void join(Point v, std::size_t in, std::size_t out) {
        // On a closed contour the joins at vertex 0 (out = 0) and vertex 1 (in = 0) share the first
        // segment's length; they are decided in that order. On an open one the start's cut takes
        // its share first.
        const double shared = in == 0 ? first_reach_ : 0;
        const double reach = turn(v, dir_[in], dir_[out], len_[in], len_[in] - shared, len_[out], smooth_[out] != 0);
        last_reach_ = reach;
        if (closed_ && out == 0) first_reach_ = reach;
    }

    // The pieces where a segment of direction d1 and length len1 meets one of direction d2 and
    // length len2 at v: the join on the outer side (round where the path is `smooth`), and on the
    // inner side the shortcut when its quadrilateral fits in `room1` (what is left of len1) and
    // len2, else the pivot (and the swept wedge where smooth). Returns how far the shortcut reaches
    // back along each segment, 0 when it is not taken. Non-empty `cut`: the points that replace v
    // in the pivot route, cutting the region between them and v out of the stroke (an end of the
    // path, see start_end()).
    double turn(Point v, Vec d1, Vec d2, double len1, double room1, double len2, bool smooth,
                std::span<const Point> cut = {}) {
        check_size(16);
        const double cr = d1.cross(d2), dt = d1.dot(d2);
        if (cr == 0 && dt > 0) {  // straight on
            left_.push_back(v + perp(d1) * h_);
            right_.push_back(v - perp(d1) * h_);
            return 0;
        }
        // Turning towards the left (cr > 0) puts the outer side on the right.
        const bool outer_left = cr <= 0;
        const double s = outer_left ? 1.0 : -1.0;
        const Vec n1 = perp(d1) * s, n2 = perp(d2) * s;  // outer normals
        std::vector<Point>& outer = outer_left ? left_ : right_;
        std::vector<Point>& inner = outer_left ? right_ : left_;
        const double sn = std::abs(cr);
        // The turn's angle. A forward turn of at most one arc step (sin below sin(step)) draws no
        // arc points, so most smooth vertices of a finely flattened curve skip the atan2.
        const bool within_step = dt > 0 && sn <= sin_step_;
        // A swept wedge needs short segments (wedge_gap) and, for a turn under a right angle, a
        // sine of at least max(len) / (h - tol): its nearest point lies at least the longer
        // segment's length over sin(turn) from v (the factor 0.999 keeps rounding on the safe side).
        const double longer = std::max(len1, len2);
        const bool wedge_possible =
            smooth && len1 < h_ && len2 < h_ && h_ - longer > tol_ && (dt <= 0 || sn * (h_ - tol_) >= 0.999 * longer);
        // A gentle turn inside a curve: the corner where the two offset lines meet lies within the
        // tolerance of the circle the normal sweeps (h / cos(turn / 2) from v), so one point stands
        // for the sector, as the chords stand for the curve.
        const bool corner = smooth && dt > 0 && dt >= smooth_corner_min_;
        const double angle = (within_step || corner) && !wedge_possible ? 0.0 : std::atan2(sn, dt);

        if (corner) {
            outer.push_back(v + (n1 + n2) * (h_ / (1 + dt)));
        } else {
            outer.push_back(v + n1 * h_);
            // Where the path is smooth there is no corner to join: the pen's normal turns with the
            // curve.
            switch (smooth ? LineJoin::Round : st_.join) {
                case LineJoin::Bevel: break;
                case LineJoin::Round:
                    if (!within_step) arc(outer, v, n1, -s * angle);
                    break;
                case LineJoin::Miter:
                case LineJoin::MiterClip: miter(outer, v, d1, d2, n1, n2, dt); break;
            }
            outer.push_back(v + n2 * h_);
        }

        if (1 + dt > 1e-9) {
            const double need = h_ * std::max(sn / (1 + dt), sn);
            if (need <= room1 && need <= len2) {
                inner.push_back(v - (n1 + n2) * (h_ / (1 + dt)));
                return need;
            }
        }
        inner.push_back(v - n1 * h_);
        if (cut.empty())
            inner.push_back(v);
        else
            inner.insert(inner.end(), cut.begin(), cut.end());
        inner.push_back(v - n2 * h_);
        if (wedge_possible) {
            // The wedge the turning normal sweeps on the inner side; the part of it the two
            // segments' rectangles leave is one more piece, a contour of its own.
            double psi, rho;
            if (wedge_gap(len1, len2, angle, psi, rho))
                wedge_piece(v, -n1, s, angle, len1, len2, psi, rho, &inner == &right_);
        }
        return 0;
    }

    // The outer corner of a miter join (or, past the limit, of a clipped miter or a bevel).
    void miter(std::vector<Point>& outer, Point v, Vec d1, Vec d2, Vec n1, Vec n2, double dt) const {
        // miter length / width = 1 / cos(theta / 2) <= limit  <=>  (1 + cos theta) limit^2 >= 2.
        if ((1 + dt) * miter_limit_ * miter_limit_ >= 2) {
            outer.push_back(v + (n1 + n2) * (h_ / (1 + dt)));
        } else if (st_.join == LineJoin::MiterClip) {
            const Vec sum = n1 + n2;
            const double sl = sum.length();
            const Vec b = sl > 1e-12 ? sum / sl : d1;  // bisector; straight ahead at 180 degrees
            const double along = d1.dot(b);
            if (along > 0) {
                const double t = (miter_limit_ - n1.dot(b)) * h_ / along;
                outer.push_back(v + n1 * h_ + d1 * t);
                outer.push_back(v + n2 * h_ - d2 * t);
            }
        }
    }

    // Whether the sector of radius h and angle `turn` that the normal sweeps on the inner side of a
    // vertex reaches outside both segment rectangles by more than the tolerance. Its point at angle
    // psi from the incoming normal and distance rho lies rho sin(psi) behind the vertex along the
    // incoming segment and rho sin(turn - psi) ahead along the outgoing one, outside both when
    // those exceed their lengths. The nearest such point is where both reach their lengths
    // together, tan(psi) = len_in sin(turn) / (len_out + len_in cos(turn)), at distance rho: the
    // part of the sector outside lies between that point and the arc.
    bool wedge_gap(double len_in, double len_out, double turn, double& psi, double& rho) const {
        // rho is at least the longer segment's length, so a segment within the tolerance of h
        // settles it without the trigonometry.
        if (!(len_in < h_ && len_out < h_) || !(h_ - std::max(len_in, len_out) > tol_)) return false;
        psi = std::atan2(len_in * std::sin(turn), len_out + len_in * std::cos(turn));
        const double a = len_in > 0 ? len_in / std::sin(psi) : 0;
        const double b = len_out > 0 ? len_out / std::sin(turn - psi) : 0;
        rho = std::max(a, b);
        return h_ - rho > tol_;
    }

    // The part of the swept wedge at v outside both rectangles, as a contour: bounded by the
    // incoming segment's start line (rho sin(psi) = len_in, meeting the arc at psi_a), the
    // outgoing segment's end line (meeting it at psi_b) and the arc between. `m1`: the incoming
    // inner normal; the wedge turns from it by `turn` in the direction -s. Oriented as the inner
    // side's pieces: `reverse` when that side is emitted backwards.
    void wedge_piece(Point v, Vec m1, double s, double turn, double len_in, double len_out, double psi, double rho,
                     bool reverse) {
        auto dir = [&](double a) {
            const double c = std::cos(-s * a), n = std::sin(-s * a);
            return Vec{m1.x * c - m1.y * n, m1.x * n + m1.y * c};
        };
        const double pa = std::asin(len_in / h_), pb = turn - std::asin(len_out / h_);
        const std::size_t start = wedges_.size();
        wedges_.push_back(v + dir(pb) * h_);
        arc(wedges_, v, dir(pb), s * (pb - pa));
        wedges_.push_back(v + dir(pa) * h_);
        wedges_.push_back(v + dir(psi) * rho);
        if (reverse) std::reverse(wedges_.begin() + static_cast<std::ptrdiff_t>(start), wedges_.end());
        wedge_ends_.push_back(wedges_.size());
    }

    // Emits the wedge pieces gathered for the contour.
    void emit_wedges() {
        std::size_t start = 0;
        for (std::size_t end : wedge_ends_) {
            piece_.assign(wedges_.begin() + static_cast<std::ptrdiff_t>(start),
                          wedges_.begin() + static_cast<std::ptrdiff_t>(end));
            emit(piece_);
            start = end;
        }
        wedges_.clear();
        wedge_ends_.clear();
    }

    // The ends of an open contour, where the path's own direction t (zero: the chord's) differs
    // from its chord's d by an angle a. The cap stands square to t, across the line L through the
    // end perpendicular to t. On the side the path turns away from, the chord's rectangle falls
    // short of L: the sector the normal sweeps from d to t fills it. On the other side the
    // rectangle reaches beyond L, into a wedge between L and the chord's own end line L0 that is no
    // part of the stroke, and is cut along L, when the curve's radius there is at least h. The
    // radius is taken as r = len / (2 sin a): the circle through the chord's ends tangent to t,
    // whose centre C lies on L, r from the end, and projects onto the chord's middle. A tighter
    // end has C inside the pen: the chord's normals turn about C and, past it, sweep a cone of
    // angle 2a beyond L. The wedge minus that cone is the triangle between the end, C and the
    // point F at 2 r cos(a) along L0 (isosceles), cut off where F lies beyond the chord's side;
    // that triangle is cut, and the end is otherwise joined like a smooth vertex to a segment of
    // length zero along t. A cut must fit in what the chord has left (`room`, at most its length
    // `len`); without room the end keeps the whole rectangle.
    // Returns how far the cut reaches along the chord, and sets `cap` to the direction the cap
    // stands on (pointing along the path).

    // The start at v, the path leaving in direction t and its first chord in direction d.
    double start_end(Point v, Vec d, Vec t, double len, Vec& cap) {
        cap = t == Vec{0, 0} ? d : t;
        left_.push_back(v + perp(cap) * h_);
        right_.push_back(v - perp(cap) * h_);
        const double cr = t.cross(d), dt = t.dot(d);
        if (t == Vec{0, 0} || (cr == 0 && dt > 0)) return 0;
        const double reach = h_ * std::abs(cr) / dt, r = len / (2 * std::abs(cr));
        if (dt > 0 && 2 * reach <= len) {
            const Side side = sides(t, d);
            side.outer.pop_back();
            side.inner.pop_back();
            sweep(side.outer, v, side.n1, side.n2, cr, dt, side.s);
            side.inner.push_back(v - side.n1 * h_);
            side.inner.push_back(v - side.n2 * h_ + d * reach);
            return reach;
        }
        const bool cut = dt > 0 && r < h_;
        Point pts[2];
        if (cut) {
            const Side side = sides(t, d);
            pts[0] = v - side.n1 * r;
            pts[1] = cut_corner(v, -side.n2, pts[0], r, dt);
        }
        turn(v, t, d, 0, 0, len, true, cut ? std::span<const Point>(pts) : std::span<const Point>());
        return cut ? len / 2 : 0;
    }

    // The end at v: the last chord arrives in direction d, the path in direction t.
    Vec finish_end(Point v, Vec d, Vec t, double len, double room) {
        const double cr = d.cross(t), dt = d.dot(t);
        if (t == Vec{0, 0} || (cr == 0 && dt > 0)) {
            left_.push_back(v + perp(d) * h_);
            right_.push_back(v - perp(d) * h_);
            return d;
        }
        const double reach = h_ * std::abs(cr) / dt, r = len / (2 * std::abs(cr));
        if (dt > 0 && 2 * reach <= room) {
            const Side side = sides(d, t);
            sweep(side.outer, v, side.n1, side.n2, cr, dt, side.s);
            side.inner.push_back(v - side.n1 * h_ - d * reach);
            side.inner.push_back(v - side.n2 * h_);
            return t;
        }
        const bool cut = dt > 0 && r < h_ && len / 2 <= room;
        Point pts[2];
        if (cut) {
            const Side side = sides(d, t);
            pts[1] = v - side.n2 * r;
            pts[0] = cut_corner(v, -side.n1, pts[1], r, dt);
        }
        turn(v, d, t, len, room, 0, true, cut ? std::span<const Point>(pts) : std::span<const Point>());
        left_.push_back(v + perp(t) * h_);
        right_.push_back(v - perp(t) * h_);
        return t;
    }

    // The corner of the cut at an end v opposite C: F = v + m 2 r cos(a) on the chord's end line
    // (m: the chord's inner normal), or, when F lies beyond the chord's side (h from the chord),
    // where the line from C to F crosses that side.
    Point cut_corner(Point v, Vec m, Point c, double r, double cos_a) const {
        const double f = 2 * r * cos_a;
        if (f <= h_) return v + m * f;
        const double lambda = h_ / (r * cos_a) - 1;  // C is r cos(a) from the chord, F twice that
        return c + (v + m * f - c) * lambda;
    }

    // The outer and inner sides of a turn from direction d1 to d2, with their outer normals.
    struct Side {
        std::vector<Point>& outer;
        std::vector<Point>& inner;
        Vec n1, n2;
        double s;
    };
    Side sides(Vec d1, Vec d2) {
        const bool outer_left = d1.cross(d2) <= 0;
        const double s = outer_left ? 1.0 : -1.0;
        return {outer_left ? left_ : right_, outer_left ? right_ : left_, perp(d1) * s, perp(d2) * s, s};
    }

    // The sector the outer normal sweeps at v from n1 to n2.
    void sweep(std::vector<Point>& outer, Point v, Vec n1, Vec n2, double cr, double dt, double s) {
        outer.push_back(v + n1 * h_);
        arc(outer, v, n1, -s * std::atan2(std::abs(cr), dt));
        outer.push_back(v + n2 * h_);
    }

    // The outline grows by a contour's two sides before emit() sees them: a long contour of round
    // joins at a fine step (a huge width against the tolerance) must fail as it passes the path
    // size limit, not after gigabytes of points.
    void check_size(std::size_t more) const {
        if (total_ + left_.size() + right_.size() + wedges_.size() + more > max_points_)
            throw Error(ErrorKind::Limit, "stroke: outline exceeds the path size limit");
    }

    void emit(const std::vector<Point>& pts) {
        if (pts.size() < 2) return;
        total_ += pts.size() + 1;
        if (total_ > max_points_) throw Error(ErrorKind::Limit, "stroke: outline exceeds the path size limit");
        bool repeats = false;
        for (std::size_t i = 0; i < pts.size(); ++i) {
            if (!pts[i].is_finite()) throw Error(ErrorKind::Limit, "stroke: outline coordinates overflow");
            repeats = repeats || (i > 0 && pts[i] == pts[i - 1]);
        }
        if (!repeats) {  // the common case, in one piece
            out_.add_polygon(pts, true);
            return;
        }
        out_.move_to(pts[0]);
        for (std::size_t i = 1; i < pts.size(); ++i)
            if (!(pts[i] == pts[i - 1])) out_.line_to(pts[i]);
        out_.close();
    }

    const StrokeStyle& st_;
    double h_;
    Path& out_;
    double miter_limit_;
    double eps_ = 0;
    double tol_ = 0;
    double step_ = kPi / 2;
    double sin_step_ = 1;
    double smooth_corner_min_ = 1;  // cosine of the largest smooth turn drawn as one outer corner
    std::size_t total_ = 0;
    const std::size_t max_points_ = current_limits().path_points;
    std::vector<Point>&q_, &left_, &right_;
    std::vector<Point>&wedges_, &piece_;    // swept wedge pieces of the contour, one after another
    std::vector<std::size_t>& wedge_ends_;  // where each ends in wedges_
    std::vector<std::uint8_t>& smooth_;     // per point of q_: the path is smooth there
    std::vector<Vec>& dir_;
    std::vector<double>& len_;
    bool closed_ = false;
    // How far the inner side is cut short along segment 0: by the shortcut at vertex 0 (closed
    // contours) or by the start's cut (open ones); and along the outgoing segment of the last join.
    double first_reach_ = 0;
    double last_reach_ = 0;
};

}  // namespace

double user_tolerance(const Affine& m, double tolerance) {
    if (!(tolerance > 0) || !std::isfinite(tolerance))
        throw Error(ErrorKind::InvalidArgument, "stroke: tolerance must be a positive finite number");
    if (!m.is_finite()) throw Error(ErrorKind::InvalidData, "stroke: transform is not finite");
    const double s = m.max_scale();
    // A transform that collapses everything to a point shows nothing; any tolerance will do.
    if (!(s > 0) || !std::isfinite(s)) return tolerance;
    const double tol = tolerance / s;
    return std::isfinite(tol) && tol > 0 ? tol : tolerance;
}

double tangent_resolution(double width, double tol) { return std::max(tol, width / 40); }

void check_finite(const Path& path) {
    if (!path.is_finite()) throw Error(ErrorKind::InvalidData, "stroke: path has a non-finite coordinate");
}

// What one thread's strokes work in: lists that keep their memory from one stroke to the next,
// unless a stroke made them larger than kKeptPoints points (trim).
struct StrokeScratch {
    FlatContours flat, dashed;
    std::vector<Point> dirs;
    OutlineBuffers outline;
};
constexpr std::size_t kKeptPoints = std::size_t(1) << 18;

StrokeScratch& scratch() {
    thread_local StrokeScratch s;
    return s;
}

// Frees the scratch lists once a stroke grew one of them past kKeptPoints. The others grow with
// these: per point of the flattened path or its dashes, or per point of the outline's sides and
// wedges.
void trim(StrokeScratch& s) {
    const OutlineBuffers& b = s.outline;
    for (const std::size_t c : {s.flat.poly.points.capacity(), s.dashed.poly.points.capacity(), b.left.capacity(),
                                b.right.capacity(), b.wedges.capacity()})
        if (c > kKeptPoints) {
            s = StrokeScratch{};
            return;
        }
}

void stroke_polyline(const FlatContours& flat, std::span<const Point> dirs, const StrokeStyle& style, double tol,
                     Path& out) {
    Outliner o(style, tol, out, scratch().outline);
    const Polyline& poly = flat.poly;
    std::size_t start = 0;
    for (std::size_t c = 0; c < poly.contour_count(); ++c) {
        const std::size_t end = poly.contour_ends[c];
        const Point hint = c < dirs.size() ? dirs[c] : Point{0, 0};
        o.contour(std::span<const Point>(poly.points.data() + start, end - start),
                  std::span<const std::uint8_t>(flat.smooth.data() + start, end - start), poly.closed[c], hint,
                  flat.head[c], flat.tail[c]);
        start = end;
    }
}

}  // namespace casteljau::stroke_detail

namespace casteljau {

double stroke_merge_distance(const Affine& m, double tolerance) {
    return stroke_detail::user_tolerance(m, tolerance) * stroke_detail::kMergeFactor;
}

namespace {

// stroke(), stroke_outline() and stroke_interior(): the outline into `out` and the capsules inside
// it into `inside`, each when given (and cleared first).
void stroke_with(const Path& path, const StrokeStyle& style, const Affine& m, double tolerance, Path* out,
                 std::vector<CutCapsule>* inside) {
    using namespace stroke_detail;
    if (out) out->clear();
    if (inside) inside->clear();
    const double tol = user_tolerance(m, tolerance);
    check_finite(path);
    if (!std::isfinite(style.width) || !std::isfinite(style.miter_limit) || !std::isfinite(style.dash_offset))
        throw Error(ErrorKind::InvalidData, "stroke: width, miter limit and dash offset must be finite");
    const std::vector<double> pattern = effective_pattern(style.dashes);
    if (!(style.width > 0) || path.empty()) return;

    StrokeScratch& sc = scratch();
    struct Trim {
        StrokeScratch& s;
        ~Trim() { trim(s); }
    } trim_after{sc};
    FlatContours& flat = sc.flat;
    flatten_for_stroke(path, tol, tangent_resolution(style.width, tol), flat);
    if (pattern.empty()) {
        if (out) stroke_polyline(flat, {}, style, tol, *out);
        if (inside) interior_capsules(flat, style, tol, m, *inside);
    } else {
        FlatContours& dashed = sc.dashed;
        std::vector<Point>& dirs = sc.dirs;
        dash_polyline(flat, pattern, style.dash_offset, dashed, dirs);
        if (out) stroke_polyline(dashed, dirs, style, tol, *out);
        if (inside) interior_capsules(dashed, style, tol, m, *inside);
    }
}

}  // namespace

Path stroke(const Path& path, const StrokeStyle& style, const Affine& m, double tolerance) {
    Path out;
    stroke_with(path, style, m, tolerance, &out, nullptr);
    return out;
}

StrokeOutline stroke_outline(const Path& path, const StrokeStyle& style, const Affine& m, double tolerance) {
    StrokeOutline o;
    stroke_with(path, style, m, tolerance, &o.outline, &o.inside);
    return o;
}

void stroke_outline(const Path& path, const StrokeStyle& style, const Affine& m, double tolerance, StrokeOutline& out) {
    try {
        stroke_with(path, style, m, tolerance, &out.outline, &out.inside);
    } catch (...) {
        out.outline.clear();
        out.inside.clear();
        throw;
    }
}

std::vector<CutCapsule> stroke_interior(const Path& path, const StrokeStyle& style, const Affine& m, double tolerance) {
    std::vector<CutCapsule> inside;
    stroke_with(path, style, m, tolerance, nullptr, &inside);
    return inside;
}

Path dash(const Path& path, std::span<const double> dashes, double offset, const Affine& m, double tolerance) {
    using namespace stroke_detail;
    const double tol = user_tolerance(m, tolerance);
    check_finite(path);
    if (!std::isfinite(offset)) throw Error(ErrorKind::InvalidData, "stroke: dash offset must be finite");
    const std::vector<double> pattern = effective_pattern(dashes);

    FlatContours flat, dashed;
    std::vector<Point> dirs;
    flatten_for_stroke(path, tol, tol, flat);
    const Polyline* src = &flat.poly;
    if (!pattern.empty()) {
        dash_polyline(flat, pattern, offset, dashed, dirs);
        src = &dashed.poly;
    }
    Path out;
    std::size_t start = 0;
    for (std::size_t c = 0; c < src->contour_count(); ++c) {
        const std::size_t end = src->contour_ends[c];
        if (end - start > 1 || (end > start && src->closed[c])) {  // lone moves are dropped
            out.move_to(src->points[start]);
            for (std::size_t i = start + 1; i < end; ++i) out.line_to(src->points[i]);
            if (src->closed[c]) out.close();
        }
        start = end;
    }
    return out;
}

bool parse_line_cap(std::string_view name, LineCap& out) {
    if (name == "butt")
        out = LineCap::Butt;
    else if (name == "round")
        out = LineCap::Round;
    else if (name == "square")
        out = LineCap::Square;
    else
        return false;
    return true;
}

bool parse_line_join(std::string_view name, LineJoin& out) {
    if (name == "miter")
        out = LineJoin::Miter;
    else if (name == "miter-clip")
        out = LineJoin::MiterClip;
    else if (name == "round")
        out = LineJoin::Round;
    else if (name == "bevel")
        out = LineJoin::Bevel;
    else
        return false;
    return true;
}

}  // namespace casteljau
