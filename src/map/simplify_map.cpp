// Map stage: simplifying a MapData for one output resolution (src/map/simplify_map.hpp).
#include "map/simplify_map.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>

#include "map/simplify_polyline.hpp"
#include "core/for_each_index.hpp"

namespace casteljau::map_detail {

namespace {

// Widens `bounds` by `q` (inline: called once per projected position).
void widen(Rect& bounds, Point q) {
    bounds =
        Rect{std::min(bounds.x0, q.x), std::min(bounds.y0, q.y), std::max(bounds.x1, q.x), std::max(bounds.y1, q.y)};
}

// Whether a step of the line (or ring, `closed`) spans more than 180 degrees of longitude: the
// renderer draws such a step across the antimeridian.
bool crosses_antimeridian(std::span<const Point> line, bool closed) {
    for (std::size_t k = 1; k < line.size(); ++k)
        if (std::fabs(line[k].x - line[k - 1].x) > 180) return true;
    return closed && line.size() > 1 && std::fabs(line.front().x - line.back().x) > 180;
}

bool less(Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// One worker's projection and scratch buffers.
class LineSimplifier {
public:
    LineSimplifier(const MapProjection& proj, const Affine& to_pixel, double tolerance)
        : proj_(proj.clone()),
          scale_{to_pixel.a, to_pixel.b, to_pixel.c, to_pixel.d, 0, 0},
          tolerance_(tolerance),
          max_degrees_(proj_.preserves_graticule_lines() ? INFINITY : kDensifyDegrees) {}

    // Appends to `out` the positions of the ring or line `pts` that stay (a ring closed again by
    // its first position); `node` holds the node flags of pts. Widens `bounds` by the projected
    // positions; returns true when a step crosses the antimeridian.
    bool simplify(std::span<const Point> pts, std::span<const std::uint8_t> node, bool closed, std::vector<Point>& out,
                  Rect& bounds) {
        distinct_positions(pts, closed, distinct_);
        const std::size_t m = distinct_.size();
        lonlat_.resize(m);
        pixel_.resize(m);
        locked_.assign(m, 0);
        unprojected_.assign(m, 0);
        keep_.assign(m, 0);
        for (std::size_t k = 0; k < m; ++k) {
            const Point p = pts[distinct_[k]];
            lonlat_[k] = p;
            Point q;
            if (proj_.project(p, q)) {
                pixel_[k] = scale_.apply(q);
                widen(bounds, q);
            } else {
                locked_[k] = unprojected_[k] = 1;  // dropped by the renderer: its runs are kept whole
            }
            locked_[k] |= node[distinct_[k]];
        }
        const bool crosses = crosses_antimeridian(lonlat_, closed);
        if (m < 3)
            keep_.assign(m, 1);
        else if (closed)
            simplify_ring();
        else
            simplify_open();
        for (std::size_t k = 0; k < m; ++k)
            if (keep_[k]) out.push_back(lonlat_[k]);
        if (closed && m > 0) out.push_back(lonlat_[0]);
        return crosses;
    }

    // Widens `bounds` by the projected points.
    void bound_points(std::span<const Point> pts, Rect& bounds) const {
        Point q;
        for (Point p : pts)
            if (proj_.project(p, q)) widen(bounds, q);
    }

private:
    void simplify_ring() {
        const std::size_t m = lonlat_.size();
        std::size_t first = m;
        for (std::size_t k = 0; k < m && first == m; ++k)
            if (locked_[k]) first = k;
        if (first == m) {
            // No node: the ring is one closed run from its least position (the same start in
            // every ring that holds the same loop).
            first = 0;
            for (std::size_t k = 1; k < m; ++k)
                if (less(lonlat_[k], lonlat_[first])) first = k;
            run(first, first + m);
            return;
        }
        // Runs from each node to the next, round the ring (k counts on past m, i wraps).
        const std::size_t stop = first + m;
        for (std::size_t k = first + 1, i = first + 1 == m ? 0 : first + 1, from = first; k <= stop;
             ++k, i = i + 1 == m ? 0 : i + 1)
            if (locked_[i]) {
                run(from, k);
                from = k;
            }
    }

    void simplify_open() {
        std::size_t first = 0;
        for (std::size_t k = 1; k < lonlat_.size(); ++k)
            if (locked_[k]) {
                run(first, k);
                first = k;
            }
    }

    // Simplifies the run of ring positions first .. last (indices taken modulo the size), in its
    // canonical direction.
    void run(std::size_t first, std::size_t last) {
        const std::size_t m = lonlat_.size();
        const std::size_t n = last - first + 1;
        const std::size_t f = first % m, l = last % m;
        // The ring positions of the run in order (reversed: from its last), stepping round the ring.
        auto for_each_position = [&](bool reversed, auto&& each) {
            std::size_t k = reversed ? l : f;
            for (std::size_t i = 0; i < n; ++i) {
                each(i, k);
                k = reversed ? (k == 0 ? m - 1 : k - 1) : (k + 1 == m ? 0 : k + 1);
            }
        };
        if (unprojected_[f] || unprojected_[l]) {
            for_each_position(false, [&](std::size_t, std::size_t k) { keep_[k] = 1; });
            return;
        }
        const Point a = lonlat_[f], b = lonlat_[l];
        bool reversed = less(b, a);
        if (a == b && n > 2) reversed = less(lonlat_[(first + n - 2) % m], lonlat_[(first + 1) % m]);
        // A step of more than 180 degrees of longitude would be read as crossing the antimeridian;
        // a projection that bends lon/lat steps draws a step longer than kDensifyDegrees as a curve.
        auto too_long = [this](const Point* lonlat) {
            return [this, lonlat](std::size_t i, std::size_t j) {
                const double dx = std::fabs(lonlat[j].x - lonlat[i].x);
                return dx > 180 || dx > max_degrees_ || std::fabs(lonlat[j].y - lonlat[i].y) > max_degrees_;
            };
        };
        if (!reversed && f + n <= m) {  // in place: the run's positions lie in order in the ring's
            runs_.simplify(std::span<const Point>(pixel_).subspan(f, n), tolerance_,
                           std::span<std::uint8_t>(keep_).subspan(f, n), too_long(lonlat_.data() + f));
            return;
        }
        run_pixel_.resize(n);
        run_lonlat_.resize(n);
        run_keep_.assign(n, 0);
        for_each_position(reversed, [&](std::size_t i, std::size_t k) {
            run_pixel_[i] = pixel_[k];
            run_lonlat_[i] = lonlat_[k];
        });
        runs_.simplify(run_pixel_, tolerance_, run_keep_, too_long(run_lonlat_.data()));
        for_each_position(reversed, [&](std::size_t i, std::size_t k) { keep_[k] |= run_keep_[i]; });
    }

    MapProjection proj_;
    Affine scale_;  // to_pixel without its translation: the same distances, the same choices in every translated frame
    double tolerance_, max_degrees_;
    RunSimplifier runs_;
    std::vector<std::uint32_t> distinct_;
    std::vector<Point> lonlat_, pixel_, run_lonlat_, run_pixel_;
    std::vector<std::uint8_t> locked_, unprojected_, keep_, run_keep_;
};

Geometry simplify_geometry(const Geometry& g, std::span<const std::uint8_t> node, LineSimplifier& ls, Rect& bounds,
                           bool& crosses) {
    if (g.kind == GeometryKind::Points) {
        ls.bound_points(g.points, bounds);
        return g;
    }
    Geometry out;
    out.kind = g.kind;
    out.polygon_ends = g.polygon_ends;
    out.ring_ends.reserve(g.ring_ends.size());
    std::uint32_t start = 0;
    const std::span<const Point> pts(g.points);
    for (std::uint32_t end : g.ring_ends) {
        crosses = ls.simplify(pts.subspan(start, end - start), node.subspan(start, end - start),
                              g.kind == GeometryKind::Polygons, out.points, bounds) ||
                  crosses;
        out.ring_ends.push_back(static_cast<std::uint32_t>(out.points.size()));
        start = end;
    }
    out.points.shrink_to_fit();
    return out;
}

}  // namespace

SimplifiedMap simplify_map(const MapData& data, const BorderNodes& nodes, const MapProjection& proj,
                           const Affine& to_pixel, double tolerance, int threads) {
    SimplifiedMap r;
    r.features.resize(data.features.size());
    r.bounds.resize(data.features.size());
    std::vector<std::unique_ptr<LineSimplifier>> workers;
    for (int w = 0; w < threads; ++w) workers.push_back(std::make_unique<LineSimplifier>(proj, to_pixel, tolerance));
    parallel::for_each_index(threads, data.features.size(), [&](int w, std::size_t i) {
        const Feature& f = data.features[i];
        LineSimplifier& ls = *workers[static_cast<std::size_t>(w)];
        Rect bounds{INFINITY, INFINITY, -INFINITY, -INFINITY};
        bool crosses = false;
        std::size_t base = nodes.feature_start[i];
        r.features[i].reserve(f.geometries.size());
        for (const Geometry& g : f.geometries) {
            const std::span<const std::uint8_t> node =
                std::span<const std::uint8_t>(nodes.node).subspan(base, g.points.size());
            r.features[i].push_back(simplify_geometry(g, node, ls, bounds, crosses));
            base += g.points.size();
        }
        r.bounds[i] = crosses ? Rect{-INFINITY, -INFINITY, INFINITY, INFINITY} : bounds;
    });
    for (const auto& f : r.features)
        for (const Geometry& g : f) r.positions += g.points.size();
    return r;
}

SimplifiedMap bounds_only(const MapData& data, const MapProjection& proj, int threads) {
    SimplifiedMap r;
    r.bounds.resize(data.features.size());
    std::vector<Rect> extents(data.features.size());
    std::vector<MapProjection> projections;
    for (int w = 0; w < threads; ++w) projections.push_back(proj.clone());
    parallel::for_each_index(threads, data.features.size(), [&](int w, std::size_t i) {
        const MapProjection& p = projections[static_cast<std::size_t>(w)];
        Rect bounds{INFINITY, INFINITY, -INFINITY, -INFINITY};
        bool crosses = false;
        for (const Geometry& g : data.features[i].geometries) {
            std::uint32_t start = 0;
            const std::span<const Point> pts(g.points);
            if (g.kind != GeometryKind::Points)
                for (std::uint32_t end : g.ring_ends) {
                    crosses = crosses ||
                              crosses_antimeridian(pts.subspan(start, end - start), g.kind == GeometryKind::Polygons);
                    start = end;
                }
            Point q;
            for (Point pt : g.points)
                if (p.project(pt, q)) widen(bounds, q);
        }
        extents[i] = bounds;
        r.bounds[i] = crosses ? Rect{-INFINITY, -INFINITY, INFINITY, INFINITY} : bounds;
    });
    for (const Feature& f : data.features)
        for (const Geometry& g : f.geometries) r.positions += g.points.size();
    for (const Rect& e : extents) r.extent = r.extent.united(e);
    return r;
}

namespace {

bool dense_enough(std::size_t positions, const Rect& extent, const Affine& to_pixel) {
    if (!(extent.x0 <= extent.x1) || !(extent.y0 <= extent.y1)) return false;  // nothing projected
    const double pixels = (extent.x1 - extent.x0) * (extent.y1 - extent.y0) *
                          std::fabs(to_pixel.a * to_pixel.d - to_pixel.b * to_pixel.c);
    return static_cast<double>(positions) > kSimplifyDensity * std::max(pixels, 1.0);
}

}  // namespace

bool worth_simplifying(const SimplifiedMap& b, const MapProjection& proj, const Affine& to_pixel) {
    // A projection that bends lon/lat steps needs the simplifier's densifying bound: always.
    if (!proj.preserves_graticule_lines()) return true;
    return dense_enough(b.positions, b.extent, to_pixel);
}

bool worth_simplifying(const MapData& data, const MapProjection& proj, const Affine& to_pixel) {
    if (!proj.preserves_graticule_lines()) return true;
    const Rect ll = data.bounds();
    if (!(ll.x0 <= ll.x1) || !(ll.y0 <= ll.y1) || data.position_count() == 0) return false;
    Point lo, hi;
    if (!proj.project({ll.x0, ll.y0}, lo) || !proj.project({ll.x1, ll.y1}, hi)) return true;
    const Rect extent{std::min(lo.x, hi.x), std::min(lo.y, hi.y), std::max(lo.x, hi.x), std::max(lo.y, hi.y)};
    return dense_enough(data.position_count(), extent, to_pixel);
}

}  // namespace casteljau::map_detail
