// Map stage: a feature's geometry projected into pixel-space paths (see feature_paths.hpp).
#include "map/feature_paths.hpp"

#include <algorithm>
#include <cmath>

#include "map/clip_to_frame.hpp"
#include "map/ring_spikes.hpp"
#include "map/simplify_map.hpp"

namespace casteljau::map_detail {

namespace {

// Whether some step of the ring goes more than half way round (split_ring_at_antimeridian then
// cuts it), and twice its signed area (its orientation), in one pass over it.
struct RingScan {
    bool crosses = false;
    double area2 = 0;
};
RingScan scan_ring(std::span<const Point> r) {
    RingScan s;
    const std::size_t n = r.size();
    for (std::size_t i = 0; i + 1 < n; ++i) {
        s.crosses = s.crosses || std::fabs(r[i + 1].x - r[i].x) > 180;
        s.area2 += r[i].x * r[i + 1].y - r[i + 1].x * r[i].y;
    }
    if (n > 0) s.area2 += r[n - 1].x * r[0].y - r[0].x * r[n - 1].y;
    return s;
}

}  // namespace

std::span<const Point> Projector::projected(std::span<const Point> in, bool closed) const {
    if (proj_.kind() == MapProjection::Kind::Equirectangular) return in;  // the identity: no copy
    std::vector<Point>& out = projected_;
    out.clear();
    out.reserve(in.size());
    Point q;
    const std::size_t n = in.size();
    const std::size_t segs = closed ? n : (n == 0 ? 0 : n - 1);
    if (!densify_) {
        for (const Point& p : in)
            if (proj_.project(p, q)) out.push_back(q);
        return out;
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (proj_.project(in[i], q)) out.push_back(q);
        if (i >= segs) continue;
        const Point a = in[i], b = in[(i + 1) % n];
        const double len = std::max(std::fabs(b.x - a.x), std::fabs(b.y - a.y));
        const int steps = static_cast<int>(std::ceil(len / kDensifyDegrees));
        for (int s = 1; s < steps && steps <= 4096; ++s)
            if (proj_.project(lerp(a, b, static_cast<double>(s) / steps), q)) out.push_back(q);
    }
    return out;
}

void Projector::geometry(const Geometry& g, PieceVisitor& v) const {
    Point q;
    if (g.kind == GeometryKind::Points) {
        for (const Point& p : g.points)
            if (proj_.project(p, q)) v.point(q);
        return;
    }
    std::size_t start = 0;
    if (g.kind == GeometryKind::Lines) {
        for (std::uint32_t end : g.ring_ends) {
            pieces_.clear();
            split_line_at_antimeridian(std::span<const Point>(g.points).subspan(start, end - start), pieces_);
            for (const auto& piece : pieces_) {
                const std::span<const Point> line = projected(piece, false);
                if (line.size() >= 2) v.line(line);
            }
            start = end;
        }
        return;
    }
    std::size_t ring = 0;
    for (std::uint32_t pend : g.polygon_ends) {
        for (bool exterior = true; ring < pend; ++ring, exterior = false) {
            const std::uint32_t end = g.ring_ends[ring];
            std::span<const Point> r = std::span<const Point>(g.points).subspan(start, end - start);
            start = end;
            const RingScan scan = scan_ring(r);
            if (!scan.crosses) {
                // What split_ring_at_antimeridian gives such a ring, without its copies: the
                // ring less its repeated closing position (which adds nothing to the area).
                if (r.size() < 3) continue;
                if (r.front() == r.back()) r = r.first(r.size() - 1);
                ring_piece(r, exterior, scan.area2, v);
                continue;
            }
            pieces_.clear();
            split_ring_at_antimeridian(r, pieces_);
            for (const auto& piece : pieces_) ring_piece(piece, exterior, scan_ring(piece).area2, v);
        }
    }
}

// One piece of a ring: oriented (exteriors counter-clockwise in lon/lat, positive area; holes
// clockwise), projected, handed to the visitor.
void Projector::ring_piece(std::span<const Point> r, bool exterior, double area2, PieceVisitor& v) const {
    if ((exterior && area2 < 0) || (!exterior && area2 > 0)) {
        reversed_.assign(r.rbegin(), r.rend());
        r = reversed_;
    }
    const std::span<const Point> ring = projected(r, true);
    if (ring.size() >= 3) v.ring(ring);
}

void append_polyline_segments(std::span<const Point> pts, bool closed, std::vector<LineSegment>& out) {
    if (pts.size() < 2) return;
    for (std::size_t i = 1; i < pts.size(); ++i) out.push_back({pts[i - 1], pts[i]});
    if (closed) out.push_back({pts.back(), pts.front()});
}

void append_segments(const Path& path, double tolerance, Polyline& flat, std::vector<LineSegment>& out) {
    if (path.empty()) return;
    flat.clear();
    flatten(path, Affine{}, tolerance, flat);
    std::size_t begin = 0;
    for (std::size_t c = 0; c < flat.contour_ends.size(); ++c) {
        const std::size_t end = flat.contour_ends[c];
        append_polyline_segments(std::span<const Point>(flat.points).subspan(begin, end - begin), flat.closed[c], out);
        begin = end;
    }
}

void PathVisitor::map_all(std::span<const Point> pts) {
    mapped.resize(pts.size());
    for (std::size_t i = 0; i < pts.size(); ++i) mapped[i] = m.apply(pts[i]);
}

void PathVisitor::ring(std::span<const Point> pts) {
    if (ring_segments) {
        map_all(pts);  // the stroke keeps the spikes
        if (!stroke_clip || inside(mapped, *stroke_clip)) {
            append_polyline_segments(mapped, true, *ring_segments);
        } else {
            clip_ring(mapped, *stroke_clip, clipped);
            if (clipped.size() >= 3) append_polyline_segments(clipped, true, *ring_segments);
        }
        if (fill_only) drop_spikes(mapped);
    } else if (fill_only) {
        map_without_spikes(pts, m, mapped);
    } else {
        map_all(pts);
    }
    if (mapped.size() < 3) return;  // nothing but spikes
    if (clip && !inside(mapped, *clip)) {
        clip_ring(mapped, *clip, clipped);
        if (clipped.size() >= 3) fill.add_polygon(clipped);
        return;
    }
    fill.add_polygon(mapped);
}

void PathVisitor::line(std::span<const Point> pts) {
    map_all(pts);
    const std::optional<Rect>& cut = clip ? clip : stroke_clip;
    if (cut && !inside(mapped, *cut)) {
        clip_line(mapped, *cut, lines);
        return;
    }
    lines.move_to(mapped[0]);
    for (std::size_t i = 1; i < mapped.size(); ++i) lines.line_to(mapped[i]);
}

void PathVisitor::point(Point p) {
    if (!(point_radius > 0)) return;
    fill.add_circle(m.apply(p), point_radius);
    if (ring_segments) {
        Path disk;
        disk.add_circle(m.apply(p), point_radius);
        append_segments(disk, disk_tolerance, flat, *ring_segments);
    }
}

}  // namespace casteljau::map_detail
