/* casteljau/casteljau.h: the C API of casteljau, a 2D vector rasterizer (plain C99).
 *
 * It mirrors the C++ Canvas (casteljau/canvas.hpp) call for call: paths (a builder and SVG path
 * data), stroke styles, paints (solid colours, linear and radial gradients, image patterns, opacity,
 * blend modes), a canvas with a state stack (transform, clip, opacity, blend mode), clipping to
 * rectangles and paths, images (premultiplied RGBA8, PNG read, write and encode, raw pixel
 * access), layers, and text with a font file. Three headers beside it, each including this one,
 * add the documents casteljau draws, with the options of the command line: casteljau_svg.h (SVG
 * documents), casteljau_map.h (GeoJSON and TopoJSON maps, tile pyramids) and casteljau_text.h
 * (paragraph layout: fallback fonts, wrapping, alignment, direction, features, variations).
 *
 * Conventions
 * - Every name starts with casteljau_ / CASTELJAU_. Objects are opaque handles made by a
 *   casteljau_X_create (or a function that returns one through an out-parameter) and released by
 *   casteljau_X_destroy, which accepts NULL. The caller owns every handle it receives and must
 *   destroy it exactly once; a handle used after its destroy is undefined behaviour (it cannot be
 *   detected), a NULL handle is detected and reported as CASTELJAU_ERROR_INVALID_ARGUMENT.
 * - Functions that can fail return a casteljau_status; on failure the message of the error is
 *   available from casteljau_last_error() on the same thread until the next failing call there.
 *   No C++ exception ever crosses this API; out of memory is reported as a status too.
 * - Coordinates: pixel space has x to the right and y down; pixel (i, j) is the square
 *   [i, i+1) x [j, j+1). A canvas maps user space to pixel space by its current transform.
 *   Matrices are [a c e; b d f]: x' = a x + c y + e, y' = b x + d y + f.
 * - Colours are 8-bit sRGB with straight alpha; images hold premultiplied RGBA8, rows `stride`
 *   bytes apart, top row first.
 * - A canvas borrows the image (or the caller's memory) it draws into: destroy the canvas first.
 *   A paint made from an image keeps its own reference to the pixels (the image may be destroyed).
 * Thread-safety: distinct objects may be used from distinct threads at the same time; one object
 * belongs to one thread at a time. Paths, paints, stroke styles and fonts may be read (drawn with)
 * from several threads at once only if nobody modifies them; fonts: one thread at a time.
 */
#ifndef CASTELJAU_H
#define CASTELJAU_H

#include <stddef.h>
#include <stdint.h>

#if defined(__GNUC__)
#define CASTELJAU_API __attribute__((visibility("default")))
#else
#define CASTELJAU_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

#define CASTELJAU_VERSION_MAJOR 0
#define CASTELJAU_VERSION_MINOR 1
#define CASTELJAU_VERSION_PATCH 0
/* MAJOR * 10000 + MINOR * 100 + PATCH, as casteljau_version() returns for the library linked. */
#define CASTELJAU_VERSION (CASTELJAU_VERSION_MAJOR * 10000 + CASTELJAU_VERSION_MINOR * 100 + CASTELJAU_VERSION_PATCH)

/* Enumerations: in C++ they take int as their underlying type, so that every int a C caller may
 * pass is a value of the type there too (the library range-checks them: INVALID_ARGUMENT), and not
 * undefined behaviour in the library's own C++. The size and calling convention are those of the
 * C enum either way. */
#ifdef __cplusplus
#define CASTELJAU_ENUM(name) enum name : int
#else
#define CASTELJAU_ENUM(name) enum name
#endif

