// Raster stage, driver: flatten straight into edges, split the shape's bounds into strips,
// accumulate, resolve marked cells exactly, and hand rows of 8-bit coverage to the sink.
//
// Two ways in. When the transformed control points of the path lie inside the target (glyphs,
// most shapes) the flattener's points go straight into edges in coordinates local to the shape's
// pixel bounds, with no clipping. Otherwise every edge is clipped in double precision before it
// becomes a cell coordinate: edges above or below the target are dropped, the parts of edges left
// of it are moved onto its left side (only their height matters there: they add cover to column
// 0), and the parts right of it are dropped (pixels only see edges to their left). So coordinates
// of any finite size are safe and cell coordinates never exceed the target's size.
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <string>

#include "casteljau/error.hpp"
#include "path/flatten_internal.hpp"
#include "raster/direct.hpp"
#include "raster/raster_internal.hpp"

namespace casteljau {

using raster::Edge;

namespace {

// Upper bound on cells in one strip buffer: 2^18 cells = 2 MiB of accumulators + 2 MiB of tags.
constexpr std::size_t kMaxStripCells = std::size_t(1) << 18;

// The edge list of the strip path: edges linked along their contour (prev/next).
struct EdgeList {
    std::vector<Edge>& edges;
    std::size_t contour_first = 0;

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
    void contour_end() {
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

// Receives flattened points (flatten_into's sink interface) and hands straight edges to `out`
// (EdgeList or raster::Direct), clipping them to [0, W] x [0, H] when kClip, else as they are.
template <bool kClip, class Out>
struct EdgeSink {
    Out& out;
    double W = 0, H = 0;
    bool clipped_right = false;
    Point start{}, cur{};
    bool open = false;

    void begin(Point p) {
        end();
        start = cur = p;
        open = true;
    }
    [[gnu::always_inline]] inline void point(Point p) {
        if constexpr (kClip) add_clipped(cur, p);
        else push(cur.x, cur.y, p.x, p.y);
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

    void add_clipped(Point p, Point q) {
        if (p.y == q.y) {
            // Horizontal: keeps its part in [0, W] (it separates winding regions in its cells).
            if (p.y <= 0 || p.y >= H) return;
            const double xa = std::clamp(p.x, 0.0, W), xb = std::clamp(q.x, 0.0, W);
            if (xa != xb) push(xa, p.y, xb, q.y);
            return;
        }
        if (std::max(p.y, q.y) <= 0 || std::min(p.y, q.y) >= H) return;
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
        // In travel order: [part left of 0, projected], part inside, [part right of W, dropped].
        if (a.x < 0) {
            const double yc = at_x(0);
            push(0, a.y, 0, yc);
            a = {0, yc};
        } else if (a.x > W) {
            a = {W, at_x(W)};
            clipped_right = true;
        }
        if (b.x < 0) {
            const double yc = at_x(0);
            push(a.x, a.y, 0, yc);
            push(0, yc, 0, b.y);
        } else if (b.x > W) {
            push(a.x, a.y, W, at_x(W));
            clipped_right = true;
        } else {
            push(a.x, a.y, b.x, b.y);
        }
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

void check_clip(const IRect& clip) {
    if (clip.width() > limits::kMaxCanvasDimension || clip.height() > limits::kMaxCanvasDimension)
        throw Error(ErrorKind::Limit, "raster target exceeds " + std::to_string(limits::kMaxCanvasDimension) +
                                          " pixels per side");
}

// Transformed control-point bounds; throws for non-finite input (flatten's checks).
Rect transformed_bounds(const Path& path, const Affine& m, double tolerance) {
    return check_flatten_input(path, m, tolerance);
}

}  // namespace

struct Rasterizer::Impl {
    std::vector<Edge> edges;
    std::vector<double> acc;
    std::vector<std::uint64_t> tags;
    std::vector<int> row_min, row_max;
    std::vector<std::uint32_t> marked;
    std::vector<raster::CellEdge> log;
    std::vector<std::uint8_t> cov;
    raster::ExactScratch scratch;
    std::vector<std::pair<std::uint32_t, std::uint8_t>> patches;
    std::vector<std::uint32_t> order;   // edges sorted by top y (multi-strip shapes)
    std::vector<std::uint32_t> active;  // edges overlapping the current strip
    raster::Direct direct;              // shapes whose clipped bounds fit one buffer

    // Rasterizes `edges` (local to the bounds at (ox, oy), bw x bh pixels).
    void run(const FillOptions& opts, int ox, int oy, int bw, int bh, SpanSink& sink, RasterStats& stats);
    void run_strip(const FillOptions& opts, raster::Strip& s, const std::uint32_t* ids, std::size_t n, int ox, int oy,
                   SpanSink& sink, RasterStats& stats);
    void resolve_row(const FillOptions& opts, raster::Strip& s, int r, std::size_t& mi, std::size_t& li);
};

Rasterizer::Rasterizer() : impl_(std::make_unique<Impl>()) {}
Rasterizer::~Rasterizer() = default;
Rasterizer::Rasterizer(Rasterizer&&) noexcept = default;
Rasterizer& Rasterizer::operator=(Rasterizer&&) noexcept = default;

void Rasterizer::fill(const Path& path, const Affine& m, const FillOptions& options, const IRect& clip, SpanSink& sink) {
    stats_ = {};
    check_clip(clip);
    if (clip.empty() || path.empty()) return;
    const Rect b = transformed_bounds(path, m, options.tolerance);
    // The shape's bounds inside the target; when that box fits one buffer, the direct path.
    const double fx0 = std::floor(std::max(b.x0, static_cast<double>(clip.x0)));
    const double fy0 = std::floor(std::max(b.y0, static_cast<double>(clip.y0)));
    const double fx1 = std::ceil(std::min(b.x1, static_cast<double>(clip.x1)));
    const double fy1 = std::ceil(std::min(b.y1, static_cast<double>(clip.y1)));
    if (!(fx1 > fx0 && fy1 > fy0)) return;  // nothing of the shape inside the target
    // Exactness is decided before rasterizing, once for the shape: one the caller proved simple
    // (classify_topology, cached per outline) is accumulated plainly, exact for it; any other takes
    // the per-cell overlap check. An unknown topology is not classified here: classifying costs
    // about 3 us per glyph-sized outline (BENCHMARKS.md), more than the per-cell check of the
    // same shape, so it pays only when its verdict is reused.
    FillOptions opts = options;
    if (opts.exact_overlaps) {
        stats_.topology = opts.topology;
        opts.exact_overlaps = opts.topology != Topology::Simple;
    }
    const bool inside = b.x0 >= clip.x0 && b.y0 >= clip.y0 && b.x1 <= clip.x1 && b.y1 <= clip.y1;
    if ((fx1 - fx0) * (fy1 - fy0) <= static_cast<double>(kMaxStripCells)) {
        const int ox = static_cast<int>(fx0), oy = static_cast<int>(fy0);
        const int bw = static_cast<int>(fx1) - ox, bh = static_cast<int>(fy1) - oy;
        raster::Direct& d = impl_->direct;
        d.begin(bw, bh, opts.exact_overlaps, options.exact_overlaps);
        const Affine local = Affine::translate(-ox, -oy) * m;
        if (inside) {
            EdgeSink<false, raster::Direct> es{d};
            flatten_into(path, local, opts.tolerance, nullptr, es, true);
            es.end();
        } else {
            // Clipped to the box: what lies left of it only adds cover to its first column.
            const Rect cull{-1.0, -1.0, bw + 1.0, bh + 1.0};
            EdgeSink<true, raster::Direct> es{d, static_cast<double>(bw), static_cast<double>(bh)};
            flatten_into(path, local, opts.tolerance, &cull, es, true);
            es.end();
        }
        d.finish(opts.rule, ox, oy, sink, stats_);
        return;
    }
    auto& edges = impl_->edges;
    edges.clear();
    EdgeList list{edges};
    if (inside) {
        // Inside the target: no clipping; edges local to the control bounds.
        const int ox = static_cast<int>(std::floor(b.x0)), oy = static_cast<int>(std::floor(b.y0));
        const int bw = std::max(1, static_cast<int>(std::ceil(b.x1)) - ox);
        const int bh = std::max(1, static_cast<int>(std::ceil(b.y1)) - oy);
        edges.reserve(path.points().size() * 4);
        EdgeSink<false, EdgeList> es{list};
        flatten_into(path, Affine::translate(-ox, -oy) * m, opts.tolerance, nullptr, es, true);
        es.end();
        impl_->run(opts, ox, oy, std::min(bw, clip.x1 - ox), std::min(bh, clip.y1 - oy), sink, stats_);
        return;
    }
    // Partly or wholly outside: clip. Curves wholly outside (with a one-pixel margin) become chords.
    // The flattener sees points relative to the clip's origin, so the cull box is too.
    const Rect cull{-1.0, -1.0, clip.width() + 1.0, clip.height() + 1.0};
    EdgeSink<true, EdgeList> es{list, static_cast<double>(clip.width()), static_cast<double>(clip.height())};
    flatten_into(path, Affine::translate(-clip.x0, -clip.y0) * m, opts.tolerance, &cull, es, true);
    es.end();
    if (edges.empty()) return;
    double minx = INFINITY, maxx = -INFINITY, miny = INFINITY, maxy = -INFINITY;
    for (const Edge& e : edges) {
        minx = std::min({minx, e.x0, e.x1});
        maxx = std::max({maxx, e.x0, e.x1});
        miny = std::min({miny, e.y0, e.y1});
        maxy = std::max({maxy, e.y0, e.y1});
    }
    const int bx0 = std::clamp(static_cast<int>(std::floor(minx)), 0, clip.width());
    int bx1 = std::clamp(static_cast<int>(std::ceil(maxx)), 0, clip.width());
    if (es.clipped_right) bx1 = clip.width();  // right of every edge the coverage may stay constant
    const int by0 = std::clamp(static_cast<int>(std::floor(miny)), 0, clip.height());
    const int by1 = std::clamp(static_cast<int>(std::ceil(maxy)), 0, clip.height());
    if (bx1 <= bx0 || by1 <= by0) return;
    for (Edge& e : edges) {
        e.x0 -= bx0; e.x1 -= bx0;
        e.y0 -= by0; e.y1 -= by0;
    }
    impl_->run(opts, clip.x0 + bx0, clip.y0 + by0, bx1 - bx0, by1 - by0, sink, stats_);
}

void Rasterizer::fill(const Polyline& poly, const FillOptions& opts, const IRect& clip, SpanSink& sink) {
    Path p;
    std::size_t begin = 0;
    for (std::uint32_t end : poly.contour_ends) {
        if (end > begin) {
            p.move_to(poly.points[begin]);
            for (std::size_t i = begin + 1; i < end; ++i) p.line_to(poly.points[i]);
            p.close();
        }
        begin = end;
    }
    fill(p, Affine{}, opts, clip, sink);
}

void Rasterizer::Impl::run(const FillOptions& opts, int ox, int oy, int bw, int bh, SpanSink& sink, RasterStats& stats) {
    if (edges.empty() || bw <= 0 || bh <= 0) return;
    stats.segments = edges.size();
    raster::Strip s;
    s.width = bw;
    s.stride = static_cast<std::size_t>(bw) + 2;
    const int rows_per_strip = static_cast<int>(std::max<std::size_t>(1, kMaxStripCells / s.stride));
    const int strip_rows = std::min(bh, rows_per_strip);
    const std::size_t cells = s.stride * static_cast<std::size_t>(strip_rows);
    if (acc.size() < cells) acc.assign(cells, 0.0);
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
    s.edges = edges.data();
    s.marked = &marked;
    s.log = &log;

    if (bh <= rows_per_strip) {
        s.y0 = 0;
        s.rows = bh;
        run_strip(opts, s, nullptr, edges.size(), ox, oy, sink, stats);
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
        active.erase(std::remove_if(active.begin(), active.end(),
                                    [&](std::uint32_t i) { return std::max(edges[i].y0, edges[i].y1) < y; }),
                     active.end());
        while (next < order.size() && top(order[next]) < strip_bottom) active.push_back(order[next++]);
        if (active.empty()) continue;
        run_strip(opts, s, active.data(), active.size(), ox, oy, sink, stats);
    }
}

void Rasterizer::Impl::resolve_row(const FillOptions& opts, raster::Strip& s, int r, std::size_t& mi, std::size_t& li) {
    // Marked cells of row r: their accumulated integrals (prefix sums), then exact coverage.
    const std::size_t row_base = static_cast<std::size_t>(r) * s.stride;
    const double* acc_row = s.acc + row_base;
    double prefix = 0;
    int pos = s.row_min[r];
    while (mi < marked.size() && marked[mi] < row_base + s.stride) {
        const std::uint32_t cell = marked[mi];
        const int col = static_cast<int>(cell - row_base);
        for (; pos <= col; ++pos) prefix += acc_row[pos];
        auto& ids = scratch.ids;
        ids.clear();
        while (li < log.size() && log[li].cell < cell) ++li;
        for (; li < log.size() && log[li].cell == cell; ++li) {
            const std::uint32_t id = log[li].edge;
            if (!ids.empty() && ids.back() == id) continue;
            ids.push_back(id);
        }
        if (col < s.width)
            patches.push_back({cell, raster::exact_cell_u8(edges.data(), ids, col, s.y0 + r, prefix, opts.rule, scratch)});
        ++mi;
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
    log.clear();
    if (ids) {
        for (std::size_t i = 0; i < n; ++i) raster::accumulate_edge(edges[ids[i]], ids[i], s);
    } else {
        for (std::uint32_t i = 0; i < n; ++i) raster::accumulate_edge(edges[i], i, s);
    }
    if (!marked.empty()) {
        std::sort(marked.begin(), marked.end());
        std::sort(log.begin(), log.end());
        stats.exact_cells += marked.size();
    }
    std::size_t mi = 0, li = 0;
    for (int r = 0; r < s.rows; ++r) {
        if (s.row_max[r] < 0) continue;
        const std::size_t row_base = static_cast<std::size_t>(r) * s.stride;
        patches.clear();
        if (mi < marked.size() && marked[mi] < row_base + s.stride) resolve_row(opts, s, r, mi, li);
        double* acc_row = s.acc + row_base;
        const int from = s.row_min[r];
        const int last = s.row_max[r];  // last cell written (may be a spill cell)
        const int to = std::min(last + 1, s.width);
        const double sum = raster::accumulate_row(acc_row, cov.data(), from, to, 0.0, opts.rule);
        int end = to;
        if (to < s.width) {  // beyond the last touched cell the coverage is constant
            const std::uint8_t tail = raster::coverage_u8(sum, opts.rule);
            if (tail != 0) {
                std::memset(cov.data() + to, tail, static_cast<std::size_t>(s.width - to));
                end = s.width;
            }
        }
        for (int k = std::max(s.width, from); k <= last; ++k) acc_row[k] = 0.0;  // spill cells
        if (s.tags) std::memset(s.tags + row_base + from, 0, sizeof(std::uint64_t) * static_cast<std::size_t>(last - from + 1));
        for (const auto& p : patches) cov[p.first - row_base] = p.second;
        if (end > from) sink.row(oy + s.y0 + r, ox + from, end - from, cov.data() + from);
    }
}

Mask Rasterizer::fill_mask(const Path& path, const Affine& m, const FillOptions& opts) {
    const Rect b = transformed_bounds(path, m, opts.tolerance);
    if (path.empty() || b.x0 > b.x1) return {};
    const double lim = limits::kMaxCanvasDimension;
    IRect r{static_cast<int>(std::floor(std::clamp(b.x0, -lim, lim))), static_cast<int>(std::floor(std::clamp(b.y0, -lim, lim))),
            static_cast<int>(std::ceil(std::clamp(b.x1, -lim, lim))), static_cast<int>(std::ceil(std::clamp(b.y1, -lim, lim)))};
    if (r.x1 == r.x0) ++r.x1;
    if (r.y1 == r.y0) ++r.y1;
    r.x1 = std::min(r.x1, r.x0 + limits::kMaxCanvasDimension);
    r.y1 = std::min(r.y1, r.y0 + limits::kMaxCanvasDimension);
    return fill_mask(path, m, opts, r);
}

Mask Rasterizer::fill_mask(const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip) {
    Mask mask;
    if (clip.empty()) return mask;
    check_clip(clip);
    mask.bounds = clip;
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
