// Map stage (internal): a MapData's rings and lines reduced to what one output resolution can show.
//
// Pipeline position: between reading and drawing. Each ring and line is projected and mapped to
// pixels (to_pixel), cut into runs at its border nodes (border_nodes.hpp), and each run is
// simplified by RunSimplifier (simplify_polyline.hpp) at `tolerance` pixels, in a canonical
// direction (from the lesser end position to the greater, x then y; ties by the second position),
// so a border shared by two features keeps the same positions in both and fills stay seamless.
// The result keeps positions of the input (a subset, in longitude/latitude, rings still closed),
// so it is drawn like the input: antimeridian cut, projection and densifying happen as before.
//
// Bound: with a projection that keeps lon/lat segments straight (equirectangular, Web Mercator)
// the simplified rings and lines lie within `tolerance` pixels of the original ones (Hausdorff
// distance, per run; see simplify_polyline.hpp). With a projection that bends them (PROJ), no kept
// step spans more than kDensifyDegrees, so the renderer draws it as its chord, and the same bound
// holds. No kept step spans more than 180 degrees of longitude, which the renderer would take for
// a crossing of the antimeridian. Distances are measured through to_pixel without its translation,
// so every frame that differs from it by a translation (the metatiles of one zoom, a window of a
// larger map) keeps the same positions.
//
// Every ring keeps at least three distinct positions when it had them, so no island vanishes (its
// fill and its stroke stay within the bound of the original's).
// Thread-safety: free function; runs on up to `threads` threads of the pool, each with a clone of
// the projection.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "casteljau/geojson.hpp"
#include "casteljau/map.hpp"
#include "casteljau/projection.hpp"
#include "map/border_nodes.hpp"

namespace casteljau::map_detail {

// Densify step for projections that bend straight lon/lat segments (degrees): the renderer adds a
// position every kDensifyDegrees along a longer step.
inline constexpr double kDensifyDegrees = 1.0;

struct SimplifiedMap {
    // The geometries of MapData::features[i]; empty when the data are drawn as they are
    // (bounds_only).
    std::vector<std::vector<Geometry>> features;
    // The projected bounds of each feature's positions (before to_pixel); the whole plane for a
    // feature with a step across the antimeridian (the renderer's cut may add positions outside).
    std::vector<Rect> bounds;
    std::size_t positions = 0;                              // kept, in all
    Rect extent{INFINITY, INFINITY, -INFINITY, -INFINITY};  // of every projected position (bounds_only)
};

SimplifiedMap simplify_map(const MapData& data, const BorderNodes& nodes, const MapProjection& proj,
                           const Affine& to_pixel, double tolerance, int threads);

// The data as they are (no features: draw the data's own geometries), with every feature's
// projected bounds and the data's extent, for the renderer to leave out what cannot reach the
// image. Depends on no output: one copy serves every zoom.
SimplifiedMap bounds_only(const MapData& data, const MapProjection& proj, int threads);

// Simplifying pays for an output when the data hold more than this many positions per pixel of
// their projected extent: below it, the positions the output cannot resolve are too few to save
// the cost of finding them. Measured with `casteljau map`, fill and 0.8 px stroke:
// countries-land-10km at 4096 and 1024 px (0.01 and 0.14 per pixel) draws faster as it is,
// Natural Earth at 2048 px (0.27) costs the same either way, and at 1024 px (1.1) a quarter less
// simplified. Sparser data are drawn as they are, every position kept.
inline constexpr double kSimplifyDensity = 0.25;

// Whether the data whose bounds_only copy is `b` are worth simplifying for an output of to_pixel's
// scale (its translation does not matter: every metatile of a zoom decides alike). Always with a
// projection that bends lon/lat steps, whose long steps the simplifier bounds.
bool worth_simplifying(const SimplifiedMap& b, const MapProjection& proj, const Affine& to_pixel);
// The same decision from the data themselves, without projecting every position: a projection
// that keeps lon/lat lines straight maps longitude and latitude each on its own, monotonically,
// so the projected extent is that of the data's lon/lat bounds.
bool worth_simplifying(const MapData& data, const MapProjection& proj, const Affine& to_pixel);

// render_map (casteljau/map.hpp) drawing `simplified` in place of the data's geometries (made for
// frame.to_pixel, or for a translation of it), whatever opts.simplify says. Features whose bounds
// lie outside the image by more than any stroke or point reaches are not drawn.
void render_simplified_map(const MapData& data, const SimplifiedMap& simplified, const MapProjection& proj,
                           const MapFrame& frame, const MapStyle& style, const MapOptions& opts, Pixmap& target);

}  // namespace casteljau::map_detail
