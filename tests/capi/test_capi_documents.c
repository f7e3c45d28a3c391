/* The C API's SVG, map, tile and text calls (casteljau_svg.h, casteljau_map.h, casteljau_text.h),
 * compiled as C99: every call made, its results sampled, and bad input (malformed SVG, GeoJSON with
 * a NaN, an unknown projection, a missing font, NULL handles, values out of range) answered with a
 * status and a message. Run under AddressSanitizer (the sanitizer build), it also shows that
 * nothing leaks. Text options are compared with `casteljau text`'s output when its path is given.
 * Usage: test_capi_documents SOURCE_DIR SCRATCH_DIR [CASTELJAU_CLI] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "casteljau/casteljau.h"
#include "casteljau/casteljau_map.h"
#include "casteljau/casteljau_svg.h"
#include "casteljau/casteljau_text.h"
#include "capi_check.h"

static char source[2048], scratch[2048], cli[2048];

static const char* in_source(const char* rel) {
    static char buf[4][4096];
    static int next = 0;
    char* b = buf[next++ % 4];
    snprintf(b, sizeof buf[0], "%s/%s", source, rel);
    return b;
}

static const char* in_scratch(const char* rel) {
    static char buf[4][4096];
    static int next = 0;
    char* b = buf[next++ % 4];
    snprintf(b, sizeof buf[0], "%s/%s", scratch, rel);
    return b;
}

static const uint8_t* pixel(casteljau_image* im, int x, int y) {
    return casteljau_image_data(im) + casteljau_image_stride(im) * (size_t)y + 4 * (size_t)x;
}

static int same_pixels(casteljau_image* a, casteljau_image* b) {
    int y;
    const int w = casteljau_image_width(a), h = casteljau_image_height(a);
    if (w != casteljau_image_width(b) || h != casteljau_image_height(b)) return 0;
    for (y = 0; y < h; ++y)
        if (memcmp(pixel(a, 0, y), pixel(b, 0, y), 4 * (size_t)w) != 0) return 0;
    return 1;
}

/* Whether no channel of a pixel differs by more than `levels`. */
static int close_pixels(casteljau_image* a, casteljau_image* b, int levels) {
    int x, y;
    const int w = casteljau_image_width(a), h = casteljau_image_height(a);
    if (w != casteljau_image_width(b) || h != casteljau_image_height(b)) return 0;
    for (y = 0; y < h; ++y)
        for (x = 0; x < 4 * w; ++x) {
            const int d = (int)pixel(a, 0, y)[x] - (int)pixel(b, 0, y)[x];
            if (d > levels || d < -levels) return 0;
        }
    return 1;
}

