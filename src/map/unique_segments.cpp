// Map stage: dropping repeated segments (unique_segments.hpp) with open-addressing tables of
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
constexpr std::uint64_t kEmptySlot = std::numeric_limits<std::uint64_t>::max();

// Repeats have equal hashes, so the segments can be split into parts by the hash's top bits and
// each part searched on its own, in a table small enough to stay in the first-level cache (about
// kPartSegments segments, 16 KB): one table for all would miss the cache at nearly every probe
// once it outgrows it (a world map at 1024 px has 300,000 segments).
constexpr std::size_t kPartSegments = 1024;
constexpr int kMaxPartBits = 16;

int part_bits(std::size_t n) {
    int bits = 0;
    while (bits < kMaxPartBits && (n >> bits) > 2 * kPartSegments) ++bits;
    return bits;
}

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
    std::vector<std::uint64_t> hash(n);
    for (std::size_t i = 0; i < n; ++i) {
        const auto [a, b] = canonical(segments[i]);
        hash[i] = mix(hash_point(a) ^ (hash_point(b) >> 1));
    }
    // The segments' indices grouped by their parts, in order within each.
    const int bits = part_bits(n);
    auto part = [bits](std::uint64_t h) {
        return bits == 0 ? std::size_t{0} : static_cast<std::size_t>(h >> (64 - bits));
    };
    std::vector<std::uint32_t> end(std::size_t{1} << bits, 0);
    struct Entry {
        std::uint64_t hash;
        std::uint32_t index;
    };
    std::vector<Entry> order(n);  // hashes beside indices: each part is then read in sequence
    for (std::uint64_t h : hash) ++end[part(h)];
    std::uint32_t sum = 0;
    for (std::uint32_t& e : end) {
        sum += e;
        e = sum - e;  // the part's start, moved to its end by the pass below
    }
    for (std::size_t i = 0; i < n; ++i) order[end[part(hash[i])]++] = {hash[i], static_cast<std::uint32_t>(i)};
    // Each part's table: a slot holds a kept segment's index and 32 further bits of its hash, so a
    // probe reads the segment itself only when those agree, nearly always a repeat.
    std::vector<std::uint8_t> repeat(n, 0);
    std::vector<std::uint64_t> slots;
    std::size_t begin = 0;
    for (const std::uint32_t stop : end) {
        const std::size_t mask = std::bit_ceil(2 * (stop - begin)) - 1;
        slots.assign(mask + 1, kEmptySlot);
        for (std::size_t k = begin; k < stop; ++k) {
            const auto [h, i] = order[k];
            const std::uint64_t tag = (h >> 24) << 32;
            std::size_t s = static_cast<std::size_t>(h) & mask;
            for (; slots[s] != kEmptySlot; s = (s + 1) & mask) {
                if ((slots[s] >> 32 << 32) != tag) continue;
                if (canonical(segments[static_cast<std::uint32_t>(slots[s])]) == canonical(segments[i])) {
                    repeat[i] = 1;
                    break;
                }
            }
            if (!repeat[i]) slots[s] = tag | i;
        }
        begin = stop;
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < n; ++i)
        if (!repeat[i]) segments[kept++] = segments[i];
    segments.resize(kept);
}

}  // namespace casteljau::map_detail
