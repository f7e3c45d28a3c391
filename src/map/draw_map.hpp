// Map stage (internal): drawing the features of a map onto a pixmap, layer by layer (what
// render_map and the tile pyramid do once the frame is known).
//
// Features are drawn in chunks of input positions, so that only one chunk's pixel-space paths
// exist at a time: each chunk is projected by all threads (a feature each), then drawn by all
// threads (a horizontal band of the image each). The pixels do not depend on the thread count.
// Thread-safety: draw_map runs on the process-wide pool; concurrent calls need their own targets.
#pragma once

#include "casteljau/map.hpp"
#include "map/map_cache.hpp"
#include "map/simplify_map.hpp"

namespace casteljau::map_detail {

// Draws the layers of `style` onto `target` (the frame's size), background first. `cleared`: the
// target is known to be transparent already (a new Pixmap), so a transparent background need not
// be written. `simplified`: the geometry to draw in place of the data's (nullptr: the data's,
// simplified here when opts.simplify asks). `cache`: a MapCache's contents (map_cache.hpp), read
// when `simplified` is not given: the fills' overlap analyses, and the copy simplified to this
// frame's scale; nullptr: each fill decides alone and the data are simplified here.
// Throws Error(InvalidArgument) for a target of another size or a bad simplify distance.
void draw_map(const MapData& data, const SimplifiedMap* simplified, const MapProjection& proj, const MapFrame& frame,
              const MapStyle& style, const MapOptions& opts, Pixmap& target, bool cleared, KeptMap* cache = nullptr);

}  // namespace casteljau::map_detail