static void check_svg(void) {
    casteljau_svg_options* options = casteljau_svg_options_create();
    casteljau_svg *doc = NULL, *text = NULL, *bad = (casteljau_svg*)1;
    casteljau_image *image = NULL, *scaled = NULL, *direct = NULL;
    casteljau_canvas* canvas = NULL;
    double w = 0, h = 0;
    int ow = 0, oh = 0;
    const casteljau_color white = {255, 255, 255, 255}, clear = {0, 0, 0, 0};
    const char* svg_text =
        "<svg xmlns='http://www.w3.org/2000/svg' width='60.5' height='20'>"
        "<text x='2' y='16' font-family='sans-serif' font-size='14'>Svg</text><blink/></svg>";
    CHECK(options != NULL);
    CHECK_OK(casteljau_svg_options_add_font_dir(options, in_source("fonts")));
    CHECK_OK(casteljau_svg_options_add_font_file(options, in_source("fonts/DejaVuSans.ttf")));
    CHECK_OK(casteljau_svg_options_set_system_fonts(options, 0));
    CHECK_OK(casteljau_svg_options_set_font_family(options, CASTELJAU_FAMILY_SANS_SERIF, "DejaVu Sans"));
    CHECK_OK(casteljau_svg_options_set_resources(options, in_source("examples/data")));
    CHECK_OK(casteljau_svg_options_set_resources(options, NULL));

    CHECK_OK(casteljau_svg_load(in_source("examples/data/badge.svg"), NULL, &doc));
    CHECK_OK(casteljau_svg_intrinsic_size(doc, &w, &h));
    CHECK(w == 320 && h == 240);
    CHECK_OK(casteljau_svg_output_size(doc, 0, 0, 0, &ow, &oh));
    CHECK(ow == 320 && oh == 240);
    CHECK_OK(casteljau_svg_output_size(doc, 0, 120, 0, &ow, &oh));
    CHECK(ow == 160 && oh == 120);
    CHECK_OK(casteljau_svg_output_size(doc, 0, 0, 0.5, &ow, &oh));
    CHECK(ow == 160 && oh == 120);
    CHECK(casteljau_svg_warning_count(doc) == 0 && casteljau_svg_warning(doc, 0) == NULL);

    /* render_image at 2x equals rendering onto a white canvas scaled by 2. */
    CHECK_OK(casteljau_svg_render_image(doc, 640, 0, 0, white, &image));
    CHECK(casteljau_image_width(image) == 640 && casteljau_image_height(image) == 480);
    CHECK(pixel(image, 0, 0)[3] == 255);
    CHECK_OK(casteljau_image_create(640, 480, &scaled));
    CHECK_OK(casteljau_canvas_create(scaled, &canvas));
    CHECK_OK(casteljau_canvas_clear(canvas, white));
    CHECK_OK(casteljau_canvas_scale(canvas, 2, 2));
    CHECK_OK(casteljau_svg_render(doc, canvas));
    CHECK(same_pixels(image, scaled));

    /* Text from memory with the fonts of the options; a warning for the unknown element. */
    CHECK_OK(casteljau_svg_parse((const uint8_t*)svg_text, strlen(svg_text), options, &text));
    CHECK(casteljau_svg_warning_count(text) >= 1 && strlen(casteljau_svg_warning(text, 0)) > 0);
    CHECK_OK(casteljau_svg_render_image(text, 0, 0, 0, clear, &direct));
    CHECK(casteljau_image_width(direct) == 61 && casteljau_image_height(direct) == 20);
    {
        int x, y, ink = 0;
        for (y = 0; y < 20; ++y)
            for (x = 0; x < 61; ++x) ink |= pixel(direct, x, y)[3];
        CHECK(ink != 0);
    }

    /* Bad input */
    CHECK_ERROR(casteljau_svg_parse((const uint8_t*)"<svg", 4, NULL, &bad), CASTELJAU_ERROR_PARSE, "");
    CHECK(bad == NULL);
    CHECK_ERROR(
        casteljau_svg_parse((const uint8_t*)"<svg xmlns='http://www.w3.org/2000/svg' width='0'/>", 51, NULL, &bad),
        CASTELJAU_ERROR_INVALID_DATA, "positive");
    CHECK_ERROR(casteljau_svg_parse(NULL, 5, NULL, &bad), CASTELJAU_ERROR_INVALID_ARGUMENT, "data is NULL");
    CHECK_ERROR(casteljau_svg_load(in_scratch("no-such.svg"), NULL, &bad), CASTELJAU_ERROR_IO, "no-such.svg");
    CHECK_ERROR(casteljau_svg_load(NULL, NULL, &bad), CASTELJAU_ERROR_INVALID_ARGUMENT, "path is NULL");
    CHECK_ERROR(casteljau_svg_load(in_source("examples/data/badge.svg"), NULL, NULL), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "out");
    CHECK_OK(casteljau_svg_options_add_font_dir(options, in_scratch("no-such-fonts")));
    CHECK_ERROR(casteljau_svg_load(in_source("examples/data/badge.svg"), options, &bad), CASTELJAU_ERROR_IO,
                "no-such-fonts");
    CHECK(bad == NULL);
    CHECK_ERROR(casteljau_svg_options_set_font_family(options, (casteljau_font_generic)6, "X"),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "generic");
    CHECK_ERROR(casteljau_svg_options_add_font_dir(NULL, "x"), CASTELJAU_ERROR_INVALID_ARGUMENT, "options is NULL");
    CHECK_ERROR(casteljau_svg_output_size(doc, 10, 0, 2, &ow, &oh), CASTELJAU_ERROR_INVALID_ARGUMENT, "zoom");
    CHECK_ERROR(casteljau_svg_output_size(doc, 0, 0, NAN, &ow, &oh), CASTELJAU_ERROR_INVALID_ARGUMENT, "zoom");
    CHECK_ERROR(casteljau_svg_output_size(doc, 0, 0, 1e3, &ow, &oh), CASTELJAU_ERROR_LIMIT, "");
    casteljau_image_destroy(direct); /* a failing call hands back NULL in its place */
    direct = NULL;
    CHECK_ERROR(casteljau_svg_render_image(doc, -1, 0, 0, white, &direct), CASTELJAU_ERROR_INVALID_ARGUMENT, "width");
    CHECK_ERROR(casteljau_svg_render(NULL, canvas), CASTELJAU_ERROR_INVALID_ARGUMENT, "svg is NULL");
    CHECK_ERROR(casteljau_svg_render(doc, NULL), CASTELJAU_ERROR_INVALID_ARGUMENT, "canvas is NULL");
    CHECK_ERROR(casteljau_svg_intrinsic_size(NULL, &w, &h), CASTELJAU_ERROR_INVALID_ARGUMENT, "svg is NULL");
    CHECK(casteljau_svg_warning_count(NULL) == 0 && casteljau_svg_warning(NULL, 0) == NULL);

    casteljau_canvas_destroy(canvas);
    casteljau_image_destroy(scaled);
    casteljau_image_destroy(image);
    casteljau_image_destroy(direct);
    casteljau_svg_destroy(text);
    casteljau_svg_destroy(doc);
    casteljau_svg_destroy(NULL);
    casteljau_svg_options_destroy(options);
    casteljau_svg_options_destroy(NULL);
}

/* --dpi and --export-id: a 1in x 0.5in document at 192 dpi is 192 x 96 pixels; exporting its
 * blue square draws that square alone, where it lies; an id no element has is invalid data. */
static void check_svg_dpi_export(void) {
    casteljau_svg_options* options = casteljau_svg_options_create();
    casteljau_svg *doc = NULL, *bad = (casteljau_svg*)1;
    casteljau_image* image = NULL;
    double w = 0, h = 0;
    const casteljau_color clear = {0, 0, 0, 0};
    const char* svg_text =
        "<svg xmlns='http://www.w3.org/2000/svg' width='1in' height='0.5in'>"
        "<rect id='red' width='0.5in' height='0.5in' fill='#ff0000'/>"
        "<rect id='blue' x='0.5in' width='0.5in' height='0.5in' fill='#0000ff'/></svg>";
    CHECK(options != NULL);
    CHECK_OK(casteljau_svg_options_set_dpi(options, 192));
    CHECK_OK(casteljau_svg_options_set_export_id(options, "#blue"));
    CHECK_OK(casteljau_svg_parse((const uint8_t*)svg_text, strlen(svg_text), options, &doc));
    CHECK_OK(casteljau_svg_intrinsic_size(doc, &w, &h));
    CHECK(w == 192 && h == 96);
    CHECK_OK(casteljau_svg_render_image(doc, 0, 0, 0, clear, &image));
    CHECK(casteljau_image_width(image) == 192 && casteljau_image_height(image) == 96);
    CHECK(pixel(image, 40, 40)[3] == 0);
    CHECK(pixel(image, 140, 40)[2] == 255 && pixel(image, 140, 40)[3] == 255);
    casteljau_image_destroy(image);
    casteljau_svg_destroy(doc);

    CHECK_OK(casteljau_svg_options_set_export_id(options, "nope"));
    CHECK_ERROR(casteljau_svg_parse((const uint8_t*)svg_text, strlen(svg_text), options, &bad),
                CASTELJAU_ERROR_INVALID_DATA, "no element with id 'nope'");
    CHECK(bad == NULL);
    CHECK_OK(casteljau_svg_options_set_export_id(options, NULL));
    CHECK_ERROR(casteljau_svg_options_set_dpi(options, 0.5), CASTELJAU_ERROR_INVALID_ARGUMENT, "dpi");
    CHECK_ERROR(casteljau_svg_options_set_dpi(options, NAN), CASTELJAU_ERROR_INVALID_ARGUMENT, "dpi");
    CHECK_ERROR(casteljau_svg_options_set_dpi(options, 20000), CASTELJAU_ERROR_INVALID_ARGUMENT, "dpi");
    CHECK_ERROR(casteljau_svg_options_set_export_id(NULL, "a"), CASTELJAU_ERROR_INVALID_ARGUMENT, "options is NULL");
    CHECK_OK(casteljau_svg_parse((const uint8_t*)svg_text, strlen(svg_text), options, &doc));
    CHECK_OK(casteljau_svg_intrinsic_size(doc, &w, &h));
    CHECK(w == 192 && h == 96); /* the dpi of the rejected calls did not replace 192 */
    casteljau_svg_destroy(doc);
    casteljau_svg_options_destroy(options);
}

