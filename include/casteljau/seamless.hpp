// casteljau/seamless.hpp: conflation-free compositing of many fills ("composite by area").
//
// Drawing two fills that share an edge one after the other with source-over leaves a seam: a pixel
// half covered by each comes out 1 - (1 - 1/2)(1 - 1/2) = 75% covered, so the background shows
// through along every shared border. An AreaCompositor instead gives each pixel to the fills in
// proportion to the exact area they cover in it, and leaves to what is below only the area nobody
// covers:
//   layer = sum_i c_i * colour_i,   sum_i c_i <= 1,   c_i = min(coverage_i, 1 - sum_{j<i} c_j)
// where coverage_i is the exact area of fill i in the pixel (8-bit, from the Rasterizer) and the
// fills are added in PRECEDENCE order: a fill added earlier keeps the area it covers where fills
// overlap (a map draws its features from the last to the first, so later features win, as they
// would with source-over). The layer is then composited once, source-over, onto the target.
// Two fills sharing an edge therefore sum to full coverage there and no background bleeds in.
//
// Rounding: 8-bit coverage is round(area * 255). The areas of two fills meeting along an edge add up
// to 1 exactly, so their rounded coverages add up to 255 or 256 (both halves at .5) and clamp to
// 255 — unless float rounding inside the rasterizer puts both just below .5, giving 254. So when a
// second fill would bring a pixel to exactly 254/255, it is given the last 1/255 as well (a pixel
// truly left 1/255 uncovered by two fills is drawn full: an error of 1/255 that cannot show).
//
// Cost: 5 bytes per pixel of the target (a premultiplied RGBA8 layer and an 8-bit coverage plane),
// allocated once; per covered pixel a few integer operations more than source-over. Time is that of
// rasterizing each fill once plus one pass over the pixels at the end.
//
// Coordinates: pixel space of the target (x right, y down). Thread-safety: one thread at a time,
// except add() with disjoint clip rectangles.
#pragma once

#include <cstdint>
#include <vector>

#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"
#include "casteljau/raster.hpp"

namespace casteljau {

class AreaCompositor {
public:
    // Throws like Pixmap(width, height) for sizes outside the canvas limits.
    AreaCompositor(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    // Adds the fill of `path` (pixel space) in `color` with `opacity` (multiplies the alpha).
    // Fills added earlier take precedence where they overlap.
    void add(Rasterizer& raster, const Path& path, const FillOptions& opts, Color color, double opacity = 1.0);
    // The same inside `clip` only (pixel rectangle within the compositor). Calls with disjoint
    // clips touch disjoint pixels, so they may run on different threads at once.
    void add(Rasterizer& raster, const Path& path, const FillOptions& opts, Color color, double opacity, const IRect& clip);
    // Coverage already taken in pixel (x, y), 0..255.
    std::uint8_t taken(int x, int y) const { return cov_[static_cast<std::size_t>(y) * width_ + x]; }
    // Source-over of the layer onto `dst` (same size).
    void composite_onto(Pixmap& dst) const;
    void clear();

private:
    int width_, height_;
    std::vector<std::uint8_t> layer_;  // premultiplied RGBA8
    std::vector<std::uint8_t> cov_;
};

}  // namespace casteljau
