// casteljau/seamless.hpp: seamless (conflation-free) compositing of many fills.
//
// Drawing two fills that share an edge one after the other with source-over leaves a seam: a pixel
// half covered by each comes out 1 - (1 - 1/2)(1 - 1/2) = 75% covered, so the background shows
// through along every shared border. A SeamlessCompositor instead gives each pixel to the fills in
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
// Cost: 5 bytes per pixel of the region it covers (a premultiplied RGBA8 layer and an 8-bit
// coverage plane); per covered pixel a few integer operations more than source-over. Time is that
// of rasterizing each fill once plus one pass over the region's pixels at the end. A compositor may
// cover only a band of the target (render_map gives each thread one band at a time and reuses its
// memory with reset()), so that its memory stays small and in cache.
//
// Each row remembers the columns fills have touched, so reset(), clear() and composite_onto() pass
// over those only (a world map's oceans cost nothing there).
//
// Onto a transparent target (a new Pixmap) the layer composited source-over is the layer itself,
// so reset_into() lets the compositor use the target's own pixels as its layer: no layer memory,
// and no pass at the end (render_map does this for its first fills on a transparent background).
//
// Coordinates: pixel space of the target (x right, y down), also for a compositor covering a
// region only. Thread-safety: one thread at a time, except add() with clip rectangles that share
// no row; compositors of disjoint regions may composite onto one target at once.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "casteljau/paint.hpp"
#include "casteljau/path.hpp"
#include "casteljau/raster.hpp"

namespace casteljau {

class SeamlessCompositor {
public:
    // Covers the target's pixels [0, width) x [0, height). Throws like Pixmap(width, height) for
    // sizes outside the canvas limits.
    SeamlessCompositor(int width, int height);
    // Covers `region` of the target only (pixel rectangle, non-empty).
    explicit SeamlessCompositor(const IRect& region);
    // Covers `region` of `target` with the target's pixels as the layer (see reset_into).
    SeamlessCompositor(Pixmap& target, const IRect& region);

    int width() const { return region_.x1 - region_.x0; }
    int height() const { return region_.y1 - region_.y0; }
    const IRect& region() const { return region_; }
    // Starts again, empty, over `region` (keeps the memory when the new region is not larger).
    void reset(const IRect& region);
    // Starts again over `region` of `target` (which must contain it), with the target's pixels
    // there as the layer: they must be transparent (all zero), as in a new Pixmap. add() then
    // writes the final pixels into `target`, and composite_onto(target) does nothing. Fills
    // written into the target before stay there (reset_into() band after band fills one image).
    // Throws Error(InvalidArgument) when the region is empty or not inside the target.
    void reset_into(Pixmap& target, const IRect& region);

    // Adds the fill of `path` (pixel space) in `color` with `opacity` (multiplies the alpha).
    // Fills added earlier take precedence where they overlap.
    void add(Rasterizer& raster, const Path& path, const FillOptions& opts, Color color, double opacity = 1.0);
    // The same inside `clip` only (pixel rectangle, intersected with the region). Calls whose
    // clips share no row touch disjoint memory, so they may run on different threads at once.
    void add(Rasterizer& raster, const Path& path, const FillOptions& opts, Color color, double opacity,
             const IRect& clip);
    // Coverage already taken in pixel (x, y) of the region, 0..255.
    std::uint8_t taken(int x, int y) const {
        return cov_[static_cast<std::size_t>(y - region_.y0) * static_cast<std::size_t>(width()) +
                    static_cast<std::size_t>(x - region_.x0)];
    }
    // Source-over of the layer onto the region of `dst` (which must contain the region); nothing
    // when the layer is `dst` itself (reset_into).
    void composite_onto(Pixmap& dst) const;
    // The region of `dst` set to `background` (its pixels replaced), then the layer composited
    // source-over onto it: the pixels of dst.fill_rows() followed by composite_onto(dst), with each
    // row written while it is in cache. Not after reset_into() (Error(InvalidArgument)).
    void composite_onto(Pixmap& dst, Color background) const;
    // Forgets every fill: the coverage and the layer (after reset_into, the fills' pixels in the
    // target go back to transparent).
    void clear();

private:
    // composite_onto(), with every row of the region set to `background` first when it is given.
    void composite_rows(Pixmap& dst, const PremulPixel* background) const;
    IRect region_;
    std::vector<std::uint8_t> layer_;  // premultiplied RGBA8, when the layer is the compositor's own
    // Coverage taken per pixel of the region. It comes from the system as zero pages, so a large
    // region costs nothing where no fill reaches (a map's oceans) and nothing is written to clear it.
    struct FreeCoverage {
        std::size_t bytes;
        void operator()(std::uint8_t* p) const noexcept;
    };
    std::unique_ptr<std::uint8_t[], FreeCoverage> cov_;
    std::vector<int> lo_, hi_;  // per row: the columns [lo, hi) fills have touched (lo >= hi: none)
    Pixmap* into_ = nullptr;    // the target whose pixels are the layer (reset_into), or null
    // The layer's pixel at the region's origin, and the bytes from one layer row to the next.
    std::uint8_t* layer_origin() const;
    std::size_t layer_stride() const;
    void forget(bool layer_too);  // clears the touched coverage (and layer) ranges
    bool same_size(const IRect& region) const;
    static std::size_t coverage_cells(const IRect& region);
    // The coverage planes made ready for `region`: the touched ranges forgotten (with the layer's
    // when `clear_layer`) if its size is the current one, allocated afresh otherwise.
    void start(const IRect& region, bool clear_layer);
};

}  // namespace casteljau