typedef CASTELJAU_ENUM(casteljau_status){
    CASTELJAU_OK = 0,
    CASTELJAU_ERROR_INVALID_ARGUMENT = 1, /* a NULL handle, a value outside the documented domain */
    CASTELJAU_ERROR_PARSE = 2,            /* malformed text (path data, colour) */
    CASTELJAU_ERROR_INVALID_DATA = 3,     /* unusable content: NaN geometry, a corrupt PNG */
    CASTELJAU_ERROR_LIMIT = 4,            /* past a documented limit (image size, nesting) */
    CASTELJAU_ERROR_IO = 5,               /* a file could not be read or written */
    CASTELJAU_ERROR_FONT = 6,             /* FreeType or HarfBuzz refused a font */
    CASTELJAU_ERROR_OUT_OF_MEMORY = 7,
    CASTELJAU_ERROR_INTERNAL = 8,
    CASTELJAU_ERROR_CANCELLED = 9 /* a progress callback asked to stop */
} casteljau_status;

typedef CASTELJAU_ENUM(casteljau_fill_rule){CASTELJAU_FILL_NONZERO = 0, CASTELJAU_FILL_EVENODD = 1} casteljau_fill_rule;
typedef CASTELJAU_ENUM(casteljau_line_cap){CASTELJAU_CAP_BUTT = 0, CASTELJAU_CAP_ROUND = 1,
                                           CASTELJAU_CAP_SQUARE = 2} casteljau_line_cap;
typedef CASTELJAU_ENUM(casteljau_line_join){CASTELJAU_JOIN_MITER = 0, CASTELJAU_JOIN_MITER_CLIP = 1,
                                            CASTELJAU_JOIN_ROUND = 2, CASTELJAU_JOIN_BEVEL = 3} casteljau_line_join;
typedef CASTELJAU_ENUM(casteljau_spread){CASTELJAU_SPREAD_PAD = 0, CASTELJAU_SPREAD_REFLECT = 1,
                                         CASTELJAU_SPREAD_REPEAT = 2} casteljau_spread;
typedef CASTELJAU_ENUM(casteljau_sampling){CASTELJAU_SAMPLING_NEAREST = 0, CASTELJAU_SAMPLING_BILINEAR = 1,
                                           CASTELJAU_SAMPLING_BICUBIC = 2} casteljau_sampling;
/* The values of casteljau::BlendMode (blend_mode.hpp), formulas there. */
typedef CASTELJAU_ENUM(casteljau_blend_mode){CASTELJAU_BLEND_NORMAL = 0,
                                             CASTELJAU_BLEND_MULTIPLY,
                                             CASTELJAU_BLEND_SCREEN,
                                             CASTELJAU_BLEND_OVERLAY,
                                             CASTELJAU_BLEND_DARKEN,
                                             CASTELJAU_BLEND_LIGHTEN,
                                             CASTELJAU_BLEND_COLOR_DODGE,
                                             CASTELJAU_BLEND_COLOR_BURN,
                                             CASTELJAU_BLEND_HARD_LIGHT,
                                             CASTELJAU_BLEND_SOFT_LIGHT,
                                             CASTELJAU_BLEND_DIFFERENCE,
                                             CASTELJAU_BLEND_EXCLUSION,
                                             CASTELJAU_BLEND_HUE,
                                             CASTELJAU_BLEND_SATURATION,
                                             CASTELJAU_BLEND_COLOR,
                                             CASTELJAU_BLEND_LUMINOSITY,
                                             CASTELJAU_BLEND_CLEAR,
                                             CASTELJAU_BLEND_SOURCE,
                                             CASTELJAU_BLEND_DESTINATION,
                                             CASTELJAU_BLEND_DESTINATION_OVER,
                                             CASTELJAU_BLEND_SOURCE_IN,
                                             CASTELJAU_BLEND_DESTINATION_IN,
                                             CASTELJAU_BLEND_SOURCE_OUT,
                                             CASTELJAU_BLEND_DESTINATION_OUT,
                                             CASTELJAU_BLEND_SOURCE_ATOP,
                                             CASTELJAU_BLEND_DESTINATION_ATOP,
                                             CASTELJAU_BLEND_XOR,
                                             CASTELJAU_BLEND_PLUS,
                                             CASTELJAU_BLEND_SOURCE_OVER = CASTELJAU_BLEND_NORMAL} casteljau_blend_mode;

typedef struct casteljau_matrix {
    double a, b, c, d, e, f;
} casteljau_matrix;
typedef struct casteljau_color {
    uint8_t r, g, b, a;
} casteljau_color;
typedef struct casteljau_gradient_stop {
    double offset;
    casteljau_color color;
} casteljau_gradient_stop;

