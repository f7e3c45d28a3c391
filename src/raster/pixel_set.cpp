// Raster stage: PixelSet, a bit per pixel over a rectangle (include/casteljau/raster.hpp).
#include <algorithm>
#include <bit>

#include "casteljau/raster.hpp"

namespace casteljau {

PixelSet::PixelSet(const IRect& bounds) : bounds_(bounds) {
    if (bounds.empty()) {
        bounds_ = {};
        return;
    }
    words_ = (static_cast<std::size_t>(bounds.width()) + 63) / 64;
    bits_.assign(words_ * static_cast<std::size_t>(bounds.height()), 0);
}

void PixelSet::insert(int y, int x0, int x1) {
    if (y < bounds_.y0 || y >= bounds_.y1) return;
    x0 = std::max(x0, bounds_.x0);
    x1 = std::min(x1, bounds_.x1);
    if (x0 >= x1) return;
    std::uint64_t* row = bits_.data() + static_cast<std::size_t>(y - bounds_.y0) * words_;
    const std::size_t a = static_cast<std::size_t>(x0 - bounds_.x0), b = static_cast<std::size_t>(x1 - bounds_.x0);
    for (std::size_t w = a / 64; w <= (b - 1) / 64; ++w) {
        const std::size_t lo = std::max(a, w * 64) - w * 64, hi = std::min(b, w * 64 + 64) - w * 64;
        // Bits lo .. hi - 1 of the word (hi - lo is 1 to 64).
        const std::uint64_t ones = hi - lo == 64 ? ~std::uint64_t{0} : ((std::uint64_t{1} << (hi - lo)) - 1);
        row[w] |= ones << lo;
    }
}

std::size_t PixelSet::count() const {
    std::size_t n = 0;
    for (std::uint64_t w : bits_) n += static_cast<std::size_t>(std::popcount(w));
    return n;
}

}  // namespace casteljau
