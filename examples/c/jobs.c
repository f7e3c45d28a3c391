/* casteljau's three jobs in C99 against the installed package (pkg-config casteljau):
 *   cc -std=c99 jobs.c $(pkg-config --cflags --libs casteljau) -o jobs
 *   ./jobs BADGE.svg WORLD.json FONT.ttf OUT_DIR
 * writes OUT_DIR/badge.png, world.png and text.png, the same bytes as
 *   casteljau svg BADGE.svg -w 256 -b white -o badge.png
 *   casteljau map WORLD.json --layer countries --width 480 --projection +proj=robin --fill-by name \
 *       --stroke "#4a4a4a" --stroke-width 0.6 --background white -o world.png
 *   casteljau text "Hello, casteljau" --font FONT.ttf -o text.png */
#include <stdio.h>

#include <casteljau/casteljau.h>
#include <casteljau/casteljau_map.h>
#include <casteljau/casteljau_svg.h>
#include <casteljau/casteljau_text.h>

/* Reports the library's message for a failed call. */
static int ok(casteljau_status status, const char* what) {
    if (status != CASTELJAU_OK) fprintf(stderr, "jobs: %s: %s\n", what, casteljau_last_error());
    return status == CASTELJAU_OK;
}

static int svg_job(const char* svg_path, const char* out) {
    const casteljau_color white = {255, 255, 255, 255};
    casteljau_svg* doc = NULL;
    casteljau_image* image = NULL;
    const int done = ok(casteljau_svg_load(svg_path, NULL, &doc), "load the SVG") &&
                     ok(casteljau_svg_render_image(doc, 256, 0, 0, white, &image), "render the SVG") &&
                     ok(casteljau_image_write_png(image, out), "write badge.png");
    casteljau_image_destroy(image);
    casteljau_svg_destroy(doc);
    return done;
}

static int map_job(const char* map_path, const char* out) {
    casteljau_color stroke, background;
    casteljau_map* map = NULL;
    casteljau_map_style* style = casteljau_map_style_create();
    casteljau_map_options* options = casteljau_map_options_create();
    casteljau_image* image = NULL;
    const int done = style && options && ok(casteljau_map_load(map_path, "countries", &map), "load the map") &&
                     ok(casteljau_color_parse("#4a4a4a", &stroke), "stroke colour") &&
                     ok(casteljau_color_parse("white", &background), "background colour") &&
                     ok(casteljau_map_style_set_fill_by(style, "name"), "fill by") &&
                     ok(casteljau_map_style_set_stroke(style, &stroke), "stroke") &&
                     ok(casteljau_map_style_set_stroke_width(style, 0.6), "stroke width") &&
                     ok(casteljau_map_style_set_background(style, background), "background") &&
                     ok(casteljau_map_options_set_size(options, 480, 0), "size") &&
                     ok(casteljau_map_options_set_projection(options, "+proj=robin"), "projection") &&
                     ok(casteljau_map_render_image(map, style, options, &image), "render the map") &&
                     ok(casteljau_image_write_png(image, out), "write world.png");
    casteljau_image_destroy(image);
    casteljau_map_options_destroy(options);
    casteljau_map_style_destroy(style);
    casteljau_map_destroy(map);
    return done;
}

static int text_job(const char* font_path, const char* out) {
    const casteljau_color black = {0, 0, 0, 255}, white = {255, 255, 255, 255};
    casteljau_font* font = NULL;
    casteljau_text_style* style = casteljau_text_style_create();
    casteljau_text_layout* layout = NULL;
    casteljau_paint* ink = NULL;
    casteljau_image* image = NULL;
    const casteljau_font* fonts[1];
    int done = style && ok(casteljau_font_load(font_path, &font), "load the font") &&
               ok(casteljau_text_style_set_size(style, 32), "size") &&
               ok(casteljau_paint_create_solid(black, &ink), "paint");
    fonts[0] = font;
    done = done && ok(casteljau_text_layout_create("Hello, casteljau", fonts, 1, style, &layout), "lay out the text") &&
           ok(casteljau_text_layout_render_image(layout, ink, white, 4, &image), "render the text") &&
           ok(casteljau_image_write_png(image, out), "write text.png");
    casteljau_image_destroy(image);
    casteljau_paint_destroy(ink);
    casteljau_text_layout_destroy(layout);
    casteljau_text_style_destroy(style);
    casteljau_font_destroy(font);
    return done;
}

int main(int argc, char** argv) {
    char badge[4096], world[4096], text[4096];
    if (argc != 5) {
        fprintf(stderr, "usage: jobs BADGE.svg WORLD.json FONT.ttf OUT_DIR\n");
        return 2;
    }
    snprintf(badge, sizeof badge, "%s/badge.png", argv[4]);
    snprintf(world, sizeof world, "%s/world.png", argv[4]);
    snprintf(text, sizeof text, "%s/text.png", argv[4]);
    return svg_job(argv[1], badge) && map_job(argv[2], world) && text_job(argv[3], text) ? 0 : 1;
}