typedef struct casteljau_path casteljau_path;
typedef struct casteljau_stroke casteljau_stroke;
typedef struct casteljau_paint casteljau_paint;
typedef struct casteljau_image casteljau_image;
typedef struct casteljau_canvas casteljau_canvas;
typedef struct casteljau_font casteljau_font;

/* Library */
CASTELJAU_API const char* casteljau_version_string(void); /* "0.1.0" */
CASTELJAU_API int casteljau_version(void);                /* CASTELJAU_VERSION of the library */
/* The message of the last failed call on this thread ("" when none); valid until the next one. */
CASTELJAU_API const char* casteljau_last_error(void);
CASTELJAU_API const char* casteljau_status_name(casteljau_status status);
/* Releases memory the library allocated for the caller (casteljau_image_encode_png); accepts NULL. */
CASTELJAU_API void casteljau_free(void* memory);
/* Parses a CSS colour ("crimson", "#4a4a4a", "rgb(10 20 30 / 50%)", "transparent"), as the
 * command line's colour options do; CASTELJAU_ERROR_PARSE for anything else. */
CASTELJAU_API casteljau_status casteljau_color_parse(const char* text, casteljau_color* out);

/* Paths: contours of lines, quadratic and cubic curves, in user space. */
CASTELJAU_API casteljau_path* casteljau_path_create(void); /* NULL when out of memory */
CASTELJAU_API void casteljau_path_destroy(casteljau_path* path);
/* Parses SVG path data ("M10 10 L 20 20 Z"); CASTELJAU_ERROR_PARSE names the position of an error. */
CASTELJAU_API casteljau_status casteljau_path_from_svg(const char* data, casteljau_path** out);
CASTELJAU_API casteljau_status casteljau_path_move_to(casteljau_path* path, double x, double y);
CASTELJAU_API casteljau_status casteljau_path_line_to(casteljau_path* path, double x, double y);
CASTELJAU_API casteljau_status casteljau_path_quad_to(casteljau_path* path, double cx, double cy, double x, double y);
CASTELJAU_API casteljau_status casteljau_path_cubic_to(casteljau_path* path, double c1x, double c1y, double c2x,
                                                       double c2y, double x, double y);
CASTELJAU_API casteljau_status casteljau_path_close(casteljau_path* path);
CASTELJAU_API casteljau_status casteljau_path_add_rect(casteljau_path* path, double x, double y, double w, double h);
CASTELJAU_API casteljau_status casteljau_path_add_ellipse(casteljau_path* path, double cx, double cy, double rx,
                                                          double ry);
CASTELJAU_API casteljau_status casteljau_path_add_round_rect(casteljau_path* path, double x, double y, double w,
                                                             double h, double rx, double ry);
CASTELJAU_API casteljau_status casteljau_path_transform(casteljau_path* path, const casteljau_matrix* m);
/* Tight bounds; an empty path gives all zeros. */
CASTELJAU_API casteljau_status casteljau_path_bounds(const casteljau_path* path, double* x0, double* y0, double* x1,
                                                     double* y1);

/* Stroke styles (width 1, butt caps, miter joins with limit 4, no dashes when created). */
CASTELJAU_API casteljau_stroke* casteljau_stroke_create(void);
CASTELJAU_API void casteljau_stroke_destroy(casteljau_stroke* stroke);
CASTELJAU_API casteljau_status casteljau_stroke_set_width(casteljau_stroke* stroke, double width);
CASTELJAU_API casteljau_status casteljau_stroke_set_cap(casteljau_stroke* stroke, casteljau_line_cap cap);
CASTELJAU_API casteljau_status casteljau_stroke_set_join(casteljau_stroke* stroke, casteljau_line_join join,
                                                         double miter_limit);
/* `count` dash lengths (0 to clear), the pattern starting `offset` into it. */
CASTELJAU_API casteljau_status casteljau_stroke_set_dashes(casteljau_stroke* stroke, const double* dashes, size_t count,
                                                           double offset);

