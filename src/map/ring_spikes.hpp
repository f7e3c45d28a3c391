// Map stage (internal): spikes taken out of a polygon ring before it is filled.
//
// Map data and their simplification to an output's resolution leave rings that step out to a
// position and straight back (A, B, A) or repeat a position. Such a step encloses no area and
// leaves every winding number off the ring unchanged, so the filled coverage is the same without
// it; but the rasterizer's overlap check cannot prove a cell with a fold exact, and computes it
// the slow way. Strokes keep their spikes (a stroked spike has ink).
//
// Positions compare exactly (-0.0 equals +0.0). Cost: linear in the ring's length, in place.
// Thread-safety: a free function.
#pragma once

#include <span>
#include <vector>

#include "casteljau/geometry.hpp"

namespace casteljau::map_detail {

// Removes from closed ring `r` (its last position joins its first; a repeat of the first at the
// end is allowed) every repeated position and every spike, including those across the start and
// those left when an inner one goes (A, B, C, B, A becomes A). Fewer than three positions left:
// the ring is emptied (it enclosed nothing).
void drop_spikes(std::vector<Point>& r);

// The ring `in` mapped by `m` into `out` without its spikes: drop_spikes of the mapped ring, in one
// pass over it.
void map_without_spikes(std::span<const Point> in, const Affine& m, std::vector<Point>& out);

}  // namespace casteljau::map_detail
