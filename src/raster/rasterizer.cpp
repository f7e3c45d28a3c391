// Raster stage, driver: decides how a shape is rasterized, then runs the one engine on it.
//
//   1. Exactness, before rasterizing: a shape whose topology is Simple (classify_topology: given
//      by the caller, or decided here for shapes large for their number of segments) is
//      accumulated plainly; any other is made exact by the winding sweep (winding_sweep.hpp: its
//      edges become the boundary of the region it fills) when it fits one dense buffer and has no
//      FillOptions::inside or hidden, else by the engine's overlap check. The sweep is faster on
//      glyphs, random curves and canvas fills; stroke outlines, whose joins cross themselves
//      hundreds of times, are faster through the overlap check with their inside capsules, and
//      map features with their hidden pixels (FillOptions::hidden) too.
//   2. The box: the shape's transformed control bounds inside the target, in whole pixels. The
//      edge builder (edge_builder.hpp) flattens the path into edges local to it, clipping them to
//      it unless the control points already lie inside.
//   3. Storage: a box of at most 2^18 cells (2^15 under the overlap check, whose per-cell records
//      must stay in cache) is one dense buffer, and edges go into the engine as the flattener
//      makes them (a batch of points at a time when no clipping is needed); a larger box is swept
//      in horizontal bands of at most as many cells, each a dense buffer of the same engine, from
//      the edges kept once (each band takes the edges that reach its rows, clipped to them, in
//      contour order).
// The engine (engine.hpp, engine.cpp): cell walk with cover/area accumulation, the overlap check
// by visits, exact coverage of the cells that need it (exact_cell.cpp), and the row scan
// (coverage.cpp).
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <mutex>
#include <string>

#include "casteljau/error.hpp"
#include "casteljau/limits.hpp"
#include "raster/engine.hpp"
#include "raster/edge_builder.hpp"
#include "raster/raster_internal.hpp"
#include "raster/winding_sweep.hpp"

namespace casteljau {

using raster::Edge;

namespace {

// Upper bound on cells in one dense buffer (a whole box or one band): 2^18 cells, 2 MiB of accumulators.
constexpr std::size_t kMaxStripCells = std::size_t(1) << 18;
// The same for shapes under the overlap check, whose cell walk reads and writes a double
// accumulator, a visit head and a candidate flag per cell in the order of the outline: 2^15 cells
// (416 KiB of them) stay in a core's own cache (a 1 MiB L2), where 2^18 cells (3.3 MiB) missed it
// at nearly every step. A world map's fill at 4096 x 2048 (map_bench) took 0.81 of AGG's speed
// with bands of 2^18 cells, 0.88 with 2^17, 0.91 with 2^16, 0.94 with 2^15 and 0.92 with 2^14.
constexpr std::size_t kMaxTrackedStripCells = std::size_t(1) << 15;

// Spare rasterizer states kept for reuse (see SparePool), and the edge records one may keep.
constexpr std::size_t kMaxSpare = 8;
constexpr std::size_t kMaxSpareEdges = std::size_t(1) << 16;

// A path without a topology verdict that the winding sweep does not take is classified before
// filling when its box's width + height reaches this many pixels per verb (see Rasterizer::fill
// and decide_topology). Classifying a glyph costs 2.4 to 6 us, about what the per-cell check costs
// over its boundary at 100 to 250 px: glyphs through the per-cell check (compare_glyphs, DejaVu
// Sans and Linux Libertine) filled fastest with the limit at 12 to 32; at 4 they were 12 % and
// 26 % slower at 96 px.
constexpr double kClassifyPixelsPerSegment = 16.0;

// The winding sweep's budget, in edge-strip steps: kSweepWorkPerEdge per edge plus kSweepWorkBase.
// Past it the shape takes the per-cell overlap check.
constexpr std::size_t kSweepWorkPerEdge = 32;
constexpr std::size_t kSweepWorkBase = 1024;

// The edge list of a banded fill: edges in contour order, with each edge's contour.
struct EdgeList {
    std::vector<Edge>& edges;
    std::vector<std::uint32_t>& contour;
    std::uint32_t current = 0;
    std::size_t max_edges = current_limits().flattened_segments;

    void push(double x0, double y0, double x1, double y1) {
        if (y0 == y1 && x0 == x1) return;
        if (edges.size() >= max_edges)
            throw Error(ErrorKind::Limit, "path too complex: more than " + std::to_string(max_edges) + " edges");
        edges.push_back({x0, y0, x1, y1, -1, -1});
        contour.push_back(current);
    }
    void contour_end() { ++current; }
};

// The edges of a shape to the winding sweep and to an engine at once (the edge builder's interface).
struct SweepAndEngine {
    raster::WindingSweep& sweep;
    raster::Engine& engine;

