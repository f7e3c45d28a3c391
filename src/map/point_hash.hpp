// Internal to the map stage: hashing of positions by their exact bits, for the tables that find
// shared positions and segments (border_nodes.cpp, shared_borders.cpp).
#pragma once

#include <bit>
#include <cstdint>

#include "casteljau/geometry.hpp"

namespace casteljau::map_detail {

// A 64-bit finalizer (MurmurHash3's): every input bit reaches every output bit.
inline std::uint64_t mix(std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
    return h;
}

// Equal positions hash equally: + 0.0 turns -0.0 into +0.0, which compares equal to it.
inline std::uint64_t hash_point(Point p) {
    return mix(std::bit_cast<std::uint64_t>(p.x + 0.0) ^ mix(std::bit_cast<std::uint64_t>(p.y + 0.0)));
}

}  // namespace casteljau::map_detail
