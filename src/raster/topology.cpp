// Raster stage, topology: decides before rasterizing whether plain accumulation is exact for a
// path (classify_topology in include/casteljau/raster.hpp).
//
// Plain cover/area accumulation gives each pixel the integral of the winding number over it. That
// is the covered area exactly when the winding number takes only the values 0 and 1 (or only 0 and
// -1) over the whole plane: then nonzero and even-odd agree with |integral| in every pixel. The
// classifier proves this from the path's control points, in the path's own coordinates, in three
// steps:
//   0. Spikes go first: a line followed by the line straight back to where it started adds
//      nothing to any pixel's integral (the rasterizer maps both of their shared end points
//      alike, so the two cancel) and changes no winding number off itself.
//   1. No segment crosses itself (a cubic must have control points monotone in x or in y, with
//      the margin its area-balanced pieces need; lines, quadratics and conics cannot), and no two
//      segments meet, except consecutive segments of a contour at their shared end point, and
//      lines that share an end point V exactly and leave it in different directions: there the
//      contours touch, and touches_uncross requires that they do not cross at V, so that pulling
//      the passes through V apart by an arbitrarily small amount makes contours that do not
//      meet, with the same winding numbers but on a set of no area.
//      Every segment (line, quadratic, cubic, conic with a positive weight) lies in the convex hull
//      of its control points, and so does every chord the flattener draws between two of its
//      points. Two segments are apart when a line separates their hulls: the candidate lines run
//      through two control points of either segment, or perpendicular to such a pair. When no
//      candidate separates them, the larger is split in halves (de Casteljau) and the halves are
//      tested, to a fixed depth. Consecutive segments meet at one point S; they meet nowhere else
//      when the directions from S to their other control points fill two disjoint angular sectors,
//      each under a half turn (else both are split and the parts tested again). Segments are
//      paired on a uniform grid over their boxes, so far-apart segments cost nothing. Pairs are
//      decided on whole segments (no splitting): the flattener's chords can span any part of a
//      segment but stay inside its whole hull, so the verdict holds for the flattened polygon at
//      any tolerance.
//      The verdict for similarity maps (classify_topology(path, max_tolerance)) goes further for
//      two non-adjacent segments whose hulls meet: the flattener halves conics while their
//      flatness bound exceeds the tolerance, and under a similarity map of scale s that bound is
//      s times the one in path units, so which chords it draws at tolerance tol depends only on
//      lambda = tol / s. chords_apart walks both halving trees and requires every two chords that
//      can be drawn at one lambda in (0, max_tolerance] to be apart (quadratics and cubics,
//      flattened in equal pieces, stand for their chords by their whole hulls). Two things the
//      curves' own configuration no longer carries over to the flattened one are then checked:
//      each contour's orientation is decided with a slack of its segments' hull areas (any
//      flattening moves the contour's area by less), and winding numbers are read at a point of
//      the contour outside every hull of the other contours (winding_point).
//   2. So every contour is a simple closed curve and contours do not meet (after the pulling
//      apart of step 1). Its orientation is the
//      sign of its area (closed-form Bezier area).
//   3. The winding number of every region: a region touches some contour A, on A's inside or its
//      outside, so it is w(A) or w(A) + orientation(A), where w(A) is the winding number of the
//      other contours at a point of A (the same all along A since no contour meets A). Winding
//      numbers at a point P come from control polygons: a segment may be replaced by its control
//      polygon without changing the winding number around any P outside its hull (the straight
//      homotopy between them stays inside the hull), and segments whose hull holds P are split.
// Every test is decided with a margin of 2^-40 of the path's extent (2^-20 rad for sectors), far
// above double rounding: a "simple" verdict is never an artefact of rounding, and configurations
// that touch or come closer than the margin are "overlapping". Without a tolerance nothing here
// depends on the affine map later applied (nor on the flattening tolerance), since affine maps
// keep convex hulls, separating lines, crossings and orientations (a mirror flips every
// orientation together, which keeps winding values in {0, s}).
// A work budget bounds the splitting; past it the verdict is "overlapping" (the exact path).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/raster.hpp"
#include "path/flatten_internal.hpp"