static void check_map(void) {
    const char* geojson =
        "{\"type\": \"FeatureCollection\", \"features\": ["
        "{\"type\": \"Feature\", \"properties\": {\"v\": 1}, \"geometry\": {\"type\": \"Polygon\","
        " \"coordinates\": [[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]]}},"
        "{\"type\": \"Feature\", \"properties\": {\"v\": 9}, \"geometry\": {\"type\": \"Polygon\","
        " \"coordinates\": [[[10, 0], [20, 0], [20, 10], [10, 10], [10, 0]]]}}]}";
    const char* style_json =
        "{\"background\": \"white\", \"layers\": [{\"fill_by\": \"v\", \"ramp\": [[0, \"#ffffff\"],"
        " [10, \"#000080\"]], \"stroke\": \"black\", \"width\": 1}]}";
    casteljau_map *map = NULL, *world = NULL, *bad = (casteljau_map*)1;
    casteljau_map_style *style = casteljau_map_style_create(), *from_file = NULL, *nostyle = NULL;
    casteljau_map_options* options = casteljau_map_options_create();
    casteljau_image *image = NULL, *target = NULL, *ramp = NULL;
    casteljau_canvas* canvas = NULL;
    const casteljau_color white = {255, 255, 255, 255}, navy = {0, 0, 128, 255}, grey = {74, 74, 74, 255};
    casteljau_color parsed;
    FILE* f;
    CHECK(style != NULL && options != NULL);

    CHECK_OK(casteljau_map_parse(geojson, strlen(geojson), NULL, &map));
    CHECK(casteljau_map_feature_count(map) == 2);
    CHECK_OK(casteljau_map_load(in_source("tests/data/maps/countries-110m.json"), "countries", &world));
    CHECK(casteljau_map_feature_count(world) == 177);

    /* A ramp over property v: white at 0, navy at 10; the bbox maps lon 0..20 onto 200 px. */
    CHECK_OK(casteljau_map_style_set_fill_by(style, "v"));
    CHECK_OK(casteljau_map_style_set_ramp(style, 0, white, 10, navy));
    CHECK_OK(casteljau_map_style_set_background(style, white));
    CHECK_OK(casteljau_map_options_set_size(options, 200, 100));
    CHECK_OK(casteljau_map_options_set_bbox(options, 0, 0, 20, 10));
    CHECK_OK(casteljau_map_render_image(map, style, options, &ramp));
    CHECK(casteljau_image_width(ramp) == 200 && casteljau_image_height(ramp) == 100);
    CHECK(abs(pixel(ramp, 50, 50)[0] - 230) <= 1 && pixel(ramp, 50, 50)[2] == 242); /* v = 1: 0.9 white */
    CHECK(abs(pixel(ramp, 150, 50)[0] - 26) <= 1 && abs(pixel(ramp, 150, 50)[2] - 140) <= 1);

    /* The same through a style file. */
    f = fopen(in_scratch("capi-style.json"), "w");
    CHECK(f != NULL);
    if (f) {
        fputs(style_json, f);
        fclose(f);
    }
    CHECK_OK(casteljau_map_style_load(in_scratch("capi-style.json"), &from_file));
    CHECK_OK(casteljau_map_style_set_stroke(from_file, NULL));
    CHECK_OK(casteljau_map_render_image(map, from_file, options, &image));
    CHECK(same_pixels(image, ramp));
    casteljau_image_destroy(image);
    image = NULL;

    /* The world in Robinson with every style setter; onto a canvas equals the image. */
    CHECK_OK(casteljau_color_parse("#4a4a4a", &parsed));
    CHECK(parsed.r == 74 && parsed.a == 255);
    casteljau_map_style_destroy(style);
    style = casteljau_map_style_create();
    CHECK_OK(casteljau_map_style_set_fill(style, &navy));
    CHECK_OK(casteljau_map_style_set_fill(style, NULL));
    CHECK_OK(casteljau_map_style_set_fill(style, &white));
    CHECK_OK(casteljau_map_style_set_fill_by(style, "name"));
    CHECK_OK(casteljau_map_style_set_stroke(style, &grey));
    CHECK_OK(casteljau_map_style_set_stroke_width(style, 0.6));
    CHECK_OK(casteljau_map_style_set_opacity(style, 1));
    CHECK_OK(casteljau_map_style_set_line_join(style, CASTELJAU_JOIN_ROUND));
    CHECK_OK(casteljau_map_style_set_line_cap(style, CASTELJAU_CAP_ROUND));
    CHECK_OK(casteljau_map_style_set_point_radius(style, 3));
    casteljau_map_options_destroy(options);
    options = casteljau_map_options_create();
    CHECK_OK(casteljau_map_options_set_projection(options, "+proj=robin"));
    CHECK_OK(casteljau_map_options_set_padding(options, 4));
    CHECK_OK(casteljau_map_options_set_separate(options, 0));
    CHECK_OK(casteljau_map_options_set_exact_overlaps(options, 1));
    CHECK_OK(casteljau_map_options_set_tolerance(options, 0.015));
    CHECK_ERROR(casteljau_map_render_image(world, style, options, &image), CASTELJAU_ERROR_INVALID_ARGUMENT, "size");
    CHECK(image == NULL);
    CHECK_OK(casteljau_image_create(300, 160, &target));
    CHECK_OK(casteljau_canvas_create(target, &canvas));
    CHECK_OK(casteljau_map_render(world, style, options, canvas));
    CHECK_OK(casteljau_map_options_set_size(options, 300, 160));
    CHECK_OK(casteljau_map_render_image(world, style, options, &image));
    CHECK(same_pixels(image, target));
    CHECK_OK(casteljau_image_write_png(image, in_scratch("capi-world.png")));

    /* A cache kept across renders of the world draws its pixels, to rounding; another map
     * through it is refused. */
    {
        casteljau_map_cache* cache = casteljau_map_cache_create();
        casteljau_image* cached = NULL;
        int round;
        CHECK(cache != NULL);
        CHECK_OK(casteljau_map_options_set_cache(options, cache));
        for (round = 0; round < 2; ++round) {
            CHECK_OK(casteljau_map_render_image(world, style, options, &cached));
            CHECK(close_pixels(cached, image, 1));
            casteljau_image_destroy(cached);
            cached = NULL;
        }
        CHECK_ERROR(casteljau_map_render_image(map, style, options, &cached), CASTELJAU_ERROR_INVALID_ARGUMENT,
                    "MapCache");
        CHECK(cached == NULL);
        CHECK_OK(casteljau_map_options_set_cache(options, NULL));
        casteljau_map_cache_destroy(cache);
        CHECK_ERROR(casteljau_map_options_set_cache(NULL, NULL), CASTELJAU_ERROR_INVALID_ARGUMENT, "options");
    }

    /* Bad input */
    CHECK_ERROR(casteljau_map_parse("{\"type\": \"Point\", \"coordinates\": [NaN, 1]}", 42, NULL, &bad),
                CASTELJAU_ERROR_PARSE, "");
    CHECK(bad == NULL);
    CHECK_ERROR(casteljau_map_parse("{\"type\": \"Point\", \"coordinates\": [1e999, 1]}", 44, NULL, &bad),
                CASTELJAU_ERROR_PARSE, "");
    CHECK_ERROR(casteljau_map_parse("{\"type\": \"Point\", \"coordinates\": [0, 91]}", 41, NULL, &bad),
                CASTELJAU_ERROR_INVALID_DATA, "coordinates");
    CHECK_ERROR(casteljau_map_parse(geojson, strlen(geojson), "countries", &bad), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "TopoJSON");
    CHECK_ERROR(casteljau_map_load(in_source("tests/data/maps/countries-110m.json"), "nowhere", &bad),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "nowhere");
    CHECK_ERROR(casteljau_map_load(in_scratch("no-such.geojson"), NULL, &bad), CASTELJAU_ERROR_IO, "no-such.geojson");
    CHECK_ERROR(casteljau_map_options_set_projection(options, "+proj=nonsense"), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "nonsense");
    CHECK_ERROR(casteljau_map_options_set_projection(options, NULL), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "projection is NULL");
    CHECK_ERROR(casteljau_map_options_set_bbox(options, 10, 0, 0, 10), CASTELJAU_ERROR_INVALID_ARGUMENT, "bbox");
    CHECK_ERROR(casteljau_map_options_set_bbox(options, 0, NAN, 10, 10), CASTELJAU_ERROR_INVALID_ARGUMENT, "bbox");
    CHECK_ERROR(casteljau_map_options_set_size(options, 0, 0), CASTELJAU_ERROR_INVALID_ARGUMENT, "width");
    CHECK_ERROR(casteljau_map_options_set_tolerance(options, 0), CASTELJAU_ERROR_INVALID_ARGUMENT, "tolerance");
    CHECK_ERROR(casteljau_map_options_set_padding(options, -1), CASTELJAU_ERROR_INVALID_ARGUMENT, "padding");
    CHECK_ERROR(casteljau_map_style_set_ramp(style, 5, white, 5, navy), CASTELJAU_ERROR_INVALID_ARGUMENT, "ramp");
    CHECK_ERROR(casteljau_map_style_set_stroke_width(style, INFINITY), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "stroke width");
    CHECK_ERROR(casteljau_map_style_set_opacity(style, 2), CASTELJAU_ERROR_INVALID_ARGUMENT, "opacity");
    CHECK_ERROR(casteljau_map_style_set_line_join(style, (casteljau_line_join)7), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "join");
    CHECK_ERROR(casteljau_map_style_set_line_cap(style, (casteljau_line_cap)-1), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "cap");
    CHECK_ERROR(casteljau_map_style_set_point_radius(NULL, 1), CASTELJAU_ERROR_INVALID_ARGUMENT, "style is NULL");
    CHECK_ERROR(casteljau_map_style_parse("{\"layers\": 5}", &nostyle), CASTELJAU_ERROR_PARSE, "layers");
    CHECK(nostyle == NULL);
    CHECK_ERROR(casteljau_map_style_load(in_scratch("no-such-style.json"), &nostyle), CASTELJAU_ERROR_IO,
                "no-such-style");
    casteljau_image_destroy(image); /* a failing call hands back NULL in its place */
    image = NULL;
    CHECK_ERROR(casteljau_map_render_image(NULL, style, options, &image), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "map is NULL");
    CHECK_ERROR(casteljau_map_render_image(map, style, NULL, &image), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "options is NULL");
    CHECK_ERROR(casteljau_map_render(map, style, options, NULL), CASTELJAU_ERROR_INVALID_ARGUMENT, "canvas is NULL");
    {
        casteljau_map* empty = NULL;
        casteljau_map_options* o = casteljau_map_options_create();
        casteljau_image* none = NULL;
        const char* none_json = "{\"type\": \"FeatureCollection\", \"features\": []}";
        CHECK_OK(casteljau_map_parse(none_json, strlen(none_json), NULL, &empty));
        CHECK_OK(casteljau_map_options_set_size(o, 10, 10));
        CHECK_ERROR(casteljau_map_render_image(empty, NULL, o, &none), CASTELJAU_ERROR_INVALID_DATA, "");
        casteljau_map_options_destroy(o);
        casteljau_map_destroy(empty);
    }
    CHECK(casteljau_map_feature_count(NULL) == 0);

    casteljau_canvas_destroy(canvas);
    casteljau_image_destroy(target);
    casteljau_image_destroy(image);
    casteljau_image_destroy(ramp);
    casteljau_map_options_destroy(options);
    casteljau_map_style_destroy(style);
    casteljau_map_style_destroy(from_file);
    casteljau_map_destroy(map);
    casteljau_map_destroy(world);
    casteljau_map_destroy(NULL);
}

