// casteljau/raster.hpp: scan conversion with exact-area anti-aliasing.
//
// Pipeline position: Path --(Affine)--> flatten --> clip to the target rectangle --> accumulate
// cover/area per cell --> per-row prefix sum --> fill rule --> 8-bit coverage spans --> sink.
// Coverage of a pixel is the exact area of the pixel square covered by the flattened shape under
// the fill rule, rounded to 1/255. Plain accumulation (the integral of the winding number over the
// pixel) is that area exactly wherever the winding number stays within one unit interval. Whether
// it does is decided per shape before rasterizing (classify_topology, once per outline: the glyph
// cache keeps each glyph's verdict): a shape proven "simple" (no two segments meet, winding values
// only 0 and 1, or only 0 and -1: 96 % of DejaVu Sans glyphs, and under the similarity maps that
// glyphs are drawn with 89 % of Linux Libertine's, against 50 % under every map) is accumulated plainly; any
// other shape is made exact in one of two ways:
//   - the winding sweep (src/raster/winding_sweep.hpp), for shapes of one dense buffer (below)
//     without FillOptions::inside or hidden: a sweep down the shape keeps its edges in x order
//     and replaces them by the boundary of the region it fills, which plain accumulation renders
//     exactly. A shape that winds 0 and one other value only in every strip keeps its own edges
//     (RasterStats::swept_simple); one that does not is cut into that boundary from the first
//     strip that winds a second value. It costs per edge and per crossing, not per pixel; a
//     shape with too many crossings for its size (past 32 strip steps per edge, plus 1024) takes
//     the overlap check instead;
//   - the overlap check, where every pixel in which edges could make accumulation inexact
//     (crossings, overlapping or stacked contours) is recomputed exactly from the edges inside it
//     (see src/raster/exact_cell.cpp).
// A shape whose topology the caller did not give goes to the winding sweep when it can take it
// (the sweep proves a simple shape for less than classifying it costs). Any other is classified
// by fill() when its box is large for its number of segments (width + height at least 16 pixels
// per path verb: there the per-cell check would cost more than the classification; under a
// similarity map with the verdict for that map and tolerance), and otherwise made exact as above.
// Precision: shapes with the overlap check, and shapes wider than 1024 px, accumulate in double,
// which rounds the area correctly but for values within about 1e-12 of a level of half-way
// between two levels. Narrower shapes without it (most glyphs) accumulate in float: the area
// before rounding is within about 4e-3 of a level of the exact one (positions rounded to float;
// pieces narrower than 1e-4 px taken as vertical), so a pixel may round one level away from the
// correctly rounded value only where its exact area lies that close to half-way. A half-way value
// rounds up in both (from exactly representable positions; see kRoundUp in
// src/raster/raster_internal.hpp).
//
// Range: geometry is clipped in double precision before it is converted to float cell coordinates,
// so any finite coordinate up to limits::kMaxCoordinate is accepted; the target rectangle is at
// most limits::kMaxCanvasDimension on each side. Memory grows with the clipped bounds of the shape,
// never with the canvas area: a shape whose clipped bounds hold at most 2^18 pixels is accumulated
// in one buffer as it is flattened; larger ones are swept in bands (strips) of at most 2^18 cells.
//
// Thread-safety: a Rasterizer holds scratch buffers; use one per thread. Masks are values.
// Memory kept: a destroyed Rasterizer's buffers wait, process-wide, for the next Rasterizer made
// (at most 8 of them, each first trimmed to the size of a fill of about 65,000 edges: a few MiB),
// so that short-lived rasterizers (one per worker per render_map call) do not map their buffers
// afresh, page by page.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "casteljau/flatten.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/limits.hpp"
#include "casteljau/path.hpp"

