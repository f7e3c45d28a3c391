// Map stage: dropping repeated segments (unique_segments.hpp) with one open-addressing table of
// segment indices, probed linearly from a hash of the segment's ends taken in a canonical order.
#include "map/unique_segments.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <utility>

#include "casteljau/error.hpp"
#include "map/point_hash.hpp"

namespace casteljau::map_detail {

namespace {

constexpr std::uint32_t kEmpty = std::numeric_limits<std::uint32_t>::max();

// The ends in a canonical order (the lesser first, x then y), so both directions compare equal.
std::pair<Point, Point> canonical(const LineSegment& s) {
    const bool swap = s.b.x < s.a.x || (s.b.x == s.a.x && s.b.y < s.a.y);
    return swap ? std::pair{s.b, s.a} : std::pair{s.a, s.b};
}

}  // namespace

void drop_repeated_segments(std::vector<LineSegment>& segments) {
    const std::size_t n = segments.size();
    if (n < 2) return;
    if (n >= kEmpty / 2) throw Error(ErrorKind::Limit, "map strokes: too many segments");
    const std::size_t size = std::bit_ceil(2 * n);
    const std::size_t mask = size - 1;
    // A slot holds a kept segment's index and the upper half of its hash: a probe reads the
    // segment itself only when the halves agree, nearly always a repeat.
    std::vector<std::uint64_t> slots(size, kEmpty);
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto [a, b] = canonical(segments[i]);
        const std::uint64_t h = mix(hash_point(a) ^ (hash_point(b) >> 1));
        const std::uint64_t tag = h >> 32 << 32;
        std::size_t s = static_cast<std::size_t>(h) & mask;
        bool repeat = false;
        for (; slots[s] != kEmpty; s = (s + 1) & mask) {
            if ((slots[s] >> 32 << 32) != tag) continue;
            const auto [c, d] = canonical(segments[static_cast<std::uint32_t>(slots[s])]);
            if (c == a && d == b) {
                repeat = true;
                break;
            }
        }
        if (repeat) continue;
        segments[kept] = segments[i];
        slots[s] = tag | kept;
        ++kept;
    }
    segments.resize(kept);
}

}  // namespace casteljau::map_detail