    void push(double x0, double y0, double x1, double y1) {
        sweep.push(x0, y0, x1, y1);
        engine.push(x0, y0, x1, y1);
    }
    void push_polyline(const double* xy, std::size_t n) {
        sweep.push_polyline(xy, n);
        engine.push_polyline(xy, n);
    }
    void contour_end() {
        sweep.contour_end();
        engine.contour_end();
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
    // The mask is fresh and zeroed (fill_mask).
    CoverageTarget target() override { return {mask_.data.data(), mask_.bounds.width(), mask_.bounds}; }

private:
    Mask& mask_;
};

void check_clip(const IRect& clip) {
    if (clip.width() > limits::kMaxCanvasDimension || clip.height() > limits::kMaxCanvasDimension)
        throw Error(ErrorKind::Limit,
                    "raster target exceeds " + std::to_string(limits::kMaxCanvasDimension) + " pixels per side");
}

// Transformed control-point bounds; throws for non-finite input (flatten's checks).
Rect transformed_bounds(const Path& path, const Affine& m, double tolerance) {
    return check_flatten_input(path, m, tolerance);
}

// A shape that reaches into the target is rasterized only when its coordinates stay within
// limits::kMaxCoordinate: beyond, differences inside the flattener and the clipper could overflow
// to infinity or NaN. (A shape wholly outside the target is skipped before this, whatever its
// coordinates.)
void check_coordinate_range(const Rect& b) {
    const double far = std::max(std::max(-b.x0, b.x1), std::max(-b.y0, b.y1));
    if (far > limits::kMaxCoordinate)
        throw Error(ErrorKind::Limit, "path coordinate beyond +/-1e15 pixels after the transform");
}

}  // namespace

struct Rasterizer::Impl {
    raster::Engine engine;                         // the one engine: cell walk, overlap check, scan
    std::vector<Edge> edges;                       // banded fills: the clipped edges ...
    std::vector<std::uint32_t> contour;            // ... their contours ...
    std::vector<std::vector<std::uint32_t>> band;  // ... and the edges of each band, in contour order
    raster::WindingSweep sweep;                    // shapes without a verdict: their region's boundary

