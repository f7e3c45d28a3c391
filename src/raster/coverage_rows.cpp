// Raster stage: CoverageRows, coverage rows recorded to be replayed (include/casteljau/raster.hpp).
#include "casteljau/raster.hpp"

namespace casteljau {

void CoverageRows::row(int y, int x, int length, const std::uint8_t* coverage) {
    if (length <= 0) return;
    rows_.push_back({y, x, length, bytes_.size()});
    bytes_.insert(bytes_.end(), coverage, coverage + length);
}

void CoverageRows::replay(SpanSink& sink) const {
    for (const Row& r : rows_) sink.row(r.y, r.x, r.length, bytes_.data() + r.at);
}

void CoverageRows::clear() {
    rows_.clear();
    bytes_.clear();
}

}  // namespace casteljau
