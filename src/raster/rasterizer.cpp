// Raster stage, driver: clip edges to the target, split the shape's bounds into strips, accumulate,
// recompute marked cells exactly, and hand rows of 8-bit coverage to the sink.
//
// Clipping (double precision, before anything becomes a cell coordinate): edges above or below the
// target are dropped, the parts of edges left of it are moved onto its left side (only their height
// matters there: they add cover to column 0), and the parts right of it are dropped (pixels only
// see edges to their left). So coordinates of any finite size are safe; cell coordinates are at
// most the target's size.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <string>

#include "casteljau/error.hpp"
#include "path/flatten_internal.hpp"
#include "raster/raster_internal.hpp"

namespace casteljau {

using raster::Edge;

namespace {

// Upper bound on cells in one strip buffer: 2^18 cells = 1 MiB of float + 1 MiB of tags.
constexpr std::size_t kMaxStripCells = std::size_t(1) << 18;

struct EdgeBuilder {
    std::vector<Edge>& edges;
    double W, H;
    bool clipped_right = false;
    std::size_t contour_first = 0;  // index of the contour's first edge

    void push(double x0, double y0, double x1, double y1) {
        if (y0 == y1 && x0 == x1) return;
        Edge e{x0, y0, x1, y1, -1, -1};
        if (edges.size() > contour_first) {
            Edge& last = edges.back();
            if (last.x1 == x0 && last.y1 == y0) {
                e.prev = static_cast<std::int32_t>(edges.size() - 1);
                last.next = static_cast<std::int32_t>(edges.size());
            }
        }
        if (edges.size() >= limits::kMaxFlattenedSegments)
            throw Error(ErrorKind::Limit, "path too complex: more than " +
                                              std::to_string(limits::kMaxFlattenedSegments) + " edges");
        edges.push_back(e);
    }

    // Clips the edge p -> q against [0, W] x [0, H] as described at the top of this file.
    void add(Point p, Point q) {
        if (p.y == q.y) {
            // Horizontal: no coverage of its own, but it separates winding regions inside the
            // cells it crosses, so it takes part in the multi-edge test. Keep its part in [0, W].
            if (p.y <= 0 || p.y >= H) return;
            const double xa = std::clamp(p.x, 0.0, W), xb = std::clamp(q.x, 0.0, W);
            if (xa != xb) push(xa, p.y, xb, q.y);
            return;
        }
        if (std::max(p.y, q.y) <= 0 || std::min(p.y, q.y) >= H) return;
        // Clip in y (keep the direction of travel).
        auto at_y = [&](double y) { return p.x + (q.x - p.x) * ((y - p.y) / (q.y - p.y)); };
        Point a = p, b = q;
        if (a.y < 0) a = {at_y(0), 0};
        else if (a.y > H) a = {at_y(H), H};
        if (b.y < 0) b = {at_y(0), 0};
        else if (b.y > H) b = {at_y(H), H};
        if (a.y == b.y) return;
        if (std::min(a.x, b.x) >= W) {
            clipped_right = true;
            return;
        }
        if (std::max(a.x, b.x) <= 0) {
            push(0, a.y, 0, b.y);
            return;
        }
        auto at_x = [&](double x) { return a.y + (b.y - a.y) * ((x - a.x) / (b.x - a.x)); };
        // Pieces in travel order: possibly [left part projected], middle, [right part dropped].
        if (a.x < 0) {
            const double yc = at_x(0);
            push(0, a.y, 0, yc);
            a = {0, yc};
        }
        Point end = b;
        bool right_cut = false;
        if (b.x > W) {
            end = {W, at_x(W)};
            right_cut = true;
        }
        if (end.x < 0) {  // b left of 0 while a was inside: cut at 0 and project the rest
            const double yc = at_x(0);
            if (a.x > W) {  // a right of W: drop the part right of W first
                a = {W, at_x(W)};
                clipped_right = true;
            }
            push(a.x, a.y, 0, yc);
            push(0, yc, 0, b.y);
            return;
        }
        if (a.x > W) {  // travelling leftwards from beyond the right side
            a = {W, at_x(W)};
            clipped_right = true;
        }
        push(a.x, a.y, end.x, end.y);
        if (right_cut) clipped_right = true;
    }