    // Releases the edge lists and the engine's records when a fill made them larger than an
    // ordinary one needs (before waiting in the spare pool).
    void trim() {
        if (edges.capacity() > kMaxSpareEdges) {
            std::vector<Edge>().swap(edges);
            std::vector<std::uint32_t>().swap(contour);
            band.clear();
            band.shrink_to_fit();
        }
        engine.trim(kMaxSpareEdges);
        sweep.trim(kMaxSpareEdges);
    }
    // Fills the box of one dense buffer (bw x bh cells at (ox, oy)) by the winding sweep; false,
    // with nothing delivered, when the sweep gives up (too many crossings for its budget).
    bool fill_swept(const Path& path, const Affine& local, const FillOptions& opts, bool inside, int ox, int oy, int bw,
                    int bh, SpanSink& sink, RasterStats& stats);
    // Fills the box of bw x bh cells at (ox, oy) band by band from `edges`, in bands of at most
    // max_cells cells.
    void run_bands(const FillOptions& opts, std::size_t max_cells, int ox, int oy, int bw, int bh, SpanSink& sink,
                   RasterStats& stats);
};

namespace {

// Rasterizers come and go with their users (render_map makes one canvas per worker per call, a
// tile pyramid one per metatile), and a new engine maps its buffers afresh, page by page: 2 MiB
// of accumulators and 1.25 MiB of visit heads for a full strip, about 800 page faults, which cost
// a world map at 4096 x 2048 about 10 % of its time (and more on two threads, whose faults contend
// in the kernel). So a destroyed rasterizer's state waits here for the next one, up to kMaxSpare
// of them, each trimmed to the memory of ordinary fills first (Engine::trim, edge lists).
struct SparePool {
    std::mutex mu;
    std::vector<void*> impls;  // Rasterizer::Impl, owned
};

SparePool& spare_pool() {
    static SparePool* pool = new SparePool;  // never destroyed: rasterizers may outlive static destruction
    return *pool;
}

}  // namespace

Rasterizer::Rasterizer() {
    SparePool& pool = spare_pool();
    {
        std::lock_guard<std::mutex> lock(pool.mu);
        if (!pool.impls.empty()) {
            impl_.reset(static_cast<Impl*>(pool.impls.back()));
            pool.impls.pop_back();
            return;
        }
    }
    impl_ = std::make_unique<Impl>();
}

Rasterizer::~Rasterizer() {
    if (!impl_) return;
    impl_->trim();
    SparePool& pool = spare_pool();
    std::lock_guard<std::mutex> lock(pool.mu);
    if (pool.impls.size() < kMaxSpare) pool.impls.push_back(impl_.release());
}
Rasterizer::Rasterizer(Rasterizer&&) noexcept = default;
Rasterizer& Rasterizer::operator=(Rasterizer&&) noexcept = default;

Topology decide_topology(const Path& path, const Affine& m, double tolerance, double box_width, double box_height) {
    if (!(box_width + box_height >= kClassifyPixelsPerSegment * static_cast<double>(path.verbs().size())))
        return Topology::Unknown;
    // Under a similarity map the verdict for this very flattening proves more (thin curved strokes).
    const double s = similarity_scale(m);
    return s > 0 ? classify_topology(path, tolerance / s) : classify_topology(path);
}

void Rasterizer::fill(const Path& path, const Affine& m, const FillOptions& options, const IRect& clip,
                      SpanSink& sink) {
    stats_ = {};
    check_clip(clip);
    if (clip.empty() || path.empty()) return;
    const Rect b = transformed_bounds(path, m, options.tolerance);
    // The shape's box: its bounds inside the target.
    const double fx0 = std::floor(std::max(b.x0, static_cast<double>(clip.x0)));
    const double fy0 = std::floor(std::max(b.y0, static_cast<double>(clip.y0)));
    const double fx1 = std::ceil(std::min(b.x1, static_cast<double>(clip.x1)));
    const double fy1 = std::ceil(std::min(b.y1, static_cast<double>(clip.y1)));
    if (!(fx1 > fx0 && fy1 > fy0)) return;  // nothing of the shape inside the target
    check_coordinate_range(b);
    const bool inside = b.x0 >= clip.x0 && b.y0 >= clip.y0 && b.x1 <= clip.x1 && b.y1 <= clip.y1;
    const int ox = static_cast<int>(fx0), oy = static_cast<int>(fy0);
    const int bw = static_cast<int>(fx1) - ox, bh = static_cast<int>(fy1) - oy;
    // Exactness is decided before rasterizing, once for the shape: one proven simple
    // (classify_topology) is accumulated plainly, exact for it; any other is made exact by the
    // winding sweep or the per-cell overlap check. A verdict the caller gives (the glyph cache's,
    // cached per outline) is used as it is. Without one, a shape the sweep can take goes to it
    // unclassified: the sweep proves a simple shape for about 5 ns per flattened edge, less than
    // classifying costs (0.1 us per segment) at any size that fits its buffer. Any other shape is
    // decided by decide_topology's rule: the per-cell check costs per boundary pixel, so
    // classifying pays from kClassifyPixelsPerSegment pixels of box side per segment.
    FillOptions opts = options;
    const double cells = (fx1 - fx0) * (fy1 - fy0);
    const bool sweepable = cells <= static_cast<double>(kMaxStripCells) && opts.winding_sweep && opts.inside.empty() &&
                           !opts.hidden && opts.overlap_boxes.empty();
    if (opts.exact_overlaps) {
        if (opts.topology == Topology::Unknown && !sweepable)
            opts.topology = decide_topology(path, m, opts.tolerance, bw, bh);
        stats_.topology = opts.topology;
        opts.exact_overlaps = opts.topology != Topology::Simple;
    }
    const Affine local = Affine::translate(-ox, -oy) * m;
    const std::size_t max_cells = opts.exact_overlaps ? kMaxTrackedStripCells : kMaxStripCells;
    if (sweepable && opts.exact_overlaps && impl_->fill_swept(path, local, opts, inside, ox, oy, bw, bh, sink, stats_))
        return;
    if (cells <= static_cast<double>(max_cells)) {
        // The box fits one dense buffer: edges go into the engine as the flattener makes them (after
        // a sweep that gave up, flattened again for the overlap check).
        raster::Engine& d = impl_->engine;
        d.begin(bw, bh, opts.exact_overlaps);
        if (!opts.overlap_boxes.empty()) d.set_region(opts.overlap_boxes, -ox, -oy);
        raster::build_edges(path, local, opts.tolerance, inside, bw, bh, d);
        d.finish(opts.rule, ox, oy, sink, stats_, opts.inside, opts.hidden);
        return;
    }
    // Larger boxes: the clipped edges are kept, then swept in bands of at most kMaxStripCells cells.
    impl_->edges.clear();
    impl_->contour.clear();
    EdgeList list{impl_->edges, impl_->contour};
    raster::build_edges(path, local, opts.tolerance, inside, bw, bh, list);
    impl_->run_bands(opts, max_cells, ox, oy, bw, bh, sink, stats_);
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

bool Rasterizer::Impl::fill_swept(const Path& path, const Affine& local, const FillOptions& opts, bool inside, int ox,
                                  int oy, int bw, int bh, SpanSink& sink, RasterStats& stats) {
    engine.begin(bw, bh, false);
    // An engine that only lists the edges until finish() takes them as the sweep does, while they
    // are in the cache: most shapes prove simple, and then the sweep needs to hand nothing over.
    const bool both = engine.defers_accumulation();
    sweep.begin(current_limits().flattened_segments, !both);
    if (both) {
        SweepAndEngine tee{sweep, engine};
        raster::build_edges(path, local, opts.tolerance, inside, bw, bh, tee);
    } else {
        raster::build_edges(path, local, opts.tolerance, inside, bw, bh, sweep);
    }
    const std::size_t budget = kSweepWorkPerEdge * sweep.edges() + kSweepWorkBase;
    const raster::WindingSweep::Outcome outcome = sweep.fill(opts.rule, budget, engine);
    if (outcome == raster::WindingSweep::Outcome::TooCostly) return false;
    stats.swept_simple = outcome == raster::WindingSweep::Outcome::Simple;
    // The pushed edges wind 0 and one other value only, so the nonzero rule renders either rule's
    // region.
    engine.finish(FillRule::NonZero, ox, oy, sink, stats);
    stats.segments = sweep.edges();
    stats.swept = true;
    return true;
}

void Rasterizer::Impl::run_bands(const FillOptions& opts, std::size_t max_cells, int ox, int oy, int bw, int bh,
                                 SpanSink& sink, RasterStats& stats) {
    stats.segments = edges.size();
    if (edges.empty()) return;
    const std::size_t stride = static_cast<std::size_t>(bw) + 2;
    const int rows = static_cast<int>(std::clamp<std::size_t>(max_cells / stride, 1, static_cast<std::size_t>(bh)));
    const std::size_t nbands = static_cast<std::size_t>((bh + rows - 1) / rows);
    if (band.size() < nbands) band.resize(nbands);
    for (std::size_t k = 0; k < nbands; ++k) band[k].clear();
    // Each edge goes to every band its rows touch, in edge order (so contour order is kept).
    const int last = static_cast<int>(nbands) - 1;
    for (std::uint32_t i = 0; i < edges.size(); ++i) {
        const Edge& e = edges[i];
        const int b0 = std::clamp(static_cast<int>(std::min(e.y0, e.y1)) / rows, 0, last);
        const int b1 = std::clamp(static_cast<int>(std::max(e.y0, e.y1)) / rows, 0, last);
        for (int k = b0; k <= b1; ++k) band[static_cast<std::size_t>(k)].push_back(i);
    }
    for (std::size_t k = 0; k < nbands; ++k) {
        if (band[k].empty()) continue;
        const int y0 = static_cast<int>(k) * rows;
        const int h = std::min(rows, bh - y0);
        engine.begin(bw, h, opts.exact_overlaps);
        if (!opts.overlap_boxes.empty()) engine.set_region(opts.overlap_boxes, -ox, -(oy + y0));
        std::uint32_t c = contour[band[k].front()];
        for (std::uint32_t i : band[k]) {
            if (contour[i] != c) {
                engine.contour_end();
                c = contour[i];
            }
            const Edge& e = edges[i];
            raster::clip_edge(bw, h, Point{e.x0, e.y0 - y0}, Point{e.x1, e.y1 - y0}, engine);
        }
        engine.contour_end();
        RasterStats part;
        engine.finish(opts.rule, ox, oy + y0, sink, part, opts.inside, opts.hidden);
        stats.exact_cells += part.exact_cells;
        stats.dense_cells += part.dense_cells;
        stats.accumulated_cells += part.accumulated_cells;
        stats.inside_cells += part.inside_cells;
        stats.hidden_cells += part.hidden_cells;
        stats.exact_work += part.exact_work;
        ++stats.strips;
    }
}

Mask Rasterizer::fill_mask(const Path& path, const Affine& m, const FillOptions& opts) {
    const Rect b = transformed_bounds(path, m, opts.tolerance);
    if (path.empty() || b.x0 > b.x1) return {};
    const double lim = limits::kMaxCanvasDimension;
    IRect r{static_cast<int>(std::floor(std::clamp(b.x0, -lim, lim))),
            static_cast<int>(std::floor(std::clamp(b.y0, -lim, lim))),
            static_cast<int>(std::ceil(std::clamp(b.x1, -lim, lim))),
            static_cast<int>(std::ceil(std::clamp(b.y1, -lim, lim)))};
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