/* Paints. Gradient geometry is in user space, mapped by `m` (NULL: identity) and then by the
 * canvas transform at drawing time. Stops need not be sorted (offsets are clamped to [0, 1] and
 * made non-decreasing); at least one is required. */
CASTELJAU_API casteljau_status casteljau_paint_create_solid(casteljau_color color, casteljau_paint** out);
CASTELJAU_API casteljau_status casteljau_paint_create_linear(double x0, double y0, double x1, double y1,
                                                             const casteljau_gradient_stop* stops, size_t count,
                                                             casteljau_spread spread, const casteljau_matrix* m,
                                                             casteljau_paint** out);
/* The circle (cx, cy, r) at offset 1, the focal circle (fx, fy, fr) at offset 0. */
CASTELJAU_API casteljau_status casteljau_paint_create_radial(double cx, double cy, double r, double fx, double fy,
                                                             double fr, const casteljau_gradient_stop* stops,
                                                             size_t count, casteljau_spread spread,
                                                             const casteljau_matrix* m, casteljau_paint** out);
/* An image pattern: the image's pixel space mapped by `m`; `repeat` tiles the plane (else
 * transparent outside). The paint copies the pixels, so later changes to the image do not show. */
CASTELJAU_API casteljau_status casteljau_paint_create_image(const casteljau_image* image, casteljau_sampling sampling,
                                                            const casteljau_matrix* m, int repeat,
                                                            casteljau_paint** out);
CASTELJAU_API void casteljau_paint_destroy(casteljau_paint* paint);
CASTELJAU_API casteljau_status casteljau_paint_set_opacity(casteljau_paint* paint, double opacity);
CASTELJAU_API casteljau_status casteljau_paint_set_blend_mode(casteljau_paint* paint, casteljau_blend_mode mode);
/* Nonzero: solid colours are blended with coverage in linear light (gamma-correct) instead of
 * sRGB, as `casteljau text --gamma-correct` draws; 0 (the default): sRGB. */
CASTELJAU_API casteljau_status casteljau_paint_set_linear_blend(casteljau_paint* paint, int linear);

/* Images: premultiplied RGBA8 pixels. */
CASTELJAU_API casteljau_status casteljau_image_create(int width, int height, casteljau_image** out); /* transparent */
CASTELJAU_API casteljau_status casteljau_image_read_png(const char* path, casteljau_image** out);
CASTELJAU_API casteljau_status casteljau_image_decode_png(const uint8_t* bytes, size_t size, casteljau_image** out);
/* Writes through a temporary file renamed into place: never a half-written file. */
CASTELJAU_API casteljau_status casteljau_image_write_png(const casteljau_image* image, const char* path);
/* The PNG file casteljau_image_write_png would write, in memory: *out (size *size bytes) is the
 * caller's, to release with casteljau_free. */
CASTELJAU_API casteljau_status casteljau_image_encode_png(const casteljau_image* image, uint8_t** out, size_t* size);
CASTELJAU_API void casteljau_image_destroy(casteljau_image* image);
CASTELJAU_API int casteljau_image_width(const casteljau_image* image);     /* 0 for NULL */
CASTELJAU_API int casteljau_image_height(const casteljau_image* image);    /* 0 for NULL */
CASTELJAU_API size_t casteljau_image_stride(const casteljau_image* image); /* bytes per row, 0 for NULL */
/* The first row of pixels, owned by the image (valid until it is destroyed); NULL for NULL. */
CASTELJAU_API uint8_t* casteljau_image_data(casteljau_image* image);

/* Fonts (TrueType/OpenType/collections through FreeType, shaped by HarfBuzz). */
CASTELJAU_API casteljau_status casteljau_font_load(const char* path, casteljau_font** out);
/* Face `face_index` (0 and up) of a collection (.ttc/.otc); CASTELJAU_ERROR_FONT past its last. */
CASTELJAU_API casteljau_status casteljau_font_load_face(const char* path, int face_index, casteljau_font** out);
CASTELJAU_API void casteljau_font_destroy(casteljau_font* font);