namespace casteljau {

namespace {

struct Seg {
    Point p[4];
    int n = 2;  // control points: 2 line, 3 quadratic or conic, 4 cubic
    bool conic = false;
    double w = 1;  // conic weight
    int contour = 0;
    int index = 0;  // position in its contour
    Rect box;
    // For the similarity verdict (classify_topology with a tolerance): whether this is a segment
    // of the path itself (not a half made by add_contour), its depth in the flattener's halving
    // tree, and the tolerances lambda (in path units) for which the flattener emits it as one
    // chord: lo <= lambda < hi.
    bool whole = true;
    int depth = 0;
    double lo = 0, hi = INFINITY;
};

// b goes straight back along line a (a spike): for plain accumulation the two cancel exactly, as
// the rasterizer maps their shared end points alike.
bool is_spike_pair(const Seg& a, const Seg& b) { return a.n == 2 && b.n == 2 && a.p[0] == b.p[1] && a.p[1] == b.p[0]; }

Rect box_of(const Seg& s) {
    Rect r{s.p[0].x, s.p[0].y, s.p[0].x, s.p[0].y};
    for (int i = 1; i < s.n; ++i) {
        r.x0 = std::min(r.x0, s.p[i].x);
        r.y0 = std::min(r.y0, s.p[i].y);
        r.x1 = std::max(r.x1, s.p[i].x);
        r.y1 = std::max(r.y1, s.p[i].y);
    }
    return r;
}

inline Point mid(Point a, Point b) { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }
inline double cross(Point a, Point b) { return a.x * b.y - a.y * b.x; }
// Squared length; control points stay within 2^500 (Classifier::run checks the extent), so the
// squares cannot overflow.
inline double length_sq(Point v) { return v.x * v.x + v.y * v.y; }

// Splits s at t = 1/2 (parameter midpoint; for a conic, of its standard parametrization).
void split(const Seg& s, Seg& a, Seg& b) {
    a = s;
    b = s;
    if (s.conic) {
        // Homogeneous de Casteljau: (p0, 1), (w p1, w), (p2, 1); both halves get weight sqrt((1 + w) / 2).
        const double w = s.w;
        const Point q0{(s.p[0].x + w * s.p[1].x) / (1 + w), (s.p[0].y + w * s.p[1].y) / (1 + w)};
        const Point q1{(w * s.p[1].x + s.p[2].x) / (1 + w), (w * s.p[1].y + s.p[2].y) / (1 + w)};
        const Point m{(s.p[0].x + 2 * w * s.p[1].x + s.p[2].x) / (2 + 2 * w),
                      (s.p[0].y + 2 * w * s.p[1].y + s.p[2].y) / (2 + 2 * w)};
        a.p[1] = q0;
        a.p[2] = m;
        b.p[0] = m;
        b.p[1] = q1;
        a.w = b.w = std::sqrt(0.5 * (1 + w));
    } else if (s.n == 2) {
        const Point m = mid(s.p[0], s.p[1]);
        a.p[1] = m;
        b.p[0] = m;
    } else if (s.n == 3) {
        const Point m01 = mid(s.p[0], s.p[1]), m12 = mid(s.p[1], s.p[2]), m = mid(m01, m12);
        a.p[1] = m01;
        a.p[2] = m;
        b.p[0] = m;
        b.p[1] = m12;
    } else {
        const Point m01 = mid(s.p[0], s.p[1]), m12 = mid(s.p[1], s.p[2]), m23 = mid(s.p[2], s.p[3]);
        const Point m012 = mid(m01, m12), m123 = mid(m12, m23), m = mid(m012, m123);
        a.p[1] = m01;
        a.p[2] = m012;
        a.p[3] = m;
        b.p[0] = m;
        b.p[1] = m123;
        b.p[2] = m23;
    }
    a.box = box_of(a);
    b.box = box_of(b);
}

class Classifier {
public:
    // lambda = 0: the verdict for every affine map and tolerance; lambda > 0: for similarity maps
    // of scale s and tolerances tol with tol / s <= lambda (see classify_topology).
    Topology run(const Path& path, double lambda = 0);
    // Frees the scratch buffers when a large path left them big, so that a thread that once
    // classified a map does not keep its memory; small buffers stay for the next glyph. The size
    // is judged by the segments and the grid's membership list (a few entries per segment).
    void trim() {
        if (segs_.capacity() + members_.capacity() / 4 > kKeptSegments) *this = Classifier{};
    }
    static constexpr std::size_t kKeptSegments = 1 << 16;

private:
    std::vector<Seg> segs_;
    std::vector<std::size_t> contour_at_;  // first segment of each contour (+ end)
    // Scratch of run(), kept between calls (classify_topology reuses one classifier per thread).
    struct Cells {
        int x0, y0, x1, y1;
    };
    std::size_t open_ = 0;  // the contour being collected: segs_[open_, end)
    std::vector<Seg> halves_;
    std::vector<Cells> span_;
    std::vector<std::uint32_t> cstart_, members_, fill_;
    std::vector<Rect> boxes_;
    std::vector<int> orient_;
    double delta_ = 0;           // distance margin (path units)
    double lambda_ = 0;          // largest tolerance in path units (0: any, whole hulls only)
    std::vector<char> relaxed_;  // per contour: a pair inside it was decided by chords
    long budget_ = 0;            // hull tests left

