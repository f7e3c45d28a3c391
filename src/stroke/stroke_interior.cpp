// Stroke stage: capsules that lie wholly inside a stroke's outline, for the rasterizer (see
// stroke_outline() in include/casteljau/stroke.hpp).
//
// Why they are inside. Let P be one contour of the flattened centre line, h half the pen's width,
// and p a point within r < h of a segment s of P; its nearest point q on P is then within r too.
//   - q inside a segment: p lies on that segment's normal, in its rectangle, which the outline
//     holds whole (inner joins either pivot through the vertex, keeping both rectangles, or go
//     through the offset lines' intersection where the rectangles' union is that corner).
//   - q at a vertex: p lies in the vertex's normal cone, on the outer side of the turn, which a
//     round join (or, at a smooth vertex, the always-round sweep) fills up to h.
//   - q at an open end E, or p where the end changes the stroke. What the end draws differs from
//     the ideal only beyond the line L through E square to the path's direction there (caps, the
//     chord's rectangle cut along L; behind L the sweep from the chord's direction to the path's
//     covers what lies within h of E) and, at a tight end (the path turning by a right angle or
//     more within its first chord, or on a radius under h), in a triangle within 2h of E. So a
//     segment keeps its whole capsule when it is at least 4h from E (every p is then more than
//     4h - r > 2h from E, and nearer s than E, so q is not E) or when the capsule lies wholly
//     behind L; else, at an end that is not tight, its capsule is cut by L (moved back by the
//     tolerance); at a tight end it is dropped.
// The outline is short of this ideal by the flattening of round arcs (chords within the
// tolerance) and the swept wedges it leaves out when they reach less than the tolerance: radius
// h - 3 tol keeps clear of both. Under m the capsule's image holds the capsule of radius
// r x m.min_scale() about the images of its ends.
#include <algorithm>
#include <cmath>

#include "stroke/stroke_internal.hpp"

namespace casteljau::stroke_detail {
namespace {

// What an open end does to a segment's capsule: nothing when the segment lies at least `away` (4h)
// from the end or the capsule lies wholly behind the line through the end square to `out` (the
// path's outward unit direction there) by `behind`; else, unless the end is tight (`out` zero),
// the capsule is cut by that line moved `margin` behind; at a tight end it is dropped.
struct OpenEnd {
    Point at;
    Vec out;
    enum Effect { Keep, Cut, Drop };
    Effect effect(Point a, Point b, double behind, double away) const {
        const bool has_line = out != Vec{0, 0};
        if (has_line && std::max((a - at).dot(out), (b - at).dot(out)) <= -behind) return Keep;
        if (distance_squared_to_segment(at, a, b) >= away * away) return Keep;
        return has_line ? Cut : Drop;
    }
    HalfPlane line(double margin) const { return {at - out * margin, out}; }
};

// The end at `e`, whose first chord goes to `q` (the first point apart from it), the path leaving
// it in unit direction `t` ((0, 0): the chord's). As the outliner draws it (stroke.cpp,
// start_end and finish_end), an end where the path turns from the chord by a right angle or more,
// or on a radius (len / (2 sin a)) under h, may have a triangle within 2h of it cut away: tight.
// Any other end covers, behind the line through it square to t, everything within h of the path.
// A chord shorter than `tol` gives no reliable direction: tight too.
OpenEnd open_end(Point e, Point q, Vec t, double h, double tol) {
    const Vec v = q - e;
    const double len = length_of(v);
    if (!(len >= tol)) return {e, {0, 0}};
    const Vec d = v / len;
    if (t == Vec{0, 0}) return {e, -d};
    const double cr = std::abs(t.cross(d)), dt = t.dot(d);
    if (cr == 0 && dt > 0) return {e, -t};
    if (dt <= 0 || len < 2 * cr * h) return {e, {0, 0}};
    return {e, -t};
}

}  // namespace

void interior_capsules(const FlatContours& flat, const StrokeStyle& style, double tol, const Affine& m,
                       std::vector<CutCapsule>& out) {
    const double h = style.width / 2, r = h - 3 * tol, scale = m.min_scale();
    constexpr double kHalfDiagonal = 0.70710678118654757;  // a capsule thinner than this holds no pixel
    if (!(r > 0) || !(r * scale >= kHalfDiagonal) || !std::isfinite(r * scale)) return;
    const Polyline& poly = flat.poly;
    std::size_t start = 0;
    for (std::size_t c = 0; c < poly.contour_count(); ++c) {
        const std::size_t end = poly.contour_ends[c];
        const std::span<const Point> pts(poly.points.data() + start, end - start);
        const std::span<const std::uint8_t> smooth(flat.smooth.data() + start, end - start);
        start = end;
        if (pts.size() < 2) continue;
        const bool closed = poly.closed[c];
        if (style.join != LineJoin::Round) {
            // A corner joined otherwise may leave its normal cone short of h: no capsules.
            bool corner = false;
            for (std::size_t i = closed ? 0 : 1; i + (closed ? 0 : 1) < pts.size() && !corner; ++i)
                corner = smooth[i] == 0;
            if (corner) continue;
        }
        double length = 0;
        for (std::size_t i = 1; i < pts.size() && length < style.width; ++i) length += length_of(pts[i] - pts[i - 1]);
        if (closed) length += length_of(pts.front() - pts.back());
        if (!(length >= style.width)) continue;
        OpenEnd ends[2];
        if (!closed) {
            std::size_t i = 1, j = pts.size() - 2;
            while (i + 1 < pts.size() && pts[i] == pts[0]) ++i;
            while (j > 0 && pts[j] == pts.back()) --j;
            ends[0] = open_end(pts[0], pts[i], flat.head[c], h, tol);
            ends[1] = open_end(pts.back(), pts[j], -flat.tail[c], h, tol);
        }
        const std::size_t segs = closed ? pts.size() : pts.size() - 1;
        for (std::size_t i = 0; i < segs; ++i) {
            const Point a = pts[i], b = pts[(i + 1) % pts.size()];
            CutCapsule cc(Capsule{m.apply(a), m.apply(b), r * scale});
            bool keep = true;
            for (int k = 0; k < (closed ? 0 : 2) && keep; ++k) {
                const OpenEnd::Effect e = ends[k].effect(a, b, r + tol, 4 * h);
                keep = e != OpenEnd::Drop;
                if (e == OpenEnd::Cut) {
                    // The cut in pixel space: the line's image, `out` turned into its normal there.
                    const HalfPlane hp = ends[k].line(tol);
                    const Vec along = m.apply_vector(Vec{-hp.out.y, hp.out.x});
                    Vec n{along.y, -along.x};
                    if (n.dot(m.apply_vector(hp.out)) < 0) n = -n;
                    cc.cuts[cc.cut_count++] = {m.apply(hp.at), n};
                }
            }
            if (keep) out.push_back(cc);
        }
    }
}

}  // namespace casteljau::stroke_detail
