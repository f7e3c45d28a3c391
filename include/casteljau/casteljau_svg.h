/* casteljau/casteljau_svg.h: SVG documents through the C API (plain C99; casteljau.h includes it).
 *
 * Reads SVG and gzip-compressed SVG (.svgz) documents, with what casteljau/svg.hpp lists as
 * supported (shapes, paint servers, clips, masks, markers, filters, text, images), and draws them
 * onto a canvas or into a new image. The options are those of `casteljau svg`: the resources
 * folder <image> files may come from (nothing is ever fetched over a network), font folders and
 * files, whether the system's fonts are used, and the families of the generic CSS font names.
 *
 * Sizes: a document's intrinsic size is its root width and height in CSS pixels (96 dpi),
 * fractional; the default output size rounds it to whole pixels (at least 1). Coordinates: the
 * viewBox maps the document onto the rectangle (0, 0)-(intrinsic width, intrinsic height) of user
 * space, which the canvas maps to pixels by its current transform.
 *
 * Conventions, errors and ownership are those of casteljau.h: every handle here is the caller's,
 * released by its destroy function (which accepts NULL); a NULL handle or out-parameter is
 * CASTELJAU_ERROR_INVALID_ARGUMENT unless a comment says NULL means the defaults.
 * Thread-safety: a document is immutable once read: several threads may render one document at
 * once, each onto its own canvas. An options object belongs to one thread at a time; the document
 * keeps a copy of the options it was read with.
 */
#ifndef CASTELJAU_SVG_H
#define CASTELJAU_SVG_H

#include "casteljau.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct casteljau_svg casteljau_svg;
typedef struct casteljau_svg_options casteljau_svg_options;

/* The generic CSS families that casteljau_svg_options_set_font_family maps to a family name. */
typedef CASTELJAU_ENUM(casteljau_font_generic){
    CASTELJAU_FAMILY_DEFAULT = 0,    /* ends every font-family list: --font-family (Times New Roman) */
    CASTELJAU_FAMILY_SERIF = 1,      /* --serif-family (Times New Roman) */
    CASTELJAU_FAMILY_SANS_SERIF = 2, /* --sans-serif-family (Arial) */
    CASTELJAU_FAMILY_CURSIVE = 3,    /* --cursive-family (Comic Sans MS) */
    CASTELJAU_FAMILY_FANTASY = 4,    /* --fantasy-family (Impact) */
    CASTELJAU_FAMILY_MONOSPACE = 5   /* --monospace-family (Courier New) */
} casteljau_font_generic;

/* Options (the defaults of `casteljau svg`: no resources folder beyond the file's own, no font
 * folder or file, the system's fonts used, resvg's generic families). NULL when out of memory. */
CASTELJAU_API casteljau_svg_options* casteljau_svg_options_create(void);
CASTELJAU_API void casteljau_svg_options_destroy(casteljau_svg_options* options);
/* --resources: the folder <image> files may be read from. A file's relative hrefs resolve against
 * its own folder and may not leave `folder` (default: the file's folder); a document from memory
 * resolves them against `folder` and reads no file without it. NULL or "" restores the default. */
CASTELJAU_API casteljau_status casteljau_svg_options_set_resources(casteljau_svg_options* options, const char* folder);
/* --font-dir and --font-file: a folder scanned for fonts, a font file (each call adds one). They
 * must exist when a document is read (CASTELJAU_ERROR_IO names the missing one). */
CASTELJAU_API casteljau_status casteljau_svg_options_add_font_dir(casteljau_svg_options* options, const char* folder);
CASTELJAU_API casteljau_status casteljau_svg_options_add_font_file(casteljau_svg_options* options, const char* file);
/* 0: --no-system-fonts (text uses the font folders and files alone: characters they lack are not
 * drawn or show a .notdef glyph); nonzero, the default: the system's fonts are matched by family
 * name too, and characters no other font has come from them as in `casteljau text` (fontconfig's
 * per-cluster fallback, after the folders and files given; SvgOptions::system_fallback). */