    // Completes the contour being collected; false (and the contour dropped) for one the proof
    // cannot take.
    bool add_contour();
    bool boxes_apart(const Rect& a, const Rect& b) const {
        return a.x1 + delta_ < b.x0 || b.x1 + delta_ < a.x0 || a.y1 + delta_ < b.y0 || b.y1 + delta_ < a.y0;
    }
    bool separated(const Point* a, int na, const Point* b, int nb, double gap = 0);
    bool disjoint(const Seg& a, const Seg& b, int depth);
    bool sectors_apart(const Seg& a, const Seg& b) const;
    bool meet_only_at_end(const Seg& a, const Seg& b, int depth);
    bool directions_apart(Point u, Point v) const;
    bool touch_at_vertex(const Seg& a, const Seg& b);
    bool touches_uncross();
    std::vector<Point> touches_;  // vertices where non-consecutive lines touch (touch_at_vertex)
    std::vector<std::pair<std::uint32_t, std::uint32_t>> passes_;  // (touch, segment leaving it)
    // The flattener's bound of a conic node in path units (0 for lines, quadratics and cubics,
    // which it does not halve). Rounding of the bounds (here in path units, in pixels in the
    // flattener) is covered by widening every comparison with them by a relative kBoundSlack.
    static double halving_bound(const Seg& s);
    static constexpr double kBoundSlack = 0x1p-30;
    static constexpr int kBandDepth = 12;  // halvings of a pair in bands_apart
    static void as_root(Seg& s);
    bool chords_apart(const Seg& a, const Seg& b);
    static double band(const Seg& s, double lambda);
    bool bands_apart(const Seg& a, const Seg& b, double gap, int depth);
    bool winding_about(const Seg& s, Point p, int depth, int& w);
    bool orientation(std::size_t c, int& o, double slack) const;
    double hull_areas(std::size_t c) const;
    bool winding_point(std::size_t a, const std::vector<Rect>& boxes, Point& p);
    class Collector;
    bool pairs_apart(const Rect& cb);
    bool pair_apart(const Seg& s, const Seg& t);
    bool windings_in_range();
};

// Is there a line, through two control points of a or of b or perpendicular to such a pair, with
// a's hull and b's hull strictly on its two sides (by more than delta, plus `gap`)?
bool Classifier::separated(const Point* a, int na, const Point* b, int nb, double gap) {
    --budget_;
    auto try_dir = [&](Point o, Point d) {
        const double len = std::max(std::abs(d.x), std::abs(d.y));
        if (len == 0) return false;
        const double margin = delta_ * len + (gap > 0 ? gap * std::sqrt(d.x * d.x + d.y * d.y) : 0.0);
        double amin = INFINITY, amax = -INFINITY, bmin = INFINITY, bmax = -INFINITY;
        for (int i = 0; i < na; ++i) {
            const double v = cross(d, a[i] - o);
            amin = std::min(amin, v);
            amax = std::max(amax, v);
        }
        for (int i = 0; i < nb; ++i) {
            const double v = cross(d, b[i] - o);
            bmin = std::min(bmin, v);
            bmax = std::max(bmax, v);
        }
        return amax + margin < bmin || bmax + margin < amin;
    };
    for (int pass = 0; pass < 2; ++pass) {
        const Point* q = pass == 0 ? a : b;
        const int n = pass == 0 ? na : nb;
        for (int i = 0; i < n; ++i)
            for (int k = i + 1; k < n; ++k) {
                const Point d = q[k] - q[i];
                if (try_dir(q[i], d) || try_dir(q[i], Point{-d.y, d.x})) return true;
            }
    }
    return false;
}

bool Classifier::disjoint(const Seg& a, const Seg& b, int depth) {
    if (boxes_apart(a.box, b.box)) return true;
    if (budget_ <= 0) return false;
    if (a.n == 2 && b.n == 2) {
        // Two straight segments are apart when the line of one has both ends of the other
        // strictly on one side; they cross when each line separates the other's ends; anything
        // else (collinear, nearly touching) goes to the general test.
        auto side = [&](const Seg& u, Point q) {
            const Point d = u.p[1] - u.p[0];
            const double v = cross(d, q - u.p[0]);
            const double margin = delta_ * std::max(std::abs(d.x), std::abs(d.y));
            return v > margin ? 1 : (v < -margin ? -1 : 0);
        };
        const int s0 = side(a, b.p[0]), s1 = side(a, b.p[1]);
        if (s0 != 0 && s0 == s1) return true;
        const int t0 = side(b, a.p[0]), t1 = side(b, a.p[1]);
        if (t0 != 0 && t0 == t1) return true;
        if (s0 * s1 < 0 && t0 * t1 < 0) return false;  // a proper crossing
    }
    if (separated(a.p, a.n, b.p, b.n)) return true;
    if (depth == 0) return false;
    Seg h0, h1;
    const bool split_a = std::max(a.box.width(), a.box.height()) >= std::max(b.box.width(), b.box.height());
    split(split_a ? a : b, h0, h1);
    const Seg& other = split_a ? b : a;
    return disjoint(h0, other, depth - 1) && disjoint(h1, other, depth - 1);
}

// a ends where b starts (at S). The directions from S to a's other control points span a sector
// under a half turn, so do b's, and the two sectors are apart by more than the angular margin:
// then the hulls share S only. Directions are unit vectors compared by cross and dot products
// (sin and cos of the angle between them), each sector widened by the margin on both sides.
bool Classifier::sectors_apart(const Seg& a, const Seg& b) const {
    // The margin m = 2^-20 rad: sin m and cos m (to double precision).
    constexpr double kSin = 1.0 / (1 << 20), kCos = 1.0 - 0.5 * kSin * kSin;
    const Point s = b.p[0];
    const double min_len = delta_ * double(1 << 10);  // directions of shorter vectors are not trusted
    struct Sector {
        Point lo, hi;  // its clockwise-most and counter-clockwise-most directions, widened by m
    };
    // The sector of the directions to q[0..n) (those other than s), widened; false when there is
    // none, a vector is too short, or the widened sector is not under a half turn.
    auto sector = [&](const Point* q, int n, Sector& out) {
        Point u[3];
        int k = 0;
        for (int i = 0; i < n; ++i) {
            const Point v = q[i] - s;
            if (v.x == 0 && v.y == 0) continue;
            if (std::max(std::abs(v.x), std::abs(v.y)) < min_len) return false;
            const double len = std::sqrt(v.x * v.x + v.y * v.y);
            u[k++] = {v.x / len, v.y / len};
        }
        if (k == 0) return false;
        // lo: a direction with every other one counter-clockwise of it (cross >= 0); then hi: the
        // one furthest counter-clockwise from lo. Within a sector under a half turn both exist.
        int lo = -1;
        for (int i = 0; i < k && lo < 0; ++i) {
            bool all = true;
            for (int j = 0; j < k; ++j)
                if (j != i && cross(u[i], u[j]) < 0) all = false;
            if (all) lo = i;
        }
        if (lo < 0) return false;
        int hi = lo;
        for (int j = 0; j < k; ++j)
            if (cross(u[hi], u[j]) > 0) hi = j;
        // Widen: lo turned clockwise by m, hi counter-clockwise by m.
        const Point l{u[lo].x * kCos + u[lo].y * kSin, -u[lo].x * kSin + u[lo].y * kCos};
        const Point h{u[hi].x * kCos - u[hi].y * kSin, u[hi].x * kSin + u[hi].y * kCos};
        // Under a half turn from l to h: h on the left of l (and not straight back).
        if (!(cross(l, h) > 0) && !(cross(l, h) == 0 && l.x * h.x + l.y * h.y > 0)) return false;
        // Every direction must lie between l and h (a set spanning more than a half turn has no
        // valid lo, but rounding must not hide it: check).
        for (int j = 0; j < k; ++j)
            if (cross(l, u[j]) < 0 || cross(u[j], h) < 0) return false;
        out = {l, h};
        return true;
    };
    // Is direction d inside sector x (closed)? Both are under a half turn.
    auto inside = [](Point d, const Sector& x) { return cross(x.lo, d) >= 0 && cross(d, x.hi) >= 0; };
    Sector sa, sb;
    // a's other points: all but its end; b's: all but its start.
    if (!sector(a.p, a.n - 1, sa) || !sector(b.p + 1, b.n - 1, sb)) return false;
    // Two arcs of a circle, each under a half turn, meet exactly when one's start lies in the other.
    return !inside(sa.lo, sb) && !inside(sb.lo, sa);
}

// Two straight segments leaving one point S along u and v meet only at S unless they fold onto
// each other: apart when the angle between u and v exceeds the angular margin, or they point
// apart. Directions of vectors shorter than 2^10 margins are not trusted.
bool Classifier::directions_apart(Point u, Point v) const {
    const double lu = std::max(std::abs(u.x), std::abs(u.y)), lv = std::max(std::abs(v.x), std::abs(v.y));
    const double min_len = delta_ * double(1 << 10);
    if (!(lu >= min_len && lv >= min_len)) return false;
    const double c = cross(u, v), dot = u.x * v.x + u.y * v.y;
    // |u| |v| <= 2 lu lv: the turn exceeds the angular margin, or u and v point apart.
    return std::abs(c) > 2 * lu * lv / double(1 << 20) || dot < -0.5 * lu * lv;
}

bool Classifier::meet_only_at_end(const Seg& a, const Seg& b, int depth) {
    if (budget_ <= 0) return false;
    --budget_;
    if (a.n == 2 && b.n == 2 && directions_apart(a.p[0] - b.p[0], b.p[1] - b.p[0])) return true;
    if (sectors_apart(a, b)) return true;
    if (depth == 0) return false;
    Seg a0, a1, b0, b1;
    split(a, a0, a1);
    split(b, b0, b1);
    return disjoint(a0, b, depth - 1) && disjoint(a1, b1, depth - 1) && meet_only_at_end(a1, b0, depth - 1);
}

// Two lines that are not consecutive in a contour share exactly one end point V and leave it in
// directions apart (directions_apart): they meet at V only, where the boundary touches itself (map
// rings often touch at a node). V is kept for touches_uncross, which decides whether the touch is
// harmless. Curves touching at a vertex are not accepted (they take the exact path).
bool Classifier::touch_at_vertex(const Seg& a, const Seg& b) {
    if (a.n != 2 || b.n != 2) return false;
    int shared = 0;
    Point v{}, ua{}, ub{};
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            if (a.p[i] == b.p[j]) {
                ++shared;
                v = a.p[i];
                ua = a.p[1 - i] - v;
                ub = b.p[1 - j] - v;
            }
    if (shared != 1 || !directions_apart(ua, ub)) return false;
    touches_.push_back(v);
    return true;
}

// At every touch vertex V the contours pass several times, each pass arriving along one line and
// leaving along the next. The passes do not cross when, for every two of them, the two directions
// of one from V lie on the same side of the other's pair in the circular order (chords of a
// circle that do not interleave). Then the passes can be pulled apart by an arbitrarily small
// amount without meeting: every contour becomes a simple closed curve apart from the others, and
// winding numbers change only on a set of no area, so steps 2 and 3 decide the path as they do
// contours that do not meet. All directions at V are apart by the angular margin (every pair of
// lines at V passed directions_apart or meet_only_at_end), so the order is not a matter of rounding.
bool Classifier::touches_uncross() {
    if (touches_.empty()) return true;
    auto before = [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
    std::sort(touches_.begin(), touches_.end(), before);
    touches_.erase(std::unique(touches_.begin(), touches_.end()), touches_.end());
    passes_.clear();
    for (std::size_t i = 0; i < segs_.size(); ++i) {
        const auto at = std::lower_bound(touches_.begin(), touches_.end(), segs_[i].p[0], before);
        if (at != touches_.end() && *at == segs_[i].p[0])
            passes_.emplace_back(static_cast<std::uint32_t>(at - touches_.begin()), static_cast<std::uint32_t>(i));
    }
    std::sort(passes_.begin(), passes_.end());
    struct Pass {
        double lo, hi;  // the angles of its two directions from V, lo < hi
    };
    std::vector<Pass> at_v;
    for (std::size_t k = 0; k < passes_.size();) {
        std::size_t e = k;
        at_v.clear();
        for (; e < passes_.size() && passes_[e].first == passes_[k].first; ++e) {
            const Seg& out = segs_[passes_[e].second];
            const std::size_t c = static_cast<std::size_t>(out.contour);
            const std::size_t first = contour_at_[c], count = contour_at_[c + 1] - first;
            const Seg& in = segs_[first + (static_cast<std::size_t>(out.index) + count - 1) % count];
            if (out.n != 2 || in.n != 2 || !(in.p[1] == out.p[0])) return false;
            const Point v = out.p[0];
            const double a = std::atan2(in.p[0].y - v.y, in.p[0].x - v.x);
            const double b = std::atan2(out.p[1].y - v.y, out.p[1].x - v.x);
            if (!(a != b)) return false;
            at_v.push_back({std::min(a, b), std::max(a, b)});
        }
        for (std::size_t i = 0; i < at_v.size(); ++i)
            for (std::size_t j = i + 1; j < at_v.size(); ++j) {
                const Pass& p = at_v[i];
                const Pass& q = at_v[j];
                if (q.lo == p.lo || q.lo == p.hi || q.hi == p.lo || q.hi == p.hi) return false;
                const bool lo_in = q.lo > p.lo && q.lo<p.hi, hi_in = q.hi> p.lo && q.hi < p.hi;
                if (lo_in != hi_in) return false;  // the passes cross at V
            }
        k = e;
    }
    return true;
}

// The flattener halves conics at t = 1/2 (de Casteljau) while their flatness bound
// exceeds the tolerance, so every chord it draws for such a segment joins the ends of one node of
// the segment's halving tree, and a node is drawn as a chord exactly when its bound is within the
// tolerance and no ancestor's is. In path units under a similarity map of scale s, that is for
// lambda = tol / s in [lo, hi): lo = the node's bound, hi = the least bound of its ancestors.
// Lines are one chord at every tolerance; quadratics and cubics (n pieces of equal parameter
// length) may draw a chord anywhere inside their hull, which stands in for their chords.
double Classifier::halving_bound(const Seg& s) {
    if (s.conic) return std::sqrt(flatten_detail::bound2_conic(s.p[0], s.p[1], s.p[2], s.w));
    return 0;
}

void Classifier::as_root(Seg& s) {
    s.depth = 0;
    s.hi = INFINITY;
    s.lo = halving_bound(s);
}

// Two non-adjacent segments whose hulls no line separates: do the chords the flattener draws for
// them stay apart at every tolerance lambda in (0, lambda_]? Walks both halving trees: a pair of
// nodes whose hulls are apart covers every pair of their descendants; otherwise, when both nodes
// can be chords at one tolerance, their chords must be apart, and the coarser node (larger lo) is
// halved. Every pair of nodes that are chords at a common tolerance is reached or covered.
bool Classifier::chords_apart(const Seg& a, const Seg& b) {
    if (boxes_apart(a.box, b.box) || separated(a.p, a.n, b.p, b.n)) return true;
    if (budget_ <= 0) return false;
    const double lo = std::max(a.lo, b.lo) * (1 - kBoundSlack), hi = std::min(a.hi, b.hi) * (1 + kBoundSlack);
    if (lo < hi && lo <= lambda_ * (1 + kBoundSlack)) {
        auto chord = [](const Seg& s, Point* q) {
            if (!s.conic && s.n > 2) {
                for (int i = 0; i < s.n; ++i) q[i] = s.p[i];
                return s.n;
            }
            q[0] = s.p[0];
            q[1] = s.p[s.n - 1];
            return 2;
        };
        Point ca[4], cb[4];
        const int na = chord(a, ca), nb = chord(b, cb);
        if (!separated(ca, na, cb, nb)) return false;
    }
    const bool split_a = a.lo >= b.lo;
    const Seg& x = split_a ? a : b;
    // Nodes with lo = 0 are never halved (lines, quadratics, cubics, straight conics, the depth limit):
    // both are chords at every tolerance, and those were just found apart.
    if (!(x.lo > 0)) return true;
    Seg h[2];
    split(x, h[0], h[1]);
    for (Seg& c : h) {
        c.depth = x.depth + 1;
        c.hi = std::min(x.hi, x.lo);
        c.lo = c.depth >= limits::kMaxFlattenDepth ? 0 : halving_bound(c);
    }
    const Seg& other = split_a ? b : a;
    return chords_apart(h[0], other) && chords_apart(h[1], other);
}

// How far the flattened polygon of s can lie from the curve at tolerance lambda (path units):
// nothing for a line, else lambda itself, unless the depth limit stops the flattener first, which
// leaves at most the chord bound divided by 4^kMaxFlattenDepth (doubled here to cover the
// area-balanced pieces).
double Classifier::band(const Seg& s, double lambda) {
    if (s.n == 2) return 0;
    double b = 0;
    if (s.conic)
        b = std::sqrt(flatten_detail::bound2_conic(s.p[0], s.p[1], s.p[2], s.w));
    else if (s.n == 3)
        b = std::sqrt(flatten_detail::bound2_quad(s.p[0], s.p[1], s.p[2]));
    else if (s.n == 4)
        b = std::sqrt(flatten_detail::bound2_cubic(s.p[0], s.p[1], s.p[2], s.p[3]));
    constexpr double kDepthShrink =
        1.0 / (double(1u << limits::kMaxFlattenDepth) * double(1u << limits::kMaxFlattenDepth));
    return std::max(lambda, 2 * b * kDepthShrink) * (1 + kBoundSlack);
}

// Two non-adjacent segments whose hulls meet: are the curves farther apart than `gap`, the sum of
// their bands? Every flattening at a tolerance up to lambda_ stays within its band of its curve,
// so the two polygons then cannot meet. Proven on hulls widened by the gap, halving the larger
// segment while none separates them.
bool Classifier::bands_apart(const Seg& a, const Seg& b, double gap, int depth) {
    const Rect& p = a.box;
    const Rect& q = b.box;
    if (p.x1 + gap < q.x0 || q.x1 + gap < p.x0 || p.y1 + gap < q.y0 || q.y1 + gap < p.y0) return true;
    if (budget_ <= 0) return false;
    if (separated(a.p, a.n, b.p, b.n, gap)) return true;
    if (depth == 0) return false;
    Seg h0, h1;
    const bool split_a = std::max(p.width(), p.height()) >= std::max(q.width(), q.height());
    split(split_a ? a : b, h0, h1);
    const Seg& other = split_a ? b : a;
    return bands_apart(h0, other, gap, depth - 1) && bands_apart(h1, other, gap, depth - 1);
}

// Adds to w the crossings of s's control polygon with the ray from p to +x (Sunday's rule: +1
// upwards with p on the left), splitting s while p lies in its hull.
bool Classifier::winding_about(const Seg& s, Point p, int depth, int& w) {
    if (budget_ <= 0) return false;
    const bool apart = boxes_apart(s.box, Rect{p.x, p.y, p.x, p.y}) || separated(s.p, s.n, &p, 1);
    if (!apart) {
        if (depth == 0) return false;
        Seg h0, h1;
        split(s, h0, h1);
        return winding_about(h0, p, depth - 1, w) && winding_about(h1, p, depth - 1, w);
    }
    for (int i = 0; i + 1 < s.n; ++i) {
        const Point u = s.p[i], v = s.p[i + 1];
        const double side = cross(v - u, p - u);  // > 0: p left of u -> v
        if (u.y <= p.y) {
            if (v.y > p.y && side > 0) ++w;
        } else if (v.y <= p.y && side < 0) {
            --w;
        }
    }
    return true;
}

// Twice the area within which every flattening of contour c at a tolerance up to lambda_ differs
// from the curves, summed over its segments, each bounded in two ways (the smaller counts).
// Hulls: any chord the flattener draws for a node of a segment's halving tree bounds, with the
// node's curve, a region inside the node's hull. For a conic that sum is taken over the nodes its
// flattening can start from (the first nodes, from the root down, whose bound is within lambda_:
// every chord drawn is one of them or inside one), for a quadratic or a cubic over its whole hull
// (its pieces, area-balanced ones included, stay inside it).
// Bands: the straight homotopy from a segment's curve B to its polygon P (the same parameter)
// moves every point by at most the band d, so it sweeps twice an area of at most
// d (len B + len P). len B is at most the control polygon's length Lc, and len P at most
// len B + max|P_i - 2 P_(i+1) + P_(i+2)| / 2 <= 1.5 Lc (the balanced vertices' offsets), so
// 3 d Lc bounds it. An orientation decided with this slack holds for the flattened contour.
// (Twice a hull's area is half the sum of twice the areas of the triangles that leave out one
// control point each, for three or four points in any position.)
double Classifier::hull_areas(std::size_t c) const {
    auto tri = [](Point a, Point b, Point d) { return std::abs(cross(b - a, d - a)); };
    auto hull2 = [&](const Seg& s) {
        if (s.n == 3) return tri(s.p[0], s.p[1], s.p[2]);
        if (s.n == 4)
            return 0.5 * (tri(s.p[1], s.p[2], s.p[3]) + tri(s.p[0], s.p[2], s.p[3]) + tri(s.p[0], s.p[1], s.p[3]) +
                          tri(s.p[0], s.p[1], s.p[2]));
        return 0.0;
    };
    // Explicit stack: at most one pending half per level.
    Seg stack[limits::kMaxFlattenDepth + 2];
    double sum = 0;
    for (std::size_t i = contour_at_[c]; i < contour_at_[c + 1]; ++i) {
        const Seg& s = segs_[i];
        if (s.n == 2) continue;
        double lc = 0;
        for (int k = 1; k < s.n; ++k) lc += std::sqrt(length_sq(s.p[k] - s.p[k - 1]));
        const double banded = 3 * band(s, lambda_) * lc;
        if (!s.conic) {
            sum += std::min(hull2(s), banded);
            continue;
        }
        int n = 0;
        stack[n] = s;
        stack[n++].depth = 0;
        double nodes = 0;
        while (n > 0) {
            const Seg q = stack[--n];
            if (q.depth >= limits::kMaxFlattenDepth || halving_bound(q) <= lambda_ * (1 + kBoundSlack)) {
                nodes += hull2(q);
                continue;
            }
            split(q, stack[n], stack[n + 1]);
            stack[n].depth = stack[n + 1].depth = q.depth + 1;
            n += 2;
        }
        sum += std::min(nodes, banded);
    }
    return sum;
}

// A point of contour a (a segment's start) outside the hull of every segment of the other
// contours. Chords of those segments are drawn inside their hulls, so the winding number of the
// other contours about it is the same for the curves and for their flattening at any tolerance.
// False when there is none (a contour lying in other segments' hulls: no proof).
bool Classifier::winding_point(std::size_t a, const std::vector<Rect>& boxes, Point& p) {
    const std::size_t ncontours = contour_at_.size() - 1;
    for (std::size_t i = contour_at_[a]; i < contour_at_[a + 1]; ++i) {
        const Point q = segs_[i].p[0];
        const Rect qb{q.x, q.y, q.x, q.y};
        bool clear = true;
        for (std::size_t b = 0; b < ncontours && clear; ++b) {
            if (b == a || boxes_apart(boxes[b], qb)) continue;
            for (std::size_t k = contour_at_[b]; k < contour_at_[b + 1] && clear; ++k)
                clear = boxes_apart(segs_[k].box, qb) || separated(segs_[k].p, segs_[k].n, &q, 1);
        }
        if (budget_ <= 0) return false;
        if (clear) {
            p = q;
            return true;
        }
    }
    return false;
}

// Sign of contour c's area (closed-form areas of lines, quadratics and cubics relative to the
// contour's first point; a conic's bulge lies between 0 and its control triangle, so both bounds
// must agree). False when the area is within the margin of zero.
bool Classifier::orientation(std::size_t c, int& o, double slack) const {
    const Point origin = segs_[contour_at_[c]].p[0];
    double lo = 0, hi = 0;  // twice the area, bounds
    double scale = 0;
    for (std::size_t i = contour_at_[c]; i < contour_at_[c + 1]; ++i) {
        const Seg& s = segs_[i];
        Point q[4];
        for (int k = 0; k < s.n; ++k) {
            q[k] = s.p[k] - origin;
            scale = std::max({scale, std::abs(q[k].x), std::abs(q[k].y)});
        }
        double a = 0;
        if (s.n == 2) {
            a = cross(q[0], q[1]);
        } else if (s.conic) {
            const double chord = cross(q[0], q[2]);
            const double tri = cross(q[1] - q[0], q[2] - q[1]);
            lo += chord + std::min(0.0, tri);
            hi += chord + std::max(0.0, tri);
            continue;
        } else if (s.n == 3) {
            a = (2 * cross(q[0], q[1]) + cross(q[0], q[2]) + 2 * cross(q[1], q[2])) / 3;
        } else {
            a = 0.6 * cross(q[0], q[1]) + 0.3 * cross(q[0], q[2]) + 0.1 * cross(q[0], q[3]) + 0.3 * cross(q[1], q[2]) +
                0.3 * cross(q[1], q[3]) + 0.6 * cross(q[2], q[3]);
        }
        lo += a;
        hi += a;
    }
    const double margin = delta_ * scale * 64 + slack;
    if (lo > margin)
        o = 1;
    else if (hi < -margin)
        o = -1;
    else
        return false;
    return true;
}

bool Classifier::add_contour() {
    const std::size_t start = open_;
    // Spikes across the contour's start (its last line returning along its first).
    std::size_t first = start;
    while (segs_.size() - first >= 2 && is_spike_pair(segs_.back(), segs_[first])) {
        segs_.pop_back();
        ++first;
    }
    segs_.erase(segs_.begin() + static_cast<std::ptrdiff_t>(start), segs_.begin() + static_cast<std::ptrdiff_t>(first));
    if (segs_.size() == start) return true;
    // At least three segments, so that consecutive segments share exactly one end point. Lines
    // are halved for that, never curves: the flattener's chords span a whole curve, and its
    // area-balanced vertices lie off the curve, outside the hulls of the curve's halves. A
    // contour of curves alone is not proven.
    while (segs_.size() - start < 3) {
        const auto begin = segs_.begin() + static_cast<std::ptrdiff_t>(start);
        if (std::none_of(begin, segs_.end(), [](const Seg& s) { return s.n == 2; })) {
            segs_.resize(start);
            return false;
        }
        halves_.clear();
        for (auto it = begin; it != segs_.end(); ++it) {
            if (it->n != 2) {
                halves_.push_back(*it);
                continue;
            }
            Seg a, b;
            split(*it, a, b);
            a.whole = b.whole = false;
            halves_.push_back(a);
            halves_.push_back(b);
        }
        segs_.resize(start);
        segs_.insert(segs_.end(), halves_.begin(), halves_.end());
    }
    const int id = static_cast<int>(contour_at_.size());
    for (std::size_t i = start; i < segs_.size(); ++i) {
        segs_[i].contour = id;
        segs_[i].index = static_cast<int>(i - start);
    }
    contour_at_.push_back(start);
    return true;
}

// Segments per contour (each contour closed by a line when it does not end at its start), without
// segments whose control points all coincide (they draw nothing) and without spikes. Notes a cubic
// not proven free of loops (self_crossing), a conic weight outside [2^-500, 2^500], where no proof
// is attempted (splitting such a conic would overflow; control points are finite here), and a
// contour add_contour cannot take (unproven).
class Classifier::Collector {
public:
    explicit Collector(Classifier& c) : c_(c) {}
    bool self_crossing = false;
    bool out_of_range = false;
    bool unproven = false;  // a contour add_contour could not take

    void move(Point p) {
        end();
        start_ = cur_ = p;
    }
    void line(Point a, Point b) {
        push({a, b}, false, 1);
        cur_ = b;
    }
    void quad(Point a, Point c, Point b) {
        push({a, c, b}, false, 1);
        cur_ = b;
    }
    void cubic(Point a, Point c1, Point c2, Point b) {
        push({a, c1, c2, b}, false, 1);
        cur_ = b;
    }
    void conic(Point a, Point c, Point b, double w) {
        push({a, c, b}, true, w);
        cur_ = b;
    }
    void close(Point last, Point first) {
        if (!(last == first)) push({last, first}, false, 1);
        cur_ = start_ = first;
        end();
    }
    // Closes and adds the current contour.
    void end() {
        if (c_.segs_.size() > c_.open_ && !(cur_ == start_)) push({cur_, start_}, false, 1);
        if (!c_.add_contour()) unproven = true;
        c_.open_ = c_.segs_.size();
    }

private:
    // Appends the segment to the contour being collected, in place (segments are large).
    void push(std::initializer_list<Point> pts, bool conic, double w) {
        std::vector<Seg>& segs = c_.segs_;
        Seg& s = segs.emplace_back();
        s.n = 0;
        for (Point q : pts) s.p[s.n++] = q;
        s.conic = conic;
        s.w = w;
        if (conic && !(w >= 0x1p-500 && w <= 0x1p500)) out_of_range = true;
        bool degenerate = true;
        for (int i = 1; i < s.n; ++i) degenerate = degenerate && s.p[i] == s.p[0];
        if (degenerate) return segs.pop_back();
        if (s.n == 4 && !cubic_monotone(s)) self_crossing = true;
        s.box = box_of(s);
        // A line straight back along the previous one (a spike, A to B to A) adds nothing to any
        // pixel's integral and no area anywhere: both are left out.
        if (segs.size() - 1 > c_.open_ && is_spike_pair(segs[segs.size() - 2], s)) segs.resize(segs.size() - 2);
    }

    // A cubic may loop on itself. One whose control points are monotone in x or in y is monotone
    // there too, and so is every polygon inscribed in it: no self-crossing. So is the fill's
    // area-balanced polygon (Flattener::balanced_cubic), whose inner vertices B(t) - (h^2 / 2) L(t)
    // lie off the curve. With a, b, c >= 0 the steps dP_j of the coordinate (E = a - 2b + c) and
    // h <= 1/2, an end step is a (3h - 5h^2/2 + h^3/2) + b (5h^2/2 - h^3) + c h^3/2 >= 0, and an
    // inner step over [t, t + h] (h <= t <= 1 - 2h) is the curve's step minus (h^3 / 2) E, where the
    // curve's step, 3 the integral of a (1 - s)^2 + 2 b s (1 - s) + c s^2, is at least 7 (a + c) h^3.
    static bool cubic_monotone(const Seg& s) {
        auto mono = [&](double Point::*c) {
            const double a = s.p[0].*c, b = s.p[1].*c, d = s.p[2].*c, e = s.p[3].*c;
            return (a <= b && b <= d && d <= e) || (a >= b && b >= d && d >= e);
        };
        return mono(&Point::x) || mono(&Point::y);
    }

    Classifier& c_;
    Point start_{}, cur_{};
};

Topology Classifier::run(const Path& path, double lambda) {
    lambda_ = lambda;
    segs_.clear();
    contour_at_.clear();
    open_ = 0;
    touches_.clear();
    if (!path.is_finite()) return Topology::Overlapping;
    const Rect cb = path.control_bounds();
    if (!(cb.x1 >= cb.x0)) return Topology::Simple;  // no points
    const double extent =
        std::max({std::abs(cb.x0), std::abs(cb.x1), std::abs(cb.y0), std::abs(cb.y1), cb.width(), cb.height()});
    if (extent == 0) return Topology::Simple;
    // Beyond 2^500 products of coordinates (and the grid's cell indices) could overflow, and below
    // 2^-500 the margin could underflow to nothing: no proof is attempted there (the per-cell
    // check is exact at any scale).
    if (!(extent >= 0x1p-500 && extent <= 0x1p500)) return Topology::Overlapping;
    delta_ = std::ldexp(extent, -40);

    Collector collect(*this);
    path.visit(collect);
    collect.end();
    contour_at_.push_back(segs_.size());
    if (collect.self_crossing || collect.out_of_range || collect.unproven) return Topology::Overlapping;
    if (segs_.empty()) return Topology::Simple;
    budget_ = 200 * static_cast<long>(segs_.size()) + 20000;
    if (!pairs_apart(cb) || !touches_uncross()) return Topology::Overlapping;
    return windings_in_range() ? Topology::Simple : Topology::Overlapping;
}

// 1. Pairs of segments with overlapping boxes, found on a uniform grid of about one cell per
// segment over the path's bounds `cb`: each segment is listed in the cells its box covers, and a
// pair is tested in one cell only (the corner cell of the two boxes' overlap), so segments far
// apart cost nothing and a pair is never tested twice.
// Pairs are decided on the segments' whole hulls, without splitting: the flattener's chords may
// span any part of a segment, and they stay inside its whole hull, so only a separation of whole
// hulls also holds for the flattened polygon at any tolerance.
bool Classifier::pairs_apart(const Rect& cb) {
    const std::size_t n = segs_.size();
    const int grid = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(n))), 1, 1024);
    const double gx = grid / std::max(cb.width() + 2 * delta_, delta_),
                 gy = grid / std::max(cb.height() + 2 * delta_, delta_);
    auto cell_x = [&](double x) { return std::clamp(static_cast<int>((x - cb.x0 + delta_) * gx), 0, grid - 1); };
    auto cell_y = [&](double y) { return std::clamp(static_cast<int>((y - cb.y0 + delta_) * gy), 0, grid - 1); };
    std::vector<Cells>& span = span_;
    span.resize(n);
    std::vector<std::uint32_t>& cstart = cstart_;
    cstart.assign(static_cast<std::size_t>(grid) * grid + 1, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const Rect& b = segs_[i].box;
        span[i] = {cell_x(b.x0 - delta_), cell_y(b.y0 - delta_), cell_x(b.x1 + delta_), cell_y(b.y1 + delta_)};
        for (int y = span[i].y0; y <= span[i].y1; ++y)
            for (int x = span[i].x0; x <= span[i].x1; ++x) ++cstart[static_cast<std::size_t>(y) * grid + x + 1];
    }
    for (std::size_t c = 1; c < cstart.size(); ++c) cstart[c] += cstart[c - 1];
    if (cstart.back() > 64 * n + 100000) return false;  // long segments everywhere: not worth it
    std::vector<std::uint32_t>& members = members_;
    members.resize(cstart.back());
    std::vector<std::uint32_t>& fill = fill_;
    fill.assign(cstart.begin(), cstart.end() - 1);
    for (std::uint32_t i = 0; i < n; ++i)
        for (int y = span[i].y0; y <= span[i].y1; ++y)
            for (int x = span[i].x0; x <= span[i].x1; ++x) members[fill[static_cast<std::size_t>(y) * grid + x]++] = i;
    relaxed_.assign(contour_at_.size() - 1, 0);
    long box_tests = 0;
    for (int cy = 0; cy < grid; ++cy)
        for (int cx = 0; cx < grid; ++cx) {
            const std::size_t c = static_cast<std::size_t>(cy) * grid + cx;
            for (std::uint32_t k = cstart[c]; k < cstart[c + 1]; ++k)
                for (std::uint32_t l = k + 1; l < cstart[c + 1]; ++l) {
                    if (++box_tests > 256 * static_cast<long>(n) + 100000) return false;
                    const std::uint32_t i = members[k], j = members[l];
                    if (std::max(span[i].x0, span[j].x0) != cx || std::max(span[i].y0, span[j].y0) != cy) continue;
                    if (!boxes_apart(segs_[i].box, segs_[j].box) && !pair_apart(segs_[i], segs_[j])) return false;
                }
        }
    return true;
}