namespace casteljau {

enum class FillRule { NonZero, EvenOdd };

// What a path's outline allows plain accumulation to do (classify_topology).
enum class Topology : std::uint8_t {
    Unknown,      // not decided yet: the rasterizer decides
    Simple,       // the winding number takes only the values 0 and 1, or only 0 and -1: plain
                  // accumulation is exact under both fill rules. Proven when no two segments
                  // meet except consecutive ones at their shared point and lines touching at a
                  // shared vertex without crossing there; spikes (a line straight back along the
                  // one before) are left out of the proof, as they cancel in accumulation
    Overlapping,  // anything else (or not proven simple): made exact by the winding sweep or the
                  // per-cell overlap check (see the top of this header)
};

// Decides the topology of `path` from its control points, in its own coordinates. The verdict
// holds for the path under every invertible affine map, so callers may compute it once per outline
// (the glyph cache does, per glyph and variation instance) and pass it in FillOptions::topology.
// Each test keeps a margin of 2^-40 of the path's extent, far above double rounding: shapes whose
// parts touch or nearly touch are "overlapping", except lines that share an end point exactly
// (map rings meeting at a node, a ring pinched onto itself), which are proven when the contours
// pass through that vertex without crossing. Cost: segments paired on a uniform grid over
// their boxes, about 0.1 us per segment for outlines whose segments are apart; bounded work (then
// "overlapping") for adversarial ones. See src/raster/topology.cpp. Thread-safe (scratch buffers
// are per thread).
Topology classify_topology(const Path& path);

// The verdict for filling `path` through a similarity map (a uniform scale s > 0 with any
// rotation, reflection and translation, such as a glyph's map to pixels) at a flattening
// tolerance t with t / s <= max_tolerance (in the path's units): a glyph at every size from
// t / max_tolerance pixels per unit up. It proves more than classify_topology(path) (a path
// proven there is proven here, within the same work budget): two segments whose hulls overlap, such as the two sides of a thin
// curved stroke, are apart when every pair of chords the flattener can draw for them at one such
// tolerance is apart (conics are halved while their flatness bound exceeds the tolerance, so
// their chords are known in advance; see src/raster/topology.cpp). The verdict
// says nothing about other maps: a non-uniform scale or a shear flattens differently. Throws
// Error(InvalidArgument) unless max_tolerance is positive and finite. Thread-safe.
Topology classify_topology(const Path& path, double max_tolerance);

// The scale s of `m` when it is a similarity map (its linear part s times a rotation, or times a
// rotation and a mirror, to a relative 2^-40), else 0: what classify_topology(path,
// max_tolerance) asks of the map, with tolerance / s to compare against max_tolerance.
double similarity_scale(const Affine& m);

// The verdict Rasterizer::fill reaches for `path` under `m` at `tolerance` (pixels) when it is
// given none, cannot take the winding sweep (a box of more than 2^18 pixels, FillOptions::inside,
// hidden or overlap_boxes, or winding_sweep off) and the shape's box on the target measures
// box_width x box_height pixels: classify_topology (for this map and tolerance when m is a
// similarity) when width + height is at least 16 pixels per path verb, else Unknown: not worth
// classifying, the per-cell check costs per boundary pixel and the classification per segment
// (fill() then takes the per-cell check). A caller filling one path in several pieces (bands,
// tiles) decides once with the whole box and passes the verdict in FillOptions::topology, instead
// of fill() classifying it again for every piece. Thread-safe.
Topology decide_topology(const Path& path, const Affine& m, double tolerance, double box_width, double box_height);

// Where plain accumulation of a polygon may be inexact (find_overlap_region).
struct OverlapRegion {
    // Simple: plain accumulation is exact everywhere (no box); Overlapping: exact outside the
    // boxes; Unknown: not decided (the path has curves, or its segments crowd together beyond
    // the analysis' linear budget: see below), `boxes` empty.
    Topology topology = Topology::Unknown;
    std::vector<Rect> boxes;  // in the path's coordinates
};

// For a path of straight lines only (a map's polygons): the boxes of the segments near which
// plain accumulation may be inexact, because they meet another segment (cross it, touch it, run
// along it) or have a winding number outside {0, 1} (or {0, -1}) on one of their sides. Outside
// the boxes every pixel is exact without the overlap check; FillOptions::overlap_boxes takes them
// (mapped to pixels) so that the check looks only inside. The analysis holds under any affine map
// (meetings and winding numbers are affine invariants), with a margin of 2^-30 of the path's
// extent for every decision. Cost: segments paired on a uniform grid, and one ray along a row of
// it for each run of segments between those that meet: about as much as classify_topology for a
// polygon, and linear in its segments: a path whose segments crowd into few cells (stacked copies)
// or rows beyond a fixed budget per segment is left Unknown (src/raster/overlap_region.cpp).
// Thread-safe.
OverlapRegion find_overlap_region(const Path& path);

// A set of pixels over a rectangle (pixel space), one bit each; pixels outside the rectangle are
// never in it. Inserting on different rows from different threads is safe (each row has words of
// its own); anything else needs the caller's synchronisation.
class PixelSet {
public:
    PixelSet() = default;
    // The empty set over `bounds` (bounds.width() x bounds.height() bits, all clear).
    explicit PixelSet(const IRect& bounds);
    const IRect& bounds() const { return bounds_; }
    // Adds pixels x0 .. x1 - 1 of row y (those inside the bounds).
    void insert(int y, int x0, int x1);
    bool contains(int x, int y) const {
        if (x < bounds_.x0 || y < bounds_.y0 || x >= bounds_.x1 || y >= bounds_.y1) return false;
        const std::size_t i = static_cast<std::size_t>(x - bounds_.x0);
        return (bits_[static_cast<std::size_t>(y - bounds_.y0) * words_ + i / 64] >> (i % 64)) & 1;
    }
    // The number of pixels in the set.
    std::size_t count() const;

private:
    IRect bounds_;
    std::size_t words_ = 0;  // per row
    std::vector<std::uint64_t> bits_;
};

struct FillOptions {
    FillRule rule = FillRule::NonZero;
    double tolerance = kDefaultTolerance;  // flattening tolerance in pixels
    bool exact_overlaps = true;            // exact coverage where edges overlap (off: plain accumulation everywhere)
    // The path's topology when the caller knows it (classify_topology of this very path, under any
    // affine map; or classify_topology(path, max_tolerance) when the map is a similarity and
    // tolerance / scale is at most max_tolerance): a Simple path is accumulated plainly, which is
    // exact for it; Overlapping is made exact by the winding sweep or the per-cell overlap check;
    // Unknown lets fill() decide (see the top of this header). Only read when exact_overlaps is
    // on.
    Topology topology = Topology::Unknown;
    // Capsules, possibly cut by lines (pixel space), that the caller knows lie wholly inside the
    // shape, such as the ones stroke_outline() gives with a stroke's outline. With the nonzero rule, a pixel that the
    // overlap check would recompute exactly and that lies wholly inside one of them is full: the
    // exact computation, which would find the same, is skipped. A capsule that does not lie inside
    // the shape gives wrong pixels. Ignored under the even-odd rule. The span must outlive the
    // fill. Cost: a sweep over the capsules that can hold a pixel, with a work budget of a few
    // tests per capsule and per recomputed pixel. A shape given capsules takes the overlap check,
    // not the winding sweep (stroke outlines, whose joins cross themselves many times, are faster
    // that way).
    std::span<const CutCapsule> inside;
    // Pixels the caller will paint over with opaque paint at full coverage, so that their coverage
    // is never seen: the overlap check leaves them to plain accumulation (what exact_overlaps =
    // false gives) instead of recomputing them exactly. Every other pixel keeps its exact
    // coverage. The set must outlive the fill. render_map hides the pixels its opaque strokes
    // cover fully from the fills under them. A shape given hidden pixels takes the overlap check,
    // not the winding sweep (map features with their hidden pixels are faster that way).
    const PixelSet* hidden = nullptr;
    // Boxes (pixel space) outside which the caller knows plain accumulation to be exact: the boxes
    // of find_overlap_region for this path, mapped to the target (render_map draws its polygons in
    // pixel coordinates and passes them as they are). The overlap check then visits only the
    // pixels the boxes meet (grown by a pixel for rounding). Empty, or boxes of more pixels in all
    // than the shape's box (long segments crossing it many times): the check looks everywhere.
    // Read only when the check runs (exact_overlaps, a shape not proven simple); the span must
    // outlive the fill. A shape given boxes takes the overlap check, not the winding sweep.
    std::span<const Rect> overlap_boxes;
    // Shapes that need exactness may take the winding sweep (see the top of this header); false
    // sends every one to the per-cell overlap check. Both are exact; the pixels they give differ
    // by at most one level, where float and double accumulation round differently.
    bool winding_sweep = true;
};

// An 8-bit buffer a SpanSink lets the renderer write coverage into (see SpanSink::target).
struct CoverageTarget {
    std::uint8_t* data = nullptr;  // pixel (bounds.x0, bounds.y0); null: no direct target
    std::ptrdiff_t stride = 0;     // bytes from one row to the next
    IRect bounds;                  // the pixels it holds
};

// Receives coverage one row at a time, rows in increasing y. `coverage[i]` belongs to pixel
// (x + i, y). Rows the shape does not touch are not delivered; zero runs may be.
class SpanSink {
public:
    virtual ~SpanSink() = default;
    virtual void row(int y, int x, int length, const std::uint8_t* coverage) = 0;
    // A sink filling a fresh mask may offer that mask here, asked before each fill's rows: every
    // pixel of its bounds must hold zero. The renderer may then write the coverage of a row whose
    // whole width (the shape's box) lies inside the bounds straight into it, zeros included,
    // instead of calling row() for that row; other rows still come through row(). This saves a
    // copy of every covered pixel of shapes wider than a glyph at text sizes. The default offers
    // none.
    virtual CoverageTarget target() { return {}; }
};

// Coverage rows kept to be used later: a SpanSink that records the rows it is handed, in order,
// and hands them on to another sink (replay), as often as asked. Memory: the coverage bytes plus
// 24 bytes per row. A value; not for concurrent recording.
class CoverageRows final : public SpanSink {
public:
    void row(int y, int x, int length, const std::uint8_t* coverage) override;
    // Hands every recorded row to `sink`, in the order they came.
    void replay(SpanSink& sink) const;
    void clear();
    bool empty() const { return rows_.empty(); }

private:
    struct Row {
        int y, x, length;
        std::size_t at;  // its coverage: bytes_[at, at + length)
    };
    std::vector<Row> rows_;
    std::vector<std::uint8_t> bytes_;
};

// An 8-bit coverage mask (A8) positioned at `origin` in pixel space.
struct Mask {
    IRect bounds;                         // pixel rectangle the mask covers
    std::vector<std::uint8_t> data;       // bounds.width() * bounds.height(), row-major
    std::uint8_t at(int x, int y) const;  // 0 outside bounds
};

struct RasterStats {
    std::size_t segments = 0;  // line segments accumulated
    bool swept = false;        // the winding sweep made the shape exact (no cell below is counted)
    // The sweep found that the shape winds 0 and one other value only (as glyphs do), so its own
    // edges were accumulated rather than the boundary of its region.
    bool swept_simple = false;
    std::size_t exact_cells = 0;  // cells recomputed exactly
    // Of those, cells where the exact method would cost too much (thousands of pieces crossing in
    // one pixel, or the fill's exact-work budget spent: Limits::exact_work piece visits plus 2000 per
    // segment) and lines through the cell were integrated
    // instead: within 1/2048 of a pixel, 1/32 at worst. Real glyphs and maps have none.
    std::size_t dense_cells = 0;
    // Of those, cells left to plain accumulation (as exact_overlaps = false would give) because the
    // fill had already spent twice its exact-work budget: only shapes that pile thousands of
    // crossing pieces into hundreds of pixels get there, and this bounds their time.
    std::size_t accumulated_cells = 0;
    // Of the cells the overlap check marked, those found full inside FillOptions::inside (not
    // counted in exact_cells).
    std::size_t inside_cells = 0;
    // Cells the overlap check would have examined, left to accumulation because they are in
    // FillOptions::hidden (not counted in exact_cells).
    std::size_t hidden_cells = 0;
    double exact_work = 0;                  // piece visits the exact cells cost (bounded by the fill's size)
    std::size_t strips = 0;                 // dense buffers run: 1, or the bands of a large shape
    Topology topology = Topology::Unknown;  // the verdict the fill used (Unknown: exact_overlaps off)
};

class Rasterizer {
public:
    Rasterizer();
    ~Rasterizer();
    Rasterizer(Rasterizer&&) noexcept;
    Rasterizer& operator=(Rasterizer&&) noexcept;

    // Fills `path` mapped by `m` inside `clip` (pixel rectangle) and hands coverage to `sink`.
    // Throws Error(InvalidData) for non-finite geometry, Error(Limit) past the documented limits.
    void fill(const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip, SpanSink& sink);
    // Same for an already flattened polyline in pixel space (contours closed implicitly).
    void fill(const Polyline& poly, const FillOptions& opts, const IRect& clip, SpanSink& sink);

    // Convenience: coverage of `path` mapped by `m` as a Mask covering the shape's pixel bounds
    // (intersected with `clip` when given).
    Mask fill_mask(const Path& path, const Affine& m, const FillOptions& opts = {});
    Mask fill_mask(const Path& path, const Affine& m, const FillOptions& opts, const IRect& clip);

    const RasterStats& last_stats() const { return stats_; }

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    RasterStats stats_;
};

}  // namespace casteljau