    void close_contour() {
        if (edges.size() > contour_first + 1) {
            Edge& first = edges[contour_first];
            Edge& last = edges.back();
            if (last.x1 == first.x0 && last.y1 == first.y0) {
                last.next = static_cast<std::int32_t>(contour_first);
                first.prev = static_cast<std::int32_t>(edges.size() - 1);
            }
        }
        contour_first = edges.size();
    }
};

class MaskSink final : public SpanSink {
public:
    explicit MaskSink(Mask& m) : mask_(m) {}
    void row(int y, int x, int length, const std::uint8_t* coverage) override {
        const IRect& b = mask_.bounds;
        if (y < b.y0 || y >= b.y1) return;
        const int x0 = std::max(x, b.x0), x1 = std::min(x + length, b.x1);
        if (x1 <= x0) return;
        std::memcpy(&mask_.data[static_cast<std::size_t>(y - b.y0) * b.width() + (x0 - b.x0)], coverage + (x0 - x),
                    static_cast<std::size_t>(x1 - x0));
    }

private:
    Mask& mask_;
};

inline std::uint8_t to_u8(double c) { return static_cast<std::uint8_t>(c * 255.0 + 0.5); }

}  // namespace

struct Rasterizer::Impl {
    Polyline poly;
    std::vector<Edge> edges;
    std::vector<float> acc;
    std::vector<std::uint32_t> tags;
    std::vector<int> row_min, row_max;
    std::vector<std::uint32_t> marked;
    std::vector<std::uint8_t> cov;
    std::vector<raster::RowPiece> pieces;
    raster::ExactScratch scratch;
    std::vector<std::pair<std::uint32_t, std::uint8_t>> patches;
    std::vector<std::uint32_t> order;   // edges sorted by top y (multi-strip shapes)
    std::vector<std::uint32_t> active;  // edges overlapping the current strip

