// Map stage (internal): each feature's overlap analysis (find_overlap_region, raster.hpp), kept
// across renders of the same geometry.
//
// The analysis of a polygon (the boxes of the segments near which plain accumulation may be
// inexact, or the proof that there are none) holds under any affine map, so it is found once, in
// the pixel space of the first render that fills the feature, stored in projected coordinates
// and mapped into every later frame. A map's fills are not clipped to the frame and their pixel
// paths are the projected ones mapped by MapFrame::to_pixel (spikes, dropped by exact equality of
// positions, go alike in every frame), so a render of any frame of the same geometry can use it.
// The analysis decides every question with a margin of 2^-30 of the path's extent, far above the
// rounding by which two frames' paths differ.
//
// Thread-safety: every method may be called from any thread. A feature's analysis is found by the
// first thread that claims it; the others fill that feature without it meanwhile.
#pragma once

#include <atomic>
#include <cstddef>
#include <memory>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/raster.hpp"

namespace casteljau::map_detail {

class FillAnalyses {
public:
    explicit FillAnalyses(std::size_t features);

    std::size_t size() const { return n_; }
    // Feature i's analysis in projected coordinates, or nullptr while none is kept.
    const OverlapRegion* find(std::size_t i) const;
    // True for the one caller that may find feature i's analysis and keep() it.
    bool claim(std::size_t i);
    // Keeps the analysis of feature i found on `pixel_path` (its fill in a frame whose to_pixel
    // is `to_pixel`); returns it in pixel space. Only after claim(i) returned true.
    OverlapRegion keep(std::size_t i, const Path& pixel_path, const Affine& to_pixel);
    // `r` (projected coordinates) in the frame of `to_pixel`: the boxes' bounds mapped.
    static OverlapRegion in_frame(const OverlapRegion& r, const Affine& to_pixel);
    std::size_t kept() const { return kept_.load(std::memory_order_relaxed); }

private:
    std::size_t n_;
    std::unique_ptr<std::atomic<unsigned char>[]> state_;  // 0 none, 1 being found, 2 kept
    std::vector<OverlapRegion> regions_;
    std::atomic<std::size_t> kept_{0};
};

}  // namespace casteljau::map_detail
