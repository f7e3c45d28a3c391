/* casteljau/casteljau_map.h: maps and tile pyramids through the C API (plain C99; casteljau.h
 * includes it).
 *
 * Map data comes from GeoJSON (RFC 7946), newline-delimited GeoJSON or TopoJSON
 * (casteljau/geojson.hpp); it is drawn through a projection with a style into an image, onto a
 * canvas, or as an XYZ pyramid of Web Mercator tiles into a folder (DIR/z/x/y.png) or an MBTiles
 * file (casteljau/map.hpp, casteljau/tiles.hpp). Styles and options are those of `casteljau map`
 * and `casteljau tiles`; each setter names the option it stands for.
 *
 * Coordinates: positions are longitude/latitude degrees; the projection and the fit (the data's
 * extent, or the bbox) map them onto the image, x right, y down. Tile (z, x, y) is the XYZ scheme.
 *
 * Conventions, errors and ownership are those of casteljau.h: every handle here is the caller's,
 * released by its destroy function (which accepts NULL); a NULL handle or out-parameter is
 * CASTELJAU_ERROR_INVALID_ARGUMENT unless a comment says NULL means the defaults.
 * Thread-safety: map data is immutable once read: several threads may draw one map at once.
 * Styles and options belong to one thread at a time, and are only read while a map is drawn.
 * Drawing runs on the process-wide pool (casteljau_set_thread_count) and returns when it is done;
 * the pixels do not depend on the number of threads.
 */
#ifndef CASTELJAU_MAP_H
#define CASTELJAU_MAP_H

#include "casteljau.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct casteljau_map casteljau_map;
typedef struct casteljau_map_style casteljau_map_style;
typedef struct casteljau_map_options casteljau_map_options;
typedef struct casteljau_map_cache casteljau_map_cache;
typedef struct casteljau_tile_options casteljau_tile_options;

/* Map data: features with their geometries (lon/lat) and properties. `layer` selects one object
 * of a TopoJSON topology by name (--layer; NULL or "": every object); a layer for GeoJSON is
 * CASTELJAU_ERROR_INVALID_ARGUMENT. casteljau_map_load chooses the reader by the file name (.geojsonl, .geojsons,
 * .ndjson, .geojsonseq: GeoJSON lines; .topojson: TopoJSON) and otherwise by content, as
 * casteljau_map_parse always does ({"type": "Topology"}: TopoJSON; one JSON object per line:
 * GeoJSON lines; else GeoJSON). CASTELJAU_ERROR_PARSE for malformed JSON or a member of the wrong
 * type, CASTELJAU_ERROR_INVALID_DATA for positions out of range or rings that are not closed (the
 * message names the JSON path), CASTELJAU_ERROR_LIMIT past casteljau_limits.map_positions,
 * CASTELJAU_ERROR_IO for a file that cannot be read. */
CASTELJAU_API casteljau_status casteljau_map_load(const char* path, const char* layer, casteljau_map** out);
CASTELJAU_API casteljau_status casteljau_map_parse(const char* text, size_t size, const char* layer,
                                                   casteljau_map** out);
CASTELJAU_API void casteljau_map_destroy(casteljau_map* map);
CASTELJAU_API size_t casteljau_map_feature_count(const casteljau_map* map); /* 0 for NULL */

/* Styles. A new style is the command line's default: black fill, no stroke, stroke width 1,
 * opacity 1, round joins and caps, a transparent background, point radius 3. NULL when out of
 * memory. casteljau_map_style_load and _parse read a style file (--style; its format is
 * read_map_style's in casteljau/map.hpp: layers with filters, fills by property, ramps, palettes);
 * CASTELJAU_ERROR_PARSE names the JSON path of an error. */
CASTELJAU_API casteljau_map_style* casteljau_map_style_create(void);
CASTELJAU_API casteljau_status casteljau_map_style_load(const char* path, casteljau_map_style** out);
CASTELJAU_API casteljau_status casteljau_map_style_parse(const char* json, casteljau_map_style** out);
CASTELJAU_API void casteljau_map_style_destroy(casteljau_map_style* style);
/* Setters for every layer of the style (a new style has one layer; a style file may have more). */
CASTELJAU_API casteljau_status casteljau_map_style_set_fill(casteljau_map_style* style,
                                                            const casteljau_color* fill); /* --fill; NULL: none */
CASTELJAU_API casteljau_status casteljau_map_style_set_stroke(casteljau_map_style* style,
                                                              const casteljau_color* stroke); /* --stroke; NULL: none */
CASTELJAU_API casteljau_status casteljau_map_style_set_stroke_width(casteljau_map_style* style,
                                                                    double width); /* --stroke-width: 0 to 1e4 px */
CASTELJAU_API casteljau_status casteljau_map_style_set_opacity(casteljau_map_style* style,
                                                               double opacity); /* --opacity: 0 to 1 */