struct progress_log {
    uint64_t calls, last_done, last_total, stop_after;
};

static int on_progress(uint64_t done, uint64_t total, void* user) {
    struct progress_log* log = (struct progress_log*)user;
    ++log->calls;
    log->last_done = done;
    log->last_total = total;
    return log->stop_after != 0 && log->calls >= log->stop_after;
}

static void check_tiles(void) {
    casteljau_map* world = NULL;
    casteljau_tile_options* options = casteljau_tile_options_create();
    casteljau_tile_stats stats;
    struct progress_log log = {0, 0, 0, 0};
    uint64_t written;
    FILE* f;
    CHECK(options != NULL);
    CHECK_OK(casteljau_map_load(in_source("tests/data/maps/countries-110m.json"), "countries", &world));
    CHECK_OK(casteljau_tile_options_set_zoom(options, 0, 2));
    CHECK_OK(casteljau_tile_options_set_tile_size(options, 256, 1));
    CHECK_OK(casteljau_tile_options_set_metatile(options, 2));
    CHECK_OK(casteljau_tile_options_set_buffer(options, 16));
    CHECK_OK(casteljau_tile_options_set_skip_empty(options, 1));
    CHECK_OK(casteljau_tile_options_set_resume(options, 0));
    CHECK_OK(casteljau_tile_options_set_shard(options, 0, 1));
    CHECK_OK(casteljau_tile_options_set_name(options, "world"));
    CHECK_OK(casteljau_tile_options_set_separate(options, 0));
    CHECK_OK(casteljau_tile_options_set_exact_overlaps(options, 1));
    CHECK_OK(casteljau_tile_options_set_tolerance(options, 0.05));
    CHECK_OK(casteljau_map_render_tiles(world, NULL, options, in_scratch("capi-tiles"), on_progress, &log, &stats));
    /* Metatiles of 2 x 2 tiles: 1 at z0, 1 at z1, 4 at z2; 21 tiles, the empty ones skipped. */
    CHECK(stats.metatiles == 6 && log.calls == 6 && log.last_done == 6 && log.last_total == 6);
    CHECK(stats.written + stats.skipped_empty == 21 && stats.written > 10);
    f = fopen(in_scratch("capi-tiles/2/2/1.png"), "rb");
    CHECK(f != NULL);
    if (f) fclose(f);

    /* Resumed: every tile written is there, none is written again. */
    written = stats.written;
    CHECK_OK(casteljau_tile_options_set_resume(options, 1));
    CHECK_OK(casteljau_map_render_tiles(world, NULL, options, in_scratch("capi-tiles"), NULL, NULL, &stats));
    CHECK(stats.written == 0 && stats.skipped_existing == written);
    CHECK_ERROR(casteljau_map_render_tiles(world, NULL, options, in_scratch("capi.mbtiles"), NULL, NULL, &stats),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "resume");
    CHECK_OK(casteljau_tile_options_set_resume(options, 0));

    /* MBTiles; a progress callback that stops after two metatiles leaves no file. */
    remove(in_scratch("capi.mbtiles"));
    log.calls = 0;
    log.stop_after = 2;
    CHECK_ERROR(casteljau_map_render_tiles(world, NULL, options, in_scratch("capi.mbtiles"), on_progress, &log, &stats),
                CASTELJAU_ERROR_CANCELLED, "cancel");
    CHECK(log.calls == 2 && stats.metatiles == 0);
    f = fopen(in_scratch("capi.mbtiles"), "rb");
    CHECK(f == NULL);
    if (f) fclose(f);
    CHECK(strcmp(casteljau_status_name(CASTELJAU_ERROR_CANCELLED), "cancelled") == 0);
    CHECK_OK(casteljau_map_render_tiles(world, NULL, options, in_scratch("capi.mbtiles"), NULL, NULL, NULL));
    f = fopen(in_scratch("capi.mbtiles"), "rb");
    CHECK(f != NULL);
    if (f) fclose(f);

    /* Bad input */
    CHECK_ERROR(casteljau_tile_options_set_zoom(options, 3, 2), CASTELJAU_ERROR_INVALID_ARGUMENT, "zoom");
    CHECK_ERROR(casteljau_tile_options_set_zoom(options, 0, 25), CASTELJAU_ERROR_INVALID_ARGUMENT, "zoom");
    CHECK_ERROR(casteljau_tile_options_set_tile_size(options, 300, 1), CASTELJAU_ERROR_INVALID_ARGUMENT, "256 or 512");
    CHECK_ERROR(casteljau_tile_options_set_tile_size(options, 256, 5), CASTELJAU_ERROR_INVALID_ARGUMENT, "scale");
    CHECK_ERROR(casteljau_tile_options_set_metatile(options, 0), CASTELJAU_ERROR_INVALID_ARGUMENT, "metatile");
    CHECK_ERROR(casteljau_tile_options_set_buffer(options, 2000), CASTELJAU_ERROR_INVALID_ARGUMENT, "buffer");
    CHECK_ERROR(casteljau_tile_options_set_shard(options, 2, 2), CASTELJAU_ERROR_INVALID_ARGUMENT, "shard");
    CHECK_ERROR(casteljau_tile_options_set_name(options, NULL), CASTELJAU_ERROR_INVALID_ARGUMENT, "name is NULL");
    CHECK_ERROR(casteljau_tile_options_set_tolerance(options, NAN), CASTELJAU_ERROR_INVALID_ARGUMENT, "tolerance");
    CHECK_ERROR(casteljau_map_render_tiles(world, NULL, NULL, in_scratch("x"), NULL, NULL, NULL),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "options is NULL");
    CHECK_ERROR(casteljau_map_render_tiles(world, NULL, options, NULL, NULL, NULL, NULL),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "output is NULL");
    CHECK_ERROR(casteljau_map_render_tiles(world, NULL, options, "/nonexistent-dir/x.mbtiles", NULL, NULL, NULL),
                CASTELJAU_ERROR_IO, "nonexistent-dir");

    casteljau_tile_options_destroy(options);
    casteljau_tile_options_destroy(NULL);
    casteljau_map_destroy(world);
}

