// Map stage (internal): what a MapCache (casteljau/map.hpp) keeps for the renders of one map.
//
// - The fills' overlap analyses of the data's own geometry (fill_analyses.hpp), for renders that
//   draw the data as they are.
// - The border nodes (border_nodes.hpp) and the features' projected bounds, which do not depend on
//   the output.
// - The data simplified for up to kMaxScales output scales (simplify_map.hpp), each with its own
//   analyses: simplification depends only on the linear part of MapFrame::to_pixel and on the
//   distance, so every frame of one scale (a window of a larger map, the metatiles of one zoom)
//   draws the same simplified copy. The scale used longest ago gives way to a new one; a render
//   still drawing it keeps it alive until it is done.
//
// Thread-safety: every method may be called from any thread; each copy is made once, by the first
// render that needs it, while the others wait for it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "casteljau/map.hpp"
#include "map/border_nodes.hpp"
#include "map/fill_analyses.hpp"
#include "map/simplify_map.hpp"

namespace casteljau::map_detail {

// The data simplified for one output scale, with its fills' analyses.
struct ScaledMap {
    ScaledMap(const Affine& l, double s, std::size_t features) : linear(l), simplify(s), analyses(features) {}
    Affine linear;    // to_pixel without its translation
    double simplify;  // the distance, in pixels
    std::once_flag made;
    SimplifiedMap map;  // made once, by the first render of this scale
    FillAnalyses analyses;
    std::uint64_t used = 0;  // KeptMap's clock at its last use
};

class KeptMap {
public:
    static constexpr std::size_t kMaxScales = 4;

    explicit KeptMap(std::size_t features) : as_is_(features) {}

    FillAnalyses& as_is() { return as_is_; }
    const BorderNodes& nodes(const MapData& data);
    // The data's own geometry with every feature's projected bounds (bounds_only).
    const SimplifiedMap& as_is_bounds(const MapData& data, const MapProjection& proj, int threads);
    // Features whose analysis is kept, over every copy.
    std::size_t kept();
    // The copy for frames whose to_pixel has the linear part of `to_pixel`, simplified at
    // `simplify` pixels: made by `make` the first time.
    std::shared_ptr<ScaledMap> scaled(const Affine& to_pixel, double simplify,
                                      const std::function<SimplifiedMap()>& make);

private:
    FillAnalyses as_is_;
    std::once_flag nodes_found_, bounds_found_;
    BorderNodes nodes_;
    SimplifiedMap bounds_;
    std::mutex mu_;  // guards scaled_ and clock_
    std::vector<std::shared_ptr<ScaledMap>> scaled_;
    std::uint64_t clock_ = 0;
};

// MapCache's contents for `data` drawn through `proj`, made on first use. Throws
// Error(InvalidArgument) when the cache was first used with other data or another projection.
struct MapCacheAccess {
    static KeptMap& bind(MapCache& cache, const MapData& data, const MapProjection& proj);
};

}  // namespace casteljau::map_detail
