/* The C API, compiled as C99: every object type is created and destroyed, a scene is drawn and
 * sampled, and every error is triggered and read back through casteljau_last_error(). Run under
 * AddressSanitizer (the sanitizer build), it also shows that nothing leaks.
 * Usage: test_capi FONT_DIR SCRATCH_DIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "casteljau/casteljau.h"
#include "capi_check.h"

static const uint8_t* pixel(casteljau_image* im, int x, int y) {
    return casteljau_image_data(im) + casteljau_image_stride(im) * (size_t)y + 4 * (size_t)x;
}

int main(int argc, char** argv) {
    if (argc < 3) {
        fprintf(stderr, "usage: test_capi FONT_DIR SCRATCH_DIR\n");
        return 2;
    }
    char font_path[4096], png_path[4096], missing[4096];
    snprintf(font_path, sizeof font_path, "%s/DejaVuSans.ttf", argv[1]);
    snprintf(png_path, sizeof png_path, "%s/capi_scene.png", argv[2]);
    snprintf(missing, sizeof missing, "%s/no-such-font.ttf", argv[2]);

    /* Version */
    CHECK(casteljau_version() == CASTELJAU_VERSION);
    CHECK(strcmp(casteljau_version_string(), "0.1.0") == 0 || CASTELJAU_VERSION != 100);
    CHECK(strcmp(casteljau_status_name(CASTELJAU_ERROR_PARSE), "parse error") == 0);

    /* Every object type */
    casteljau_image* image = NULL;
    CHECK(casteljau_image_create(64, 48, &image) == CASTELJAU_OK);
    CHECK(casteljau_image_width(image) == 64 && casteljau_image_height(image) == 48);
    CHECK(casteljau_image_stride(image) == 256);
    casteljau_canvas* canvas = NULL;
    CHECK(casteljau_canvas_create(image, &canvas) == CASTELJAU_OK);
    casteljau_path* path = casteljau_path_create();
    CHECK(path != NULL);
    CHECK(casteljau_path_move_to(path, 4, 4) == CASTELJAU_OK);
    CHECK(casteljau_path_line_to(path, 30, 4) == CASTELJAU_OK);
    CHECK(casteljau_path_quad_to(path, 34, 14, 30, 24) == CASTELJAU_OK);
    CHECK(casteljau_path_cubic_to(path, 20, 30, 10, 30, 4, 24) == CASTELJAU_OK);
    CHECK(casteljau_path_close(path) == CASTELJAU_OK);
    casteljau_path* svg = NULL;
    CHECK(casteljau_path_from_svg("M40 4 h20 v20 h-20 z", &svg) == CASTELJAU_OK);
    double x0, y0, x1, y1;
    CHECK(casteljau_path_bounds(svg, &x0, &y0, &x1, &y1) == CASTELJAU_OK);
    CHECK(x0 == 40 && y0 == 4 && x1 == 60 && y1 == 24);
    casteljau_stroke* stroke = casteljau_stroke_create();
    CHECK(stroke != NULL);
    CHECK(casteljau_stroke_set_width(stroke, 3) == CASTELJAU_OK);
    CHECK(casteljau_stroke_set_cap(stroke, CASTELJAU_CAP_ROUND) == CASTELJAU_OK);
    CHECK(casteljau_stroke_set_join(stroke, CASTELJAU_JOIN_ROUND, 4) == CASTELJAU_OK);
    const double dashes[2] = {4, 2};
    CHECK(casteljau_stroke_set_dashes(stroke, dashes, 2, 0) == CASTELJAU_OK);

    const casteljau_color red = {255, 0, 0, 255}, blue = {0, 0, 255, 255}, white = {255, 255, 255, 255};
    casteljau_paint *solid = NULL, *linear = NULL, *radial = NULL, *pattern = NULL;
    CHECK(casteljau_paint_create_solid(red, &solid) == CASTELJAU_OK);
    casteljau_gradient_stop stops[2] = {{0, {255, 0, 0, 255}}, {1, {0, 0, 255, 255}}};
    CHECK(casteljau_paint_create_linear(40, 0, 60, 0, stops, 2, CASTELJAU_SPREAD_PAD, NULL, &linear) == CASTELJAU_OK);
    CHECK(casteljau_paint_create_radial(32, 36, 10, 32, 36, 0, stops, 2, CASTELJAU_SPREAD_REFLECT, NULL, &radial) ==
          CASTELJAU_OK);
    CHECK(casteljau_paint_create_image(image, CASTELJAU_SAMPLING_BILINEAR, NULL, 1, &pattern) == CASTELJAU_OK);
    CHECK(casteljau_paint_set_opacity(solid, 1.0) == CASTELJAU_OK);
    CHECK(casteljau_paint_set_blend_mode(pattern, CASTELJAU_BLEND_MULTIPLY) == CASTELJAU_OK);
    casteljau_font* font = NULL;
    CHECK(casteljau_font_load(font_path, &font) == CASTELJAU_OK);

    /* A scene */
    CHECK(casteljau_canvas_clear(canvas, white) == CASTELJAU_OK);
    CHECK(casteljau_canvas_fill_path(canvas, svg, linear, CASTELJAU_FILL_NONZERO) == CASTELJAU_OK);
    CHECK(casteljau_canvas_save(canvas) == CASTELJAU_OK);
    casteljau_path* circle = casteljau_path_create();
    CHECK(casteljau_path_add_ellipse(circle, 32, 36, 10, 10) == CASTELJAU_OK);
    CHECK(casteljau_canvas_clip_path(canvas, circle, CASTELJAU_FILL_NONZERO) == CASTELJAU_OK);
    CHECK(casteljau_canvas_fill_rect(canvas, 0, 0, 64, 48, radial) == CASTELJAU_OK);
    CHECK(casteljau_canvas_restore(canvas) == CASTELJAU_OK);
    CHECK(casteljau_canvas_stroke_path(canvas, path, stroke, solid) == CASTELJAU_OK);
    CHECK(casteljau_canvas_begin_layer(canvas, 0.5, CASTELJAU_BLEND_NORMAL) == CASTELJAU_OK);
    CHECK(casteljau_canvas_draw_text(canvas, font, "Hi", 12, 2, 30, solid) == CASTELJAU_OK);
    CHECK(casteljau_canvas_end_layer(canvas) == CASTELJAU_OK);
    casteljau_matrix m = {0.25, 0, 0, 0.25, 48, 32};
    CHECK(casteljau_canvas_draw_image(canvas, image, &m, CASTELJAU_SAMPLING_BICUBIC, 1.0) == CASTELJAU_OK);
    CHECK(casteljau_canvas_translate(canvas, 1, 2) == CASTELJAU_OK);
    CHECK(casteljau_canvas_scale(canvas, 2, 2) == CASTELJAU_OK);
    CHECK(casteljau_canvas_rotate(canvas, 0) == CASTELJAU_OK);
    CHECK(casteljau_canvas_skew(canvas, 0, 0) == CASTELJAU_OK);
    casteljau_matrix got;
    CHECK(casteljau_canvas_get_transform(canvas, &got) == CASTELJAU_OK);
    CHECK(got.a == 2 && got.d == 2 && got.e == 1 && got.f == 2);
    casteljau_matrix id = {1, 0, 0, 1, 0, 0};
    CHECK(casteljau_canvas_set_transform(canvas, &id) == CASTELJAU_OK);
    CHECK(casteljau_canvas_concat(canvas, &id) == CASTELJAU_OK);
    CHECK(casteljau_canvas_set_opacity(canvas, 1) == CASTELJAU_OK);
    CHECK(casteljau_canvas_set_blend_mode(canvas, CASTELJAU_BLEND_SOURCE_OVER) == CASTELJAU_OK);
    CHECK(casteljau_canvas_set_tolerance(canvas, 0.05) == CASTELJAU_OK);
    CHECK(casteljau_canvas_clip_rect(canvas, 0, 0, 64, 48) == CASTELJAU_OK);
    CHECK(casteljau_canvas_fill_rect(canvas, 0, 46, 2, 2, pattern) == CASTELJAU_OK);
    /* Sampled pixels: white background, the gradient (t = (x + 0.5 - 40) / 20), the clipped
     * radial centre (first stop: red). */
    CHECK(pixel(image, 63, 0)[0] == 255 && pixel(image, 63, 0)[3] == 255);
    {
        const double t = (50 + 0.5 - 40) / 20.0;
        CHECK(fabs(pixel(image, 50, 10)[0] - 255 * (1 - t)) <= 1);
        CHECK(fabs(pixel(image, 50, 10)[2] - 255 * t) <= 1);
    }
    {
        const double t = sqrt(0.5) / 10;
        CHECK(fabs(pixel(image, 32, 36)[0] - 255 * (1 - t)) <= 1 && fabs(pixel(image, 32, 36)[2] - 255 * t) <= 1);
        CHECK(pixel(image, 20, 36)[0] == 255 && pixel(image, 20, 36)[1] == 255); /* outside the clip circle */
    }
    CHECK(casteljau_image_write_png(image, png_path) == CASTELJAU_OK);
    casteljau_image* back = NULL;
    CHECK(casteljau_image_read_png(png_path, &back) == CASTELJAU_OK);
    CHECK(memcmp(pixel(back, 50, 10), pixel(image, 50, 10), 4) == 0);

    /* A canvas over caller memory with padded rows */
    uint8_t buffer[3 * 40];
    memset(buffer, 0x5A, sizeof buffer);
    casteljau_canvas* raw = NULL;
    CHECK(casteljau_canvas_create_for_pixels(buffer, 8, 3, 40, &raw) == CASTELJAU_OK);
    CHECK(casteljau_canvas_clear(raw, blue) == CASTELJAU_OK);
    CHECK(buffer[40 + 2] == 255 && buffer[40 + 32] == 0x5A);
    CHECK(casteljau_canvas_pixels(raw) == buffer && casteljau_canvas_stride(raw) == 40);

    /* Errors, each read back */
    casteljau_path* bad = (casteljau_path*)1;
    CHECK_ERROR(casteljau_path_from_svg("M 10 10 L 20", &bad), CASTELJAU_ERROR_PARSE, "");
    CHECK(bad == NULL);
    CHECK(strlen(casteljau_last_error()) > 0);
    casteljau_font* nofont = NULL;
    casteljau_status fs = casteljau_font_load(missing, &nofont);
    CHECK(fs == CASTELJAU_ERROR_IO || fs == CASTELJAU_ERROR_FONT);
    CHECK(strstr(casteljau_last_error(), "no-such-font") != NULL);
    CHECK(nofont == NULL);
    const uint8_t junk[16] = {0x89, 'P', 'N', 'G', 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    casteljau_image* badpng = NULL;
    CHECK_ERROR(casteljau_image_decode_png(junk, sizeof junk, &badpng), CASTELJAU_ERROR_INVALID_DATA, "");
    CHECK(badpng == NULL);
    CHECK_ERROR(casteljau_image_read_png(missing, &badpng), CASTELJAU_ERROR_IO, "no-such-font");
    CHECK_ERROR(casteljau_canvas_fill_path(NULL, path, solid, CASTELJAU_FILL_NONZERO), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "canvas is NULL");
    CHECK_ERROR(casteljau_canvas_fill_path(canvas, NULL, solid, CASTELJAU_FILL_NONZERO),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "path is NULL");
    CHECK_ERROR(casteljau_path_line_to(path, NAN, 0), CASTELJAU_ERROR_INVALID_ARGUMENT, "finite");
    CHECK_ERROR(casteljau_image_create(0, 10, &badpng), CASTELJAU_ERROR_INVALID_ARGUMENT, "1x1");
    CHECK_ERROR(casteljau_image_create(100000, 100000, &badpng), CASTELJAU_ERROR_LIMIT, "limit");
    casteljau_paint* nopaint = solid;
    CHECK_ERROR(casteljau_paint_create_linear(0, 0, 1, 0, stops, 0, CASTELJAU_SPREAD_PAD, NULL, &nopaint),
                CASTELJAU_ERROR_INVALID_ARGUMENT, "stop");
    CHECK(nopaint == NULL);
    CHECK_ERROR(casteljau_canvas_set_blend_mode(canvas, (casteljau_blend_mode)99), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "blend");
    casteljau_canvas* nocanvas = NULL;
    CHECK_ERROR(casteljau_canvas_create_for_pixels(buffer, 8, 3, 16, &nocanvas), CASTELJAU_ERROR_INVALID_ARGUMENT,
                "stride");
    CHECK(nocanvas == NULL);
    CHECK_ERROR(casteljau_canvas_draw_text(canvas, font, "x", NAN, 0, 0, solid), CASTELJAU_ERROR_INVALID_ARGUMENT, "");
    CHECK_ERROR(casteljau_image_write_png(image, "/nonexistent-dir/x.png"), CASTELJAU_ERROR_IO, "nonexistent-dir");
    CHECK_ERROR(casteljau_canvas_set_opacity(canvas, 2), CASTELJAU_ERROR_INVALID_ARGUMENT, "opacity");
    {
        int i, limit = 0;
        for (i = 0; i < 2000 && !limit; ++i) limit = casteljau_canvas_save(canvas) == CASTELJAU_ERROR_LIMIT;
        CHECK(limit);
        CHECK(strstr(casteljau_last_error(), "1024") != NULL);
    }
    {
        /* The documented C API limits: 65536 gradient stops, 4096 dash values. */
        casteljau_gradient_stop* many = (casteljau_gradient_stop*)calloc(65537, sizeof *many);
        double* dashes = (double*)calloc(4097, sizeof *dashes);
        int i;
        CHECK(many != NULL && dashes != NULL);
        for (i = 0; i < 65537; ++i) {
            many[i].offset = i / 65536.0;
            many[i].color.a = 255;
        }
        for (i = 0; i < 4097; ++i) dashes[i] = 1;
        nopaint = NULL;
        CHECK_ERROR(casteljau_paint_create_linear(0, 0, 1, 0, many, 65537, CASTELJAU_SPREAD_PAD, NULL, &nopaint),
                    CASTELJAU_ERROR_LIMIT, "65536");
        CHECK(nopaint == NULL);
        CHECK(casteljau_paint_create_linear(0, 0, 1, 0, many, 65536, CASTELJAU_SPREAD_PAD, NULL, &nopaint) ==
              CASTELJAU_OK);
        casteljau_paint_destroy(nopaint);
        CHECK_ERROR(casteljau_stroke_set_dashes(stroke, dashes, 4097, 0), CASTELJAU_ERROR_LIMIT, "4096");
        CHECK(casteljau_stroke_set_dashes(stroke, dashes, 4096, 0) == CASTELJAU_OK);
        CHECK(casteljau_stroke_set_dashes(stroke, NULL, 0, 0) == CASTELJAU_OK);
        free(many);
        free(dashes);
    }
    CHECK(casteljau_image_width(NULL) == 0 && casteljau_image_data(NULL) == NULL);

    /* Limits: read, lowered, crossed, a bad value refused, a prefix set, the defaults restored */
    {
        casteljau_limits lim, now;
        casteljau_image* big = NULL;
        casteljau_path* pts = NULL;
        casteljau_font* nofont = NULL;
        casteljau_canvas* small = NULL;
        int32_t side = 100;
        int i;
        CHECK(casteljau_limits_get(&lim, sizeof lim) == CASTELJAU_OK);
        CHECK(lim.canvas_dimension == 32768 && lim.canvas_pixels == 268435456 && lim.nesting_depth == 64);
        CHECK(lim.svg_elements == 1000000 && lim.svg_image_nesting == 4 && lim.canvas_save_depth == 1024);
        CHECK_ERROR(casteljau_limits_get(&lim, 3), CASTELJAU_ERROR_INVALID_ARGUMENT, "size");
        CHECK_ERROR(casteljau_limits_get(&lim, sizeof lim + 8), CASTELJAU_ERROR_INVALID_ARGUMENT, "size");
        CHECK_ERROR(casteljau_limits_get(NULL, sizeof lim), CASTELJAU_ERROR_INVALID_ARGUMENT, "NULL");

        lim.canvas_dimension = 40000; /* above its ceiling: refused, nothing changes */
        lim.canvas_save_depth = 3;
        CHECK_ERROR(casteljau_limits_set(&lim, sizeof lim), CASTELJAU_ERROR_INVALID_ARGUMENT, "canvas_dimension");
        CHECK(casteljau_limits_get(&now, sizeof now) == CASTELJAU_OK && now.canvas_save_depth == 1024);

        lim.canvas_dimension = 100;
        lim.path_points = 10;
        lim.text_bytes = 5;
        lim.font_file_bytes = 1000;
        CHECK(casteljau_limits_set(&lim, sizeof lim) == CASTELJAU_OK);
        CHECK_ERROR(casteljau_image_create(101, 10, &big), CASTELJAU_ERROR_LIMIT, "100");
        CHECK(big == NULL);
        CHECK(casteljau_image_create(100, 10, &big) == CASTELJAU_OK);
        CHECK_ERROR(casteljau_path_from_svg("M0 0 1 1 2 2 3 3 4 4 5 5 6 6 7 7 8 8 9 9 10 10", &pts),
                    CASTELJAU_ERROR_LIMIT, "10");
        CHECK(pts == NULL);
        CHECK_ERROR(casteljau_font_load(font_path, &nofont), CASTELJAU_ERROR_LIMIT, "1000");
        CHECK_ERROR(casteljau_canvas_draw_text(canvas, font, "hello world", 10, 0, 0, solid), CASTELJAU_ERROR_LIMIT,
                    "5");
        CHECK(casteljau_canvas_create(big, &small) == CASTELJAU_OK);
        for (i = 0; i < 3; ++i) CHECK(casteljau_canvas_save(small) == CASTELJAU_OK);
        CHECK_ERROR(casteljau_canvas_save(small), CASTELJAU_ERROR_LIMIT, "3");
        casteljau_canvas_destroy(small);
        casteljau_image_destroy(big);

        /* A caller compiled against a header whose struct held only canvas_dimension. */
        CHECK(casteljau_limits_set((const casteljau_limits*)&side, sizeof side) == CASTELJAU_OK);
        CHECK(casteljau_limits_get(&now, sizeof now) == CASTELJAU_OK);
        CHECK(now.canvas_dimension == 100 && now.path_points == 10);

        casteljau_limits_reset();
        CHECK(casteljau_limits_get(&now, sizeof now) == CASTELJAU_OK);
        CHECK(now.canvas_dimension == 32768 && now.path_points == 16777216 && now.canvas_save_depth == 1024);
        CHECK(casteljau_font_load(font_path, &nofont) == CASTELJAU_OK);
        casteljau_font_destroy(nofont);
    }

    /* The thread pool's size */
    {
        int hw = casteljau_thread_count();
        CHECK(hw >= 1);
        CHECK(casteljau_set_thread_count(3) == CASTELJAU_OK && casteljau_thread_count() == 3);
        CHECK_ERROR(casteljau_set_thread_count(-1), CASTELJAU_ERROR_INVALID_ARGUMENT, "0 (all cores) to 256");
        CHECK(casteljau_thread_count() == 3);
        CHECK(casteljau_set_thread_count(0) == CASTELJAU_OK && casteljau_thread_count() == hw);
    }

    /* Destroy everything (NULL is accepted) */
    casteljau_canvas_destroy(raw);
    casteljau_canvas_destroy(canvas);
    casteljau_image_destroy(back);
    casteljau_image_destroy(image);
    casteljau_path_destroy(path);
    casteljau_path_destroy(svg);
    casteljau_path_destroy(circle);
    casteljau_stroke_destroy(stroke);
    casteljau_paint_destroy(solid);
    casteljau_paint_destroy(linear);
    casteljau_paint_destroy(radial);
    casteljau_paint_destroy(pattern);
    casteljau_font_destroy(font);
    casteljau_path_destroy(NULL);
    casteljau_canvas_destroy(NULL);
    if (failures)
        fprintf(stderr, "%d checks failed\n", failures);
    else
        printf("C API: all checks passed\n");
    return failures ? 1 : 0;
}
