// Map stage (internal): one copy of each segment, for the strokes drawn as a union of capsules.
//
// Neighbouring polygons repeat their common border in both rings, and a border simplified for one
// output (simplify_map.hpp) keeps the same positions in both. A round stroke's coverage is the
// union of one capsule per segment, whatever the segments' order, direction or repetition, so the
// repeats can go before the capsules are swept: a quarter of a world map's segments at 4096 px.
//
// Segments compare by their exact end positions, in either direction (-0.0 equals +0.0).
// Memory: 25 bytes per segment and a table of 16 KB, for the call's duration.
// Thread-safety: a free function.
#pragma once

#include <vector>

#include "casteljau/round_stroke.hpp"

namespace casteljau::map_detail {

// Removes every segment that repeats an earlier one (the same ends, either way round), keeping
// the first of each in its place and the order of the rest.
void drop_repeated_segments(std::vector<LineSegment>& segments);

}  // namespace casteljau::map_detail
