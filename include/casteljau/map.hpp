// casteljau/map.hpp: drawing MapData (geojson.hpp) through a MapProjection (projection.hpp) onto a
// Pixmap: the map stage above canvas.
//
// Pipeline position: MapData (lon/lat) --antimeridian split--> project --fit (Affine to pixels)-->
// Path per feature (pixel space) --> fills composited seamlessly (SeamlessCompositor,
// seamless.hpp) or one by one (source-over), then strokes, then the result onto the background.
//
// Coordinates: positions are longitude/latitude degrees; projected coordinates are y-up; the
// MapFrame maps them to pixel space (x right, y down, pixel (i, j) = [i, i+1) x [j, j+1)).
//
// Antimeridian rule: within a ring or line, a segment whose longitudes differ by more than 180
// degrees crosses the antimeridian the short way round. Such a ring is unwrapped (longitudes made
// continuous), cut at every odd multiple of 180 degrees, and each piece shifted back into
// [-180, 180], so no band streaks across the map. A ring whose unwrapped longitudes do not return
// to their start (it winds around a pole, as Antarctica's does when drawn without its seam) is
// closed along the pole it encloses (the one on the side of its mean latitude). Lines are cut the
// same way. The split happens in longitude/latitude before projecting, so it is right for every
// projection centred on the Greenwich meridian; a PROJ projection with another +lon_0 is not
// re-cut at its own edge.
//
// Winding: every polygon's exterior is drawn with one orientation and its holes with the other,
// so the nonzero rule gives holes whatever the file's ring order (RFC 7946 asks for
// counter-clockwise exteriors, many files do not follow it).
//
// Strokes: all stroke outlines of one style layer are filled as ONE path with the nonzero rule.
// Polygon rings first go through SharedBorders (below), in feature order, so a border shared by two
// countries is stroked once; the rasterizer computes what overlap is left (where borders meet)
// exactly, so a border is never drawn twice darker. Lines (LineString) are stroked with the stroke
// colour, or with the fill colour when the layer has no stroke. Points are disks of point_radius
// pixels filled like polygons.
//
// Thread-safety: free functions; a MapProjection must not be shared between threads (clone it).
// render_map() works on up to MapOptions::threads threads of the process-wide pool
// (casteljau/threads.hpp; each with a clone of the projection) and returns when they are done;
// MapData is only read. A MapCache (MapOptions::cache) is written by the renders that use it and
// may be shared by renders of its map on several threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "casteljau/geojson.hpp"
#include "casteljau/paint.hpp"
#include "casteljau/projection.hpp"
#include "casteljau/raster.hpp"
#include "casteljau/stroke.hpp"