    void fill(const FillOptions& opts, const IRect& clip, SpanSink& sink, RasterStats& stats);
    void run_strip(const FillOptions& opts, raster::Strip& s, const std::uint32_t* ids, std::size_t n,
                   int ox, int oy, SpanSink& sink, RasterStats& stats);
};

Rasterizer::Rasterizer() : impl_(std::make_unique<Impl>()) {}
Rasterizer::~Rasterizer() = default;
Rasterizer::Rasterizer(Rasterizer&&) noexcept = default;
Rasterizer& Rasterizer::operator=(Rasterizer&&) noexcept = default;

static void check_clip(const IRect& clip) {
    if (clip.width() > limits::kMaxCanvasDimension || clip.height() > limits::kMaxCanvasDimension)
        throw Error(ErrorKind::Limit, "raster target exceeds " + std::to_string(limits::kMaxCanvasDimension) +
                                          " pixels per side");
}

void Rasterizer::fill(const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip, SpanSink& sink) {
    stats_ = {};
    check_clip(clip);
    if (clip.empty()) return;
    // Curves wholly outside the target become chords; a one-pixel margin keeps the boundary exact.
    const Rect cull{clip.x0 - 1.0, clip.y0 - 1.0, clip.x1 + 1.0, clip.y1 + 1.0};
    flatten_culled(path, m, opts.tolerance, &cull, impl_->poly);
    impl_->fill(opts, clip, sink, stats_);
}

void Rasterizer::fill(const Polyline& poly, const FillOptions& opts, const IRect& clip, SpanSink& sink) {
    stats_ = {};
    check_clip(clip);
    if (clip.empty()) return;
    for (const Point& p : poly.points)
        if (!p.is_finite()) throw Error(ErrorKind::InvalidData, "polyline has a non-finite coordinate");
    impl_->poly = poly;
    impl_->fill(opts, clip, sink, stats_);
}

void Rasterizer::Impl::fill(const FillOptions& opts, const IRect& clip, SpanSink& sink, RasterStats& stats) {
    edges.clear();
    const double W = clip.width(), H = clip.height();
    EdgeBuilder eb{edges, W, H};
    std::size_t begin = 0;
    const Point origin{static_cast<double>(clip.x0), static_cast<double>(clip.y0)};
    for (std::uint32_t end : poly.contour_ends) {
        if (end - begin >= 2) {
            for (std::size_t i = begin; i < end; ++i) {
                const Point p = poly.points[i] - origin;
                const Point q = poly.points[i + 1 < end ? i + 1 : begin] - origin;
                eb.add(p, q);
            }
        }
        eb.close_contour();
        begin = end;
    }
    if (edges.empty()) return;

    // Pixel bounds of the clipped edges (local to the clip rectangle).
    double minx = INFINITY, maxx = -INFINITY, miny = INFINITY, maxy = -INFINITY;
    for (const Edge& e : edges) {
        minx = std::min({minx, e.x0, e.x1});
        maxx = std::max({maxx, e.x0, e.x1});
        miny = std::min({miny, e.y0, e.y1});
        maxy = std::max({maxy, e.y0, e.y1});
    }
    const int bx0 = std::clamp(static_cast<int>(std::floor(minx)), 0, clip.width());
    int bx1 = std::clamp(static_cast<int>(std::ceil(maxx)), 0, clip.width());
    if (eb.clipped_right) bx1 = clip.width();
    const int by0 = std::clamp(static_cast<int>(std::floor(miny)), 0, clip.height());
    const int by1 = std::clamp(static_cast<int>(std::ceil(maxy)), 0, clip.height());
    const int bw = bx1 - bx0, bh = by1 - by0;
    if (bw <= 0 || bh <= 0) return;
    for (Edge& e : edges) {
        e.x0 -= bx0; e.x1 -= bx0;
        e.y0 -= by0; e.y1 -= by0;
    }
    stats.segments = edges.size();

    raster::Strip s;
    s.width = bw;
    s.stride = static_cast<std::size_t>(bw) + 2;
    const int rows_per_strip = static_cast<int>(std::max<std::size_t>(1, kMaxStripCells / s.stride));
    const int strip_rows = std::min(bh, rows_per_strip);
    const std::size_t cells = s.stride * static_cast<std::size_t>(strip_rows);
    if (acc.size() < cells) acc.assign(cells, 0.0f);
    if (opts.exact_overlaps && tags.size() < cells) tags.assign(cells, 0u);
    if (row_min.size() < static_cast<std::size_t>(strip_rows)) {
        row_min.resize(static_cast<std::size_t>(strip_rows));
        row_max.resize(static_cast<std::size_t>(strip_rows));
    }
    if (cov.size() < s.stride) cov.resize(s.stride);
    s.acc = acc.data();
    s.tags = opts.exact_overlaps ? tags.data() : nullptr;
    s.row_min = row_min.data();
    s.row_max = row_max.data();
    s.marked = &marked;
    const int ox = clip.x0 + bx0, oy = clip.y0 + by0;

    if (bh <= rows_per_strip) {
        s.y0 = 0;
        s.rows = bh;
        order.resize(edges.size());
        for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        run_strip(opts, s, order.data(), order.size(), ox, oy, sink, stats);
        return;
    }
    // Several strips: sweep edges sorted by their top.
    order.resize(edges.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    auto top = [&](std::uint32_t i) { return std::min(edges[i].y0, edges[i].y1); };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return top(a) < top(b); });
    std::size_t next = 0;
    active.clear();
    for (int y = 0; y < bh; y += rows_per_strip) {
        s.y0 = y;
        s.rows = std::min(rows_per_strip, bh - y);
        const double strip_bottom = y + s.rows;
        // Drop edges that ended above this strip, add those starting in it.
        active.erase(std::remove_if(active.begin(), active.end(),
                                    [&](std::uint32_t i) { return std::max(edges[i].y0, edges[i].y1) <= y; }),
                     active.end());
        while (next < order.size() && top(order[next]) < strip_bottom) active.push_back(order[next++]);
        if (active.empty()) continue;
        run_strip(opts, s, active.data(), active.size(), ox, oy, sink, stats);
    }
}