static void check_text(void) {
    casteljau_font *dejavu = NULL, *arabic = NULL, *nofont = (casteljau_font*)1;
    casteljau_text_style* style = casteljau_text_style_create();
    casteljau_text_layout *layout = NULL, *rtl = NULL, *bad = (casteljau_text_layout*)1;
    casteljau_image *image = NULL, *target = NULL;
    casteljau_canvas* canvas = NULL;
    casteljau_paint* ink = NULL;
    casteljau_text_line line;
    double w = 0, h = 0, x0 = 1, y0 = 1, x1 = 0, y1 = 0;
    const casteljau_color black = {0, 0, 0, 255}, white = {255, 255, 255, 255};
    const casteljau_font* chain[2];
    CHECK(style != NULL);
    CHECK_OK(casteljau_font_load(in_source("fonts/DejaVuSans.ttf"), &dejavu));
    CHECK_OK(casteljau_font_load_face(in_source("fonts/NotoSansArabic-Regular.ttf"), 0, &arabic));
    chain[0] = dejavu;
    chain[1] = arabic;
    CHECK_OK(casteljau_paint_create_solid(black, &ink));
    CHECK_OK(casteljau_paint_set_linear_blend(ink, 0));

    CHECK_OK(casteljau_text_style_set_size(style, 20));
    CHECK_OK(casteljau_text_style_set_width(style, 150));
    CHECK_OK(casteljau_text_style_set_align(style, CASTELJAU_ALIGN_CENTER));
    CHECK_OK(casteljau_text_style_set_line_height(style, 1.25));
    CHECK_OK(casteljau_text_style_set_direction(style, CASTELJAU_DIRECTION_AUTO));
    CHECK_OK(casteljau_text_style_set_script(style, NULL));
    CHECK_OK(casteljau_text_style_set_language(style, "en"));
    CHECK_OK(casteljau_text_style_add_feature(style, "liga=0"));
    CHECK_OK(casteljau_text_layout_create("Layout through the C API, wrapped and centred", chain, 2, style, &layout));
    CHECK_OK(casteljau_text_layout_size(layout, &w, &h));
    CHECK(w == 150 && h > 40);
    CHECK_OK(casteljau_text_layout_bounds(layout, &x0, &y0, &x1, &y1));
    CHECK(x0 <= 0 && y0 <= 0 && x1 >= 150 && y1 >= h - 1);
    CHECK(casteljau_text_layout_line_count(layout) >= 2);
    CHECK_OK(casteljau_text_layout_line(layout, 0, &line));
    CHECK(strncmp(line.text, "Layout", 6) == 0 && line.length == strlen(line.text) && !line.rtl);
    CHECK(line.width <= 150 && line.x > 0 && line.baseline > 0);

    /* Arabic falls back to the second font and runs right to left; the layout keeps its fonts. */
    CHECK_OK(casteljau_text_layout_create("\xd9\x85\xd8\xb1\xd8\xad\xd8\xa8\xd8\xa7", chain, 2, NULL, &rtl));
    casteljau_font_destroy(arabic);
    arabic = NULL;
    CHECK_OK(casteljau_text_layout_line(rtl, 0, &line));
    CHECK(line.rtl && strcmp(line.text, "\xd9\x85\xd8\xb1\xd8\xad\xd8\xa8\xd8\xa7") == 0);

    /* render_image: the bounds plus padding; draw onto a canvas at the same origin agrees. */
    CHECK_OK(casteljau_text_layout_render_image(rtl, ink, white, 4, &image));
    CHECK(casteljau_image_width(image) > 8 && casteljau_image_height(image) > 8);
    CHECK_OK(casteljau_text_layout_bounds(rtl, &x0, &y0, &x1, &y1));
    CHECK_OK(casteljau_image_create(casteljau_image_width(image), casteljau_image_height(image), &target));
    CHECK_OK(casteljau_canvas_create(target, &canvas));
    CHECK_OK(casteljau_canvas_clear(canvas, white));
    CHECK_OK(casteljau_text_layout_draw(rtl, canvas, 4 - floor(x0), 4 - floor(y0), ink));
    CHECK(same_pixels(image, target));

    /* Bad input */
    nofont = (casteljau_font*)1;
    CHECK_ERROR(casteljau_font_load(in_scratch("no-such-font.ttf"), &nofont), CASTELJAU_ERROR_IO, "no-such-font");
    CHECK(nofont == NULL);
    CHECK_ERROR(casteljau_font_load_face(in_source("fonts/DejaVuSans.ttf"), 3, &nofont), CASTELJAU_ERROR_FONT, "");
    CHECK_ERROR(casteljau_font_load_face(in_source("fonts/DejaVuSans.ttf"), -1, &nofont),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "face");
    CHECK_ERROR(casteljau_text_layout_create("x", chain, 0, NULL, &bad), CASTELJAU_ERROR_INVALID_ARGUMENT, "font");
    CHECK(bad == NULL);
    CHECK_ERROR(casteljau_text_layout_create("x", NULL, 1, NULL, &bad), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "fonts is NULL");
    chain[1] = NULL;
    CHECK_ERROR(casteljau_text_layout_create("x", chain, 2, NULL, &bad), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "font is NULL");
    CHECK_ERROR(casteljau_text_layout_create(NULL, chain, 1, NULL, &bad), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "text is NULL");
    CHECK_OK(casteljau_text_style_add_variation(style, "wght=700"));
    CHECK_ERROR(casteljau_text_layout_create("x", chain, 1, style, &bad), CASTELJAU_ERROR_FONT, "wght");
    CHECK_ERROR(casteljau_text_style_add_variation(style, "wght"), CASTELJAU_ERROR_PARSE, "");
    casteljau_text_style_destroy(style);
    style = casteljau_text_style_create();
    CHECK_OK(casteljau_text_style_add_feature(style, "+++"));
    CHECK_ERROR(casteljau_text_layout_create("x", chain, 1, style, &bad), CASTELJAU_ERROR_PARSE, "+++");
    CHECK_ERROR(casteljau_text_style_set_size(style, 0), CASTELJAU_ERROR_INVALID_ARGUMENT, "");
    CHECK_ERROR(casteljau_text_style_set_size(style, 1e9), CASTELJAU_ERROR_LIMIT, "");
    CHECK_ERROR(casteljau_text_style_set_line_height(style, NAN), CASTELJAU_ERROR_INVALID_ARGUMENT, "line height");
    CHECK_ERROR(casteljau_text_style_set_width(style, -3), CASTELJAU_ERROR_INVALID_ARGUMENT, "wrap width");
    CHECK_ERROR(casteljau_text_style_set_align(style, (casteljau_text_align)4), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "alignment");
    CHECK_ERROR(casteljau_text_style_set_direction(style, (casteljau_text_direction)-1),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "direction");
    CHECK_ERROR(casteljau_text_layout_line(layout, 99, &line), CASTELJAU_ERROR_INVALID_ARGUMENT, "line");
    CHECK_ERROR(casteljau_text_layout_draw(layout, canvas, NAN, 0, ink), CASTELJAU_ERROR_INVALID_ARGUMENT, "finite");
    CHECK_ERROR(casteljau_text_layout_draw(NULL, canvas, 0, 0, ink), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "layout is NULL");
    CHECK_ERROR(casteljau_text_layout_draw(layout, canvas, 0, 0, NULL), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "paint is NULL");
    casteljau_image_destroy(image); /* a failing call hands back NULL in its place */
    image = NULL;
    CHECK_ERROR(casteljau_text_layout_render_image(layout, ink, white, -1, &image), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "padding");
    CHECK_ERROR(casteljau_text_layout_size(NULL, &w, &h), CASTELJAU_ERROR_INVALID_ARGUMENT, "layout is NULL");
    CHECK_ERROR(casteljau_text_style_set_size(NULL, 10), CASTELJAU_ERROR_INVALID_ARGUMENT, "style is NULL");
    CHECK_ERROR(casteljau_paint_set_linear_blend(NULL, 1), CASTELJAU_ERROR_INVALID_ARGUMENT, "paint is NULL");
    CHECK(casteljau_text_layout_line_count(NULL) == 0);

    casteljau_canvas_destroy(canvas);
    casteljau_image_destroy(target);
    casteljau_image_destroy(image);
    casteljau_paint_destroy(ink);
    casteljau_text_layout_destroy(layout);
    casteljau_text_layout_destroy(rtl);
    casteljau_text_layout_destroy(NULL);
    casteljau_text_style_destroy(style);
    casteljau_text_style_destroy(NULL);
    casteljau_font_destroy(dejavu);
}

