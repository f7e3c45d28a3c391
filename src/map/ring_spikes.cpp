// Map stage: spikes taken out of a polygon ring before it is filled (ring_spikes.hpp).
#include "map/ring_spikes.hpp"

namespace casteljau::map_detail {

void drop_spikes(std::vector<Point>& r) {
    // One pass keeps a stack of the positions so far: a repeat of the top is dropped, a return to
    // the position under the top drops the top (the tip of a spike).
    std::size_t k = 0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const Point p = r[i];
        if (k > 0 && r[k - 1] == p) continue;
        if (k > 1 && r[k - 2] == p) {
            --k;
            continue;
        }
        r[k++] = p;
    }
    // Across the start, where the ring closes: [s, k) is what remains.
    std::size_t s = 0;
    while (k - s >= 3) {
        if (r[k - 1] == r[s]) {
            --k;  // the last position repeats the first
        } else if (r[k - 2] == r[s]) {
            k -= 2;  // a spike whose tip is the last position: ..., A, B | A, ...
        } else if (r[k - 1] == r[s + 1]) {
            s += 2;  // a spike whose tip is the first position: ..., A | B, A, ...
        } else {
            break;
        }
    }
    if (k - s < 3) {
        r.clear();
        return;
    }
    r.erase(r.begin() + static_cast<std::ptrdiff_t>(k), r.end());
    r.erase(r.begin(), r.begin() + static_cast<std::ptrdiff_t>(s));
}

}  // namespace casteljau::map_detail
