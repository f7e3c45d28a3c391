// Map stage (internal): a feature's geometry projected into pixel space, as the paths that fill
// and stroke it.
//
// Projector takes each ring and line of a Geometry through the antimeridian cut and the map
// projection (densified where the projection bends lines) and hands the pieces to a PieceVisitor,
// in projected coordinates: polygon rings oriented (exteriors positive signed area in lon/lat,
// holes negative), lines, points. PathVisitor maps them to pixels and builds the feature's fill
// (rings and point disks) and its lines; BoundsVisitor only measures them.
// Thread-safety: a Projector and a visitor hold scratch buffers; one each per thread.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <vector>

#include "casteljau/flatten.hpp"
#include "casteljau/map.hpp"
#include "casteljau/round_stroke.hpp"

namespace casteljau::map_detail {

// Receives the projected pieces of one geometry.
struct PieceVisitor {
    virtual ~PieceVisitor() = default;
    virtual void ring(std::span<const Point> pts) = 0;
    virtual void line(std::span<const Point> pts) = 0;
    virtual void point(Point p) = 0;
};

class Projector {
public:
    explicit Projector(const MapProjection& p) : proj_(p), densify_(!p.preserves_graticule_lines()) {}

    // Hands every piece of `g` to `v`.
    void geometry(const Geometry& g, PieceVisitor& v) const;

private:
    // A lon/lat polyline projected (points that cannot be projected are dropped): `in` itself
    // under the identity (equirectangular), else projected_.
    std::span<const Point> projected(std::span<const Point> in, bool closed) const;
    // `area2`: twice the piece's signed area in lon/lat (its orientation).
    void ring_piece(std::span<const Point> r, bool exterior, double area2, PieceVisitor& v) const;

    const MapProjection& proj_;
    bool densify_;
    mutable std::vector<std::vector<Point>> pieces_;
    mutable std::vector<Point> reversed_;
    mutable std::vector<Point> projected_;
};

// The bounds of every piece.
struct BoundsVisitor final : PieceVisitor {
    Rect r{INFINITY, INFINITY, -INFINITY, -INFINITY};
    void add(Point p) {
        r.x0 = std::min(r.x0, p.x);
        r.y0 = std::min(r.y0, p.y);
        r.x1 = std::max(r.x1, p.x);
        r.y1 = std::max(r.y1, p.y);
    }
    void ring(std::span<const Point> pts) override {
        for (const Point& p : pts) add(p);
    }
    void line(std::span<const Point> pts) override {
        for (const Point& p : pts) add(p);
    }
    void point(Point p) override { add(p); }
};

// Appends the segments of the polyline `pts` to `out`, and for a closed one (`closed`) the segment
// back to its start; a single point gives none.
void append_polyline_segments(std::span<const Point> pts, bool closed, std::vector<LineSegment>& out);

// Appends the segments of `path` (pixel space; curves flattened within `tolerance`) to `out`: its
// closed contours with their closing segments, and a contour of one point as nothing, as stroke()
// draws them.
void append_segments(const Path& path, double tolerance, Polyline& flat, std::vector<LineSegment>& out);

// Builds the pixel-space paths of one feature.
struct PathVisitor final : PieceVisitor {
    Affine m;
    double point_radius = 3;
    // Strokes only: rings and lines cut to this rectangle around the image (clip_to_frame.hpp).
    std::optional<Rect> clip;
    bool fill_only = false;              // rings only filled: their spikes go (ring_spikes.hpp)
    Path fill;                           // polygons + point disks
    Path lines;                          // open polylines, to be stroked
    std::vector<Point> mapped, clipped;  // a ring in pixel space
    // A fill's visitor that also gathers the segments a sampled stroke draws of the rings and point
    // disks (append_segments), so that the feature is projected once for both: the rings as the
    // stroke's visitor would add them (spikes kept, cut to stroke_clip, as lines are too), the
    // disks flattened within disk_tolerance. nullptr: none.
    std::vector<LineSegment>* ring_segments = nullptr;
    std::optional<Rect> stroke_clip;
    double disk_tolerance = 0;
    Polyline flat;
    void ring(std::span<const Point> pts) override;
    void line(std::span<const Point> pts) override;
    void point(Point p) override;

private:
    void map_all(std::span<const Point> pts);  // mapped = pts mapped by m
};

}  // namespace casteljau::map_detail