// Whether segments s and t, whose boxes overlap, meet nowhere but at a vertex they may share.
bool Classifier::pair_apart(const Seg& s, const Seg& t) {
    constexpr int kDepth = 0;
    const std::size_t count =
        contour_at_[static_cast<std::size_t>(s.contour) + 1] - contour_at_[static_cast<std::size_t>(s.contour)];
    const int last = static_cast<int>(count) - 1;
    if (s.contour == t.contour && (t.index == s.index + 1 || (s.index == last && t.index == 0)))
        return meet_only_at_end(s, t, kDepth);
    if (s.contour == t.contour && (s.index == t.index + 1 || (t.index == last && s.index == 0)))
        return meet_only_at_end(t, s, kDepth);
    bool ok = disjoint(s, t, kDepth) || touch_at_vertex(s, t);
    if (!ok && lambda_ > 0 && s.whole && t.whole) {
        Seg a = s, b = t;
        as_root(a);
        as_root(b);
        ok = chords_apart(a, b) || bands_apart(s, t, band(s, lambda_) + band(t, lambda_), kBandDepth);
        if (ok && s.contour == t.contour) relaxed_[static_cast<std::size_t>(s.contour)] = 1;
    }
    return ok;
}

// 2 and 3. Orientation of each contour and winding numbers of the others along it: the winding
// numbers must span one unit.
bool Classifier::windings_in_range() {
    const std::size_t ncontours = contour_at_.size() - 1;
    std::vector<Rect>& boxes = boxes_;
    boxes.resize(ncontours);
    std::vector<int>& orient = orient_;
    orient.resize(ncontours);
    for (std::size_t c = 0; c < ncontours; ++c) {
        if (!orientation(c, orient[c], relaxed_[c] ? hull_areas(c) : 0)) return false;
        Rect b = segs_[contour_at_[c]].box;
        for (std::size_t i = contour_at_[c]; i < contour_at_[c + 1]; ++i) {
            const Rect& sb = segs_[i].box;
            b = {std::min(b.x0, sb.x0), std::min(b.y0, sb.y0), std::max(b.x1, sb.x1), std::max(b.y1, sb.y1)};
        }
        boxes[c] = b;
    }
    int lo = 0, hi = 0;
    for (std::size_t a = 0; a < ncontours; ++a) {
        // The winding numbers are read at a vertex of a; where contours touch, at one clear of the others.
        Point p = segs_[contour_at_[a]].p[0];
        if ((lambda_ > 0 || !touches_.empty()) && !winding_point(a, boxes, p)) return false;
        int w = 0;
        for (std::size_t b = 0; b < ncontours; ++b) {
            if (b == a || boxes_apart(boxes[b], Rect{p.x, p.y, p.x, p.y})) continue;
            for (std::size_t i = contour_at_[b]; i < contour_at_[b + 1]; ++i)
                if (!winding_about(segs_[i], p, 20, w)) return false;
        }
        lo = std::min({lo, w, w + orient[a]});
        hi = std::max({hi, w, w + orient[a]});
        if (hi - lo > 1) return false;
    }
    return true;
}

}  // namespace

Topology classify_topology(const Path& path) {
    // One classifier per thread keeps its buffers between calls: no allocation per path once warm.
    thread_local Classifier c;
    const Topology t = c.run(path);
    c.trim();
    return t;
}

double similarity_scale(const Affine& m) {
    const double s = std::hypot(m.a, m.b);
    const bool turn = std::abs(m.d - m.a) + std::abs(m.c + m.b) <= 0x1p-40 * s;
    const bool mirror = std::abs(m.d + m.a) + std::abs(m.c - m.b) <= 0x1p-40 * s;
    return s > 0 && std::isfinite(s) && (turn || mirror) ? s : 0;
}

Topology classify_topology(const Path& path, double max_tolerance) {
    if (!(max_tolerance > 0) || !std::isfinite(max_tolerance))
        throw Error(ErrorKind::InvalidArgument, "classify_topology: the tolerance must be a positive number");
    thread_local Classifier c;
    const Topology t = c.run(path, max_tolerance);
    c.trim();
    return t;
}

}  // namespace casteljau