/* Whether two files hold the same bytes. */
static int same_file(const char* a, const char* b) {
    FILE* fa = fopen(a, "rb");
    FILE* fb = fopen(b, "rb");
    int same = fa != NULL && fb != NULL;
    while (same) {
        const int ca = fgetc(fa), cb = fgetc(fb);
        same = ca == cb;
        if (ca == EOF) break;
    }
    if (fa) fclose(fa);
    if (fb) fclose(fb);
    return same;
}

/* Runs `casteljau text` (the CLI given as the third argument) with `args` appended; 0 when it
 * succeeded. The arguments are quoted by the caller. */
static int run_text_cli(const char* args) {
    char command[8192];
    snprintf(command, sizeof command, "'%s' text %s > /dev/null", cli, args);
    return system(command);
}

/* Renders `text` in `font` at 40 px with `style` and writes it to scratch file `name`; CHECKs that
 * it worked and returns whether it did. */
static int write_text_png(const char* text, const casteljau_font* font, const casteljau_text_style* style,
                          const char* name) {
    const casteljau_color black = {0, 0, 0, 255}, white = {255, 255, 255, 255};
    casteljau_text_layout* layout = NULL;
    casteljau_paint* ink = NULL;
    casteljau_image* image = NULL;
    casteljau_status s = casteljau_paint_create_solid(black, &ink);
    if (s == CASTELJAU_OK) s = casteljau_text_layout_create(text, &font, 1, style, &layout);
    if (s == CASTELJAU_OK) s = casteljau_text_layout_render_image(layout, ink, white, 4, &image);
    if (s == CASTELJAU_OK) s = casteljau_image_write_png(image, in_scratch(name));
    if (s != CASTELJAU_OK) fprintf(stderr, "rendering \"%s\" to %s: %s\n", text, name, casteljau_last_error());
    CHECK(s == CASTELJAU_OK);
    casteljau_image_destroy(image);
    casteljau_text_layout_destroy(layout);
    casteljau_paint_destroy(ink);
    return s == CASTELJAU_OK;
}

