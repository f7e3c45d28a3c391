// Internal: the clipping edge builder of the raster stage. It receives the flattener's points
// (flatten_into's sink interface) and hands straight edges, in contour order, to the engine or to
// the edge list of a banded fill, each edge clipped to the shape's box [0, W] x [0, H] when kClip.
//
// Clipping is in double precision before anything becomes a cell coordinate: parts above or below
// the box are dropped, parts left of it are moved onto its left side (only their height matters
// there: they add cover to column 0), parts right of it are dropped (pixels only see edges to their
// left). So coordinates of any finite size are safe and cell coordinates never exceed the box.
// Every contour is closed (fills close contours implicitly). A shape inside its box reaches an
// engine that takes polylines (Engine::push_polyline) a batch of points at a time.
#pragma once

#include <algorithm>
#include <cmath>

#include "casteljau/error.hpp"
#include "casteljau/geometry.hpp"
#include "path/flatten_internal.hpp"
#include "casteljau/limits.hpp"

namespace casteljau::raster {

// The part of edge p -> q inside [0, W] x [0, H] (its part left of the box moved onto x = 0) to out.push.
template <class Out>
void clip_edge(double W, double H, Point p, Point q, Out& out) {
    if (p.y == q.y) {
        // Horizontal: keeps its part in [0, W] (it separates winding regions in its cells).
        if (p.y <= 0 || p.y >= H) return;
        const double xa = std::clamp(p.x, 0.0, W), xb = std::clamp(q.x, 0.0, W);
        if (xa != xb) out.push(xa, p.y, xb, q.y);
        return;
    }
    if (std::max(p.y, q.y) <= 0 || std::min(p.y, q.y) >= H) return;
    auto at_y = [&](double y) { return p.x + (q.x - p.x) * ((y - p.y) / (q.y - p.y)); };
    Point a = p, b = q;
    if (a.y < 0)
        a = {at_y(0), 0};
    else if (a.y > H)
        a = {at_y(H), H};
    if (b.y < 0)
        b = {at_y(0), 0};
    else if (b.y > H)
        b = {at_y(H), H};
    if (a.y == b.y) return;
    if (std::min(a.x, b.x) >= W) return;
    if (std::max(a.x, b.x) <= 0) {
        out.push(0, a.y, 0, b.y);
        return;
    }
    auto at_x = [&](double x) { return a.y + (b.y - a.y) * ((x - a.x) / (b.x - a.x)); };
    // In travel order: [part left of 0, projected], part inside, [part right of W, dropped].
    if (a.x < 0) {
        const double yc = at_x(0);
        out.push(0, a.y, 0, yc);
        a = {0, yc};
    } else if (a.x > W) {
        a = {W, at_x(W)};
    }
    if (b.x < 0) {
        const double yc = at_x(0);
        out.push(a.x, a.y, 0, yc);
        out.push(0, yc, 0, b.y);
    } else if (b.x > W) {
        out.push(a.x, a.y, W, at_x(W));
    } else {
        out.push(a.x, a.y, b.x, b.y);
    }
}

// The control points were checked before flattening, and polynomial curves flatten inside their
// hull; but a conic with an extreme weight can still put a flattened point at NaN or far beyond
// its control points, and the walk must never see one. The sinks below give this to the flattener
// as check_rational, which it calls for every point it makes by halving a conic.
inline void check_conic_point(Point p) {
    constexpr double kFar = 4 * limits::kMaxCoordinate;
    if (!(std::fabs(p.x) <= kFar && std::fabs(p.y) <= kFar)) [[unlikely]]
        throw Error(ErrorKind::InvalidData,
                    "flattening produced a non-finite or out-of-range point (a conic weight out of range?)");
}

// Receives flattened points (flatten_into's sink interface) and hands straight edges to `out`
// (the engine or a banded fill's edge list), clipping them to [0, W] x [0, H] when kClip, else as they are.
template <bool kClip, class Out>
struct EdgeSink {
    Out& out;
    double W = 0, H = 0;
    Point start{}, cur{};
    bool open = false;

    void begin(Point p) {
        end();
        start = cur = p;
        open = true;
    }
    [[gnu::always_inline]] inline void point(Point p) {
        if constexpr (kClip)
            add_clipped(cur, p);
        else
            push(cur.x, cur.y, p.x, p.y);
        cur = p;
    }
    void mark_closed() {}
    void end() {
        if (!open) return;
        point(start);  // fills close every contour
        out.contour_end();
        open = false;
    }

    [[gnu::always_inline]] inline void push(double x0, double y0, double x1, double y1) { out.push(x0, y0, x1, y1); }

    void add_clipped(Point p, Point q) { clip_edge(W, H, p, q, out); }

    static void check_rational(Point p) { check_conic_point(p); }
};

// Receives the flattened points of a shape inside its box and hands them to `out` a polyline at a
// time (out.push_polyline(xy, n): the edges between n consecutive points, x and y interleaved), so
// that the engine's per-edge work runs in one loop instead of one call per edge.
template <class Out>
struct PolylineSink {
    static constexpr std::size_t kBatch = 64;  // points per call
    Out& out;
    double start_x = 0, start_y = 0;
    double xy[2 * kBatch];  // not initialised: only [0, 2 n) is read
    std::size_t n = 0;
    bool open = false;

    explicit PolylineSink(Out& o) : out(o) {}
    void begin(Point p) {
        end();
        start_x = xy[0] = p.x;
        start_y = xy[1] = p.y;
        n = 1;
        open = true;
    }
    [[gnu::always_inline]] inline void point(Point p) {
        xy[2 * n] = p.x;
        xy[2 * n + 1] = p.y;
        if (++n == kBatch) [[unlikely]] {
            out.push_polyline(xy, n);
            xy[0] = xy[2 * n - 2];
            xy[1] = xy[2 * n - 1];
            n = 1;
        }
    }
    void mark_closed() {}
    void end() {
        if (!open) return;
        point({start_x, start_y});  // fills close every contour
        if (n > 1) out.push_polyline(xy, n);
        out.contour_end();
        n = 0;
        open = false;
    }
    static void check_rational(Point p) { check_conic_point(p); }
};

// Flattens `path` mapped by `local` (path -> the box's cell coordinates) into `out`. `inside`: the
// transformed control points lie inside the box, so no clipping is needed.
template <class Out>
void build_edges(const Path& path, const Affine& local, double tolerance, bool inside, int w, int h, Out& out) {
    if (inside) {
        if constexpr (requires(const double* xy) { out.push_polyline(xy, std::size_t{2}); }) {
            PolylineSink<Out> ps(out);
            flatten_into(path, local, tolerance, nullptr, ps, true);
            ps.end();
        } else {
            EdgeSink<false, Out> es{out};
            flatten_into(path, local, tolerance, nullptr, es, true);
            es.end();
        }
    } else {
        // Curves wholly outside the box (with a one-cell margin) become chords.
        const Rect cull{-1.0, -1.0, w + 1.0, h + 1.0};
        EdgeSink<true, Out> es{out, static_cast<double>(w), static_cast<double>(h)};
        flatten_into(path, local, tolerance, &cull, es, true);
        es.end();
    }
}

}  // namespace casteljau::raster
