/* The backend scene, in C99 against the installed package (pkg-config casteljau):
 *   cc -std=c99 scene.c $(pkg-config --cflags --libs casteljau) -o scene && ./scene out.png FONT.ttf
 * Draws the same scene as examples/scene.cpp and examples/python/scene.py. */
#include <stdio.h>

#include <casteljau/casteljau.h>

#define TRY(call)                                                                      \
    do {                                                                               \
        if ((call) != CASTELJAU_OK) {                                                  \
            fprintf(stderr, "scene: error: %s (%s)\n", casteljau_last_error(), #call); \
            return 1;                                                                  \
        }                                                                              \
    } while (0)

static int draw(casteljau_image* image, casteljau_canvas* c, const char* font_path, const char* out) {
    const casteljau_color white = {255, 255, 255, 255}, red = {255, 0, 0, 255}, orange = {255, 165, 0, 255};
    const casteljau_color black = {0, 0, 0, 255}, ink = {40, 40, 40, 255};
    const casteljau_gradient_stop stops[2] = {{0, {0, 0, 255, 255}}, {1, {0, 255, 0, 255}}};
    casteljau_paint *p_red = NULL, *p_grad = NULL, *p_orange = NULL, *p_black = NULL, *p_ink = NULL;
    casteljau_path *circle = casteljau_path_create(), *line = casteljau_path_create();
    casteljau_stroke* st = casteljau_stroke_create();
    casteljau_image* checker = NULL;
    casteljau_font* font = NULL;
    int rc = 1;
    (void)image;
    if (!circle || !line || !st) goto done;
    if (casteljau_paint_create_solid(red, &p_red) || casteljau_paint_create_solid(orange, &p_orange) ||
        casteljau_paint_create_solid(black, &p_black) || casteljau_paint_create_solid(ink, &p_ink) ||
        casteljau_paint_create_linear(80, 0, 190, 0, stops, 2, CASTELJAU_SPREAD_PAD, NULL, &p_grad) ||
        casteljau_image_create(2, 2, &checker) || casteljau_font_load(font_path, &font))
        goto fail;
    {
        /* The checker's four premultiplied pixels: red, green / blue, white. */
        uint8_t* px = casteljau_image_data(checker);
        const size_t s = casteljau_image_stride(checker);
        const uint8_t colors[4][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {255, 255, 255, 255}};
        int i, k;
        for (i = 0; i < 4; ++i)
            for (k = 0; k < 4; ++k) px[(size_t)(i / 2) * s + 4 * (size_t)(i % 2) + (size_t)k] = colors[i][k];
    }
    {
        const casteljau_matrix m = {10, 0, 0, 10, 170, 80};
        if (casteljau_canvas_clear(c, white) || casteljau_canvas_fill_rect(c, 10, 10, 60, 40, p_red) ||
            casteljau_canvas_fill_rect(c, 80, 10, 110, 40, p_grad) || casteljau_canvas_save(c) ||
            casteljau_path_add_ellipse(circle, 50, 90, 25, 25) ||
            casteljau_canvas_clip_path(c, circle, CASTELJAU_FILL_NONZERO) ||
            casteljau_canvas_fill_rect(c, 0, 60, 200, 60, p_orange) || casteljau_canvas_restore(c) ||
            casteljau_path_move_to(line, 90, 70) || casteljau_path_line_to(line, 190, 70) ||
            casteljau_stroke_set_width(st, 4) || casteljau_canvas_stroke_path(c, line, st, p_black) ||
            casteljau_canvas_draw_image(c, checker, &m, CASTELJAU_SAMPLING_NEAREST, 1.0) ||
            casteljau_canvas_draw_text(c, font, "casteljau", 14, 90, 90, p_ink) ||
            casteljau_image_write_png(image, out))
            goto fail;
    }
    rc = 0;
    goto done;
fail:
    fprintf(stderr, "scene: error: %s\n", casteljau_last_error());
done:
    casteljau_font_destroy(font);
    casteljau_image_destroy(checker);
    casteljau_stroke_destroy(st);
    casteljau_path_destroy(line);
    casteljau_path_destroy(circle);
    casteljau_paint_destroy(p_ink);
    casteljau_paint_destroy(p_black);
    casteljau_paint_destroy(p_orange);
    casteljau_paint_destroy(p_grad);
    casteljau_paint_destroy(p_red);
    return rc;
}

int main(int argc, char** argv) {
    casteljau_image* image = NULL;
    casteljau_canvas* canvas = NULL;
    int rc;
    if (argc < 3) {
        fprintf(stderr, "usage: %s OUT.png FONT.ttf\n", argv[0]);
        return 2;
    }
    printf("casteljau %s\n", casteljau_version_string());
    TRY(casteljau_image_create(200, 120, &image));
    TRY(casteljau_canvas_create(image, &canvas));
    rc = draw(image, canvas, argv[2], argv[1]);
    casteljau_canvas_destroy(canvas);
    casteljau_image_destroy(image);
    return rc;
}
