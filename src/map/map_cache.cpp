// Map stage: MapCache and what it keeps for the renders of one map (src/map/map_cache.hpp).
#include "map/map_cache.hpp"

#include <algorithm>
#include <string>

#include "casteljau/error.hpp"

namespace casteljau {

struct MapCache::Impl {
    std::mutex mu;  // guards the binding
    const MapData* data = nullptr;
    std::string projection;
    std::unique_ptr<map_detail::KeptMap> kept;
};

MapCache::MapCache() : impl_(std::make_unique<Impl>()) {}
MapCache::~MapCache() = default;

std::size_t MapCache::kept() const {
    std::lock_guard<std::mutex> lock(impl_->mu);
    return impl_->kept ? impl_->kept->kept() : 0;
}

namespace map_detail {

const BorderNodes& KeptMap::nodes(const MapData& data) {
    std::call_once(nodes_found_, [&] { nodes_ = find_border_nodes(data); });
    return nodes_;
}

const SimplifiedMap& KeptMap::as_is_bounds(const MapData& data, const MapProjection& proj, int threads) {
    std::call_once(bounds_found_, [&] { bounds_ = bounds_only(data, proj, threads); });
    return bounds_;
}

std::size_t KeptMap::kept() {
    std::lock_guard<std::mutex> lock(mu_);
    std::size_t n = as_is_.kept();
    for (const auto& s : scaled_) n += s->analyses.kept();
    return n;
}

std::shared_ptr<ScaledMap> KeptMap::scaled(const Affine& m, double simplify,
                                           const std::function<SimplifiedMap()>& make) {
    const Affine linear{m.a, m.b, m.c, m.d, 0, 0};
    std::shared_ptr<ScaledMap> s;
    {
        std::lock_guard<std::mutex> lock(mu_);
        for (const auto& k : scaled_)
            if (k->linear == linear && k->simplify == simplify) s = k;
        if (!s) {
            if (scaled_.size() == kMaxScales) {
                const auto oldest = std::min_element(scaled_.begin(), scaled_.end(),
                                                     [](const auto& x, const auto& y) { return x->used < y->used; });
                scaled_.erase(oldest);
            }
            s = std::make_shared<ScaledMap>(linear, simplify, as_is_.size());
            scaled_.push_back(s);
        }
        s->used = ++clock_;
    }
    std::call_once(s->made, [&] { s->map = make(); });
    return s;
}

KeptMap& MapCacheAccess::bind(MapCache& cache, const MapData& data, const MapProjection& proj) {
    MapCache::Impl& c = *cache.impl_;
    std::lock_guard<std::mutex> lock(c.mu);
    if (!c.kept) {
        c.data = &data;
        c.projection = proj.spec();
        c.kept = std::make_unique<KeptMap>(data.features.size());
    } else if (c.data != &data || c.kept->as_is().size() != data.features.size() || c.projection != proj.spec()) {
        throw Error(ErrorKind::InvalidArgument,
                    "a MapCache serves the map it was first used with: other data or another projection given");
    }
    return *c.kept;
}

}  // namespace map_detail

}  // namespace casteljau