void Rasterizer::Impl::run_strip(const FillOptions& opts, raster::Strip& s, const std::uint32_t* ids, std::size_t n,
                                 int ox, int oy, SpanSink& sink, RasterStats& stats) {
    ++stats.strips;
    for (int r = 0; r < s.rows; ++r) {
        s.row_min[r] = INT_MAX;
        s.row_max[r] = -1;
    }
    marked.clear();
    for (std::size_t i = 0; i < n; ++i) raster::accumulate_edge(edges[ids[i]], ids[i], s);

    // Exact recomputation of marked cells, row by row.
    patches.clear();
    if (!marked.empty()) {
        std::sort(marked.begin(), marked.end());
        stats.exact_cells += marked.size();
        std::size_t mi = 0;
        while (mi < marked.size()) {
            const int local = static_cast<int>(marked[mi] / s.stride);
            const double ry = s.y0 + local;
            pieces.clear();
            for (std::size_t i = 0; i < n; ++i) {
                const Edge& e = edges[ids[i]];
                double x0 = e.x0, y0 = e.y0, x1 = e.x1, y1 = e.y1;
                int dir = 1;
                if (y0 == y1) continue;  // horizontal: crossed by no horizontal line, no area
                if (y0 > y1) { std::swap(x0, x1); std::swap(y0, y1); dir = -1; }
                if (y1 <= ry || y0 >= ry + 1) continue;
                const double k = (x1 - x0) / (y1 - y0);
                const double ya = std::max(y0, ry), yb = std::min(y1, ry + 1);
                const double xlo = std::min(x0, x1), xhi = std::max(x0, x1);
                pieces.push_back({std::clamp(x0 + (ya - y0) * k, xlo, xhi), ya,
                                  std::clamp(x0 + (yb - y0) * k, xlo, xhi), yb, dir});
            }
            for (; mi < marked.size() && static_cast<int>(marked[mi] / s.stride) == local; ++mi) {
                const int col = static_cast<int>(marked[mi] % s.stride);
                if (col >= s.width) continue;  // spill cells are never shown
                const double c = raster::exact_cell_coverage(pieces, col, ry, opts.rule, scratch);
                patches.push_back({marked[mi], to_u8(c)});
            }
        }
    }

    // Rows: prefix sum + fill rule, patches, delivery; clear what was touched.
    std::size_t pi = 0;
    for (int r = 0; r < s.rows; ++r) {
        if (s.row_max[r] < 0) continue;
        float* acc_row = s.acc + static_cast<std::size_t>(r) * s.stride;
        const int from = s.row_min[r];
        const int last = s.row_max[r];  // last acc index written (may be a spill cell)
        const int to = std::min(last + 1, s.width);
        const float sum = raster::accumulate_row(acc_row, cov.data(), from, to, 0.0f, opts.rule);
        // Beyond the last touched cell the coverage is constant.
        int end = to;
        if (to < s.width) {
            const std::uint8_t tail = raster::coverage_u8(sum, opts.rule);
            if (tail != 0) {
                std::memset(cov.data() + to, tail, static_cast<std::size_t>(s.width - to));
                end = s.width;
            }
        }
        for (int k = s.width; k <= last; ++k) acc_row[k] = 0.0f;  // spill cells
        if (s.tags) {
            std::memset(s.tags + static_cast<std::size_t>(r) * s.stride + from, 0,
                        sizeof(std::uint32_t) * static_cast<std::size_t>(last - from + 1));
        }
        const std::size_t row_base = static_cast<std::size_t>(r) * s.stride;
        while (pi < patches.size() && patches[pi].first < row_base + s.stride) {
            const int col = static_cast<int>(patches[pi].first - row_base);
            cov[static_cast<std::size_t>(col)] = patches[pi].second;  // marked cells lie in [from, to)
            ++pi;
        }
        if (end > from) sink.row(oy + s.y0 + r, ox + from, end - from, cov.data() + from);
    }
}

Mask Rasterizer::fill_mask(const Path& path, const Affine& m, const FillOptions& opts) {
    if (!m.is_finite() || !path.is_finite())
        throw Error(ErrorKind::InvalidData, "path or transform has a non-finite value");
    const Rect b = transform_bounds(m, path.control_bounds());
    const double lim = limits::kMaxCanvasDimension;
    IRect r{static_cast<int>(std::floor(std::clamp(b.x0, -lim, lim))), static_cast<int>(std::floor(std::clamp(b.y0, -lim, lim))),
            static_cast<int>(std::ceil(std::clamp(b.x1, -lim, lim))), static_cast<int>(std::ceil(std::clamp(b.y1, -lim, lim)))};
    if (r.x1 - r.x0 > limits::kMaxCanvasDimension) r.x1 = r.x0 + limits::kMaxCanvasDimension;
    if (r.y1 - r.y0 > limits::kMaxCanvasDimension) r.y1 = r.y0 + limits::kMaxCanvasDimension;
    return fill_mask(path, m, opts, r);
}

Mask Rasterizer::fill_mask(const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip) {
    Mask mask;
    mask.bounds = clip;
    if (clip.empty()) {
        mask.bounds = {};
        return mask;
    }
    mask.data.assign(static_cast<std::size_t>(clip.width()) * static_cast<std::size_t>(clip.height()), 0);
    MaskSink sink(mask);
    fill(path, m, opts, clip, sink);
    return mask;
}

std::uint8_t Mask::at(int x, int y) const {
    if (x < bounds.x0 || x >= bounds.x1 || y < bounds.y0 || y >= bounds.y1) return 0;
    return data[static_cast<std::size_t>(y - bounds.y0) * bounds.width() + (x - bounds.x0)];
}

}  // namespace casteljau