CASTELJAU_API casteljau_status casteljau_svg_options_set_system_fonts(casteljau_svg_options* options, int use);
CASTELJAU_API casteljau_status casteljau_svg_options_set_font_family(casteljau_svg_options* options,
                                                                     casteljau_font_generic generic,
                                                                     const char* family);

/* --dpi: pixels per inch of the physical units (in, cm, mm, pt, pc), the root's size included
 * (SvgOptions::dpi; default 96). CASTELJAU_ERROR_INVALID_ARGUMENT outside 1 to 10000. */
CASTELJAU_API casteljau_status casteljau_svg_options_set_dpi(casteljau_svg_options* options, double dpi);
/* --export-id: draw only the element with this id (a leading '#' is ignored) and its content,
 * where it lies in the whole document, on the document's canvas (SvgOptions::export_id). Reading
 * a document without such an element is CASTELJAU_ERROR_INVALID_DATA. NULL or "": the whole
 * document. */
CASTELJAU_API casteljau_status casteljau_svg_options_set_export_id(casteljau_svg_options* options, const char* id);

/* Reads a document from a file (.svg or .svgz), or from `size` bytes of memory (SVG text or
 * gzip-compressed SVG text); `options` NULL: the defaults. CASTELJAU_ERROR_PARSE for malformed
 * XML, CASTELJAU_ERROR_INVALID_DATA for an unusable root (a width or height of zero or below),
 * CASTELJAU_ERROR_LIMIT past the limits (casteljau_limits), CASTELJAU_ERROR_IO for a file that
 * cannot be read. Features casteljau does not draw are warnings, not errors. */
CASTELJAU_API casteljau_status casteljau_svg_load(const char* path, const casteljau_svg_options* options,
                                                  casteljau_svg** out);
CASTELJAU_API casteljau_status casteljau_svg_parse(const uint8_t* data, size_t size,
                                                   const casteljau_svg_options* options, casteljau_svg** out);
CASTELJAU_API void casteljau_svg_destroy(casteljau_svg* svg);

/* The intrinsic size in CSS pixels (fractional); either pointer may be NULL. */
CASTELJAU_API casteljau_status casteljau_svg_intrinsic_size(const casteljau_svg* svg, double* width, double* height);
/* The output size `casteljau svg` picks, as resvg and rsvg-convert do: `width` and `height` both
 * above 0: that size; one of them: the other from the rounded aspect ratio (rounded up); neither:
 * the rounded intrinsic size times `zoom` (0 stands for 1; 1e-3 to 1e3), rounded up. A zoom other
 * than 0 or 1 together with a width or height is CASTELJAU_ERROR_INVALID_ARGUMENT (the options
 * exclude each other); CASTELJAU_ERROR_LIMIT past the canvas limits. */
CASTELJAU_API casteljau_status casteljau_svg_output_size(const casteljau_svg* svg, int width, int height, double zoom,
                                                         int* out_width, int* out_height);
/* The warnings collected while reading (features not drawn, recovered errors): each valid while
 * the document lives; casteljau_svg_warning gives NULL past the last one and for a NULL document. */
CASTELJAU_API size_t casteljau_svg_warning_count(const casteljau_svg* svg);
CASTELJAU_API const char* casteljau_svg_warning(const casteljau_svg* svg, size_t index);

/* Draws the document onto `canvas` under its current transform and clip, with its tolerance (one
 * user unit of the canvas per CSS pixel: scale the canvas to draw it larger). */
CASTELJAU_API casteljau_status casteljau_svg_render(const casteljau_svg* svg, casteljau_canvas* canvas);
/* What `casteljau svg -w W --height H -z Z -b BACKGROUND` writes: a new image of the output size
 * (casteljau_svg_output_size), filled with `background`, the document scaled to fill it exactly. */
CASTELJAU_API casteljau_status casteljau_svg_render_image(const casteljau_svg* svg, int width, int height, double zoom,
                                                          casteljau_color background, casteljau_image** out);

#ifdef __cplusplus
}
#endif

#endif /* CASTELJAU_SVG_H */