/* Canvas. */
/* Draws into `image`, which must outlive the canvas. */
CASTELJAU_API casteljau_status casteljau_canvas_create(casteljau_image* image, casteljau_canvas** out);
/* Draws straight into caller-owned premultiplied RGBA8 memory: `height` rows of `stride` bytes
 * (stride >= 4 x width), which must outlive the canvas. */
CASTELJAU_API casteljau_status casteljau_canvas_create_for_pixels(uint8_t* pixels, int width, int height, size_t stride,
                                                                  casteljau_canvas** out);
CASTELJAU_API void casteljau_canvas_destroy(casteljau_canvas* canvas);
CASTELJAU_API int casteljau_canvas_width(const casteljau_canvas* canvas);
CASTELJAU_API int casteljau_canvas_height(const casteljau_canvas* canvas);
CASTELJAU_API uint8_t* casteljau_canvas_pixels(casteljau_canvas* canvas);
CASTELJAU_API size_t casteljau_canvas_stride(const casteljau_canvas* canvas);

CASTELJAU_API casteljau_status casteljau_canvas_save(casteljau_canvas* canvas); /* LIMIT past 1024 */
CASTELJAU_API casteljau_status casteljau_canvas_restore(casteljau_canvas* canvas);
CASTELJAU_API casteljau_status casteljau_canvas_translate(casteljau_canvas* canvas, double tx, double ty);
CASTELJAU_API casteljau_status casteljau_canvas_scale(casteljau_canvas* canvas, double sx, double sy);
CASTELJAU_API casteljau_status casteljau_canvas_rotate(casteljau_canvas* canvas, double radians);
CASTELJAU_API casteljau_status casteljau_canvas_skew(casteljau_canvas* canvas, double ax, double ay);
CASTELJAU_API casteljau_status casteljau_canvas_concat(casteljau_canvas* canvas, const casteljau_matrix* m);
CASTELJAU_API casteljau_status casteljau_canvas_set_transform(casteljau_canvas* canvas, const casteljau_matrix* m);
CASTELJAU_API casteljau_status casteljau_canvas_get_transform(const casteljau_canvas* canvas, casteljau_matrix* out);
CASTELJAU_API casteljau_status casteljau_canvas_clip_rect(casteljau_canvas* canvas, double x, double y, double w,
                                                          double h);
CASTELJAU_API casteljau_status casteljau_canvas_clip_path(casteljau_canvas* canvas, const casteljau_path* path,
                                                          casteljau_fill_rule rule);
CASTELJAU_API casteljau_status casteljau_canvas_set_opacity(casteljau_canvas* canvas, double opacity);
CASTELJAU_API casteljau_status casteljau_canvas_set_blend_mode(casteljau_canvas* canvas, casteljau_blend_mode mode);
/* Flattening tolerance in pixels (default 0.015; 1e-4 .. 10) of the fills and strokes that follow. */
CASTELJAU_API casteljau_status casteljau_canvas_set_tolerance(casteljau_canvas* canvas, double tolerance);

CASTELJAU_API casteljau_status casteljau_canvas_clear(casteljau_canvas* canvas, casteljau_color color);
CASTELJAU_API casteljau_status casteljau_canvas_fill_path(casteljau_canvas* canvas, const casteljau_path* path,
                                                          const casteljau_paint* paint, casteljau_fill_rule rule);
CASTELJAU_API casteljau_status casteljau_canvas_fill_rect(casteljau_canvas* canvas, double x, double y, double w,
                                                          double h, const casteljau_paint* paint);
CASTELJAU_API casteljau_status casteljau_canvas_stroke_path(casteljau_canvas* canvas, const casteljau_path* path,
                                                            const casteljau_stroke* stroke,
                                                            const casteljau_paint* paint);
/* `m` maps the image's pixel space to user space (NULL: identity). */
CASTELJAU_API casteljau_status casteljau_canvas_draw_image(casteljau_canvas* canvas, const casteljau_image* image,
                                                           const casteljau_matrix* m, casteljau_sampling sampling,
                                                           double opacity);
/* Lays out UTF-8 `text` in `font` at `size` pixels per em and draws it with its box's top-left
 * corner at (x, y) in user space. */