/* --fill-by: the property whose value picks each feature's fill (a categorical palette, the same
 * colour for the same value in every render and tile; or the ramp below); NULL or "": the fill. */
CASTELJAU_API casteljau_status casteljau_map_style_set_fill_by(casteljau_map_style* style, const char* property);
/* --ramp MIN:COLOR,MAX:COLOR: a numeric fill-by property, linear in sRGB between the two colours
 * (clamped outside); needs min < max, both finite. */
CASTELJAU_API casteljau_status casteljau_map_style_set_ramp(casteljau_map_style* style, double min,
                                                            casteljau_color min_color, double max,
                                                            casteljau_color max_color);
/* Setters for the whole style. */
CASTELJAU_API casteljau_status casteljau_map_style_set_background(casteljau_map_style* style,
                                                                  casteljau_color background); /* --background */
CASTELJAU_API casteljau_status casteljau_map_style_set_line_join(casteljau_map_style* style,
                                                                 casteljau_line_join join); /* --line-join */
CASTELJAU_API casteljau_status casteljau_map_style_set_line_cap(casteljau_map_style* style,
                                                                casteljau_line_cap cap); /* --line-cap */
CASTELJAU_API casteljau_status casteljau_map_style_set_point_radius(casteljau_map_style* style,
                                                                    double radius); /* --point-radius: 0 to 1e4 px */

/* Options of one map image. A new object: no size (casteljau_map_render_image needs one), the
 * equirectangular projection, no bbox, no padding, seamless fills, exact overlaps, tolerance
 * 0.015 px. NULL when out of memory. */
CASTELJAU_API casteljau_map_options* casteljau_map_options_create(void);
CASTELJAU_API void casteljau_map_options_destroy(casteljau_map_options* options);
/* --width (1 and up) and --height (0: from the extent's aspect ratio). */
CASTELJAU_API casteljau_status casteljau_map_options_set_size(casteljau_map_options* options, int width, int height);
/* --projection: "equirectangular", "mercator", a PROJ string ("+proj=robin") or a CRS
 * ("EPSG:3035"). CASTELJAU_ERROR_INVALID_ARGUMENT, naming it, for one PROJ does not know. */
CASTELJAU_API casteljau_status casteljau_map_options_set_projection(casteljau_map_options* options,
                                                                    const char* projection);
/* --bbox W,S,E,N: the extent, in degrees, mapped exactly onto the image; needs west < east and
 * -90 <= south < north <= 90. */
CASTELJAU_API casteljau_status casteljau_map_options_set_bbox(casteljau_map_options* options, double west, double south,
                                                              double east, double north);
CASTELJAU_API casteljau_status casteljau_map_options_set_padding(casteljau_map_options* options,
                                                                 double pixels); /* --padding: 0 to 1e5 */
/* Nonzero: --separate (each fill on its own with source-over: seams between neighbours). */
CASTELJAU_API casteljau_status casteljau_map_options_set_separate(casteljau_map_options* options, int separate);
/* 0: --no-exact-overlaps (fills by plain accumulation, faster, exact for valid polygons). */
CASTELJAU_API casteljau_status casteljau_map_options_set_exact_overlaps(casteljau_map_options* options, int exact);
CASTELJAU_API casteljau_status casteljau_map_options_set_tolerance(casteljau_map_options* options,
                                                                   double tolerance); /* --tolerance: 1e-4 to 10 px */

/* What one render learns about a map, kept for the next renders of the same map in any frame (a
 * server or a viewer drawing one map again; MapCache in casteljau/map.hpp): where each feature's
 * fill may overlap itself, so that the exact overlap check looks only there, and the data
 * simplified to each of the last four scales drawn. The pixels are those of a render without a
 * cache, to rounding (at most one level). The first render that fills a feature pays for its
 * analysis (1.3 to 1.8 times a render without a cache); the later ones draw faster. A cache
 * serves the first map and projection it is drawn with: drawing another through it is
 * CASTELJAU_ERROR_INVALID_ARGUMENT. Several threads drawing the same map may share one cache; it
 * must outlive every render that uses it and the map must outlive the cache's use. NULL when out
 * of memory. */
CASTELJAU_API casteljau_map_cache* casteljau_map_cache_create(void);
CASTELJAU_API void casteljau_map_cache_destroy(casteljau_map_cache* cache);
/* The cache the options' renders fill and read; NULL: none (the default). */
CASTELJAU_API casteljau_status casteljau_map_options_set_cache(casteljau_map_options* options,
                                                               casteljau_map_cache* cache);

/* What `casteljau map` writes: a new image of the options' size with the map drawn, background
 * first. `style` NULL: the default style. CASTELJAU_ERROR_INVALID_DATA when there is nothing to
 * fit (no position and no bbox). */
