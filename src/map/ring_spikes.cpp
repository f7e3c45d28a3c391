// Map stage: spikes taken out of a polygon ring before it is filled (ring_spikes.hpp).
#include "map/ring_spikes.hpp"

namespace casteljau::map_detail {

namespace {

// The stack pass of drop_spikes over the positions at(0), ..., at(n - 1), written into `r` (which
// may be where they are read from: the stack never gets ahead of the reading). Returns the
// positions kept.
template <class At>
std::size_t stack_spikes(std::size_t n, At&& at, std::vector<Point>& r) {
    // One pass keeps a stack of the positions so far: a repeat of the top is dropped, a return to
    // the position under the top drops the top (the tip of a spike).
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const Point p = at(i);
        if (k > 0 && r[k - 1] == p) continue;
        if (k > 1 && r[k - 2] == p) {
            --k;
            continue;
        }
        r[k++] = p;
    }
    return k;
}

// The rest of drop_spikes once the first k positions of r are the stack's.
void close_spikes(std::vector<Point>& r, std::size_t k) {
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

}  // namespace

void drop_spikes(std::vector<Point>& r) {
    const std::size_t kept = stack_spikes(
        r.size(), [&](std::size_t i) { return r[i]; }, r);
    close_spikes(r, kept);
}

void map_without_spikes(std::span<const Point> in, const Affine& m, std::vector<Point>& out) {
    out.resize(in.size());
    const std::size_t kept = stack_spikes(
        in.size(), [&](std::size_t i) { return m.apply(in[i]); }, out);
    close_spikes(out, kept);
}

}  // namespace casteljau::map_detail