namespace casteljau {

// Which features a style layer draws: all (property empty), or those whose property compares.
struct MapFilter {
    enum class Op { All, Equals, NotEquals, In, Less, Greater, Has } op = Op::All;
    std::string property;
    std::vector<PropertyValue> values;  // one for Equals/NotEquals/Less/Greater, any number for In
    bool matches(const Feature& f) const;
};

// A numeric colour ramp: values at or below `min` get min_color, at or above `max` max_color,
// linear in between (sRGB components).
struct ColorRamp {
    double min = 0, max = 1;
    Color min_color = Color::white(), max_color = Color::black();
    Color at(double v) const;
};

struct MapLayerStyle {
    MapFilter filter;
    std::optional<Color> fill = Color::black();  // nullopt: no fill
    std::string fill_by;                         // property giving the fill colour
    std::optional<ColorRamp> ramp;               // numeric fill_by; otherwise categorical palette
    std::vector<Color> palette;                  // categorical colours (empty: the built-in 12)
    std::optional<Color> stroke;                 // nullopt: no stroke
    double stroke_width = 1;                     // pixels
    double opacity = 1;                          // multiplies fill and stroke alpha
    // The fill of one feature (nullopt: not filled). A categorical value picks palette entry
    // FNV-1a(value text) mod size, the same colour for the same value in every render and tile.
    std::optional<Color> fill_for(const Feature& f) const;
};

struct MapStyle {
    Color background = Color::transparent();
    std::vector<MapLayerStyle> layers = {MapLayerStyle{}};  // drawn in order
    LineJoin join = LineJoin::Round;
    LineCap cap = LineCap::Round;
    double miter_limit = 4;
    double point_radius = 3;  // pixels
};

// Reads a style file: {"background": C, "point_radius": R, "line_join": J, "line_cap": C,
//  "layers": [{"filter": {"property": P, "==" | "!=" | "<" | ">": V | "in": [V...] | "has": true},
//              "fill": C | null, "fill_by": P, "ramp": [[MIN, C], [MAX, C]], "palette": [C...],
//              "stroke": C | null, "width": W, "opacity": O}, ...]}. Throws Error(Parse) naming the
// JSON path.
MapStyle read_map_style(std::string_view json);

// The default of MapOptions::simplify (pixels), chosen by measuring coverage against the exact
// rendering of the original geometry (bench/map_accuracy): on Natural Earth 10m and
// countries-land-10km at 4096 x 2048 and 256 x 128, fill and 0.8 px stroke, it moves coverage by
// at most 0.14/255 on average and 7/255 in any pixel (the worst: Natural Earth at 256 px, along
// fjords, where a border passes one pixel several times and each pass may move by the bound);
// 1/64 px moved fills by up to 7/255 too, 1/50 px by 11/255.
inline constexpr double kDefaultMapSimplify = 0.0125;

namespace map_detail {
struct MapCacheAccess;
}  // namespace map_detail

// What render_map learns about a map that holds for more than one frame, kept for the renders
// that follow, as GEOS's prepared geometries keep their indexes (for a server or a viewer that
// draws the same map again; the tile pyramid keeps its own simplified copy per zoom level):
//   - for each polygon feature, the boxes of the segments near which its fill may overlap itself
//     (find_overlap_region, raster.hpp), or the proof that there are none. The first render that
//     fills a feature finds them (that render takes 1.3 to 1.8 times as long as one without a
//     cache: countries-land-10km, Natural Earth 10m at 4096 px); later renders, in any frame,
//     confine the exact overlap check to those boxes instead of running it over every boundary
//     pixel of the feature;
//   - the data simplified to an output's resolution (MapOptions::simplify), for each of the last
//     four scales drawn (the linear part of MapFrame::to_pixel: every window and offset of one
//     scale shares it), with the analyses of that copy; and the border nodes and features' bounds
//     that simplifying and leaving features out need.
// Measured in BENCHMARKS.md (countries-land-10km, later renders: 0.8x the fill's time without a
// cache at 4096 px, 0.4x at 256 px).
// The pixels are the same as without a cache, to rounding: a pixel the analysis proves plain
// where the overlap check would compute it again may land on the neighbouring level.
// A cache serves one MapData, drawn through projections with one spec(): render_map throws
// Error(InvalidArgument) when it is given other data (another object, or another number of
// features) or another projection. The data must not change while the cache serves them.
// Memory: a few bytes per feature and 32 per box kept, plus each kept simplified copy (at most
// the data's positions).
// Thread-safety: renders of the same map on several threads may share one cache.
class MapCache {
public:
    MapCache();
    ~MapCache();
    MapCache(const MapCache&) = delete;
    MapCache& operator=(const MapCache&) = delete;
    // Features whose analysis is kept.
    std::size_t kept() const;

private:
    friend struct map_detail::MapCacheAccess;
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

struct MapOptions {
    int width = 0;             // pixels, required (>= 1)
    int height = 0;            // 0: from the extent's aspect ratio
    std::optional<Rect> bbox;  // degrees: x0 = west, y0 = south, x1 = east, y1 = north
    double padding = 0;        // pixels on each side
    bool seamless = true;      // false: each fill source-over on its own (--separate)
    FillRule fill_rule = FillRule::NonZero;
    double tolerance = kDefaultTolerance;
    // Geometry at the image's resolution: before anything is drawn, each ring and line is reduced
    // (Douglas-Peucker in pixel space) to the positions that keep it within `simplify` pixels of the
    // original, so the cost grows with the image's pixels, not with the data's positions. A border
    // shared by two features (the same positions in both rings, in either direction) is reduced to
    // the same positions in both, so fills stay seamless and shared borders are still stroked once.
    // Bound: the simplified rings and lines lie within `simplify` pixels of the original ones
    // (Hausdorff distance), with the projection's straight steps drawn as they are; every ring keeps
    // at least three distinct positions. A pixel's coverage moves by at most `simplify` times the
    // length of border inside it, plus rounding. 0: draw every position. Data holding at most a
    // quarter of a position per pixel of their projected extent at the output's scale are drawn
    // as they are whatever `simplify` says: the few positions an output that fine cannot resolve
    // cost less to draw than to find (with a projection through PROJ, whose long steps the
    // simplification bounds, the data are always simplified).
    double simplify = kDefaultMapSimplify;
    // Fills only: recompute pixels where a feature's own edges overlap (self-intersecting or
    // overlapping rings) exactly. Off: plain accumulation, about 3x faster on dense data (Natural
    // Earth 10m) and still exact for valid polygons (simple rings, holes inside their exterior),
    // whose winding numbers stay within 0..1. Strokes are always exact (their outlines overlap).
    bool exact_overlaps = true;
    // Strokes at most 64 px wide with round joins and caps: drawn from their segments as the union
    // of capsules (casteljau/round_stroke.hpp), whose cost grows with the pixels they cover, within
    // that header's bound of the exact union (1/64 per horizontal border through a pixel; measured
    // in BENCHMARKS.md). False: through their outlines, exact to rounding, at a cost that grows with
    // how often the outline folds inside a pixel (thousands of times on a small world map) and with
    // its overlaps' exact cells.
    bool sampled_strokes = true;
    // Threads that project and draw (0: all of the pool, casteljau/threads.hpp; more than the
    // pool's size get the pool's size; at most 256). The image is cut into horizontal
    // bands by its height alone, so the pixels are the same whatever the number of threads.
    int threads = 0;
    // Fills' analyses kept across renders of the same map (MapCache above); nullptr: none.
    MapCache* cache = nullptr;
};

// Projected space -> pixel space, and the image size.
struct MapFrame {
    Affine to_pixel;
    int width = 0, height = 0;
};

// The frame of the options: the bbox mapped exactly onto the image (padding inside it when asked),
// or the projected extent of the data plus padding with the aspect ratio kept (centred).
// Throws Error(InvalidData) when there is nothing to fit (no positions and no bbox),
// Error(InvalidArgument) for a bad bbox (west >= east, south >= north, outside the globe).
MapFrame fit_map(const MapData& data, const MapProjection& proj, const MapOptions& opts);

// Draws the map onto `target` (its own size), background first.
void render_map(const MapData& data, const MapProjection& proj, const MapFrame& frame, const MapStyle& style,
                const MapOptions& opts, Pixmap& target);
// The number of threads MapOptions::threads gets: at most the pool's size (casteljau/threads.hpp),
// all of it for 0.
// Throws Error(InvalidArgument) outside 0..256.
int map_threads(int requested);
// Convenience: fit + a new Pixmap + render.
Pixmap render_map(const MapData& data, const MapProjection& proj, const MapStyle& style, const MapOptions& opts);

// Shared borders, each stroked once. Neighbouring polygons repeat their common border in both
// rings; filling the union of both strokes is exact (the rasterizer resolves the overlap) but costs
// the exact computation along every border. SharedBorders removes what an earlier ring already
// holds, so each border is stroked once and the union stays the same:
//   - a segment (two consecutive positions, in either direction) that an earlier ring (or earlier in
//     the same ring) has is dropped;
//   - a join (a position with its two neighbours, in either order) that an earlier ring (or the same
//     ring, earlier) has is not drawn again; one that is new keeps both of its segments, dropped
//     or not;
//   - what is left comes out as open chains (stroke them with Butt caps: every chain end lies on a
//     segment drawn in full by another chain, or at a join drawn elsewhere) and as rings that keep
//     everything, closed as they were.
// The stroke of a polyline is the union of one rectangle per segment and one join piece per vertex
// (stroke.hpp), and a join piece depends only on the vertex and its two neighbours, so stroking the
// result with the same width and join, Butt caps, gives the same union as stroking every ring: the
// same pixels, up to rounding. Positions match exactly or not at all (no snapping): rings from one
// file and one projection share their borders bit for bit when the file shares its positions
// (TopoJSON always does).
// Input contours: closed contours of line segments (Path::close) with at least three distinct
// positions, not all within `merge_distance` of the first (pass stroke_merge_distance() of the
// stroke call to come: the stroker draws such a ring as a dot). Every other contour (open, with
// curves such as point disks, or a ring of zero length or of two distinct positions, whose stroke
// depends on the caps) goes to `whole` unchanged, to be stroked with the style's own caps.
// A position within `merge_distance` of the last one kept (or, closing a ring, of the first) is
// taken as that one, as the stroker does: a ring's segments and joins are those the stroker draws.
// Memory: 16 bytes per position added plus two hash tables of 4-byte entries; clear() frees nothing
// but forgets every ring. At most 2^31 positions between clear() calls (Error(Limit)).
// Thread-safety: one object per thread; its methods must not be called concurrently.
class SharedBorders {
public:
    // Appends to `chains` what is left of the rings of `rings` that no earlier call holds, and to
    // `whole` the contours it does not take (see above).
    void add(const Path& rings, Path& chains, Path& whole, double merge_distance = 0);
    void clear();

private:
    bool add_ring(std::span<const Point> ring, Path& out, double merge_distance);
    std::uint32_t* find_segment(std::uint32_t a);
    std::uint32_t* find_join(std::uint32_t v);
    void grow(std::vector<std::uint32_t>& table, bool joins);
    std::vector<Point> pts_;                       // each ring: its n positions, then its first two again
    std::vector<std::uint32_t> segments_, joins_;  // open addressing: index into pts_ + 1, 0 empty
    std::size_t segment_count_ = 0, join_count_ = 0;
    std::vector<Point> ring_;
    std::vector<std::uint8_t> flags_;
};

// The antimeridian split of one closed ring or one line (lon/lat), see the rule above. Appends the
// pieces to `out` (rings closed implicitly, without repeating the first position).
void split_ring_at_antimeridian(std::span<const Point> ring, std::vector<std::vector<Point>>& out);
void split_line_at_antimeridian(std::span<const Point> line, std::vector<std::vector<Point>>& out);

}  // namespace casteljau