CASTELJAU_API casteljau_status casteljau_canvas_draw_text(casteljau_canvas* canvas, const casteljau_font* font,
                                                          const char* text, double size, double x, double y,
                                                          const casteljau_paint* paint);
CASTELJAU_API casteljau_status casteljau_canvas_begin_layer(casteljau_canvas* canvas, double opacity,
                                                            casteljau_blend_mode mode);
CASTELJAU_API casteljau_status casteljau_canvas_end_layer(casteljau_canvas* canvas);

/* Resource limits (casteljau::Limits in casteljau/limits.hpp, which gives each field's default
 * and ceiling; README.md "Limits" lists them): process-wide bounds on what untrusted input may
 * make the library allocate or compute. Read them with casteljau_limits_get, change fields, apply
 * them with casteljau_limits_set; each check reads the value in force when it runs, so set them
 * before drawing. `size` is sizeof(casteljau_limits) as the caller was compiled: later versions
 * only append fields, and a caller built against an older header gets and sets its prefix. */
typedef struct casteljau_limits {
    int32_t canvas_dimension;      /* pixels per side of an image or canvas */
    int64_t canvas_pixels;         /* pixels of an image or canvas */
    uint64_t path_points;          /* points of one path (parsed or stroked) */
    uint64_t flattened_segments;   /* line segments of one fill after flattening */
    int32_t nesting_depth;         /* SVG elements, patterns, GeoJSON collections, canvas layers */
    uint64_t svg_elements;         /* elements drawn per SVG document, each use copy counted */
    int32_t svg_image_nesting;     /* SVG documents drawn as images inside SVG documents (0: none) */
    uint64_t svgz_bytes;           /* inflated size of an .svgz */
    uint64_t css_rules;            /* style sheet rules per SVG document */
    uint64_t svg_text_chars;       /* characters of SVG text per document */
    int64_t filter_pixels;         /* pixels of one filter region */
    uint64_t filter_primitives;    /* primitives in one filter */
    uint64_t map_positions;        /* positions in one GeoJSON or TopoJSON map */
    uint64_t dashes;               /* dashes produced from one path */
    uint64_t font_file_bytes;      /* size of a font file */
    uint64_t png_chunk_bytes;      /* inflated text or ICC chunk of a PNG */
    uint32_t png_ancillary_chunks; /* text, sPLT and unknown chunks kept per PNG */
    uint64_t jpeg_working_memory;  /* libjpeg's memory besides the image */
    uint64_t canvas_save_depth;    /* casteljau_canvas_save nesting */
    uint64_t text_bytes;           /* UTF-8 bytes of one text drawn */
    uint64_t input_bytes;          /* one input file or stream read whole */
    uint64_t exact_work;           /* piece visits of one fill's exact cells, besides 2000 per segment */
} casteljau_limits;

/* Fills the first `size` bytes of *out with the limits in force. INVALID_ARGUMENT for NULL or a
 * size that is 0, larger than this library's casteljau_limits or cuts a field in two. */
CASTELJAU_API casteljau_status casteljau_limits_get(casteljau_limits* out, size_t size);
/* Applies every field within the first `size` bytes of *limits (the others keep their values).
 * INVALID_ARGUMENT, changing nothing, for a bad pointer or size as above or a field below its
 * minimum (1; 0 for svg_image_nesting) or above its ceiling; the message names the field. */
CASTELJAU_API casteljau_status casteljau_limits_set(const casteljau_limits* limits, size_t size);
/* Restores every default. */
CASTELJAU_API void casteljau_limits_reset(void);

/* The process-wide pool of threads casteljau's own parallel work runs on (casteljau/threads.hpp):
 * `threads` in all, the calling thread included; 1 runs everything on the calling thread, 0 (the
 * default) uses every hardware thread. INVALID_ARGUMENT outside 0..256. Not from inside a
 * callback casteljau runs. */
CASTELJAU_API casteljau_status casteljau_set_thread_count(int threads);
CASTELJAU_API int casteljau_thread_count(void);

#ifdef __cplusplus
}
#endif

#endif /* CASTELJAU_H */
