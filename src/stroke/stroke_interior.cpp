// Stroke stage: capsules that lie wholly inside a stroke's outline, for the rasterizer (see
// stroke_outline() in include/casteljau/stroke.hpp).
//
// Why they are inside. Let P be one contour of the flattened centre line, h half the pen's width,
// and p a point within r < h of a segment s of P; its nearest point q on P is then within r too.
//   - q inside a segment: p lies on that segment's normal, in its rectangle, which the outline
//     holds whole (inner joins either pivot through the vertex, keeping both rectangles, or go
//     through the offset lines' intersection where the rectangles' union is that corner).
//   - q at a vertex: p lies in the vertex's normal cone, on the outer side of the turn, which a
//     round join (or, at a smooth vertex, the always-round sweep, or the offset lines' corner
//     that stands for it and holds it) fills up to h.
//   - q at an open end E, or p where the end changes the stroke. What the end draws differs from
//     the ideal only beyond the line L through E square to the path's direction there (caps, the
//     chord's rectangle cut along L; behind L the sweep from the chord's direction to the path's
//     covers what lies within h of E) and, at a tight end (the path turning by a right angle or
//     more within its first chord, or on a radius under h), in a triangle within 2h of E. So a
//     segment's capsule is cut where it could reach those places (OpenEnd below): by L, or by a
//     line that keeps it out of the disc around E that holds them; at a tight end, capsules
//     within 4h of E are dropped.
// With other joins a corner's outer cone may be short of h, and a capsule reaching into it from a
// nearby segment would not be inside: a contour with such a corner gives only its segments'
// rectangles (the first case above holds for every join), none for a segment an end cuts or drops.
// The outline is short of this ideal by the flattening of round arcs (chords within the
// tolerance) and the swept wedges it leaves out when they reach less than the tolerance: radius
// h - 3 tol keeps clear of both. Under m the capsule's image holds the capsule of radius
// r x m.min_scale() about the images of its ends.
#include <algorithm>
#include <cmath>

#include "stroke/stroke_internal.hpp"

namespace casteljau::stroke_detail {
namespace {

// What an open end E does to a segment's capsule. At an end that is not tight, the outline differs
// from the ideal only beyond the line L through E square to the path's direction `out` (pointing
// out of the path), and only within `reach` of E: the cap (within h sqrt 2), the sector the normal
// sweeps from the chord's direction to the path's, and the part of the first chord's rectangle cut
// along L (within sqrt(h^2 + c^2) of E, c = h tan(a) the cut's reach along the chord, a the angle
// between chord and path). A point p of a capsule (radius r < h) of a segment s whose nearest point
// on the path is not E lies in a rectangle or a round sector the outline holds, so only p beyond L
// and within `reach` of E can be missing. Two cuts exclude that region: L itself (moved back by the
// tolerance), or, for a segment farther than `reach` from E, the line square to the direction from
// E to the segment's nearest point at distance `reach` from E, which keeps the whole segment. The
// capsule takes whichever keeps it deeper, and no cut at all when it lies wholly behind L or at
// least `reach` + r from E. At a tight end (`out` zero) the outline may lack a triangle within 2h
// of E, and the capsules of segments within 4h of E are dropped.
struct OpenEnd {
    Point at;
    Vec out;
    double reach = 0;
    enum Effect { Keep, Cut, Drop };
    // The cut to apply (Cut), or none.
    Effect effect(Point a, Point b, double r, double tol, double h, HalfPlane& cut) const {
        const bool has_line = out != Vec{0, 0};
        const double behind_a = -(a - at).dot(out), behind_b = -(b - at).dot(out);
        if (has_line && std::min(behind_a, behind_b) >= r + tol) return Keep;
        const Vec ab = b - a;
        const double len2 = ab.dot(ab);
        const double t = len2 > 0 ? std::clamp((at - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
        const Vec to = a + ab * t - at;
        const double dist = length_of(to);
        if (!has_line) return dist >= 4 * h ? Keep : Drop;
        if (dist >= reach + r) return Keep;
        const double line_depth = std::min(behind_a, behind_b) - tol;
        if (dist > reach && dist - reach > line_depth) {
            const Vec u = to / dist;
            cut = {at + u * reach, -u};
        } else {
            cut = {at - out * tol, out};
        }
        return Cut;
    }
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
    // Caps reach h sqrt 2 from e (square), h (round); 2h bounds both with room to spare.
    const double cap_reach = 2 * h + tol;
    if (t == Vec{0, 0}) return {e, -d, cap_reach};
    const double cr = std::abs(t.cross(d)), dt = t.dot(d);
    if (cr == 0 && dt > 0) return {e, -t, cap_reach};
    if (dt <= 0 || len < 2 * cr * h) return {e, {0, 0}};
    const double c = h * cr / dt;  // the reach of the rectangle's cut along the chord
    return {e, -t, std::max(cap_reach, std::sqrt(h * h + c * c) + tol)};
}

// A half-plane of user space as a half-plane of pixel space under m.
HalfPlane to_pixels(const HalfPlane& hp, const Affine& m) {
    const Vec along = m.apply_vector(Vec{-hp.out.y, hp.out.x});
    Vec n{along.y, -along.x};
    if (n.dot(m.apply_vector(hp.out)) < 0) n = -n;
    return {m.apply(hp.at), n};
}

// Cuts `cc` (the capsule from a to b) square to the segment at both ends: what is left is the
// segment's rectangle, which the outline holds whole whatever the joins. False for a segment of no
// length.
bool cut_square(Point a, Point b, const Affine& m, CutCapsule& cc) {
    const Vec d = b - a;
    const double len = length_of(d);
    if (!(len > 0)) return false;
    const Vec u = d / len;
    cc.cuts[0] = to_pixels(HalfPlane{a, -u}, m);
    cc.cuts[1] = to_pixels(HalfPlane{b, u}, m);
    cc.cut_count = 2;
    return true;
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
        // A corner joined otherwise than round may leave its normal cone short of h, and a capsule
        // around a nearby segment may reach into it: such contours give only their segments'
        // rectangles, each cut square at both ends.
        bool rectangles = false;
        if (style.join != LineJoin::Round)
            for (std::size_t i = closed ? 0 : 1; i + (closed ? 0 : 1) < pts.size() && !rectangles; ++i)
                rectangles = smooth[i] == 0;
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
            if (rectangles && !cut_square(a, b, m, cc)) continue;
            bool keep = true;
            for (int k = 0; k < (closed ? 0 : 2) && keep; ++k) {
                HalfPlane cut;
                const OpenEnd::Effect e = ends[k].effect(a, b, r, tol, h, cut);
                keep = e == OpenEnd::Keep || (e == OpenEnd::Cut && !rectangles);
                if (keep && e == OpenEnd::Cut) cc.cuts[cc.cut_count++] = to_pixels(cut, m);
            }
            if (keep) out.push_back(cc);
        }
    }
}

}  // namespace casteljau::stroke_detail