/* casteljau_text_style_set_system_fonts: "Kanji 日本" in DejaVu Sans (which lacks the two Han
 * characters) as `casteljau text` draws it (fallback through fontconfig) and as it draws it with
 * --no-system-fonts (.notdef boxes), byte for byte; skipped without Noto Sans CJK. */
static void check_text_system_fonts(void) {
    const char* cjk_font = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc";
    const char* text = "Kanji \xe6\x97\xa5\xe6\x9c\xac";
    casteljau_text_style* style = casteljau_text_style_create();
    casteljau_font* dejavu = NULL;
    char args[8192];
    FILE* probe = fopen(cjk_font, "rb");
    CHECK(style != NULL);
    if (probe == NULL || cli[0] == '\0') {
        printf("C API documents: SKIP system font fallback: %s\n",
               probe == NULL ? "no NotoSansCJK-Regular.ttc (Debian fonts-noto-cjk)" : "no CLI given");
        if (probe) fclose(probe);
        casteljau_text_style_destroy(style);
        return;
    }
    fclose(probe);
    CHECK_OK(casteljau_font_load(in_source("fonts/DejaVuSans.ttf"), &dejavu));
    CHECK_OK(casteljau_text_style_set_size(style, 40));
    if (write_text_png(text, dejavu, style, "capi-cjk-plain.png")) {
        snprintf(args, sizeof args, "'%s' --font '%s' --size 40 --color black --no-system-fonts -o '%s'", text,
                 in_source("fonts/DejaVuSans.ttf"), in_scratch("capi-cjk-plain-cli.png"));
        CHECK(run_text_cli(args) == 0);
        CHECK(same_file(in_scratch("capi-cjk-plain.png"), in_scratch("capi-cjk-plain-cli.png")));
    }
    CHECK_OK(casteljau_text_style_set_system_fonts(style, 1));
    if (write_text_png(text, dejavu, style, "capi-cjk.png")) {
        snprintf(args, sizeof args, "'%s' --font '%s' --size 40 --color black -o '%s'", text,
                 in_source("fonts/DejaVuSans.ttf"), in_scratch("capi-cjk-cli.png"));
        CHECK(run_text_cli(args) == 0);
        CHECK(same_file(in_scratch("capi-cjk.png"), in_scratch("capi-cjk-cli.png")));
        CHECK(!same_file(in_scratch("capi-cjk.png"), in_scratch("capi-cjk-plain.png")));
    }
    CHECK_OK(casteljau_text_style_set_system_fonts(style, 0));
    CHECK_ERROR(casteljau_text_style_set_system_fonts(NULL, 1), CASTELJAU_ERROR_INVALID_ARGUMENT, "style is NULL");
    casteljau_text_style_destroy(style);
    casteljau_font_destroy(dejavu);
}

