// Internal: flattening with culling, used by the rasterizer.
#pragma once
#include "casteljau/flatten.hpp"

namespace casteljau {
// As flatten(), but a curve whose transformed control points all lie outside `cull` (when given) is
// replaced by its chord: outside the clip rectangle only a segment's end points matter to coverage.
void flatten_culled(const Path& path, const Affine& m, double tolerance, const Rect* cull, Polyline& out);
}  // namespace casteljau
