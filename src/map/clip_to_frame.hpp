// Map stage (internal): rings and lines cut to a rectangle around the image before they are
// stroked, so that a feature much larger than the image (a country on a tile of zoom 5) costs what
// its part near the image costs.
//
// The rectangle is the image grown by at least the farthest any stroke piece reaches from its
// segment (half the width times the miter limit, a cap, a pixel of anti-aliasing): whatever the
// cut adds or removes lies outside it, so the stroke's union inside the image stays the same.
//   - A ring is clipped to the rectangle (Sutherland-Hodgman): inside it the ring is unchanged;
//     the edges the clip adds run along the rectangle, outside the image's reach.
//   - A line keeps the steps whose bounding box meets the rectangle, as chains; a chain ends at a
//     position outside the rectangle, so its caps do not reach the image.
// A crossing with the rectangle's side is computed from the step's ends in a fixed order (the
// lesser position first), so two rings that share the step cut it at the same point.
// Thread-safety: free functions.
#pragma once

#include <span>
#include <vector>

#include "casteljau/geometry.hpp"
#include "casteljau/path.hpp"

namespace casteljau::map_detail {

// The ring (closed implicitly) clipped to `r` into `out` (empty when nothing is left).
void clip_ring(std::span<const Point> ring, const Rect& r, std::vector<Point>& out);

// Appends to `out` the chains of `line` whose steps reach `r`.
void clip_line(std::span<const Point> line, const Rect& r, Path& out);

// Whether every position lies inside `r` (nothing to cut).
bool inside(std::span<const Point> pts, const Rect& r);

}  // namespace casteljau::map_detail