CASTELJAU_API casteljau_status casteljau_map_render_image(const casteljau_map* map, const casteljau_map_style* style,
                                                          const casteljau_map_options* options, casteljau_image** out);
/* The same image drawn onto `canvas` with its top-left corner at the origin of user space, one
 * pixel per user unit, under the canvas's transform, clip, opacity and blend mode. Options
 * without a size take the canvas's width and height. */
CASTELJAU_API casteljau_status casteljau_map_render(const casteljau_map* map, const casteljau_map_style* style,
                                                    const casteljau_map_options* options, casteljau_canvas* canvas);

/* Tile pyramids. A new object: zoom 0 to 0, 256 px tiles at scale 1, metatiles of 8 x 8 tiles
 * with a 64 px buffer, every tile written, no resume, shard 0 of 1, MBTiles name "casteljau",
 * seamless fills, exact overlaps, tolerance 0.015 px. NULL when out of memory. */
CASTELJAU_API casteljau_tile_options* casteljau_tile_options_create(void);
CASTELJAU_API void casteljau_tile_options_destroy(casteljau_tile_options* options);
CASTELJAU_API casteljau_status casteljau_tile_options_set_zoom(casteljau_tile_options* options, int min_zoom,
                                                               int max_zoom); /* --zoom MIN-MAX: 0 to 24 */
/* --tile-size (256 or 512) and --scale (1 to 4: pixels per tile side are size x scale, and the
 * buffer, stroke widths and point radii are multiplied by the scale too). */
CASTELJAU_API casteljau_status casteljau_tile_options_set_tile_size(casteljau_tile_options* options, int size,
                                                                    int scale);
CASTELJAU_API casteljau_status casteljau_tile_options_set_metatile(casteljau_tile_options* options,
                                                                   int tiles); /* --metatile: 1 to 64 */
CASTELJAU_API casteljau_status casteljau_tile_options_set_buffer(casteljau_tile_options* options,
                                                                 int pixels); /* --buffer: 0 to 1024 */
CASTELJAU_API casteljau_status casteljau_tile_options_set_skip_empty(casteljau_tile_options* options,
                                                                     int skip); /* --skip-empty */
CASTELJAU_API casteljau_status casteljau_tile_options_set_resume(casteljau_tile_options* options,
                                                                 int resume); /* --resume (folders only) */
/* --shard I/N: render share `shard` (0-based) of `shards`, 1 to 1000000. */
CASTELJAU_API casteljau_status casteljau_tile_options_set_shard(casteljau_tile_options* options, int shard, int shards);
CASTELJAU_API casteljau_status casteljau_tile_options_set_name(casteljau_tile_options* options,
                                                               const char* name); /* --name (MBTiles metadata) */
CASTELJAU_API casteljau_status casteljau_tile_options_set_separate(casteljau_tile_options* options, int separate);
CASTELJAU_API casteljau_status casteljau_tile_options_set_exact_overlaps(casteljau_tile_options* options, int exact);
CASTELJAU_API casteljau_status casteljau_tile_options_set_tolerance(casteljau_tile_options* options, double tolerance);

typedef struct casteljau_tile_stats {
    uint64_t metatiles;        /* rendered */
    uint64_t written;          /* tiles written */
    uint64_t skipped_empty;    /* tiles showing only the background, not written (skip_empty) */
    uint64_t skipped_existing; /* tiles already there (resume) */
} casteljau_tile_stats;

/* Called after each metatile with the number done and the total of this shard; return 0 to go on,
 * anything else to stop. Called from one thread at a time, not necessarily the caller's, with
 * `user` as given; it must not call casteljau_set_thread_count. */
typedef int (*casteljau_tile_progress)(uint64_t done, uint64_t total, void* user);

/* What `casteljau tiles MAP -o OUTPUT` writes: a Web Mercator pyramid into the folder OUTPUT
 * (OUTPUT/z/x/y.png, folders created, each file written atomically) or, when OUTPUT ends in
 * ".mbtiles", into that MBTiles file (built under a temporary name and renamed when complete).
 * `style` NULL: the default style; `progress` and `stats` may be NULL. A progress callback that
 * stops the pyramid gives CASTELJAU_ERROR_CANCELLED: the tiles already written to a folder stay,
 * an MBTiles file is not created. CASTELJAU_ERROR_IO when a tile or the file cannot be written
 * (SQLite, libsqlite3.so.0, is loaded for the first MBTiles file). */
CASTELJAU_API casteljau_status casteljau_map_render_tiles(const casteljau_map* map, const casteljau_map_style* style,
                                                          const casteljau_tile_options* options, const char* output,
                                                          casteljau_tile_progress progress, void* user,
                                                          casteljau_tile_stats* stats);

#ifdef __cplusplus
}
#endif

#endif /* CASTELJAU_MAP_H */
