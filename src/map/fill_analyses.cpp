// Map stage: each feature's overlap analysis kept across renders (src/map/fill_analyses.hpp).
#include "map/fill_analyses.hpp"

namespace casteljau::map_detail {

namespace {

OverlapRegion mapped(const OverlapRegion& r, const Affine& m) {
    OverlapRegion out;
    out.topology = r.topology;
    out.boxes.reserve(r.boxes.size());
    for (const Rect& b : r.boxes) out.boxes.push_back(m.map_bounds(b));
    return out;
}

}  // namespace

FillAnalyses::FillAnalyses(std::size_t features)
    : n_(features), state_(new std::atomic<unsigned char>[features]), regions_(features) {
    for (std::size_t i = 0; i < n_; ++i) state_[i].store(0, std::memory_order_relaxed);
}

const OverlapRegion* FillAnalyses::find(std::size_t i) const {
    return i < n_ && state_[i].load(std::memory_order_acquire) == 2 ? &regions_[i] : nullptr;
}

bool FillAnalyses::claim(std::size_t i) {
    unsigned char none = 0;
    return i < n_ && state_[i].compare_exchange_strong(none, 1, std::memory_order_acq_rel);
}

OverlapRegion FillAnalyses::keep(std::size_t i, const Path& pixel_path, const Affine& to_pixel) {
    OverlapRegion found = find_overlap_region(pixel_path);
    const std::optional<Affine> back = to_pixel.inverse();
    if (!back) {
        state_[i].store(0, std::memory_order_release);  // a singular frame draws nothing to keep
        return found;
    }
    regions_[i] = mapped(found, *back);
    kept_.fetch_add(1, std::memory_order_relaxed);
    state_[i].store(2, std::memory_order_release);
    return found;
}

OverlapRegion FillAnalyses::in_frame(const OverlapRegion& r, const Affine& to_pixel) { return mapped(r, to_pixel); }

}  // namespace casteljau::map_detail
