// casteljau/raster.hpp: scan conversion with exact-area anti-aliasing.
//
// Pipeline position: Path --(Affine)--> flatten --> clip to the target rectangle --> accumulate
// cover/area per cell --> per-row prefix sum --> fill rule --> 8-bit coverage spans --> sink.
// Coverage of a pixel is the exact area of the pixel square covered by the flattened shape under
// the fill rule, rounded to 1/255. Where two or more edges share a pixel in a way that makes plain
// accumulation inexact (crossings, overlapping or stacked contours), that pixel is recomputed
// exactly from the edges inside it (see src/raster/exact_cell.cpp).
//
// Range: geometry is clipped in double precision before it is converted to float cell coordinates,
// so any finite coordinate up to limits::kMaxCoordinate is accepted; the target rectangle is at
// most limits::kMaxCanvasDimension on each side. Memory grows with the clipped bounds of the shape,
// never with the canvas area: a shape whose clipped bounds hold at most 2^18 pixels is accumulated
// in one buffer as it is flattened; larger ones are swept in strips of at most 2^18 cells.
//
// Thread-safety: a Rasterizer holds scratch buffers; use one per thread. Masks are values.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "casteljau/flatten.hpp"
#include "casteljau/geometry.hpp"
#include "casteljau/path.hpp"

namespace casteljau {

enum class FillRule { NonZero, EvenOdd };

struct FillOptions {
    FillRule rule = FillRule::NonZero;
    double tolerance = kDefaultTolerance;  // flattening tolerance in pixels
    bool exact_overlaps = true;            // recompute multi-edge pixels exactly (off: plain accumulation)
};

// Receives coverage one row at a time, rows in increasing y. `coverage[i]` belongs to pixel
// (x + i, y). Rows the shape does not touch are not delivered; zero runs may be.
class SpanSink {
public:
    virtual ~SpanSink() = default;
    virtual void row(int y, int x, int length, const std::uint8_t* coverage) = 0;
};

// An 8-bit coverage mask (A8) positioned at `origin` in pixel space.
struct Mask {
    IRect bounds;                    // pixel rectangle the mask covers
    std::vector<std::uint8_t> data;  // bounds.width() * bounds.height(), row-major
    std::uint8_t at(int x, int y) const;  // 0 outside bounds
};

struct RasterStats {
    std::size_t segments = 0;        // line segments accumulated
    std::size_t exact_cells = 0;     // cells recomputed exactly
    std::size_t strips = 0;
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