/* Counts the pixels of `image` near `r`, `g`, `b`. */
static int count_colour(casteljau_image* image, int r, int g, int b) {
    int x, y, n = 0;
    for (y = 0; y < casteljau_image_height(image); ++y)
        for (x = 0; x < casteljau_image_width(image); ++x) {
            const uint8_t* p = casteljau_image_data(image) + casteljau_image_stride(image) * (size_t)y + 4 * (size_t)x;
            n += abs(p[0] - r) < 8 && abs(p[1] - g) < 8 && abs(p[2] - b) < 8;
        }
    return n;
}

/* casteljau_text_style_set_palette: tests/data/colr_test.ttf's "F" is red in CPAL palette 0 and
 * green (0, 128, 0) in palette 1, drawn as `casteljau text --palette N` draws it, byte for byte. */
static void check_text_palette(void) {
    casteljau_font* colr = NULL;
    casteljau_text_style* style = casteljau_text_style_create();
    casteljau_image* image = NULL;
    char args[8192], name[64], cli_name[64];
    int palette;
    CHECK(style != NULL);
    CHECK_OK(casteljau_font_load(in_source("tests/data/colr_test.ttf"), &colr));
    CHECK_OK(casteljau_text_style_set_size(style, 40));
    for (palette = 0; palette <= 1 && colr != NULL; ++palette) {
        snprintf(name, sizeof name, "capi-palette%d.png", palette);
        snprintf(cli_name, sizeof cli_name, "capi-palette%d-cli.png", palette);
        CHECK_OK(casteljau_text_style_set_palette(style, palette));
        if (!write_text_png("F", colr, style, name)) continue;
        CHECK_OK(casteljau_image_read_png(in_scratch(name), &image));
        if (image != NULL) {
            CHECK(count_colour(image, palette ? 0 : 255, palette ? 128 : 0, 0) > 50);
            CHECK(count_colour(image, palette ? 255 : 0, palette ? 0 : 128, 0) == 0);
        }
        casteljau_image_destroy(image);
        image = NULL;
        if (cli[0] == '\0') continue;
        snprintf(args, sizeof args, "F --font '%s' --size 40 --color black --palette %d -o '%s'",
                 in_source("tests/data/colr_test.ttf"), palette, in_scratch(cli_name));
        CHECK(run_text_cli(args) == 0);
        CHECK(same_file(in_scratch(name), in_scratch(cli_name)));
    }
    CHECK_ERROR(casteljau_text_style_set_palette(style, -1), CASTELJAU_ERROR_INVALID_ARGUMENT, "palette");
    CHECK_ERROR(casteljau_text_style_set_palette(style, 65536), CASTELJAU_ERROR_INVALID_ARGUMENT, "palette");
    CHECK_ERROR(casteljau_text_style_set_palette(NULL, 0), CASTELJAU_ERROR_INVALID_ARGUMENT, "style is NULL");
    casteljau_text_style_destroy(style);
    casteljau_font_destroy(colr);
}

static void check_core_additions(void) {
    casteljau_image* image = NULL;
    casteljau_image* back = NULL;
    casteljau_color c = {1, 2, 3, 4};
    uint8_t* png = NULL;
    size_t size = 0;
    CHECK_OK(casteljau_color_parse("rgb(10 20 30 / 50%)", &c));
    CHECK(c.r == 10 && c.g == 20 && c.b == 30 && c.a == 128);
    CHECK_ERROR(casteljau_color_parse("notacolour", &c), CASTELJAU_ERROR_PARSE, "notacolour");
    CHECK_ERROR(casteljau_color_parse(NULL, &c), CASTELJAU_ERROR_INVALID_ARGUMENT, "text is NULL");
    CHECK_OK(casteljau_image_create(3, 2, &image));
    casteljau_image_data(image)[3] = 255;
    CHECK_OK(casteljau_image_encode_png(image, &png, &size));
    CHECK(png != NULL && size > 8 && memcmp(png + 1, "PNG", 3) == 0);
    CHECK_OK(casteljau_image_decode_png(png, size, &back));
    CHECK(same_pixels(image, back));
    casteljau_free(png);
    casteljau_free(NULL);
    png = (uint8_t*)1;
    CHECK_ERROR(casteljau_image_encode_png(NULL, &png, &size), CASTELJAU_ERROR_INVALID_ARGUMENT, "image is NULL");
    CHECK(png == NULL && size == 0);
    casteljau_image_destroy(back);
    casteljau_image_destroy(image);
}

int main(int argc, char** argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: test_capi_documents SOURCE_DIR SCRATCH_DIR [CASTELJAU_CLI]\n");
        return 2;
    }
    snprintf(source, sizeof source, "%s", argv[1]);
    snprintf(scratch, sizeof scratch, "%s", argv[2]);
    snprintf(cli, sizeof cli, "%s", argc > 3 ? argv[3] : "");
    check_core_additions();
    check_svg();
    check_svg_dpi_export();
    check_map();
    check_tiles();
    check_text();
    check_text_system_fonts();
    check_text_palette();
    if (failures)
        fprintf(stderr, "%d checks failed\n", failures);
    else
        printf("C API documents: all checks passed\n");
    return failures ? 1 : 0;
}
