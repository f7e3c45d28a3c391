// Map stage (internal): a layer's opaque round stroke swept before the fills it is drawn over.
//
// A thin map stroke at a small scale covers many pixels fully: coasts and borders wind through
// them in dozens of segments. Those are the very pixels where a fill's contours crowd and the
// overlap check would recompute its coverage exactly, though the opaque stroke painted over them
// replaces whatever the fill left there. Swept first, the stroke tells the fills which pixels it
// covers fully (FillOptions::hidden), and its rows wait to be composited after them: the pixels
// are the same as with the stroke swept after the fills.
//
// Memory: the stroke's coverage bytes (one per pixel it reaches) plus a bit per image pixel.
// Thread-safety: a value; sweep() runs its regions on the process-wide pool.
#pragma once

#include <span>
#include <vector>

#include "casteljau/canvas.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/round_stroke.hpp"

namespace casteljau::map_detail {

class StrokeCover {
public:
    // Sweeps the union of the capsules of `radius` around `segments` over each of `regions`
    // (disjoint rectangles of `image`, on up to `threads` threads), keeping each region's rows and
    // the pixels covered fully.
    void sweep(std::span<const LineSegment> segments, double radius, const IRect& image,
               const std::vector<IRect>& regions, int threads);
    // The pixels the stroke covers fully (coverage 255).
    const PixelSet& full() const { return full_; }
    // Composites region k's rows onto `canvas` with `paint`.
    void composite(std::size_t k, Canvas& canvas, const Paint& paint) const { canvas.fill_coverage(rows_[k], paint); }

private:
    std::vector<CoverageRows> rows_;  // per region
    PixelSet full_;
};

}  // namespace casteljau::map_detail
